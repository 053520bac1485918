//! What a run, a batch of runs or a stationary sweep will cost, estimated before it starts: a run's steps times a
//! per-step cost linear in the DOFs, the friction sections and the wheels; a stationary solve's nodes times a cost
//! per node that depends on whether the problem is smooth. Rates measured on the project machine (2 cores, release
//! build, one run on one core; BENCHMARKS.md). An estimate to within a factor of about 2–3, for deciding whether
//! to wait — the one rule every entry point (runs, sweeps, studies, stationary sweeps) announces long work by.

use nscd::SolverKind;
use scenario::Case;
use stationary::StationaryProblem;

/// Seconds per DOF and step of a friction-free run: the two banded solves and products of the step and the
/// observers (measured 7.9e-9 s with 40 002 DOFs × 20 000 steps, 1.4e-8 s on the 402-DOF reference case, where the
/// fixed costs weigh more).
const PER_DOF_STEP: f64 = 1.0e-8;
/// Seconds per friction section and step under the interior point (what `auto` picks for many sections; the
/// homotopy costs about the same): distributed friction on the reference track 0.25–0.3 s for 799 sections × 2000
/// steps beyond the friction-free run (1.7e-7); on 0.15 m elements near the critical speed, 5327 sections of 2–5 kN/m
/// with 10–13 iterations a step, 3.3–4.3 s for 1998 steps (3.1e-7–4.0e-7, the sleeper-friction study's continuous
/// twin); devices cost about the same per section. Between the two. (On sleepers, whose band is wider, 2 kN/m along
/// 30 m of rail took 1.43 s for 799 sections × 1000 steps, 1.8e-6, the window then covering nearly every section.)
const PER_SECTION_STEP: f64 = 3.0e-7;
/// Seconds per friction section and step under Clarabel, a general conic solver re-factoring a sparse KKT system each
/// iteration: 2 kN/m along 30 m, 799 sections × 1000 steps, 12.2 s on a soil and 17.7 s on sleepers
/// (1.5e-5–2.2e-5; the interior point took 0.63 and 1.43 s).
const CLARABEL_PER_SECTION_STEP: f64 = 2.0e-5;
/// Seconds per friction section and step under projection (Gauss–Seidel on the dense W, handing the steps it stalls
/// on to the fallback): the same 30 m, 3.4 s on a soil and 1.55 s on sleepers (4.3e-6, 1.9e-6); the reference track
/// with 5 kN/m, 4.9 s for 799 × 2000 (3.1e-6).
const PROJECTION_PER_SECTION_STEP: f64 = 3.0e-6;
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
    /// The friction solver asked for (its sections' rate).
    pub solver: SolverKind,
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
        let solver = case.settings.integration.solver.kind;
        let per_section = match solver {
            SolverKind::Clarabel => CLARABEL_PER_SECTION_STEP,
            SolverKind::Projection => PROJECTION_PER_SECTION_STEP,
            SolverKind::Auto | SolverKind::InteriorPoint | SolverKind::Homotopy => PER_SECTION_STEP,
        };
        let per_step = PER_DOF_STEP * dofs as f64 + per_section * sections as f64 + PER_WHEEL_STEP * wheels as f64;
        Self { steps, dofs, sections, wheels, solver, seconds: steps * per_step }
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
/// Seconds per node and speed of a nonsmooth stationary solve at or above the critical speed, where the wave reaches
/// far and the domain grows with it: measured 8.5e-4 s on a damped track (ζ = 5 %, 10 kN/m of ballast friction,
/// 200–300 m/s: 0.41 s a speed) and 1.05e-3 s undamped with 10 kN/m by 1 m/s steps. Undamped (ζ < [`DAMPED`]) the
/// cost grows as the friction falls — 2 kN/m took over 20 s a speed — so the estimate is then only a lower bound.
const STATIONARY_SUPERCRITICAL_PER_NODE: f64 = 8e-4;
/// The damping ratio from which a supercritical wave counts as damped.
const DAMPED: f64 = 0.02;
/// The share of a stationary solve's cost left without the halved-element error estimate (measured 2.41 s of 4.21 s
/// on the friction sweep of BENCHMARKS.md).
const WITHOUT_ERROR_ESTIMATE: f64 = 0.6;

