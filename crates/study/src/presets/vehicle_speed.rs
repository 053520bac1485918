//! Study 8: vehicles against the moving force (docs/theory.md §12). On the base track, three loads of equal static
//! weight — the moving force F, a moving mass F/g and the default quarter car scaled to F — each without friction
//! and with a friction set-up (the scenario's `[friction]`, else the HSLM study's devices), on a smooth and on an
//! irregular rail (the scenario's `[rail]`, else a German low-irregularity profile, seed 1): the max downward rail
//! deflection, the smallest wheel–rail force (0 once the wheel leaves the rail) and the largest body acceleration
//! against speed. A moving force feels no irregularity, so it runs once per friction set-up.
//!
//! The step must resolve the wheel–rail contact mode ([`track::vehicle::consist::MAX_CONTACT_STEP`]): the study caps
//! the time step (`integration.max_step`) where the load advance alone would not at the slower speeds, and says so
//! (lowering the load advance instead would give the fast speeds the slow ones' steps, which they do not need). On a
//! track it adds absorbing zones and takes the extremes over the middle third, as the HSLM study does, and every load
//! starts at rest in its static equilibrium at the end of the left zone: entering from the rigid ground, a moving mass
//! dropped into the soft reference track's 52 mm trough and still bounced ±37 % in the middle third at 30 m/s.

use super::hslm::friction_setups;
use super::resolution::Resolution;
use super::setups::{as_long_track, blank, mean_iterations};
use super::study_data::{StudyData, StudySummary, failed_runs};
use report::plot::{PlotSpec, Series, Stroke};
use runner::{Runner, SweepPoint, SweepRow, finished};
use scenario::axis::{Axis, Shown};
use scenario::error::Result;
use scenario::number::row_with_gaps;
use scenario::rail::IrregularitySection;
use scenario::vehicle::VehicleKind;
use scenario::{RailSection, Scenario, VehicleSection};
use serde::Serialize;
use std::fmt::Write as _;
use track::vehicle::consist::MAX_CONTACT_STEP;

/// The loads compared, in the files' order.
pub(super) const MODELS: [&str; 3] = ["moving-force", "moving-mass", "quarter-car"];
/// The rails, in the files' order.
pub(super) const RAILS: [&str; 2] = ["smooth", "irregular"];

/// The rail the study calls irregular: the scenario's `[rail]`, else German low irregularity over 1–80 m, seed 1.
fn irregular_rail(base: &Scenario) -> RailSection {
    if !base.rail.is_empty() {
        return base.rail.clone();
    }
    let random =
        IrregularitySection::Random { spectrum: "german-low".into(), band: Some([1.0, 80.0]), seed: 1, length: None };
    RailSection { irregularities: vec![random] }
}

/// The default vehicle of load `model` (1 moving mass, 2 quarter car). The study runs it on the one-axle train
/// `single` of F, which scales it to F ([`track::vehicle::consist::VehicleSettings::populate`]: masses, stiffness
/// and damping alike, so its frequencies and damping ratio stay).
fn vehicle(model: usize) -> VehicleSection {
    let kind = if model == 1 { VehicleKind::MovingMass } else { VehicleKind::QuarterCar };
    VehicleSection { kind, ..VehicleSection::default() }
}

/// The one-axle train the vehicles are scaled onto.
pub(super) const SINGLE: &str = "single";

/// `base` as the study runs it, and a sentence for each change: a long track, and a longest time step that resolves
/// the stiffest contact mode of the study's vehicles at every one of `speeds`, with 5 % to spare.
fn prepared(base: &Scenario, speeds: &[f64]) -> Result<(Scenario, Vec<String>)> {
    let mut s = base.clone();
    let mut notes = Vec::new();
    s.load.train = None;
    s.load.axles.clear();
    s.load.patches.clear();
    s.vehicle = None;
    s.rail = RailSection::default();
    if base.model()?.foundation().stiffness > 0.0 {
        as_long_track(&mut s, &mut notes, "the vehicles");
    }
    if s.integration.static_start.is_none() {
        let start = s.integration.steady_start.take().unwrap_or((s.mesh.length / 5.0).min(40.0));
        notes.push(format!(
            "every load starts at rest in its static equilibrium at {start:.1} m (integration.static_start): a vehicle \
             entering from the rigid ground would drop into the track's static trough, and on a soft track its bounce \
             would outlast the crossing"
        ));
        s.integration.static_start = Some(start);
    }
    let vehicles: Vec<VehicleSection> = (1..MODELS.len()).map(vehicle).collect();
    cap_contact_step(&mut s, speeds, &vehicles, &mut notes)?;
    Ok((s, notes))
}

