//! The table of study presets: for each, its name, title, what it sets, how it samples speeds, how it runs and
//! what of the base scenario it replaces — every fact of a preset in one row, in the order of [`Preset::ALL`].

use super::preset::Preset;
use super::resolution::Resolution;
use super::study_data::StudyData;
use super::{
    amplification, discrete_speed, discrete_vs_distributed, distributed_speed, equal_cost, hslm, ledsgard,
    optimal_force, sleeper_friction, stationary_wave, track_receptance, vehicle_speed, voided_sleepers,
};
use runner::Runner;
use scenario::Scenario;
use scenario::error::{Result, invalid};

/// How a study samples the load speed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Sampling {
    /// Over the case's speed range ([`Resolution::speeds`]).
    Speeds,
    /// Over the train speeds of EN 1991-2 ([`Resolution::train_speeds`]).
    TrainSpeeds,
    /// At speeds of its own, fixed fractions of v_cr.
    Fixed,
}

/// One row of the table.
pub(super) struct PresetEntry {
    /// Name on the command line and of the output files.
    pub(super) name: &'static str,
    /// A one-line title.
    pub(super) title: &'static str,
    /// What the study sets itself on top of the base scenario.
    pub(super) sets: &'static [&'static str],
    /// How it samples speeds.
    pub(super) sampling: Sampling,
    /// The study.
    pub(super) run: fn(Resolution, &Scenario, &Runner) -> Result<StudyData>,
    /// The parts of the base scenario it replaces, when it says so itself (else the common rule of
    /// [`Preset::overrides`]).
    pub(super) overrides: Option<fn(&Scenario) -> Vec<String>>,
}

