//! The `frictrack` command: railway track dynamics with Coulomb frictional damping.
//!
//! A library so that the command runs the same from its own binary (`src/main.rs`) and from the Python wheel's
//! `frictrack` console script ([`run_command_line`]): one parser, one dispatch, one exit-code convention.

mod analytic;
mod check;
mod co_moving;
mod files;
mod ground;
mod init;
mod interrupt;
mod jobs;
mod merge;
mod plot;
mod progress;
mod receptance;
mod reference;
mod report_cmd;
mod reproduce;
mod resolution_check;
mod run;
mod scenario_args;
mod stationary;
mod study_cmd;
mod sweep;
mod sweep_check;
mod track_profile;
mod trains;

use clap::{Parser, Subcommand, ValueEnum};
use std::ffi::OsString;
use std::io::Write as _;
use std::sync::OnceLock;

/// Railway track dynamics under moving loads: an Euler–Bernoulli rail on a viscoelastic Winkler foundation.
#[derive(Debug, Parser)]
#[command(name = "frictrack", version, about, long_about = None, after_help = "Examples:\n  frictrack run\n  frictrack init case.toml && frictrack check case.toml\n  frictrack run case.toml --speed 180\n  frictrack sweep case.toml --speeds 150:260:5 --out sweep.csv --critical\n  frictrack sweep case.toml --out sweep.csv --resume\n  frictrack sweep case.toml --out part1.csv --shard 1/3  (… 2/3, 3/3)\n  frictrack merge --out sweep.csv part1.csv part2.csv part3.csv\n  frictrack study optimal-force --out results\n  frictrack reproduce --out results --resolution coarse\n  frictrack report results --out results.html\n  frictrack run --speed 180 --devices 31 --device-force 50e3\n  frictrack run --distributed-friction 5000 --format json\n  frictrack reference --elements 400\n  frictrack analytic --speed 200 --damping-ratio 0.05\n  frictrack analytic --damping-ratio 0.05 --speeds 10:300:10 --format json\n  frictrack track-profile fra-4 --seed 7 --out profile")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Simulate a scenario (default: the reference case) under a moving load, with friction devices and/or
    /// distributed friction; flags override the scenario.
    Run(run::RunArgs),
    /// Run a scenario at many speeds in parallel; CSV of max deflections, dissipated energy and W̄ per speed.
    Sweep(sweep::SweepArgs),
    /// Run one of the thirteen studies (docs/theory.md §7, §10, §12, §14, §17–§19): CSV, JSON and figures in a folder.
    Study(study_cmd::StudyArgs),
    /// Run the nine studies of the thesis (§7, §10, §12, §14) and write their data, figures and report.md.
    Reproduce(reproduce::ReproduceArgs),
    /// Validate a scenario file.
    Check(check::CheckArgs),
    /// Combine the outputs of `frictrack sweep --shard K/N` (all N shards) into the file one unsharded sweep writes.
    Merge(merge::MergeArgs),
    /// Write the documented scenario template (the reference case).
    Init(init::InitArgs),
    /// Draw the figures of outputs on disk: a sweep's CSV, or a run's folder (`run --out`).
    Plot(plot::PlotArgs),
    /// Static response and natural frequencies of the reference case beside their closed forms.
    Reference(reference::ReferenceArgs),
    /// List the catalogue of trains, or print one train's axles (offsets behind the first axle, forces).
    Trains(trains::TrainsArgs),
    /// Sample a random rail profile from a track-quality spectrum: CSV, its periodogram against the target, figures.
    TrackProfile(track_profile::TrackProfileArgs),
    /// Closed-form steady state of an infinite beam under a moving load: max downward/upward deflection, and the
    /// dynamic amplification curve over a speed range.
    Analytic(analytic::AnalyticArgs),
    /// The stationary wave of the load on the infinite track (moving coordinates, no time stepping), for linear,
    /// tensionless and bilinear soils and ballast friction: its shape, peaks, lift-off and slip zones and what
    /// friction leaves behind, at one speed or over a speed range.
    Stationary(stationary::StationaryArgs),
    /// The track's receptance (m/N) and mobility over frequency — point or transfer, Euler–Bernoulli or Timoshenko
    /// rail, viscous damping and loss factors — from the scenario's own model, with its resonances and a figure.
    Receptance(receptance::ReceptanceArgs),
    /// One self-contained HTML report (figures inline, tables, verdicts, warnings, scenario, provenance) of a folder
    /// written by `run --out`, `study --out` or `reproduce --out`.
    Report(report_cmd::ReportArgs),
    /// The composite track on a layered `[ground]`: the soil's Rayleigh modes and least phase velocity, the static
    /// strip stiffness and the Winkler control, the critical speed of the track on the ground, with figures.
    Ground(ground::GroundArgs),
}

