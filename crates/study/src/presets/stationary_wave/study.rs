//! Study 9: the stationary wave on the infinite track (docs/theory.md §13, §14): the peak deflection against speed
//! by the stationary solve for no friction and f_u ∈ {1, 2, 5, 10} kN/m, and for tensionless and bilinear (α = ½)
//! soils with the rail's weight, beside the finite beam's curves of the distributed-speed study (the same runs);
//! the deflection friction leaves behind the load, the waves' shapes at three speeds, and the critical-speed shift
//! and peak reduction on the infinite track.

use super::curves::{FRICTION, InfiniteCritical, InfiniteCurve, Soil, TENSION_RATIO};
use super::figures;
use crate::presets::curves::{Curves, CurvesSummary, sweep_curves};
use crate::presets::setups::{blank, mean_iterations, with_distributed};
use crate::presets::study_data::{StudyData, StudySummary};
use crate::stationary::output::{ErrorEstimate, StationaryPoint, StationaryStudy};
use analytic::golden::refine_peak;
use runner::Runner;
use runner::cost::Estimate;
use scenario::error::Result;
use scenario::speeds::SpeedScale;
use scenario::{FoundationLawKind, Scenario};
use serde::Serialize;
use stationary::{ContactGuess, Domain};
use std::fmt::Write as _;

pub(in crate::presets) fn study(
    resolution: crate::presets::resolution::Resolution,
    base: &Scenario,
    runner: &Runner,
) -> Result<StudyData> {
    let speeds = resolution.speeds(base)?;
    let scale = SpeedScale::of(base)?;
    let v_cr = scale.critical_speed;
    // The sampled speeds nearest ½, 1 and 1.25 v_cr: their waves are the sweep's.
    let nearest = |target: f64| speeds.iter().copied().min_by(|a, b| (a - target).abs().total_cmp(&(b - target).abs()));
    let shape_speeds: Vec<f64> = [0.5, 1.0, 1.25].iter().filter_map(|f| nearest(f * v_cr.unwrap_or(200.0))).collect();
    let finite_scenarios =
        FRICTION.iter().map(|&f| (vec![("force_per_length".into(), f)], with_distributed(base, f))).collect();
    let finite = sweep_curves(finite_scenarios, &speeds, runner)?;
    let soils = Soil::all();
    let first = speeds.first().copied().unwrap_or(0.0);
    let problems = soils.iter().map(|soil| soil.scenario(base).stationary_problem(first, Domain::default()));
    let solves = problems.map(|p| Ok(Estimate::stationary(&p?, &speeds, false))).collect::<Result<Vec<_>>>()?;
    runner.announce(Estimate::together(solves, runner.threads()));
    let infinite = runner.silent().map(&soils, |soil| {
        let scenario = soil.scenario(base);
        let stop = runner.stop;
        let study =
            StationaryStudy::of_until(&scenario, &speeds, Domain::default(), ErrorEstimate::Skip, stop, &|_| {})?;
        let (critical, refinement) = refine(&scenario, &study, (v_cr, stop))?;
        let shapes = shape_speeds
            .iter()
            .map(|v| {
                let at = study.points.iter().position(|p| p.speed == *v);
                at.and_then(|i| study.waves[i].clone()).filter(|w| w.convergence.is_converged())
            })
            .collect();
        Ok(InfiniteCurve { soil: *soil, study, critical, refinement, shapes })
    })?;
    let (summary, lines) = summary(&infinite, &finite, v_cr);
    Ok(StudyData {
        csv: csv(&infinite, &finite),
        summary: StudySummary::of(summary),
        lines,
        headline: headline(&infinite, &finite),
        plots: figures::plots(&infinite, &finite, &shape_speeds, base),
        mean_iterations: mean_iterations(finite.points.iter().flatten()),
        failures: finite.failures.clone(),
        ..blank(finite.runs)
    })
}

