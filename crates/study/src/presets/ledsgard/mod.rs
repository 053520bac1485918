//! Study 13: Ledsgård (docs/theory.md §19) — the X2000 on the soft site every ground-dynamics model is checked
//! against, from the built-in `examples/ledsgard`: the computed wave beside the records measured at 70 and 185 km/h
//! (one figure each), the deepest deflection over speed with the ground's critical speed and the Winkler control's,
//! and the same curve with ballast friction of 1, 2 and 5 kN/m under the composite beam — how much friction cuts the
//! response near the critical speed of a soft site.

mod figures;
mod site;

use super::resolution::Resolution;
use super::setups::blank;
use super::study_data::{StudyData, StudySummary};
use crate::ground::comparison::Comparison;
use crate::ground::numbers::{GroundRequest, GroundStudy};
use crate::ground::wave::{GroundWaveStudy, WaveWindow};
use runner::Runner;
use scenario::Scenario;
use scenario::error::Result;
use scenario::number::row;
use scenario::units::KMH;
use serde::Serialize;
use std::fmt::Write as _;

/// The ballast's friction of the curves (N/m): none, then the 1, 2 and 5 kN/m.
pub(super) const FRICTIONS: [f64; 4] = [0.0, 1000.0, 2000.0, 5000.0];

/// The speed of the faster record (km/h), always among the curves' speeds.
const RECORD_SPEED: f64 = 185.0;

/// The train speeds (km/h): 100 to 280 every 20 (coarse) or every 5 (paper), and [`RECORD_SPEED`].
fn speeds(resolution: Resolution) -> Vec<f64> {
    let step = match resolution {
        Resolution::Coarse => 20.0,
        Resolution::Paper => 5.0,
    };
    let count = (180.0 / step) as usize + 1;
    let mut speeds: Vec<f64> = (0..count).map(|i| 100.0 + step * i as f64).collect();
    if !speeds.contains(&RECORD_SPEED) {
        speeds.push(RECORD_SPEED);
        speeds.sort_by(f64::total_cmp);
    }
    speeds
}

/// What the study replaces: all of the base scenario (the site is built in).
pub(super) fn overrides(_base: &Scenario) -> Vec<String> {
    vec![
        "the site: examples/ledsgard built in (its profile, composite beam and X2000); the base scenario is not used"
            .into(),
    ]
}

/// One curve of the deepest deflection over speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LedsgardCurve {
    /// f_u (N/m).
    pub force_per_length: f64,
    /// The deepest deflection over the sampled speeds (m) and its speed (m/s): a sampled peak, not a refined one.
    pub max_downward_deflection: f64,
    /// At (m/s).
    pub speed: f64,
    /// The deepest deflection at 185 km/h (m), where the record is.
    pub at_185_km_per_h: f64,
}

/// The record beside the computed wave at one speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LedsgardComparison {
    /// v (m/s).
    pub speed: f64,
    /// What the comparison found (peaks at the record's points, RMS misfit, placement).
    pub comparison: Comparison,
}

/// The study's JSON summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LedsgardSummary {
    /// The track's critical speed on the ground for one load (m/s), refined (`frictrack ground`).
    pub critical_speed: Option<f64>,
    /// The same beam's on the static strip stiffness (m/s).
    pub winkler_critical_speed: f64,
    /// One per friction.
    pub curves: Vec<LedsgardCurve>,
    /// At 70 and 185 km/h.
    pub measured: Vec<LedsgardComparison>,
}

pub(super) fn study(resolution: Resolution, _base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let site = site::site()?;
    let speeds: Vec<f64> = speeds(resolution).iter().map(|v| v / KMH).collect();
    // One estimate for the whole study: the ground's numbers, the two records and the curves (those with friction
    // at their measured cost over a linear wave's).
    let linear = crate::ground::numbers::SPECTRA + 2 + speeds.len();
    let with_friction = (FRICTIONS.len() - 1) * speeds.len();
    runner.announce(runner::cost::Estimate::ground_waves(linear, with_friction, runner.threads()));
    let ground = GroundStudy::of(&site, &GroundRequest { frequencies: vec![5.0] }, &runner.silent())?;
    let mut measured = Vec::new();
    let mut compared_waves = Vec::new();
    for (speed_kmh, record) in site::records()? {
        let speed = speed_kmh / KMH;
        let window = record.widened(WaveWindow::default());
        let before = measured.len();
        let mut study = GroundWaveStudy::of(&site, &[speed], window, runner.stop, &|n| (runner.progress)(before + n))?;
        study.compare_with(&record, "ledsgard")?;
        study.train.name = "X2000".into();
        let comparison = study.comparison.clone().expect("just compared");
        measured.push(LedsgardComparison { speed, comparison });
        compared_waves.push((speed_kmh, study, record));
    }
    let mut curves = Vec::new();
    for (i, friction) in FRICTIONS.into_iter().enumerate() {
        let before = measured.len() + i * speeds.len();
        let mut case = site.clone();
        if friction > 0.0 {
            case.friction.distributed =
                Some(scenario::DistributedSection { force_per_length: friction, ..Default::default() });
        }
        let progress = |n: usize| (runner.progress)(before + n);
        let mut study = GroundWaveStudy::of(&case, &speeds, WaveWindow::default(), runner.stop, &progress)?;
        study.train.name = "X2000".into();
        curves.push((friction, study));
    }
    let summary = summarise(&ground, &curves, measured);
    let plots = figures::figures(&ground, &curves, &compared_waves);
    Ok(StudyData {
        csv: csv(&curves),
        lines: lines(&summary),
        headline: headline(&summary),
        summary: StudySummary::of(summary),
        plots,
        ..blank(FRICTIONS.len() * speeds.len() + 2)
    })
}

