//! The band-limited response: the part of a motion carried by the modes at or below a frequency.
//!
//! EN 1990 Annex A2.4.4.2.1(4) checks a bridge deck's peak acceleration "considering frequencies (including associated
//! mode shapes) up to the greater of 30 Hz, 1.5 f₁ and f₃": the modes below that limit, not a filter in time. With
//! the mass-normalised modes φⱼ of K φ = ω² M φ (φⱼᵀ M φₖ = δⱼₖ), a field a (here an acceleration over the free DOFs)
//! has the modal coordinates ηⱼ = φⱼᵀ M a, and its band-limited part is a_b = Σ_{fⱼ ≤ f_max} φⱼ ηⱼ — the M-orthogonal
//! projection onto those modes (docs/theory.md §10.4). A point load on a Timoshenko rail makes the nodal acceleration
//! at its passage grow without bound under refinement; the band-limited one converges, as the lowest modes do.

use crate::assembly::BeamModel;
use crate::error::{FemError, Result};

/// Which modes a band keeps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BandLimit {
    /// A bridge deck's check band of EN 1990 A2.4.4.2.1(4): the modes up to f_max = [`deck_band`] of the model's own
    /// f₁ and f₃ — so that its third mode is kept whatever the mesh's frequency error.
    Deck,
    /// The modes at or below this frequency (Hz).
    Frequency(f64),
}

impl std::fmt::Display for BandLimit {
    /// The band as a report names it.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            BandLimit::Deck => write!(f, "max(30 Hz, 1.5 f₁, f₃) (a span's default, EN 1990 A2)"),
            BandLimit::Frequency(limit) => write!(f, "{limit} Hz"),
        }
    }
}

/// f_max = max(30 Hz, 1.5 f₁, f₃) (Hz) from a deck's first and third natural frequencies (Hz): the highest frequency
/// its acceleration check considers (EN 1990 A2.4.4.2.1(4)).
pub fn deck_band(first: f64, third: f64) -> f64 {
    30f64.max(1.5 * first).max(third)
}

/// The mass-normalised modes of a model at or below a frequency, ready to project a field onto them.
#[derive(Debug, Clone, PartialEq)]
pub struct ModalBand {
    /// The band's upper limit f_max (Hz).
    limit: f64,
    /// The modes' natural frequencies fⱼ (Hz), ascending.
    frequencies: Vec<f64>,
    /// φⱼ over the free DOFs, mass-normalised.
    shapes: Vec<Vec<f64>>,
    /// M φⱼ, so that ηⱼ = (M φⱼ)ᵀ a costs one dot product.
    mass_shapes: Vec<Vec<f64>>,
}

impl ModalBand {
    /// The modes of `model` within `band` (a frequency finite and > 0). Solved densely ([`BeamModel::MAX_MODAL_DOFS`]
    /// at most); a band without any mode is an error naming the lowest frequency.
    pub fn of(model: &BeamModel, band: BandLimit) -> Result<Self> {
        if let BandLimit::Frequency(limit) = band
            && !(limit.is_finite() && limit > 0.0)
        {
            return Err(FemError::InvalidBand { value: band.to_string(), allowed: "must be finite and > 0".into() });
        }
        // The eigenproblem's own size check (before any dense matrix), said as the band's.
        let (l, standard) = model.standard_eigenproblem().map_err(|e| match e {
            FemError::InvalidCount { .. } => FemError::InvalidBand {
                value: band.to_string(),
                allowed: format!(
                    "its modes are solved densely, for at most {} free DOFs, and this model has {} (mesh.elements \
                     = {}): use fewer elements or leave the band out",
                    BeamModel::MAX_MODAL_DOFS,
                    model.mass().order(),
                    model.mesh().elements
                ),
            },
            other => other,
        })?;
        let eigen = standard.symmetric_eigen();
        let mut order: Vec<usize> = (0..eigen.eigenvalues.len()).collect();
        order.sort_by(|&a, &b| eigen.eigenvalues[a].total_cmp(&eigen.eigenvalues[b]));
        let frequency = |i: usize| eigen.eigenvalues[i].max(0.0).sqrt() / std::f64::consts::TAU;
        let nth = |n: usize| order.get(n).map_or(f64::INFINITY, |&i| frequency(i));
        let limit = match band {
            BandLimit::Deck => deck_band(nth(0), nth(2)),
            BandLimit::Frequency(limit) => limit,
        };
        let kept: Vec<usize> = order.iter().copied().take_while(|&i| frequency(i) <= limit).collect();
        if kept.is_empty() {
            let lowest = frequency(order[0]);
            return Err(FemError::InvalidBand {
                value: band.to_string(),
                allowed: format!("holds no mode: the structure's lowest natural frequency is {lowest:.3} Hz"),
            });
        }
        // φ = L⁻ᵀ y for M = L Lᵀ: then φᵀ M φ = yᵀ y = 1.
        let lt = l.transpose();
        let mut band = Self { limit, frequencies: Vec::new(), shapes: Vec::new(), mass_shapes: Vec::new() };
        for i in kept {
            let y = eigen.eigenvectors.column(i).into_owned();
            let phi = lt.solve_upper_triangular(&y).ok_or(FemError::NonPositivePivot { index: i, pivot: 0.0 })?;
            let phi: Vec<f64> = phi.iter().copied().collect();
            let mut m_phi = vec![0.0; phi.len()];
            model.mass().mul_vec(&phi, &mut m_phi);
            band.frequencies.push(frequency(i));
            band.shapes.push(phi);
            band.mass_shapes.push(m_phi);
        }
        Ok(band)
    }

    /// f_max (Hz).
    pub fn limit(&self) -> f64 {
        self.limit
    }

    /// The kept modes' frequencies (Hz), ascending.
    pub fn frequencies(&self) -> &[f64] {
        &self.frequencies
    }

    /// The modal coordinates ηⱼ = φⱼᵀ M a of `field` over the free DOFs (its first [`ModalBand::dofs`] entries),
    /// written into `eta` (one per mode).
    pub fn coordinates(&self, field: &[f64], eta: &mut [f64]) {
        for (e, m_phi) in eta.iter_mut().zip(&self.mass_shapes) {
            *e = m_phi.iter().zip(field).map(|(a, b)| a * b).sum();
        }
    }

    /// The band-limited field at free DOF `dof` from its modal coordinates: Σⱼ φⱼ(dof) ηⱼ.
    pub fn at(&self, eta: &[f64], dof: usize) -> f64 {
        self.shapes.iter().zip(eta).map(|(phi, e)| phi[dof] * e).sum()
    }

    /// The number of modes kept.
    pub fn modes(&self) -> usize {
        self.shapes.len()
    }

    /// The free DOFs the modes span.
    pub fn dofs(&self) -> usize {
        self.shapes.first().map_or(0, Vec::len)
    }
}
