//! `--jobs N`: one pool of worker threads per command, never more threads than the machine has cores.

use anyhow::Result;
use runner::{Runner, worker_threads};

/// The runner of a command with `jobs` threads (0 = all cores); says on stderr (unless `quiet`) when the request
/// is capped at the number of cores.
pub fn runner(jobs: usize, quiet: bool) -> Result<Runner<'static>> {
    let threads = worker_threads(jobs);
    if jobs > threads && !quiet {
        eprintln!("note: --jobs {jobs} capped at {threads}, the number of cores this machine has");
    }
    Ok(Runner::new(jobs)?)
}
