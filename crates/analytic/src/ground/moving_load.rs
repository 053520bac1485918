//! A beam on a line support (a Winkler foundation or the ground's strip) under a force moving at speed v, in the
//! steady state of the moving frame s = x − vt (docs/theory.md §19). A wave e^{iks} of s has the circular frequency
//! ω = −kv at a fixed point, so with the ground's convention e^{i(ωt − k_x x)} (k_x = −k) and real responses
//! (negative ω the conjugate), for k > 0
//!
//! ```text
//! D(k) = EI(1 − iη)k⁴ − ρA v²k² + conj(k_support(k, kv)),      W(s) = (1/π) Re ∫₀^∞ −P/D(k) · e^{iks} dk
//! ```
//!
//! (W upward, P downward). The spectrum G = −1/D is sampled adaptively in ln k — from 1e-5 of the beam's
//! characteristic wavenumber k_c (the head below it linear in ln k, as a long wave on the ground is) up to where
//! EI k⁴ is 1e10 times the support at k_c and 100 times the inertia (the tail beyond is ≲ 3e-8 of W) — each
//! interval bisected until a cubic through its neighbours predicts the midpoint to [`SPECTRUM_TOLERANCE`] of
//! max|G|; that cubic, redrawn as cubics in k on panels at most 0.05 wide in ln k, is integrated against e^{iks}
//! exactly (`filon`), so a deflection costs the same at any s. One spectrum serves every s and, shifted, every axle
//! of a train: W(s) = Σ_j P_j W₁(s + d_j).

use super::filon::PiecewiseCubic;
use super::line_support::LineSupport;
use crate::interpolation::read_equally_spaced;
use fem_beam::error::Result;
use fem_beam::properties::Beam;
use fem_beam::{Axle, FemError};
use num_complex::Complex64;
use rayon::prelude::*;
use std::f64::consts::PI;

/// How closely the sampled spectrum's cubic must predict each new sample, relative to max|G|.
pub const SPECTRUM_TOLERANCE: f64 = 1e-6;
/// The most samples of one spectrum (each may cost a strip integral).
const MAX_SAMPLES: usize = 20_000;
/// Initial samples per decade of k.
const PER_DECADE: f64 = 8.0;

/// An Euler–Bernoulli beam (EI, ρA, loss factor) on a line support, in the moving frame.
#[derive(Debug, Clone, Copy)]
pub struct GroundedBeam<'a, S: LineSupport + ?Sized> {
    /// EI (N·m²).
    pub bending_stiffness: f64,
    /// ρA (kg/m).
    pub mass_per_length: f64,
    /// η ≥ 0: EI → EI(1 + iη sgn ω).
    pub loss_factor: f64,
    /// What carries it.
    pub support: &'a S,
}

/// The sampled spectrum G(k) = −1/D(k) (m/N per rad/m) of a unit downward force at one speed.
#[derive(Debug, Clone, PartialEq)]
pub struct MovingSpectrum {
    /// ln k of the samples, ascending.
    log_k: Vec<f64>,
    /// G at each.
    response: Vec<Complex64>,
    /// G between the first sample and the last significant one (past it ∫|G| dk, trapezoid over the samples, which
    /// bounds what the rest adds to any W(s), is below [`NEGLIGIBLE`] of the whole: the far tail of short waves) as
    /// cubics in k on panels at most [`PANEL_LOG_WIDTH`] wide in ln k, each through four points of the cubic in ln k:
    /// their Fourier integral is exact at any s.
    body: PiecewiseCubic,
}

/// The spacing (m) of a single load's wave read by a train's ([`MovingSpectrum::wave_under`]).
const GRID_STEP: f64 = 0.05;

/// The widest panel (in ln k) on which the cubic in ln k is redrawn as a cubic in k: ln k departs from a cubic in k
/// there by ~(Δ ln k)⁴/100 ≈ 6e-8 of the panel's change in ln k.
const PANEL_LOG_WIDTH: f64 = 0.05;

/// The share of ∫|G| dk whose intervals a deflection leaves out (their contribution to W(s) is at most that).
const NEGLIGIBLE: f64 = 1e-10;

