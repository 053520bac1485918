//! End supports and the map between full nodal DOFs and the free DOFs that remain after supports.
//!
//! Supports are imposed by removing DOFs: `Pinned` removes w at that end, `Clamped` removes w and θ, `Free`
//! removes nothing. Full DOFs are ordered (w₀, θ₀, w₁, θ₁, …, w_n, θ_n); free DOFs keep that order, so the
//! assembled matrices keep half-bandwidth 3.

/// Boundary condition at one end of the beam.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum Support {
    /// w = 0, rotation free (the default, docs/theory.md §2).
    #[default]
    Pinned,
    /// w = 0 and θ = 0.
    Clamped,
    /// No constraint.
    Free,
}

impl Support {
    /// Its name in scenario files and messages: "pinned", "clamped" or "free".
    pub fn name(self) -> &'static str {
        match self {
            Support::Pinned => "pinned",
            Support::Clamped => "clamped",
            Support::Free => "free",
        }
    }

    /// The DOFs it holds at its node (0: free, 1: w, 2: w and θ).
    pub fn held(self) -> usize {
        let (w, theta) = self.constrains();
        usize::from(w) + usize::from(theta)
    }

    /// (w constrained, θ constrained).
    fn constrains(self) -> (bool, bool) {
        match self {
            Support::Pinned => (true, false),
            Support::Clamped => (true, true),
            Support::Free => (false, false),
        }
    }
}

/// Supports at both ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(default, deny_unknown_fields))]
pub struct Supports {
    /// Support at x = 0. Default pinned.
    pub left: Support,
    /// Support at x = L. Default pinned.
    pub right: Support,
}

impl Supports {
    /// The same support at both ends.
    pub fn both(support: Support) -> Self {
        Self { left: support, right: support }
    }
}

/// Index map between the full nodal DOFs and the free (unconstrained) DOFs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DofMap {
    free_of_full: Vec<Option<usize>>,
    full_of_free: Vec<usize>,
    /// The rail's full DOFs, 2·nodes; sleeper s's are the next `per_sleeper`, from `rail + per_sleeper·s`.
    rail: usize,
    /// DOFs per sleeper: 1 (z) or 2 (z, and y of a ballast body).
    per_sleeper: usize,
    /// Where an embankment beam under the ballast has its full DOFs (w_e, θ_e per node, after the sleepers'), if any.
    embankment: Option<usize>,
}

impl DofMap {
    /// The map for a mesh with `nodes` nodes and the given end supports.
    pub fn new(nodes: usize, supports: Supports) -> Self {
        let full = 2 * nodes;
        let mut constrained = vec![false; full];
        let (lw, lt) = supports.left.constrains();
        let (rw, rt) = supports.right.constrains();
        constrained[0] = lw;
        constrained[1] = lt;
        constrained[full - 2] |= rw;
        constrained[full - 1] |= rt;
        let mut free_of_full = vec![None; full];
        let mut full_of_free = Vec::with_capacity(full);
        for (dof, &c) in constrained.iter().enumerate() {
            if !c {
                free_of_full[dof] = Some(full_of_free.len());
                full_of_free.push(dof);
            }
        }
        Self { free_of_full, full_of_free, rail: full, per_sleeper: 1, embankment: None }
    }

    /// The map with `per_sleeper` DOFs (1: the sleeper's z; 2: z and the ballast body's y under it) under each of
    /// `sleeper_nodes` (increasing): full DOFs from 2·nodes + per_sleeper·s for sleeper s after the rail's, free
    /// DOFs numbered node by node — the rail's w, θ, then the sleeper's — so that a sleeper sits in the band beside
    /// its rail node (half-bandwidth 3 + per_sleeper).
    pub fn with_sleepers(nodes: usize, supports: Supports, sleeper_nodes: &[usize], per_sleeper: usize) -> Self {
        Self::with_track(nodes, supports, sleeper_nodes, per_sleeper, false)
    }

