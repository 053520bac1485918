//! The fixed interactions' rows packed four entries at a time ([`BlockRows`]) for the products a step repeats over
//! all of them — U = H v twice a step, and g₀ + H q and H v_k in the update phase of a soil's sections — where each
//! row's own product would test its shape first. Built only where the packed product is the row's own to the bit:
//! every fixed row short (at most four entries) and on consecutive DOFs; the sum is h₀x_f + h₁x_{f+1} + h₂x_{f+2} +
//! h₃x_{f+3} left to right, as [`friction::InteractionRow::dot`] forms it.

use banded::BlockRows;
use friction::{InteractionRow, InteractionSet};

/// `rows` packed four entries at a time, so that [`BlockRows::mul`] gives each row's [`InteractionRow::dot`] to the
/// bit; None unless each row is short (at most four entries) and on consecutive DOFs.
pub fn pack_rows<'a>(rows: impl ExactSizeIterator<Item = &'a InteractionRow> + Clone) -> Option<BlockRows> {
    if rows.len() == 0 || !rows.clone().all(|r| r.is_local() && r.len() <= 4) {
        return None;
    }
    let mut block = BlockRows::with_capacity(rows.len());
    for row in rows {
        block.push(row.dofs()[0], row.values());
    }
    Some(block)
}

/// The packed fixed rows and the update phase's scratch products.
#[derive(Debug, Clone)]
pub(super) struct FixedRows {
    rows: BlockRows,
    /// Whether every fixed law has a gap (a soil's or a stop's sections): the update phase then takes H q and H v_k
    /// of every row, packed.
    pub(super) all_gaps: bool,
    /// H q of the update phase.
    pub(super) at_q: Vec<f64>,
    /// H v_k (or the scheme's start velocity) of the update phase.
    pub(super) at_start: Vec<f64>,
    /// H v_k where the start velocity is not v_k.
    pub(super) at_v: Vec<f64>,
}

impl FixedRows {
    /// The first `fixed` rows of `set` packed; None unless each is short and on consecutive DOFs.
    pub(super) fn new(set: &InteractionSet, fixed: usize) -> Option<Self> {
        let block = pack_rows(set.rows()[..fixed].iter())?;
        let all_gaps = set.laws()[..fixed].iter().all(|law| law.gap().is_some());
        let scratch = vec![0.0; if all_gaps { fixed } else { 0 }];
        Some(Self { rows: block, all_gaps, at_q: scratch.clone(), at_start: scratch.clone(), at_v: scratch })
    }

    /// out_j = H_j x over the fixed rows.
    pub(super) fn mul(&self, x: &[f64], out: &mut [f64]) {
        self.rows.mul(x, out);
    }

    /// The update phase's products at (q, start, v): H q and H start into the scratch, H v too unless `same`.
    pub(super) fn update_products(&mut self, q: &[f64], start: &[f64], v: &[f64], same: bool) {
        self.rows.mul(q, &mut self.at_q);
        self.rows.mul(start, &mut self.at_start);
        if !same {
            self.rows.mul(v, &mut self.at_v);
        }
    }
}
