//! The scenario of a command: a TOML file (or the reference case) with command-line overrides on top.

use anyhow::{Context, Result};
use clap::Args;
use clap::builder::{PossibleValuesParser, TypedValueParser};
use nscd::SolverKind;
use std::path::PathBuf;
use study::Scenario;
use study::scenario::{AbsorbingZonesSection, DevicesSection, DistributedSection};

/// `--solver NAME`: the names of [`SolverKind::ALL`], checked by clap, mapped to the kind.
fn solver_parser() -> impl TypedValueParser<Value = SolverKind> {
    PossibleValuesParser::new(SolverKind::ALL.map(SolverKind::name))
        .map(|name| name.parse::<SolverKind>().unwrap_or_default())
}

/// A scenario file and the flags that override it.
#[derive(Debug, Args)]
pub struct ScenarioArgs {
    /// Scenario file (TOML); without it, the reference case. Flags override the file.
    pub scenario: Option<PathBuf>,
    /// Load speed: m/s (`100`), or with a unit (`100m/s`, `360km/h`).
    #[arg(long, allow_negative_numbers = true, value_parser = crate::units::parse_speed)]
    pub speed: Option<f64>,
    /// A train instead of the single load: a catalogue name (see `frictrack trains`) or a CSV file of offset,force
    /// lines (m behind the first axle, N).
    #[arg(long, value_name = "NAME|FILE")]
    pub train: Option<String>,
    /// Number of friction devices, evenly spaced at i·L/(N+1) and snapped to nodes.
    #[arg(long, allow_negative_numbers = true)]
    pub devices: Option<usize>,
    /// Maximal force of one device F_u (N); required with --devices unless the scenario gives it.
    #[arg(long, allow_negative_numbers = true)]
    pub device_force: Option<f64>,
    /// Distributed friction f_u (N/m).
    #[arg(long, allow_negative_numbers = true)]
    pub distributed_friction: Option<f64>,
    /// Foundation damping ratio ζ = c_f/c_cr.
    #[arg(long, allow_negative_numbers = true)]
    pub damping_ratio: Option<f64>,
    /// θ of the Moreau–Jean scheme, in [0.5, 1].
    #[arg(long, allow_negative_numbers = true)]
    pub theta: Option<f64>,
    /// Number of beam elements.
    #[arg(long, allow_negative_numbers = true)]
    pub elements: Option<usize>,
    /// Load advance per time step (m): h = advance / speed.
    #[arg(long, allow_negative_numbers = true)]
    pub load_advance: Option<f64>,
    /// Friction solver: auto (projection for sparse devices, interior point for dense sections), projection
    /// (nonsmooth Gauss–Seidel), interior-point (banded primal–dual) or clarabel (cross-check; slow for many sections).
    #[arg(long, value_parser = solver_parser())]
    pub solver: Option<SolverKind>,
    /// Relative tolerance of the friction law residual (relative to the largest free section velocity).
    #[arg(long, allow_negative_numbers = true)]
    pub tolerance: Option<f64>,
    /// Start from the analytic steady state with the load at this position (m) instead of at rest.
    #[arg(long, allow_negative_numbers = true)]
    pub steady_start: Option<f64>,
    /// Start in the static equilibrium of the loads (and vehicles) standing with the first at this position
    /// (m): no drop of vehicles into a soft track's trough as they enter.
    #[arg(long, allow_negative_numbers = true)]
    pub static_start: Option<f64>,
    /// Absorbing end zones of this length (m), foundation damping graded up to c_cr.
    #[arg(long, allow_negative_numbers = true)]
    pub absorbing_zones: Option<f64>,
    /// Load positions A:B (m) over which the "window" extremes are reported beside the whole-run ones; default the
    /// middle third of the beam.
    #[arg(long, value_name = "A:B", allow_negative_numbers = true)]
    pub extremes_window: Option<String>,
}

