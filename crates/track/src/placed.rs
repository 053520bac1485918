//! Interactions placed on the beam: the engine's [`InteractionSet`] — rows, laws, ledger kinds, all the engine
//! needs — with, for each interaction, where it acts on the beam (m) and what it is on the track. The records,
//! snapshots and reports of a run read the places; the engine never does.

use friction::{InteractionKind, InteractionRow, InteractionSet, Law};

/// What a placed interaction is on the track.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SectionKind {
    /// A discrete friction device (FDD) on a node.
    Device,
    /// A section of friction distributed in the ballast.
    Ballast,
    /// A section of a foundation that cannot pull (a unilateral support).
    Foundation,
    /// The ballast under a sleeper that cannot pull (tensionless, or voided by a gap).
    SleeperBallast,
    /// Coulomb friction between a sleeper and the ballast.
    SleeperFriction,
}

impl SectionKind {
    /// The energy ledger's account for this kind's work.
    pub fn ledger_kind(self) -> InteractionKind {
        match self {
            Self::Device | Self::Ballast | Self::SleeperFriction => InteractionKind::Friction,
            Self::Foundation | Self::SleeperBallast => InteractionKind::Support,
        }
    }
}

/// Interactions at fixed places on the beam, in the order of the engine's set.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PlacedInteractions {
    interactions: InteractionSet,
    positions: Vec<f64>,
    kinds: Vec<SectionKind>,
    /// f₀ (N, over the beam's free DOFs; empty for none): the constant force that holds the interactions' forces at
    /// q = 0 in equilibrium — the self-weight a nonlinear foundation's sections carry (docs/theory.md §13).
    preload: Vec<f64>,
}

impl PlacedInteractions {
    /// None placed (no friction, no unilateral support).
    pub fn new() -> Self {
        Self::default()
    }

    /// Place an interaction of row H (over the beam's free DOFs) and `law` at `x` (m); a row on a support (empty)
    /// is dropped as [`InteractionSet::push`] drops it, with its place.
    pub fn push(&mut self, row: InteractionRow, law: Law, x: f64, kind: SectionKind) {
        if self.interactions.push(row, law, kind.ledger_kind()).is_some() {
            self.positions.push(x);
            self.kinds.push(kind);
        }
    }

    /// Append all interactions placed in `other`.
    pub fn extend(&mut self, other: PlacedInteractions) {
        self.interactions.extend(other.interactions);
        self.positions.extend(other.positions);
        self.kinds.extend(other.kinds);
        self.add_preload(&other.preload);
    }

    /// Whether interaction j is a void: a law with a positive gap, open at rest.
    fn is_void(&self, j: usize) -> bool {
        self.interactions.laws()[j].gap().is_some_and(|g| g > 0.0)
    }

    /// The same without its voids ([`Self::is_void`]): what holds the track at rest.
    pub(crate) fn without_voids(&self) -> Self {
        let mut kept = Self { preload: self.preload.clone(), ..Self::default() };
        for j in (0..self.len()).filter(|&j| !self.is_void(j)) {
            let (rows, laws) = (self.interactions.rows(), self.interactions.laws());
            kept.push(rows[j].clone(), laws[j], self.positions[j], self.kinds[j]);
        }
        kept
    }

    /// Move the gap of every law touching at rest (gap ≤ 0) to what its row reads in the state `q` (free DOFs):
    /// g → g + H q ([`Law::shifted`]); a void keeps its gap, measured in that state.
    pub(crate) fn shift_gaps(&mut self, q: &[f64]) {
        for j in 0..self.interactions.len() {
            if self.is_void(j) {
                continue;
            }
            let shift = self.interactions.rows()[j].dot(q);
            let law = self.interactions.law_mut(j);
            *law = law.shifted(shift);
        }
    }

    /// Add `force` (N, free DOFs) to the preload f₀.
    pub(crate) fn add_preload(&mut self, force: &[f64]) {
        if self.preload.len() < force.len() {
            self.preload.resize(force.len(), 0.0);
        }
        for (p, f) in self.preload.iter_mut().zip(force) {
            *p += f;
        }
    }

    /// f₀ (N, free DOFs of the beam; empty for none): the constant force a run adds to its loads so that q = 0 is the
    /// equilibrium the interactions were placed in.
    pub fn preload(&self) -> &[f64] {
        &self.preload
    }

    /// The engine's interactions.
    pub fn interactions(&self) -> &InteractionSet {
        &self.interactions
    }

    /// Number of interactions placed (kept).
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// Whether none is placed.
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// Where each interaction acts (m).
    pub fn positions(&self) -> &[f64] {
        &self.positions
    }

    /// What each interaction is.
    pub fn kinds(&self) -> &[SectionKind] {
        &self.kinds
    }

    /// Whether any placed law is a spring (a soil section, a sleeper's unilateral ballast): statics then needs
    /// [`crate::unilateral_statics::static_deflection`], K alone does not hold the track.
    pub fn has_springs(&self) -> bool {
        self.interactions.laws().iter().any(|law| law.linear_spring().is_some())
    }

    /// How many interactions of `kind` are placed.
    pub fn count(&self, kind: SectionKind) -> usize {
        self.kinds.iter().filter(|&&k| k == kind).count()
    }

    /// The index of the interaction at `x` within `tolerance` (m), if any (first match).
    pub fn section_at(&self, x: f64, tolerance: f64) -> Option<usize> {
        self.positions.iter().position(|&p| (p - x).abs() <= tolerance)
    }
}
