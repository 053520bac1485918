//! Trains: axles and uniform load patches moving together (docs/theory.md §10), and the catalogue — the reference
//! case's single load and the ten Eurocode high-speed load models HSLM-A1 … A10 (EN 1991-2, Annex E).
//!
//! Offsets are measured backwards from the first axle: axle i is at x_i(t) = x_head(t) − d_i. Forces act downward.

use crate::discretisation::Discretisation;
use crate::error::{FemError, Result};
use crate::load::{ElementLoad, LoadVector};

/// One axle: its offset d ≥ 0 behind the first axle (m) and its static force P ≥ 0 (N, downward).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axle {
    /// Offset behind the first axle (m).
    pub offset: f64,
    /// Static force (N, downward).
    pub force: f64,
}

/// A uniform load patch: from `offset` behind the first axle, `length` long, of `intensity` (N/m, downward).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Patch {
    /// Offset of its front behind the first axle (m).
    pub offset: f64,
    /// Length (m).
    pub length: f64,
    /// Load per length (N/m, downward).
    pub intensity: f64,
}

/// A train: axles and patches at fixed offsets.
#[derive(Debug, Clone, PartialEq)]
pub struct Train {
    /// Name (a catalogue name, or what the user called it).
    pub name: String,
    /// The axles, in any order.
    pub axles: Vec<Axle>,
    /// The patches.
    pub patches: Vec<Patch>,
}

/// The HSLM-A parameters of EN 1991-2 Table E.1, as in docs/theory.md §10: number of intermediate coaches N, coach
/// length D (m), bogie axle spacing d (m), axle force P (N).
pub const HSLM_A: [(usize, f64, f64, f64); 10] = [
    (18, 18.0, 2.0, 170e3),
    (17, 19.0, 3.5, 200e3),
    (16, 20.0, 2.0, 180e3),
    (15, 21.0, 3.0, 190e3),
    (14, 22.0, 2.0, 170e3),
    (13, 23.0, 2.0, 180e3),
    (13, 24.0, 2.0, 190e3),
    (12, 25.0, 2.5, 190e3),
    (11, 26.0, 2.0, 210e3),
    (11, 27.0, 2.0, 210e3),
];

/// Largest number of axles or patches a train may have (the catalogue's longest has 50 axles).
pub const MAX_TRAIN_ITEMS: usize = 10_000;

impl Train {
    /// The names of the catalogue: `single` and `hslm-a1` … `hslm-a10`.
    pub fn catalogue() -> Vec<String> {
        std::iter::once("single".to_string()).chain((1..=10).map(|k| format!("hslm-a{k}"))).collect()
    }

    /// The train of the catalogue called `name` (`single`: one axle of `single_force` N, the reference case's load).
    pub fn named(name: &str, single_force: f64) -> Result<Self> {
        if name == "single" {
            return Ok(Self::single(single_force));
        }
        let k = name.strip_prefix("hslm-a").and_then(|k| k.parse::<usize>().ok()).filter(|k| (1..=10).contains(k));
        match k {
            Some(k) => Ok(Self::hslm_a(k)),
            None => Err(FemError::UnknownTrain { name: name.to_string(), known: Self::catalogue().join(", ") }),
        }
    }

    /// One axle of `force` (N).
    pub fn single(force: f64) -> Self {
        Self { name: "single".into(), axles: vec![Axle { offset: 0.0, force }], patches: Vec::new() }
    }

