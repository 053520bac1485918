//! The one-step problem of every interaction (docs/theory.md §5, §9): the box-constrained convex QP
//!
//! ```text
//! min ½ pᵀ(W + D)p + cᵀp   s.t.  lo ≤ p ≤ hi,    W = H M̂⁻¹Hᵀ,  D = diag(d),  c = H v_free + b
//! ```
//!
//! with v_{k+1} = v_free + M̂⁻¹Hᵀp. Its optimality conditions are the law of [`friction::law`] with the law velocity
//! r = (W + D)p + c = U_{k+1} + b + d∘p, U_{k+1} = H v_{k+1}. The run's data (M̂, its factor, W's diagonal, the impulse
//! responses) are made once; the step's law (lo, hi, d, b) is set from each law by [`InteractionProblem::update`]:
//!
//! - Coulomb friction of capacity F: [−hF, hF], d = 0, b = 0 (fixed for the run);
//! - Signorini contact, gap g = g₀ + H q: in the step's index set when the predicted gap g_k + γhU_k ≤ 0
//!   (γ = ½), or, moving and projected ([`crate::position`]), when closed: [0, +∞), d = 0, b = e·U_k (Newton
//!   impact); otherwise [0, 0];
//! - compliant stop of stiffness k_c, penetration δ = −g: [0, +∞), d = 1/(h²θk_c), b = −(δ_k − h(1−θ)U_k)/(hθ),
//!   so that a positive impulse is p = h k_c δ_{k+1}.
//!
//! A moving interaction ([`crate::moving`]) has its row (for t_{k+1}), gap g_k, velocity U_k and rheonomic
//! velocity b_r (U_{k+1} = H v_{k+1} + b_r) set by the update phase each step, its response G = M̂⁻¹Hᵀ and W_jj with
//! them; b_r joins its drift.

mod dof_responses;
mod energy;
mod fixed_rows;
pub mod responses;

use crate::integrator::{Integration, IterationMatrix};
use crate::kernels::axpy;
use crate::moving::{Interactions, MovingInteraction, MovingState};
use crate::position::{CLOSED_GAP, PositionProjection, ProjectionReport};
use crate::system::LinearSystem;
use dof_responses::DofResponses;
use fixed_rows::FixedRows;
pub use fixed_rows::pack_rows;
use friction::hertz::{HertzStep, NEWTON_TOLERANCE, PENETRATION_FLOOR};
use friction::law::{RowStart, natural_residual};
use friction::{InteractionSet, Law};
use responses::ImpulseResponses;
use std::sync::Arc;

/// Below this velocity (m/s) a section is considered at rest when scaling tolerances.
pub const VELOCITY_FLOOR: f64 = 1e-14;

/// The law of one step, per interaction: impulse bounds (N·s), compliance d (m/s per N·s), drift b (m/s).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StepLaw {
    /// lo (N·s), may be −∞.
    pub lower: Vec<f64>,
    /// hi (N·s), may be +∞.
    pub upper: Vec<f64>,
    /// d ≥ 0 (m/s per N·s): fixed for the run, except a Hertz contact's, which follows its linearisation.
    pub compliance: Vec<f64>,
    /// b (m/s).
    pub drift: Vec<f64>,
}

impl StepLaw {
    /// r = U + b + d·p: the velocity the law of interaction j holds against its impulse.
    #[inline]
    pub fn law_velocity(&self, j: usize, u: f64, p: f64) -> f64 {
        u + self.drift[j] + self.compliance[j] * p
    }

    /// Whether interaction j has room to move this step (lo < hi); otherwise its impulse is lo.
    #[inline]
    pub fn is_free(&self, j: usize) -> bool {
        self.lower[j] < self.upper[j]
    }
}

