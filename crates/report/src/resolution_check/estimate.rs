//! The error of one outcome from three resolutions, each with elements and steps half as long as the one before
//! (docs/theory.md §6.1): the order measured, not assumed.
//!
//! For q_h − q* ≈ C hᵖ the differences d₁ = q₁ − q₀ and d₂ = q₂ − q₁ of successive halvings shrink by r = 2⁻ᵖ, the
//! observed order is p = log₂|d₁/d₂|, and the limit is q* ≈ q₂ + d₂ r/(1 − r) (Richardson). Where p lies in the
//! range the schemes can have ([`MIN_ORDER`]–[`MAX_ORDER`]), the error is Richardson's times Roache's safety factor
//! F_s = 1.25 for three grids with the order observed (Roache 1994, "Perspective: a method for uniform reporting of
//! grid refinement studies", J. Fluids Eng. 116; the grid convergence index). Elsewhere — differences that alternate
//! in sign, or an order no scheme here has (above 2: a difference small by chance, as when a peak moves to another
//! node or step; below ½: the tail would be unbounded) — the values are not yet in the asymptotic range, and the
//! error is taken as F_s = 3 times the spread of the three values (the data range of Eça & Hoekstra 2014, "A
//! procedure for the estimation of the numerical uncertainty of CFD calculations based on grid refinement studies",
//! J. Comput. Phys. 262; for p < ½ the smaller of the two). Differences that do not shrink leave the error undefined:
//! the outcome is not converging at these resolutions, and no number is given — unless a fourth, coarser value shows
//! the three within a floor the refinement has reached ([`Sequence::scattered_error`]; `run
//! --accuracy` has it), where the error is again three times their spread.

use serde::Serialize;

/// Roache's safety factor for a three-grid study with the observed order in the asymptotic range.
pub const SAFETY: f64 = 1.25;

/// The safety factor on the spread of the values outside the asymptotic range (Eça & Hoekstra).
pub const SPREAD_SAFETY: f64 = 3.0;

/// The largest order the schemes have (second order at best); an observed order above it is a chance.
pub const MAX_ORDER: f64 = 2.0;

/// The smallest order taken as asymptotic (below it Richardson's tail 1/(2ᵖ − 1) is unbounded).
pub const MIN_ORDER: f64 = 0.5;

/// Differences below this fraction of the outcome's size are round-off (the solvers' tolerances are ~1e-10).
pub const ROUND_OFF: f64 = 1e-9;

/// How an outcome behaves over the three resolutions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Convergence {
    /// The three values agree to round-off.
    Settled,
    /// The differences keep their sign and shrink: `order` = log₂|d₁/d₂| as observed (before the cap).
    Monotone {
        /// The observed order p.
        order: f64,
    },
    /// The differences alternate in sign and shrink: the limit lies between the two finest values.
    Alternating,
    /// The differences do not shrink: not converging at these resolutions; no error is estimated.
    NotContracting,
    /// The differences do not shrink, but the three values spread over no more than the change from `earlier` (the
    /// value one halving coarser) to the first of them: a floor reached (stick and slip starting between steps, a
    /// peak hopping between nodes, the solvers' tolerances), the error three times their spread
    /// ([`Sequence::scattered_error`]).
    Scattered {
        /// The value one halving coarser than the three.
        earlier: f64,
    },
}

/// One outcome at three resolutions, each refined by halving the one before.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sequence(pub [f64; 3]);

impl Sequence {
    /// How the three values converge.
    pub fn convergence(&self) -> Convergence {
        let [q0, q1, q2] = self.0;
        let (d1, d2) = (q1 - q0, q2 - q1);
        let scale = q0.abs().max(q1.abs()).max(q2.abs());
        if d1.abs().max(d2.abs()) <= ROUND_OFF * scale {
            Convergence::Settled
        } else if d2.abs() >= d1.abs() || !(d1.is_finite() && d2.is_finite()) {
            Convergence::NotContracting
        } else if d1 * d2 > 0.0 {
            Convergence::Monotone { order: (d1 / d2).abs().log2() }
        } else {
            Convergence::Alternating
        }
    }

    /// Whether the values are in the asymptotic range: monotone, of an order the schemes can have.
    pub fn asymptotic(&self) -> bool {
        matches!(self.convergence(), Convergence::Monotone { order } if (MIN_ORDER..=MAX_ORDER + 1e-6).contains(&order))
    }

    /// Richardson's estimate of the converged value, with the observed order (monotone values only).
    fn extrapolated(&self) -> Option<f64> {
        let Convergence::Monotone { order } = self.convergence() else { return None };
        let [_, q1, q2] = self.0;
        let r = 2f64.powf(-order);
        Some(q2 + (q2 - q1) * r / (1.0 - r))
    }

    /// With `earlier`, the value one halving coarser than the three: where the three do not contract but spread over
    /// no more than the change from `earlier` to the first of them, they scatter about a floor the refinement has
    /// reached (whichever way they move within it), and the error of each is three times their spread (Eça &
    /// Hoekstra's data range, for values that show no order); None where they contract (the three-value rules hold)
    /// or spread wider than that change (not converging: a growth that keeps up with the change before it).
    pub fn scattered_error(&self, earlier: f64) -> Option<f64> {
        let spread = self.spread();
        let settled_from_earlier = spread <= (self.0[0] - earlier).abs();
        (self.convergence() == Convergence::NotContracting && settled_from_earlier).then_some(SPREAD_SAFETY * spread)
    }

