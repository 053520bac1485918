//! Study 10: voided sleepers under a quarter car (docs/theory.md §18) — the question maintenance engineers ask of a
//! hanging sleeper. On the base track on sleepers (the scenario's `[sleepers]`, else the typical ballasted track
//! replacing its soil), 0–3 consecutive sleepers at mid-track hang above the ballast by a void of 0–3 mm (0: ballast
//! that cannot pull, no void), and the default quarter car scaled to F crosses at 20–100 m/s: the largest rail
//! deflection, the largest ballast force under the neighbouring sleepers (which carry what the voided ones do not)
//! and the largest pad force, how low the voided sleepers go, and the wheel–rail force and losses of contact.

use super::discrete_track::{ELEMENTS_PER_BAY, TYPICAL, fit_mesh, sleepers_unless_given};
use super::resolution::Resolution;
use super::setups::{as_long_track, blank, mean_iterations};
use super::study_data::{StudyData, StudySummary, failed_runs};
use super::vehicle_speed::{SINGLE, cap_contact_step};
use report::plot::{PlotSpec, Series, Stroke};
use runner::{Runner, SweepPoint, SweepRow, finished};
use scenario::axis::{Axis, Shown};
use scenario::error::Result;
use scenario::number::row_with_gaps;
use scenario::sleepers::{ExceptionSection, SleeperIndex, SleepersSection};
use scenario::vehicle::VehicleKind;
use scenario::{Scenario, VehicleSection};
use serde::Serialize;
use std::fmt::Write as _;

/// Voided sleepers side by side.
const VOIDED: [usize; 4] = [0, 1, 2, 3];
/// Voids under them (m); 0: tensionless ballast in contact at rest.
const GAPS: [f64; 4] = [0.0, 1e-3, 2e-3, 3e-3];

/// The speeds (m/s): 20–100 every 20 (coarse) or 5 (paper).
fn speeds(resolution: Resolution) -> Vec<f64> {
    let step = match resolution {
        Resolution::Coarse => 20.0,
        Resolution::Paper => 5.0,
    };
    (0..).map(|i| 20.0 + step * i as f64).take_while(|v| *v <= 100.0 + 1e-9).collect()
}

/// `base` as the study runs it, with a sentence for each change: on sleepers (a node over each), the quarter car on
/// the one-axle train, a long track, a static start, a step that resolves the sleeper passing frequency and the
/// contact mode.
fn prepared(base: &Scenario, speeds: &[f64]) -> Result<(Scenario, Vec<String>)> {
    let mut s = base.clone();
    let mut notes = Vec::new();
    sleepers_unless_given(&mut s, SleepersSection::default(), TYPICAL, &mut notes);
    let a = s.sleepers.as_ref().map_or(0.6, |x| x.spacing);
    fit_mesh(&mut s, ELEMENTS_PER_BAY, &mut notes);
    s.load.train = Some(SINGLE.into());
    s.load.axles.clear();
    s.load.patches.clear();
    s.vehicle = Some(VehicleSection { kind: VehicleKind::QuarterCar, ..VehicleSection::default() });
    s.friction = Default::default();
    as_long_track(&mut s, &mut notes, "the vehicles");
    if s.integration.static_start.is_none() {
        let start = s.foundation.absorbing_zones.as_ref().map_or(0.0, |z| z.length).max(s.mesh.length / 5.0);
        notes.push(format!("the quarter car starts at rest in its static equilibrium at {start:.1} m"));
        s.integration.static_start = Some(start);
    }
    let advance = a / 20.0;
    if s.integration.load_advance > advance {
        notes.push(format!(
            "integration.load_advance = {advance} m: 20 steps a sleeper-passing period (a/20) at every speed"
        ));
        s.integration.load_advance = advance;
    }
    let vehicle = s.vehicle.clone().expect("set above");
    cap_contact_step(&mut s, speeds, &[vehicle], &mut notes)?;
    Ok((s, notes))
}

/// The parts of `base` the study replaces or adds, one sentence each.
pub(super) fn overrides(base: &Scenario) -> Vec<String> {
    let mut notes = Vec::new();
    if base.friction.devices.is_some() || base.friction.distributed.is_some() {
        notes.push("the scenario's [friction] is not used".into());
    }
    if base.vehicle.is_some() || base.load.train.is_some() || !base.load.axles.is_empty() {
        notes.push("the scenario's train and [vehicle] are not used: the study runs the default quarter car".into());
    }
    if base.sleepers.as_ref().is_some_and(|s| !s.exceptions.is_empty()) {
        notes.push("the scenario's [[sleepers.exceptions]] are replaced by the study's voided sleepers".into());
    }
    if let Ok((_, prepared)) = prepared(base, &speeds(Resolution::Coarse)) {
        notes.extend(prepared);
    }
    notes
}

