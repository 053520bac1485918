//! How the runs of sweeps and studies are carried out: one thread pool, progress, a journal of finished runs, a stop
//! flag, and an estimate of each batch's cost before it starts.

use crate::cost::{Estimate, RunCost};
use crate::journal::Journal;
use crate::run_point::{point_until, simulate_until};
use crate::sweep_point::{FailedRun, SweepPoint, SweepRow};
use rayon::prelude::*;
use scenario::Case;
use scenario::error::{Result, StudyError, invalid};
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use track::{RunResult, RunSettings};

/// The worker threads a request for `jobs` gets: all cores for 0, and never more than the cores the machine
/// has (`std::thread::available_parallelism`): more threads than cores only add memory and switching.
pub fn worker_threads(jobs: usize) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    if jobs == 0 { cores } else { jobs.min(cores) }
}

/// How the runs of a sweep or study are carried out: on one thread pool built once (see [`worker_threads`]),
/// reporting the number of finished runs to `progress`, keeping every finished run in an optional [`Journal`] (and
/// taking runs already there from it), and stopping once an optional `stop` flag is raised (Ctrl-C, SIGTERM): runs
/// not started fail with [`StudyError::Interrupted`], runs in flight are abandoned at their next step.
#[derive(Clone)]
pub struct Runner<'a> {
    pool: Arc<rayon::ThreadPool>,
    /// Called with the number of finished runs of the current parallel loop after each one.
    pub progress: &'a (dyn Fn(usize) + Sync),
    /// Finished runs, on disk.
    pub journal: Option<&'a Journal>,
    /// Told what each batch of runs will cost before it starts (see [`Runner::announce`]).
    pub estimate: &'a (dyn Fn(&Estimate) + Sync),
    /// Raised to stop: runs not yet started fail with [`StudyError::Interrupted`], runs in flight stop at their next
    /// step.
    pub stop: Option<&'a AtomicBool>,
    /// Runs each case of a sweep will take after it (a critical speed's refinement, [`crate::refinement_runs`]),
    /// counted in the sweep's estimate. Default 0.
    pub refinement_runs: usize,
}

static NO_PROGRESS: fn(usize) = |_| {};
static NO_ESTIMATE: fn(&Estimate) = |_| {};

impl Runner<'static> {
    /// A pool of [`worker_threads`]`(jobs)` threads, no progress, no journal, no stop flag.
    pub fn new(jobs: usize) -> Result<Self> {
        let threads = worker_threads(jobs);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| invalid("jobs", jobs, format!("cannot start {threads} worker threads: {e}")))?;
        Ok(Runner {
            pool: Arc::new(pool),
            progress: &NO_PROGRESS,
            estimate: &NO_ESTIMATE,
            journal: None,
            stop: None,
            refinement_runs: 0,
        })
    }
}