impl<'a, S: LineSupport + ?Sized> GroundedBeam<'a, S> {
    /// `beam` (Euler–Bernoulli: a Timoshenko composite beam is refused by key) on `support`.
    pub fn new(beam: &Beam, support: &'a S) -> Result<Self> {
        if beam.shear_stiffness().is_some() {
            return Err(FemError::InvalidField {
                field: "beam.theory",
                value: f64::NAN,
                allowed: "must be euler-bernoulli for a beam on the ground (the composite track-and-embankment beam)",
            });
        }
        Ok(Self {
            bending_stiffness: beam.bending_stiffness(),
            mass_per_length: beam.mass_per_length(),
            loss_factor: beam.loss_factor,
            support,
        })
    }

    /// G(k) = −1/D(k) at k > 0 and `speed` (m/s), the support left out where EI k⁴ is 1e4 times its bound (G is
    /// then ≲ 1e-4 of the support's compliance there, and changes by ≲ 1e-4 of itself: ≲ 1e-8 of max|G|).
    pub fn response(&self, k: f64, speed: f64) -> Result<Complex64> {
        let omega = k * speed;
        let bending = self.bending_stiffness * k.powi(4);
        // Hysteretic damping is iη sgn ω: none at rest, where a load deflects the beam elastically.
        let loss = if omega > 0.0 { self.loss_factor } else { 0.0 };
        let beam = Complex64::new(bending - self.mass_per_length * (speed * k).powi(2), -loss * bending);
        let support = match bending > 1e4 * self.support.stiffness_bound(k, omega) {
            true => Complex64::new(0.0, 0.0),
            false => self.support.line_stiffness(k, omega)?.conj(),
        };
        Ok(-1.0 / (beam + support))
    }

    /// The spectrum of a unit downward force at `speed` (m/s, ≥ 0), sampled to [`SPECTRUM_TOLERANCE`].
    pub fn spectrum(&self, speed: f64) -> Result<MovingSpectrum> {
        let [single] = sample_channels(self.range(speed), speed, &|k| Ok([self.response(k, speed)?]))?;
        Ok(single)
    }

    /// [k_low, k_high] (rad/m) around the characteristic wavenumber k_c where EI k⁴ meets the support's bound and
    /// the inertia: 1e-5·k_c, and where EI k⁴ is both 1e10 times the support's bound at k_c (≳ 300·k_c: the tail
    /// beyond, ∫|G| ~ 1/(3EI k³), is ≲ 3e-8 of the whole) and 100 times the inertia ρA v²k².
    pub(crate) fn range(&self, speed: f64) -> (f64, f64) {
        let inertia = |k: f64| self.mass_per_length * (speed * k).powi(2);
        let first_above = |above: &dyn Fn(f64) -> f64| {
            let mut k: f64 = 1e-3;
            while self.bending_stiffness * k.powi(4) < above(k) {
                k *= 2.0;
            }
            k
        };
        let characteristic = first_above(&|k| self.support.stiffness_bound(k, k * speed) + inertia(k));
        let at_characteristic = self.support.stiffness_bound(characteristic, characteristic * speed);
        let high = first_above(&|_| 1e10 * at_characteristic).max(first_above(&|k| 100.0 * inertia(k)));
        (1e-5 * characteristic, high)
    }
}

impl MovingSpectrum {
    /// How many samples the spectrum took.
    pub fn samples(&self) -> usize {
        self.log_k.len()
    }

    /// The samples as (k (rad/m), G, dk): each with its share of ∫ dk by the trapezoid rule in k.
    pub fn samples_in_k(&self) -> Vec<(f64, Complex64, f64)> {
        let k: Vec<f64> = self.log_k.iter().map(|u| u.exp()).collect();
        (0..k.len())
            .map(|i| {
                let (before, after) = (k[i.saturating_sub(1)], k[(i + 1).min(k.len() - 1)]);
                (k[i], self.response[i], 0.5 * (after - before))
            })
            .collect()
    }

    /// W(s) (m, upward) per newton of the downward force, at s = x − vt (m; s > 0 ahead of the load).
    pub fn deflection(&self, s: f64) -> f64 {
        (self.head(s) + self.body.fourier(s)).re / PI
    }

