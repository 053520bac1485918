//! The per-section terms of the Mehrotra predictor–corrector iteration (`iteration.rs`; docs/theory.md §5):
//! each a loop over the sections of one window, written as a function of slices so that the compiler knows the
//! arrays do not overlap (and, all of one length, needs no bounds checks) and vectorises it.

/// Predictor set-up: 1/s₁ (0 without an upper bound), 1/s₂, 1/z₁ (1 without an upper bound, where z₁ = 0), 1/z₂,
/// (Σ + D)⁻¹ = 1/(max(z₁/s₁ + z₂/s₂, 1e-15·w) + d), r = −u, c₁ = c₂ = 0.
#[inline(always)]
pub(super) fn predictor_terms(input: [&[f64]; 6], law: [&[f64]; 3], inverses: [&mut [f64]; 4], out: [&mut [f64]; 4]) {
    let [s1, s2, z1, z2, w, u] = input;
    let [closed, open, compliance] = law;
    let [inv_s1, inv_s2, inv_z1, inv_z2] = inverses;
    let [inv_sigma, r, c1, c2] = out;
    let len = s1.len();
    let (s2, z1, z2, w, u) = (&s2[..len], &z1[..len], &z2[..len], &w[..len], &u[..len]);
    let (closed, open, compliance) = (&closed[..len], &open[..len], &compliance[..len]);
    let (inv_s1, inv_s2, inv_z1, inv_z2) =
        (&mut inv_s1[..len], &mut inv_s2[..len], &mut inv_z1[..len], &mut inv_z2[..len]);
    let (inv_sigma, r, c1, c2) = (&mut inv_sigma[..len], &mut r[..len], &mut c1[..len], &mut c2[..len]);
    for k in 0..len {
        inv_s1[k] = closed[k] / s1[k];
        inv_s2[k] = 1.0 / s2[k];
        inv_z1[k] = 1.0 / (z1[k] + open[k]);
        inv_z2[k] = 1.0 / z2[k];
        inv_sigma[k] = 1.0 / ((z1[k] * inv_s1[k] + z2[k] * inv_s2[k]).max(1e-15 * w[k]) + compliance[k]);
        r[k] = -u[k];
        c1[k] = 0.0;
        c2[k] = 0.0;
    }
}

/// Newton direction per section: Δp = (r − H dy)Σ⁻¹, Δz₁ = (c₁ + z₁Δp)/s₁ − z₁, Δz₂ = (c₂ − z₂Δp)/s₂ − z₂; returns
/// the largest ratios −Δx/x over the primal (s) and dual (z) variables, at least 1.
#[inline(always)]
pub(super) fn direction_terms(first: [&[f64]; 6], second: [&[f64]; 5], out: [&mut [f64]; 3]) -> (f64, f64) {
    let [r, g, inv_sigma, c1, c2, z1] = first;
    let [z2, inv_s1, inv_s2, inv_z1, inv_z2] = second;
    let [dp_out, dz1_out, dz2_out] = out;
    let len = r.len();
    let (g, inv_sigma, c1, c2, z1) = (&g[..len], &inv_sigma[..len], &c1[..len], &c2[..len], &z1[..len]);
    let (z2, inv_s1, inv_s2, inv_z1, inv_z2) =
        (&z2[..len], &inv_s1[..len], &inv_s2[..len], &inv_z1[..len], &inv_z2[..len]);
    let (dp_out, dz1_out, dz2_out) = (&mut dp_out[..len], &mut dz1_out[..len], &mut dz2_out[..len]);
    let (mut primal, mut dual): (f64, f64) = (1.0, 1.0);
    for k in 0..len {
        let dp = (r[k] - g[k]) * inv_sigma[k];
        let dz1 = (c1[k] + z1[k] * dp) * inv_s1[k] - z1[k];
        let dz2 = (c2[k] - z2[k] * dp) * inv_s2[k] - z2[k];
        dp_out[k] = dp;
        dz1_out[k] = dz1;
        dz2_out[k] = dz2;
        primal = primal.max(dp * inv_s1[k]).max(-dp * inv_s2[k]);
        dual = dual.max(-dz1 * inv_z1[k]).max(-dz2 * inv_z2[k]);
    }
    (primal, dual)
}