    /// HSLM-A`k` (k in 1..=10; panics otherwise — use [`Train::named`] for input) by the rule of docs/theory.md §10:
    /// power car axles at 0, 3, 14, 17 m; the end coach's bogie at 17 + 3.525 and 17 + 3.525 + d; N + 1
    /// articulated bogies centred at 17 + 3.525/2 + i·D (i = 1 … N + 1) with axles at ±d/2; the rear end coach and
    /// power car mirror the front about the middle of the articulated bogies. 2N + 14 axles of force P.
    pub fn hslm_a(k: usize) -> Self {
        let (coaches, coach, spacing, force) = HSLM_A[k - 1];
        let mut front = vec![0.0, 3.0, 14.0, 17.0, 17.0 + 3.525, 17.0 + 3.525 + spacing];
        let centre = |i: usize| 17.0 + 3.525 / 2.0 + i as f64 * coach;
        let mut bogies = Vec::with_capacity(2 * coaches + 2);
        for i in 1..=coaches + 1 {
            bogies.push(centre(i) - spacing / 2.0);
            bogies.push(centre(i) + spacing / 2.0);
        }
        // The middle of the articulated bogies is the train's centre of symmetry.
        let mirror = centre(1) + centre(coaches + 1);
        let rear: Vec<f64> = front.iter().rev().map(|x| mirror - x).collect();
        front.extend(bogies);
        front.extend(rear);
        Self {
            name: format!("hslm-a{k}"),
            axles: front.into_iter().map(|offset| Axle { offset, force }).collect(),
            patches: Vec::new(),
        }
    }

    /// Its length (m): from the first axle to the last axle or the end of the last patch.
    pub fn length(&self) -> f64 {
        let axles = self.axles.iter().map(|a| a.offset);
        let patches = self.patches.iter().map(|p| p.offset + p.length);
        axles.chain(patches).fold(0.0, f64::max)
    }

    /// The same train with every axle force and patch intensity times `factor` (one rail's share of a train given
    /// per axle: ½).
    pub fn scaled(&self, factor: f64) -> Self {
        Self {
            name: self.name.clone(),
            axles: self.axles.iter().map(|a| Axle { offset: a.offset, force: a.force * factor }).collect(),
            patches: self.patches.iter().map(|p| Patch { intensity: p.intensity * factor, ..*p }).collect(),
        }
    }

    /// Σ P_i + Σ q_j ℓ_j (N): the train's whole weight.
    pub fn total_force(&self) -> f64 {
        self.axles.iter().map(|a| a.force).sum::<f64>()
            + self.patches.iter().map(|p| p.intensity * p.length).sum::<f64>()
    }

    /// The consistent element loads of the train with its first axle at `head` (m): each axle on the beam
    /// (−P·Ψᵀ(x), within 1e-9·L of an end counted at the end, against round-off in x = vt), then the covered part of
    /// each patch (−q∫Ψᵀdx). Nothing allocates: the moving load calls it every step.
    pub fn element_loads<'a>(&'a self, beam: &'a Discretisation, head: f64) -> impl Iterator<Item = ElementLoad> + 'a {
        let length = beam.mesh().length;
        let tol = 1e-9 * length;
        let axles = self.axles.iter().filter_map(move |axle| {
            let x = head - axle.offset;
            if x < -tol || x > length + tol {
                return None;
            }
            ElementLoad::point_force(beam, x.clamp(0.0, length), -axle.force).ok()
        });
        let patches = self.patches.iter().flat_map(move |patch| {
            let front = head - patch.offset;
            ElementLoad::uniform_patch(beam, front - patch.length, front, -patch.intensity)
        });
        axles.chain(patches)
    }

    /// The train standing with its first axle at `head` (m), as a load case (for statics).
    pub fn load_vector(&self, beam: &Discretisation, head: f64) -> LoadVector {
        let mut loads = LoadVector::new();
        for load in self.element_loads(beam, head) {
            loads.push(load);
        }
        loads
    }