/// The data of every step of a run: M̂ and its LDLᵀ factors (always of that matrix: both are made here), the
/// interactions, the diagonal of W + D and the step's law. It owns all of it, so a stepper built on it borrows
/// nothing.
#[derive(Debug)]
pub struct InteractionProblem {
    /// The interactions.
    pub interactions: InteractionSet,
    /// The integrator's M̂ (for the step h and θ the problem is built for) and its factors, shared with the stepper.
    pub matrix: Arc<IterationMatrix>,
    /// The law of the current step.
    pub law: StepLaw,
    /// W_jj + d_j (m/s per N·s), W_jj = H_j M̂⁻¹ H_jᵀ.
    pub delassus_diagonal: Vec<f64>,
    /// G_j = M̂⁻¹H_jᵀ of the fixed interactions, truncated to round-off, when few and short enough to beat a solve
    /// (see [`ImpulseResponses`]).
    pub responses: Option<ImpulseResponses>,
    /// Whether the law changes from step to step (some unilateral or moving interaction).
    varying: bool,
    /// The fixed interactions come first: indices 0..fixed.
    fixed: usize,
    /// The moving interactions, at indices fixed.. of `interactions`.
    moving: Vec<Box<dyn MovingInteraction>>,
    /// Their states and dense responses G_j = M̂⁻¹H_jᵀ (n each, refreshed every step; zero outside
    /// `moving_support`).
    moving_states: Vec<MovingState>,
    moving_responses: Vec<f64>,
    /// The DOF range [lo, hi) each moving response was last written over.
    moving_support: Vec<(usize, usize)>,
    /// The single-DOF responses the moving responses are assembled from.
    dof_responses: DofResponses,
    /// The Hertz contacts' step states, by interaction (None for every other law).
    hertz: Vec<Option<HertzStep>>,
    /// The position projection of the rigid moving contacts.
    projection: PositionProjection,
    /// The fixed rows packed for the products of every step, where each is short and on consecutive DOFs.
    fixed_rows: Option<FixedRows>,
}

impl InteractionProblem {
    /// The problem of a step of `integration` on `system`: M̂ = M + hθC + h²θ²K is built and factored
    /// ([`IterationMatrix::new`], docs/theory.md §5).
    pub fn new(
        system: &LinearSystem,
        interactions: impl Into<Interactions>,
        integration: Integration,
    ) -> crate::Result<Self> {
        Self::with_matrix(interactions, IterationMatrix::new(system, integration)?)
    }

    /// The same on a given iteration matrix (e.g. a test problem's, [`IterationMatrix::of`]). The law is set for
    /// t = 0, q = 0, v = 0 until the first [`InteractionProblem::update`].
    pub fn with_matrix(interactions: impl Into<Interactions>, matrix: Arc<IterationMatrix>) -> crate::Result<Self> {
        let Interactions { fixed: mut interactions, moving } = interactions.into();
        let (factor, integration) = (&matrix.factor, matrix.integration);
        let weights = integration.weights();
        let fixed = interactions.len();
        let (responses, mut delassus_diagonal) = ImpulseResponses::new(&interactions, factor);
        for interaction in &moving {
            interactions.push_moving(Default::default(), interaction.law(), interaction.kind());
            delassus_diagonal.push(0.0);
        }
        let m = interactions.len();
        let mut law =
            StepLaw { lower: vec![0.0; m], upper: vec![0.0; m], compliance: vec![0.0; m], drift: vec![0.0; m] };
        let mut hertz = vec![None; m];
        for (j, l) in interactions.laws().iter().enumerate() {
            if let Law::Hertz { coefficient, .. } = *l {
                // Hertz's law is linearised step by step (its Newton state); only a moving contact takes it.
                if j < fixed {
                    return Err(crate::NscdError::InvalidField {
                        field: "law",
                        value: coefficient,
                        allowed: "Hertz's law is taken by moving interactions (wheels) only".into(),
                    });
                }
                hertz[j] = Some(HertzStep { coefficient, ..HertzStep::default() });
                continue;
            }
            law.compliance[j] = l.run_compliance(weights);
            // Friction's bounds are fixed for the run: set here, by the one mapping from law to bounds.
            if !l.depends_on_state() {
                (law.lower[j], law.upper[j], law.drift[j]) = l.step_bounds(RowStart::default(), weights, false);
            }
        }
        for (w, d) in delassus_diagonal.iter_mut().zip(&law.compliance) {
            *w += d;
        }
        let varying = !interactions.is_friction_only() || !moving.is_empty();
        let projection = PositionProjection::new(moving.len(), |k| moving[k].law().is_rigid());
        let n = matrix.order();
        let fixed_rows = FixedRows::new(&interactions, fixed);
        let mut problem = Self {
            fixed_rows,
            interactions,
            matrix,
            law,
            delassus_diagonal,
            responses,
            varying,
            fixed,
            moving_states: vec![MovingState::default(); moving.len()],
            moving_responses: vec![0.0; moving.len() * n],
            moving_support: vec![(0, 0); moving.len()],
            dof_responses: DofResponses::new(n),
            moving,
            hertz,
            projection,
        };
        problem.update(0.0, &vec![0.0; n], &vec![0.0; n]);
        Ok(problem)
    }

