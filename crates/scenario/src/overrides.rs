//! What a command's flags (`--speed`, `--devices`, …) and the Python package's keyword arguments (`speed=`,
//! `devices=`, …) set on top of a scenario: one table, [`OVERRIDES`], from which the command line builds its flags
//! and help, Python checks its keywords, and a test holds the Python docs and type stubs against it; one mapping,
//! [`Overrides::set`], for both (each value read by its kind in `override_values`).

use crate::error::{Result, invalid};
use crate::{AbsorbingZonesSection, DevicesSection, DistributedSection, Scenario};
use nscd::SolverKind;

/// The kind of value an override takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OverrideKind {
    /// A speed: a number in m/s, or text with a unit (`100m/s`, `360km/h`).
    Speed,
    /// A number in `unit` ("" for a pure number).
    Number {
        /// The unit of the value ("" for none).
        unit: &'static str,
    },
    /// A whole number ≥ 0.
    Count,
    /// Text (a train's catalogue name or CSV file).
    Text,
    /// A friction solver's name ([`SolverKind::name`]).
    Solver,
    /// Two numbers A, B (`A:B` on the command line, `[A, B]` in Python) in `unit`.
    Pair {
        /// The unit of both numbers.
        unit: &'static str,
    },
}

/// One override: its name (`name=` in Python, `--name` with dashes on the command line), its kind and what it does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OverrideSpec {
    /// The Python keyword.
    pub name: &'static str,
    /// The command-line flag without its dashes: `name` with `_` written `-`.
    pub flag: &'static str,
    /// The kind of value.
    pub kind: OverrideKind,
    /// The value's placeholder in the command line's help: the name in capitals unless the value has a form.
    pub placeholder: &'static str,
    /// What it sets, one sentence without a final full stop (the command line's help, the Python docs).
    pub help: &'static str,
}

