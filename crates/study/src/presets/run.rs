//! Running a study: the preset's own run on the checked base scenario, its figures naming a rail other than the
//! default, and the set-ups studies share (friction by devices or distributed, a long track, a blank result).

use super::preset::Preset;
use super::resolution::Resolution;
use super::study_data::{StudyData, StudySummary};
use report::plot::PlotSpec;
use runner::{Runner, SweepPoint};
use scenario::error::Result;
use scenario::{AbsorbingZonesSection, DevicesSection, DistributedSection, Scenario};

/// Run `preset` on top of `base` (normally the reference case), checked first: a bad key is named as the user wrote
/// it (`sleepers.spacing`), not as what a preset derives from it (`mesh.elements`).
pub fn run_preset(preset: Preset, resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    base.validate()?;
    let mut data = (preset.entry().run)(resolution, base, runner)?;
    name_the_rail(preset, base, &mut data.plots);
    let header = data.csv.lines().next().unwrap_or_default();
    let columns = header.split(',').map(|c| (c.to_string(), column_unit(c))).collect();
    Ok(StudyData { columns, name: preset.name(), title: preset.title(), resolution: resolution.name(), ..data })
}

/// The unit the study's files give a column: its quantity's ([`scenario::quantities`]), or "unknown" (never a
/// guess; `study/tests/studies.rs` runs every study and fails on a column without a listed quantity).
fn column_unit(column: &str) -> &'static str {
    scenario::quantities::unit_of(column).unwrap_or("unknown")
}

/// A figure pasted alone into a report names a rail that is not the default Euler–Bernoulli one, first in its
/// subtitle (the receptance study draws both rails and says which in its legends).
fn name_the_rail(preset: Preset, base: &Scenario, plots: &mut [PlotSpec]) {
    let Some(rail) = base.beam.theory.unless_default().filter(|_| preset != Preset::Receptance) else { return };
    for plot in plots {
        plot.subtitle =
            if plot.subtitle.is_empty() { format!("{rail} rail") } else { format!("{rail} rail; {}", plot.subtitle) };
    }
}

/// On a track, what stands for an infinite one under long loads (`what`, e.g. "the trains"): absorbing zones of
/// min(40 m, L/5) at the ends unless the scenario has its own (an undamped track keeps the waves trapped between its
/// pinned ends), and the extremes over the nodes of the middle third unless `[output] extremes_nodes` is given (loads
/// entering and leaving over a support set off transients there); a sentence in `notes` for each change.
pub(super) fn as_long_track(s: &mut Scenario, notes: &mut Vec<String>, what: &str) {
    let length = s.mesh.length;
    if s.foundation.absorbing_zones.is_none() {
        let zones = AbsorbingZonesSection { length: (length / 5.0).min(40.0), ..Default::default() };
        notes.push(format!(
            "on a track the study adds absorbing zones of {:.1} m at the ends (damping up to {} × c_cr) so that \
             {what}' waves leave the beam as on an infinite track (give [foundation.absorbing_zones], with \
             peak_ratio = 0 for none)",
            zones.length, zones.peak_ratio
        ));
        s.foundation.absorbing_zones = Some(zones);
    }
    if s.output.extremes_nodes.is_none() {
        s.output.extremes_nodes = Some([length / 3.0, 2.0 * length / 3.0]);
        notes.push(format!(
            "on a track the extremes are taken over the nodes of the middle third, {:.1}–{:.1} m, away from the \
             transients where {what} enter and leave over the supports ([output] extremes_nodes sets another range)",
            length / 3.0,
            2.0 * length / 3.0
        ));
    }
}

pub(super) fn with_devices(base: &Scenario, count: usize, force: f64) -> Scenario {
    let mut s = base.clone();
    s.friction.devices =
        (count > 0).then_some(DevicesSection { count: Some(count), positions: None, force: Some(force) });
    s.friction.distributed = None;
    s
}

pub(super) fn with_distributed(base: &Scenario, force_per_length: f64) -> Scenario {
    let mut s = base.clone();
    s.friction.devices = None;
    s.friction.distributed =
        (force_per_length > 0.0).then(|| DistributedSection { force_per_length, ..DistributedSection::default() });
    s
}

pub(super) fn blank(runs: usize) -> StudyData {
    StudyData {
        name: "",
        title: "",
        resolution: "",
        csv: String::new(),
        summary: StudySummary::none(),
        lines: Vec::new(),
        headline: Vec::new(),
        plots: Vec::new(),
        runs,
        mean_iterations: 0.0,
        columns: Vec::new(),
        failures: Vec::new(),
    }
}

pub(super) fn mean_iterations<'a>(points: impl Iterator<Item = &'a SweepPoint>) -> f64 {
    let (sum, count) = points.fold((0.0, 0usize), |(s, c), p| (s + p.mean_iterations, c + 1));
    if count > 0 { sum / count as f64 } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_timoshenko_rail_is_named_on_every_figure_but_the_receptance_studys() {
        let plot = |subtitle: &str| PlotSpec { subtitle: subtitle.into(), ..PlotSpec::new("p", "t", "x", "y") };
        let timoshenko = Scenario::from_toml(
            "[beam]\ntheory = \"timoshenko\"\nshear_modulus = 81e9\nshear_coefficient = 0.4\n",
            "t.toml",
        )
        .unwrap();
        let mut plots = vec![plot("solid: infinite track"), plot("")];
        name_the_rail(Preset::StationaryWave, &timoshenko, &mut plots);
        assert_eq!(plots[0].subtitle, "Timoshenko (G = 81 GPa, κ = 0.4) rail; solid: infinite track");
        assert_eq!(plots[1].subtitle, "Timoshenko (G = 81 GPa, κ = 0.4) rail");
        let mut receptance = vec![plot("both rails")];
        name_the_rail(Preset::Receptance, &timoshenko, &mut receptance);
        let mut euler = vec![plot("both rails")];
        name_the_rail(Preset::StationaryWave, &Scenario::default(), &mut euler);
        assert_eq!((receptance[0].subtitle.as_str(), euler[0].subtitle.as_str()), ("both rails", "both rails"));
    }
}
