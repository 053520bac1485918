//! Study 12: the track's receptance (docs/theory.md §17, §18) — the linear questions every track model answers. On
//! the scenario's sleepers (else the typical ballasted track in place of its soil), an Euler–Bernoulli and a
//! Timoshenko rail (the scenario's G and κ, else UIC60's 81 GPa and 0.4), each on the sleepers — the point
//! receptance at mid-span between the two sleepers nearest mid-track and above the first of them — and on the
//! equivalent continuous support (the continuous twin: k_eq, c_eq and the sleepers' long-wave mass): |α| and phase
//! over 10 Hz – 2 kHz, log-spaced, the resonances refined and named.

use super::discrete_track::{TYPICAL, fit_mesh, sleepers_unless_given};
use super::resolution::Resolution;
use super::setups::blank;
use super::study_data::{StudyData, StudySummary};
use crate::receptance::peaks::Resonance;
use crate::receptance::{ReceptanceRequest, ReceptanceStudy};
use fem_beam::BeamTheory;
use report::plot::{Mark, PlotSpec, Series, Stroke};
use runner::Runner;
use scenario::axis::{Axis, Shown};
use scenario::error::Result;
use scenario::number::row;
use scenario::sleepers::SleepersSection;
use scenario::{AbsorbingZonesSection, Scenario};
use serde::Serialize;
use std::fmt::Write as _;

/// The frequency range (Hz).
const RANGE: (f64, f64) = (10.0, 2000.0);
/// Elements a bay: ten a bending wavelength of the Timoshenko rail up to 2 kHz (0.075 m at a = 0.6 m).
const ELEMENTS_PER_BAY: usize = 8;

/// Log-spaced frequencies over [`RANGE`]: 200 (coarse) or 1000 (paper).
fn frequencies(resolution: Resolution) -> Vec<f64> {
    let n = match resolution {
        Resolution::Coarse => 200,
        Resolution::Paper => 1000,
    };
    let (a, b) = (RANGE.0.ln(), RANGE.1.ln());
    (0..n).map(|i| (a + (b - a) * i as f64 / (n - 1) as f64).exp()).collect()
}

/// The Timoshenko rail the study compares: the scenario's, else UIC60 (G = 81 GPa, κ = 0.4).
fn timoshenko(base: &Scenario) -> BeamTheory {
    match base.beam.theory {
        t @ BeamTheory::Timoshenko { .. } => t,
        BeamTheory::EulerBernoulli => BeamTheory::Timoshenko { shear_modulus: 81e9, shear_coefficient: 0.4 },
    }
}

/// `base` as the study runs it, with a sentence for each change: on sleepers, eight elements a bay, absorbing
/// zones so that the track answers as an infinite one.
fn prepared(base: &Scenario) -> Result<(Scenario, Vec<String>)> {
    let mut s = base.clone();
    let mut notes = Vec::new();
    sleepers_unless_given(&mut s, SleepersSection::default(), TYPICAL, &mut notes);
    if let Some(section) = s.sleepers.as_mut().filter(|x| !x.exceptions.is_empty()) {
        section.exceptions.retain(|e| e.gap.is_none() && e.law.is_none() && e.friction.is_none());
        notes.push(
            "the receptance is the linear track's: voided, tensionless and frictional sleepers are left out".into(),
        );
    }
    fit_mesh(&mut s, ELEMENTS_PER_BAY, &mut notes);
    if s.foundation.absorbing_zones.is_none() {
        let zones = AbsorbingZonesSection { length: (s.mesh.length / 5.0).min(40.0), ..Default::default() };
        notes.push(format!("absorbing zones of {:.1} m at the ends, so that no wave comes back", zones.length));
        s.foundation.absorbing_zones = Some(zones);
    }
    Ok((s, notes))
}

/// The parts of `base` the study replaces or adds, one sentence each.
pub(super) fn overrides(base: &Scenario) -> Vec<String> {
    prepared(base).map(|(_, notes)| notes).unwrap_or_default()
}

