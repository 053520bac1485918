//! The largest band-limited acceleration of a run: each step's mean nodal acceleration (v_{k+1} − v_k)/h projected
//! onto the beam's modes at or below a frequency ([`fem_beam::modal_band::ModalBand`], docs/theory.md §10.4).

use super::observers::NodalDeflections;
use super::records::{Record, StepState};
use super::results::BandAcceleration;
use crate::error::Result;
use fem_beam::modal_band::{BandLimit, ModalBand};
use fem_beam::{BeamModel, Extreme};

/// The band's modes, its scratch vectors and the largest value so far.
pub(super) struct BandRecord {
    band: ModalBand,
    nodes: NodalDeflections,
    /// The step's mean acceleration over the beam's free DOFs (m/s²), and its modal coordinates.
    acceleration: Vec<f64>,
    eta: Vec<f64>,
    largest: Extreme,
}

impl BandRecord {
    /// The record of `model`'s accelerations in the modes of `limit`, over the nodes in `region` (m) or all.
    pub(super) fn new(model: &BeamModel, limit: BandLimit, region: Option<(f64, f64)>) -> Result<Self> {
        let band = ModalBand::of(model, limit)?;
        Ok(Self {
            nodes: NodalDeflections::new(model.mesh(), model.dofs(), region),
            acceleration: vec![0.0; band.dofs()],
            eta: vec![0.0; band.modes()],
            largest: Extreme::default(),
            band,
        })
    }

    /// The largest band-limited acceleration with its band.
    pub(super) fn finish(self) -> BandAcceleration {
        BandAcceleration {
            extreme: self.largest,
            limit: self.band.limit(),
            frequencies: self.band.frequencies().to_vec(),
        }
    }
}

impl Record for BandRecord {
    fn record(&mut self, s: &StepState<'_>) -> Result<()> {
        for ((a, v), v_prev) in self.acceleration.iter_mut().zip(s.v).zip(s.previous_v) {
            *a = (v - v_prev) / s.h;
        }
        self.band.coordinates(&self.acceleration, &mut self.eta);
        let (a, x) = self.nodes.largest(|d| self.band.at(&self.eta, d));
        self.largest.raise(a, x, s.time);
        Ok(())
    }
}