/// One curve: `voided` sleepers hanging by `gap` (m), swept over speed.
struct Curve {
    voided: usize,
    gap: f64,
    rows: Vec<SweepRow>,
    points: Vec<SweepPoint>,
}

impl Curve {
    fn label(&self) -> String {
        match (self.voided, self.gap > 0.0) {
            (0, _) => "intact track".into(),
            (n, true) => format!("{n} voided, {} mm", self.gap * 1e3),
            (n, false) => format!("{n} tensionless, no void"),
        }
    }

    /// (speed, value) of the largest `value` over the curve's points.
    fn largest(&self, value: impl Fn(&SweepPoint) -> Option<f64>) -> Option<(f64, f64)> {
        self.points.iter().filter_map(|p| Some((p.speed, value(p)?))).max_by(|a, b| a.1.total_cmp(&b.1))
    }
}

fn neighbour_force(p: &SweepPoint) -> Option<f64> {
    let s = p.sleepers?;
    Some(s.neighbour_ballast_force.unwrap_or(s.max_ballast_force))
}

fn min_wheel_force(p: &SweepPoint) -> Option<f64> {
    p.vehicles.map(|v| v.min_wheel_force)
}

pub(super) fn study(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let speeds = speeds(resolution);
    let (base, _) = prepared(base, &speeds)?;
    let count = base.model()?.sleepers().map_or(0, |(_, nodes)| nodes.len());
    let first = count.saturating_sub(VOIDED[VOIDED.len() - 1]) / 2;
    let mut keys = Vec::new();
    let mut cases = Vec::new();
    for voided in VOIDED {
        for gap in GAPS.into_iter().take(if voided == 0 { 1 } else { GAPS.len() }) {
            let mut s = base.clone();
            let sleepers = s.sleepers.as_mut().expect("on sleepers");
            sleepers.exceptions.clear();
            if voided > 0 {
                sleepers.exceptions.push(ExceptionSection {
                    index: SleeperIndex::Range([first, first + voided - 1]),
                    gap: (gap > 0.0).then_some(gap),
                    law: Some(scenario::sleepers::BallastLawKind::Tensionless),
                    friction: None,
                    pad_scale: None,
                    ballast_scale: None,
                });
            }
            keys.push((voided, gap));
            cases.push(s.build()?);
        }
    }
    let swept = runner.sweep_many_keeping(&cases, &speeds)?;
    let failures = failed_runs(&swept, |c| format!("voided = {}, gap = {}", keys[c].0, keys[c].1));
    let runs = swept.iter().flatten().filter(|r| r.is_ok()).count();
    let curves: Vec<Curve> = keys
        .into_iter()
        .zip(swept)
        .map(|((voided, gap), rows)| Curve { voided, gap, points: finished(&rows), rows })
        .collect();
    let (summary, lines) = summary(&curves, &base, first);
    let model = base.model()?;
    let (sleepers, nodes) = model.sleepers().expect("on sleepers");
    let subtitle = format!(
        "{}; quarter car of {:.1} kN; voided sleepers from no. {first} at x = {:.1} m",
        report::sleeper_output::sleepers_in_words(sleepers, nodes.len()),
        base.load.force / 1e3,
        summary.first_voided_position
    );
    Ok(StudyData {
        csv: csv(&curves),
        summary: StudySummary::of(summary),
        lines,
        headline: headline(&curves),
        plots: figures(&curves, &subtitle),
        mean_iterations: mean_iterations(curves.iter().flat_map(|c| &c.points)),
        failures,
        ..blank(runs)
    })
}