    /// The spread of the three values (max − min).
    fn spread(&self) -> f64 {
        let [q0, q1, q2] = self.0;
        q0.max(q1).max(q2) - q0.min(q1).min(q2)
    }

    /// The estimated error of the value at `level` (0, 1 or 2); None where the values do not converge.
    pub fn error_of(&self, level: usize) -> Option<f64> {
        let q = self.0[level];
        match self.convergence() {
            Convergence::NotContracting => None,
            Convergence::Scattered { .. } => Some(SPREAD_SAFETY * self.spread()),
            Convergence::Settled => Some(self.spread()),
            Convergence::Monotone { order } if order < MIN_ORDER => {
                let richardson = SAFETY * (q - self.extrapolated()?).abs();
                Some(richardson.min(SPREAD_SAFETY * self.spread()))
            }
            _ if self.asymptotic() => Some(SAFETY * (q - self.extrapolated()?).abs()),
            _ => Some(SPREAD_SAFETY * self.spread()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn power_law(limit: f64, c: f64, p: f64, h0: f64) -> Sequence {
        Sequence([0, 1, 2].map(|k| limit + c * (h0 / 2f64.powi(k)).powf(p)))
    }

    #[test]
    fn an_exact_power_law_of_first_or_second_order_gives_its_order_and_its_error_times_the_safety_factor() {
        for p in [1.0, 1.5, 2.0] {
            let s = power_law(3.0, 0.4, p, 0.5);
            let Convergence::Monotone { order } = s.convergence() else { panic!("{:?}", s.convergence()) };
            assert!((order - p).abs() < 1e-12, "order {order} for p = {p}");
            for level in 0..3 {
                let truth = (s.0[level] - 3.0).abs();
                let error = s.error_of(level).unwrap();
                assert!((error / truth - SAFETY).abs() < 1e-9, "level {level}: {error} for {truth}");
            }
        }
    }

    #[test]
    fn an_order_no_scheme_has_or_alternating_differences_take_three_times_the_spread() {
        // p = 4 (a difference small by chance): 3 × (q₀ − q₂), not Richardson's smaller tail.
        let s = power_law(-1.0, 2.0, 4.0, 0.5);
        let spread = (s.0[0] - s.0[2]).abs();
        assert!((s.error_of(1).unwrap() - SPREAD_SAFETY * spread).abs() < 1e-12);
        // q_k = 1 + (−½)^k·0.1: alternating, 3 × (1.1 − 0.95).
        let s = Sequence([1.1, 0.95, 1.025]);
        assert_eq!(s.convergence(), Convergence::Alternating);
        assert!((s.error_of(1).unwrap() - SPREAD_SAFETY * 0.15).abs() < 1e-12);
    }

    #[test]
    fn an_order_below_a_half_takes_the_smaller_of_richardson_and_the_spread() {
        // p = 0.25: Richardson's tail is 1/(2^¼ − 1) ≈ 5.3 differences, three times the spread is less.
        let s = power_law(0.0, 1.0, 0.25, 1.0);
        let richardson = SAFETY * s.0[1].abs();
        let spread = SPREAD_SAFETY * (s.0[0] - s.0[2]).abs();
        assert!(spread < richardson);
        assert!((s.error_of(1).unwrap() - spread).abs() < 1e-12);
    }

    #[test]
    fn differences_that_do_not_shrink_leave_the_error_undefined() {
        for s in [Sequence([1.0, 1.1, 1.3]), Sequence([1.0, 1.1, 1.0]), Sequence([1.0, f64::NAN, 1.0])] {
            assert_eq!(s.convergence(), Convergence::NotContracting, "{s:?}");
            assert_eq!(s.error_of(1), None);
        }
    }

    #[test]
    fn values_that_spread_within_the_change_before_them_take_three_times_their_spread() {
        // The friction work under 5 kN/m ballast friction at 1600, 3200, 6400 elements: turning, not shrinking.
        let s = Sequence([370_990.0, 370_717.0, 371_095.0]);
        assert_eq!(s.convergence(), Convergence::NotContracting);
        // Reached from 2 000 J below: a floor of 378 J, the error 3 × 378 J.
        assert_eq!(s.scattered_error(369_000.0), Some(SPREAD_SAFETY * 378.0));
        // Reached from 300 J away: the scatter is as wide as the change before it, not a floor.
        assert_eq!(s.scattered_error(370_690.0), None);
        // The whole run's downward peak under 5 kN/m at 1600, 3200, 6400 elements: a drift of 0.07 and 0.11 mm after
        // a larger change (at 12 800 elements it is 175.634 mm, well within 3 × 0.18 mm).
        let s = Sequence([175.836, 175.765, 175.657]);
        assert!((s.scattered_error(176.4).unwrap() - SPREAD_SAFETY * 0.179).abs() < 1e-9);
        // A growth that keeps up with the change before it (the step acceleration under friction: 1891, then 1983,
        // 4279, 7587 m/s²) does not converge; contracting values keep the three-value rules.
        assert_eq!(Sequence([1983.0, 4279.0, 7587.0]).scattered_error(1891.0), None);
        assert_eq!(Sequence([1.4, 1.2, 1.1]).scattered_error(2.0), None);
    }

    #[test]
    fn values_equal_to_round_off_are_settled_with_their_spread() {
        let s = Sequence([2.0, 2.0 + 1e-12, 2.0 - 1e-12]);
        assert_eq!(s.convergence(), Convergence::Settled);
        assert!(s.error_of(0).unwrap() <= 3e-12);
        assert_eq!(Sequence([0.0; 3]).error_of(2), Some(0.0));
    }
}
