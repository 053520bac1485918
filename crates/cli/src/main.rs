//! The `frictrack` command: railway track dynamics with Coulomb frictional damping.

mod analytic;
mod run;

use clap::{Parser, Subcommand, ValueEnum};
use std::process::ExitCode;

/// Railway track dynamics under moving loads: an Euler–Bernoulli rail on a viscoelastic Winkler foundation.
#[derive(Debug, Parser)]
#[command(name = "frictrack", version, about, long_about = None, after_help = "Examples:\n  frictrack run\n  frictrack run --elements 400 --format json\n  frictrack analytic --speed 200 --damping-ratio 0.05\n  frictrack analytic --damping-ratio 0.05 --speeds 10:300:10 --format json")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run the reference case (MODEL.md §2): static response under the load at mid-span, lowest natural
    /// frequencies, and their closed-form references.
    Run(run::RunArgs),
    /// Closed-form steady state of an infinite beam under a moving load: max downward/upward deflection, and the
    /// dynamic amplification curve over a speed range.
    Analytic(analytic::AnalyticArgs),
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

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Run(args) => run::run(&args),
        Command::Analytic(args) => analytic::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {error:#}");
            ExitCode::from(error_code(&error))
        }
    }
}

/// 2 for invalid input (a parameter the model rejects), 1 for anything else.
fn error_code(error: &anyhow::Error) -> u8 {
    match error.downcast_ref::<fem_beam::FemError>() {
        Some(fem_beam::FemError::InvalidField { .. } | fem_beam::FemError::InvalidCount { .. }) => 2,
        Some(fem_beam::FemError::NoSteadyState { .. }) => 2,
        _ => 1,
    }
}