    /// The update phase (docs/theory.md §9): rebuild the moving interactions' rows, responses and W_jj at (t_k, q_k),
    /// then set the law of the step from the state (q_k, v_k). Nothing to do for fixed friction alone.
    pub fn update(&mut self, time: f64, q: &[f64], v: &[f64]) {
        self.update_from(time, q, v, v);
    }

    /// The same for a scheme whose laws start from a velocity `start` other than v_k (the generalized-α's,
    /// [`friction::law::RowStart`]): the step's displacement runs from `start`, a dashpot's velocity from `v` = v_k.
    pub fn update_from(&mut self, time: f64, q: &[f64], start: &[f64], v: &[f64]) {
        if !self.varying {
            return;
        }
        let n = self.matrix.order();
        if !self.moving.is_empty() {
            self.dof_responses.begin_update();
        }
        for (k, interaction) in self.moving.iter_mut().enumerate() {
            let j = self.fixed + k;
            let row = self.interactions.row_mut(j);
            let state = interaction.update(time, self.matrix.integration.step, q, start, row);
            // G = Σ_i H_i r_i from the kept single-DOF responses, over the range the last G left non-zero.
            let column = &mut self.moving_responses[k * n..(k + 1) * n];
            let (lo, hi) = self.moving_support[k];
            column[lo..hi].iter_mut().for_each(|x| *x = 0.0);
            let mut support = (n, 0);
            for (dof, value) in row.entries() {
                let (a, b) = self.dof_responses.add(dof, value, &self.matrix.factor, column);
                support = (support.0.min(a), support.1.max(b));
            }
            self.moving_support[k] = if support.0 < support.1 { support } else { (0, 0) };
            self.delassus_diagonal[j] = row.dot(column) + self.law.compliance[j];
            self.moving_states[k] = state;
        }
        let weights = self.matrix.integration.weights();
        let (h, theta) = (weights.step, weights.theta);
        let rows = self.interactions.rows();
        // The θ-method's laws start from v_k itself: one product a row, not two.
        let same = std::ptr::eq(start, v);
        // Every fixed law with a gap (a soil's sections): its products packed, one pass each.
        if let Some(products) = self.fixed_rows.as_mut().filter(|r| r.all_gaps) {
            products.update_products(q, start, v, same);
        }
        let packed = self.fixed_rows.as_ref().filter(|r| r.all_gaps);
        for (j, law) in self.interactions.laws().iter().enumerate() {
            let row_start = if j >= self.fixed {
                let state = self.moving_states[j - self.fixed];
                RowStart {
                    gap: state.gap,
                    velocity: state.velocity,
                    current: state.velocity,
                    rheonomic: state.rheonomic,
                }
            } else {
                let Some(gap) = law.gap() else { continue };
                let (at_q, velocity, current) = match packed {
                    Some(p) => (p.at_q[j], p.at_start[j], if same { p.at_start[j] } else { p.at_v[j] }),
                    None => {
                        let velocity = rows[j].dot(start);
                        (rows[j].dot(q), velocity, if same { velocity } else { rows[j].dot(v) })
                    }
                };
                RowStart { gap: gap + at_q, velocity, current, rheonomic: 0.0 }
            };
            let RowStart { gap, velocity: u, rheonomic, .. } = row_start;
            if let Some(hertz) = self.hertz[j].as_mut() {
                hertz.start(-gap, u, rheonomic, h);
                Self::set_hertz_law(&mut self.law, &mut self.delassus_diagonal, j, hertz, (h, theta));
                continue;
            }
            // A moving rigid contact's positions are projected: closed, it stays in the step's index set.
            let closed = j >= self.fixed && gap <= CLOSED_GAP;
            let (lower, upper, drift) = law.step_bounds(row_start, weights, closed);
            self.law.lower[j] = lower;
            self.law.upper[j] = upper;
            self.law.drift[j] = drift;
        }
    }