/// The presets, in the order of [`Preset::ALL`] (a test checks it).
pub(super) const TABLE: [PresetEntry; 13] = [
    // 1. Preset::DiscreteSpeed
    PresetEntry {
        name: "discrete-speed",
        title: "Critical speed with discrete friction devices",
        sets: &["friction: none, and N ∈ {3, 7, 15, 31} devices of F_u ∈ {10, 50, 100} kN"],
        sampling: Sampling::Speeds,
        run: discrete_speed::study,
        overrides: None,
    },
    // 2. Preset::EqualCost
    PresetEntry {
        name: "equal-cost",
        title: "Equal-cost device solutions (N·F_u constant)",
        sets: &["friction: N·F_u ∈ {3100, 1550, 310} kN shared by N ∈ {31, 15, 7, 3} devices"],
        sampling: Sampling::Speeds,
        run: equal_cost::study,
        overrides: None,
    },
    // 3. Preset::OptimalForce
    PresetEntry {
        name: "optimal-force",
        title: "Optimal device force near the critical speed",
        sets: &[
            "friction: N ∈ {3, 7, 15, 31} devices, F_u scanned over 1 kN–10 MN",
            "load.speed: the critical speed v_cr rounded (206 m/s for the reference case)",
        ],
        sampling: Sampling::Fixed,
        run: optimal_force::study,
        overrides: None,
    },
    // 4. Preset::DistributedSpeed
    PresetEntry {
        name: "distributed-speed",
        title: "Critical speed with distributed friction",
        sets: &["friction: distributed f_u ∈ {0, 1, 2, 5, 10} kN/m, no devices"],
        sampling: Sampling::Speeds,
        run: distributed_speed::study,
        overrides: None,
    },
    // 5. Preset::Amplification
    PresetEntry {
        name: "amplification",
        title: "Dynamic amplification at mid-span",
        sets: &[
            "friction: distributed f_u ∈ {1, 2} kN/m, no devices",
            "load.speed: ¼, ½, ¾ and 1 × v_cr rounded (50, 100, 150, 200 m/s for the reference case)",
            "output.sections: mid-span",
        ],
        sampling: Sampling::Fixed,
        run: |_, base, runner| amplification::study(base, runner),
        overrides: None,
    },
    // 6. Preset::DiscreteVsDistributed
    PresetEntry {
        name: "discrete-vs-distributed",
        title: "199 devices × 1 kN against 0.995 kN/m distributed friction",
        sets: &[
            "friction: 199 devices of 1 kN, and distributed 0.995 kN/m",
            "load.speed: ¾ v_cr rounded (150 m/s for the reference case)",
            "output.sections: mid-span",
        ],
        sampling: Sampling::Fixed,
        run: |_, base, runner| discrete_vs_distributed::study(base, runner),
        overrides: None,
    },
    // 7. Preset::Hslm
    PresetEntry {
        name: "hslm",
        title: "Eurocode HSLM-A1 … A10: deflection and deck acceleration vs speed",
        sets: &[
            "friction: none, and the scenario's [friction] (if it has none: devices of 50 kN, 31 per 200 m)",
            "load: HSLM-A1 … A10 in turn (EN 1991-2 §6.4.6.1.1)",
            "speeds: 140–420 km/h every 20 km/h (coarse) or 2 km/h (paper), unless the scenario has a [sweep]",
            "integration.load_advance: on a span, at most what resolves max(30 Hz, 1.5 f₁, f₃) with 20 steps per \
                     period at the lowest speed",
            "foundation.absorbing_zones and output.extremes_nodes: on a track, unless the scenario gives them, \
                     zones of min(40 m, L/5) at the ends and the extremes over the middle third",
        ],
        sampling: Sampling::TrainSpeeds,
        run: hslm::study,
        overrides: Some(hslm::overrides),
    },
    // 8. Preset::VehicleSpeed
    PresetEntry {
        name: "vehicle-speed",
        title: "Vehicles against the moving force: deflection, wheel force, body acceleration",
        sets: &[
            "load: a moving force F, a moving mass F/g and the default quarter car scaled to F, in turn",
            "friction: none, and the scenario's [friction] (if it has none: devices of 50 kN, 31 per 200 m)",
            "rail: smooth, and the scenario's [rail] (if it has none: German low irregularity, 1–80 m, seed 1)",
            "integration.max_step: what resolves the wheel–rail contact mode at every speed (the load advance kept where \
             it does)",
            "integration.static_start: every load starts at rest in its static equilibrium at min(40 m, L/5), \
                     unless the scenario gives a start",
            "foundation.absorbing_zones and output.extremes_nodes: on a track, unless the scenario gives them, \
                     zones of min(40 m, L/5) at the ends and the extremes over the middle third",
        ],
        sampling: Sampling::Speeds,
        run: vehicle_speed::study,
        overrides: Some(vehicle_speed::overrides),
    },
    // 9. Preset::StationaryWave
    PresetEntry {
        name: "stationary-wave",
        title: "The stationary wave on the infinite track beside the finite beam",
        sets: &[
            "friction: distributed f_u ∈ {0, 1, 2, 5, 10} kN/m, no devices, on the infinite track (stationary solve) \
                     and on the finite beam (the distributed-speed study's runs)",
            "foundation.law: linear; and tensionless and bilinear (α = ½) with the rail's weight, without friction, on \
                     the infinite track",
        ],
        sampling: Sampling::Speeds,
        run: stationary_wave::study,
        overrides: Some(stationary_wave::overrides),
    },
    // 10. Preset::VoidedSleepers
    PresetEntry {
        name: "voided-sleepers",
        title: "Voided sleepers under a quarter car: rail deflection, neighbouring sleepers, wheel force",
        sets: &[
            "sleepers: 0–3 consecutive sleepers at mid-track hanging by voids of 0, 1, 2, 3 mm (0: tensionless \
             ballast), on the scenario's [sleepers] (if it has none: the typical ballasted track in place of its soil)",
            "load: the default quarter car scaled to F, from a static start; speeds 20–100 m/s every 20 (coarse) or \
             5 (paper)",
            "integration.load_advance: a/20 (20 steps a sleeper-passing period), and a step that resolves the \
             wheel–rail contact mode",
            "mesh: whole bays, four elements each, where the scenario's does not put a node over every sleeper",
        ],
        sampling: Sampling::Fixed,
        run: voided_sleepers::study,
        overrides: Some(voided_sleepers::overrides),
    },
    // 11. Preset::SleeperFriction
    PresetEntry {
        name: "sleeper-friction",
        title: "Friction at the sleepers against friction in the ballast",
        sets: &[
            "friction: none and f_u ∈ {2, 5} kN/m — distributed in the ballast on the continuous track, a slider of \
             f_u·a at every sleeper on the discrete one",
            "sleepers: the scenario's [sleepers] (if it has none: light sleepers every 0.6 m holding its soil), and \
             the continuous twin with their long-wave support and mass",
            "mesh: whole bays, four elements each, where the scenario's does not put a node over every sleeper",
        ],
        sampling: Sampling::Speeds,
        run: sleeper_friction::study,
        overrides: Some(sleeper_friction::overrides),
    },
    // 12. Preset::Receptance
    PresetEntry {
        name: "receptance",
        title: "The track's receptance: Euler–Bernoulli and Timoshenko rails, on sleepers and on a continuous support",
        sets: &[
            "rail: Euler–Bernoulli and Timoshenko (the scenario's G and κ, else 81 GPa and 0.4)",
            "support: the scenario's [sleepers] (if it has none: the typical ballasted track in place of its soil), \
             read at mid-span and above a sleeper near mid-track; and the continuous twin (k_eq, c_eq, the sleepers' \
             long-wave mass)",
            "frequencies: 10 Hz – 2 kHz, 200 (coarse) or 1000 (paper) log-spaced; mesh eight elements a bay; \
             absorbing zones of min(40 m, L/5) unless the scenario gives them",
        ],
        sampling: Sampling::Fixed,
        run: track_receptance::study,
        overrides: Some(track_receptance::overrides),
    },
    // 13. Preset::Ledsgard
    PresetEntry {
        name: "ledsgard",
        title: "Ledsgård: the X2000 on soft ground beside the measurements, with ballast friction",
        sets: &[
            "site: examples/ledsgard built in — the composite beam on the site's layered ground, the X2000",
            "speeds: 100–280 km/h every 20 (coarse) or 5 (paper); ballast friction f_u ∈ {0, 1, 2, 5} kN/m under the \
             composite beam; the measured records at 70 and 185 km/h beside the computed waves",
        ],
        sampling: Sampling::Fixed,
        run: ledsgard::study,
        overrides: Some(ledsgard::overrides),
    },
];