/// One row per curve and speed: `voided,gap,speed,max_downward_deflection,max_pad_force,max_ballast_force,
/// exception_ballast_force,neighbour_ballast_force,exception_lowest,min_wheel_force,max_wheel_force,
/// losses_of_contact` (1, m, m/s, m, N, N, N, N, m, N, N, 1); a failed run's values empty.
fn csv(curves: &[Curve]) -> String {
    let mut out = String::from(
        "voided,gap,speed,max_downward_deflection,max_pad_force,max_ballast_force,exception_ballast_force,\
         neighbour_ballast_force,exception_lowest,min_wheel_force,max_wheel_force,losses_of_contact\n",
    );
    for c in curves {
        for r in &c.rows {
            let mut values = vec![c.voided as f64, c.gap];
            match r {
                Ok(p) => {
                    values.extend([p.speed, p.deflection.max_downward.value]);
                    values.extend(p.sleepers.map_or([f64::NAN; 5], |s| s.values()));
                    let v = p
                        .vehicles
                        .map_or([f64::NAN; 3], |v| [v.min_wheel_force, v.max_wheel_force, v.losses_of_contact as f64]);
                    values.extend(v);
                }
                Err(f) => values.extend([f.speed].into_iter().chain([f64::NAN; 9])),
            }
            let _ = writeln!(out, "{}", row_with_gaps(&values));
        }
    }
    out
}

/// What one curve found, each with its speed (m/s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct VoidedCurve {
    /// Voided sleepers side by side.
    pub voided: usize,
    /// Their void (m); 0: tensionless, no void.
    pub gap: f64,
    /// The largest rail deflection (m) and its speed.
    pub peak_deflection: f64,
    /// See `peak_deflection`.
    pub peak_deflection_speed: f64,
    /// The largest ballast force under the voided sleepers' neighbours (N; the intact track's largest where none).
    pub neighbour_ballast_force: f64,
    /// See `neighbour_ballast_force`.
    pub neighbour_ballast_force_speed: f64,
    /// The largest pad force (N).
    pub max_pad_force: f64,
    /// The smallest wheel–rail force (N) and its speed.
    pub min_wheel_force: f64,
    /// See `min_wheel_force`.
    pub min_wheel_force_speed: f64,
    /// The first speed at which the wheel left the rail; None if it never did.
    pub first_loss_of_contact_speed: Option<f64>,
}

/// The set-up and what each curve found.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct VoidedSummary {
    /// The first voided sleeper's number (0-based) and where it sits (m).
    pub first_voided: usize,
    /// See `first_voided`.
    pub first_voided_position: f64,
    /// The wheel's static load Q₀ (N).
    pub wheel_load: f64,
    /// One per (voided, gap).
    pub curves: Vec<VoidedCurve>,
}

fn summary(curves: &[Curve], base: &Scenario, first: usize) -> (VoidedSummary, Vec<String>) {
    let sleepers = base.sleepers.as_ref().expect("on sleepers");
    let x = sleepers.first.unwrap_or(0.5 * sleepers.spacing) + first as f64 * sleepers.spacing;
    let mut items = Vec::new();
    let mut lines = Vec::new();
    for c in curves {
        let (Some(peak), Some(neighbour), Some(pad), Some(weakest)) = (
            c.largest(|p| Some(p.deflection.max_downward.value)),
            c.largest(neighbour_force),
            c.largest(|p| p.sleepers.map(|s| s.max_pad_force)),
            c.largest(|p| min_wheel_force(p).map(|f| -f)),
        ) else {
            continue;
        };
        let lifts = c.points.iter().find(|p| p.vehicles.is_some_and(|v| v.losses_of_contact > 0)).map(|p| p.speed);
        items.push(VoidedCurve {
            voided: c.voided,
            gap: c.gap,
            peak_deflection: peak.1,
            peak_deflection_speed: peak.0,
            neighbour_ballast_force: neighbour.1,
            neighbour_ballast_force_speed: neighbour.0,
            max_pad_force: pad.1,
            min_wheel_force: -weakest.1,
            min_wheel_force_speed: weakest.0,
            first_loss_of_contact_speed: lifts,
        });
        let lift = lifts
            .map_or("the wheel stays on the rail".into(), |v| format!("the wheel leaves the rail from {v:.0} m/s"));
        lines.push(format!(
            "{}: rail deflection up to {:.3} mm (at {:.0} m/s), neighbouring ballast {:.1} kN, pads {:.1} kN, wheel \
             force down to {:.1} kN (at {:.0} m/s); {lift}",
            c.label(),
            peak.1 * 1e3,
            peak.0,
            neighbour.1 / 1e3,
            pad.1 / 1e3,
            -weakest.1 / 1e3,
            weakest.0
        ));
    }
    let summary =
        VoidedSummary { first_voided: first, first_voided_position: x, wheel_load: base.load.force, curves: items };
    (summary, lines)
}