    /// Put Hertz contact j's current linearisation into the step's law and W_jj + d_j.
    fn set_hertz_law(law: &mut StepLaw, diagonal: &mut [f64], j: usize, hertz: &HertzStep, (h, theta): (f64, f64)) {
        let (compliance, drift) = hertz.law(h, theta);
        diagonal[j] += compliance - law.compliance[j];
        (law.lower[j], law.upper[j], law.compliance[j], law.drift[j]) = (0.0, f64::INFINITY, compliance, drift);
    }

    /// Whether some interactions follow Hertz's law (the step then iterates, [`InteractionProblem::newton_step`]).
    pub fn has_hertz(&self) -> bool {
        self.hertz.iter().any(Option::is_some)
    }

    /// One Newton update of the Hertz contacts from the step's impulses `p` ([`friction::hertz`]): when some contact's
    /// δ* would move by more than [`friction::hertz::NEWTON_TOLERANCE`], relinearise them all and return true (solve
    /// again); else leave the law as the impulses were solved for and return false.
    pub fn newton_step(&mut self, p: &[f64]) -> bool {
        let weights = self.matrix.integration.weights();
        let (h, theta) = (weights.step, weights.theta);
        let moves = self.hertz.iter().zip(p).any(|(hz, &pj)| {
            hz.is_some_and(|hz| {
                (hz.end_penetration(pj, h).max(PENETRATION_FLOOR) - hz.linearised_at).abs() > NEWTON_TOLERANCE
            })
        });
        if moves {
            for (j, hertz) in self.hertz.iter_mut().enumerate() {
                if let Some(hertz) = hertz.as_mut() {
                    hertz.relinearise(p[j], h);
                    Self::set_hertz_law(&mut self.law, &mut self.delassus_diagonal, j, hertz, (h, theta));
                }
            }
        }
        moves
    }

    /// Whether some moving contact is rigid, so that positions are projected after each step
    /// ([`InteractionProblem::project_positions`]).
    pub fn has_projection(&self) -> bool {
        self.projection.is_needed()
    }

    /// The position projection of the rigid moving contacts ([`crate::position`]) after a step with impulses `p` and
    /// velocities `v` = v_{k+1}: from q̃_{k+1} = `q` at t_{k+1} = `time`, write the correction Δq into `dq` (n) and
    /// report (`dq` is untouched when the report has 0 sweeps: nothing to move). A contact pressed in the step when
    /// its impulse outweighs its law velocity, p·(W_jj + d_j) > r_j: exactly p > 0 for an exact solution, while an
    /// interior point's small positive p beside a separating velocity does not count.
    pub fn project_positions(
        &mut self,
        time: f64,
        (q, v): (&[f64], &[f64]),
        p: &[f64],
        dq: &mut [f64],
    ) -> ProjectionReport {
        let (n, responses) = (self.matrix.order(), &self.moving_responses);
        let response = |k: usize| &responses[k * n..(k + 1) * n];
        let (rows, law, diagonal, fixed) = (self.interactions.rows(), &self.law, &self.delassus_diagonal, self.fixed);
        let pressed = |k: usize| {
            let j = fixed + k;
            p[j] > 0.0 && p[j] * diagonal[j] > law.law_velocity(j, rows[j].dot(v), p[j])
        };
        self.projection.project(&self.moving, (time, q), pressed, response, dq)
    }

