//! Hertz's contact law in the step (docs/theory.md §9): λ = C_H⟨δ⟩₊^{3/2}, δ = −g the penetration, integrated
//! implicitly like the compliant stop but with Newton iterations on its tangent.
//!
//! Linearised at a penetration δ* at the step's end, λ ≈ λ(δ*) + k_t(δ − δ*) = k_t(δ − δ₀) with the tangent
//! k_t = (3/2)C_H√δ* and the offset δ₀ = δ* − λ(δ*)/k_t = δ*/3: a compliant stop of stiffness k_t whose spring starts
//! at δ₀. Its step law is the compliant one with δ_k − δ₀ for δ_k: lo = 0, hi = +∞, d = 1/(h²θk_t),
//! b = b_r − ((δ_k − δ₀) − h(1−θ)U_k)/(hθ), and a positive impulse gives δ_{k+1} = δ₀ + p/(hk_t). Newton: start from
//! the explicit prediction δ* = δ_k − hU_k, solve the step, set δ* ← δ_{k+1}, solve again, until δ* changes by less
//! than [`NEWTON_TOLERANCE`]. A zero impulse says only δ_{k+1} ≤ δ₀; δ* ← δ₀ then lowers the kink by a third each
//! iteration, so a separating contact converges to no force. δ* is kept ≥ [`PENETRATION_FLOOR`] so k_t > 0.

/// Smallest penetration a linearisation is taken at (m): k_t = 1.5·C_H·√δ* stays > 0 (4e6 N/m for C_H = 8.6e10).
pub const PENETRATION_FLOOR: f64 = 1e-9;

/// Newton stops when δ* changes by less than this (m): 1e-13 m is 1e-8 of the static penetration of a wheel
/// (~1e-4 m at 80 kN), a force error of ~1e-8 of the wheel load.
pub const NEWTON_TOLERANCE: f64 = 1e-13;

/// Most Newton iterations in a step (each one more solve of the step's problem); measured: 3–6 while pressing.
pub const NEWTON_ITERATIONS: usize = 30;

/// The state of one Hertz contact in a step: the law's C_H and the step's start, and the linearisation in use.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HertzStep {
    /// C_H (N/m^1.5).
    pub coefficient: f64,
    /// δ_k (m).
    pub penetration: f64,
    /// U_k (m/s).
    pub velocity: f64,
    /// b_r (m/s).
    pub rheonomic: f64,
    /// δ* of the linearisation (m).
    pub linearised_at: f64,
}

impl HertzStep {
    /// The tangent stiffness k_t (N/m) and the offset δ₀ (m) at δ*.
    pub fn tangent(&self) -> (f64, f64) {
        let d = self.linearised_at;
        (1.5 * self.coefficient * d.sqrt(), d / 3.0)
    }

    /// The compliance d (m/s per N·s) and drift b (m/s) of the step's law at the current linearisation.
    pub fn law(&self, h: f64, theta: f64) -> (f64, f64) {
        let (k, offset) = self.tangent();
        let drift = crate::drift::compliant_drift(self.penetration - offset, self.velocity, self.rheonomic, h, theta);
        (1.0 / (h * h * theta * k), drift)
    }

    /// Start a step from δ_k, U_k, b_r, linearised at the explicit prediction δ_k − hU_k.
    pub fn start(&mut self, penetration: f64, velocity: f64, rheonomic: f64, h: f64) {
        self.penetration = penetration;
        self.velocity = velocity;
        self.rheonomic = rheonomic;
        self.linearised_at = (penetration - h * velocity).max(PENETRATION_FLOOR);
    }

    /// The penetration at the step's end for impulse `p` under the current linearisation: δ₀ + p/(hk_t) when p > 0;
    /// for p = 0, δ₀, the largest it can be.
    pub fn end_penetration(&self, p: f64, h: f64) -> f64 {
        let (k, offset) = self.tangent();
        if p > 0.0 { offset + p / (h * k) } else { offset }
    }

    /// One Newton update from impulse `p`: δ* ← δ_{k+1}; returns |Δδ*| (m).
    pub fn relinearise(&mut self, p: f64, h: f64) -> f64 {
        let next = self.end_penetration(p, h).max(PENETRATION_FLOOR);
        let change = (next - self.linearised_at).abs();
        self.linearised_at = next;
        change
    }

    /// The energy stored at the step's end for impulse `p` (J): ∫λ dδ = (2/5)C_H δ^{5/2}, with δ_{k+1} of a positive
    /// impulse, else 0.
    pub fn energy(&self, p: f64, h: f64) -> f64 {
        if p > 0.0 { potential(self.coefficient, self.end_penetration(p, h)) } else { 0.0 }
    }
}

/// Hertz's potential (2/5)C_H⟨δ⟩₊^{5/2} (J) at penetration δ (m), coefficient C_H (N/m^1.5): ∫λ dδ.
pub fn potential(coefficient: f64, penetration: f64) -> f64 {
    0.4 * coefficient * penetration.max(0.0).powf(2.5)
}

#[cfg(test)]
mod tests {
    use super::HertzStep;

    /// The linearisation reproduces λ and dλ/dδ at δ*, and a Newton update from the exact impulse of a penetration
    /// δ lands on δ.
    #[test]
    fn tangent_and_update() {
        let c = 8.6e10;
        let mut s = HertzStep { coefficient: c, linearised_at: 1e-4, ..Default::default() };
        let (k, offset) = s.tangent();
        let lambda = c * 1e-4f64.powf(1.5);
        assert!((k * (1e-4 - offset) / lambda - 1.0).abs() < 1e-14);
        assert!((k / (1.5 * c * 1e-2) - 1.0).abs() < 1e-14);
        let h = 1e-3;
        let p = h * k * (2e-4 - offset);
        assert!(s.relinearise(p, h) > 0.0);
        assert!((s.linearised_at - 2e-4).abs() < 1e-18);
        assert_eq!(s.energy(0.0, h), 0.0);
    }
}
