//! Study 11: friction at the sleepers against the thesis's friction distributed in the ballast (docs/theory.md §7,
//! §18). The base track on sleepers — the scenario's `[sleepers]`, else light sleepers every 0.6 m holding its soil
//! ([`super::discrete_track::sleepers_for_soil`]) — and its continuous twin (the same long-wave support and mass,
//! [`Scenario::continuous_twin`]), each without friction and with f_u ∈ {2, 5} kN/m: distributed on
//! the continuous track (the thesis's ballast friction on the rail), a Coulomb slider of F = f_u·a between each
//! sleeper and the ballast on the discrete one — the same force per metre. Max deflection, dissipated energy and the
//! refined critical speed of each curve: how much of the thesis's friction the sleepers keep, and the discrete
//! track's critical speed against the continuous one's.

use super::curves::{Curves, curves_study};
use super::discrete_track::{fit_mesh, sleepers_for_soil, sleepers_unless_given};
use super::resolution::Resolution;
use super::setups::with_distributed;
use super::study_data::StudyData;
use report::figures::dissipated_energy_axis;
use report::plot::PlotSpec;
use runner::Runner;
use scenario::Scenario;
use scenario::error::Result;
use scenario::sleepers::{ExceptionSection, SleeperIndex};

/// Friction per metre compared (N/m); 0: none.
const FORCES: [f64; 3] = [0.0, 2e3, 5e3];

/// The discrete track the study runs, with a sentence for each change.
fn discrete(base: &Scenario) -> Result<(Scenario, Vec<String>)> {
    let mut s = base.clone();
    let mut notes = Vec::new();
    s.friction = Default::default();
    if s.sleepers.is_none() {
        let what = "light sleepers (a tenth of the rail's mass over a bay) every 0.6 m whose pads and ballast in \
                    series hold its soil's spring and dashpot";
        sleepers_unless_given(&mut s, sleepers_for_soil(base)?, what, &mut notes);
    }
    if let Some(section) = s.sleepers.as_mut().filter(|x| !x.exceptions.is_empty()) {
        section.exceptions.clear();
        notes.push("the scenario's [[sleepers.exceptions]] are not used".into());
    }
    fit_mesh(&mut s, super::discrete_track::ELEMENTS_PER_BAY, &mut notes);
    Ok((s, notes))
}

/// The discrete track with a slider of `force_per_length`·a at every sleeper.
fn with_sliders(discrete: &Scenario, force_per_length: f64) -> Result<Scenario> {
    let mut s = discrete.clone();
    let count = s.model()?.sleepers().map_or(0, |(_, nodes)| nodes.len());
    let section = s.sleepers.as_mut().expect("on sleepers");
    if force_per_length > 0.0 && count > 0 {
        section.exceptions.push(ExceptionSection {
            index: SleeperIndex::Range([0, count - 1]),
            gap: None,
            law: None,
            friction: Some(force_per_length * section.spacing),
            pad_scale: None,
            ballast_scale: None,
        });
    }
    Ok(s)
}

/// The parts of `base` the study replaces, one sentence each.
pub(super) fn overrides(base: &Scenario) -> Vec<String> {
    let mut notes = Vec::new();
    if base.friction.devices.is_some() || base.friction.distributed.is_some() {
        notes.push("the scenario's [friction] is not used: the study compares its own friction".into());
    }
    if let Ok((_, prepared)) = discrete(base) {
        notes.extend(prepared);
    }
    notes
}

pub(super) fn study(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let (discrete, _) = discrete(base)?;
    let continuous = discrete.continuous_twin()?;
    let model = discrete.model()?;
    let (sleepers, nodes) = model.sleepers().expect("on sleepers");
    let spacing = sleepers.spacing;
    let subtitle = format!(
        "{}; its continuous twin k = {:.4} MN/m², ρA + {:.1} kg/m (the sleepers' long-wave mass)",
        report::sleeper_output::sleepers_in_words(sleepers, nodes.len()),
        continuous.foundation.stiffness / 1e6,
        (continuous.beam.mass_per_length() - discrete.beam.mass_per_length())
    );
    let mut scenarios = Vec::new();
    for (track, label) in [(&continuous, 0.0), (&discrete, 1.0)] {
        for f in FORCES {
            let s = if label == 0.0 { with_distributed(track, f) } else { with_sliders(track, f)? };
            scenarios.push((vec![("sleepers".into(), label), ("force_per_length".into(), f)], s));
        }
    }
    curves_study(
        scenarios,
        &resolution.speeds(&discrete)?,
        runner,
        &|curves| {
            let legend = |c: usize| {
                let (track, f) = (c / FORCES.len(), FORCES[c % FORCES.len()]);
                match (track, f > 0.0) {
                    (0, false) => "continuous, no friction".to_string(),
                    (0, true) => format!("continuous, {} kN/m in ballast", f / 1e3),
                    (_, false) => "sleepers, no friction".to_string(),
                    (_, true) => format!("sleepers, {} kN each (≙ {} kN/m)", f * spacing / 1e3, f / 1e3),
                }
            };
            // Two panels, the continuous track above and the sleepers below on a shared y range; within each one
            // colour per friction level, the same for the equal friction per metre in both (one colour per curve
            // in one panel left near hues side by side: orange beside vermillion, sky blue beside blue).
            let color = |c: usize| [0, 1, 4][c % FORCES.len()];
            let tracks: [(&str, Vec<usize>); 2] = [
                ("continuous track: friction in the ballast", (0..FORCES.len()).collect()),
                ("on sleepers: a slider at each sleeper", (FORCES.len()..2 * FORCES.len()).collect()),
            ];
            let deflection = |members: &[usize]| curves.deflection_plot("", "", members, &legend, &color);
            let dissipated = |members: &[usize]| {
                let y = dissipated_energy_axis();
                curves.quantity_plot("", "", &y, |q| q.energy.dissipated / 1e3, members, &legend, &color)
            };
            let paneled = |stem: &str, title: &str, panel: &dyn Fn(&[usize]) -> PlotSpec| {
                let mut spec = panel(&[]);
                (spec.stem, spec.title, spec.subtitle) = (stem.into(), title.into(), subtitle.clone());
                spec.panels =
                    tracks.iter().map(|(name, members)| PlotSpec { title: (*name).into(), ..panel(members) }).collect();
                spec
            };
            let plots = vec![
                paneled(
                    "sleeper-friction-deflection",
                    "Friction at the sleepers vs in the ballast: max deflection vs speed",
                    &deflection,
                ),
                paneled(
                    "sleeper-friction-dissipated",
                    "Friction at the sleepers vs in the ballast: dissipated energy vs speed",
                    &dissipated,
                ),
            ];
            plots
        },
        headline,
    )
}

/// The critical speeds of the two tracks without friction, and the peaks with the most friction.
fn headline(curves: &Curves) -> Vec<String> {
    let find = |track: f64, f: f64| {
        (0..curves.len())
            .find(|&c| curves.label(Some(c), "sleepers") == track && curves.label(Some(c), "force_per_length") == f)
    };
    let top = FORCES[FORCES.len() - 1];
    vec![
        format!(
            "Without friction the track on sleepers has its critical speed at {}, its continuous twin at {}.",
            curves.critical_text(find(1.0, 0.0)),
            curves.critical_text(find(0.0, 0.0))
        ),
        format!(
            "With {} kN/m of friction the peak deflection is {:.3} mm at the sleepers against {:.3} mm in the ballast.",
            top / 1e3,
            curves.peak(find(1.0, top)) * 1e3,
            curves.peak(find(0.0, top)) * 1e3
        ),
    ]
}
