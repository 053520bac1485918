//! Work that releases the GIL and stops on Ctrl-C: it runs on a worker thread with a stop flag (the library's runs
//! check it every step), while the caller waits without the GIL and, every [`POLL`], takes it back to let Python
//! handle its signals; a KeyboardInterrupt raises the flag, waits for the worker to stop and is raised. The worker
//! may tell its progress, which the caller passes to a Python callback as it waits.

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex, PoisonError};
use std::time::Duration;

/// How often a waiting caller checks Python's signals.
pub const POLL: Duration = Duration::from_millis(50);

/// How far a worker's job is, as a fraction in [0, 1] (f64 bits in an atomic), and the lines it has to say (the
/// estimate of a long batch): set by the worker, read by the waiting caller.
#[derive(Debug, Default)]
pub(crate) struct Progress {
    fraction: AtomicU64,
    notes: Mutex<Vec<String>>,
}

impl Progress {
    /// Set the fraction done.
    pub(crate) fn set(&self, fraction: f64) {
        self.fraction.store(fraction.clamp(0.0, 1.0).to_bits(), Ordering::Relaxed);
    }

    fn get(&self) -> f64 {
        f64::from_bits(self.fraction.load(Ordering::Relaxed))
    }

    /// Announce `estimate` of `what` ("frictrack.sweep", …) on Python's standard error when it is long
    /// ([`runner::cost::Estimate::is_long`]), as the command line does on its own.
    pub(crate) fn announce(&self, what: &str, estimate: &runner::cost::Estimate) {
        if estimate.is_long() {
            let line = format!("{what}: {}; KeyboardInterrupt (Ctrl-C) stops it\n", estimate.describe());
            self.notes.lock().unwrap_or_else(PoisonError::into_inner).push(line);
        }
    }

    /// Write the lines said since the last call to `sys.stderr`.
    fn write_notes(&self, py: Python<'_>) -> PyResult<()> {
        let notes = std::mem::take(&mut *self.notes.lock().unwrap_or_else(PoisonError::into_inner));
        if notes.is_empty() {
            return Ok(());
        }
        let stderr = py.import("sys")?.getattr("stderr")?;
        for line in notes {
            stderr.call_method1("write", (line,))?;
        }
        stderr.call_method0("flush").map(|_| ())
    }
}

/// Run `work(stop, progress)` on a worker thread without the GIL; Ctrl-C raises `stop` and KeyboardInterrupt.
/// `work` tells its progress and the estimate of a long batch: the estimate is written to `sys.stderr`, and `report`
/// (a Python callable, if given) is called with the fraction done whenever it changed, every [`POLL`] with the GIL,
/// and with 1.0 at the end; an exception it raises stops the work and is raised.
pub(crate) fn run_reporting<T: Send + 'static>(
    py: Python<'_>,
    report: Option<Bound<'_, PyAny>>,
    work: impl FnOnce(&AtomicBool, &Progress) -> T + Send + 'static,
) -> PyResult<T> {
    let progress = Arc::new(Progress::default());
    let mut reported = -1.0;
    let mut tell = |fraction: f64| -> PyResult<()> {
        match &report {
            Some(callback) if fraction != reported => {
                reported = fraction;
                callback.call1((fraction,)).map(|_| ())
            }
            _ => Ok(()),
        }
    };
    let stop = Arc::new(AtomicBool::new(false));
    let done = Arc::new((Mutex::new(None::<T>), Condvar::new()));
    let (flag, slot, told) = (Arc::clone(&stop), Arc::clone(&done), Arc::clone(&progress));
    let worker = std::thread::spawn(move || {
        let result = work(&flag, &told);
        let (lock, ready) = &*slot;
        *lock.lock().unwrap_or_else(PoisonError::into_inner) = Some(result);
        ready.notify_all();
    });
    // Wait up to `timeout` (without the GIL): the result, if it came.
    let wait = |timeout: Duration| {
        let (lock, ready) = &*done;
        let guard = lock.lock().unwrap_or_else(PoisonError::into_inner);
        let (mut guard, _) =
            ready.wait_timeout_while(guard, timeout, |r| r.is_none()).unwrap_or_else(PoisonError::into_inner);
        guard.take()
    };
    loop {
        if let Some(result) = py.detach(|| wait(POLL)) {
            let _ = worker.join();
            progress.write_notes(py)?;
            tell(1.0)?;
            return Ok(result);
        }
        if worker.is_finished() {
            // Finished without a result: it panicked.
            let reason = match worker.join() {
                Err(panic) => panic
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| panic.downcast_ref::<String>().cloned())
                    .unwrap_or_else(|| "unknown".into()),
                Ok(()) => return py.detach(|| wait(Duration::ZERO)).ok_or_else(lost),
            };
            return Err(PyRuntimeError::new_err(format!(
                "frictrack's worker thread failed: {reason} (a bug: please report it with the scenario)"
            )));
        }
        if let Err(signal) =
            py.check_signals().and_then(|()| progress.write_notes(py)).and_then(|()| tell(progress.get()))
        {
            stop.store(true, Ordering::Relaxed);
            // The run stops at its next step; its result is dropped.
            let _ = worker.join();
            return Err(signal);
        }
    }
}

fn lost() -> PyErr {
    PyRuntimeError::new_err("frictrack's worker thread ended without a result (a bug: please report it)")
}