/// Cap `s`'s step (`integration.max_step`) where its load advance at the slowest of `speeds` (m/s) would not
/// resolve the stiffest wheel–rail contact mode of `vehicles` (each on the one-axle train of F), 5 % to spare; a
/// sentence in `notes` when it does.
pub(super) fn cap_contact_step(
    s: &mut Scenario,
    speeds: &[f64],
    vehicles: &[VehicleSection],
    notes: &mut Vec<String>,
) -> Result<()> {
    let slowest = speeds.iter().copied().fold(f64::INFINITY, f64::min);
    let mut omega = 0.0f64;
    let axle = fem_beam::Train::single(s.load.force);
    for v in vehicles {
        let settings = v.settings(Some(&axle), |_| Ok(irregularity::Profile::Smooth))?;
        omega = omega.max(settings.contact_frequency()?);
    }
    let longest = 0.95 * MAX_CONTACT_STEP / omega;
    let step = s.integration.load_advance / slowest;
    if longest < step && s.integration.max_step.is_none_or(|h| h > longest) {
        notes.push(format!(
            "integration.max_step = {longest:.4e} s: the step resolves the wheel–rail contact mode ({:.0} Hz) below \
             {:.1} m/s, where the load advance of {} m would not",
            omega / std::f64::consts::TAU,
            s.integration.load_advance / longest,
            s.integration.load_advance,
        ));
        s.integration.max_step = Some(longest);
    }
    Ok(())
}

/// The parts of `base` the study replaces or adds, one sentence each.
pub(super) fn overrides(base: &Scenario) -> Vec<String> {
    let mut notes = Vec::new();
    let load = &base.load;
    if load.train.is_some() || !load.axles.is_empty() || !load.patches.is_empty() || base.vehicle.is_some() {
        notes.push("the scenario's train and [vehicle] are not used: the study runs its three loads of F".into());
    }
    if base.rail.is_empty() {
        notes
            .push("the irregular rail is German low irregularity over 1–80 m, seed 1 (give [rail] for another)".into());
    }
    if let Some((count, force)) = super::hslm::fallback_devices(base) {
        notes.push(format!(
            "the scenario has no [friction]: the study compares no friction with {}",
            scenario::devices_text(count, force)
        ));
    }
    if let Ok(speeds) = Resolution::Coarse.speeds(base)
        && let Ok((_, prepared)) = prepared(base, &speeds)
    {
        notes.extend(prepared);
    }
    notes
}

/// One curve: a load, a friction set-up, a rail, swept over speed.
struct Curve {
    model: usize,
    friction: usize,
    rail: usize,
    /// One row per speed, in the order of the speeds: a finished point or why the run failed.
    rows: Vec<SweepRow>,
    /// The finished points, in the order of the speeds.
    points: Vec<SweepPoint>,
}

/// A curve's case as text, for the failures: "model = quarter-car, friction = with, rail = irregular".
fn describe(model: usize, friction: usize, rail: usize) -> String {
    format!("model = {}, friction = {}, rail = {}", MODELS[model], FRICTION[friction], RAILS[rail])
}

/// The friction set-ups, in the files' order.
const FRICTION: [&str; 2] = ["none", "with"];

impl Curve {
    /// The smallest wheel force at a point (N): the force itself for the moving force.
    fn min_force(&self, p: &SweepPoint, force: f64) -> f64 {
        p.vehicles.map_or(force, |v| v.min_wheel_force)
    }

    /// The largest body acceleration at a point (m/s²): the quarter car's only — a moving mass is all wheel, its
    /// "body" rings with the contact, and a moving force has none.
    fn body_acceleration(&self, p: &SweepPoint) -> Option<f64> {
        p.vehicles.filter(|_| self.model == 2).map(|v| v.max_body_acceleration)
    }

