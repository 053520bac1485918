//! Rows of a sparse matrix H with at most four nonzeros each, in consecutive columns — the contact rows of Hermite
//! beam elements (a section's deflection w(x) = N(x)·q_e touches the four DOFs of its element) — and the three
//! products an interior-point iteration repeats on them:
//!
//! ```text
//! H x,    Hᵀ s,    A + Hᵀ diag(d) H   (A banded with half-bandwidth 3, and so is the sum)
//! ```
//!
//! Each row is kept as `[0, 0, 0, h₀, h₁, h₂, h₃]` (zero-padded to four entries, three leading zeros), so that every
//! piece of a row the products need is one 4-wide slice: row k adds s_k·(h₀…h₃) to entries f…f+3 of Hᵀs
//! (f = first_k), and (d_k h_a)·(h_{a−3}…h_a) — the slice starting at a — to the band row f + a of the sum, whose
//! four slots are the columns f + a − 3 … f + a. The terms and their order are those of an entry-by-entry scatter
//! (row after row, each entry computed as (d·h_a)·h_c), so the results are the same to the bit; the slots a scatter
//! would skip receive exact zeros.
//!
//! A row may also skip columns ([`BlockRows::push_entries`]: up to four entries within the band — a rail element's
//! four DOFs with its sleeper's DOF numbered between them). Once one such row is there, the three products take
//! each row's columns one by one (the Gram sum through [`SymmetricBanded::add_outer`]).

use crate::symmetric::SymmetricBanded;

/// Rows of H, each with up to four nonzeros, in consecutive columns or (see [`BlockRows::push_entries`]) spread
/// within the band.
#[derive(Debug, Clone, Default)]
pub struct BlockRows {
    /// First column of each row.
    first: Vec<usize>,
    /// Entries of each row: three zeros, then the entries zero-padded to four.
    padded: Vec<[f64; 7]>,
    /// Number of entries of each row.
    lens: Vec<usize>,
    /// Column of each entry after the row's first (0, 1, 2, 3 for a consecutive row).
    offsets: Vec<[usize; 4]>,
    /// Whether some row skips a column (the products then go entry by entry).
    spread: bool,
    /// The rows grouped into blocks of up to four consecutive rows that start in the same column (a soil's or a
    /// ballast's sections of one element): H x and Hᵀ s take the block's four columns of x or of the sum once.
    blocks: Vec<Block>,
}

/// Up to four consecutive rows starting in column `first`: `columns[c][r]` is entry c of row `row + r` (zero past
/// `len` rows and past a row's entries).
#[derive(Debug, Clone, Copy)]
struct Block {
    first: usize,
    row: usize,
    len: usize,
    columns: [[f64; 4]; 4],
}

/// The offsets of a consecutive row.
const CONSECUTIVE: [usize; 4] = [0, 1, 2, 3];

impl BlockRows {
    /// Room for `rows` rows, so that refilling allocates nothing.
    pub fn with_capacity(rows: usize) -> Self {
        Self {
            first: Vec::with_capacity(rows),
            padded: Vec::with_capacity(rows),
            lens: Vec::with_capacity(rows),
            offsets: Vec::with_capacity(rows),
            spread: false,
            blocks: Vec::with_capacity(rows),
        }
    }

    /// Remove every row.
    pub fn clear(&mut self) {
        self.first.clear();
        self.padded.clear();
        self.lens.clear();
        self.offsets.clear();
        self.spread = false;
        self.blocks.clear();
    }

    /// Append a row whose entries `values` (at most four) sit in columns first, first + 1, ….
    pub fn push(&mut self, first: usize, values: &[f64]) {
        assert!(values.len() <= 4, "BlockRows::push: {} entries, at most 4", values.len());
        let mut padded = [0.0; 7];
        padded[3..3 + values.len()].copy_from_slice(values);
        let row = self.first.len();
        self.first.push(first);
        self.padded.push(padded);
        self.lens.push(values.len());
        self.offsets.push(CONSECUTIVE);
        let block = match self.blocks.last_mut().filter(|b| b.first == first && b.len < 4) {
            Some(block) => block,
            None => {
                self.blocks.push(Block { first, row, len: 0, columns: [[0.0; 4]; 4] });
                self.blocks.last_mut().expect("just pushed")
            }
        };
        for (column, &h) in block.columns.iter_mut().zip(values) {
            column[block.len] = h;
        }
        block.len += 1;
    }