/// The intact track against the worst case (three sleepers, the largest void).
fn headline(curves: &[Curve]) -> Vec<String> {
    let find = |voided: usize, gap: f64| curves.iter().find(|c| c.voided == voided && c.gap == gap);
    let (intact, worst) = (find(0, 0.0), find(VOIDED[3], GAPS[3]));
    let value = |c: Option<&Curve>, f: &dyn Fn(&SweepPoint) -> Option<f64>| {
        c.and_then(|c| c.largest(f)).map_or(f64::NAN, |v| v.1)
    };
    let deflection = |c| value(c, &|p| Some(p.deflection.max_downward.value)) * 1e3;
    let force = |c| value(c, &neighbour_force) / 1e3;
    let weakest = |c| -value(c, &|p| min_wheel_force(p).map(|f| -f)) / 1e3;
    vec![
        format!(
            "Three sleepers hanging {} mm above the ballast raise the rail's largest deflection under the quarter car \
             from {:.2} to {:.2} mm and the ballast force under their neighbours from {:.1} to {:.1} kN.",
            GAPS[3] * 1e3,
            deflection(intact),
            deflection(worst),
            force(intact),
            force(worst)
        ),
        format!(
            "The wheel force dips to {:.1} kN over them (intact track {:.1} kN) at 20–100 m/s.",
            weakest(worst),
            weakest(intact)
        ),
    ]
}

/// Deflection, neighbouring ballast force and smallest wheel force against speed for 0–3 sleepers at the largest
/// void; and the peak deflection against the void for 1–3 sleepers.
fn figures(curves: &[Curve], subtitle: &str) -> Vec<PlotSpec> {
    type Value = fn(&SweepPoint) -> Option<f64>;
    // Deflections in mm, forces in kN (the axes' factors).
    let quantities: [(&str, Axis, Value); 3] = [
        ("deflection", Axis::new("largest downward rail deflection", "deflection", Shown::Milli), |p| {
            Some(p.deflection.max_downward.value * 1e3)
        }),
        (
            "neighbour-force",
            Axis::new("largest ballast force beside the voids", "neighbour_ballast_force", Shown::Kilo),
            |p| neighbour_force(p).map(|f| f / 1e3),
        ),
        (
            "wheel-force",
            Axis::noted("smallest wheel–rail force", "min_wheel_force", Shown::Kilo, "0: contact lost"),
            |p| min_wheel_force(p).map(|f| f / 1e3),
        ),
    ];
    let speed = Axis::new("speed v", "speed", Shown::Si);
    let mut plots = Vec::new();
    let shown: Vec<&Curve> = curves.iter().filter(|c| c.voided == 0 || c.gap == GAPS[3]).collect();
    for (stem, y, value) in quantities {
        let title = format!("Voided sleepers ({} mm) under a quarter car: {}", GAPS[3] * 1e3, y.caption());
        let mut spec = PlotSpec::new(format!("voided-sleepers-{stem}"), &title, &speed, &y);
        spec.subtitle = subtitle.to_string();
        for c in &shown {
            let points: Vec<(f64, f64)> = c.points.iter().filter_map(|p| Some((p.speed, value(p)?))).collect();
            spec.series.push(Series {
                label: Some(c.label()),
                color: c.voided,
                stroke: Stroke::Solid,
                markers: true,
                points,
            });
        }
        plots.push(spec);
    }
    let mut spec = PlotSpec::new(
        "voided-sleepers-gap",
        "Voided sleepers: the largest rail deflection over 20–100 m/s against the void",
        &Axis::new("void under the sleepers", "gap", Shown::Milli),
        &Axis::new("largest downward rail deflection", "deflection", Shown::Milli),
    );
    spec.subtitle = subtitle.to_string();
    for voided in 1..VOIDED.len() {
        let points: Vec<(f64, f64)> = curves
            .iter()
            .filter(|c| c.voided == voided)
            .filter_map(|c| Some((c.gap * 1e3, c.largest(|p| Some(p.deflection.max_downward.value))?.1 * 1e3)))
            .collect();
        let label = format!("{voided} sleeper{}", if voided == 1 { "" } else { "s" });
        spec.series.push(Series { label: Some(label), color: voided, stroke: Stroke::Solid, markers: true, points });
    }
    plots.push(spec);
    plots
}
