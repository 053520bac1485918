//! The equations of the stationary wave made affine by its sets (docs/theory.md §14): the soil's force and the
//! ballast's friction are piecewise affine in W, so for the sets of a W — the sections pressed into the soil, each
//! friction section slipping or stuck and to which anchor — the equations are linear. Their residual, their matrix
//! factored, and their solution are what the Newton iteration ([`crate::newton`]) and the path search
//! ([`crate::path_search`]) both step with.

use crate::error::Result;
use crate::friction::{AnchorCoupling, FrictionSection, FrictionState};
use crate::operator::{MovingFrame, factor};
use crate::rows::row_add;
use banded::general::{GeneralBanded, GeneralLu};

/// The sets that make the soil's and the ballast's forces affine near W: the soil sections pressed into it, and
/// each friction section slipping or stuck (and to which anchor).
pub(crate) struct Sets {
    pub(crate) pressed: Vec<bool>,
    pub(crate) friction: Option<FrictionState>,
}

impl Sets {
    /// Whether `other` has the same pressed sections and the same friction states.
    pub(crate) fn same_as(&self, other: &Sets) -> bool {
        self.pressed == other.pressed
            && self.friction.as_ref().map(|f| &f.states) == other.friction.as_ref().map(|f| &f.states)
    }

    pub(crate) fn of(frame: &MovingFrame, w: &[f64]) -> Self {
        Self {
            pressed: frame.sections.iter().map(|s| s.deflection(w) < 0.0).collect(),
            friction: frame.friction.as_ref().map(|f| f.march(w)),
        }
    }
}

/// The equations of a [`MovingFrame`] made affine by `sets`, factored: the banded matrix with the pressed springs and
/// stuck Jenkins springs, less each stick segment's rank-one coupling to its anchor, solved by
/// Sherman–Morrison–Woodbury: W = y + Z (I − VᵀZ)⁻¹ Vᵀy with y = B⁻¹g, Z = B⁻¹U, V the anchors' rows.
pub(crate) struct SetSystem {
    lu: GeneralLu,
    /// Z's columns and the anchors' sections, with (I − VᵀZ) factored; none without couplings.
    couplings: Option<(Vec<Vec<f64>>, Vec<FrictionSection>, GeneralLu)>,
    /// The right-hand side of the sets' equations: the loads less the friction forces that do not depend on W (N).
    pub(crate) rhs: Vec<f64>,
}

impl SetSystem {
    pub(crate) fn new(frame: &MovingFrame, sets: &Sets, speed: f64) -> Result<Self> {
        let mut matrix = frame.with_pressed(&sets.pressed);
        let mut rhs = frame.rhs.clone();
        let (couplings, sections) = match (&frame.friction, &sets.friction) {
            (Some(friction), Some(state)) => (friction.linearise(state, &mut matrix, &mut rhs), &friction.sections[..]),
            _ => (Vec::new(), &[][..]),
        };
        let lu = factor(matrix, speed)?;
        if couplings.is_empty() {
            return Ok(Self { lu, couplings: None, rhs });
        }
        let k = couplings.len();
        let mut z = Vec::with_capacity(k);
        let mut anchors = Vec::with_capacity(k);
        for AnchorCoupling { mut column, anchor } in couplings {
            lu.solve_in_place(&mut column);
            z.push(column);
            anchors.push(sections[anchor]);
        }
        let mut small = GeneralBanded::zeros(k, k - 1, k - 1);
        for (j, anchor) in anchors.iter().enumerate() {
            for (m, column) in z.iter().enumerate() {
                small.add(j, m, if j == m { 1.0 } else { 0.0 } - anchor.deflection(column));
            }
        }
        let small = factor(small, speed)?;
        Ok(Self { lu, couplings: Some((z, anchors, small)), rhs })
    }

    /// `b` replaced by the solution of the sets' equations with right-hand side `b`.
    pub(crate) fn solve_in_place(&self, b: &mut [f64]) {
        self.lu.solve_in_place(b);
        if let Some((z, anchors, small)) = &self.couplings {
            let mut c: Vec<f64> = anchors.iter().map(|a| a.deflection(b)).collect();
            small.solve_in_place(&mut c);
            for (column, c) in z.iter().zip(&c) {
                b.iter_mut().zip(column).for_each(|(y, z)| *y += c * z);
            }
        }
    }
}

/// r = A W − Σ H_sᵀ k_s⟨−H_s W⟩₊ + Σ_i weight_i H_iᵀ r_i − f (N), the friction forces r_i given (those of the
/// march at W for the residual; none without friction).
pub(crate) fn residual(frame: &MovingFrame, w: &[f64], friction_force: Option<&[f64]>) -> Vec<f64> {
    let mut r = vec![0.0; w.len()];
    frame.matrix.mul_vec(w, &mut r);
    for s in &frame.sections {
        row_add(s.element, &s.row, -s.stiffness * (-s.deflection(w)).max(0.0), &mut r);
    }
    if let (Some(friction), Some(force)) = (&frame.friction, friction_force) {
        friction.add_forces(force, &mut r);
    }
    r.iter_mut().zip(&frame.rhs).for_each(|(r, f)| *r -= f);
    r
}