    /// Append a row with entries `values` (at most four) in the ascending `columns`, which may skip columns; it must
    /// lie within the band of the matrices [`BlockRows::weighted_gram_into`] is given.
    pub fn push_entries(&mut self, columns: &[usize], values: &[f64]) {
        assert_eq!(columns.len(), values.len(), "BlockRows::push_entries: one column per entry");
        let Some(&first) = columns.first() else {
            return self.push(0, &[]);
        };
        self.push(first, values);
        let mut offsets = CONSECUTIVE;
        for (offset, &column) in offsets.iter_mut().zip(columns) {
            assert!(column >= first, "BlockRows::push_entries: columns ascend");
            *offset = column - first;
        }
        self.spread |= offsets[..columns.len()] != CONSECUTIVE[..columns.len()];
        *self.offsets.last_mut().expect("the row just pushed") = offsets;
    }

    /// The columns and entries of row k, one by one.
    fn entries(&self, k: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let (first, h) = (self.first[k], &self.padded[k]);
        self.offsets[k][..self.lens[k]].iter().zip(&h[3..]).map(move |(&offset, &h)| (first + offset, h))
    }

    /// out_k = H_k·x = h₀x_f + h₁x_{f+1} + h₂x_{f+2} + h₃x_{f+3} (f = first_k, summed left to right; the padding's
    /// zeros where a row has fewer than four entries). A row whose four slots reach past the end of `x` sums its own
    /// entries from zero instead.
    #[inline(always)]
    pub fn mul(&self, x: &[f64], out: &mut [f64]) {
        let by_entries = |k: usize| self.entries(k).fold(0.0, |sum, (column, h)| sum + h * x[column]);
        if self.spread {
            for (k, o) in out.iter_mut().enumerate().take(self.first.len()) {
                *o = by_entries(k);
            }
            return;
        }
        if self.blocks.len() == self.first.len() {
            // Every row alone in its block (sections on nodes, devices): each row's own sum, in the same order —
            // the four-row block's sixteen products would be three quarters zeros.
            for block in &self.blocks {
                let Some(o) = out.get_mut(block.row) else { break };
                *o = match x.get(block.first..block.first + 4) {
                    Some(&[x0, x1, x2, x3]) => {
                        let c = &block.columns;
                        let mut y = c[0][0] * x0;
                        y += c[1][0] * x1;
                        y += c[2][0] * x2;
                        y += c[3][0] * x3;
                        y
                    }
                    _ => by_entries(block.row),
                };
            }
            return;
        }
        for block in &self.blocks {
            let Some(out) = out.get_mut(block.row..block.row + block.len) else { break };
            match x.get(block.first..block.first + 4) {
                Some(&[x0, x1, x2, x3]) => {
                    // Column after column into the four rows' sums: h₀x_f + h₁x_{f+1} + … in each, packed.
                    let c = &block.columns;
                    let mut y = c[0].map(|h| h * x0);
                    for (column, x) in c[1..].iter().zip([x1, x2, x3]) {
                        for (y, h) in y.iter_mut().zip(column) {
                            *y += h * x;
                        }
                    }
                    match <&mut [f64; 4]>::try_from(&mut *out) {
                        Ok(whole) => *whole = y,
                        Err(_) => out.iter_mut().zip(y).for_each(|(o, y)| *o = y),
                    }
                }
                _ => out.iter_mut().enumerate().for_each(|(r, o)| *o = by_entries(block.row + r)),
            }
        }
    }

    /// out = Hᵀ s, summed from zero row after row. `out` needs three entries past the last column a row can start
    /// in; they receive s_k·0.
    #[inline(always)]
    pub fn transpose_mul(&self, s: &[f64], out: &mut [f64]) {
        out.iter_mut().for_each(|x| *x = 0.0);
        if self.spread {
            for (k, &s) in s.iter().enumerate() {
                self.entries(k).for_each(|(column, h)| out[column] += s * h);
            }
            return;
        }
        for block in &self.blocks {
            // A block's rows one after the other into the four sums held apart (the additions of a row-by-row
            // scatter, in its order), stored entry by entry: rows of neighbouring elements overlap by two entries,
            // and a packed store followed by a packed load that overlaps it only in part stalls store-to-load
            // forwarding (measured: those two instructions took 25 % of the interior point's samples).
            let out = &mut out[block.first..block.first + 4];
            let mut sums = [out[0], out[1], out[2], out[3]];
            for (r, &s) in s[block.row..block.row + block.len].iter().enumerate() {
                for (sum, column) in sums.iter_mut().zip(&block.columns) {
                    *sum += s * column[r];
                }
            }
            for (o, sum) in out.iter_mut().zip(sums) {
                *o = sum;
            }
        }
    }