/// Output format of a command.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum, Default)]
pub enum Format {
    /// Human-readable text.
    #[default]
    Text,
    /// One JSON object on stdout.
    Json,
}

/// Output format of a command whose result is a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum, Default)]
pub enum TableFormat {
    /// Human-readable text.
    #[default]
    Text,
    /// One JSON value on stdout.
    Json,
    /// The table as CSV, with a closing `# units (SI): …` line.
    Csv,
}

impl From<TableFormat> for report::output::Format {
    fn from(format: TableFormat) -> Self {
        match format {
            TableFormat::Text => Self::Text,
            TableFormat::Json => Self::Json,
            TableFormat::Csv => Self::Csv,
        }
    }
}

impl From<Format> for report::output::Format {
    fn from(format: Format) -> Self {
        match format {
            Format::Text => Self::Text,
            Format::Json => Self::Json,
        }
    }
}

/// Print `output` in `format` (the library renders it: the CLI and Python give the same text and JSON).
pub fn print_output(
    output: &dyn report::output::Output,
    format: impl Into<report::output::Format>,
) -> anyhow::Result<()> {
    print!("{}", report::output::render(output, format.into())?);
    Ok(())
}

/// Exit code when standard output is closed early (`frictrack … | head`): 128 + SIGPIPE, as a Unix tool killed by
/// the signal reports.
const BROKEN_PIPE_EXIT: i32 = 141;

/// Rust ignores SIGPIPE, so writing to a closed pipe makes `println!` panic: end quietly instead, with
/// [`BROKEN_PIPE_EXIT`], and leave every other panic to the default report.
fn end_quietly_on_a_closed_pipe() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let message = info
            .payload()
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| info.payload().downcast_ref::<&str>().copied())
            .unwrap_or("");
        if message.contains("failed printing to stdout") && message.contains("Broken pipe") {
            std::process::exit(BROKEN_PIPE_EXIT);
        }
        default(info);
    }));
}

