//! The set-valued Coulomb law p ∈ −a·Sign(u) (docs/theory.md §4), written for impulses p = h·r over a step with bound
//! a = h·F_u.
//!
//! Sign(u) = {−1} for u < 0, [−1, 1] for u = 0, {+1} for u > 0. For any ρ > 0 the law is equivalent to the
//! fixed point p = proj_[−a, a](p − ρ·u), which is what the solvers iterate and what [`natural_residual`] measures.

/// Projection of `p` onto [−a, a] (a ≥ 0).
#[inline]
pub fn project(p: f64, a: f64) -> f64 {
    p.clamp(-a, a)
}

/// Natural residual |p − proj_[−a, a](p − ρ·u)| / ρ of the law, in velocity units (m/s) when p is an impulse
/// (N·s) and ρ an impulse per velocity (kg, e.g. 1/W_jj). Zero exactly when p ∈ −a·Sign(u):
/// for a stuck section it is |u|, for a slipping one the distance of p from −a·sign(u) divided by ρ.
#[inline]
pub fn natural_residual(u: f64, p: f64, a: f64, rho: f64) -> f64 {
    (p - project(p - rho * u, a)).abs() / rho
}