/// Terms of μ_aff: (s₁ − α_pΔp)(z₁ + α_dΔz₁) + (s₂ + α_pΔp)(z₂ + α_dΔz₂).
#[inline(always)]
pub(super) fn affine_terms(
    (alpha_p, alpha_d): (f64, f64),
    state: [&[f64]; 4],
    direction: [&[f64]; 3],
    out: &mut [f64],
) {
    let [s1, s2, z1, z2] = state;
    let [dp, dz1, dz2] = direction;
    let len = out.len();
    let (s1, s2, z1, z2, dp, dz1, dz2) =
        (&s1[..len], &s2[..len], &z1[..len], &z2[..len], &dp[..len], &dz1[..len], &dz2[..len]);
    for k in 0..len {
        let step = alpha_p * dp[k];
        out[k] = (s1[k] - step) * (z1[k] + alpha_d * dz1[k]) + (s2[k] + step) * (z2[k] + alpha_d * dz2[k]);
    }
}

/// Corrector targets c₁ = t + Δp Δz₁, c₂ = t − Δp Δz₂ and r = −u − c₁/s₁ + c₂/s₂.
#[inline(always)]
pub(super) fn corrector_terms(target: f64, input: [&[f64]; 6], out: [&mut [f64]; 3]) {
    let [dp, dz1, dz2, u, inv_s1, inv_s2] = input;
    let [c1, c2, r] = out;
    let len = dp.len();
    let (dz1, dz2, u, inv_s1, inv_s2) = (&dz1[..len], &dz2[..len], &u[..len], &inv_s1[..len], &inv_s2[..len]);
    let (c1, c2, r) = (&mut c1[..len], &mut c2[..len], &mut r[..len]);
    for k in 0..len {
        c1[k] = target + dp[k] * dz1[k];
        c2[k] = target - dp[k] * dz2[k];
        r[k] = -u[k] - c1[k] * inv_s1[k] + c2[k] * inv_s2[k];
    }
}

/// Centring targets of a safeguarded step: c₁ = c₂ = t and r = −u − t/s₁ + t/s₂.
#[inline(always)]
pub(super) fn centring_terms(target: f64, input: [&[f64]; 3], out: [&mut [f64]; 3]) {
    let [u, inv_s1, inv_s2] = input;
    let [c1, c2, r] = out;
    let len = u.len();
    let (inv_s1, inv_s2) = (&inv_s1[..len], &inv_s2[..len]);
    let (c1, c2, r) = (&mut c1[..len], &mut c2[..len], &mut r[..len]);
    for k in 0..len {
        c1[k] = target;
        c2[k] = target;
        r[k] = -u[k] - target * inv_s1[k] + target * inv_s2[k];
    }
}

/// The step: p += αΔp, s₁ −= αΔp, s₂ += αΔp (slacks are updated, not recomputed from p: near a bound a − p loses
/// all precision), z += α_dΔz, r = c + H y + d p.
#[inline(always)]
pub(super) fn take_step((alpha, alpha_d): (f64, f64), input: [&[f64]; 6], state: [&mut [f64]; 6]) {
    let [dp, dz1, dz2, u_free, hy, compliance] = input;
    let [p, s1, s2, z1, z2, u] = state;
    let len = dp.len();
    let (dz1, dz2, u_free, hy, compliance) = (&dz1[..len], &dz2[..len], &u_free[..len], &hy[..len], &compliance[..len]);
    let (p, s1, s2, z1, z2, u) =
        (&mut p[..len], &mut s1[..len], &mut s2[..len], &mut z1[..len], &mut z2[..len], &mut u[..len]);
    for k in 0..len {
        let step = alpha * dp[k];
        p[k] += step;
        s1[k] -= step;
        s2[k] += step;
        z1[k] += alpha_d * dz1[k];
        z2[k] += alpha_d * dz2[k];
        u[k] = u_free[k] + hy[k] + compliance[k] * p[k];
    }
}
