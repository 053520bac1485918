//! The parametric active-set (homotopy) solver of a friction step (docs/theory.md §5).
//!
//! # The law it solves
//! For ε > 0, γ_j = a_j/ε (kg; a_j the half-width of section j's impulse interval [lo_j, hi_j], centre c_j) and a
//! shift p̄, the *shifted Huber law* is
//!
//! ```text
//! p_j = clip(q_j, lo_j, hi_j),   q_j = p̄_j − γ_j u_j,   u = H v,   M̂(v − v_free) = Hᵀp,
//! ```
//!
//! the optimality condition of the strongly convex, piecewise quadratic problem
//! min_v ½‖v − v_free‖²_M̂ + Σ_j ψ_j(H_j v) with ψ_j′(u) = −clip(p̄_j − γ_j u, lo_j, hi_j): v and p are unique, however
//! many sections share an element (where Coulomb's own stuck impulses are not). With p̄ = the previous step's
//! impulses, a section inside its interval ("in the band") has |u_j| = |p̄_j − p_j|/γ_j ≤ 2ε, one at a bound slips with
//! the sign Coulomb's law demands: the law residual is ≤ 2ε. ε = 0.4·tol·U, the velocity scale U ≈ max|u_free| kept
//! while max|u_free| stays within [0.85U, 4U], so 2ε ≤ 0.94·tol·max|u_free|: the step meets the relative tolerance
//! by construction.
//!
//! # One step: a path in τ
//! On a fixed partition (band, at the lower bound, at the upper bound) the law is linear:
//! B v = M̂ v_free + Σ_band h_j p̄_j + Σ_bound h_j p_j with B = M̂ + Σ_band γ_j h_j h_jᵀ (banded). The step follows
//! v_free(τ) = v_free⁰ + τ(v_free − v_free⁰), p̄(τ) = p̄⁰ + τ(p̄¹ − p̄⁰) from τ = 0, where the previous step's solution
//! (v⁰, p⁰) solves the law exactly (p̄⁰ = p⁰ + γu⁰ in the band, p⁰ at a bound), to τ = 1 (p̄¹ = p⁰): the solution
//! is linear in τ between *events*, where some q_j reaches a bound of its interval and the section changes side.
//! An event is a rank-one change of B, corrected on B₀'s factor by Sherman–Morrison–Woodbury with a local solve
//! (`corrections`): it moves the rates and event times only of the sections near it; after [`MAX_CORRECTIONS`]
//! events, or when the capacitance's pivot shows it ill-conditioned, B₀ is factored afresh. At τ = 1 a *polish* solves the final partition exactly and repairs any section found on the wrong side (round-off
//! at ties) by moving it and solving again (at most [`MAX_REPAIRS`] rounds); a step still inconsistent is reported
//! stalled and the stepper's fallback solvers take it.
//!
//! After Ferreau, Bock & Diehl (2008), the online active set strategy of qpOASES (a parametric QP followed along a
//! homotopy between two problems), and Tibshirani & Taylor (2011) for the path of a piecewise quadratic problem.

mod corrections;
mod path;

use super::{InteractionProblem, InteractionSolver, SolverKind, StepReport, StepStatus, StepWork};
use banded::{BandedLdlt, SymmetricBanded};

/// Polish rounds after the path (each a factorisation and a solve) before the step is handed to a fallback.
pub const MAX_REPAIRS: usize = 3;

/// ε = this × the relative tolerance × the velocity scale U: the band's half-width in u is 2ε, below the tolerance.
const BAND_FRACTION: f64 = 0.4;

/// Events corrected by Sherman–Morrison–Woodbury before B₀ is factored afresh (the capacitance's LDLᵀ grows by a
/// row per event, O(k²); each event's rates cost O(k × the sections a column touches)). Measured on the four
/// reference distributed runs (BENCHMARKS.md): 12 is the fastest; 64 brings the factorisations to 1.03–1.38 per
/// step but costs 1.2–1.7× the time, the rates of ~25 earlier events being redone at every event.
pub const MAX_CORRECTIONS: usize = 12;

/// An event time waiting in the queue: stale once its section's `version` has moved on.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Pending {
    time: f64,
    section: usize,
    version: u32,
}

impl Eq for Pending {}

impl Ord for Pending {
    /// The earliest time first (the queue is a max-heap), ties by section.
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        other.time.total_cmp(&self.time).then(other.section.cmp(&self.section))
    }
}

