//! Study 7: the Eurocode high-speed load model HSLM-A1 … A10 (EN 1991-2 §6.4.6.1.1, docs/theory.md §10) over the
//! base scenario, a track or a bridge: max downward deflection and max deck acceleration vs speed for the ten trains,
//! without friction and with a friction set-up (the scenario's `[friction]`, else devices of 50 kN at the density of
//! 31 on 200 m: 31 on the reference track, 3 on a 20 m span); the envelope over the trains with the critical train
//! and speed; the resonance speeds v = f_j·D/i (a train of coaches of length D loads the structure periodically at
//! v/D; its i-th harmonic meets the natural frequency f_j there).
//!
//! On a span (no foundation, pinned ends) the deck-acceleration check needs frequencies up to f_max = max(30 Hz,
//! 1.5 f₁, f₃): the study reduces the load advance, where needed, to the one that resolves f_max with 20 steps per
//! period at the lowest speed, and says so. On a span each train's refined acceleration peak is checked against the
//! EN 1990 A2.4.4.2.1 limit of its deck's track (`[output] deck_track`: 3.5 m/s² ballasted, 5 m/s² direct
//! fastening), a verdict per train and set-up ([`super::hslm_verdict`]); on a track the "deck" is the rail and nothing
//! is checked.

use super::resonances::{Resonance, natural_frequencies, resonances};
use super::results::{Results, TrainCurve, coach_length, friction_name};
use super::verdict::{DeckLimit, larger, near_limit_peaks};
use crate::presets::resolution::Resolution;
use crate::presets::setups::{blank, mean_iterations, with_devices};
use crate::presets::study_data::{StudyData, StudyFailure, failed_runs, nothing_finished};
use fem_beam::Train;
use fem_beam::train::HSLM_A;
use runner::{Metric, RefinedPeak, Runner, SweepPoint, finished, refine_maximum, unrefined};
use scenario::diagnostics::{deck_frequency, resolving_advance};
use scenario::error::{Result, StudyError};
use scenario::number::row_with_gaps;
use scenario::{Case, Scenario, devices_text};
use std::fmt::Write as _;

/// km/h per m/s.
/// The friction set-up when the scenario has none: devices of F_u = 50 kN (the middle force of study 1) at the
/// density of its strongest set, 31 on the 200 m reference track ([`fallback_devices`]).
const FALLBACK_FORCE: f64 = 50e3;
/// The trains: HSLM-A1 … A10.
pub(in crate::presets) const TRAINS: usize = HSLM_A.len();
/// Samples of the bracket around each sampled maximum before golden section ([`refine_maximum`]): the largest
/// acceleration over the nodes has two peaks 0.7 m/s apart at HSLM-A3's resonance on the example deck, which
/// golden section alone may tell apart wrongly (7.76 instead of 7.91 m/s²).
pub(in crate::presets) const PEAK_SCAN: usize = 7;

/// The devices the study compares when `base` has no `[friction]`: N = round(31·L/200 m), at least 1 (3 on a 20 m
/// span), of 50 kN; None when the scenario gives its own friction.
pub(in crate::presets) fn fallback_devices(base: &Scenario) -> Option<(usize, f64)> {
    let f = &base.friction;
    (f.devices.is_none() && f.distributed.is_none())
        .then(|| (((31.0 * base.mesh.length / 200.0).round() as usize).max(1), FALLBACK_FORCE))
}

/// The study's two set-ups on `base`: without any friction, and with the scenario's `[friction]` (else the fallback
/// devices) and its description.
pub(in crate::presets) fn friction_setups(base: &Scenario) -> (Scenario, Scenario, String) {
    let none = with_devices(base, 0, 0.0);
    if let Some((count, force)) = fallback_devices(base) {
        return (none, with_devices(base, count, force), devices_text(count, force));
    }
    (none, base.clone(), base.friction.describe().unwrap_or_default())
}

/// `base` as the study runs it, with a sentence for each change (docs/theory.md §10). On a span, the load advance
/// the slowest speed needs to resolve the deck-acceleration band. On a track, what stands for the infinite track a
/// 400 m train needs: absorbing zones at the ends unless the scenario has its own (undamped, the 200 m reference
/// track keeps the waves of 50 axles trapped between its pinned ends, and its maxima jump by ±4 % between speeds
/// 2 km/h apart; with zones they vary smoothly), and the extremes over the nodes of the middle third unless
/// `[output] extremes_nodes` is given (a train longer than the beam is always entering or leaving over a support).
fn prepared(base: &Scenario, speeds: &[f64]) -> Result<(Scenario, Vec<String>)> {
    let mut s = base.clone();
    let mut notes = Vec::new();
    let slowest = speeds.iter().copied().fold(f64::INFINITY, f64::min);
    match deck_frequency(&base.model()?) {
        Some((f_max, _)) => {
            let needed = resolving_advance(f_max, slowest);
            if needed < s.integration.load_advance {
                notes.push(format!(
                    "integration.load_advance = {} m is reduced to {needed:.4} m so that the step resolves the deck \
                     accelerations up to {f_max:.1} Hz with 20 steps per period at the lowest speed, {slowest:.1} m/s",
                    s.integration.load_advance
                ));
                s.integration.load_advance = needed;
            }
        }
        None => crate::presets::setups::as_long_track(&mut s, &mut notes, "the trains"),
    }
    Ok((s, notes))
}

