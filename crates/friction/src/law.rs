//! The one nonsmooth law of every interaction (docs/theory.md §9): an impulse p in a closed interval [lo, hi]
//! (hi may be +∞) against its law velocity r = (W + D)p + c, complementary in the sense
//!
//! ```text
//! p = lo where r > 0,   p = hi where r < 0,   r = 0 for lo < p < hi,
//! ```
//!
//! i.e. −r ∈ `N_[lo, hi](p)`, the normal cone of the interval. For any ρ > 0 this is the fixed point
//! p = proj_[lo, hi](p − ρ r), which every solver iterates or measures. Coulomb friction is the box [−a, a] with
//! r the section velocity (docs/theory.md §4); Signorini contact and the compliant stop are [0, +∞) with a drift and,
//! for the stop, a compliance (docs/theory.md §9).
//!
//! Each [`Law`] states its own behaviour in the step — bounds and drift, compliance, gap, stored energy, end
//! penetration — so that a new law is written here and in no other file of the engine.

pub use crate::drift::{compliant_drift, soil_drift};
pub use crate::step::{RowStart, StepWeights};

/// The law of an interaction (docs/theory.md §9). The gap of a unilateral law is g = `gap` + H_α q (m, positive
/// open), so U_α = ġ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Law {
    /// Coulomb friction r ∈ −F·Sign(U) with maximal force `capacity` F ≥ 0 (N): impulses in [−hF, hF].
    Coulomb {
        /// F (N).
        capacity: f64,
    },
    /// Rigid unilateral contact g ≥ 0, force ≥ 0, with Newton impact of restitution e ∈ [0, 1]: active in a step
    /// when the predicted gap g_k + h U_k / 2 ≤ 0, then 0 ≤ p ⊥ U_{k+1} + e U_k ≥ 0.
    Signorini {
        /// g₀: the gap at q = 0 (m).
        gap: f64,
        /// e ∈ [0, 1].
        restitution: f64,
    },
    /// A linear spring k_c in series with a unilateral stop: force k_c⟨−g⟩₊ ≥ 0, integrated implicitly.
    Compliant {
        /// g₀: the gap at q = 0 (m).
        gap: f64,
        /// k_c > 0 (N/m).
        stiffness: f64,
    },
    /// A unilateral Kelvin–Voigt support that pushes but cannot pull — a soil's Winkler spring, a voided sleeper's
    /// ballast: force ⟨kδ_w + cδ̇_w⟩₊ with the penetration δ_w and its rate taken where the scheme's forces act
    /// (t_k + wh, where the structure's K and C act too), so that while it presses it is that linear spring and
    /// dashpot step for step (the spring energy-conserving at θ = ½) — the compliant stop, which takes its force at
    /// the step's end, damps a distributed soil numerically (docs/theory.md §13). The dashpot acts in contact only:
    /// it neither pulls a separating body nor acts across an open gap. Fixed interactions only.
    Soil {
        /// g₀: the gap at q = 0 (m).
        gap: f64,
        /// k > 0 (N/m).
        stiffness: f64,
        /// c ≥ 0 (N·s/m), acting only in contact.
        damping: f64,
    },
    /// A linear spring that also pulls: force k·(−g) of either sign, integrated implicitly — a glued (bilateral)
    /// contact, the reference a unilateral one equals while it presses.
    Spring {
        /// g₀: the gap at q = 0 (m).
        gap: f64,
        /// k > 0 (N/m).
        stiffness: f64,
    },
    /// Hertz's law λ = C_H⟨δ⟩₊^{3/2} of a wheel on a rail, δ = −g the penetration: unilateral, integrated implicitly by
    /// Newton iterations on its tangent compliance within the step (docs/theory.md §9). Moving interactions only.
    Hertz {
        /// g₀: the gap at q = 0 (m).
        gap: f64,
        /// C_H > 0 (N/m^1.5).
        coefficient: f64,
    },
}

impl Law {
    /// The Coulomb capacity F (N), zero for the unilateral laws.
    pub fn capacity(&self) -> f64 {
        match *self {
            Law::Coulomb { capacity } => capacity,
            _ => 0.0,
        }
    }

    /// Whether the impulse bounds change from step to step (they do for the unilateral laws, whose state is the gap).
    pub fn depends_on_state(&self) -> bool {
        !matches!(self, Law::Coulomb { .. })
    }

    /// g₀, the gap at q = 0 (m), of a law whose state is a gap; None for friction.
    #[inline]
    pub fn gap(&self) -> Option<f64> {
        match *self {
            Law::Coulomb { .. } => None,
            Law::Signorini { gap, .. }
            | Law::Compliant { gap, .. }
            | Law::Soil { gap, .. }
            | Law::Spring { gap, .. }
            | Law::Hertz { gap, .. } => Some(gap),
        }
    }