/// Run one command line (`args[0]` is the program's name, as in `std::env::args_os`) to its end: print what it
/// prints and return its exit code — 0 on success, 2 for invalid input, 130 after Ctrl-C, 1 for anything else
/// (as `error_code` sorts them). Standard output is flushed before returning, so a caller that is not Rust's `main` (the Python
/// console script) loses nothing. Installs the process-wide panic hook and the Ctrl-C handler
/// (`interrupt::stop_flag`): meant for a process that runs this one command.
pub fn run_command_line<I, T>(args: I) -> u8
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    end_quietly_on_a_closed_pipe();
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    let _ = COMMAND_LINE.set(args.iter().map(|a| a.to_string_lossy().into_owned()).collect());
    let cli = Cli::parse_from(args);
    // From here on a first SIGINT/SIGTERM stops the command within interrupt::GRACE wherever it is.
    interrupt::stop_flag();
    let result = match cli.command {
        Command::Run(args) => run::run(&args),
        Command::Sweep(args) => sweep::run(&args),
        Command::Study(args) => study_cmd::run(&args),
        Command::Reproduce(args) => reproduce::run(&args),
        Command::Check(args) => check::run(&args),
        Command::Merge(args) => merge::run(&args),
        Command::Init(args) => init::run(&args),
        Command::Plot(args) => plot::run(&args),
        Command::Reference(args) => reference::run(&args),
        Command::Analytic(args) => analytic::run(&args),
        Command::Stationary(args) => stationary::run(&args),
        Command::Receptance(args) => receptance::run(&args),
        Command::Ground(args) => ground::run(&args),
        Command::Report(args) => report_cmd::run(&args),
        Command::Trains(args) => trains::run(&args),
        Command::TrackProfile(args) => track_profile::run(&args),
    };
    let code = match result {
        Ok(()) => 0,
        Err(error) => {
            // An interruption's message says it all; its cause ("interrupted") would only repeat it.
            if error_code(&error) == interrupt::EXIT_CODE {
                eprintln!("error: {error}");
            } else {
                eprintln!("error: {error:#}");
            }
            if let Some(hint) = hint(&error) {
                eprintln!("hint: {hint}");
            }
            error_code(&error)
        }
    };
    let _ = std::io::stdout().flush();
    code
}

/// The git commit this build was made from (`FRICTRACK_COMMIT` when the build set it, else `git rev-parse` of the
/// source tree at build time; none for a build outside a repository, e.g. from an sdist).
pub const COMMIT: Option<&str> = option_env!("FRICTRACK_BUILT_FROM");

/// The command line being run ([`run_command_line`]'s arguments).
static COMMAND_LINE: OnceLock<Vec<String>> = OnceLock::new();

/// Where a result written now comes from: this command line, this build, this instant.
pub(crate) fn provenance() -> report::provenance::Provenance {
    report::provenance::Provenance::now(
        report::provenance::shell_line(COMMAND_LINE.get().map_or(&[], Vec::as_slice)),
        COMMIT,
    )
}

/// What to try after a friction step that did not converge, in terms of this command's flags. Measured
/// (`cargo run --release -p track --example solver_table`): projection stalls on dense distributed sections,
/// Clarabel is limited by its own stopping criteria, the interior point by its iteration cap at tight tolerances.
fn hint(error: &anyhow::Error) -> Option<&'static str> {
    use nscd::NscdError;
    let Some(scenario::StudyError::Stepping(stepping)) = error.downcast_ref::<scenario::StudyError>() else {
        return None;
    };
    match stepping {
        NscdError::Unconverged { status: nscd::StepStatus::Stalled, fallbacks: Some(_), .. } => Some(
            "every solver stalled short of the tolerance, which lies below what the step's arithmetic resolves: \
             raise --tolerance (the default 1e-6 is met in every case measured)",
        ),
        NscdError::Unconverged { solver: nscd::SolverKind::Projection, .. } => Some(
            "raise [integration] max_iterations or --tolerance, or choose another solver (--solver interior-point or \
             clarabel)",
        ),
        NscdError::Unconverged { solver: nscd::SolverKind::Clarabel, .. } => {
            Some("raise --tolerance, or choose another solver (--solver interior-point or projection)")
        }
        NscdError::Unconverged { .. } => Some(
            "raise [integration] max_iterations or --tolerance (the default 1e-6 is met in every case measured), or \
             choose another solver (--solver clarabel or projection)",
        ),
        _ => None,
    }
}

/// 2 for invalid input (a parameter the model rejects), 130 after Ctrl-C, 1 for anything else (e.g. a solver
/// failure).
/// The library reaches the commands through `study` only: every error of a lower layer arrives as a
/// [`scenario::StudyError`], which says whether it is the user's input.
pub(crate) fn error_code(error: &anyhow::Error) -> u8 {
    use scenario::StudyError;
    match error.downcast_ref::<StudyError>() {
        Some(StudyError::Interrupted) => interrupt::EXIT_CODE,
        Some(e) if e.is_invalid_input() => 2,
        _ => 1,
    }
}
