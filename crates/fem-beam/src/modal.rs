//! Undamped natural frequencies: the generalised eigenproblem K φ = ω² M φ over the free DOFs.
//!
//! Solved densely: M = L Lᵀ (Cholesky), then the symmetric standard problem L⁻¹ K L⁻ᵀ y = ω² y. Cost O(n³): fine
//! for the reference mesh (400 free DOFs, well under a second), meant for verification and reporting rather than
//! meshes of many thousand DOFs. For the pinned reference beam the closed form is
//! ω_n² = (EI(nπ/L)⁴ + k_f)/(ρA) (docs/theory.md §8).

use crate::assembly::BeamModel;
use crate::error::{FemError, Result};
use nalgebra::DMatrix;

impl BeamModel {
    /// The largest eigenproblem solved densely: 2000 free DOFs (1000 elements; 32 MB per dense matrix, a few
    /// seconds). Larger meshes are refused before any dense matrix is allocated.
    pub const MAX_MODAL_DOFS: usize = 2000;

    /// All eigenvalues ω² (rad²/s²) in ascending order. Zero (rigid-body) modes give values at round-off level,
    /// possibly slightly negative. Errors for more than [`BeamModel::MAX_MODAL_DOFS`] free DOFs.
    pub fn eigenvalues(&self) -> Result<Vec<f64>> {
        let (_, a) = self.standard_eigenproblem()?;
        let mut values: Vec<f64> = a.symmetric_eigenvalues().iter().copied().collect();
        values.sort_by(f64::total_cmp);
        Ok(values)
    }

    /// M = L Lᵀ and the symmetric standard form A = L⁻¹ K L⁻ᵀ of K φ = ω² M φ (A y = ω² y, φ = L⁻ᵀ y), dense over
    /// the free DOFs; refused beyond [`BeamModel::MAX_MODAL_DOFS`] before any dense matrix is allocated.
    pub(crate) fn standard_eigenproblem(&self) -> Result<(DMatrix<f64>, DMatrix<f64>)> {
        let n = self.mass().order();
        if n > Self::MAX_MODAL_DOFS {
            return Err(FemError::InvalidCount {
                field: "mesh.elements",
                value: self.mesh().elements,
                allowed: "gives more than 2000 free DOFs, the limit of the dense eigenproblem of the natural \
                          frequencies (use at most 1000 elements)",
            });
        }
        let m = self.mass().to_dense();
        let k = self.stiffness().to_dense();
        let chol = m.cholesky().ok_or(FemError::NonPositivePivot { index: 0, pivot: f64::NAN })?;
        let l = chol.l();
        let x = l.solve_lower_triangular(&k).ok_or(FemError::NonPositivePivot { index: 0, pivot: 0.0 })?;
        let a = l.solve_lower_triangular(&x.transpose()).ok_or(FemError::NonPositivePivot { index: 0, pivot: 0.0 })?;
        let a = (&a + a.transpose()) * 0.5;
        Ok((l, a))
    }

    /// The lowest `count` natural circular frequencies ω (rad/s), ascending; zero modes give 0.
    pub fn natural_frequencies(&self, count: usize) -> Result<Vec<f64>> {
        let n = self.dofs().free_len();
        if count == 0 || count > n {
            return Err(FemError::InvalidCount {
                field: "mode count",
                value: count,
                allowed: "must be between 1 and the number of free DOFs",
            });
        }
        Ok(self.eigenvalues()?.into_iter().take(count).map(|w2| w2.max(0.0).sqrt()).collect())
    }
}