    /// out = base + Hᵀ diag(d) H: entry (f + a, f + c), c ≤ a, adds (d_k·h_a)·h_c row after row onto base's entry
    /// — what [`SymmetricBanded::add_outer`] row after row adds, to the bit. Every row must lie inside the matrix
    /// and within its band. Half-bandwidth 3 (every Hermite beam) takes the packed path described in the module
    /// documentation.
    #[inline(always)]
    pub fn weighted_gram_into(&self, base: &SymmetricBanded, d: &[f64], out: &mut SymmetricBanded) {
        out.copy_from(base);
        if base.bandwidth() != 3 || self.spread {
            let mut dofs = [0; 4];
            for (k, (&d, h)) in d.iter().zip(&self.padded).enumerate() {
                let len = self.lens[k];
                for (dof, (column, _)) in dofs.iter_mut().zip(self.entries(k)) {
                    *dof = column;
                }
                out.add_outer(&dofs[..len], &h[3..3 + len], d);
            }
            return;
        }
        let n = out.order();
        let band = out.lower_band_mut();
        for ((&d, &first), h) in d.iter().zip(&self.first).zip(&self.padded) {
            let weighted = [d * h[3], d * h[4], d * h[5], d * h[6]];
            if first + 4 <= n {
                // Sixteen slots known at compile time: the four band rows unroll into packed operations.
                let block: &mut [f64; 16] = (&mut band[4 * first..4 * first + 16]).try_into().expect("16 slots");
                add_windows(block, h, &weighted);
            } else {
                // A row at the end of the matrix: band rows past the order take no entries (its trailing h are 0).
                debug_assert!(h[3 + n - first..].iter().all(|&x| x == 0.0), "BlockRows: a row reaches past the matrix");
                add_windows(&mut band[4 * first..4 * n], h, &weighted);
            }
        }
    }
}

