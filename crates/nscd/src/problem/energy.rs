//! The energy a moving contact's law holds and loses in a step (docs/theory.md §9, §12): read from the law after
//! the step, for the energy ledger.

use super::InteractionProblem;

impl InteractionProblem {
    /// The energy stored in moving interaction j's spring after a step with impulse `p` (J), read from its law: a
    /// compliant stop or a spring holds p = h·k·δ_{k+1}, so ½kδ² = p²/(2h²k) (a stop only when pressing); Hertz
    /// (2/5)C_Hδ^{5/2}. None for other laws.
    pub fn moving_spring_energy(&self, j: usize, p: f64) -> Option<f64> {
        self.interactions.laws()[j].stored_energy(self.end_penetration(j, p)?)
    }

    /// The penetration δ_{k+1} (m) moving interaction j's law holds for impulse `p`: p/(hk) of a linear spring,
    /// δ₀ + p/(hk_t) of Hertz's linearisation; a stop without force ends open (0 stands for any δ ≤ 0). None for
    /// laws without a spring.
    fn end_penetration(&self, j: usize, p: f64) -> Option<f64> {
        let h = self.matrix.integration.step;
        match self.hertz[j] {
            Some(hz) => Some(if p > 0.0 { hz.end_penetration(p, h) } else { 0.0 }),
            None => self.interactions.laws()[j].linear_end_penetration(p, h),
        }
    }

    /// What moving contact j lost in the step just solved with impulse `p` (J): −p·Ū − ΔΦ, with Ū = (δ_k − δ_{k+1})/h
    /// its mean relative velocity over the step and Φ its spring energy (½k⟨δ⟩₊², ½kδ², (2/5)C_H⟨δ⟩₊^{5/2}). The
    /// implicit law takes the force at the step's end, so this is ≥ 0 — ½k(Δδ)² for a linear spring — and largest
    /// at landings; a step without force loses what the spring held (δ_{k+1} ≤ 0). δ_k is the penetration the step
    /// started from (−g_k of the update phase). A rigid contact stores nothing: −p·Ū with Ū = θU_{k+1} + (1−θ)U_k =
    /// H v_θ + b_r, both velocities taken with the step's row (`v_theta` = v_θ) — for an impact from U⁻ to U⁺ = −eU⁻,
    /// ½m_eff(1 − e²)U⁻² at θ = ½; while it presses on a moving rail, the drift's O(h) share, which the projection's
    /// energy change, booked with it in [`crate::EnergyLedger::contact_loss`], cancels. None for friction and fixed
    /// interactions.
    pub fn moving_contact_loss(&self, j: usize, p: f64, v_theta: &[f64]) -> Option<f64> {
        let h = self.matrix.integration.step;
        let state = self.moving_states.get(j.checked_sub(self.fixed)?)?;
        let law = &self.interactions.laws()[j];
        if law.is_rigid() {
            // Newton's impact: what the impulse takes from the relative motion, −p·(H v_θ + b_r).
            return Some(-p * (self.interactions.rows()[j].dot(v_theta) + state.rheonomic));
        }
        let start = -state.gap;
        let end = self.end_penetration(j, p)?;
        let relative_work = p * (start - end) / h;
        Some(-relative_work - (law.stored_energy(end)? - law.stored_energy(start)?))
    }
}