    fn label(&self, friction: &str) -> String {
        let f = if self.friction == 0 { "no friction".to_string() } else { friction.to_string() };
        format!("{}, {f}", MODELS[self.model].replace('-', " "))
    }
}

pub(super) fn study(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let speeds = resolution.speeds(base)?;
    let (base, _) = prepared(base, &speeds)?;
    let (none, with, friction) = friction_setups(&base);
    let force = base.load.force;
    let irregular = irregular_rail(&base);
    let mut keys = Vec::new();
    let mut cases = Vec::new();
    for (f, set_up) in [&none, &with].into_iter().enumerate() {
        for model in 0..MODELS.len() {
            for (r, rail) in [RailSection::default(), irregular.clone()].into_iter().enumerate() {
                // A moving force feels no rail profile: one run serves both rails.
                if model == 0 && r == 1 {
                    continue;
                }
                let mut s = set_up.clone();
                if model > 0 {
                    s.vehicle = Some(vehicle(model));
                    s.load.train = Some(SINGLE.into());
                    s.rail = rail;
                }
                keys.push((model, f, r));
                cases.push(s.build()?);
            }
        }
    }
    // A failed run leaves a gap in its curve and is recorded; every other run is kept.
    let swept = runner.sweep_many_keeping(&cases, &speeds)?;
    let failures = failed_runs(&swept, |c| {
        let (model, f, r) = keys[c];
        // The moving force's one run stands for both rails.
        if model == 0 { format!("model = {}, friction = {}", MODELS[0], FRICTION[f]) } else { describe(model, f, r) }
    });
    let runs = swept.iter().flatten().filter(|r| r.is_ok()).count();
    let mut curves = Vec::new();
    for ((model, f, r), rows) in keys.into_iter().zip(swept) {
        let points = finished(&rows);
        if model == 0 {
            curves.push(Curve { model, friction: f, rail: 1, rows: rows.clone(), points: points.clone() });
        }
        curves.push(Curve { model, friction: f, rail: r, rows, points });
    }
    curves.sort_by_key(|c| (c.rail, c.friction, c.model));
    let (summary, lines) = summary(&curves, force, &friction, &base.integration);
    Ok(StudyData {
        csv: csv(&curves, force),
        summary: StudySummary::of(summary),
        lines,
        headline: headline(&curves, force),
        plots: figures(&curves, force, &friction),
        mean_iterations: mean_iterations(curves.iter().flat_map(|c| &c.points)),
        failures,
        ..blank(runs)
    })
}

/// One row per curve and speed: `model,friction,rail,speed,max_downward_deflection,min_wheel_force,max_wheel_force,
/// max_dynamic_increment,losses_of_contact,max_body_acceleration,rms_body_acceleration` (text, text, text, m/s, m, N,
/// N, 1, 1, m/s², m/s²); the moving force's wheel force is F and its body columns empty, as is every value of a
/// failed run (why: the JSON's failures).
fn csv(curves: &[Curve], force: f64) -> String {
    let mut out = String::from(
        "model,friction,rail,speed,max_downward_deflection,min_wheel_force,max_wheel_force,max_dynamic_increment,\
         losses_of_contact,max_body_acceleration,rms_body_acceleration\n",
    );
    for c in curves {
        for r in &c.rows {
            let values = match r {
                Ok(p) => {
                    let vehicle = p.vehicles.map_or([force, force, 0.0, 0.0, f64::NAN, f64::NAN], |v| v.values());
                    let mut values = vec![p.speed, p.deflection.max_downward.value];
                    values.extend(vehicle);
                    values
                }
                Err(f) => [f.speed].into_iter().chain([f64::NAN; 7]).collect(),
            };
            let (model, friction, rail) = (MODELS[c.model], FRICTION[c.friction], RAILS[c.rail]);
            let _ = writeln!(out, "{model},{friction},{rail},{}", row_with_gaps(&values));
        }
    }
    out
}