    /// The same law with its gap moved by `shift` (m): the law seen from a state where the row reads `shift` more
    /// (friction, which has no gap, unchanged).
    pub fn shifted(&self, shift: f64) -> Self {
        let mut law = *self;
        match &mut law {
            Law::Coulomb { .. } => {}
            Law::Signorini { gap, .. }
            | Law::Compliant { gap, .. }
            | Law::Soil { gap, .. }
            | Law::Spring { gap, .. }
            | Law::Hertz { gap, .. } => *gap += shift,
        }
        law
    }

    /// The stiffness k (N/m) of a linear spring law and whether it also pulls: the compliant stop and the soil push
    /// only, the bilateral spring pulls as well; None for friction, rigid contact and Hertz (nonlinear). What a
    /// static solve takes of a law.
    pub fn linear_spring(&self) -> Option<(f64, bool)> {
        match *self {
            Law::Compliant { stiffness, .. } | Law::Soil { stiffness, .. } => Some((stiffness, false)),
            Law::Spring { stiffness, .. } => Some((stiffness, true)),
            Law::Coulomb { .. } | Law::Signorini { .. } | Law::Hertz { .. } => None,
        }
    }

    /// Whether the law holds energy in a spring (compliant stop, bilateral spring, Hertz): the energy ledger then
    /// books what it stores and loses.
    #[inline]
    pub fn has_spring(&self) -> bool {
        matches!(self, Law::Compliant { .. } | Law::Soil { .. } | Law::Spring { .. } | Law::Hertz { .. })
    }

    /// Whether the contact is rigid (Signorini with Newton impact): its positions are projected after a step and its
    /// loss is the impact's.
    pub fn is_rigid(&self) -> bool {
        matches!(self, Law::Signorini { .. })
    }

    /// The step's impulse bounds and drift (lo, hi, b) from the row's [`RowStart`] and the scheme's [`StepWeights`]
    /// (docs/theory.md §9):
    ///
    /// - Coulomb of capacity F: [−hF, hF], b = b_r;
    /// - Signorini: [0, +∞), b = b_r + e·U_k when the predicted gap g_k + γhU_k ≤ 0 ([`PREDICTION_WEIGHT`]) or
    ///   `closed` (a projected contact found closed), else [0, 0];
    /// - compliant stop and Hertz: [0, +∞), a bilateral spring (−∞, +∞), each with the drift of
    ///   [`compliant_drift`] from the penetration δ_k = −g_k. Their compliance is [`Law::run_compliance`]
    ///   (Hertz: its linearisation's, [`crate::hertz::HertzStep::law`]).
    #[inline]
    pub fn step_bounds(&self, start: RowStart, weights: StepWeights, closed: bool) -> (f64, f64, f64) {
        let StepWeights { step: h, theta, .. } = weights;
        let RowStart { gap, velocity: u, rheonomic, .. } = start;
        let spring = || compliant_drift(-gap, u, rheonomic, h, theta);
        match *self {
            Law::Coulomb { capacity } => (-h * capacity, h * capacity, rheonomic),
            Law::Signorini { restitution, .. } => {
                if gap + PREDICTION_WEIGHT * h * u <= 0.0 || closed {
                    (0.0, f64::INFINITY, rheonomic + restitution * u)
                } else {
                    (0.0, 0.0, 0.0)
                }
            }
            Law::Compliant { .. } | Law::Hertz { .. } => (0.0, f64::INFINITY, spring()),
            Law::Soil { stiffness, damping, .. } => {
                (0.0, f64::INFINITY, soil_drift(start, weights, stiffness, damping))
            }
            Law::Spring { .. } => (f64::NEG_INFINITY, f64::INFINITY, spring()),
        }
    }

    /// The compliance d (m/s per N·s) the law keeps for a whole run of the step's `weights`: 1/(h²θk) for a linear
    /// spring of stiffness k (so that a positive impulse is p = h·k·δ_{k+1}), 1/(hw(hθk + c)) for the soil
    /// (p = h(kδ_w + cδ̇_w), [`soil_drift`]), 0 for friction and rigid contact, and 0 for Hertz, whose compliance
    /// follows its linearisation step by step.
    pub fn run_compliance(&self, weights: StepWeights) -> f64 {
        let StepWeights { step: h, theta, force } = weights;
        match *self {
            Law::Compliant { stiffness, .. } | Law::Spring { stiffness, .. } => 1.0 / (h * h * theta * stiffness),
            Law::Soil { stiffness, damping, .. } => 1.0 / (h * force * (h * theta * stiffness + damping)),
            Law::Coulomb { .. } | Law::Signorini { .. } | Law::Hertz { .. } => 0.0,
        }
    }