/// Seconds per free DOF and frequency of a receptance: one complex banded factorisation and solve, its resonances'
/// refinement included (20 001 frequencies on one thread: 1.36 s over the reference track's 400 DOFs, 1.7e-7;
/// 11.4 s over examples/discrete-track.toml's 2997, 1.9e-7).
const RECEPTANCE_PER_DOF_FREQUENCY: f64 = 2e-7;

/// Seconds per moving-load spectrum of a beam on a layered ground on one thread (each spectrum a few hundred strip
/// integrals: 0.54–0.90 s on 2 threads on a soft two-layer site, BENCHMARKS.md; ~1.4 s on one), for a ground of
/// [`GROUND_LAYERS`] layers; a strip integral's layer matrices grow with the layers ([`layers_factor`]).
const GROUND_SPECTRUM: f64 = 1.4;
/// The layers of the site [`GROUND_SPECTRUM`] was measured on.
const GROUND_LAYERS: usize = 2;

/// How a ground's cost grows with its `layers` over [`GROUND_LAYERS`]: affine, (4 + n)/(4 + 2) — measured on
/// Ledsgård's profile with each of its 4 layers split into 1, 5 and 25 of the same soil (one spectrum at 40 m/s,
/// 2 threads, a loaded machine): 0.34, 0.97 and 5.57 s, i.e. 1 : 2.9 : 16.4 against (4 + n)'s 1 : 3 : 13.
fn layers_factor(layers: usize) -> f64 {
    (4.0 + layers as f64) / (4.0 + GROUND_LAYERS as f64)
}

/// A speed's wave with ballast friction on the ground over its linear wave: 2.2–3.0 at Ledsgård (1.15–1.57 s against
/// 0.53 s, BENCHMARKS.md).
pub const GROUND_FRICTION_FACTOR: f64 = 2.5;
/// Seconds per frequency of a point receptance on a layered ground on one thread (an integral over k of strip
/// integrals: 30 frequencies of examples/soft-ground.toml took 104 s on 2 threads).
const GROUND_RECEPTANCE: f64 = 7.0;

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
    /// Whether `seconds` is only a lower bound (nonsmooth stationary solves above the critical speed of an undamped
    /// track, whose domains grow with the wave by an amount no rate foresees).
    pub lower_bound: bool,
}