/// What a curve shows: its peak deflection, its smallest wheel force, where a wheel first left the rail and its
/// largest body acceleration, each with its speed (m/s).
struct Findings {
    /// (speed, max downward deflection (m)) of the largest deflection.
    peak: (f64, f64),
    /// (speed, wheel force (N)) of the smallest wheel force.
    weakest: (f64, f64),
    /// The first speed at which a wheel lost contact.
    lifts: Option<f64>,
    /// (speed, body acceleration (m/s²)) of the largest, for the quarter car.
    body: Option<(f64, f64)>,
}

impl Curve {
    /// The findings of the curve; None when none of its runs finished.
    fn findings(&self, force: f64) -> Option<Findings> {
        let peak = self
            .points
            .iter()
            .max_by(|a, b| a.deflection.max_downward.value.total_cmp(&b.deflection.max_downward.value))?;
        let weakest =
            self.points.iter().min_by(|a, b| self.min_force(a, force).total_cmp(&self.min_force(b, force)))?;
        let lifts = self.points.iter().find(|p| p.vehicles.is_some_and(|v| v.losses_of_contact > 0)).map(|p| p.speed);
        let body = self.points.iter().filter_map(|p| self.body_acceleration(p).map(|a| (p.speed, a)));
        Some(Findings {
            peak: (peak.speed, peak.deflection.max_downward.value),
            weakest: (weakest.speed, self.min_force(weakest, force)),
            lifts,
            body: body.max_by(|a, b| a.1.total_cmp(&b.1)),
        })
    }
}

/// The vehicles against the moving force over speed: the set-up and what each curve found.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct VehicleSummary {
    /// The axle load Q₀ (N).
    pub force: f64,
    /// The friction set-up, in words.
    pub friction_setup: String,
    /// Δx (m).
    pub load_advance: f64,
    /// The longest step (s), if capped.
    pub max_step: Option<f64>,
    /// One per load model, friction set-up and rail.
    pub curves: Vec<VehicleCurve>,
}

/// What one curve found: its peak deflection, the smallest wheel force, the first loss of contact and the largest
/// body acceleration, each with its speed (m/s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct VehicleCurve {
    /// "moving-force", "moving-mass" or "quarter-car".
    pub model: &'static str,
    /// "none" or "with".
    pub friction: &'static str,
    /// "smooth" or "irregular".
    pub rail: &'static str,
    /// m.
    pub peak_max_downward_deflection: f64,
    /// m/s.
    pub peak_speed: f64,
    /// N.
    pub min_wheel_force: f64,
    /// m/s.
    pub min_wheel_force_speed: f64,
    /// m/s; None if no wheel left the rail.
    pub first_loss_of_contact_speed: Option<f64>,
    /// m/s²; None without a body.
    pub max_body_acceleration: Option<f64>,
    /// m/s.
    pub max_body_acceleration_speed: Option<f64>,
}

/// Per curve: the peak deflection and its speed, the smallest wheel force and its speed, the first speed where a
/// wheel lost contact, the largest body acceleration and its speed.
fn summary(
    curves: &[Curve],
    force: f64,
    friction: &str,
    integration: &scenario::IntegrationSection,
) -> (VehicleSummary, Vec<String>) {
    let mut items = Vec::new();
    let mut lines = Vec::new();
    for c in curves {
        let Some(f) = c.findings(force) else { continue };
        items.push(VehicleCurve {
            model: MODELS[c.model],
            friction: FRICTION[c.friction],
            rail: RAILS[c.rail],
            peak_max_downward_deflection: f.peak.1,
            peak_speed: f.peak.0,
            min_wheel_force: f.weakest.1,
            min_wheel_force_speed: f.weakest.0,
            first_loss_of_contact_speed: f.lifts,
            max_body_acceleration: f.body.map(|b| b.1),
            max_body_acceleration_speed: f.body.map(|b| b.0),
        });
        let lift =
            f.lifts.map_or("never leaves the rail".to_string(), |v| format!("first leaves the rail at {v:.0} m/s"));
        let body = f.body.map_or(String::new(), |(v, a)| format!(", body up to {a:.2} m/s² (at {v:.0} m/s)"));
        lines.push(format!(
            "{} rail, {}: peak deflection {:.1} mm at {:.0} m/s; wheel force down to {:.1} kN (at {:.0} m/s), {lift}{body}",
            RAILS[c.rail],
            c.label(friction),
            f.peak.1 * 1e3,
            f.peak.0,
            f.weakest.1 / 1e3,
            f.weakest.0
        ));
    }
    let summary = VehicleSummary {
        force,
        friction_setup: friction.to_string(),
        load_advance: integration.load_advance,
        max_step: integration.max_step,
        curves: items,
    };
    (summary, lines)
}

