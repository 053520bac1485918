//! The interior-point state of the active sections, one array per quantity, and the per-section passes over it.

use super::extra_rows::ExtraRows;
use banded::BlockRows;
use friction::law::project;

/// Interior-point state of the active sections, one array per quantity, k = 0..len in the order of `index`. The
/// per-section arithmetic runs as straight loops over contiguous arrays (which the compiler vectorises); B and the
/// right-hand side are accumulated section after section ([`BlockRows`]) and the sums μ in section order, so every
/// result is the same to the bit as section-by-section evaluation.
#[derive(Debug, Default)]
pub(super) struct Sections {
    /// Section index j of each active section.
    pub(super) index: Vec<usize>,
    /// The local rows H_k over the subproblem's DOFs (at most four DOFs within the band; a row beyond the band is empty here).
    pub(super) rows: BlockRows,
    /// The non-local rows (a wheel's contact), by the low-rank correction of the Newton systems.
    pub(super) extra: ExtraRows,
    /// Bounds lo_j, hi_j (N·s; hi_j may be +∞), W_jj + d_j and its inverse, the compliance d_j.
    pub(super) lower: Vec<f64>,
    pub(super) upper: Vec<f64>,
    pub(super) w: Vec<f64>,
    pub(super) inv_w: Vec<f64>,
    pub(super) compliance: Vec<f64>,
    /// 1 where hi_j is finite, 0 where it is +∞ (then the upper slack and its multiplier drop out: s₁ is a dummy,
    /// z₁ = 0, 1/s₁ = 0); `open` is 1 − `closed`.
    pub(super) closed: Vec<f64>,
    pub(super) open: Vec<f64>,
    /// U_free,j (+ b_j once the iteration starts: the constant c_j of the QP).
    pub(super) u_free: Vec<f64>,
    /// The law velocity r = (W + D)p + c of the current iterate.
    pub(super) u: Vec<f64>,
    pub(super) p: Vec<f64>,
    pub(super) s1: Vec<f64>,
    pub(super) s2: Vec<f64>,
    pub(super) z1: Vec<f64>,
    pub(super) z2: Vec<f64>,
    pub(super) inv_s1: Vec<f64>,
    pub(super) inv_s2: Vec<f64>,
    pub(super) inv_z1: Vec<f64>,
    pub(super) inv_z2: Vec<f64>,
    pub(super) inv_sigma: Vec<f64>,
    pub(super) r: Vec<f64>,
    pub(super) c1: Vec<f64>,
    pub(super) c2: Vec<f64>,
    pub(super) dp: Vec<f64>,
    pub(super) dz1: Vec<f64>,
    pub(super) dz2: Vec<f64>,
    /// H_j·x gathered for each section, and per-section terms of the sums.
    pub(super) gathered: Vec<f64>,
    /// r_k Σ_k⁻¹, the weights of the Newton right-hand side.
    pub(super) weighted: Vec<f64>,
}

impl Sections {
    /// Arrays with room for `m` sections, so that no step allocates.
    pub(super) fn with_capacity(m: usize) -> Self {
        let mut sections = Self { rows: BlockRows::with_capacity(m), ..Self::default() };
        sections.index.resize(m, 0);
        sections.fit();
        sections.index.clear();
        sections
    }

    /// Size every array to `index.len()` (no allocation once the capacity is there).
    pub(super) fn fit(&mut self) {
        let len = self.index.len();
        for v in [
            &mut self.lower,
            &mut self.upper,
            &mut self.w,
            &mut self.inv_w,
            &mut self.compliance,
            &mut self.closed,
            &mut self.open,
            &mut self.u_free,
            &mut self.u,
            &mut self.p,
            &mut self.s1,
            &mut self.s2,
            &mut self.z1,
            &mut self.z2,
            &mut self.inv_s1,
            &mut self.inv_s2,
            &mut self.inv_z1,
            &mut self.inv_z2,
            &mut self.inv_sigma,
            &mut self.r,
            &mut self.c1,
            &mut self.c2,
            &mut self.dp,
            &mut self.dz1,
            &mut self.dz2,
            &mut self.gathered,
            &mut self.weighted,
        ] {
            v.resize(len, 0.0);
        }
    }

    /// gathered_k = H_k·x (x padded with three zeros past its end).
    #[inline(always)]
    pub(super) fn gather(&mut self, x: &[f64]) {
        self.rows.mul(x, &mut self.gathered);
        if !self.extra.is_empty() {
            self.extra.gather(x, &mut self.gathered);
        }
    }

    /// The Newton right-hand side out = Σ_k H_kᵀ r_k Σ_k⁻¹ over the local rows, summed in section order (out padded
    /// with three zeros past its end); the non-local rows enter through their own impulses ([`ExtraRows::solve`]).
    #[inline(always)]
    pub(super) fn right_hand_side(&mut self, out: &mut [f64]) {
        let len = self.index.len();
        let (r, inv_sigma, weighted) = (&self.r[..len], &self.inv_sigma[..len], &mut self.weighted[..len]);
        for k in 0..len {
            weighted[k] = r[k] * inv_sigma[k];
        }
        self.rows.transpose_mul(weighted, out);
    }

    /// max_k of the law residual |p − proj_[lo, hi](p − r/w)|·w (m/s), w = W_kk + d_k.
    #[inline(always)]
    pub(super) fn law_residual(&self) -> f64 {
        let mut residual: f64 = 0.0;
        let bounds = self.lower.iter().zip(&self.upper);
        let scales = self.w.iter().zip(&self.inv_w);
        for (((&p, &u), (&lo, &hi)), (&w, &inv_w)) in self.p.iter().zip(&self.u).zip(bounds).zip(scales) {
            residual = residual.max((p - project(p - u * inv_w, lo, hi)).abs() * w);
        }
        residual
    }
}