/// Every override, in the order the help lists them.
pub const OVERRIDES: [OverrideSpec; 18] = [
    OverrideSpec {
        name: "speed",
        flag: "speed",
        kind: OverrideKind::Speed,
        placeholder: "SPEED",
        help: "Load speed: m/s (`100`), or with a unit (`100m/s`, `360km/h`)",
    },
    OverrideSpec {
        name: "acceleration",
        flag: "acceleration",
        kind: OverrideKind::Number { unit: "m/s²" },
        placeholder: "ACCELERATION",
        help: "The load's acceleration (m/s², negative brakes), the speed being its speed at x = 0",
    },
    OverrideSpec {
        name: "train",
        flag: "train",
        kind: OverrideKind::Text,
        placeholder: "NAME|FILE",
        help: "A train instead of the single load: a catalogue name (see `frictrack trains`) or a CSV file of \
               offset,force lines (m behind the first axle, N)",
    },
    OverrideSpec {
        name: "devices",
        flag: "devices",
        kind: OverrideKind::Count,
        placeholder: "DEVICES",
        help: "Number of friction devices, evenly spaced at i·L/(N+1) and snapped to nodes",
    },
    OverrideSpec {
        name: "device_force",
        flag: "device-force",
        kind: OverrideKind::Number { unit: "N" },
        placeholder: "DEVICE_FORCE",
        help: "Maximal force of one device F_u (N); required with --devices unless the scenario gives it",
    },
    OverrideSpec {
        name: "distributed_friction",
        flag: "distributed-friction",
        kind: OverrideKind::Number { unit: "N/m" },
        placeholder: "DISTRIBUTED_FRICTION",
        help: "Distributed friction f_u (N/m)",
    },
    OverrideSpec {
        name: "damping_ratio",
        flag: "damping-ratio",
        kind: OverrideKind::Number { unit: "" },
        placeholder: "DAMPING_RATIO",
        help: "Foundation damping ratio ζ = c_f/c_cr",
    },
    OverrideSpec {
        name: "theta",
        flag: "theta",
        kind: OverrideKind::Number { unit: "" },
        placeholder: "THETA",
        help: "θ of the Moreau–Jean scheme, in [0.5, 1]",
    },
    OverrideSpec {
        name: "spectral_radius",
        flag: "spectral-radius",
        kind: OverrideKind::Number { unit: "" },
        placeholder: "SPECTRAL_RADIUS",
        help: "Integrate with the generalized-α of spectral radius ρ∞ in [0, 1] (damps unresolved modes; θ stays 0.5)",
    },
    OverrideSpec {
        name: "elements",
        flag: "elements",
        kind: OverrideKind::Count,
        placeholder: "ELEMENTS",
        help: "Number of beam elements",
    },
    OverrideSpec {
        name: "load_advance",
        flag: "load-advance",
        kind: OverrideKind::Number { unit: "m" },
        placeholder: "LOAD_ADVANCE",
        help: "Load advance per time step (m): h = advance / speed",
    },
    OverrideSpec {
        name: "max_step",
        flag: "max-step",
        kind: OverrideKind::Number { unit: "s" },
        placeholder: "MAX_STEP",
        help: "Longest time step (s): h = min(advance / speed, max_step), for slow runs whose contact or deck needs a \
               shorter step than the load advance gives",
    },
    OverrideSpec {
        name: "solver",
        flag: "solver",
        kind: OverrideKind::Solver,
        placeholder: "SOLVER",
        help: "Friction solver: auto (projection for sparse devices, interior point for dense sections), projection \
               (nonsmooth Gauss–Seidel), interior-point (banded primal–dual), homotopy (parametric active set on a \
               regularised Coulomb law) or clarabel (cross-check; slow for many sections)",
    },
    OverrideSpec {
        name: "tolerance",
        flag: "tolerance",
        kind: OverrideKind::Number { unit: "" },
        placeholder: "TOLERANCE",
        help: "Relative tolerance of the friction law residual (relative to the largest free section velocity)",
    },
    OverrideSpec {
        name: "steady_start",
        flag: "steady-start",
        kind: OverrideKind::Number { unit: "m" },
        placeholder: "STEADY_START",
        help: "Start from the analytic steady state with the load at this position (m) instead of at rest",
    },
    OverrideSpec {
        name: "static_start",
        flag: "static-start",
        kind: OverrideKind::Number { unit: "m" },
        placeholder: "STATIC_START",
        help: "Start in the static equilibrium of the loads (and vehicles) standing with the first at this position \
               (m): no drop of vehicles into a soft track's trough as they enter",
    },
    OverrideSpec {
        name: "absorbing_zones",
        flag: "absorbing-zones",
        kind: OverrideKind::Number { unit: "m" },
        placeholder: "ABSORBING_ZONES",
        help: "Absorbing end zones of this length (m), foundation damping graded up to c_cr",
    },
    OverrideSpec {
        name: "extremes_window",
        flag: "extremes-window",
        kind: OverrideKind::Pair { unit: "m" },
        placeholder: "A:B",
        help: "Load positions A:B (m) over which the \"window\" extremes are reported beside the whole-run ones; \
               default the middle third of the beam",
    },
];

impl OverrideSpec {
    /// The override named `name`, or an error naming every one (before its value is looked at: `co_moving=True` was
    /// told its value must be a number).
    pub fn named(name: &str) -> Result<&'static OverrideSpec> {
        OVERRIDES.iter().find(|o| o.name == name).ok_or_else(|| {
            let names: Vec<&str> = OVERRIDES.iter().map(|o| o.name).collect();
            invalid("override", name, format!("is not one of {}", names.join(", ")))
        })
    }
}

/// Overrides of a scenario, each `None` unless given.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Overrides {
    /// Load speed (m/s).
    pub speed: Option<f64>,
    /// The load's acceleration (m/s²).
    pub acceleration: Option<f64>,
    /// A train: a catalogue name or a CSV file of offset,force lines.
    pub train: Option<String>,
    /// Number of evenly spaced friction devices.
    pub devices: Option<usize>,
    /// Maximal force of one device F_u (N).
    pub device_force: Option<f64>,
    /// Distributed friction f_u (N/m).
    pub distributed_friction: Option<f64>,
    /// Foundation damping ratio ζ.
    pub damping_ratio: Option<f64>,
    /// θ of the Moreau–Jean scheme.
    pub theta: Option<f64>,
    /// ρ∞ of the generalized-α.
    pub spectral_radius: Option<f64>,
    /// Number of beam elements.
    pub elements: Option<usize>,
    /// Load advance per step (m).
    pub load_advance: Option<f64>,
    /// Longest time step (s).
    pub max_step: Option<f64>,
    /// Friction solver.
    pub solver: Option<SolverKind>,
    /// Relative tolerance of the friction law residual.
    pub tolerance: Option<f64>,
    /// Start from the steady state with the load here (m).
    pub steady_start: Option<f64>,
    /// Start in static equilibrium with the first load here (m).
    pub static_start: Option<f64>,
    /// Absorbing end zones of this length (m).
    pub absorbing_zones: Option<f64>,
    /// Load positions [A, B] (m) of the window extremes.
    pub extremes_window: Option<[f64; 2]>,
}