fn summarise(
    ground: &GroundStudy,
    curves: &[(f64, GroundWaveStudy)],
    measured: Vec<LedsgardComparison>,
) -> LedsgardSummary {
    let curves = curves
        .iter()
        .map(|(friction, study)| {
            let deepest = study
                .points
                .iter()
                .max_by(|a, b| a.deflection.max_downward.value.total_cmp(&b.deflection.max_downward.value))
                .expect("speeds");
            let at_185 = study
                .points
                .iter()
                .find(|p| (p.speed * KMH - RECORD_SPEED).abs() < 1e-6)
                .map_or(f64::NAN, |p| p.deflection.max_downward.value);
            LedsgardCurve {
                force_per_length: *friction,
                max_downward_deflection: deepest.deflection.max_downward.value,
                speed: deepest.speed,
                at_185_km_per_h: at_185,
            }
        })
        .collect();
    LedsgardSummary {
        critical_speed: ground.critical_speed,
        winkler_critical_speed: ground.winkler_critical_speed,
        curves,
        measured,
    }
}

/// One row per friction and speed: `force_per_length,speed,max_downward_deflection,max_upward_deflection,
/// friction_power` (N/m, m/s, m, m, W).
fn csv(curves: &[(f64, GroundWaveStudy)]) -> String {
    let mut out = String::from("force_per_length,speed,max_downward_deflection,max_upward_deflection,friction_power\n");
    for (friction, study) in curves {
        for p in &study.points {
            let power = p.friction.as_ref().map_or(0.0, |f| f.friction_power);
            let values =
                row(&[*friction, p.speed, p.deflection.max_downward.value, p.deflection.max_upward.value, power]);
            let _ = writeln!(out, "{values}");
        }
    }
    out
}

fn lines(summary: &LedsgardSummary) -> Vec<String> {
    let mut lines: Vec<String> = summary
        .measured
        .iter()
        .map(|m| {
            let c = &m.comparison;
            format!(
                "{:.0} km/h: computed {:.2} mm down against {:.2} measured, RMS misfit {:.2} mm against the record's {:.2}",
                m.speed * KMH,
                c.computed_max_downward * 1e3,
                c.measured_max_downward * 1e3,
                c.rms_misfit * 1e3,
                c.rms_measured * 1e3
            )
        })
        .collect();
    for c in &summary.curves {
        lines.push(format!(
            "f_u = {:.0} kN/m: deepest {:.2} mm at {:.0} km/h (sampled), {:.2} mm at 185 km/h",
            c.force_per_length / 1e3,
            c.max_downward_deflection * 1e3,
            c.speed * KMH,
            c.at_185_km_per_h * 1e3
        ));
    }
    lines
}

fn headline(summary: &LedsgardSummary) -> Vec<String> {
    let far = summary
        .measured
        .iter()
        .map(|m| {
            let c = &m.comparison;
            format!(
                "{:.0} % at {:.0} km/h",
                100.0 * (c.computed_max_downward - c.measured_max_downward) / c.measured_max_downward,
                m.speed * KMH
            )
        })
        .collect::<Vec<_>>()
        .join(" and ");
    let (none, strongest) = (&summary.curves[0], &summary.curves[summary.curves.len() - 1]);
    vec![
        format!(
            "On the linear small-strain site the computed deepest deflection under the X2000 differs from the measured \
             one by {far}: near the critical speed the clay softened under large strains, which an equivalent-linear \
             soil would carry."
        ),
        format!(
            "Ballast friction of {:.0} kN/m under the track cuts the deepest deflection over speed from {:.2} to \
             {:.2} mm ({:.0} %).",
            strongest.force_per_length / 1e3,
            none.max_downward_deflection * 1e3,
            strongest.max_downward_deflection * 1e3,
            100.0 * (1.0 - strongest.max_downward_deflection / none.max_downward_deflection)
        ),
    ]
}
