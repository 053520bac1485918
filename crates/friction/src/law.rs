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