impl Preset {
    /// This preset's row of the table.
    pub(super) fn entry(self) -> &'static PresetEntry {
        &TABLE[self as usize]
    }

    /// Name on the command line and of the output files.
    pub fn name(self) -> &'static str {
        self.entry().name
    }

    /// The preset called `name`.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL.into_iter().find(|p| p.name() == name).ok_or_else(|| {
            let names: Vec<&str> = Self::ALL.iter().map(|p| p.name()).collect();
            invalid("preset", name, format!("must be one of {}", names.join(", ")))
        })
    }

    /// What the study sets itself on top of the base scenario (the friction set-ups it compares, the speeds of
    /// fixed-speed studies, the recorded section).
    pub fn sets(self) -> &'static [&'static str] {
        self.entry().sets
    }

    /// The parts of `base` that this study replaces with its own (see [`Preset::sets`]), one sentence each; empty
    /// when the base scenario leaves them at their defaults.
    pub fn overrides(self, base: &Scenario) -> Vec<String> {
        match self.entry().overrides {
            Some(overrides) => overrides(base),
            None => self.common_overrides(base),
        }
    }

    /// The common rule of [`Preset::overrides`]: the scenario's friction, where the study compares set-ups of its
    /// own (named by the first line of [`Preset::sets`]), and its `[sweep]` in a study at fixed speeds.
    pub(super) fn common_overrides(self, base: &Scenario) -> Vec<String> {
        let mut notes = Vec::new();
        let f = &base.friction;
        if f.devices.is_some() || f.distributed.is_some() {
            notes.push(format!(
                "the scenario's [friction] is not used: the study compares its own set-ups ({})",
                self.sets()[0].trim_start_matches("friction: ")
            ));
        }
        if !self.sweeps_speed() && base.sweep.is_some() {
            notes.push("the scenario's [sweep] is not used: this study runs at fixed speeds".into());
        }
        notes
    }

    /// Whether the study sweeps the load speed (the others run at fixed speeds).
    pub fn sweeps_speed(self) -> bool {
        self.entry().sampling != Sampling::Fixed
    }

    /// The speeds (m/s) the study sweeps on `base`, None for the studies at fixed speeds.
    pub fn speeds(self, resolution: Resolution, base: &Scenario) -> Result<Option<Vec<f64>>> {
        Ok(match self.entry().sampling {
            Sampling::TrainSpeeds => Some(resolution.train_speeds(base)),
            Sampling::Speeds => Some(resolution.speeds(base)?),
            Sampling::Fixed => None,
        })
    }

    /// A one-line title.
    pub fn title(self) -> &'static str {
        self.entry().title
    }
}

#[cfg(test)]
mod tests {
    use super::{Preset, TABLE};

    /// Row i of the table is the i-th preset: its name is the one the command line parses back to it.
    #[test]
    fn the_table_is_in_the_order_of_the_presets() {
        for (i, preset) in Preset::ALL.into_iter().enumerate() {
            assert_eq!(preset as usize, i);
            assert_eq!(Preset::from_name(TABLE[i].name).unwrap(), preset);
        }
    }
}