/// The peak of a curve: the largest sampled max downward deflection, refined by golden section between its
/// neighbours when both have waves; unbounded where the next speed has none because no wave exists there (undamped,
/// frictionless, at v_cr).
fn refine(
    scenario: &Scenario,
    study: &StationaryStudy,
    (v_cr, stop): (Option<f64>, Option<&std::sync::atomic::AtomicBool>),
) -> Result<(InfiniteCritical, Vec<(f64, f64)>)> {
    let points = &study.points;
    let found = |p: &StationaryPoint| p.deflection.max_downward.map(|e| e.value);
    let Some((i, peak)) =
        points.iter().enumerate().filter_map(|(i, p)| found(p).map(|w| (i, w))).max_by(|a, b| a.1.total_cmp(&b.1))
    else {
        return Ok((InfiniteCritical::None, Vec::new()));
    };
    let next = points.get(i + 1);
    if let (Some(next), Some(critical_speed)) = (next, v_cr)
        && next.status == "no stationary wave"
    {
        return Ok((InfiniteCritical::Unbounded { critical_speed, last_peak: peak }, Vec::new()));
    }
    let (Some(before), Some(after)) = (i.checked_sub(1).and_then(|j| points.get(j)), next) else {
        return Ok((InfiniteCritical::AtEnd { speed: points[i].speed, peak }, Vec::new()));
    };
    if found(before).is_none() || found(after).is_none() {
        return Ok((InfiniteCritical::AtEnd { speed: points[i].speed, peak }, Vec::new()));
    }
    // On the domain the sampled peak needed, so that each speed starts from the last one's wave.
    let (behind, ahead, element_length) = points[i].domain;
    let domain = Domain { behind, ahead, element_length };
    let mut guess = ContactGuess::default();
    let mut evaluated = Vec::new();
    let mut deflection = |v: f64| -> Result<f64> {
        let problem = scenario.stationary_problem(v, domain)?;
        let wave = stationary::solve_within(&problem, &mut guess, &stationary::Control::new(stop))?;
        // A speed without a wave inside the bracket cannot be the peak.
        if !wave.convergence.is_converged() {
            return Ok(f64::NEG_INFINITY);
        }
        let peak = wave.max_downward().value;
        evaluated.push((v, peak));
        Ok(peak)
    };
    let tolerance = 0.02 * (after.speed - before.speed) / 2.0;
    let bracket = (before.speed, after.speed);
    let (speed, peak) = refine_peak(&mut deflection, bracket, (points[i].speed, peak), tolerance)?;
    Ok((InfiniteCritical::Interior { speed, peak }, evaluated))
}

/// Long format: one row per curve and speed, infinite track first. Text cells: model ("infinite", "finite"),
/// foundation, status; empty cells where a value does not exist.
fn csv(infinite: &[InfiniteCurve], finite: &Curves) -> String {
    let mut out = String::from(
        "model,foundation,force_per_length,speed,status,max_downward_deflection,max_upward_deflection,\
         deflection_behind\n",
    );
    let cell = |x: Option<f64>| x.map_or(String::new(), |x| x.to_string());
    for curve in infinite {
        for p in &curve.study.points {
            let _ = writeln!(
                out,
                "infinite,{},{},{},{},{},{},{}",
                curve.soil.foundation,
                curve.soil.force_per_length,
                p.speed,
                p.status,
                cell(p.deflection.max_downward.map(|e| e.value)),
                cell(p.deflection.max_upward.map(|e| e.value)),
                cell(p.deflection_behind)
            );
        }
    }
    for (c, &f) in FRICTION.iter().enumerate() {
        for point in finite.speed_rows(c) {
            let (status, down, up) = match point {
                Ok(p) => ("finished", Some(p.deflection.max_downward.value), Some(p.deflection.max_upward.value)),
                Err(_) => ("failed", None, None),
            };
            let speed = point.as_ref().map_or_else(|f| f.speed, |p| p.speed);
            let _ = writeln!(out, "finite,linear,{f},{speed},{status},{},{},", cell(down), cell(up));
        }
    }
    out
}

/// Per curve: where it peaks and what friction leaves behind; the finite beam's curves as the distributed-speed
/// study reports them.
fn summary(infinite: &[InfiniteCurve], finite: &Curves, v_cr: Option<f64>) -> (StationarySummary, Vec<String>) {
    let mut items = Vec::new();
    let mut lines = Vec::new();
    for curve in infinite {
        let missing: Vec<f64> =
            curve.study.points.iter().filter(|p| p.status != "converged").map(|p| p.speed).collect();
        let behind = curve.study.points.iter().filter_map(|p| p.deflection_behind).fold(0.0f64, |m, w| m.max(w.abs()));
        items.push(InfiniteSummary {
            foundation: curve.soil.foundation,
            force_per_length: curve.soil.force_per_length,
            critical: curve.critical,
            speeds_without_wave: missing,
            largest_deflection_behind: behind,
        });
        lines.push(format!("infinite track, {}: {}", curve.soil.label(), critical_text(&curve.critical)));
    }
    lines.extend(crate::stationary::output::branch_note("tensionless").map(|n| format!("infinite track: {n}")));
    let (finite_summary, finite_lines) = finite.summary();
    lines.extend(finite_lines.into_iter().map(|l| format!("finite beam, {l}")));
    let summary =
        StationarySummary { critical_speed_of_the_infinite_beam: v_cr, infinite: items, finite: finite_summary };
    (summary, lines)
}

