//! The terms of a step's energy identity that read the interactions (docs/theory.md §6): the impulses' work by kind,
//! the compliant springs' energy, the kinetic and strain energies, and the generalized-α's starting residual.

use crate::forcing::Forcing;
use crate::kernels::dot;
use crate::problem::InteractionProblem;
use friction::InteractionKind;

/// The work U_θᵀp of one step's impulses, by kind of interaction (J).
pub(super) struct InteractionWork {
    pub(super) friction: f64,
    pub(super) contact: f64,
    pub(super) support: f64,
}

impl InteractionWork {
    pub(super) fn total(&self) -> f64 {
        self.friction + self.contact + self.support
    }
}

/// Σ_j (H_j v_θ) p_j by kind, each sum in interaction order; and the compliant springs' energy is not here (see
/// [`EnergyLedger::spring_energy`]). `friction_only`: every interaction is friction (one sum, no kind to read).
/// `hv`: m scratch for H v_θ.
pub(super) fn interaction_work(
    problem: &InteractionProblem,
    friction_only: bool,
    (p, v_theta): (&[f64], &[f64]),
    hv: &mut [f64],
) -> InteractionWork {
    let mut work = InteractionWork { friction: 0.0, contact: 0.0, support: 0.0 };
    problem.velocities(v_theta, hv);
    if friction_only {
        for (u, &pj) in hv.iter().zip(p) {
            work.friction += u * pj;
        }
        return work;
    }
    for ((u, &pj), kind) in hv.iter().zip(p).zip(problem.interactions.kinds()) {
        let term = u * pj;
        match kind {
            InteractionKind::Friction => work.friction += term,
            InteractionKind::Contact => work.contact += term,
            InteractionKind::Support => work.support += term,
        }
    }
    work
}

/// The energy in the springs of the compliant interactions at displacement q (J): ½k⟨δ⟩₊² of a stop, ½kδ² of a
/// bilateral spring. A fixed interaction's penetration is δ = −(g₀ + Hq); a moving one's gap depends on where it is
/// and on the rail's profile, so after a step (`impulses` p) its energy is read from its law
/// ([`InteractionProblem::moving_spring_energy`]). Before the first step moving interactions count 0. `hq`: m
/// scratch for H q where every fixed law has a gap (a soil's sections), taken in one packed pass.
pub(super) fn spring_energy(problem: &InteractionProblem, q: &[f64], impulses: Option<&[f64]>, hq: &mut [f64]) -> f64 {
    let interactions = &problem.interactions;
    let packed = problem.fixed_gap_products(q, hq);
    let mut energy = 0.0;
    for (j, (row, law)) in interactions.rows().iter().zip(interactions.laws()).enumerate() {
        if j >= problem.fixed_len() {
            energy += impulses.and_then(|p| problem.moving_spring_energy(j, p[j])).unwrap_or(0.0);
            continue;
        }
        // A fixed interaction with a spring is a linear one (Hertz is refused there).
        if let (Some(gap), true) = (law.gap(), law.has_spring()) {
            let hq = if packed { hq[j] } else { row.dot(q) };
            energy += law.stored_energy(-(gap + hq)).unwrap_or(0.0);
        }
    }
    energy
}

/// The generalized-α's start: M A₀ = F(t₀) − C v₀ − K q₀ + Σ_j H_jᵀ r_j into `out`, r_j the force each fixed linear
/// law holds at (q₀, v₀) ([`friction::Law::linear_force`]; friction, rigid and moving contacts hold none at the
/// start), from the products K q₀ and C v₀.
pub(super) fn start_residual(
    problem: &InteractionProblem,
    forcing: &dyn Forcing,
    t0: f64,
    state: (&[f64], &[f64], &[f64], &[f64]),
    out: &mut [f64],
) {
    let (q, v, kq, cv) = state;
    for ((o, kq), cv) in out.iter_mut().zip(kq).zip(cv) {
        *o = -(kq + cv);
    }
    forcing.add_to(t0, 1.0, out);
    let interactions = &problem.interactions;
    for (row, law) in interactions.rows().iter().zip(interactions.laws()).take(problem.fixed_len()) {
        if let Some(force) = law.gap().and_then(|gap| law.linear_force(-(gap + row.dot(q)), -row.dot(v))) {
            row.add_transpose(force, out);
        }
    }
}

/// Kinetic ½vᵀMv and strain ½qᵀKq energy (J), from the products M v and K q.
pub(super) fn energies(v: &[f64], mv: &[f64], q: &[f64], kq: &[f64]) -> (f64, f64) {
    (0.5 * dot(v, mv), 0.5 * dot(q, kq))
}