/// The parts of `base` the study replaces or adds, one sentence each.
pub(in crate::presets) fn overrides(base: &Scenario) -> Vec<String> {
    let mut notes = Vec::new();
    let load = &base.load;
    if load.train.is_some() || !load.axles.is_empty() || !load.patches.is_empty() {
        notes.push("the scenario's train is not used: the study runs HSLM-A1 … A10".to_string());
    }
    if let Some((count, force)) = fallback_devices(base) {
        notes.push(format!(
            "the scenario has no [friction]: the study compares no friction with {}, the density of 31 devices on \
             200 m (give [friction] to compare another set-up)",
            devices_text(count, force)
        ));
    }
    // Both resolutions start at 140 km/h, so the coarse grid's lowest speed is the paper grid's too.
    if let Ok((_, prepared)) = prepared(base, &Resolution::Coarse.train_speeds(base)) {
        notes.extend(prepared);
    }
    notes
}

impl Results {
    fn csv(&self) -> String {
        let mut out = String::from(
            "train,friction,speed,max_downward_deflection,max_upward_deflection,max_acceleration,\
             dynamic_amplification,static_max_downward_deflection,dissipated_energy,window_max_downward_deflection,\
             window_max_upward_deflection,deck_acceleration\n",
        );
        for c in &self.curves {
            for p in &c.points {
                let values = [
                    p.speed,
                    p.deflection.max_downward.value,
                    p.deflection.max_upward.value,
                    p.max_acceleration.map_or(f64::NAN, |a| a.value),
                    p.deflection.max_downward.value / c.static_max,
                    c.static_max,
                    p.energy.dissipated,
                    p.window_deflection.max_downward.value,
                    p.window_deflection.max_upward.value,
                    p.deck_acceleration(),
                ];
                let _ = writeln!(out, "hslm-a{},{},{}", c.train, friction_name(c.friction), row_with_gaps(&values));
            }
        }
        out
    }
}

pub(in crate::presets) fn study(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let speeds = resolution.train_speeds(base);
    let (base, _) = prepared(base, &speeds)?;
    let (none, with, friction) = friction_setups(&base);
    let scenarios = train_scenarios([&none, &with]);
    let case = base.build()?;
    // A span has natural frequencies that trains excite at f_j·D/i; a track on a Winkler foundation has none (its FE
    // modes crowd at the cut-off frequency, an artefact of its finite length), and loads of constant magnitude
    // below v_cr radiate no waves: with absorbing zones its curves show no such resonance.
    let span = deck_frequency(&case.model).is_some();
    let frequencies = if span { natural_frequencies(&case.model) } else { None };
    let range = (speeds[0], speeds[speeds.len() - 1]);
    let resonances_of =
        |train: usize| frequencies.as_deref().map_or_else(Vec::new, |f| resonances(f, coach_length(train), range));
    let cases = scenarios.iter().map(|(_, s)| s.build()).collect::<Result<Vec<_>>>()?;
    // Each curve runs the common speeds and its train's resonance speeds f₁·D/i, where its peaks are.
    let grids: Vec<Vec<f64>> = (0..cases.len())
        .map(|c| {
            let mut grid = speeds.clone();
            grid.extend(resonances_of(train_of(c)).iter().filter(|r| r.mode == 1).map(|r| r.speed));
            grid.sort_by(f64::total_cmp);
            grid.dedup();
            grid
        })
        .collect();
    // A failed run leaves a gap in its curve; a failed refinement leaves the curve's peaks unrefined (their
    // resolution the sweep's bracket); each is recorded, and the study goes on.
    let curve_name =
        |c: usize| format!("HSLM-A{}, {}", train_of(c), if c < TRAINS { "no friction" } else { "friction" });
    let tolerance = 0.02 * (speeds[1] - speeds[0]);
    // Each curve's two peaks (deflection, acceleration) are refined after the sweep: counted in its estimate.
    let refinements = 2 * runner::refinement_runs(speeds[1] - speeds[0], tolerance, PEAK_SCAN);
    let rows = runner.clone().with_refinement(refinements).sweep_grids_keeping(&cases, &grids)?;
    let mut failures = failed_runs(&rows, curve_name);
    let points: Vec<Vec<SweepPoint>> = rows.iter().map(|r| finished(r)).collect();
    if let Some(c) = points.iter().position(Vec::is_empty) {
        return Err(nothing_finished(curve_name(c), &failures));
    }
    let limit = span.then(|| base.output.deck_track.acceleration_limit());
    let refined = refine_peaks(&cases, &points, (tolerance, limit), runner, &mut |c, e| {
        failures.push(StudyFailure { case: curve_name(c), speed: None, error: format!("peaks not refined: {e}") })
    })?;
    let advance = base.integration.load_advance;
    let statics = runner.silent().map(&(1..=TRAINS).collect::<Vec<_>>(), |&k| {
        let nodes = case.settings.record.extremes_nodes;
        let train = base.on_the_beam(Train::hslm_a(k));
        Ok(track::statics::static_envelope(&case.model, &case.interactions, &train, advance, nodes)?.max_downward)
    })?;
    let runs = points.iter().map(Vec::len).sum::<usize>()
        + refined.iter().map(|(d, a)| d.evaluations.len() + a.evaluations.len()).sum::<usize>();
    let results = Results {
        curves: train_curves(points, refined, &statics, resonances_of),
        axle_share: base.axle_share(),
        friction,
        frequencies,
        acceleration_limit: span.then(|| DeckLimit::of(base.output.deck_track)),
        load_advance: advance,
        tolerance,
        extremes_nodes: base.output.extremes_nodes,
    };
    let (summary, lines) = results.summary();
    Ok(StudyData {
        csv: results.csv(),
        summary: crate::presets::study_data::StudySummary::of(summary),
        lines,
        headline: results.headline(),
        plots: results.figures(),
        mean_iterations: mean_iterations(results.curves.iter().flat_map(|c| &c.points)),
        failures,
        ..blank(runs)
    })
}

