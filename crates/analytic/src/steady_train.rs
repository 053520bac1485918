//! The steady state of a train on the infinite beam (docs/theory.md §8, §10): the equation is linear, so the
//! response is the sum of its axles' single-load steady states, each shifted by the axle's offset. In the train's
//! frame s = x − x_head (m; positive ahead of the first axle, axle i at s = −d_i):
//! w(s) = Σ_i (P_i/P)·w_P(s + d_i).

use crate::reference::scan_extremes;
use crate::{MovingBeam, SteadyWave};
use fem_beam::DeflectionExtremes;
use fem_beam::error::{FemError, Result};
use fem_beam::extreme::Extreme;
use fem_beam::train::Train;

/// A train's steady state: the unit-load state and the axles (offset, force).
#[derive(Debug, Clone)]
pub struct TrainSteadyState {
    unit: SteadyWave,
    axles: Vec<(f64, f64)>,
    length: f64,
    /// Sampling of the unit state: step (m) and reach (m) beyond which it is below e⁻⁴⁰ of its scale.
    step: f64,
    reach: f64,
}

impl MovingBeam {
    /// The steady state of `train` (axles only) at `speed` (m/s).
    pub fn train_steady_state(&self, speed: f64, train: &Train) -> Result<TrainSteadyState> {
        train.validate()?;
        if !train.patches.is_empty() {
            return Err(FemError::InvalidTrain {
                path: "patches".into(),
                value: train.patches.len() as f64,
                allowed: "the closed-form steady state takes trains of axles only",
            });
        }
        let unit = self.steady_state(speed, 1.0)?;
        let (step, reach) = unit.sampling();
        Ok(TrainSteadyState {
            unit,
            axles: train.axles.iter().map(|a| (a.offset, a.force)).collect(),
            length: train.length(),
            step,
            reach,
        })
    }
}

impl TrainSteadyState {
    /// Deflection w (m, positive upward) at s = x − x_head (m).
    pub fn deflection(&self, s: f64) -> f64 {
        self.axles.iter().map(|&(offset, force)| force * self.unit.deflection(s + offset)).sum()
    }

    /// Largest downward and upward deflections and where they are in the train's frame (s = x − x_head): dense
    /// sampling from `reach` behind the last axle to `reach` ahead of the first, then golden-section refinement.
    pub fn extremes(&self) -> DeflectionExtremes {
        let (from, to) = (-self.length - self.reach, self.reach);
        let count = ((to - from) / self.step).ceil() as usize;
        let samples = (0..=count).map(|i| from + i as f64 * self.step);
        let (down, up) = scan_extremes(|s| -self.deflection(s), samples, self.step);
        DeflectionExtremes {
            max_downward: Extreme::in_frame(down.1.max(0.0), down.0),
            max_upward: Extreme::in_frame(up.1.max(0.0), up.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::uic60_on_soft_soil;
    use fem_beam::properties::BeamTheory;
    use fem_beam::train::Axle;

    /// One axle is the single-load state; two far-apart axles each give their own peak; axles closer than the
    /// decay length add up (at rest: the superposed static shapes) — on an Euler–Bernoulli and a Timoshenko rail.
    #[test]
    fn a_train_superposes_its_axles() {
        let case = uic60_on_soft_soil();
        let timoshenko = fem_beam::Beam {
            theory: BeamTheory::Timoshenko { shear_modulus: 81e9, shear_coefficient: 0.4 },
            ..case.beam
        };
        for beam in [case.beam, timoshenko] {
            let foundation = case.foundation.with_damping_ratio(0.05, &beam).unwrap();
            let infinite = MovingBeam::new(&beam, &foundation).unwrap();
            let single = infinite.steady_state(150.0, 100e3).unwrap().extremes();
            let one = infinite.train_steady_state(150.0, &Train::single(100e3)).unwrap().extremes();
            assert!((one.max_downward.value - single.max_downward.value).abs() <= 1e-12 * single.max_downward.value);
            assert!((one.max_downward.position.unwrap() - single.max_downward.position.unwrap()).abs() <= 1e-6);
            let far = Train {
                name: "far".into(),
                axles: vec![Axle { offset: 0.0, force: 100e3 }, Axle { offset: 300.0, force: 50e3 }],
                patches: vec![],
            };
            let apart = infinite.train_steady_state(150.0, &far).unwrap();
            let e = apart.extremes();
            assert!((e.max_downward.value - single.max_downward.value).abs() <= 1e-9 * single.max_downward.value);
            let under = infinite.steady_state(150.0, 100e3).unwrap().deflection(0.0);
            assert!((apart.deflection(-300.0) - 0.5 * under).abs() < 1e-12);
            let pair = Train {
                name: "pair".into(),
                axles: vec![Axle { offset: 0.0, force: 100e3 }, Axle { offset: 0.0, force: 100e3 }],
                patches: vec![],
            };
            let doubled = infinite.train_steady_state(150.0, &pair).unwrap().extremes();
            let twice = 2.0 * single.max_downward.value;
            assert!((doubled.max_downward.value - twice).abs() <= 1e-9 * single.max_downward.value);
        }
    }
}
