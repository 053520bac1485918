//! Ctrl-C (SIGINT, and SIGTERM as sent by batch schedulers): the first stops sweeps, studies and single runs within
//! a time step — runs not started are skipped, runs in flight are abandoned at their next step — and the command
//! exits with 130; the second quits at once. Work that cannot look at the stop flag where it is (a ground spectrum's
//! sampling, a fit, a large run's set-up and statics) is not waited for: [`GRACE`] after the first signal the process
//! exits with 130 by itself, saying what was kept. Nothing is lost by that: a journal holds every finished run (its
//! lines are written whole, and a cut last line is dropped on resuming) and every result file is written atomically,
//! so `--resume` continues from the journal and no half file lies over a good one.

use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, OnceLock};
use std::time::Duration;

static STOP: AtomicBool = AtomicBool::new(false);
static INSTALLED: OnceLock<()> = OnceLock::new();
/// What the command leaves behind if it is stopped ([`keep`]).
static KEPT: Mutex<Option<Kept>> = Mutex::new(None);
/// Set once the interruption's message is said (by the command or the watchdog), so that it is said once.
static SAID: AtomicBool = AtomicBool::new(false);

/// Exit code after an interruption (128 + SIGINT).
pub const EXIT_CODE: u8 = 130;

/// How long after the first signal the process ends whether or not the work has reached a point where it stops:
/// under the second a user or a scheduler waits before sending the next.
pub const GRACE: Duration = Duration::from_millis(500);

/// What an interrupted command leaves behind.
#[derive(Debug, Clone)]
pub enum Kept {
    /// Its journal: every finished run, continued by `--resume`.
    Journal(PathBuf),
    /// Nothing: the command writes its files when it finishes — into this `--out` folder if one was given (and
    /// whether the command created it, in which case an interruption removes it while it is empty).
    Nothing(Option<(PathBuf, bool)>),
}

impl Kept {
    /// Finished runs kept in `journal`, or nothing without one.
    pub fn in_journal(journal: Option<&runner::Journal>) -> Self {
        journal.map_or(Kept::Nothing(None), |j| Kept::Journal(j.path().to_path_buf()))
    }
}

/// The stop flag, with the signal handler installed on first use.
pub fn stop_flag() -> &'static AtomicBool {
    INSTALLED.get_or_init(|| {
        let installed = ctrlc::set_handler(|| {
            if STOP.swap(true, Ordering::SeqCst) {
                std::process::exit(i32::from(EXIT_CODE));
            }
            eprintln!("\nstopping: runs in flight end at their next step, finished runs are kept (Ctrl-C again to quit at once) …");
            std::thread::spawn(|| {
                std::thread::sleep(GRACE);
                if !SAID.swap(true, Ordering::SeqCst) {
                    eprintln!("error: interrupted: {}", what_is_kept());
                    std::process::exit(i32::from(EXIT_CODE));
                }
            });
        });
        if let Err(e) = installed {
            eprintln!("warning: no Ctrl-C handler ({e}); an interrupt will still keep the finished runs");
        }
    });
    &STOP
}

/// Say what this command leaves behind if it is stopped from now on (the last call holds).
pub fn keep(kept: Kept) {
    *KEPT.lock().unwrap_or_else(|poisoned| poisoned.into_inner()) = Some(kept);
}

/// Check the `--out` folder `out`, if given, with `check` (which creates it if missing and says whether it did), and
/// say that an interruption from now on leaves nothing written there ([`Kept::Nothing`]).
pub fn keep_nothing_in(
    out: Option<&std::path::Path>,
    check: impl FnOnce(&std::path::Path) -> scenario::Result<bool>,
) -> anyhow::Result<()> {
    let out = match out {
        Some(folder) => Some((folder.to_path_buf(), check(folder)?)),
        None => None,
    };
    keep(Kept::Nothing(out));
    Ok(())
}

/// What was kept, in words; a `--out` folder the command created and left empty is removed on the way.
fn what_is_kept() -> String {
    let kept = KEPT.lock().unwrap_or_else(|poisoned| poisoned.into_inner()).clone();
    match kept {
        Some(Kept::Journal(path)) => {
            format!("finished runs are kept in {}; run the same command with --resume", path.display())
        }
        None | Some(Kept::Nothing(None)) => "nothing was kept (no --out); run it again".to_string(),
        // remove_dir removes an empty folder only: nothing a user put there is touched.
        Some(Kept::Nothing(Some((folder, created)))) => match created && std::fs::remove_dir(&folder).is_ok() {
            true => format!(
                "nothing was written (the files are written at the end; {} removed again); run it again",
                folder.display()
            ),
            false => {
                format!("nothing was written to {} (the files are written at the end); run it again", folder.display())
            }
        },
    }
}

/// The error of a command interrupted after its main work was reported: `what` says what stands.
pub fn interrupted_after(what: &str) -> anyhow::Error {
    SAID.store(true, Ordering::SeqCst);
    anyhow::Error::new(scenario::StudyError::Interrupted).context(format!("interrupted: {what}"))
}

/// Turn an interruption into an error that says what was kept ([`keep`]) and how to continue.
pub fn explain<T>(result: scenario::Result<T>) -> anyhow::Result<T> {
    match result {
        Err(scenario::StudyError::Interrupted) => {
            SAID.store(true, Ordering::SeqCst);
            let kept = what_is_kept();
            Err(anyhow::Error::new(scenario::StudyError::Interrupted).context(format!("interrupted: {kept}")))
        }
        other => Ok(other?),
    }
}