impl PartialOrd for Pending {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

/// The tightest relative tolerance the solver takes (see [`ParametricActiveSet::new`]).
pub const MIN_TOLERANCE: f64 = 1e-8;

/// U is kept while max|u_free| stays within [U·KEEP_SCALE.0, U·KEEP_SCALE.1] (a new U changes every γ_j, hence B).
const KEEP_SCALE: (f64, f64) = (0.85, 4.0);

/// Where a section is on its interval.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Side {
    /// lo < p < hi: p = q.
    Band,
    /// p = lo (q ≤ lo: slipping with u ≥ 0).
    Lower,
    /// p = hi (q ≥ hi: slipping with u ≤ 0).
    Upper,
    /// lo = hi this step: p = lo, never moves.
    Fixed,
}

/// The previous step's solution, where the next path starts.
#[derive(Debug, Clone)]
struct Anchor {
    /// v_free⁰ (the previous step's free velocity).
    v_free: Vec<f64>,
    /// v⁰ = v_free⁰ + M̂⁻¹Hᵀp⁰, as the stepper formed it, and u⁰ = Hv⁰.
    v: Vec<f64>,
    u: Vec<f64>,
    /// p⁰ (N·s).
    p: Vec<f64>,
}

/// The homotopy solver of one run: the partition, B and its factor, the anchor, scratch.
#[derive(Debug)]
pub struct ParametricActiveSet {
    /// Relative tolerance of the law residual.
    tolerance: f64,
    /// Event budget of a step.
    max_events: usize,
    /// U (m/s), None before the first step.
    scale: Option<f64>,
    /// γ_j = a_j/ε (kg).
    gamma: Vec<f64>,
    /// The side of each section.
    side: Vec<Side>,
    /// B = M̂ + Σ_band γ_j h_j h_jᵀ of `side`.
    b: SymmetricBanded,
    b_factor: BandedLdlt,
    /// Whether `b` and `b_factor` must be rebuilt for `side` and `gamma` before the next solve.
    stale: bool,
    /// The previous step's solution, if this solver produced the impulses the stepper passes in.
    anchor: Option<Anchor>,
    /// Scratch: v and the direction (n), M̂(v_free − v_free⁰) (n), u, q and their rates along τ, p̄¹ − p̄⁰ (m), the
    /// τ of each section's last change of side.
    v: Vec<f64>,
    dv: Vec<f64>,
    base_rate: Vec<f64>,
    u: Vec<f64>,
    du: Vec<f64>,
    q: Vec<f64>,
    dq: Vec<f64>,
    dshift: Vec<f64>,
    changed_at: Vec<f64>,
    /// q_j is q at τ = `tau_ref[j]`, moving at `dq[j]` since.
    tau_ref: Vec<f64>,
    /// du − du₀ of the sections the events' columns touch (`union`, flagged in `in_union`), zero elsewhere.
    du_extra: Vec<f64>,
    union: Vec<usize>,
    in_union: Vec<bool>,
    /// The earliest event among the union's sections: (τ, section).
    union_next: Option<(f64, usize)>,
    /// The events since B₀'s factorisation, as its Sherman–Morrison–Woodbury correction.
    corrections: corrections::Corrections,
    /// Event times of the sections, the earliest on top; an entry is current while its version is the section's.
    pending: std::collections::BinaryHeap<Pending>,
    version: Vec<u32>,
    /// The sections in order of their rows' first DOF, and those DOFs (to find the sections a column touches).
    order: Vec<usize>,
    first_dofs: Vec<usize>,
    /// Velocity the stepper forms from the returned impulses (written back through [`InteractionSolver::velocity`]).
    v_out: Vec<f64>,
    u_out: Vec<f64>,
    /// What the step being solved has taken so far.
    work: StepWork,
}

