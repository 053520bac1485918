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

/// What an interrupted command leaves behind, for [`explain`].
#[derive(Debug, Clone, Copy)]
pub enum Kept<'a> {
    /// Its journal: every finished run, continued by `--resume`.
    Journal(&'a runner::Journal),
    /// Nothing: the command writes its files when it finishes — into this `--out` folder if one was given (and
    /// whether the command created it).
    Nothing(Option<(&'a std::path::Path, bool)>),
}

/// Turn an interruption into an error that says where the finished runs are and how to continue; a `--out` folder
/// the command created and left empty is removed.
pub fn explain<T>(result: scenario::Result<T>, kept: Kept<'_>) -> anyhow::Result<T> {
    match result {
        Err(scenario::StudyError::Interrupted) => {
            let kept = match kept {
                Kept::Journal(j) => {
                    format!("finished runs are kept in {}; run the same command with --resume", j.path().display())
                }
                Kept::Nothing(None) => "nothing was kept (no --out); run it again".to_string(),
                Kept::Nothing(Some((folder, created))) => {
                    // remove_dir removes an empty folder only: nothing a user put there is touched.
                    if created && std::fs::remove_dir(folder).is_ok() {
                        format!(
                            "nothing was written (the files are written at the end; {} removed again); run it again",
                            folder.display()
                        )
                    } else {
                        format!(
                            "nothing was written to {} (the files are written at the end); run it again",
                            folder.display()
                        )
                    }
                }
            };
            Err(anyhow::Error::new(scenario::StudyError::Interrupted).context(format!("interrupted: {kept}")))
        }
        other => Ok(other?),
    }
}