/// One curve: a rail on a support, read at a place.
struct Curve {
    rail: &'static str,
    support: &'static str,
    place: &'static str,
    study: ReceptanceStudy,
}

impl Curve {
    fn label(&self) -> String {
        match self.support {
            "sleepers" => format!("{}, {}", self.rail, self.place),
            _ => format!("{}, continuous k_eq", self.rail),
        }
    }
}

pub(super) fn study(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let (discrete, _) = prepared(base)?;
    let frequencies = frequencies(resolution);
    let model = discrete.model()?;
    let (sleepers, nodes) = model.sleepers().expect("on sleepers");
    let middle = nodes.len() / 2;
    let above = model.mesh().node_x(nodes[middle]);
    let mid_span = above + 0.5 * sleepers.spacing;
    let mut curves = Vec::new();
    for (rail, theory) in [("Euler–Bernoulli", BeamTheory::EulerBernoulli), ("Timoshenko", timoshenko(base))] {
        let mut on_sleepers = discrete.clone();
        on_sleepers.beam.theory = theory;
        let twin = on_sleepers.continuous_twin()?;
        let cases: [(&'static str, &'static str, &Scenario, f64); 3] = [
            ("sleepers", "mid-span", &on_sleepers, mid_span),
            ("sleepers", "above a sleeper", &on_sleepers, above),
            ("continuous", "mid-span", &twin, mid_span),
        ];
        for (support, place, scenario, x) in cases {
            let request = ReceptanceRequest { frequencies: frequencies.clone(), excite: x, at: x };
            let study = ReceptanceStudy::of(scenario, &request, runner)?;
            curves.push(Curve { rail, support, place, study });
        }
    }
    let subtitle = format!(
        "{}; point receptance at x = {mid_span:.2} m (mid-span) and {above:.2} m (above a sleeper)",
        report::sleeper_output::sleepers_in_words(sleepers, nodes.len())
    );
    let (summary, lines) = summary(&curves);
    Ok(StudyData {
        csv: csv(&curves),
        summary: StudySummary::of(summary),
        lines,
        headline: headline(&curves),
        plots: figures(&curves, &subtitle),
        ..blank(curves.len() * frequencies.len())
    })
}

/// One row per curve and frequency: `rail,support,place,frequency,magnitude,phase,real,imaginary` (text, text, text,
/// Hz, m/N, degrees, m/N, m/N).
fn csv(curves: &[Curve]) -> String {
    let mut out = String::from("rail,support,place,frequency,magnitude,phase,real,imaginary\n");
    for c in curves {
        for p in &c.study.points {
            let values = row(&[p.frequency, p.magnitude, p.phase, p.real, p.imaginary]);
            let _ = writeln!(out, "{},{},{},{values}", c.rail, c.support, c.place);
        }
    }
    out
}

/// One curve's resonances and doubts.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReceptanceCurve {
    /// "Euler–Bernoulli" or "Timoshenko".
    pub rail: &'static str,
    /// "sleepers" or "continuous".
    pub support: &'static str,
    /// "mid-span" or "above a sleeper".
    pub place: &'static str,
    /// x (m).
    pub at: f64,
    /// The refined, named peaks of |α|.
    pub resonances: Vec<Resonance>,
    /// What makes the curve doubtful.
    pub warnings: Vec<String>,
}

/// The receptance study's findings.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReceptanceSummary {
    /// One per rail, support and place.
    pub curves: Vec<ReceptanceCurve>,
}