/// The size of the largest item of an [`Estimate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Size {
    /// A time-domain run.
    Run(RunCost),
    /// Frequencies of a receptance, each one complex banded factorisation and solve.
    Receptance {
        /// Frequencies.
        frequencies: usize,
        /// Free DOFs of the track.
        dofs: usize,
    },
    /// Integrals over the wavenumber of a beam on a layered ground (each a few hundred strip integrals).
    Ground {
        /// How many.
        integrals: usize,
        /// What they are: "moving-load spectra", "point receptances".
        what: &'static str,
    },
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
        Self { runs: 1, threads: 1, size: Size::Run(cost), seconds: cost.seconds, lower_bound: false }
    }

    /// Runs of these costs shared by `threads` threads (see [`Estimate::together`]).
    pub fn of_runs(costs: impl IntoIterator<Item = RunCost>, threads: usize) -> Self {
        Self::together(costs.into_iter().map(Self::run), threads)
    }

    /// Independent batches shared by `threads` threads: their summed cost over the threads they can keep busy, the
    /// size of the largest.
    pub fn together(batches: impl IntoIterator<Item = Estimate>, threads: usize) -> Self {
        let mut all = Self { runs: 0, threads, size: Size::Run(RunCost::default()), seconds: 0.0, lower_bound: false };
        let (mut count, mut largest) = (0, 0.0);
        for batch in batches {
            count += 1;
            all.runs += batch.runs;
            all.seconds += batch.seconds;
            all.lower_bound |= batch.lower_bound;
            if count == 1 || batch.seconds > largest {
                (all.size, largest) = (batch.size, batch.seconds);
            }
        }
        all.seconds /= threads.clamp(1, count.max(1)) as f64;
        all
    }

    /// Whether the batch is long enough to announce ([`ANNOUNCE_ABOVE`]), or may be (a lower bound is always said).
    pub fn is_long(&self) -> bool {
        self.seconds >= ANNOUNCE_ABOVE || self.lower_bound
    }

    /// The batch in words: "195 runs, the largest of 2000 steps over 400 DOFs, 31 friction sections, 0 wheels, on
    /// 2 threads: estimated 3 min (within a factor of 2–3)".
    pub fn describe(&self) -> String {
        let size = match self.size {
            Size::Run(cost) => {
                let solver = match (cost.sections, cost.solver) {
                    (0, _) | (_, SolverKind::Auto) => String::new(),
                    (_, kind) => format!(" (by {kind})"),
                };
                format!(
                    "{:.0} steps over {} DOFs, {} friction sections{solver}, {} wheels",
                    cost.steps, cost.dofs, cost.sections, cost.wheels
                )
            }
            Size::Stationary { nodes, nonsmooth } => {
                format!("{nodes} nodes{}", if nonsmooth { ", nonsmooth (Newton on the contact set)" } else { "" })
            }
            Size::Receptance { frequencies, dofs } => format!("{frequencies} frequencies over {dofs} DOFs"),
            Size::Ground { integrals, what } => format!("{integrals} {what} on a layered ground"),
        };
        let items = match self.size {
            Size::Run(_) if self.runs == 1 => size,
            Size::Run(_) => format!("{} runs, the largest of {size}, on {}", self.runs, threads(self.threads)),
            Size::Stationary { .. } => format!("{} stationary solves of {size}", self.runs),
            Size::Receptance { .. } => format!("a receptance of {size}, on {}", threads(self.threads)),
            Size::Ground { .. } => format!("{size}, on {}", threads(self.threads)),
        };
        match self.lower_bound {
            false => format!("{items}: estimated {} (within a factor of 2–3)", duration(self.seconds)),
            true => format!(
                "{items}: estimated at least {} (above the critical speed of an undamped track the domain grows with \
                 the wave: a speed may take seconds to minutes, more as the friction falls)",
                duration(self.seconds)
            ),
        }
    }

    /// A receptance of a track of `dofs` free DOFs at `frequencies` frequencies, shared by `threads` threads.
    pub fn receptance(dofs: usize, frequencies: usize, threads: usize) -> Self {
        let threads = threads.clamp(1, frequencies.max(1));
        let seconds = RECEPTANCE_PER_DOF_FREQUENCY * (dofs * frequencies) as f64 / threads as f64;
        Self { runs: 1, threads, size: Size::Receptance { frequencies, dofs }, seconds, lower_bound: false }
    }

    /// `spectra` moving-load spectra of a beam on a ground of `layers` layers, each shared by `threads` threads.
    pub fn ground(spectra: usize, layers: usize, threads: usize) -> Self {
        let threads = threads.max(1);
        let seconds = GROUND_SPECTRUM * layers_factor(layers) * spectra as f64 / threads as f64;
        let size = Size::Ground { integrals: spectra, what: "moving-load spectra" };
        Self { runs: 1, threads, size, seconds, lower_bound: false }
    }

    /// `linear` moving-load waves on a layered ground and `with_friction` with ballast friction (each
    /// [`GROUND_FRICTION_FACTOR`] times a linear one), shared by `threads` threads.
    pub fn ground_waves(linear: usize, with_friction: usize, layers: usize, threads: usize) -> Self {
        let spectra = linear + with_friction;
        let all_linear = Self::ground(spectra, layers, threads);
        let share = (linear as f64 + GROUND_FRICTION_FACTOR * with_friction as f64) / spectra.max(1) as f64;
        Self { seconds: all_linear.seconds * share, ..all_linear }
    }

    /// A point receptance of a beam on a ground of `layers` layers at `frequencies` frequencies, shared by `threads`
    /// threads.
    pub fn ground_receptance(frequencies: usize, layers: usize, threads: usize) -> Self {
        let threads = threads.clamp(1, frequencies.max(1));
        let seconds = GROUND_RECEPTANCE * layers_factor(layers) * frequencies as f64 / threads as f64;
        let size = Size::Ground { integrals: frequencies, what: "point receptances" };
        Self { runs: 1, threads, size, seconds, lower_bound: false }
    }

    /// Stationary solves of `problem` at `speeds` in continuation (one after another), with or without the
    /// halved-element error estimate. A nonsmooth problem costs far more at or above the critical speed, where the
    /// wave reaches far behind the load and the domain grows with it.
    pub fn stationary(problem: &StationaryProblem, speeds: &[f64], error_estimate: bool) -> Self {
        let domain = &problem.domain;
        let nodes = ((domain.behind + domain.ahead) / domain.element_length).ceil() as usize + 1;
        let nonsmooth =
            problem.friction.force_per_length > 0.0 || problem.foundation.law == fem_beam::FoundationLaw::Tensionless;
        let (beam, foundation) = (&problem.beam, &problem.foundation);
        // v_cr of the rail as it is (Timoshenko's below Euler–Bernoulli's); 0 without a soil (every speed
        // supercritical), as the formula gives.
        let critical = analytic::MovingBeam::new(beam, foundation).map_or(0.0, |b| b.critical_speed());
        let per_node = |v: f64| match (nonsmooth, v >= critical) {
            (false, _) => STATIONARY_SMOOTH_PER_NODE,
            (true, false) => STATIONARY_NONSMOOTH_PER_NODE,
            (true, true) => STATIONARY_SUPERCRITICAL_PER_NODE,
        };
        let share = if error_estimate { 1.0 } else { WITHOUT_ERROR_ESTIMATE };
        let seconds = speeds.iter().map(|&v| per_node(v)).sum::<f64>() * nodes as f64 * share;
        let lower_bound = nonsmooth && foundation.damping_ratio(beam) < DAMPED && speeds.iter().any(|&v| v >= critical);
        Self { runs: speeds.len(), threads: 1, size: Size::Stationary { nodes, nonsmooth }, seconds, lower_bound }
    }
}