    /// The energy Φ(δ) (J) the law's spring holds at penetration δ (m): ½k⟨δ⟩₊² for a stop, ½kδ² for a bilateral
    /// spring, (2/5)C_H⟨δ⟩₊^{5/2} for Hertz ([`crate::hertz::potential`]); None for laws without a spring.
    #[inline]
    pub fn stored_energy(&self, penetration: f64) -> Option<f64> {
        match *self {
            Law::Compliant { stiffness, .. } | Law::Soil { stiffness, .. } => {
                Some(0.5 * stiffness * penetration.max(0.0).powi(2))
            }
            Law::Spring { stiffness, .. } => Some(0.5 * stiffness * penetration * penetration),
            Law::Hertz { coefficient, .. } => Some(crate::hertz::potential(coefficient, penetration)),
            Law::Coulomb { .. } | Law::Signorini { .. } => None,
        }
    }

    /// The force (N, pushing positive) a linear law holds at penetration δ (m) and penetration rate δ̇ (m/s): k⟨δ⟩₊
    /// for a stop, kδ for a bilateral spring, ⟨kδ + cδ̇⟩₊ for the soil in contact (δ ≥ 0; nothing across a gap);
    /// None for friction, rigid contact and Hertz.
    pub fn linear_force(&self, penetration: f64, rate: f64) -> Option<f64> {
        let (stiffness, pulls) = self.linear_spring()?;
        Some(match *self {
            Law::Soil { damping, .. } if penetration >= 0.0 => (stiffness * penetration + damping * rate).max(0.0),
            _ if pulls => stiffness * penetration,
            _ => stiffness * penetration.max(0.0),
        })
    }

    /// The penetration δ_{k+1} (m) a linear spring law holds for the step's impulse `p` (N·s) with step h (s):
    /// p/(hk); a stop without force ends open (0 stands for any δ ≤ 0). None for other laws (Hertz's follows from
    /// its linearisation, [`crate::hertz::HertzStep::end_penetration`]).
    pub fn linear_end_penetration(&self, p: f64, h: f64) -> Option<f64> {
        match *self {
            Law::Compliant { stiffness, .. } => Some(if p > 0.0 { p / (h * stiffness) } else { 0.0 }),
            Law::Spring { stiffness, .. } => Some(p / (h * stiffness)),
            Law::Coulomb { .. } | Law::Signorini { .. } | Law::Hertz { .. } | Law::Soil { .. } => None,
        }
    }
}

/// γ of Moreau's index-set rule for rigid contact: a contact enters the step when g_k + γ h U_k ≤ 0.
pub const PREDICTION_WEIGHT: f64 = 0.5;

/// Projection of `p` onto [lo, hi] (lo ≤ hi, hi may be +∞).
#[inline]
pub fn project(p: f64, lo: f64, hi: f64) -> f64 {
    p.clamp(lo, hi)
}

/// Natural residual |p − proj_[lo, hi](p − ρ·r)| / ρ of the law, in velocity units (m/s) when p is an impulse
/// (N·s), r a velocity and ρ an impulse per velocity (kg, e.g. 1/(W_jj + d_j)). Zero exactly when (r, p) satisfy
/// the law: for p strictly inside it is |r|, at a bound the distance of p from the bound the law asks for, over ρ.
#[inline]
pub fn natural_residual(r: f64, p: f64, lo: f64, hi: f64, rho: f64) -> f64 {
    (p - project(p - rho * r, lo, hi)).abs() / rho
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn residual_vanishes_exactly_on_the_law() {
        // Coulomb box [−2, 2]: stuck inside with r = 0, slipping at a bound against the motion.
        assert_eq!(natural_residual(0.0, 0.7, -2.0, 2.0, 0.5), 0.0);
        assert_eq!(natural_residual(3.0, -2.0, -2.0, 2.0, 0.5), 0.0);
        assert_eq!(natural_residual(-3.0, 2.0, -2.0, 2.0, 0.5), 0.0);
        // Stuck impulse with the section moving: the residual is the velocity.
        assert_eq!(natural_residual(0.25, 0.5, -2.0, 2.0, 1.0), 0.25);
        // One-sided [0, ∞): separating at p = 0, pressing with r = 0; a tensile impulse is off by p/ρ.
        assert_eq!(natural_residual(1.5, 0.0, 0.0, f64::INFINITY, 2.0), 0.0);
        assert_eq!(natural_residual(0.0, 1e6, 0.0, f64::INFINITY, 2.0), 0.0);
        assert_eq!(natural_residual(0.0, -1.0, 0.0, f64::INFINITY, 2.0), 0.5);
        // A closed interval [0, 0] (an inactive contact) holds p = 0 whatever r.
        assert_eq!(natural_residual(-7.0, 0.0, 0.0, 0.0, 1.0), 0.0);
    }
}