impl<'a> Runner<'a> {
    /// The same with progress reported to `progress`.
    pub fn with_progress<'b>(self, progress: &'b (dyn Fn(usize) + Sync)) -> Runner<'b>
    where
        'a: 'b,
    {
        Runner { progress, ..self }
    }

    /// The same keeping finished runs in `journal`.
    pub fn with_journal<'b>(self, journal: Option<&'b Journal>) -> Runner<'b>
    where
        'a: 'b,
    {
        Runner { journal, ..self }
    }

    /// The same, stopping once `stop` is raised.
    pub fn with_stop<'b>(self, stop: &'b AtomicBool) -> Runner<'b>
    where
        'a: 'b,
    {
        Runner { stop: Some(stop), ..self }
    }

    /// The same telling `estimate` what each batch will cost before it starts.
    pub fn with_estimate<'b>(self, estimate: &'b (dyn Fn(&Estimate) + Sync)) -> Runner<'b>
    where
        'a: 'b,
    {
        Runner { estimate, ..self }
    }

    /// The same, counting `runs` more of each case of a sweep in its estimate: those that refine its critical speed
    /// after it ([`crate::refinement_runs`]).
    pub fn with_refinement(self, runs: usize) -> Self {
        Runner { refinement_runs: runs, ..self }
    }

    /// The same without progress reports or estimates (for the short loops that follow a study's main batch).
    pub fn silent(&self) -> Self {
        Runner { progress: &NO_PROGRESS, estimate: &NO_ESTIMATE, ..self.clone() }
    }

    /// Tell the estimate hook what a batch will cost, before it starts.
    pub fn announce(&self, estimate: Estimate) {
        (self.estimate)(&estimate);
    }

    /// Announce one run of each case, at its own speed.
    pub fn announce_runs(&self, cases: &[Case]) {
        self.announce(Estimate::of_runs(cases.iter().map(RunCost::of), self.threads()));
    }

    /// Announce the runs of `cases` at these speeds (case index, speed) that the journal does not already hold, and
    /// the [`Runner::refinement_runs`] that follow each case.
    pub fn announce_points(&self, cases: &[Case], pairs: &[(usize, f64)]) {
        let costs: Vec<RunCost> = cases.iter().map(RunCost::of).collect();
        let to_run =
            pairs.iter().filter(|&&(c, speed)| !self.journal.is_some_and(|j| j.contains(&point_key(&cases[c], speed))));
        let refinements = costs.iter().flat_map(|&cost| std::iter::repeat_n(cost, self.refinement_runs));
        self.announce(Estimate::of_runs(to_run.map(|&(c, _)| costs[c]).chain(refinements), self.threads()));
    }

    /// The number of worker threads.
    pub fn threads(&self) -> usize {
        self.pool.current_num_threads()
    }

    /// One run of `case` under `settings` that stops with [`StudyError::Interrupted`] when the stop flag is raised.
    pub fn simulate(&self, case: &Case, settings: &RunSettings) -> Result<RunResult> {
        simulate_until(case, settings, self.stop)
    }

    /// Whether the stop flag is raised (work not yet started should then end with [`StudyError::Interrupted`]).
    pub fn is_stopped(&self) -> bool {
        self.stop.is_some_and(|s| s.load(Ordering::Relaxed))
    }

    /// `run` unless the journal already holds the result under `key`; a fresh result is journaled at once.
    pub fn cached<R: Serialize + DeserializeOwned>(&self, key: &str, run: impl FnOnce() -> Result<R>) -> Result<R> {
        if let Some(done) = self.journal.and_then(|j| j.get(key)) {
            return Ok(done);
        }
        if self.is_stopped() {
            return Err(StudyError::Interrupted);
        }
        let result = run()?;
        if let Some(journal) = self.journal {
            journal.record(key, &result)?;
        }
        Ok(result)
    }

    /// One run of `case` at `speed` (m/s), through the journal.
    pub fn point(&self, case: &Case, speed: f64) -> Result<SweepPoint> {
        self.cached(&point_key(case, speed), || point_until(case, speed, self.stop))
    }

    /// `f` over `items` on the pool, results in the order of `items` whatever the thread count; the first error
    /// is returned (after the runs in flight end, so that their results reach the journal).
    pub fn map<T: Sync, R: Send>(&self, items: &[T], f: impl Fn(&T) -> Result<R> + Sync) -> Result<Vec<R>> {
        // An interruption is reported only if nothing worse happened.
        let mut interrupted = false;
        let mut out = Vec::with_capacity(items.len());
        for result in self.run_all(items, f) {
            match result {
                Ok(r) => out.push(r),
                Err(StudyError::Interrupted) => interrupted = true,
                Err(e) => return Err(e),
            }
        }
        if interrupted { Err(StudyError::Interrupted) } else { Ok(out) }
    }

    /// `f` over `items` on the pool like [`Runner::map`], but a failed item does not end the loop: every item's
    /// result, in the order of `items`. Only an interruption is an error (the finished runs are in the journal).
    pub fn map_each<T: Sync, R: Send>(
        &self,
        items: &[T],
        f: impl Fn(&T) -> Result<R> + Sync,
    ) -> Result<Vec<Result<R>>> {
        let results = self.run_all(items, f);
        if results.iter().any(|r| matches!(r, Err(StudyError::Interrupted))) {
            return Err(StudyError::Interrupted);
        }
        Ok(results)
    }

    /// Every item's result of `f` on the pool, in the order of `items`, progress reported after each.
    fn run_all<T: Sync, R: Send>(&self, items: &[T], f: impl Fn(&T) -> Result<R> + Sync) -> Vec<Result<R>> {
        let done = AtomicUsize::new(0);
        self.pool.install(|| {
            items
                .par_iter()
                .map(|item| {
                    let result = f(item);
                    (self.progress)(done.fetch_add(1, Ordering::Relaxed) + 1);
                    result
                })
                .collect()
        })
    }

    /// Run `case` at every speed, keeping going past a failed run: one row per speed, in the order of `speeds`
    /// (an interruption is still an error).
    pub fn speed_sweep_keeping(&self, case: &Case, speeds: &[f64]) -> Result<Vec<SweepRow>> {
        Ok(self.sweep_many_keeping(std::slice::from_ref(case), speeds)?.pop().expect("one case"))
    }

    /// Run every case at every speed like [`Runner::sweep_many`], keeping going past a failed run: per case, one
    /// row per speed in the order of `speeds` (an interruption is still an error).
    pub fn sweep_many_keeping(&self, cases: &[Case], speeds: &[f64]) -> Result<Vec<Vec<SweepRow>>> {
        self.sweep_grids_keeping(cases, &vec![speeds.to_vec(); cases.len()])
    }

    /// Run each case over its own grid of speeds (`grids[c]` for `cases[c]`), all on one pool, keeping going past
    /// a failed run: per case, one row per speed of its grid, in its order (an interruption is still an error).
    pub fn sweep_grids_keeping(&self, cases: &[Case], grids: &[Vec<f64>]) -> Result<Vec<Vec<SweepRow>>> {
        grids.iter().try_for_each(|g| check_speeds(g))?;
        cases.iter().zip(grids).try_for_each(|(case, g)| check_fitted(case, g))?;
        let pairs: Vec<(usize, f64)> =
            grids.iter().enumerate().flat_map(|(c, g)| g.iter().map(move |&v| (c, v))).collect();
        self.announce_points(cases, &pairs);
        let rows = self.map_each(&pairs, |&(c, speed)| self.point(&cases[c], speed))?;
        let mut rows = rows
            .into_iter()
            .zip(&pairs)
            .map(|(row, &(_, speed))| row.map_err(|e| FailedRun { speed, error: e.to_string() }));
        Ok(grids.iter().map(|g| rows.by_ref().take(g.len()).collect()).collect())
    }

    /// Run `case` at every speed; results in the order of `speeds`.
    pub fn speed_sweep(&self, case: &Case, speeds: &[f64]) -> Result<Vec<SweepPoint>> {
        Ok(self.sweep_many(std::slice::from_ref(case), speeds)?.pop().expect("one case"))
    }

    /// Run every case at every speed, all (case, speed) pairs on one pool; results per case in the order of
    /// `speeds`, identical for any thread count.
    pub fn sweep_many(&self, cases: &[Case], speeds: &[f64]) -> Result<Vec<Vec<SweepPoint>>> {
        check_speeds(speeds)?;
        cases.iter().try_for_each(|case| check_fitted(case, speeds))?;
        let pairs = case_speed_pairs(cases.len(), speeds);
        self.announce_points(cases, &pairs);
        let mut points = self.map(&pairs, |&(c, speed)| self.point(&cases[c], speed))?.into_iter();
        Ok((0..cases.len()).map(|_| points.by_ref().take(speeds.len()).collect()).collect())
    }
}

