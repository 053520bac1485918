//! The linear semi-discrete system M q̈ + C q̇ + K q = F(t) + Hᵀr that the stepper integrates (docs/theory.md §3, §5).
//!
//! The engine knows no structure: a system is banded M, C, K over its DOFs, made from one block (a beam on its
//! foundation, a single-DOF oscillator) or stacked from several ([`LinearSystem::from_blocks`]: the beam and the few
//! DOFs of each vehicle), which interact only through the interactions' rows. A [`DofLayout`] says where each block's
//! DOFs sit.

use banded::SymmetricBanded;

/// Banded symmetric M (kg), C (N·s/m), K (N/m) over the system's DOFs.
#[derive(Debug, Clone)]
pub struct LinearSystem {
    /// Mass matrix, SPD.
    pub mass: SymmetricBanded,
    /// Damping matrix, symmetric positive semi-definite.
    pub damping: SymmetricBanded,
    /// Stiffness matrix, symmetric positive semi-definite.
    pub stiffness: SymmetricBanded,
}

/// Where the blocks of a stacked system sit: block b owns DOFs `offset(b) .. offset(b) + len(b)`.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct DofLayout {
    offsets: Vec<usize>,
    lengths: Vec<usize>,
}

impl DofLayout {
    /// Number of blocks.
    pub fn blocks(&self) -> usize {
        self.offsets.len()
    }

    /// First DOF of block `b`.
    pub fn offset(&self, block: usize) -> usize {
        self.offsets[block]
    }

    /// DOFs of block `b`.
    pub fn len(&self, block: usize) -> usize {
        self.lengths[block]
    }

    /// Whether the layout has no block.
    pub fn is_empty(&self) -> bool {
        self.offsets.is_empty()
    }

    /// The system DOF of DOF `local` of block `b`.
    pub fn dof(&self, block: usize, local: usize) -> usize {
        debug_assert!(local < self.lengths[block]);
        self.offsets[block] + local
    }
}

impl LinearSystem {
    /// A system of one block. The three matrices must have one order; they are brought to one bandwidth (the
    /// largest of theirs), which the iteration matrix M + hθC + h²θ²K needs.
    pub fn new(mass: SymmetricBanded, damping: SymmetricBanded, stiffness: SymmetricBanded) -> Self {
        assert!(
            mass.order() == damping.order() && mass.order() == stiffness.order(),
            "M, C and K of a system have one order"
        );
        let block = Self { mass, damping, stiffness };
        let uniform =
            [&block.mass, &block.damping, &block.stiffness].iter().all(|m| m.bandwidth() == block.mass.bandwidth());
        if uniform { block } else { Self::from_blocks(&[&block]).0 }
    }

    /// The blocks stacked along the diagonal, in order, and where each sits. The bandwidth is the largest of the
    /// blocks' (a small dense block beside a banded one keeps the band).
    pub fn from_blocks(blocks: &[&LinearSystem]) -> (Self, DofLayout) {
        let n = blocks.iter().map(|b| b.dofs()).sum();
        let bandwidth = blocks
            .iter()
            .flat_map(|b| [&b.mass, &b.damping, &b.stiffness])
            .map(SymmetricBanded::bandwidth)
            .max()
            .unwrap_or(0);
        let mut layout = DofLayout::default();
        let mut matrices = [(); 3].map(|_| SymmetricBanded::zeros(n, bandwidth));
        let mut offset = 0;
        for block in blocks {
            for (target, source) in matrices.iter_mut().zip([&block.mass, &block.damping, &block.stiffness]) {
                let w = source.bandwidth();
                for j in 0..source.order() {
                    for i in j..(j + w + 1).min(source.order()) {
                        let value = source.get(i, j);
                        if value != 0.0 {
                            target.add(offset + i, offset + j, value);
                        }
                    }
                }
            }
            layout.offsets.push(offset);
            layout.lengths.push(block.dofs());
            offset += block.dofs();
        }
        let [mass, damping, stiffness] = matrices;
        (Self { mass, damping, stiffness }, layout)
    }

    /// Number of DOFs.
    pub fn dofs(&self) -> usize {
        self.mass.order()
    }

    /// Whether C has any non-zero entry (skips the viscous terms otherwise).
    pub fn has_damping(&self) -> bool {
        (0..self.damping.order()).any(|i| self.damping.get(i, i) != 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn block(n: usize, bandwidth: usize, seed: f64) -> LinearSystem {
        let mut m = SymmetricBanded::zeros(n, bandwidth);
        for j in 0..n {
            for i in j..(j + bandwidth + 1).min(n) {
                m.add(i, j, if i == j { 10.0 + seed + j as f64 } else { seed * 0.1 + (i + j) as f64 * 0.01 });
            }
        }
        let mut k = m.clone();
        k.add(0, 0, seed);
        LinearSystem::new(m.clone(), SymmetricBanded::zeros(n, 0), k)
    }

    /// Stacked blocks: every entry of each block at its offset, nothing between blocks, the layout's offsets.
    #[test]
    fn blocks_stack_along_the_diagonal() {
        let (a, b) = (block(6, 3, 1.0), block(3, 2, 2.0));
        let (system, layout) = LinearSystem::from_blocks(&[&a, &b]);
        assert_eq!(system.dofs(), 9);
        assert_eq!(system.mass.bandwidth(), 3);
        assert_eq!((layout.blocks(), layout.offset(1), layout.len(1), layout.dof(1, 2)), (2, 6, 3, 8));
        let dense = system.stiffness.to_dense();
        for i in 0..9 {
            for j in 0..9 {
                let expected = match (i < 6, j < 6) {
                    (true, true) => a.stiffness.to_dense()[(i, j)],
                    (false, false) => b.stiffness.to_dense()[(i - 6, j - 6)],
                    _ => 0.0,
                };
                assert_eq!(dense[(i, j)], expected, "({i}, {j})");
            }
        }
        assert!(!system.has_damping());
    }
}
