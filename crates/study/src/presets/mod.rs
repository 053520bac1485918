//! The six studies of docs/theory.md §7, the train study of §10, the vehicle study of §12 and the infinite track's
//! stationary wave of §14 as named presets. Each returns its data as CSV
//! (long format, one row per point, SI units), a JSON summary (critical speeds, peaks, optimal forces) and a few
//! human-readable summary lines.
//! All runs of a study share one rayon pool; results do not depend on the thread count.
//!
//! One file per study, each with the two sentences of its report section (its headline) written from its own typed
//! results; `curves` holds the families of speed sweeps that three of them share.

mod amplification;
mod curves;
mod discrete_speed;
mod discrete_track;
mod discrete_vs_distributed;
mod distributed_speed;
mod equal_cost;
mod hslm;
mod hslm_figures;
mod hslm_headline;
mod hslm_resonances;
mod hslm_results;
mod hslm_summary;
pub mod hslm_verdict;
mod optimal_force;
mod sleeper_friction;
mod stationary_wave;
mod stationary_wave_curves;
mod stationary_wave_figures;
mod study_file;
mod table;
mod track_receptance;
mod vehicle_speed;
mod voided_sleepers;

pub use study_file::{SolverStatisticsNote, StudyFile};

use report::plot::PlotSpec;
use runner::{Runner, SweepPoint, SweepRow};
use scenario::error::{Result, StudyError, invalid};
use scenario::speeds::SpeedScale;
use scenario::{AbsorbingZonesSection, DevicesSection, DistributedSection, Scenario, SweepSection};
use serde::Serialize;
use table::Sampling;

/// The studies of docs/theory.md §7.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// 1. Critical speed with discrete devices: N ∈ {3, 7, 15, 31}, F_u ∈ {10, 50, 100} kN, and no friction.
    DiscreteSpeed,
    /// 2. Equal-cost solutions: N·F_u ∈ {3100, 1550, 310} kN for N ∈ {31, 15, 7, 3}.
    EqualCost,
    /// 3. Optimal device force near v_cr (206 m/s for the reference case) for N ∈ {3, 7, 15, 31}.
    OptimalForce,
    /// 4. Critical speed with distributed friction f_u ∈ {0, 1, 2, 5, 10} kN/m.
    DistributedSpeed,
    /// 5. Dynamic amplification at mid-span for v ∈ {50, 100, 150, 200} m/s, f_u ∈ {1, 2} kN/m.
    Amplification,
    /// 6. 199 devices of 1 kN against f_u = 0.995 kN/m at 150 m/s: mid-span histories.
    DiscreteVsDistributed,
    /// 7. Eurocode HSLM-A1 … A10 (docs/theory.md §10): max deflection and deck acceleration vs speed.
    Hslm,
    /// 8. Vehicles against the moving force (docs/theory.md §12): deflection, wheel force, body acceleration vs speed.
    VehicleSpeed,
    /// 9. The stationary wave on the infinite track (docs/theory.md §14): peak deflection vs speed, finite beam beside.
    StationaryWave,
    /// 10. Voided sleepers under a quarter car (docs/theory.md §18): 0–3 hanging sleepers, voids 0–3 mm, 20–100 m/s.
    VoidedSleepers,
    /// Study 11: friction at the sleepers against friction in the ballast, and the discrete track's critical speed
    /// (docs/theory.md §18).
    SleeperFriction,
    /// Study 12: the track's receptance (docs/theory.md §17, §18): Euler–Bernoulli and Timoshenko rails on sleepers
    /// (mid-span, above a sleeper) and on the equivalent continuous support.
    Receptance,
}

/// How finely the studies sample speeds and forces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Resolution {
    /// 10–290 m/s by 20 m/s, 9 forces per decade-scan: quick, for tests and previews.
    Coarse,
    /// 10–300 m/s by 1 m/s, 41 forces: the paper's curves.
    Paper,
}

impl Resolution {
    /// The speeds of a study on `base`: its `[sweep]` as given, whatever the resolution; otherwise the default
    /// range around the case's critical speed ([`SpeedScale::default_range`], 10–300 m/s by 10 for the reference
    /// case) sampled every second step (coarse: 10–290 m/s by 20) or every tenth of a step (paper: 1 m/s).
    pub fn speeds(self, base: &Scenario) -> Result<Vec<f64>> {
        if let Some(sweep) = &base.sweep {
            return Ok(sweep.speeds());
        }
        let range = SpeedScale::of(base)?.default_range();
        let step = match self {
            Resolution::Coarse => 2.0 * range.step,
            Resolution::Paper => 0.1 * range.step,
        };
        let count = ((range.to - range.from) / step + 1e-9).floor() as usize + 1;
        Ok((0..count).map(|i| range.from + i as f64 * step).collect())
    }