    /// [`Self::with_sleepers`], and where `embankment` an embankment beam under the ballast (docs/theory.md §19):
    /// its w_e, θ_e per node full DOFs after the sleepers', held at the ends as the rail is, numbered after each
    /// node's rail and sleeper DOFs (half-bandwidth 5 + per_sleeper: a rail element spans its first node's block
    /// and its second's θ).
    pub fn with_track(
        nodes: usize,
        supports: Supports,
        sleeper_nodes: &[usize],
        per_sleeper: usize,
        embankment: bool,
    ) -> Self {
        let rail = Self::new(nodes, supports);
        let below = rail.rail + per_sleeper * sleeper_nodes.len();
        let full = below + if embankment { 2 * nodes } else { 0 };
        let mut free_of_full = vec![None; full];
        let mut full_of_free = Vec::with_capacity(full);
        let mut number = |dof: usize| {
            free_of_full[dof] = Some(full_of_free.len());
            full_of_free.push(dof);
        };
        let mut next_sleeper = 0;
        for node in 0..nodes {
            let held = |dof: usize| rail.free_of_full[dof].is_none();
            [2 * node, 2 * node + 1].into_iter().filter(|&d| !held(d)).for_each(&mut number);
            while next_sleeper < sleeper_nodes.len() && sleeper_nodes[next_sleeper] == node {
                (rail.rail + per_sleeper * next_sleeper..rail.rail + per_sleeper * (next_sleeper + 1))
                    .for_each(&mut number);
                next_sleeper += 1;
            }
            if embankment {
                [0, 1].into_iter().filter(|&k| !held(2 * node + k)).for_each(|k| number(below + 2 * node + k));
            }
        }
        Self { free_of_full, full_of_free, rail: rail.rail, per_sleeper, embankment: embankment.then_some(below) }
    }

    /// The free DOF z of sleeper `s` of a map [`DofMap::with_sleepers`] made (a sleeper's DOF is never held).
    pub fn sleeper(&self, s: usize) -> usize {
        self.free_of_full[self.rail + self.per_sleeper * s].expect("a sleeper's DOF is free")
    }

    /// The free DOF y of the ballast body under sleeper `s`, where the map has one.
    pub fn ballast_body(&self, s: usize) -> Option<usize> {
        (self.per_sleeper == 2).then(|| self.free_of_full[self.rail + 2 * s + 1].expect("a ballast DOF is free"))
    }

    /// The free DOF under sleeper `s`'s ballast, on `node`: its ballast body's y, else the embankment's w_e at that
    /// node (None where the ballast stands on rigid ground, or a support holds w_e).
    pub fn under_ballast(&self, s: usize, node: usize) -> Option<usize> {
        self.ballast_body(s).or_else(|| self.embankment.and_then(|below| self.free_of_full[below + 2 * node]))
    }

    /// Free index of each of the embankment's element `e`'s four DOFs (w_e,a, θ_e,a, w_e,b, θ_e,b), None where a
    /// support holds it — or None throughout without an embankment.
    pub fn embankment_element_free(&self, e: usize) -> [Option<usize>; 4] {
        std::array::from_fn(|k| self.embankment.and_then(|below| self.free_of_full[below + 2 * e + k]))
    }

    /// The full index of the embankment's first DOF (w_e at node 0), if the map has an embankment.
    pub fn embankment_start(&self) -> Option<usize> {
        self.embankment
    }

    /// Number of full DOFs: 2·(n_e + 1) of the rail, and those of the sleepers (and embankment) after them.
    pub fn full_len(&self) -> usize {
        self.free_of_full.len()
    }

    /// Number of free DOFs.
    pub fn free_len(&self) -> usize {
        self.full_of_free.len()
    }

    /// Free index of a full DOF (None if constrained).
    pub fn free_index(&self, full_dof: usize) -> Option<usize> {
        self.free_of_full[full_dof]
    }

    /// Free index of each of element `e`'s four DOFs (w_a, θ_a, w_b, θ_b), None where a support holds it.
    pub fn element_free(&self, e: usize) -> [Option<usize>; 4] {
        std::array::from_fn(|k| self.free_of_full[2 * e + k])
    }

    /// Full index of each free DOF, in order.
    pub fn full_indices(&self) -> &[usize] {
        &self.full_of_free
    }

    /// Scatter a free-DOF vector into a full one (constrained DOFs = 0).
    pub fn expand_into(&self, free: &[f64], full: &mut [f64]) {
        full.iter_mut().for_each(|v| *v = 0.0);
        for (k, &dof) in self.full_of_free.iter().enumerate() {
            full[dof] = free[k];
        }
    }

    /// Scatter a free-DOF vector into a new full one.
    pub fn expand(&self, free: &[f64]) -> Vec<f64> {
        let mut full = vec![0.0; self.full_len()];
        self.expand_into(free, &mut full);
        full
    }

    /// Gather the free DOFs of a full vector.
    pub fn reduce(&self, full: &[f64]) -> Vec<f64> {
        self.full_of_free.iter().map(|&d| full[d]).collect()
    }
}
