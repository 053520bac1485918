//! What a run, a batch of runs or a stationary sweep will cost, estimated before it starts: a run's steps times a
//! per-step cost linear in the DOFs, the friction sections and the wheels; a stationary solve's nodes times a cost
//! per node that depends on whether the problem is smooth. Rates measured on the project machine (2 cores, release
//! build, one run on one core; BENCHMARKS.md). An estimate to within a factor of about 2–3, for deciding whether
//! to wait — the one rule every entry point (runs, sweeps, studies, stationary sweeps) announces long work by.

use crate::scenario::Case;
use stationary::StationaryProblem;

/// Seconds per DOF and step of a friction-free run: the two banded solves and products of the step and the
/// observers (measured 7.9e-9 s with 40 002 DOFs × 20 000 steps, 1.4e-8 s on the 402-DOF reference case, where the
/// fixed costs weigh more).
const PER_DOF_STEP: f64 = 1.0e-8;
/// Seconds per friction section and step (distributed friction on the reference track: 0.25–0.3 s for 799 sections
/// × 2000 steps beyond the friction-free run; devices cost about the same per section).
const PER_SECTION_STEP: f64 = 2.0e-7;
/// Seconds per wheel and step (a quarter car with Hertz contact on the reference track: 20 ms against 11 ms for the
/// moving force over 2000 steps).
const PER_WHEEL_STEP: f64 = 5.0e-6;

/// The size of a run and its estimated wall time on one core.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RunCost {
    /// Time steps.
    pub steps: f64,
    /// Free DOFs of the system (beam and vehicles).
    pub dofs: usize,
    /// Friction sections and devices.
    pub sections: usize,
    /// Wheels.
    pub wheels: usize,
    /// Estimated wall time (s).
    pub seconds: f64,
}

impl RunCost {
    /// The cost of one run of `case` at its own speed.
    pub fn of(case: &Case) -> Self {
        let steps = case.settings.step_count(case.model.mesh().length);
        let dofs = case.model.dofs().free_len();
        let sections = case.interactions.len();
        let wheels = case.settings.moving.load.vehicles().map_or(0, |v| v.wheels().count());
        let per_step = PER_DOF_STEP * dofs as f64 + PER_SECTION_STEP * sections as f64 + PER_WHEEL_STEP * wheels as f64;
        Self { steps, dofs, sections, wheels, seconds: steps * per_step }
    }
}

/// Seconds per node of the moving domain and speed of a smooth stationary solve (linear or bilinear soil, no
/// friction), its halved-element error estimate included: measured 1.6–2.7e-6 s on the reference track over
/// 10–200 m/s on ±60 m and ±240 m.
const STATIONARY_SMOOTH_PER_NODE: f64 = 3e-6;
/// Seconds per node and speed of a nonsmooth stationary solve (tensionless soil or ballast friction), its error
/// estimate included: measured 2.6–6.3e-5 s (5 kN/m friction and a tensionless soil with the rail's weight, ±60 m
/// and ±240 m, 0.25 m and 0.0625 m elements).
const STATIONARY_NONSMOOTH_PER_NODE: f64 = 5e-5;
/// The share of a stationary solve's cost left without the halved-element error estimate (measured 2.41 s of 4.21 s
/// on the friction sweep of BENCHMARKS.md).
const WITHOUT_ERROR_ESTIMATE: f64 = 0.6;

/// Work estimated to take longer than this (s) is announced with its size and estimate before it starts (by every
/// entry point: the command line on standard error, Python on its standard error).
pub const ANNOUNCE_ABOVE: f64 = 10.0;

/// What a batch of work will cost before it starts: how many runs (or stationary solves), on how many threads, the
/// largest of them, and the estimated wall time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// Runs or solves still to do (those a journal already holds are left out).
    pub runs: usize,
    /// Worker threads they share.
    pub threads: usize,
    /// What the largest of them is.
    pub size: Size,
    /// Estimated wall time of the batch (s).
    pub seconds: f64,
}

/// The size of the largest item of an [`Estimate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Size {
    /// A time-domain run.
    Run(RunCost),
    /// A stationary solve on the moving domain.
    Stationary {
        /// Nodes of the moving domain.
        nodes: usize,
        /// Whether the problem is nonsmooth (a tensionless soil or ballast friction).
        nonsmooth: bool,
    },
}

impl Estimate {
    /// One run of this cost.
    pub fn run(cost: RunCost) -> Self {
        Self { runs: 1, threads: 1, size: Size::Run(cost), seconds: cost.seconds }
    }

    /// Runs of these costs shared by `threads` threads (see [`Estimate::together`]).
    pub fn of_runs(costs: impl IntoIterator<Item = RunCost>, threads: usize) -> Self {
        Self::together(costs.into_iter().map(Self::run), threads)
    }

    /// Independent batches shared by `threads` threads: their summed cost over the threads they can keep busy, the
    /// size of the largest.
    pub fn together(batches: impl IntoIterator<Item = Estimate>, threads: usize) -> Self {
        let mut all = Self { runs: 0, threads, size: Size::Run(RunCost::default()), seconds: 0.0 };
        let (mut count, mut largest) = (0, 0.0);
        for batch in batches {
            count += 1;
            all.runs += batch.runs;
            all.seconds += batch.seconds;
            if count == 1 || batch.seconds > largest {
                (all.size, largest) = (batch.size, batch.seconds);
            }
        }
        all.seconds /= threads.clamp(1, count.max(1)) as f64;
        all
    }

    /// Whether the batch is long enough to announce ([`ANNOUNCE_ABOVE`]).
    pub fn is_long(&self) -> bool {
        self.seconds >= ANNOUNCE_ABOVE
    }

