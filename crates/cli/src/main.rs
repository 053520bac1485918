//! The `frictrack` binary: the command line of [`frictrack_cli`], run on this process's arguments.

use std::process::ExitCode;

fn main() -> ExitCode {
    ExitCode::from(frictrack_cli::run_command_line(std::env::args_os()))
}