/// The peaks of the three loads on the smooth rail without friction, and the quarter car's wheel and body on the
/// irregular rail.
fn headline(curves: &[Curve], force: f64) -> Vec<String> {
    let pick = |model: usize, rail: usize| {
        curves.iter().find(|c| c.model == model && c.friction == 0 && c.rail == rail).and_then(|c| c.findings(force))
    };
    let peak = |f: &Option<Findings>| {
        let (speed, w) = f.as_ref().map_or((f64::NAN, f64::NAN), |f| f.peak);
        format!("{:.1} mm at {:.0} m/s", 1e3 * w, speed)
    };
    let rough = pick(2, 1);
    let lift = match rough.as_ref().and_then(|f| f.lifts) {
        Some(speed) => format!("leaves the rail from {speed:.0} m/s on"),
        None => {
            let weakest = rough.as_ref().map_or(f64::NAN, |f| f.weakest.1);
            format!("keeps at least {:.1} kN on the rail", weakest / 1e3)
        }
    };
    let body = rough.as_ref().and_then(|f| f.body).map_or(f64::NAN, |b| b.1);
    vec![
        format!(
            "On the smooth rail without friction the peak rail deflection is {} under the moving force, {} under the \
             moving mass and {} under the quarter car.",
            peak(&pick(0, 0)),
            peak(&pick(1, 0)),
            peak(&pick(2, 0))
        ),
        format!("On the irregular rail the quarter car's wheel {lift}, its body reaching {body:.2} m/s²."),
    ]
}

/// A quantity of a curve at a point, None where the curve has none.
type Quantity<'a> = dyn Fn(&Curve, &SweepPoint) -> Option<f64> + 'a;

/// For each rail: deflection, smallest wheel force and body acceleration against speed; the loads by colour
/// (moving force black), friction dashed.
fn figures(curves: &[Curve], force: f64, friction: &str) -> Vec<PlotSpec> {
    let mut plots = Vec::new();
    for (r, rail) in RAILS.iter().enumerate() {
        // Each title names what the figure compares: only the quarter car has a body, so its figure compares the
        // car without and with friction, not the loads.
        let deflection = Axis::new("max downward rail deflection", "deflection", Shown::Milli);
        let wheel = Axis::noted("smallest wheel–rail force", "min_wheel_force", Shown::Kilo, "0: contact lost");
        let (mm, kn) = (deflection.factor(), wheel.factor());
        let quantities: [(&str, &str, Axis, &Quantity<'_>); 3] = [
            ("deflection", "Vehicles vs moving force", deflection, &|_, p| Some(p.deflection.max_downward.value * mm)),
            ("wheel-force", "Vehicles vs moving force", wheel, &|c, p| Some(c.min_force(p, force) * kn)),
            (
                "body-acceleration",
                "Quarter car without and with friction",
                Axis::new("largest body acceleration", "max_body_acceleration", Shown::Si),
                &|c, p| c.body_acceleration(p),
            ),
        ];
        let speed = Axis::new("speed v", "speed", Shown::Si);
        for (stem, compared, y, value) in quantities {
            let title = format!("{compared}, {rail} rail: {}", y.caption());
            let mut spec = PlotSpec::new(format!("vehicle-speed-{stem}-{rail}"), &title, &speed, &y);
            for c in curves.iter().filter(|c| c.rail == r) {
                let points: Vec<(f64, f64)> =
                    c.points.iter().filter_map(|p| value(c, p).map(|y| (p.speed, y))).collect();
                if points.is_empty() {
                    continue;
                }
                let stroke = if c.friction == 0 { Stroke::Solid } else { Stroke::Dashed };
                spec.series.push(Series {
                    label: Some(c.label(friction)),
                    color: c.model,
                    stroke,
                    markers: true,
                    points,
                });
            }
            plots.push(spec);
        }
    }
    plots
}