    /// Check every value: at least one axle or patch, at most [`MAX_TRAIN_ITEMS`]; offsets and forces finite and
    /// ≥ 0, one axle at offset 0 (the first); patch lengths > 0.
    pub fn validate(&self) -> Result<()> {
        let bad = |path: String, value: f64, allowed| Err(FemError::InvalidTrain { path, value, allowed });
        let items = self.axles.len() + self.patches.len();
        if items == 0 || items > MAX_TRAIN_ITEMS {
            return bad("axles".into(), items as f64, "a train has 1 to 10 000 axles and patches");
        }
        for (i, a) in self.axles.iter().enumerate() {
            if !(a.offset.is_finite() && a.offset >= 0.0) {
                return bad(format!("axles[{i}].offset"), a.offset, "must be finite and ≥ 0 (m behind the first axle)");
            }
            if !(a.force.is_finite() && a.force >= 0.0) {
                return bad(format!("axles[{i}].force"), a.force, "must be finite and ≥ 0 (N, downward)");
            }
        }
        for (i, p) in self.patches.iter().enumerate() {
            if !(p.offset.is_finite() && p.offset >= 0.0) {
                return bad(
                    format!("patches[{i}].offset"),
                    p.offset,
                    "must be finite and ≥ 0 (m behind the first axle)",
                );
            }
            if !(p.length.is_finite() && p.length > 0.0) {
                return bad(format!("patches[{i}].length"), p.length, "must be finite and > 0 (m)");
            }
            if !(p.intensity.is_finite() && p.intensity >= 0.0) {
                return bad(format!("patches[{i}].intensity"), p.intensity, "must be finite and ≥ 0 (N/m, downward)");
            }
        }
        let offsets = self.axles.iter().map(|a| a.offset).chain(self.patches.iter().map(|p| p.offset));
        let front = offsets.fold(f64::INFINITY, f64::min);
        if front != 0.0 {
            return bad("axles".into(), front, "the front of the train (the smallest offset) must be at offset 0");
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// HSLM-A: 2N + 14 axles, lengths 37.525 + (N + 2)·D (power cars and end coaches 2 × 18.7625 m, N + 2 coach
    /// lengths between the first and last articulated bogie centres plus their outer halves), sorted offsets,
    /// symmetric, and spot positions from the rule.
    #[test]
    fn hslm_trains_follow_the_rule() {
        let lengths = [397.525, 398.525, 397.525, 394.525, 389.525, 382.525, 397.525, 387.525, 375.525, 388.525];
        for k in 1..=10 {
            let train = Train::named(&format!("hslm-a{k}"), 0.0).unwrap();
            train.validate().unwrap();
            let (n, d_coach, d, p) = HSLM_A[k - 1];
            assert_eq!(train.axles.len(), 2 * n + 14, "A{k}");
            assert!((train.length() - lengths[k - 1]).abs() < 1e-9, "A{k}: {}", train.length());
            assert!((train.length() - (37.525 + (n + 2) as f64 * d_coach)).abs() < 1e-9);
            let offsets: Vec<f64> = train.axles.iter().map(|a| a.offset).collect();
            assert!(offsets.windows(2).all(|w| w[0] < w[1]), "A{k}: offsets ascend");
            for (a, b) in offsets.iter().zip(offsets.iter().rev()) {
                assert!((a + b - train.length()).abs() < 1e-9, "A{k}: symmetric");
            }
            assert!(train.axles.iter().all(|a| a.force == p));
            // Power car, end coach, first articulated bogie.
            assert_eq!(&offsets[..6], &[0.0, 3.0, 14.0, 17.0, 20.525, 20.525 + d]);
            let first_bogie = 17.0 + 3.525 / 2.0 + d_coach;
            assert!(
                (offsets[6] - (first_bogie - d / 2.0)).abs() < 1e-12
                    && (offsets[7] - (first_bogie + d / 2.0)).abs() < 1e-12
            );
        }
        // A1 by hand: 50 axles of 170 kN over 397.525 m, the articulated bogies 18 m apart.
        let a1 = Train::hslm_a(1);
        assert_eq!(a1.axles.len(), 50);
        assert!((a1.axles[8].offset - a1.axles[6].offset - 18.0).abs() < 1e-12);
        assert!((a1.total_force() - 50.0 * 170e3).abs() < 1e-6);
    }

    #[test]
    fn bad_trains_are_named() {
        assert!(matches!(Train::named("hslm-a11", 0.0), Err(FemError::UnknownTrain { .. })));
        let mut train = Train::single(1.0);
        train.axles.push(Axle { offset: -2.0, force: 1.0 });
        match train.validate() {
            Err(FemError::InvalidTrain { path, .. }) => assert_eq!(path, "axles[1].offset"),
            other => panic!("{other:?}"),
        }
        let shifted = Train { name: "x".into(), axles: vec![Axle { offset: 1.0, force: 1.0 }], patches: vec![] };
        assert!(shifted.validate().is_err());
        let empty = Train { name: "x".into(), axles: vec![], patches: vec![] };
        assert!(empty.validate().is_err());
    }
}
