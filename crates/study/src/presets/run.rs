//! Running a study: the preset's own run on the checked base scenario, its figures naming a rail other than the
//! default, and the set-ups studies share (friction by devices or distributed, a long track, a blank result).

use super::preset::Preset;
use super::resolution::Resolution;
use super::study_data::StudyData;
use report::plot::PlotSpec;
use runner::Runner;
use scenario::Scenario;
use scenario::error::Result;

/// Run `preset` on top of `base` (normally the reference case), checked first: a bad key is named as the user wrote
/// it (`sleepers.spacing`), not as what a preset derives from it (`mesh.elements`).
pub fn run_preset(preset: Preset, resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    base.validate()?;
    base.refuse_sweep_on_the_ground()?;
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_timoshenko_rail_is_named_on_every_figure_but_the_receptance_studys() {
        let plot = |subtitle: &str| PlotSpec {
            subtitle: subtitle.into(),
            ..PlotSpec::new("p", "t", &scenario::axis::Axis::none(), &scenario::axis::Axis::none())
        };
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
