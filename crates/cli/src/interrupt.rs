//! Ctrl-C (SIGINT, and SIGTERM as sent by batch schedulers): the first stops sweeps, studies and single runs within
//! a time step — runs not started are skipped, runs in flight are abandoned at their next step — and the command
//! exits with 130; the second quits at once. Either way the journal holds every finished run and `--resume`
//! continues from it.

use std::sync::OnceLock;
use std::sync::atomic::{AtomicBool, Ordering};

static STOP: AtomicBool = AtomicBool::new(false);
static INSTALLED: OnceLock<()> = OnceLock::new();

/// Exit code after an interruption (128 + SIGINT).
pub const EXIT_CODE: u8 = 130;

/// The stop flag, with the signal handler installed on first use.
pub fn stop_flag() -> &'static AtomicBool {
    INSTALLED.get_or_init(|| {
        let installed = ctrlc::set_handler(|| {
            if STOP.swap(true, Ordering::SeqCst) {
                std::process::exit(i32::from(EXIT_CODE));
            }
            eprintln!("\nstopping: runs in flight end at their next step, finished runs are kept (Ctrl-C again to quit at once) …");
        });
        if let Err(e) = installed {
            eprintln!("warning: no Ctrl-C handler ({e}); an interrupt will still keep the finished runs");
        }
    });
    &STOP
}

/// Turn an interruption into an error that says where the finished runs are and how to continue.
pub fn explain<T>(result: scenario::Result<T>, journal: Option<&runner::Journal>) -> anyhow::Result<T> {
    match result {
        Err(scenario::StudyError::Interrupted) => {
            let kept = match journal {
                Some(j) => {
                    format!("finished runs are kept in {}; run the same command with --resume", j.path().display())
                }
                None => "nothing was kept (no --out); run it again".to_string(),
            };
            Err(anyhow::Error::new(scenario::StudyError::Interrupted).context(format!("interrupted: {kept}")))
        }
        other => Ok(other?),
    }
}