    /// The speeds of the train study on `base` (m/s): its `[sweep]` as given; otherwise 140–420 km/h (Eurocode sweeps
    /// run from 40 m/s to 1.2 × the line speed, 420 km/h for a 350 km/h line) every 20 km/h (coarse) or 2 km/h
    /// (paper).
    pub fn train_speeds(self, base: &Scenario) -> Vec<f64> {
        if let Some(sweep) = &base.sweep {
            return sweep.speeds();
        }
        let step = match self {
            Resolution::Coarse => 20.0,
            Resolution::Paper => 2.0,
        };
        let kmh = SweepSection { from: 140.0, to: 420.0, step };
        kmh.speeds().into_iter().map(|v| v / scenario::units::KMH).collect()
    }

    fn forces(self) -> usize {
        match self {
            Resolution::Coarse => 9,
            Resolution::Paper => 41,
        }
    }

    /// Both, coarse first.
    pub const ALL: [Resolution; 2] = [Resolution::Coarse, Resolution::Paper];

    /// Name on the command line and in Python.
    pub fn name(self) -> &'static str {
        match self {
            Resolution::Coarse => "coarse",
            Resolution::Paper => "paper",
        }
    }

    /// What it samples, in words (for the reference case).
    pub fn description(self) -> &'static str {
        match self {
            Resolution::Coarse => "20 m/s speed steps, 9 forces: quick",
            Resolution::Paper => "1 m/s speed steps, 41 forces: the paper's curves",
        }
    }

    /// The resolution called `name`, or an error naming both.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL.into_iter().find(|r| r.name() == name).ok_or_else(|| {
            let names: Vec<&str> = Self::ALL.map(Resolution::name).to_vec();
            invalid("resolution", name, format!("must be one of {}", names.join(", ")))
        })
    }
}

impl Preset {
    /// The nine studies `frictrack reproduce` runs: the thesis's (§7), the trains' (§10), the vehicles' (§12) and the
    /// stationary wave's (§14). The discrete track's studies (§18) are run on their own (`frictrack study`).
    pub const REPRODUCED: [Preset; 9] = [
        Preset::DiscreteSpeed,
        Preset::EqualCost,
        Preset::OptimalForce,
        Preset::DistributedSpeed,
        Preset::Amplification,
        Preset::DiscreteVsDistributed,
        Preset::Hslm,
        Preset::VehicleSpeed,
        Preset::StationaryWave,
    ];