/// Band row a of `block` (four slots each) += weighted_a · h[a..a + 4], for as many rows as `block` holds.
#[inline(always)]
fn add_windows(block: &mut [f64], h: &[f64; 7], weighted: &[f64; 4]) {
    for (a, row) in block.chunks_exact_mut(4).enumerate() {
        let row: &mut [f64; 4] = row.try_into().expect("four slots");
        let window: &[f64; 4] = h[a..a + 4].try_into().expect("four entries");
        let terms = window.map(|h| weighted[a] * h);
        for slot in 0..4 {
            row[slot] += terms[slot];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows like those of distributed friction on a few Hermite elements (five sections per element, the end rows
    /// short as at a support), with arbitrary entries.
    fn rows(n: usize) -> (BlockRows, Vec<(usize, Vec<f64>)>) {
        let mut list = vec![(0, vec![0.7, -0.2])];
        let mut first = 0;
        while first + 4 <= n {
            for s in 0..5 {
                let t = s as f64 * 0.25 + 0.1 * first as f64;
                list.push((first, vec![t.sin(), 0.3 * t.cos(), 1.0 - t.sin(), -0.2 * t]));
            }
            first += 2;
        }
        list.push((n - 3, vec![0.4, 0.1, -0.5]));
        let mut block = BlockRows::with_capacity(list.len());
        for (f, v) in &list {
            block.push(*f, v);
        }
        (block, list)
    }

    fn base(n: usize) -> SymmetricBanded {
        let mut a = SymmetricBanded::zeros(n, 3);
        for i in 0..n {
            a.add(i, i, 4.0 + i as f64);
            for k in 1..=3.min(i) {
                a.add(i, i - k, 0.1 * (i * k) as f64 - 0.5);
            }
        }
        a
    }

    #[test]
    fn products_by_entry_match_row_by_row_scatters_to_the_bit() {
        let n = 13;
        let (block, list) = rows(n);
        let m = list.len();
        let x: Vec<f64> = (0..n + 3).map(|i| if i < n { (0.37 * i as f64).cos() } else { 0.0 }).collect();
        let s: Vec<f64> = (0..m).map(|k| (1.3 * k as f64).sin() * 1e3).collect();
        let mut hx = vec![0.0; m];
        block.mul(&x, &mut hx);
        // Without the padding past the last column, the rows that reach past it sum their own entries: same bits.
        let mut unpadded = vec![0.0; m];
        block.mul(&x[..n], &mut unpadded);
        assert_eq!(
            hx.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            unpadded.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        );
        let mut hts = vec![f64::NAN; n + 3];
        block.transpose_mul(&s, &mut hts);
        let mut gram = SymmetricBanded::zeros(n, 3);
        block.weighted_gram_into(&base(n), &s, &mut gram);
        let mut scattered_hts = vec![0.0; n + 3];
        let mut scattered_gram = base(n);
        for (k, (f, v)) in list.iter().enumerate() {
            let mut padded = [0.0; 4];
            padded[..v.len()].copy_from_slice(v);
            let expected = padded[0] * x[*f] + padded[1] * x[f + 1] + padded[2] * x[f + 2] + padded[3] * x[f + 3];
            assert_eq!(hx[k].to_bits(), expected.to_bits(), "H x, row {k}");
            for (a, h) in padded.iter().enumerate() {
                scattered_hts[f + a] += s[k] * h;
            }
            scattered_gram.add_outer(&(*f..f + v.len()).collect::<Vec<_>>(), v, s[k]);
        }
        for i in 0..n {
            assert_eq!(hts[i].to_bits(), scattered_hts[i].to_bits(), "Hᵀs, entry {i}");
            for j in i.saturating_sub(3)..=i {
                let (got, want) = (gram.get(i, j), scattered_gram.get(i, j));
                assert_eq!(got.to_bits(), want.to_bits(), "gram ({i}, {j}): {got} vs {want}");
            }
        }
        assert!(hts[n..].iter().all(|&x| x == 0.0), "padding past the columns stays zero");
    }

    /// Every row alone in its block (one section a node: w's single entry, two DOFs apart; the last row's slots
    /// reaching past x): H x takes the one-row path, each row's h₀x_f + h₁x_{f+1} + … to the bit, padded or not.
    #[test]
    fn rows_alone_in_their_blocks_are_their_own_sums() {
        let n = 12;
        let mut block = BlockRows::with_capacity(6);
        let list: Vec<(usize, Vec<f64>)> =
            (0..6).map(|k| (2 * k, vec![1.0 + 0.1 * k as f64, if k % 2 == 0 { 0.0 } else { -0.3 }])).collect();
        for (f, v) in &list {
            block.push(*f, v);
        }
        let x: Vec<f64> = (0..n + 3).map(|i| if i < n { (0.41 * i as f64).sin() } else { 0.0 }).collect();
        let (mut padded_out, mut unpadded) = (vec![0.0; 6], vec![0.0; 6]);
        block.mul(&x, &mut padded_out);
        block.mul(&x[..n], &mut unpadded);
        for (k, (f, v)) in list.iter().enumerate() {
            let mut h = [0.0; 4];
            h[..v.len()].copy_from_slice(v);
            let expected = h[0] * x[*f] + h[1] * x[f + 1] + h[2] * x[f + 2] + h[3] * x[f + 3];
            assert_eq!(padded_out[k].to_bits(), expected.to_bits(), "row {k}");
            assert_eq!(unpadded[k].to_bits(), expected.to_bits(), "row {k} without the padding");
        }
    }

    /// Rows skipping a column (a rail element's four DOFs with a sleeper's between them, half-bandwidth 4) beside
    /// consecutive ones: the three products are those of an entry-by-entry scatter, to the bit.
    #[test]
    fn rows_that_skip_a_column_take_the_entry_by_entry_products() {
        let n = 16;
        let mut block = BlockRows::with_capacity(8);
        let mut list: Vec<(Vec<usize>, Vec<f64>)> = Vec::new();
        for (k, first) in [0, 3, 3, 6, 9, 11].into_iter().enumerate() {
            let t = 0.7 * k as f64;
            let columns =
                if k == 1 { vec![first, first + 1, first + 2] } else { vec![first, first + 1, first + 3, first + 4] };
            let values: Vec<f64> = (0..columns.len()).map(|a| (t + a as f64).sin()).collect();
            block.push_entries(&columns, &values);
            list.push((columns, values));
        }
        let mut base = SymmetricBanded::zeros(n, 4);
        (0..n).for_each(|i| base.add(i, i, 3.0 + i as f64));
        let x: Vec<f64> = (0..n + 3).map(|i| if i < n { (0.37 * i as f64).cos() } else { 0.0 }).collect();
        let s: Vec<f64> = (0..list.len()).map(|k| 1.0 + k as f64).collect();
        let (mut hx, mut hts, mut gram) = (vec![0.0; list.len()], vec![0.0; n + 3], SymmetricBanded::zeros(n, 4));
        block.mul(&x, &mut hx);
        block.transpose_mul(&s, &mut hts);
        block.weighted_gram_into(&base, &s, &mut gram);
        let (mut scattered_hts, mut scattered_gram) = (vec![0.0; n + 3], base.clone());
        for (k, (columns, values)) in list.iter().enumerate() {
            let expected = columns.iter().zip(values).fold(0.0, |sum, (&c, h)| sum + h * x[c]);
            assert_eq!(hx[k].to_bits(), expected.to_bits(), "H x, row {k}");
            columns.iter().zip(values).for_each(|(&c, h)| scattered_hts[c] += s[k] * h);
            scattered_gram.add_outer(columns, values, s[k]);
        }
        assert_eq!(hts, scattered_hts);
        for i in 0..n {
            for j in i.saturating_sub(4)..=i {
                assert_eq!(gram.get(i, j).to_bits(), scattered_gram.get(i, j).to_bits(), "gram ({i}, {j})");
            }
        }
    }
}
