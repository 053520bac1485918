//! Study 5: dynamic amplification at mid-span, φ_w(τ) = w/w_sta and φ_M(τ) = M/M_sta, at ¼, ½, ¾ and 1 × v_cr for
//! f_u ∈ {1, 2} kN/m (docs/theory.md §6–§7).

use super::setups::{blank, with_distributed};
use super::study_data::{StudyData, StudySummary, keep_finished, nothing_finished};
use crate::metrics::{amplification, static_midspan};
use report::figures::quantity_figure;
use runner::Runner;
use scenario::Scenario;
use scenario::axis::{Axis, Shown};
use scenario::error::Result;
use scenario::number::row;
use scenario::speeds::SpeedScale;
use serde::Serialize;
use std::fmt::Write as _;

pub(super) fn study(base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let reference = static_midspan(&with_distributed(base, 0.0).build()?)?;
    let scale = SpeedScale::of(base)?;
    let speeds = [(0.25, 50.0), (0.5, 100.0), (0.75, 150.0), (1.0, 200.0)].map(|(f, v)| scale.fraction(f, v));
    let combos: Vec<(f64, f64)> = [1e3, 2e3].into_iter().flat_map(|f| speeds.map(|v| (f, v))).collect();
    // Built before any run: bad input is refused (exit 2), not recorded as a failed run.
    let cases = combos
        .iter()
        .map(|&(f, v)| {
            let mut s = with_distributed(base, f);
            s.load.speed = v;
            s.output.sections = vec![s.mesh.length / 2.0];
            s.build()
        })
        .collect::<Result<Vec<_>>>()?;
    let indices: Vec<usize> = (0..combos.len()).collect();
    runner.announce_runs(&cases);
    // A failed run is recorded and leaves its curve out; every other run is kept.
    let results = runner.map_each(&indices, |&i| {
        let ((f, v), case) = (combos[i], &cases[i]);
        let samples = runner.cached(&format!("{:016x}@{v}/midspan-amplification", case.fingerprint), || {
            let r = runner.simulate(case, &case.settings)?;
            Ok(amplification(&r.histories[0], reference, case.model.mesh().length))
        })?;
        Ok((f, v, samples))
    })?;
    let mut failures = Vec::new();
    let name = |i: usize| (format!("force_per_length = {}", combos[i].0), Some(combos[i].1));
    let results: Vec<_> = keep_finished(results, name, &mut failures).into_iter().map(|(_, r)| r).collect();
    if results.is_empty() {
        return Err(nothing_finished("the amplification study".into(), &failures));
    }
    let mut csv = String::from("force_per_length,speed,tau,phi_w,phi_m\n");
    let mut items = Vec::new();
    let mut lines = Vec::new();
    // (f_u, v, max φ_w, max φ_M) of each finished run.
    let mut maxima = Vec::new();
    for (f, v, samples) in &results {
        for a in samples {
            let _ = writeln!(csv, "{}", row(&[*f, *v, a.tau, a.deflection, a.moment]));
        }
        let max_w = samples.iter().fold(f64::NEG_INFINITY, |m, a| m.max(a.deflection));
        let max_m = samples.iter().fold(f64::NEG_INFINITY, |m, a| m.max(a.moment));
        maxima.push((*f, *v, max_w, max_m));
        items.push(AmplificationCurve { force_per_length: *f, speed: *v, max_phi_w: max_w, max_phi_m: max_m });
        lines.push(format!("f_u = {:.0} kN/m, v = {v} m/s: max φ_w {max_w:.3}, max φ_M {max_m:.3}", f / 1e3));
    }
    let plots = figures(&results, &speeds, reference);
    let headline = headline(&maxima);
    Ok(StudyData {
        csv,
        summary: StudySummary::of(AmplificationSummary { curves: items }),
        lines,
        headline,
        plots,
        failures,
        ..blank(results.len())
    })
}

/// The amplification at mid-span of each run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AmplificationSummary {
    /// One per friction level and speed.
    pub curves: Vec<AmplificationCurve>,
}

/// The largest amplifications of one run over the static mid-span response.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AmplificationCurve {
    /// f_u (N/m).
    pub force_per_length: f64,
    /// v (m/s).
    pub speed: f64,
    /// max φ_w = w/w_static at mid-span.
    pub max_phi_w: f64,
    /// max φ_M = M/M_static at mid-span.
    pub max_phi_m: f64,
}

/// The amplification at the fastest speed run, for both friction levels, from `maxima` (f_u, v, max φ_w, max φ_M).
fn headline(maxima: &[(f64, f64, f64, f64)]) -> Vec<String> {
    let top = maxima.iter().map(|m| m.1).fold(0.0, f64::max);
    let at = |f: f64| maxima.iter().find(|m| m.0 == f && m.1 == top).map_or((f64::NAN, f64::NAN), |m| (m.2, m.3));
    let ((w1, m1), (w2, m2)) = (at(1e3), at(2e3));
    vec![
        "Mid-span amplification grows with speed towards the critical speed.".into(),
        format!("At {top} m/s: max φ_w {w1:.2} and φ_M {m1:.2} with f_u = 1 kN/m, {w2:.2} and {m2:.2} with 2 kN/m."),
    ]
}

/// Per friction level, φ_w and φ_M along the crossing for each speed run (`results`: f_u, v, samples), against
/// the static reference.
fn figures(
    results: &[(f64, f64, Vec<crate::metrics::Amplification>)],
    speeds: &[f64],
    reference: crate::metrics::StaticReference,
) -> Vec<report::plot::PlotSpec> {
    let subtitle = format!(
        "w_sta = {:.2} mm, M_sta = {:.2} kN·m: mid-span static deflection and moment, load at mid-span, no friction",
        reference.deflection.abs() * 1e3,
        reference.moment.abs() / 1e3
    );
    let mut plots = Vec::new();
    for (f, kn) in [(1e3, 1), (2e3, 2)] {
        for (which, symbol, value) in [
            (
                "deflection",
                "φ(w) = w/w_sta",
                (|a: &crate::metrics::Amplification| a.deflection) as fn(&crate::metrics::Amplification) -> f64,
            ),
            ("moment", "φ(M) = M/M_sta", |a| a.moment),
        ] {
            // Fastest first, so that the slower, smaller curves are drawn on top and stay visible.
            let curves = results
                .iter()
                .enumerate()
                .filter(|(_, (ff, _, _))| *ff == f)
                .rev()
                .map(|(_, (_, v, samples))| {
                    let points = samples.iter().map(|a| (a.tau, value(a))).collect();
                    // The colour of the speed, whichever runs failed.
                    let color = 1 + speeds.iter().position(|s| s == v).unwrap_or(0);
                    (format!("v = {v} m/s"), color, points)
                })
                .collect();
            let mut plot = quantity_figure(
                &format!("amplification-{which}-{kn}kN"),
                &format!("Mid-span {which} amplification, f_u = {kn} kN/m"),
                &Axis::new("load position over length τ = x/L", "tau", Shown::Si),
                &Axis::new(symbol, "dynamic_amplification", Shown::Si),
                curves,
                false,
            );
            plot.subtitle = subtitle.clone();
            // The slow runs' curves nearly coincide (50 and 100 m/s): every second one dashed, so both show.
            for (k, series) in plot.series.iter_mut().enumerate() {
                if k % 2 == 1 {
                    series.stroke = report::plot::Stroke::Dashed;
                }
            }
            plots.push(plot);
        }
    }
    plots
}