/// A value given for an override by name.
#[derive(Debug, Clone, PartialEq)]
pub enum OverrideValue {
    /// A number (a count must be a whole one ≥ 0).
    Number(f64),
    /// A whole number ≥ 0, exactly as given (a count from the command line).
    Count(usize),
    /// Text: a train's name or file, a solver's name.
    Text(String),
    /// Two numbers (`extremes_window`).
    Pair([f64; 2]),
}

impl std::fmt::Display for OverrideValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OverrideValue::Number(x) => write!(f, "{x}"),
            OverrideValue::Count(n) => write!(f, "{n}"),
            OverrideValue::Text(t) => write!(f, "\"{t}\""),
            OverrideValue::Pair([a, b]) => write!(f, "[{a}, {b}]"),
        }
    }
}

impl Overrides {
    /// Set the override `name` to `value`: an unknown name, or a value not of the override's kind, is an error naming
    /// it, the value and what is allowed.
    pub fn set(&mut self, name: &str, value: OverrideValue) -> Result<()> {
        let spec = OverrideSpec::named(name)?;
        let number = || spec.number(&value);
        let count = || spec.count(&value);
        match spec.name {
            "speed" => self.speed = Some(number()?),
            "acceleration" => self.acceleration = Some(number()?),
            "train" => self.train = Some(spec.text(&value)?),
            "devices" => self.devices = Some(count()?),
            "device_force" => self.device_force = Some(number()?),
            "distributed_friction" => self.distributed_friction = Some(number()?),
            "damping_ratio" => self.damping_ratio = Some(number()?),
            "theta" => self.theta = Some(number()?),
            "spectral_radius" => self.spectral_radius = Some(number()?),
            "elements" => self.elements = Some(count()?),
            "load_advance" => self.load_advance = Some(number()?),
            "max_step" => self.max_step = Some(number()?),
            "solver" => self.solver = Some(spec.solver(&value)?),
            "tolerance" => self.tolerance = Some(number()?),
            "steady_start" => self.steady_start = Some(number()?),
            "static_start" => self.static_start = Some(number()?),
            "absorbing_zones" => self.absorbing_zones = Some(number()?),
            "extremes_window" => self.extremes_window = Some(spec.pair(&value)?),
            other => return Err(invalid("override", other, "is in the table of overrides but sets nothing")),
        }
        Ok(())
    }