    /// Whether some interactions move (their rows change every step).
    pub fn has_moving(&self) -> bool {
        !self.moving.is_empty()
    }

    /// Whether every moving interaction follows a co-moving window's shifts.
    pub fn moving_follow_shifts(&self) -> bool {
        self.moving.iter().all(|m| m.follows_shifts())
    }

    /// Move every moving interaction back by `distance` (m) in the window (see [`MovingInteraction::shift_back`]).
    pub fn shift_moving_back(&mut self, distance: f64) {
        self.moving.iter_mut().for_each(|m| m.shift_back(distance));
    }

    /// Number of fixed interactions (they come first).
    pub fn fixed_len(&self) -> usize {
        self.fixed
    }

    /// The response G_j = M̂⁻¹H_jᵀ of moving interaction j (an index ≥ [`InteractionProblem::fixed_len`]), as of the
    /// last update.
    pub fn moving_response(&self, j: usize) -> &[f64] {
        let n = self.matrix.order();
        let k = j - self.fixed;
        &self.moving_responses[k * n..(k + 1) * n]
    }

    /// Whether the law changes from step to step.
    pub fn is_varying(&self) -> bool {
        self.varying
    }

    /// Bring impulses into the step's bounds (a warm start from a step with other bounds).
    pub fn clamp_to_bounds(&self, p: &mut [f64]) {
        for (j, pj) in p.iter_mut().enumerate() {
            *pj = friction::law::project(*pj, self.law.lower[j], self.law.upper[j]);
        }
    }

    /// v += M̂⁻¹Hᵀp: from the stored responses when there are any (or only moving interactions, whose responses
    /// the update phase solved), else by one banded solve (`work`: n scratch).
    pub fn add_response(&self, p: &[f64], v: &mut [f64], work: &mut [f64]) {
        match &self.responses {
            Some(responses) => {
                responses.add(&p[..self.fixed], v);
                self.add_moving_responses(p, v);
            }
            None if self.fixed == 0 => self.add_moving_responses(p, v),
            None => {
                self.solve_response(p, work);
                axpy(1.0, work, v);
            }
        }
    }

    /// v += Σ_j p_j G_j over the moving interactions, each over its support.
    fn add_moving_responses(&self, p: &[f64], v: &mut [f64]) {
        for j in self.fixed..p.len() {
            if p[j] != 0.0 {
                let (lo, hi) = self.moving_support[j - self.fixed];
                axpy(p[j], &self.moving_response(j)[lo..hi], &mut v[lo..hi]);
            }
        }
    }

    /// out = M̂⁻¹Hᵀp by one banded solve.
    fn solve_response(&self, p: &[f64], out: &mut [f64]) {
        out.iter_mut().for_each(|x| *x = 0.0);
        self.interactions.add_transpose(p, out);
        self.matrix.factor.solve_in_place(out);
    }

    /// Number of interactions.
    pub fn len(&self) -> usize {
        self.delassus_diagonal.len()
    }

    /// Whether there is no interaction.
    pub fn is_empty(&self) -> bool {
        self.delassus_diagonal.is_empty()
    }

