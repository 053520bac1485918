//! The scenario of a command: a TOML file (or the reference case) with command-line overrides on top.

use anyhow::{Context, Result};
use clap::builder::PossibleValuesParser;
use clap::{Arg, ArgAction, ArgMatches, Args, Command, value_parser};
use nscd::SolverKind;
use scenario::Scenario;
use scenario::overrides::{OVERRIDES, OverrideKind, OverrideSpec, OverrideValue, Overrides};
use std::path::PathBuf;

/// A scenario file and the flags that override it.
#[derive(Debug, Args)]
pub struct ScenarioArgs {
    /// Scenario file (TOML); without it, the reference case. Flags override the file.
    pub scenario: Option<PathBuf>,
    /// The flags of the table of overrides ([`OVERRIDES`]), as given.
    #[command(flatten)]
    pub flags: OverrideFlags,
}

/// The flags of [`OVERRIDES`] given on the command line, each read by its kind: one `--flag` per row of the table,
/// its help the table's.
#[derive(Debug, Clone, Default)]
pub struct OverrideFlags {
    /// (override, value as clap parsed it; a pair still as its text `A:B`) in the table's order.
    given: Vec<(&'static OverrideSpec, OverrideValue)>,
}

impl OverrideFlags {
    /// The value given for the override `name`, as a number (None if not given or not a number).
    pub fn number(&self, name: &str) -> Option<f64> {
        self.given.iter().find(|(spec, _)| spec.name == name).and_then(|(_, v)| match v {
            OverrideValue::Number(x) => Some(*x),
            _ => None,
        })
    }
}

/// The clap argument of one override.
fn flag(spec: &'static OverrideSpec) -> Arg {
    let arg = Arg::new(spec.name)
        .long(spec.flag)
        .help(spec.help)
        .value_name(spec.placeholder)
        .allow_negative_numbers(true)
        .action(ArgAction::Set);
    match spec.kind {
        OverrideKind::Speed => arg.value_parser(scenario::units::parse_speed),
        // A value may start with '-' (a braking acceleration) and carry its unit (`-60m/s2`), which clap would
        // otherwise read as a flag.
        OverrideKind::Number { unit } => {
            arg.allow_hyphen_values(true).value_parser(move |text: &str| scenario::units::parse_in(text, unit))
        }
        OverrideKind::Count => arg.value_parser(value_parser!(usize)),
        OverrideKind::Solver => arg.value_parser(PossibleValuesParser::new(SolverKind::ALL.map(SolverKind::name))),
        OverrideKind::Text | OverrideKind::Pair { .. } => arg.value_parser(value_parser!(String)),
    }
}

impl clap::Args for OverrideFlags {
    fn augment_args(cmd: Command) -> Command {
        OVERRIDES.iter().fold(cmd, |cmd, spec| cmd.arg(flag(spec)))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

impl clap::FromArgMatches for OverrideFlags {
    fn from_arg_matches(matches: &ArgMatches) -> std::result::Result<Self, clap::Error> {
        let mut flags = Self::default();
        flags.update_from_arg_matches(matches)?;
        Ok(flags)
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> std::result::Result<(), clap::Error> {
        for spec in &OVERRIDES {
            let value = match spec.kind {
                OverrideKind::Speed | OverrideKind::Number { .. } => {
                    matches.get_one::<f64>(spec.name).map(|x| OverrideValue::Number(*x))
                }
                OverrideKind::Count => matches.get_one::<usize>(spec.name).map(|n| OverrideValue::Count(*n)),
                OverrideKind::Solver | OverrideKind::Text | OverrideKind::Pair { .. } => {
                    matches.get_one::<String>(spec.name).map(|t| OverrideValue::Text(t.clone()))
                }
            };
            if let Some(value) = value {
                self.given.retain(|(s, _)| s.name != spec.name);
                self.given.push((spec, value));
            }
        }
        Ok(())
    }
}

/// Print the warnings of a built scenario on stderr (always: they say a result may be wrong).
pub fn print_warnings(scenario: &Scenario, case: &scenario::Case) -> Vec<String> {
    let warnings: Vec<String> =
        scenario::diagnostics::warnings(scenario, case).iter().map(ToString::to_string).collect();
    for warning in &warnings {
        eprintln!("warning: {warning}");
    }
    warnings
}

/// Say, on standard error, that a model of a uniform support (`what`: "the closed form", "the stationary wave") takes
/// `scenario`'s sleepers as their long-wave twin ([`Scenario::uniform_support`]); nothing without sleepers.
pub fn print_uniform_support_note(scenario: &Scenario, what: &str) -> scenario::error::Result<()> {
    if let (_, Some(note)) = scenario.uniform_support(what)? {
        eprintln!("note: {note}");
    }
    Ok(())
}

impl ScenarioArgs {
    /// The scenario file (or the reference case) with the flags applied.
    pub fn load(&self) -> Result<Scenario> {
        let s = match &self.scenario {
            Some(path) => Scenario::from_path(path).with_context(|| format!("reading scenario {}", path.display()))?,
            None => Scenario::default(),
        };
        Ok(self.overrides()?.apply(s)?)
    }

    /// The flags as the library's [`Overrides`] (the same names as the Python package's keyword arguments).
    pub fn overrides(&self) -> Result<Overrides> {
        let mut overrides = Overrides::default();
        for (spec, value) in &self.flags.given {
            let value = match (spec.kind, value) {
                (OverrideKind::Pair { .. }, OverrideValue::Text(text)) => {
                    let flag = format!("--{}", spec.flag);
                    let bad = || scenario::error::invalid(&flag, text, "expected A:B, two load positions in m");
                    let (a, b) = text.split_once(':').ok_or_else(bad)?;
                    let number = |t: &str| t.trim().parse::<f64>().map_err(|_| bad());
                    OverrideValue::Pair([number(a)?, number(b)?])
                }
                (_, given) => given.clone(),
            };
            overrides.set(spec.name, value)?;
        }
        Ok(overrides)
    }
}
