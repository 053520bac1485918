//! The scenario of a command: a TOML file (or the reference case) with command-line overrides on top.

use anyhow::{Context, Result};
use clap::Args;
use clap::builder::{PossibleValuesParser, TypedValueParser};
use nscd::SolverKind;
use scenario::Scenario;
use scenario::overrides::Overrides;
use std::path::PathBuf;

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
pub fn print_warnings(scenario: &Scenario, case: &scenario::Case) {
    for warning in scenario::diagnostics::warnings(scenario, case) {
        eprintln!("warning: {warning}");
    }
}

impl ScenarioArgs {
    /// The scenario file (or the reference case) with the flags applied.
    pub fn load(&self) -> Result<Scenario> {
        let s = match &self.scenario {
            Some(path) => Scenario::from_path(path).with_context(|| format!("reading scenario {}", path.display()))?,
            None => Scenario::default(),
        };
        Ok(self.overrides()?.apply(s))
    }

    /// The flags as the library's [`Overrides`] (the same names as the Python package's keyword arguments).
    pub fn overrides(&self) -> Result<Overrides> {
        let extremes_window = match &self.extremes_window {
            Some(text) => {
                let bad =
                    || scenario::error::invalid("--extremes-window", text, "expected A:B, two load positions in m");
                let (a, b) = text.split_once(':').ok_or_else(bad)?;
                let number = |t: &str| t.trim().parse::<f64>().map_err(|_| bad());
                Some([number(a)?, number(b)?])
            }
            None => None,
        };
        Ok(Overrides {
            speed: self.speed,
            train: self.train.clone(),
            devices: self.devices,
            device_force: self.device_force,
            distributed_friction: self.distributed_friction,
            damping_ratio: self.damping_ratio,
            theta: self.theta,
            elements: self.elements,
            load_advance: self.load_advance,
            solver: self.solver,
            tolerance: self.tolerance,
            steady_start: self.steady_start,
            static_start: self.static_start,
            absorbing_zones: self.absorbing_zones,
            extremes_window,
        })
    }
}
