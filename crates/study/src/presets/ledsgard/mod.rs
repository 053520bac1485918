//! Study 13: Ledsgård (docs/theory.md §19) — the X2000 on the soft site every ground-dynamics model is checked
//! against, from the built-in `examples/ledsgard`: the computed wave beside the records measured at 70 and 185 km/h
//! (one figure each), the deepest deflection over speed with the ground's critical speed and the Winkler control's,
//! and the same curve with ballast friction of 1, 2 and 5 kN/m — under the composite beam (acting on its whole
//! deflection against the ground beneath) and on the two-beam track (between the sleepers and the embankment, where
//! the ballast is) — how much friction cuts the response near the critical speed of a soft site, and where.

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
        "the site: examples/ledsgard built in (its profile, composite beam, two-beam track and X2000); the base \
         scenario is not used"
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
    pub deflection_at_185_km_per_h: f64,
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
    /// One per friction, under the composite beam.
    pub curves: Vec<LedsgardCurve>,
    /// One per friction, between the sleepers and the embankment of the two-beam track.
    pub two_beam_curves: Vec<LedsgardCurve>,
    /// At 70 and 185 km/h.
    pub measured: Vec<LedsgardComparison>,
}

pub(super) fn study(resolution: Resolution, _base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let sites = [site::site()?, site::two_beam_site()?];
    let speeds: Vec<f64> = speeds(resolution).iter().map(|v| v / KMH).collect();
    // One estimate for the whole study: the ground's numbers, the two records and the curves on both tracks (those
    // with friction at their measured cost over a linear wave's).
    let linear = crate::ground::numbers::SPECTRA + 2 + sites.len() * speeds.len();
    let with_friction = sites.len() * (FRICTIONS.len() - 1) * speeds.len();
    let layers = sites[0].ground.as_ref().map_or(0, |g| g.layers.len());
    runner.announce(runner::cost::Estimate::ground_waves(linear, with_friction, layers, runner.threads()));
    let ground = GroundStudy::of(&sites[0], &GroundRequest { frequencies: vec![5.0] }, &runner.silent())?;
    let mut measured = Vec::new();
    let mut compared_waves = Vec::new();
    for (speed_kmh, record) in site::records()? {
        let speed = speed_kmh / KMH;
        let window = record.widened(WaveWindow::default());
        let before = measured.len();
        let mut study =
            GroundWaveStudy::of(&sites[0], &[speed], window, runner.stop, &|n| (runner.progress)(before + n))?;
        study.compare_with(&record, "ledsgard")?;
        study.train.name = "X2000".into();
        let comparison = study.comparison.clone().expect("just compared");
        measured.push(LedsgardComparison { speed, comparison });
        compared_waves.push((speed_kmh, study, record));
    }
    let before = measured.len();
    let composite = curves(&sites[0], &speeds, runner, before)?;
    let two_beam = curves(&sites[1], &speeds, runner, before + FRICTIONS.len() * speeds.len())?;
    let summary = summarise(&ground, [&composite, &two_beam], measured);
    let plots = figures::figures(&ground, [&composite, &two_beam], &compared_waves);
    Ok(StudyData {
        csv: csv(&composite, &two_beam),
        lines: lines(&summary),
        headline: headline(&summary),
        summary: StudySummary::of(summary),
        plots,
        ..blank(sites.len() * FRICTIONS.len() * speeds.len() + 2)
    }
    .ran_on(sites.into()))
}

/// The curves over `speeds` on `site`, one per friction of [`FRICTIONS`], counting progress from `before`.
fn curves(site: &Scenario, speeds: &[f64], runner: &Runner, before: usize) -> Result<Vec<(f64, GroundWaveStudy)>> {
    let mut curves = Vec::new();
    // The curves differ in the friction alone: each speed's spectra are sampled once for the four.
    let spectra = crate::ground::SiteSpectra::new(site);
    for (i, friction) in FRICTIONS.into_iter().enumerate() {
        let before = before + i * speeds.len();
        let mut case = site.clone();
        if friction > 0.0 {
            case.friction.distributed =
                Some(scenario::DistributedSection { force_per_length: friction, ..Default::default() });
        }
        let progress = |n: usize| (runner.progress)(before + n);
        let mut study =
            GroundWaveStudy::sharing(&case, speeds, WaveWindow::default(), (runner.stop, &progress), &spectra)?;
        study.train.name = "X2000".into();
        curves.push((friction, study));
    }
    Ok(curves)
}