    /// [`Self::deflection`] at s_m = `first` + m·`step`, m < `count`: the same sums, each panel's phases carried along
    /// the grid by products instead of a sine and a cosine each (the same values to ~1e-14; the 60-speed Ledsgård
    /// curve, ~10 400 grid points a speed, 10 % faster).
    pub fn deflections_on_grid(&self, first: f64, step: f64, count: usize) -> Vec<f64> {
        let body = self.body.fourier_on_grid(first, step, count);
        body.iter().enumerate().map(|(m, b)| (self.head(first + m as f64 * step) + b).re / PI).collect()
    }

    /// The spectrum below its first sample: G = G₀ + b·ln(k/k₀) (a long wave's ln on the ground, b = 0 on a spring)
    /// and e^{iks} = 1 + iks (k₀|s| ≲ 1e-2 for |s| ≲ 1 km): ∫₀^{k₀} = k₀(G₀ − b) + is·k₀²/2·(G₀ − b/2).
    fn head(&self, s: f64) -> Complex64 {
        let low = self.log_k[0].exp();
        let (g0, slope) = (self.response[0], (self.response[1] - self.response[0]) / (self.log_k[1] - self.log_k[0]));
        (g0 - slope) * low + Complex64::new(0.0, s * low * low / 2.0) * (g0 - slope / 2.0)
    }

    /// W(s) (m, upward) under a train of `axles` (offsets d_j ≥ 0 behind the first axle, which is at s = 0; forces
    /// P_j downward, N) at the spectrum's speed: Σ_j P_j W₁(s + d_j), the moving frame's superposition.
    pub fn deflection_under(&self, axles: &[Axle], s: f64) -> f64 {
        axles.iter().map(|axle| axle.force * self.deflection(s + axle.offset)).sum()
    }

    /// [`Self::deflection_under`] at each of `positions` (m), in parallel. Where the train has more axles than a
    /// single load's wave needs points to cover it, that wave is computed once every 5 cm over the reach
    /// of every axle and read between its points by the cubic through the four nearest: its error, ~h⁴|W⁗|/40 and
    /// h³/(20 EI) per newton beside the load's kink in W‴, is ≲ 1e-6 of the wave on a track's ≳ 5 m bowls.
    pub fn wave_under(&self, axles: &[Axle], positions: &[f64]) -> Vec<f64> {
        let offsets = axles.iter().map(|a| a.offset);
        let (first, last) = offsets.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), d| (a.min(d), b.max(d)));
        let (low, high) = positions.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &s| (a.min(s), b.max(s)));
        let (from, to) = (low + first - 2.0 * GRID_STEP, high + last + 2.0 * GRID_STEP);
        let count = ((to - from) / GRID_STEP).ceil() as usize + 1;
        if axles.is_empty() || positions.is_empty() || count >= positions.len() * axles.len() {
            return positions.par_iter().map(|&s| self.deflection_under(axles, s)).collect();
        }
        let grid = self.deflections_on_grid(from, GRID_STEP, count);
        let read = |s: f64| read_equally_spaced(&grid, from, GRID_STEP, s);
        positions.par_iter().map(|&s| axles.iter().map(|a| a.force * read(s + a.offset)).sum()).collect()
    }
}