/// The HSLM train (1–10) of curve `curve` of the study (the set-up major).
fn train_of(curve: usize) -> usize {
    curve % TRAINS + 1
}

/// Curve i of the study (train i mod 10 + 1, set-up i / 10): its swept points, its refined deflection and
/// acceleration peaks, all of them to draw in order of speed, the train's static maximum (`statics`, by train) and
/// its resonance speeds.
fn train_curves(
    points: Vec<Vec<SweepPoint>>,
    refined: Vec<(RefinedPeak, RefinedPeak)>,
    statics: &[f64],
    resonances_of: impl Fn(usize) -> Vec<Resonance>,
) -> Vec<TrainCurve> {
    let curves = points.into_iter().zip(refined).enumerate();
    curves
        .map(|(i, (points, (deflection, acceleration)))| {
            let train = train_of(i);
            let mut drawn = points.clone();
            drawn.extend(deflection.evaluations.iter().chain(&acceleration.evaluations).cloned());
            drawn.sort_by(|a, b| a.speed.total_cmp(&b.speed));
            TrainCurve {
                train,
                friction: i / TRAINS,
                points,
                critical: deflection.into(),
                acceleration,
                drawn,
                static_max: statics[train - 1],
                resonances: resonances_of(train),
            }
        })
        .collect()
}

/// The ten HSLM trains on each friction set-up, labelled by train and set-up, the set-up major.
fn train_scenarios(set_ups: [&Scenario; 2]) -> Vec<(Vec<(String, f64)>, Scenario)> {
    let mut scenarios = Vec::with_capacity(2 * TRAINS);
    for (f, set_up) in set_ups.into_iter().enumerate() {
        for k in 1..=TRAINS {
            let mut s = set_up.clone();
            s.load.train = Some(format!("hslm-a{k}"));
            s.load.axles.clear();
            s.load.patches.clear();
            scenarios.push((vec![("train".to_string(), k as f64), ("friction".to_string(), f as f64)], s));
        }
    }
    scenarios
}

/// Each curve's peaks of the max downward deflection and of the max acceleration, refined to `tolerance` (m/s) on
/// fresh runs; where a refinement fails, `failed` is told and the sweep's own maxima stand (their resolution the
/// bracket).
/// With a deck limit, every other local maximum of the acceleration sampled near it is refined too and the largest
/// stands ([`near_limit_peaks`]): a verdict of "within" must hold for every peak, not only the largest sampled one.
fn refine_peaks(
    cases: &[Case],
    points: &[Vec<SweepPoint>],
    (tolerance, limit): (f64, Option<f64>),
    runner: &Runner,
    failed: &mut dyn FnMut(usize, StudyError),
) -> Result<Vec<(RefinedPeak, RefinedPeak)>> {
    let ids: Vec<usize> = (0..cases.len()).collect();
    let refined = runner.silent().map_each(&ids, |&c| {
        let refine =
            |metric, sweep: &[SweepPoint]| refine_maximum(&cases[c], sweep, metric, (tolerance, PEAK_SCAN), runner);
        let deflection = refine(Metric::MaxDownwardDeflection, &points[c])?;
        let mut acceleration = refine(Metric::DeckAcceleration, &points[c])?;
        for i in limit.map_or_else(Vec::new, |l| near_limit_peaks(&points[c], &acceleration, l)) {
            acceleration = larger(acceleration, refine(Metric::DeckAcceleration, &points[c][i - 1..=i + 1])?);
        }
        Ok((deflection, acceleration))
    })?;
    let peaks = refined.into_iter().enumerate().map(|(c, result)| {
        result.unwrap_or_else(|e| {
            failed(c, e);
            let sweep = |metric| unrefined(&points[c], metric).expect("a finished run");
            (sweep(Metric::MaxDownwardDeflection), sweep(Metric::DeckAcceleration))
        })
    });
    Ok(peaks.collect())
}

#[cfg(test)]
#[path = "tests.rs"]
mod tests;