    /// All twelve, in docs/theory.md order: the reproduced nine, then the discrete track's three.
    pub const ALL: [Preset; 12] = {
        let mut all = [Preset::Receptance; 12];
        let mut i = 0;
        while i < Self::REPRODUCED.len() {
            all[i] = Self::REPRODUCED[i];
            i += 1;
        }
        all[9] = Preset::VoidedSleepers;
        all[10] = Preset::SleeperFriction;
        all
    };

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

/// What a study produces.
#[derive(Debug, Clone, Serialize)]
pub struct StudyData {
    /// Preset name.
    pub name: &'static str,
    /// Title.
    pub title: &'static str,
    /// Resolution name.
    pub resolution: &'static str,
    /// The data, CSV with a header line.
    #[serde(skip)]
    pub csv: String,
    /// Machine-readable summary (critical speeds, peaks, optimal forces…), typed per study.
    pub summary: StudySummary,
    /// Human-readable summary lines, one per curve or case.
    pub lines: Vec<String>,
    /// Two sentences saying what the study shows, for reports.
    pub headline: Vec<String>,
    /// The figures.
    pub plots: Vec<PlotSpec>,
    /// Number of simulations run.
    pub runs: usize,
    /// Mean friction-solver iterations per step over the study's sweep runs (solver statistics).
    pub mean_iterations: f64,
    /// The CSV's columns with their units, in order.
    pub columns: Vec<(String, &'static str)>,
    /// The runs that failed; every other run is in the data (a failed run's CSV row, where the study writes one,
    /// has its case and speed with the values empty).
    pub failures: Vec<StudyFailure>,
}

/// What a study found, typed: each preset's own summary, written with its names (`study --format json`,
/// `<study>.json`); `None` (null) for a study that has none.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum StudySummary {
    /// Curves over speed, each with its refined critical speed (the speed studies, the finite beam's curves).
    Curves(curves::CurvesSummary),
    /// The amplification at mid-span.
    Amplification(amplification::AmplificationSummary),
    /// Devices against distributed friction of the same capacity.
    DiscreteVsDistributed(discrete_vs_distributed::ComparisonSummary),
    /// The optimal device force per device count.
    OptimalForce(optimal_force::OptimaSummary),
    /// The vehicles against the moving force.
    VehicleSpeed(vehicle_speed::VehicleSummary),
    /// The HSLM trains on the track or the deck.
    Hslm(hslm_summary::HslmSummary),
    /// The infinite track's stationary waves beside the finite beam's curves.
    StationaryWave(stationary_wave::StationarySummary),
    /// Voided sleepers under a quarter car.
    VoidedSleepers(voided_sleepers::VoidedSummary),
    /// The track's receptance: resonances per rail, support and place.
    Receptance(track_receptance::ReceptanceSummary),
    /// No summary.
    None,
}

impl StudyData {
    /// The summary as a JSON reader sees it (`study --format json`, `<study>.json`).
    pub fn summary_json(&self) -> serde_json::Value {
        serde_json::to_value(&self.summary).unwrap_or(serde_json::Value::Null)
    }
}

/// The failed runs of a family of sweeps (`rows[c]` the sweep of the case called `name(c)`), in order.
pub(super) fn failed_runs(rows: &[Vec<SweepRow>], name: impl Fn(usize) -> String) -> Vec<StudyFailure> {
    let failed = |(c, curve): (usize, &Vec<SweepRow>)| {
        let name = name(c);
        runner::failures(curve).into_iter().map(move |f| StudyFailure {
            case: name.clone(),
            speed: Some(f.speed),
            error: f.error,
        })
    };
    rows.iter().enumerate().flat_map(failed).collect()
}

/// The finished results of a study's runs, each with its index, in order; each failed run is recorded in
/// `failures` under the case and speed `name(i)` gives it.
pub(super) fn keep_finished<R>(
    results: Vec<Result<R>>,
    name: impl Fn(usize) -> (String, Option<f64>),
    failures: &mut Vec<StudyFailure>,
) -> Vec<(usize, R)> {
    let mut kept = Vec::with_capacity(results.len());
    for (i, result) in results.into_iter().enumerate() {
        match result {
            Ok(r) => kept.push((i, r)),
            Err(e) => {
                let (case, speed) = name(i);
                failures.push(StudyFailure { case, speed, error: e.to_string() });
            }
        }
    }
    kept
}

/// The error of a study (or a curve) `case` of which every run failed, naming the first failure of that case.
pub(super) fn nothing_finished(case: String, failures: &[StudyFailure]) -> StudyError {
    let first = failures.iter().find(|f| f.case == case).or(failures.first());
    StudyError::CurveFailed { case, first: first.map_or(String::new(), |f| f.error.clone()) }
}

/// A run of a study that failed: which case, at which speed, and why.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StudyFailure {
    /// The case, by the values that set it apart ("devices = 31, device_force = 50000").
    pub case: String,
    /// Load speed (m/s) of the failed run; None for a failed refinement of a critical speed.
    pub speed: Option<f64>,
    /// The error, as text.
    pub error: String,
}

/// The unit of a column of a study's CSV (SI; "1" for counts and ratios); None for a column not listed here — a new
/// column must be given its unit (a test runs every study and fails on one without).
fn unit_of(column: &str) -> Option<&'static str> {
    Some(match column {
        "speed" => "m/s",
        "device_force" | "cost" => "N",
        "force_per_length" => "N/m",
        "dissipated_energy" => "J",
        "global_norm" => "m²",
        "time" => "s",
        "impulse" => "N·s",
        "model" | "train" | "friction" | "rail" | "foundation" | "status" | "support" | "place" => "text",
        "frequency" => "Hz",
        "magnitude" | "real" | "imaginary" => "m/N",
        "phase" => "degrees",
        "voided" | "sleepers" => "1",
        "gap" | "exception_lowest" => "m",
        "max_pad_force" | "max_ballast_force" | "exception_ballast_force" | "neighbour_ballast_force" => "N",
        "max_acceleration" | "deck_acceleration" | "max_body_acceleration" | "rms_body_acceleration" => "m/s²",
        "min_wheel_force" | "max_wheel_force" => "N",
        "devices"
        | "tau"
        | "phi_w"
        | "phi_m"
        | "dynamic_amplification"
        | "max_dynamic_increment"
        | "losses_of_contact" => "1",
        "deflection"
        | "deflection_behind"
        | "load_position"
        | "max_downward_deflection"
        | "max_upward_deflection"
        | "static_max_downward_deflection"
        | "window_max_downward_deflection"
        | "window_max_upward_deflection" => "m",
        _ => return None,
    })
}

/// The unit the study's files give a column: its unit, or "unknown" (never a guess).
fn column_unit(column: &str) -> &'static str {
    unit_of(column).unwrap_or("unknown")
}

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
        summary: StudySummary::None,
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