    /// |p_j − proj(p_j − r_j/(W_jj + d_j))|·(W_jj + d_j) (m/s) of interaction j with relative velocity `u` =
    /// U_{k+1}: zero exactly when (u, p) satisfy the step's law.
    #[inline]
    pub fn section_residual(&self, j: usize, u: f64, p: f64) -> f64 {
        let law = &self.law;
        let r = law.law_velocity(j, u, p);
        natural_residual(r, p, law.lower[j], law.upper[j], 1.0 / self.delassus_diagonal[j])
    }

    /// max_j of [`InteractionProblem::section_residual`] (m/s). For fixed friction alone (b = 0, d = 0) the law
    /// velocity is U itself and the loop reads nothing else.
    pub fn law_residual(&self, u: &[f64], p: &[f64]) -> f64 {
        let law = &self.law;
        let mut worst: f64 = 0.0;
        let bounds = law.lower.iter().zip(&law.upper).zip(&self.delassus_diagonal);
        if self.varying {
            let terms = law.drift.iter().zip(&law.compliance);
            for (((&u, &p), ((&lo, &hi), &w)), (&b, &d)) in u.iter().zip(p).zip(bounds).zip(terms) {
                worst = worst.max(natural_residual(u + b + d * p, p, lo, hi, 1.0 / w));
            }
        } else {
            for ((&u, &p), ((&lo, &hi), &w)) in u.iter().zip(p).zip(bounds) {
                worst = worst.max(natural_residual(u, p, lo, hi, 1.0 / w));
            }
        }
        worst
    }

    /// The step's outcome for impulses p, as the stepper will form it: v = v_free + M̂⁻¹Hᵀp and U = H v (into the
    /// given buffers), and the law residual (m/s).
    pub fn outcome(&self, v_free: &[f64], p: &[f64], v: &mut [f64], u: &mut [f64]) -> f64 {
        if let Some(responses) = &self.responses {
            v.copy_from_slice(v_free);
            responses.add(&p[..self.fixed], v);
            self.add_moving_responses(p, v);
        } else if self.fixed == 0 {
            v.copy_from_slice(v_free);
            self.add_moving_responses(p, v);
        } else {
            self.solve_response(p, v);
            axpy(1.0, v_free, v);
        }
        self.velocities(v, u);
        self.law_residual(u, p)
    }

    /// H q of the fixed rows into `out` in one packed pass, where every fixed law has a gap and the rows pack
    /// ([`pack_rows`]); false (and `out` untouched) otherwise.
    pub fn fixed_gap_products(&self, q: &[f64], out: &mut [f64]) -> bool {
        match self.fixed_rows.as_ref().filter(|r| r.all_gaps) {
            Some(rows) => {
                rows.mul(q, &mut out[..self.fixed]);
                true
            }
            None => false,
        }
    }

    /// U = H v: the fixed rows' products packed where they can be ([`pack_rows`]), the moving rows' one by one.
    pub fn velocities(&self, v: &[f64], u: &mut [f64]) {
        let Some(fixed) = &self.fixed_rows else {
            return self.interactions.velocities(v, u);
        };
        let (at_fixed, at_moving) = u.split_at_mut(self.fixed);
        fixed.mul(v, at_fixed);
        for (u, row) in at_moving.iter_mut().zip(&self.interactions.rows()[self.fixed..]) {
            *u = row.dot(v);
        }
    }

    /// Absolute tolerance (m/s) for a relative tolerance: relative to the largest of |U_free,j| and |U_free,j + b_j|,
    /// the velocities the step starts from.
    pub fn absolute_tolerance(&self, relative: f64, u_free: &[f64]) -> f64 {
        relative * self.velocity_scale(u_free)
    }

    /// The step's velocity scale (m/s): the largest of |U_free,j| and |U_free,j + b_j|, at least [`VELOCITY_FLOOR`].
    pub fn velocity_scale(&self, u_free: &[f64]) -> f64 {
        u_free.iter().zip(&self.law.drift).fold(VELOCITY_FLOOR, |m, (u, b)| m.max(u.abs()).max((u + b).abs()))
    }
}