fn summary(curves: &[Curve]) -> (ReceptanceSummary, Vec<String>) {
    let mut items = Vec::new();
    let mut lines = Vec::new();
    for c in curves {
        let peaks: Vec<String> = c
            .study
            .resonances
            .iter()
            .map(|r| format!("{:.0} Hz{}", r.frequency, r.name.map_or(String::new(), |n| format!(" ({n})"))))
            .collect();
        lines.push(format!(
            "{}: {}",
            c.label(),
            if peaks.is_empty() { "no resonance".into() } else { peaks.join(", ") }
        ));
        items.push(ReceptanceCurve {
            rail: c.rail,
            support: c.support,
            place: c.place,
            at: c.study.at,
            resonances: c.study.resonances.clone(),
            warnings: c.study.warnings.clone(),
        });
    }
    (ReceptanceSummary { curves: items }, lines)
}

/// The pinned–pinned resonance of either rail at mid-span.
fn headline(curves: &[Curve]) -> Vec<String> {
    let pinned = |rail: &str| {
        curves
            .iter()
            .find(|c| c.rail == rail && c.support == "sleepers" && c.place == "mid-span")
            .and_then(|c| c.study.resonances.iter().find(|r| r.name == Some("pinned–pinned")))
            .map_or("none in 10 Hz – 2 kHz".to_string(), |r| format!("{:.0} Hz", r.frequency))
    };
    vec![
        format!(
            "On sleepers the pinned–pinned resonance at mid-span is {} for the Timoshenko rail and {} for the \
             Euler–Bernoulli rail, whose missing shear and rotary inertia stiffen the short waves.",
            pinned("Timoshenko"),
            pinned("Euler–Bernoulli")
        ),
        "Above a sleeper it is a dip, and the continuous support of the same long-wave stiffness has neither it nor the \
         rail-on-pad resonance."
            .into(),
    ]
}

/// |α| over frequency (log–log) for the six curves, and the Timoshenko rail's phase.
fn figures(curves: &[Curve], subtitle: &str) -> Vec<PlotSpec> {
    let color = |c: &Curve| match (c.support, c.place) {
        ("continuous", _) => 0,
        (_, "mid-span") => 1,
        _ => 2,
    };
    let stroke = |c: &Curve| if c.rail == "Timoshenko" { Stroke::Solid } else { Stroke::Dashed };
    let mut magnitude = PlotSpec::new(
        "receptance-magnitude",
        "The track's point receptance: Euler–Bernoulli (dashed) and Timoshenko (solid) rails",
        &Axis::new("frequency", "frequency", Shown::Si),
        &Axis::new("receptance |α|", "magnitude", Shown::Si),
    );
    magnitude.log_x = true;
    magnitude.log_y = true;
    magnitude.subtitle = subtitle.to_string();
    let mut phase = PlotSpec::new(
        "receptance-phase",
        "The track's point receptance, Timoshenko rail: phase",
        &Axis::new("frequency", "frequency", Shown::Si),
        &Axis::new("phase of α", "phase", Shown::Si),
    );
    phase.log_x = true;
    phase.subtitle = subtitle.to_string();
    for c in curves {
        let points = |value: fn(&crate::receptance::ReceptancePoint) -> f64| {
            c.study.points.iter().map(|p| (p.frequency, value(p))).collect::<Vec<_>>()
        };
        // The refined resonances are points of the curve (a sharp pinned–pinned peak falls between the grid's
        // frequencies: drawn from the grid alone it stood 8–10× below its refined height), each marked.
        let mut curve = points(|p| p.magnitude);
        for r in &c.study.resonances {
            report::figures::insert_refined(&mut curve, (r.frequency, r.magnitude));
            magnitude.marks.push(Mark { color: color(c), point: (r.frequency, r.magnitude) });
        }
        magnitude.series.push(Series {
            label: Some(c.label()),
            color: color(c),
            stroke: stroke(c),
            markers: false,
            points: curve,
        });
        if c.rail == "Timoshenko" {
            phase.series.push(Series {
                label: Some(c.label()),
                color: color(c),
                stroke: Stroke::Solid,
                markers: false,
                points: points(|p| p.phase),
            });
        }
    }
    if !magnitude.marks.is_empty() {
        magnitude.mark_label = "resonance (refined between grid frequencies)".into();
    }
    vec![magnitude, phase]
}