fn summarise(
    ground: &GroundStudy,
    [composite, two_beam]: [&[(f64, GroundWaveStudy)]; 2],
    measured: Vec<LedsgardComparison>,
) -> LedsgardSummary {
    LedsgardSummary {
        critical_speed: ground.critical_speed,
        winkler_critical_speed: ground.winkler_critical_speed,
        curves: composite.iter().map(curve).collect(),
        two_beam_curves: two_beam.iter().map(curve).collect(),
        measured,
    }
}

/// A curve's sampled deepest point and its value at [`RECORD_SPEED`].
fn curve((friction, study): &(f64, GroundWaveStudy)) -> LedsgardCurve {
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
        deflection_at_185_km_per_h: at_185,
    }
}

/// One row per friction and speed, the composite beam's then the two-beam track's: `force_per_length,speed,
/// max_downward_deflection,max_upward_deflection,friction_power,two_beam_max_downward_deflection,
/// two_beam_max_upward_deflection,two_beam_friction_power` (N/m, m/s, m, m, W, m, m, W).
fn csv(composite: &[(f64, GroundWaveStudy)], two_beam: &[(f64, GroundWaveStudy)]) -> String {
    let mut out = String::from(
        "force_per_length,speed,max_downward_deflection,max_upward_deflection,friction_power,\
         two_beam_max_downward_deflection,two_beam_max_upward_deflection,two_beam_friction_power\n",
    );
    let columns = |p: &crate::ground::wave_point::GroundWavePoint| {
        let power = p.friction.as_ref().map_or(0.0, |f| f.friction_power);
        [p.deflection.max_downward.value, p.deflection.max_upward.value, power]
    };
    for ((friction, study), (_, on_two_beams)) in composite.iter().zip(two_beam) {
        for (p, q) in study.points.iter().zip(&on_two_beams.points) {
            let values: Vec<f64> = [*friction, p.speed].into_iter().chain(columns(p)).chain(columns(q)).collect();
            let _ = writeln!(out, "{}", row(&values));
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
    for (track, curves) in [("composite beam", &summary.curves), ("two-beam track", &summary.two_beam_curves)] {
        for c in curves {
            lines.push(format!(
                "{track}, f_u = {:.0} kN/m: deepest {:.2} mm at {:.0} km/h (sampled), {:.2} mm at 185 km/h",
                c.force_per_length / 1e3,
                c.max_downward_deflection * 1e3,
                c.speed * KMH,
                c.deflection_at_185_km_per_h * 1e3
            ));
        }
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
    let two_beam = &summary.two_beam_curves;
    let (bare, rubbing) = (two_beam[0].max_downward_deflection, two_beam[two_beam.len() - 1].max_downward_deflection);
    vec![
        format!(
            "On the linear small-strain site the computed deepest deflection under the X2000 differs from the measured \
             one by {far}: near the critical speed the clay softened under large strains, which an equivalent-linear \
             soil would carry."
        ),
        format!(
            "Ballast friction of {:.0} kN/m under the composite beam, against the ground beneath, cuts the deepest \
             deflection over speed from {:.2} to {:.2} mm ({:.0} %).",
            strongest.force_per_length / 1e3,
            none.max_downward_deflection * 1e3,
            strongest.max_downward_deflection * 1e3,
            100.0 * (1.0 - strongest.max_downward_deflection / none.max_downward_deflection)
        ),
        format!(
            "Between the sleepers and the embankment of the two-beam track, where the ballast is, the same friction \
             moves the rail's deepest deflection over speed from {:.2} to {:.2} mm ({:.2} %): on a soft site the \
             ballast's compression is a small part of the rail's deflection, the rest the embankment's and the ground's.",
            bare * 1e3,
            rubbing * 1e3,
            100.0 * (1.0 - rubbing / bare)
        ),
    ]
}
