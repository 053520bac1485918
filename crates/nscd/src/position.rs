//! The position projection of rigid moving contacts (docs/theory.md §9).
//!
//! Moreau–Jean holds a rigid contact at velocity level: in the step's index set 0 ≤ p ⊥ U_{k+1} + eU_k ≥ 0. Its
//! gap then drifts — by the O(h) penetration of a landing, and along a moving rail because the row is written at
//! t_k + θh while the gap is read at t_{k+1} (O(h²) a step, growing over a run) — and a contact a nanometre open
//! at the next step leaves Moreau's index set, rests a step and lands again: a wheel pressing on the rail chatters.
//! After the velocity step, the positions of the rigid moving contacts are therefore projected (the "Moreau–Jean
//! with projection" of Acary 2013, CMAME 256, 224–250), in the metric of the step's matrix M̂:
//!
//! ```text
//! q_{k+1} ← q̃_{k+1} + Σ_j μ_j G_j,    G_j = M̂⁻¹H_jᵀ,   g_i(q_{k+1}) = g̃_i + Σ_j (H_i(t_{k+1}) G_j) μ_j
//! contact that pressed in the step (p_i > 0):  g_i(q_{k+1}) = 0              (μ_i of either sign)
//! every other rigid moving contact:          0 ≤ μ_i ⊥ g_i(q_{k+1}) ≥ 0
//! ```
//!
//! A contact that pressed is closed at the step's end (Signorini at position level); the rest may not end
//! penetrating. The gap is affine in q at a fixed time, so with the rows at t_{k+1} the projection is exact; the
//! G_j are the step's (rows at t_k + θh), which leaves the small system W = [H_i(t_{k+1})G_j] slightly
//! non-symmetric — solved by projected Gauss–Seidel to [`PROJECTION_TOLERANCE`]. Velocities are not changed: the
//! projection moves the structure, whose strain energy it changes, booked apart in the energy ledger
//! ([`crate::EnergyLedger::projection_work`]). A contact closed at the end of a step (g ≤ [`CLOSED_GAP`]) stays in
//! the next step's index set whatever its velocity; the velocity law then lets it separate (p = 0, U > 0).

use crate::kernels::{axpy, dot};
use crate::moving::MovingInteraction;
use friction::InteractionRow;

/// A gap the projection must meet (m): 1e-12 m, 1e-9 of a millimetre rail deflection.
pub const PROJECTION_TOLERANCE: f64 = 1e-12;

/// A rigid moving contact whose gap at a step's start is at most this (m) is closed: in the step's index set
/// whatever its velocity. A nanometre, physically nothing and a thousand times the projection's tolerance.
pub const CLOSED_GAP: f64 = 1e-9;

/// Most Gauss–Seidel sweeps of one projection; a single contact is solved by the first and confirmed by the second.
pub const PROJECTION_SWEEPS: usize = 1_000;

/// How a step's projection ended.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ProjectionReport {
    /// Gauss–Seidel sweeps (0: nothing to project).
    pub sweeps: usize,
    /// The largest gap violation left (m): |g| of a contact held closed, ⟨−g⟩₊ of the others.
    pub violation: f64,
}

impl ProjectionReport {
    /// Whether the violation met [`PROJECTION_TOLERANCE`].
    pub fn converged(&self) -> bool {
        self.violation <= PROJECTION_TOLERANCE
    }
}

/// The rigid moving contacts of a problem and the projection's scratch.
#[derive(Debug, Default)]
pub(crate) struct PositionProjection {
    /// Indices of the rigid (Signorini) contacts among the moving interactions.
    rigid: Vec<usize>,
    /// Their rows at t_{k+1}.
    rows: Vec<InteractionRow>,
    /// Their gaps g̃_{k+1} (m) before the projection.
    end_gaps: Vec<f64>,
    /// Whether each must end closed (it pressed in the step).
    closed: Vec<bool>,
    /// The projection's multipliers μ.
    multipliers: Vec<f64>,
    /// W (rigid × rigid, row-major).
    delassus: Vec<f64>,
}

impl PositionProjection {
    /// The projection of the moving interactions whose law is rigid (`is_rigid` by index).
    pub(crate) fn new(moving: usize, is_rigid: impl Fn(usize) -> bool) -> Self {
        let rigid: Vec<usize> = (0..moving).filter(|&k| is_rigid(k)).collect();
        let m = rigid.len();
        Self {
            rows: vec![InteractionRow::default(); m],
            end_gaps: vec![0.0; m],
            closed: vec![false; m],
            multipliers: vec![0.0; m],
            delassus: vec![0.0; m * m],
            rigid,
        }
    }

    /// Whether there is a rigid moving contact.
    pub(crate) fn is_needed(&self) -> bool {
        !self.rigid.is_empty()
    }

    /// Project: from q̃_{k+1} = `q` at `time` = t_{k+1}, which moving interactions pressed in the step (`pressed(k)`)
    /// and their responses `response(k)` = G_k, write Δq = Σ μ_j G_j into `dq` and report; when nothing is to move
    /// (0 sweeps) `dq` is left as it was.
    pub(crate) fn project<'a>(
        &mut self,
        moving: &[Box<dyn MovingInteraction>],
        (time, q): (f64, &[f64]),
        pressed: impl Fn(usize) -> bool,
        response: impl Fn(usize) -> &'a [f64],
        dq: &mut [f64],
    ) -> ProjectionReport {
        let m = self.rigid.len();
        let mut needed = false;
        for (i, &k) in self.rigid.iter().enumerate() {
            let gap = moving[k].gap(time, q, &mut self.rows[i]);
            self.end_gaps[i] = gap;
            self.closed[i] = pressed(k);
            needed |= gap < 0.0 || (self.closed[i] && gap != 0.0);
        }
        if !needed {
            return ProjectionReport::default();
        }
        for i in 0..m {
            for l in 0..m {
                self.delassus[i * m + l] = self.rows[i].dot(response(self.rigid[l]));
            }
        }
        self.multipliers.iter_mut().for_each(|x| *x = 0.0);
        let mut report = ProjectionReport { sweeps: 0, violation: f64::INFINITY };
        while report.sweeps < PROJECTION_SWEEPS && !report.converged() {
            report.sweeps += 1;
            report.violation = 0.0;
            for i in 0..m {
                let w = &self.delassus[i * m..(i + 1) * m];
                let gap = self.end_gaps[i] + dot(w, &self.multipliers);
                let mu = self.multipliers[i];
                let (next, violation) = if self.closed[i] {
                    (mu - gap / w[i], gap.abs())
                } else {
                    ((mu - gap / w[i]).max(0.0), if mu > 0.0 { gap.abs() } else { (-gap).max(0.0) })
                };
                self.multipliers[i] = next;
                report.violation = report.violation.max(violation);
            }
        }
        // Δq = Σ μ_j G_j: the first term written, the others added (no pass to clear Δq).
        for (i, (&mu, &k)) in self.multipliers.iter().zip(&self.rigid).enumerate() {
            if i == 0 {
                dq.iter_mut().zip(response(k)).for_each(|(d, g)| *d = mu * g);
            } else if mu != 0.0 {
                axpy(mu, response(k), dq);
            }
        }
        report
    }
}
