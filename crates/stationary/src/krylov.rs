//! GMRES with right preconditioning (Saad & Schultz 1986; Saad 2003, "Iterative methods for sparse linear systems",
//! §9.3.2): the x₀ = 0 iterate's Krylov space of A M⁻¹ built by Arnoldi with modified Gram–Schmidt, the least-squares
//! problem kept triangular by Givens rotations, so ‖b − A x_k‖₂ is known at every step without forming x_k; then
//! x = M⁻¹ V y. Used where the ground's non-local operator is applied by FFT and a local (banded) operator is the
//! preconditioner M.

/// How a GMRES solve ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KrylovOutcome {
    /// Krylov steps (products with A M⁻¹).
    pub iterations: usize,
    /// ‖b − A x‖₂ / ‖b‖₂ reached (0 for b = 0).
    pub residual: f64,
}

/// x with ‖b − A x‖₂ ≤ `tolerance`·‖b‖₂ (or after `max_iterations` steps, its residual said), for A given by
/// `apply` and M⁻¹ by `precondition`.
pub fn gmres(
    apply: &dyn Fn(&[f64]) -> Vec<f64>,
    precondition: &dyn Fn(&[f64]) -> Vec<f64>,
    b: &[f64],
    tolerance: f64,
    max_iterations: usize,
) -> (Vec<f64>, KrylovOutcome) {
    let n = b.len();
    let beta = norm(b);
    if beta == 0.0 {
        return (vec![0.0; n], KrylovOutcome { iterations: 0, residual: 0.0 });
    }
    let mut basis: Vec<Vec<f64>> = vec![b.iter().map(|x| x / beta).collect()];
    // The Hessenberg columns, rotated; the rotations (c, s); the rotated right-hand side g.
    let mut columns: Vec<Vec<f64>> = Vec::new();
    let mut rotations: Vec<(f64, f64)> = Vec::new();
    let mut g = vec![beta];
    let mut residual = beta;
    while columns.len() < max_iterations && residual > tolerance * beta {
        let j = columns.len();
        let mut w = apply(&precondition(&basis[j]));
        let mut h = Vec::with_capacity(j + 2);
        for v in &basis {
            let projection = dot(&w, v);
            w.iter_mut().zip(v).for_each(|(w, v)| *w -= projection * v);
            h.push(projection);
        }
        let next = norm(&w);
        h.push(next);
        for (i, &(c, s)) in rotations.iter().enumerate() {
            let (a, b) = (h[i], h[i + 1]);
            (h[i], h[i + 1]) = (c * a + s * b, -s * a + c * b);
        }
        let radius = h[j].hypot(h[j + 1]);
        let (c, s) = if radius == 0.0 { (1.0, 0.0) } else { (h[j] / radius, h[j + 1] / radius) };
        h[j] = radius;
        h[j + 1] = 0.0;
        rotations.push((c, s));
        g.push(-s * g[j]);
        g[j] *= c;
        residual = g[j + 1].abs();
        columns.push(h);
        if next == 0.0 {
            break;
        }
        basis.push(w.iter().map(|x| x / next).collect());
    }
    // Back substitution: R y = g, R upper triangular (column j holds R[0..=j][j]).
    let k = columns.len();
    let mut y = vec![0.0; k];
    for i in (0..k).rev() {
        let sum: f64 = (i + 1..k).map(|j| columns[j][i] * y[j]).sum();
        y[i] = (g[i] - sum) / columns[i][i];
    }
    let mut combination = vec![0.0; n];
    for (v, y) in basis.iter().zip(&y) {
        combination.iter_mut().zip(v).for_each(|(c, v)| *c += y * v);
    }
    (precondition(&combination), KrylovOutcome { iterations: k, residual: residual / beta })
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(a, b)| a * b).sum()
}

fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A non-symmetric 40 × 40 system: without a preconditioner GMRES is exact in at most n steps; with the exact
    /// inverse of its diagonal-plus-bidiagonal part it needs far fewer. The solution is checked against a direct one
    /// to 1e-10 (the system's condition number is ~10: the tolerance 1e-12 of ‖b‖ times that, with room).
    #[test]
    fn gmres_solves_a_nonsymmetric_system() {
        let n = 40;
        let a = |i: usize, j: usize| match (i as i64) - (j as i64) {
            0 => 4.0 + (i as f64 * 0.1).sin(),
            1 => -1.0,
            -1 => 0.5,
            d => 0.05 / (d * d) as f64,
        };
        let apply = |x: &[f64]| -> Vec<f64> { (0..n).map(|i| (0..n).map(|j| a(i, j) * x[j]).sum()).collect() };
        let x_true: Vec<f64> = (0..n).map(|i| (i as f64).sqrt() - 2.0).collect();
        let b = apply(&x_true);
        let identity = |x: &[f64]| x.to_vec();
        let (x, plain) = gmres(&apply, &identity, &b, 1e-12, 200);
        x.iter().zip(&x_true).for_each(|(x, t)| assert!((x - t).abs() < 1e-10, "{x} vs {t}"));
        let diagonal = |x: &[f64]| -> Vec<f64> { (0..n).map(|i| x[i] / a(i, i)).collect() };
        let (x, preconditioned) = gmres(&apply, &diagonal, &b, 1e-12, 200);
        x.iter().zip(&x_true).for_each(|(x, t)| assert!((x - t).abs() < 1e-10, "{x} vs {t}"));
        assert!(plain.iterations <= n && preconditioned.iterations < plain.iterations, "{plain:?} {preconditioned:?}");
        assert!(preconditioned.residual <= 1e-12);
    }
}