/// The infinite track's curves beside the finite beam's.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StationarySummary {
    /// v_cr of the infinite beam on the linear soil (m/s); None without a foundation.
    pub critical_speed_of_the_infinite_beam: Option<f64>,
    /// One per soil of the infinite track.
    pub infinite: Vec<InfiniteSummary>,
    /// The finite beam's curves (linear soil, each friction level).
    pub finite: CurvesSummary,
}

/// One soil's curve of stationary waves.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InfiniteSummary {
    /// "linear", "tensionless" or "bilinear".
    pub foundation: &'static str,
    /// f_u (N/m).
    pub force_per_length: f64,
    /// Where the curve peaks.
    pub critical: InfiniteCritical,
    /// The speeds without a wave (m/s).
    pub speeds_without_wave: Vec<f64>,
    /// The largest |deflection| left behind the load (m).
    pub largest_deflection_behind: f64,
}

/// A curve's peak in words: "at … m/s (peak … mm)" and what bounds it.
pub(in crate::presets) fn critical_text(critical: &InfiniteCritical) -> String {
    match *critical {
        InfiniteCritical::Interior { speed, peak } => format!("at {speed:.1} m/s (peak {:.0} mm)", peak * 1e3),
        InfiniteCritical::AtEnd { speed, peak } => {
            format!("at {speed:.1} m/s, an end of the speeds with a wave (peak there {:.0} mm)", peak * 1e3)
        }
        InfiniteCritical::Unbounded { critical_speed, last_peak } => format!(
            "at v_cr = {critical_speed:.1} m/s, where it grows without bound ({:.0} mm one step below; undamped, no \
             wave exists from v_cr on)",
            last_peak * 1e3
        ),
        InfiniteCritical::None => "nowhere (no wave found at any speed)".into(),
    }
}

/// The critical-speed shift and the peak reduction on the infinite track, and what the nonlinear soils do.
fn headline(infinite: &[InfiniteCurve], finite: &Curves) -> Vec<String> {
    let linear = |f: f64| infinite.iter().find(|c| c.soil.foundation == "linear" && c.soil.force_per_length == f);
    let text = |f: f64| linear(f).map_or("unknown".into(), |c| critical_text(&c.critical));
    let finite_text = |f: f64| finite.critical_text(finite.find("force_per_length", f));
    let peaks: Vec<String> = FRICTION[1..]
        .iter()
        .map(|&f| match linear(f).map(|c| c.critical) {
            Some(InfiniteCritical::Interior { peak, .. } | InfiniteCritical::AtEnd { peak, .. }) => {
                format!("{:.0}", peak * 1e3)
            }
            _ => "—".into(),
        })
        .collect();
    let nonlinear = |name: &str| infinite.iter().find(|c| c.soil.foundation == name);
    let reach = nonlinear("tensionless").map_or("unknown".into(), |c| {
        let last = c.study.points.iter().take_while(|p| p.status == "converged").last();
        last.map_or("at no speed".into(), |p| format!("up to {:.0} m/s", p.speed))
    });
    let bilinear = nonlinear("bilinear").map_or("unknown".into(), |c| critical_text(&c.critical));
    vec![
        format!(
            "On the infinite track the peak deflection lies {} without friction and {} with f_u = 10 kN/m; on the \
             finite beam the critical speed is {} and {}.",
            text(0.0),
            text(10e3),
            finite_text(0.0),
            finite_text(10e3)
        ),
        format!(
            "Ballast friction of 1, 2, 5 and 10 kN/m caps the infinite track's peak at {} mm; without friction a \
             tensionless soil's wave is found {reach}, and a bilinear soil's (α = {TENSION_RATIO}) peak lies \
             {bilinear}.",
            peaks.join(", ")
        ),
    ]
}

/// What of `base` the study replaces: the common rule (its friction: the study sets its own per curve), and its
/// soil's law (the study sets linear, tensionless and bilinear itself).
pub(in crate::presets) fn overrides(base: &Scenario) -> Vec<String> {
    let mut notes = crate::presets::preset::Preset::StationaryWave.common_overrides(base);
    if base.foundation.law != FoundationLawKind::Linear {
        notes.push(
            "the scenario's [foundation] law is not used: the study sets linear, tensionless and bilinear (α = ½) \
             soils itself"
                .into(),
        );
    }
    notes
}