/// The spectra of N responses at the same wavenumbers in [`range`](GroundedBeam::range), sampled together from 8
/// per decade of k, each interval bisected until a cubic through its neighbours predicts every channel's midpoint
/// to [`SPECTRUM_TOLERANCE`] of that channel's max|G| (at `speed`, m/s, for the error message).
pub(crate) fn sample_channels<const N: usize>(
    (low, high): (f64, f64),
    speed: f64,
    response: &(dyn Fn(f64) -> Result<[Complex64; N]> + Sync),
) -> Result<[MovingSpectrum; N]> {
    let count = ((high / low).log10() * PER_DECADE).ceil() as usize + 1;
    let mut log_k: Vec<f64> =
        (0..count).map(|i| low.ln() + (high / low).ln() * i as f64 / (count - 1) as f64).collect();
    let at = |log_k: &[f64]| -> Result<Vec<[Complex64; N]>> { log_k.par_iter().map(|&u| response(u.exp())).collect() };
    let mut values = at(&log_k)?;
    let mut unsettled: Vec<bool> = vec![true; count - 1];
    while unsettled.iter().any(|&u| u) {
        if log_k.len() > MAX_SAMPLES {
            return Err(FemError::NotConverged {
                what: format!("the moving-load spectrum at {speed} m/s ({MAX_SAMPLES} samples)"),
                reached: f64::NAN,
                asked: SPECTRUM_TOLERANCE,
            });
        }
        let intervals: Vec<usize> = (0..unsettled.len()).filter(|&i| unsettled[i]).collect();
        let middles: Vec<f64> = intervals.iter().map(|&i| 0.5 * (log_k[i] + log_k[i + 1])).collect();
        let fresh = at(&middles)?;
        let mut fine = vec![true; intervals.len()];
        for c in 0..N {
            let channel: Vec<Complex64> = values.iter().map(|v| v[c]).collect();
            let scale = channel.iter().chain(fresh.iter().map(|v| &v[c])).map(|g| g.norm()).fold(0.0, f64::max);
            for (j, fine) in fine.iter_mut().enumerate() {
                let predicted = cubic(&log_k, &channel, intervals[j], middles[j]);
                *fine &= (fresh[j][c] - predicted).norm() <= SPECTRUM_TOLERANCE * scale;
            }
        }
        let (mut next_k, mut next_v, mut next_unsettled) = (Vec::new(), Vec::new(), Vec::new());
        let mut j = 0;
        for i in 0..log_k.len() {
            next_k.push(log_k[i]);
            next_v.push(values[i]);
            if i + 1 == log_k.len() {
                break;
            }
            if j < intervals.len() && intervals[j] == i {
                next_k.push(middles[j]);
                next_v.push(fresh[j]);
                next_unsettled.extend([!fine[j], !fine[j]]);
                j += 1;
            } else {
                next_unsettled.push(false);
            }
        }
        (log_k, values, unsettled) = (next_k, next_v, next_unsettled);
    }
    Ok(std::array::from_fn(|c| {
        let response: Vec<Complex64> = values.iter().map(|v| v[c]).collect();
        let body = in_k(&log_k, &response, significant_intervals(&log_k, &response));
        MovingSpectrum { log_k: log_k.clone(), response, body }
    }))
}

/// G on the first `intervals` intervals of the samples as cubics in k (see [`MovingSpectrum`]'s `body`).
fn in_k(log_k: &[f64], response: &[Complex64], intervals: usize) -> PiecewiseCubic {
    let mut body = PiecewiseCubic::default();
    for i in 0..intervals {
        let (u0, u1) = (log_k[i], log_k[i + 1]);
        let panels = ((u1 - u0) / PANEL_LOG_WIDTH).ceil().max(1.0) as usize;
        let width = (u1 - u0) / panels as f64;
        for p in 0..panels {
            let (start, end) = ((u0 + p as f64 * width).exp(), (u0 + (p + 1) as f64 * width).exp());
            let at = |t: f64| cubic(log_k, response, i, (start + t * (end - start)).ln());
            body.push(start, end, [at(0.0), at(1.0 / 3.0), at(2.0 / 3.0), at(1.0)]);
        }
    }
    body
}

/// How many leading intervals hold all but [`NEGLIGIBLE`] of ∫|G| dk (trapezoid in k over the samples).
fn significant_intervals(log_k: &[f64], response: &[Complex64]) -> usize {
    let pieces: Vec<f64> = (0..log_k.len() - 1)
        .map(|i| 0.5 * (response[i].norm() + response[i + 1].norm()) * (log_k[i + 1].exp() - log_k[i].exp()))
        .collect();
    let total: f64 = pieces.iter().sum();
    let mut left = total;
    for (i, piece) in pieces.iter().enumerate() {
        left -= piece;
        if left < NEGLIGIBLE * total {
            return i + 1;
        }
    }
    pieces.len()
}

/// The cubic through the samples i − 1 … i + 2 (clamped at the ends) at u, inside interval i.
fn cubic(x: &[f64], y: &[Complex64], i: usize, u: f64) -> Complex64 {
    let first = i.saturating_sub(1).min(x.len().saturating_sub(4));
    let nodes = first..(first + 4).min(x.len());
    let mut value = Complex64::new(0.0, 0.0);
    for a in nodes.clone() {
        let weight: f64 = nodes.clone().filter(|&b| b != a).map(|b| (u - x[b]) / (x[a] - x[b])).product();
        value += y[a] * weight;
    }
    value
}