impl ParametricActiveSet {
    /// The solver for `problem` at relative tolerance `tolerance` (≥ [`MIN_TOLERANCE`]) and at most `max_events`
    /// events a step. Takes fixed interactions with finite bounds, no compliance and no drift (Coulomb friction), on
    /// rows of at most four consecutive DOFs (what keeps B banded).
    pub fn new(problem: &InteractionProblem, tolerance: f64, max_events: usize) -> crate::Result<Self> {
        let law = &problem.law;
        let supported = !problem.has_moving()
            && !problem.is_varying()
            && problem.interactions.rows().iter().all(|r| r.is_local())
            && (0..problem.len()).all(|j| law.lower[j].is_finite() && law.upper[j].is_finite())
            && law.compliance.iter().all(|&d| d == 0.0)
            && law.drift.iter().all(|&b| b == 0.0);
        if !supported {
            return Err(crate::NscdError::Unsupported {
                solver: SolverKind::Homotopy,
                reason: "it takes fixed Coulomb friction sections (finite bounds, no compliance, no drift) on rows of at \
                         most four consecutive DOFs; other interactions need projection, interior-point or clarabel",
            });
        }
        if tolerance < MIN_TOLERANCE {
            return Err(crate::NscdError::Unsupported {
                solver: SolverKind::Homotopy,
                reason: "its relative tolerance must be at least 1e-8: γ = a/ε amplifies the round-off of the section \
                         velocities into the impulses (accuracy ~1e-16/(0.4·tol) relative); take the interior point \
                         for tighter tolerances",
            });
        }
        let (n, m) = (problem.matrix.m_hat.order(), problem.len());
        let first_dof = |j: usize| problem.interactions.rows()[j].dof_span().map_or(0, |(first, _)| first);
        let mut order: Vec<usize> = (0..m).collect();
        order.sort_by_key(|&j| first_dof(j));
        let first_dofs = order.iter().map(|&j| first_dof(j)).collect();
        Ok(Self {
            tolerance,
            max_events,
            scale: None,
            gamma: vec![0.0; m],
            side: vec![Side::Band; m],
            b: problem.matrix.m_hat.clone(),
            b_factor: problem.matrix.factor.clone(),
            stale: true,
            anchor: None,
            v: vec![0.0; n],
            dv: vec![0.0; n],
            base_rate: vec![0.0; n],
            u: vec![0.0; m],
            du: vec![0.0; m],
            q: vec![0.0; m],
            dq: vec![0.0; m],
            dshift: vec![0.0; m],
            changed_at: vec![f64::NAN; m],
            tau_ref: vec![0.0; m],
            du_extra: vec![0.0; m],
            union: Vec::new(),
            in_union: vec![false; m],
            union_next: None,
            corrections: corrections::Corrections::new(MAX_CORRECTIONS),
            pending: std::collections::BinaryHeap::with_capacity(4 * m),
            version: vec![0; m],
            order,
            first_dofs,
            v_out: vec![0.0; n],
            u_out: vec![0.0; m],
            work: StepWork::default(),
        })
    }

    /// Keep U while the step's velocity scale (max|u_free|: friction has no drift) stays within its range, else take
    /// U = that scale and γ_j = a_j/ε for it. Returns whether γ changed (B must then be rebuilt).
    fn update_scale(&mut self, problem: &InteractionProblem, u_free: &[f64]) -> bool {
        let largest = problem.velocity_scale(u_free);
        if let Some(scale) = self.scale
            && largest >= KEEP_SCALE.0 * scale
            && largest <= KEEP_SCALE.1 * scale
        {
            return false;
        }
        self.scale = Some(largest);
        let epsilon = BAND_FRACTION * self.tolerance * largest;
        let law = &problem.law;
        for (j, gamma) in self.gamma.iter_mut().enumerate() {
            *gamma = 0.5 * (law.upper[j] - law.lower[j]) / epsilon;
        }
        true
    }
}

impl InteractionSolver for ParametricActiveSet {
    fn kind(&self) -> SolverKind {
        SolverKind::Homotopy
    }

    fn velocity(&self) -> Option<&[f64]> {
        Some(&self.v_out)
    }

    fn solve(
        &mut self,
        problem: &InteractionProblem,
        v_free: &[f64],
        u_free: &[f64],
        p: &mut [f64],
    ) -> crate::Result<StepReport> {
        let tolerance = problem.absolute_tolerance(self.tolerance, u_free);
        self.work = StepWork::default();
        if self.update_scale(problem, u_free) {
            self.stale = true;
        }
        let mut anchor = self.take_anchor(problem, v_free, p);
        self.start(problem, v_free, &anchor);
        let events = self.follow_path(problem)?;
        let repairs = self.polish(problem, v_free, &anchor, p)?;
        // The law residual of the impulses as the stepper will use them: v = v_free + M̂⁻¹Hᵀp, formed here once
        // and handed back, so the check costs the stepper nothing.
        let residual = problem.outcome(v_free, p, &mut self.v_out, &mut self.u_out);
        self.work.solves += 1;
        self.work.events = events;
        self.work.repairs = repairs;
        // A step whose polish left a section on the wrong side still stands if its residual meets the tolerance
        // (the clipped impulses satisfy the law); otherwise the stepper's fallbacks take it.
        let status = StepStatus::of(residual, tolerance, events, self.max_events);
        // The next step starts from this one's solution, if the stepper takes it (it does when converged; the
        // impulses passed in next time tell).
        anchor.v_free.copy_from_slice(v_free);
        anchor.v.copy_from_slice(&self.v_out);
        anchor.u.copy_from_slice(&self.u_out);
        anchor.p.copy_from_slice(p);
        self.anchor = Some(anchor);
        let sections = problem.len();
        Ok(StepReport { status, iterations: events, residual, tolerance, sections, fallback: None, work: self.work })
    }
}