/// The journal key of a run of `case` at `speed`.
fn point_key(case: &Case, speed: f64) -> String {
    format!("{:016x}@{speed}", case.fingerprint)
}

/// Every (case index, speed) of `cases` cases swept over `speeds`, case by case: one pool runs them all.
fn case_speed_pairs(cases: usize, speeds: &[f64]) -> Vec<(usize, f64)> {
    (0..cases).flat_map(|c| speeds.iter().map(move |&v| (c, v))).collect()
}

/// A case on a foundation fitted to the ground runs at the speed it was fitted at only, and a given speed profile sets
/// its speeds itself: a sweep over other speeds is refused before any run (each would fail alone).
fn check_fitted(case: &Case, speeds: &[f64]) -> Result<()> {
    let moving = &case.settings.moving;
    if let (Some(&v), false, None) = (speeds.first(), moving.profile.is_empty(), moving.acceleration) {
        moving.at_speed(v)?;
    }
    match case.ground_fit {
        Some(fit) if speeds.iter().any(|&v| v != fit.speed) => {
            Err(scenario::Scenario::sweep_on_the_ground(format!("fitted at {} m/s", fit.speed)))
        }
        _ => Ok(()),
    }
}

/// Every speed of a sweep must be finite and positive.
fn check_speeds(speeds: &[f64]) -> Result<()> {
    match speeds.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
        Some(&v) => Err(invalid("speeds", v, "every speed must be finite and > 0 (m/s)")),
        None => Ok(()),
    }
}