    /// `scenario` with the overrides applied; its title, if it has one, says which of them change what runs.
    /// Refused by key: a speed beside the scenario's `load.speed_profile`, which sets the speeds itself (taking the
    /// speed would title the run with a speed it never ran at).
    pub fn apply(&self, mut s: Scenario) -> Result<Scenario> {
        if let Some(v) = self.speed {
            s.load.take_speed(v)?;
        }
        if let Some(a) = self.acceleration {
            s.load.acceleration = Some(a);
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
            s.integration.theta = Some(theta);
        }
        if let Some(rho) = self.spectral_radius {
            s.integration.spectral_radius = Some(rho);
        }
        if let Some(elements) = self.elements {
            s.mesh.elements = elements;
        }
        if let Some(dx) = self.load_advance {
            s.integration.load_advance = dx;
        }
        if let Some(h) = self.max_step {
            s.integration.max_step = Some(h);
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
        if let Some(window) = self.extremes_window {
            s.output.extremes_window = Some(window);
        }
        if let Some(length) = self.absorbing_zones {
            s.foundation.absorbing_zones = Some(AbsorbingZonesSection { length, peak_ratio: 1.0 });
        }
        // A scenario's title describes the file ("…, HSLM-A1"); overrides that change what runs are added to it, so
        // that no header, figure title or JSON names a train, speed or friction that did not run.
        let changed = self.changes_of_the_case();
        if !s.title.is_empty() && !changed.is_empty() {
            s.title = format!("{} (run with {})", s.title, changed.join(" "));
        }
        Ok(s)
    }

    /// The overrides given that change the loads, the speed, the friction or the damping, as `--flag value`.
    fn changes_of_the_case(&self) -> Vec<String> {
        // Six significant digits: `--speed 185km/h` is 51.3889 m/s in a title, not 51.38888888888889.
        let number = |flag: &str, v: Option<f64>| v.map(|v| format!("{flag} {}", crate::number::significant(v, 6)));
        // A speed with its unit and in km/h: `--speed 185km/h` titles "--speed 51.3889 m/s (185 km/h)".
        let speed = self.speed.map(|v| {
            format!(
                "--speed {} m/s ({} km/h)",
                crate::number::significant(v, 6),
                crate::number::significant(v * crate::units::KMH, 4)
            )
        });
        [
            speed,
            number("--acceleration", self.acceleration),
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_set_their_fields_and_a_wrong_name_or_kind_is_refused_by_name() {
        let mut o = Overrides::default();
        o.set("speed", OverrideValue::Number(150.0)).unwrap();
        o.set("devices", OverrideValue::Number(31.0)).unwrap();
        o.set("solver", OverrideValue::Text("projection".into())).unwrap();
        assert_eq!((o.speed, o.devices, o.solver), (Some(150.0), Some(31), Some(SolverKind::Projection)));
        let unknown = o.set("sped", OverrideValue::Number(1.0)).unwrap_err().to_string();
        assert!(unknown.contains("sped") && unknown.contains("speed"), "{unknown}");
        let fractional = o.set("devices", OverrideValue::Number(3.5)).unwrap_err().to_string();
        assert!(fractional.contains("devices") && fractional.contains("whole"), "{fractional}");
        let text = o.set("device_force", OverrideValue::Text("strong".into())).unwrap_err().to_string();
        assert!(text.contains("device_force") && text.contains("number"), "{text}");
        let scenario = o.apply(Scenario { title: "case".into(), ..Scenario::default() }).unwrap();
        assert_eq!(scenario.load.speed, 150.0);
        assert_eq!(scenario.title, "case (run with --speed 150 m/s (540 km/h) --devices 31)");
    }

    /// A value of `kind` that is not the default of its field.
    fn sample(kind: OverrideKind) -> OverrideValue {
        match kind {
            OverrideKind::Speed | OverrideKind::Number { .. } | OverrideKind::Count => OverrideValue::Number(3.0),
            OverrideKind::Text => OverrideValue::Text("hslm-a1".into()),
            OverrideKind::Solver => OverrideValue::Text("clarabel".into()),
            OverrideKind::Pair { .. } => OverrideValue::Pair([1.0, 2.0]),
        }
    }

    #[test]
    fn every_override_of_the_table_sets_its_own_field_and_is_spelled_alike_everywhere() {
        let mut names = std::collections::BTreeSet::new();
        for spec in &OVERRIDES {
            assert!(names.insert(spec.name), "{} listed twice", spec.name);
            assert_eq!(spec.flag, spec.name.replace('_', "-"), "the flag of {} is its name with dashes", spec.name);
            assert!(!spec.help.ends_with('.') && !spec.help.contains("  "), "help of {}: {:?}", spec.name, spec.help);
            let form = spec.placeholder.contains([':', '|']);
            assert!(form || spec.placeholder == spec.name.to_uppercase(), "placeholder of {}", spec.name);
            let mut o = Overrides::default();
            o.set(spec.name, sample(spec.kind)).unwrap();
            assert_ne!(o, Overrides::default(), "{} sets nothing", spec.name);
            // Exactly one field: setting a second override changes the value again.
            let mut twice = o.clone();
            twice.set(spec.name, sample(spec.kind)).unwrap();
            assert_eq!(twice, o);
        }
    }

    #[test]
    fn a_speed_may_carry_its_unit_and_other_numbers_may_not() {
        let mut o = Overrides::default();
        o.set("speed", OverrideValue::Text("360km/h".into())).unwrap();
        assert_eq!(o.speed, Some(100.0));
        o.set("speed", OverrideValue::Text("120 m/s".into())).unwrap();
        assert_eq!(o.speed, Some(120.0));
        let bad = o.set("speed", OverrideValue::Text("fast".into())).unwrap_err().to_string();
        assert!(bad.contains("speed") && bad.contains("fast") && bad.contains("km/h"), "{bad}");
        let not_a_speed = o.set("theta", OverrideValue::Text("0.5".into())).unwrap_err().to_string();
        assert!(not_a_speed.contains("theta") && not_a_speed.contains("number"), "{not_a_speed}");
    }
}