/// "1 thread", "2 threads".
fn threads(count: usize) -> String {
    format!("{count} thread{}", if count == 1 { "" } else { "s" })
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
    use nscd::SolverKind;
    use scenario::Scenario;

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
            Some(scenario::DistributedSection { force_per_length: 1e3, ..Default::default() });
        let distributed = RunCost::of(&distributed.build().unwrap());
        assert!(distributed.sections > 700 && (0.1..1.0).contains(&distributed.seconds), "{distributed:?}");
    }

    /// The solver sets a run's rate per section: 2 kN/m of ballast friction on the reference track is half a
    /// second by the interior point (measured 0.49 s) and announced as long by Clarabel (measured 22.8 s, estimated
    /// 32 s; it ran unannounced when every solver was costed at the interior point's rate).
    #[test]
    fn a_run_is_costed_at_its_solvers_rate() {
        let mut scenario = Scenario::default();
        scenario.friction.distributed =
            Some(scenario::DistributedSection { force_per_length: 2e3, ..Default::default() });
        let interior_point = RunCost::of(&scenario.build().unwrap());
        scenario.integration.solver = SolverKind::Clarabel;
        let clarabel = RunCost::of(&scenario.build().unwrap());
        assert!(interior_point.seconds < 1.0 && !Estimate::run(interior_point).is_long(), "{interior_point:?}");
        assert!((15.0..60.0).contains(&clarabel.seconds) && Estimate::run(clarabel).is_long(), "{clarabel:?}");
        assert!(Estimate::run(clarabel).describe().contains("799 friction sections (by clarabel)"));
    }

    /// A receptance costs one banded factorisation per frequency: 201 frequencies of the reference track are
    /// instant, 100 000 over a 2997-DOF sleeper track a minute on one thread (measured 11.4 s for 20 001), half on two.
    #[test]
    fn a_receptance_is_costed_by_its_dofs_and_frequencies() {
        let small = Estimate::receptance(400, 201, 2);
        assert!(small.seconds < 0.1 && !small.is_long(), "{small:?}");
        let large = Estimate::receptance(2997, 100_000, 1);
        assert!((40.0..80.0).contains(&large.seconds) && large.is_long(), "{large:?}");
        assert_eq!(Estimate::receptance(2997, 100_000, 2).seconds, 0.5 * large.seconds);
        assert_eq!(
            large.describe(),
            "a receptance of 100000 frequencies over 2997 DOFs, on 1 thread: estimated 60 s (within a factor of 2–3)"
        );
    }

    /// The ground's study is costed by its spectra: `frictrack ground`'s 37 on 2 threads are ~26 s (measured 25–34 s
    /// on the soft-ground example), long enough to be announced.
    #[test]
    fn the_ground_is_costed_by_its_spectra() {
        let ground = Estimate::ground(37, 2, 2);
        assert!((15.0..40.0).contains(&ground.seconds) && ground.is_long(), "{ground:?}");
        assert!(ground.describe().starts_with("37 moving-load spectra on a layered ground, on 2 threads"));
        // 200 layers cost ~34 times 2 (the estimate ignored them: 26 s for 2 and for 200).
        assert!((Estimate::ground(37, 200, 2).seconds / ground.seconds - 34.0).abs() < 1e-9);
        let receptance = Estimate::ground_receptance(30, 2, 2);
        assert!((50.0..200.0).contains(&receptance.seconds), "{receptance:?}");
        assert!(receptance.describe().starts_with("30 point receptances on a layered ground"));
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
        let problem = Scenario::default().stationary_problem(100.0, stationary::Domain::default()).unwrap();
        let speeds = |from: f64, to: f64, count: usize| -> Vec<f64> {
            (0..count).map(|i| from + (to - from) * i as f64 / (count - 1).max(1) as f64).collect()
        };
        let linear = Estimate::stationary(&problem, &speeds(10.0, 200.0, 100), true);
        assert_eq!(linear.size, Size::Stationary { nodes: 481, nonsmooth: false });
        assert!(linear.seconds < 1.0, "{linear:?}");
        let mut friction = problem;
        friction.friction.force_per_length = 5e3;
        let sweep = Estimate::stationary(&friction, &speeds(10.0, 200.0, 100), true);
        assert!((1.0..6.0).contains(&sweep.seconds), "{sweep:?}");
        // Above v_cr = 205.57 m/s the wave reaches far: 200–300 m/s by 20 measured 2.46 s at ζ = 5 %; undamped (21.5 s
        // with 10 kN/m by 20 m/s steps, over 20 s a speed with 2 kN/m) only a lower bound is said.
        let mut damped = friction;
        damped.foundation.damping = 0.05 * damped.foundation.critical_damping(&damped.beam);
        let damped = Estimate::stationary(&damped, &speeds(200.0, 300.0, 6), true);
        assert!((1.0..5.0).contains(&damped.seconds) && !damped.lower_bound, "{damped:?}");
        let undamped = Estimate::stationary(&friction, &speeds(200.0, 300.0, 6), true);
        assert!(undamped.lower_bound && undamped.is_long(), "{undamped:?}");
        assert!(undamped.describe().contains("estimated at least"), "{undamped:?}");
        assert!(!sweep.lower_bound && !linear.lower_bound);
        let long = Estimate::stationary(&friction, &speeds(10.0, 200.0, 190_000), true);
        assert!(long.is_long() && !linear.is_long() && long.seconds > 3600.0, "{long:?}");
        assert_eq!(
            long.describe(),
            "190000 stationary solves of 481 nodes, nonsmooth (Newton on the contact set): \
                                     estimated 76 min (within a factor of 2–3)"
        );
        assert!(Estimate::stationary(&friction, &speeds(10.0, 200.0, 100), false).seconds < sweep.seconds);
    }

    /// A Timoshenko rail's wave turns supercritical at its own v_cr, below Euler–Bernoulli's (shear and rotary
    /// inertia soften it): between the two an undamped friction sweep is said to be a lower bound — the Euler–Bernoulli
    /// formula, used before, called it subcritical.
    #[test]
    fn a_timoshenko_rail_turns_supercritical_at_its_own_critical_speed() {
        let mut problem = Scenario::default().stationary_problem(100.0, stationary::Domain::default()).unwrap();
        problem.friction.force_per_length = 5e3;
        let euler = analytic::MovingBeam::new(&problem.beam, &problem.foundation).unwrap().critical_speed();
        problem.beam.theory = fem_beam::BeamTheory::Timoshenko { shear_modulus: 81e9, shear_coefficient: 0.4 };
        let shear = analytic::MovingBeam::new(&problem.beam, &problem.foundation).unwrap().critical_speed();
        assert!(shear < euler, "{shear} vs {euler}");
        let between = [0.5 * (shear + euler)];
        assert!(Estimate::stationary(&problem, &between, true).lower_bound);
        assert!(!Estimate::stationary(&problem, &[0.99 * shear], true).lower_bound);
    }
}