/// Print the warnings of a built scenario on stderr (always: they say a result may be wrong).
pub fn print_warnings(scenario: &Scenario, case: &study::Case) {
    for warning in study::diagnostics::warnings(scenario, case) {
        eprintln!("warning: {warning}");
    }
}

impl ScenarioArgs {
    /// The scenario with the flags applied, built, with its warnings printed on stderr.
    pub fn build(&self) -> Result<(Scenario, study::Case)> {
        let scenario = self.load()?;
        let case = scenario.build()?;
        print_warnings(&scenario, &case);
        Ok((scenario, case))
    }

    /// The scenario file (or the reference case) with the flags applied.
    pub fn load(&self) -> Result<Scenario> {
        let mut s = match &self.scenario {
            Some(path) => Scenario::from_path(path).with_context(|| format!("reading scenario {}", path.display()))?,
            None => Scenario::default(),
        };
        if let Some(v) = self.speed {
            s.load.speed = v;
        }
        if let Some(train) = &self.train {
            s.load.train = Some(train.clone());
            s.load.axles.clear();
            s.load.patches.clear();
        }
        if self.devices.is_some() || self.device_force.is_some() {
            let d = s.friction.devices.get_or_insert_with(DevicesSection::default);
            if let Some(count) = self.devices {
                d.count = Some(count);
                d.positions = None;
            }
            if let Some(force) = self.device_force {
                d.force = Some(force);
            }
        }
        if let Some(f) = self.distributed_friction {
            s.friction.distributed.get_or_insert_with(DistributedSection::default).force_per_length = f;
        }
        if let Some(ratio) = self.damping_ratio {
            s.foundation.damping = None;
            s.foundation.damping_ratio = Some(ratio);
        }
        if let Some(theta) = self.theta {
            s.integration.theta = theta;
        }
        if let Some(elements) = self.elements {
            s.mesh.elements = elements;
        }
        if let Some(dx) = self.load_advance {
            s.integration.load_advance = dx;
        }
        if let Some(solver) = self.solver {
            s.integration.solver = solver;
        }
        if let Some(t) = self.tolerance {
            s.integration.tolerance = t;
        }
        if let Some(x) = self.steady_start {
            s.integration.steady_start = Some(x);
        }
        if let Some(x) = self.static_start {
            s.integration.static_start = Some(x);
        }
        if let Some(text) = &self.extremes_window {
            let bad = || study::error::invalid("--extremes-window", text, "expected A:B, two load positions in m");
            let (a, b) = text.split_once(':').ok_or_else(bad)?;
            let number = |t: &str| t.trim().parse::<f64>().map_err(|_| bad());
            s.output.extremes_window = Some([number(a)?, number(b)?]);
        }
        if let Some(length) = self.absorbing_zones {
            s.foundation.absorbing_zones = Some(AbsorbingZonesSection { length, peak_ratio: 1.0 });
        }
        // A scenario's title describes the file ("…, HSLM-A1"); flags that change what runs are added to it, so that
        // no header, figure title or JSON names a train, speed or friction that did not run.
        let changed = self.changes_of_the_case();
        if !s.title.is_empty() && !changed.is_empty() {
            s.title = format!("{} (run with {})", s.title, changed.join(" "));
        }
        Ok(s)
    }

    /// The flags given that change the loads, the speed, the friction or the damping, as `--flag value`.
    fn changes_of_the_case(&self) -> Vec<String> {
        let number = |flag: &str, v: Option<f64>| v.map(|v| format!("{flag} {v}"));
        [
            number("--speed", self.speed),
            self.train.as_ref().map(|t| format!("--train {t}")),
            self.devices.map(|n| format!("--devices {n}")),
            number("--device-force", self.device_force),
            number("--distributed-friction", self.distributed_friction),
            number("--damping-ratio", self.damping_ratio),
        ]
        .into_iter()
        .flatten()
        .collect()
    }
}
