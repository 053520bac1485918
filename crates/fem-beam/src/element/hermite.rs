//! Hermite cubic Euler–Bernoulli beam element of length l (docs/theory.md §3).
//!
//! With ξ = (x − x_a)/l ∈ [0, 1] the shape functions are
//! N₁ = 1 − 3ξ² + 2ξ³, N₂ = l(ξ − 2ξ² + ξ³), N₃ = 3ξ² − 2ξ³, N₄ = l(−ξ² + ξ³), and w(x) = Σ Nᵢ qᵢ.
//! Consistent matrices (Przemieniecki; Cook et al. §2.4):
//!
//! - mass, and the Winkler foundation's stiffness and damping: `μ·l/420·P` with μ = ρA, k_f or c_f and
//!   P = [[156, 22l, 54, −13l], [22l, 4l², 13l, −3l²], [54, 13l, 156, −22l], [−13l, −3l², −22l, 4l²]];
//! - bending stiffness: `EI/l³·[[12, 6l, −12, 6l], [6l, 4l², −6l, 2l²], [−12, −6l, 12, −6l], [6l, 2l², −6l, 4l²]]`.

use super::{ElementMatrix, ElementVector};

/// The four-point Gauss–Legendre rule on [0, 1]: (ξ_g, w_g), exact for polynomials of degree 7 — so for every
/// product of two Hermite cubics or their derivatives: Σ_g w_g l N(ξ_g)N(ξ_g)ᵀ is the consistent matrix ∫NNᵀ dx.
/// ±√(3/7 ∓ (2/7)√(6/5)) on [−1, 1] with weights (18 ± √30)/36, mapped to [0, 1].
pub const GAUSS_4: [(f64, f64); 4] = {
    const INNER: f64 = 0.339_981_043_584_856_26;
    const OUTER: f64 = 0.861_136_311_594_052_6;
    const W_INNER: f64 = 0.652_145_154_862_546_1;
    const W_OUTER: f64 = 0.347_854_845_137_453_85;
    [
        (0.5 * (1.0 - OUTER), 0.5 * W_OUTER),
        (0.5 * (1.0 - INNER), 0.5 * W_INNER),
        (0.5 * (1.0 + INNER), 0.5 * W_INNER),
        (0.5 * (1.0 + OUTER), 0.5 * W_OUTER),
    ]
};

/// Shape functions N(ξ) (dimensionless for w, metres for θ) at local coordinate ξ on an element of length l.
pub fn shape(xi: f64, l: f64) -> ElementVector {
    let (x2, x3) = (xi * xi, xi * xi * xi);
    [1.0 - 3.0 * x2 + 2.0 * x3, l * (xi - 2.0 * x2 + x3), 3.0 * x2 - 2.0 * x3, l * (x3 - x2)]
}

/// First derivatives dN/dx (1/m for w, dimensionless for θ).
pub fn shape_dx(xi: f64, l: f64) -> ElementVector {
    let x2 = xi * xi;
    [6.0 * (x2 - xi) / l, 1.0 - 4.0 * xi + 3.0 * x2, 6.0 * (xi - x2) / l, 3.0 * x2 - 2.0 * xi]
}

/// Second derivatives d²N/dx² (1/m² for w, 1/m for θ); EI·Σ N″ᵢqᵢ is the bending moment, linear on the element.
pub fn shape_dxx(xi: f64, l: f64) -> ElementVector {
    [(12.0 * xi - 6.0) / (l * l), (6.0 * xi - 4.0) / l, (6.0 - 12.0 * xi) / (l * l), (6.0 * xi - 2.0) / l]
}

/// Consistent "mass-pattern" matrix μ·l/420·P, used for the mass (μ = ρA), the foundation stiffness (μ = k_f)
/// and the foundation damping (μ = c_f).
pub fn consistent_mass(per_length: f64, l: f64) -> ElementMatrix {
    let c = per_length * l / 420.0;
    let l2 = l * l;
    [
        [156.0 * c, 22.0 * l * c, 54.0 * c, -13.0 * l * c],
        [22.0 * l * c, 4.0 * l2 * c, 13.0 * l * c, -3.0 * l2 * c],
        [54.0 * c, 13.0 * l * c, 156.0 * c, -22.0 * l * c],
        [-13.0 * l * c, -3.0 * l2 * c, -22.0 * l * c, 4.0 * l2 * c],
    ]
}

/// Bending stiffness EI/l³·[…] of the element.
pub fn bending_stiffness(ei: f64, l: f64) -> ElementMatrix {
    let c = ei / (l * l * l);
    let l2 = l * l;
    [
        [12.0 * c, 6.0 * l * c, -12.0 * c, 6.0 * l * c],
        [6.0 * l * c, 4.0 * l2 * c, -6.0 * l * c, 2.0 * l2 * c],
        [-12.0 * c, -6.0 * l * c, 12.0 * c, -6.0 * l * c],
        [6.0 * l * c, 2.0 * l2 * c, -6.0 * l * c, 4.0 * l2 * c],
    ]
}

/// Consistent nodal loads of a uniform load q (N/m) over the whole element: (ql/2, ql²/12, ql/2, −ql²/12).
pub fn uniform_load(q: f64, l: f64) -> ElementVector {
    [q * l / 2.0, q * l * l / 12.0, q * l / 2.0, -q * l * l / 12.0]
}

/// ∫ N(x) dx over the part [ξ₀, ξ₁] (0 ≤ ξ₀ ≤ ξ₁ ≤ 1) of an element of length l: the consistent nodal loads of a
/// unit uniform load over that part (docs/theory.md §10). With the antiderivatives in ξ
/// A₁ = ξ − ξ³ + ξ⁴/2, A₂ = l(ξ²/2 − 2ξ³/3 + ξ⁴/4), A₃ = ξ³ − ξ⁴/2, A₄ = l(−ξ³/3 + ξ⁴/4), the integral is
/// l·(A(ξ₁) − A(ξ₀)); over the whole element (l/2, l²/12, l/2, −l²/12), as [`uniform_load`].
pub fn shape_integral(xi0: f64, xi1: f64, l: f64) -> ElementVector {
    let antiderivative = |x: f64| {
        let (x2, x3, x4) = (x * x, x * x * x, x * x * x * x);
        [x - x3 + 0.5 * x4, l * (0.5 * x2 - 2.0 * x3 / 3.0 + 0.25 * x4), x3 - 0.5 * x4, l * (-x3 / 3.0 + 0.25 * x4)]
    };
    let (a, b) = (antiderivative(xi0), antiderivative(xi1));
    std::array::from_fn(|k| l * (b[k] - a[k]))
}

/// Element matrix sum a·A + b·B.
pub fn combine(a: f64, lhs: &ElementMatrix, b: f64, rhs: &ElementMatrix) -> ElementMatrix {
    let mut out = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            out[i][j] = a * lhs[i][j] + b * rhs[i][j];
        }
    }
    out
}

/// Matrix–vector product of an element matrix.
pub fn apply(matrix: &ElementMatrix, vector: &ElementVector) -> ElementVector {
    let mut out = [0.0; 4];
    for i in 0..4 {
        out[i] = (0..4).map(|j| matrix[i][j] * vector[j]).sum();
    }
    out
}
