//! What a command's flags (`--speed`, `--devices`, …) and the Python package's keyword arguments (`speed=`,
//! `devices=`, …) set on top of a scenario: one mapping, by the same names, for both.

use crate::error::{Result, invalid};
use crate::{AbsorbingZonesSection, DevicesSection, DistributedSection, Scenario};
use nscd::SolverKind;

/// Overrides of a scenario, each `None` unless given.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Overrides {
    /// Load speed (m/s).
    pub speed: Option<f64>,
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
    /// Number of beam elements.
    pub elements: Option<usize>,
    /// Load advance per step (m).
    pub load_advance: Option<f64>,
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
    /// Text: a train's name or file, a solver's name.
    Text(String),
    /// Two numbers (`extremes_window`).
    Pair([f64; 2]),
}

impl std::fmt::Display for OverrideValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OverrideValue::Number(x) => write!(f, "{x}"),
            OverrideValue::Text(t) => write!(f, "\"{t}\""),
            OverrideValue::Pair([a, b]) => write!(f, "[{a}, {b}]"),
        }
    }
}

impl Overrides {
    /// Every override's name, as `--name` with dashes on the command line and `name=` in Python.
    pub const NAMES: [&'static str; 15] = [
        "speed",
        "train",
        "devices",
        "device_force",
        "distributed_friction",
        "damping_ratio",
        "theta",
        "elements",
        "load_advance",
        "solver",
        "tolerance",
        "steady_start",
        "static_start",
        "absorbing_zones",
        "extremes_window",
    ];

    /// Refuse a name that is no override, naming every one (before its value is looked at: `co_moving=True` was
    /// told its value must be a number).
    pub fn check_name(name: &str) -> Result<()> {
        match Self::NAMES.contains(&name) {
            true => Ok(()),
            false => Err(invalid("override", name, format!("is not one of {}", Self::NAMES.join(", ")))),
        }
    }

    /// Set the override `name` to `value`; an unknown name or a value of the wrong kind is an error naming it.
    pub fn set(&mut self, name: &str, value: OverrideValue) -> Result<()> {
        let number = |v: &OverrideValue| match v {
            OverrideValue::Number(x) => Ok(*x),
            other => Err(invalid(name, other, "must be a number")),
        };
        let count = |v: &OverrideValue| {
            let x = number(v)?;
            match x >= 0.0 && x.fract() == 0.0 && x <= u32::MAX as f64 {
                true => Ok(x as usize),
                false => Err(invalid(name, x, "must be a whole number ≥ 0")),
            }
        };
        let text = |v: &OverrideValue| match v {
            OverrideValue::Text(t) => Ok(t.clone()),
            other => Err(invalid(name, other, "must be text")),
        };
        match name {
            "speed" => self.speed = Some(number(&value)?),
            "train" => self.train = Some(text(&value)?),
            "devices" => self.devices = Some(count(&value)?),
            "device_force" => self.device_force = Some(number(&value)?),
            "distributed_friction" => self.distributed_friction = Some(number(&value)?),
            "damping_ratio" => self.damping_ratio = Some(number(&value)?),
            "theta" => self.theta = Some(number(&value)?),
            "elements" => self.elements = Some(count(&value)?),
            "load_advance" => self.load_advance = Some(number(&value)?),
            "solver" => {
                let given = text(&value)?;
                let names = SolverKind::ALL.map(SolverKind::name);
                self.solver = Some(
                    given
                        .parse::<SolverKind>()
                        .map_err(|_| invalid(name, &given, format!("must be one of {}", names.join(", "))))?,
                );
            }
            "tolerance" => self.tolerance = Some(number(&value)?),
            "steady_start" => self.steady_start = Some(number(&value)?),
            "static_start" => self.static_start = Some(number(&value)?),
            "absorbing_zones" => self.absorbing_zones = Some(number(&value)?),
            "extremes_window" => match value {
                OverrideValue::Pair(pair) => self.extremes_window = Some(pair),
                other => return Err(invalid(name, other, "must be two load positions [A, B] (m)")),
            },
            unknown => return Self::check_name(unknown),
        }
        Ok(())
    }

    /// `scenario` with the overrides applied; its title, if it has one, says which of them change what runs.
    pub fn apply(&self, mut s: Scenario) -> Scenario {
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
        s
    }

    /// The overrides given that change the loads, the speed, the friction or the damping, as `--flag value`.
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
        let text = o.set("speed", OverrideValue::Text("fast".into())).unwrap_err().to_string();
        assert!(text.contains("speed") && text.contains("number"), "{text}");
        let scenario = o.apply(Scenario { title: "case".into(), ..Scenario::default() });
        assert_eq!(scenario.load.speed, 150.0);
        assert_eq!(scenario.title, "case (run with --speed 150 --devices 31)");
    }
}