    /// The batch in words: "195 runs, the largest of 2000 steps over 400 DOFs, 31 friction sections, 0 wheels, on
    /// 2 threads: estimated 3 min (within a factor of 2–3)".
    pub fn describe(&self) -> String {
        let size = match self.size {
            Size::Run(cost) => format!(
                "{:.0} steps over {} DOFs, {} friction sections, {} wheels",
                cost.steps, cost.dofs, cost.sections, cost.wheels
            ),
            Size::Stationary { nodes, nonsmooth } => {
                format!("{nodes} nodes{}", if nonsmooth { ", nonsmooth (Newton on the contact set)" } else { "" })
            }
        };
        let items = match self.size {
            Size::Run(_) if self.runs == 1 => size,
            Size::Run(_) => format!("{} runs, the largest of {size}, on {} threads", self.runs, self.threads),
            Size::Stationary { .. } => format!("{} stationary solves of {size}", self.runs),
        };
        format!("{items}: estimated {} (within a factor of 2–3)", duration(self.seconds))
    }

    /// `speeds` stationary solves of `problem` in continuation (one after another), with or without the
    /// halved-element error estimate.
    pub fn stationary(problem: &StationaryProblem, speeds: usize, error_estimate: bool) -> Self {
        let domain = &problem.domain;
        let nodes = ((domain.behind + domain.ahead) / domain.element_length).ceil() as usize + 1;
        let nonsmooth =
            problem.friction.force_per_length > 0.0 || problem.foundation.law == fem_beam::FoundationLaw::Tensionless;
        let per_node = if nonsmooth { STATIONARY_NONSMOOTH_PER_NODE } else { STATIONARY_SMOOTH_PER_NODE };
        let share = if error_estimate { 1.0 } else { WITHOUT_ERROR_ESTIMATE };
        let seconds = speeds as f64 * nodes as f64 * per_node * share;
        Self { runs: speeds, threads: 1, size: Size::Stationary { nodes, nonsmooth }, seconds }
    }
}

/// A duration in the unit a reader wants: s, min or h.
fn duration(seconds: f64) -> String {
    if seconds < 120.0 {
        format!("{seconds:.0} s")
    } else if seconds < 7200.0 {
        format!("{:.0} min", seconds / 60.0)
    } else {
        format!("{:.1} h", seconds / 3600.0)
    }
}

#[cfg(test)]
mod tests {
    use super::{Estimate, RunCost, Size};
    use crate::Scenario;

    /// The reference case is instant; 20 000 elements with a 0.01 m load advance take seconds (measured 6.4 s); a
    /// million elements are hours, and the estimate says so before the run.
    #[test]
    fn estimates_grow_with_steps_dofs_and_sections() {
        let reference = RunCost::of(&Scenario::default().build().unwrap());
        assert_eq!((reference.steps, reference.dofs, reference.sections), (2000.0, 400, 0));
        assert!(reference.seconds < 0.1, "{reference:?}");
        let mut fine = Scenario::default();
        fine.mesh.elements = 20_000;
        fine.integration.load_advance = 0.01;
        let fine = RunCost::of(&fine.build().unwrap());
        assert!((3.0..15.0).contains(&fine.seconds), "{fine:?}");
        let mut distributed = Scenario::default();
        distributed.friction.distributed =
            Some(crate::scenario::DistributedSection { force_per_length: 1e3, ..Default::default() });
        let distributed = RunCost::of(&distributed.build().unwrap());
        assert!(distributed.sections > 700 && (0.1..1.0).contains(&distributed.seconds), "{distributed:?}");
    }

    /// A batch's wall time is its summed cost over the threads it keeps busy; its size is its largest run.
    #[test]
    fn a_batch_shares_its_cost_over_the_threads_it_keeps_busy() {
        let run = |seconds| RunCost { seconds, ..RunCost::default() };
        let batch = Estimate::of_runs([run(2.0), run(6.0), run(4.0)], 2);
        assert_eq!((batch.runs, batch.seconds), (3, 6.0));
        assert_eq!(batch.size, Size::Run(run(6.0)));
        // One run keeps one of eight threads busy; none costs nothing.
        assert_eq!(Estimate::of_runs([run(6.0)], 8).seconds, 6.0);
        assert_eq!(Estimate::of_runs([], 8).seconds, 0.0);
    }

    /// The reference track's stationary sweep over 100 speeds: linear about 0.1 s (measured 0.04 s), with 5 kN/m
    /// ballast friction a few seconds (measured 2.2 s); 190 000 speeds with friction hours, said before the first.
    #[test]
    fn stationary_sweeps_cost_by_nodes_and_smoothness() {
        let problem =
            crate::stationary_output::problem(&Scenario::default(), 100.0, stationary::Domain::default()).unwrap();
        let linear = Estimate::stationary(&problem, 100, true);
        assert_eq!(linear.size, Size::Stationary { nodes: 481, nonsmooth: false });
        assert!(linear.seconds < 1.0, "{linear:?}");
        let mut friction = problem;
        friction.friction.force_per_length = 5e3;
        let sweep = Estimate::stationary(&friction, 100, true);
        assert!((1.0..6.0).contains(&sweep.seconds), "{sweep:?}");
        let long = Estimate::stationary(&friction, 190_000, true);
        assert!(long.is_long() && !linear.is_long() && long.seconds > 3600.0, "{long:?}");
        assert_eq!(
            long.describe(),
            "190000 stationary solves of 481 nodes, nonsmooth (Newton on the contact set): \
                                     estimated 76 min (within a factor of 2–3)"
        );
        assert!(Estimate::stationary(&friction, 100, false).seconds < sweep.seconds);
    }
}
