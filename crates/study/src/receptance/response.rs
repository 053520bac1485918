//! The track's receptance over frequency (`frictrack receptance`, docs/theory.md §17): the point or transfer
//! receptance α(f) = w(x)/F (m/N) of the scenario's track for a harmonic force at x_F, its mobility 2πf·|α|
//! (m/s/N), magnitude and phase, one complex banded solve per frequency on the runner's threads; the resonances
//! (local peaks of |α|) refined between the grid's frequencies; and what makes the numbers doubtful — a mesh too
//! coarse for the top frequency, waves that reach the ends and come back.

use crate::receptance::peaks::{Resonance, resonances, warnings};
use fem_beam::receptance::FrequencyResponse;
use num_complex::Complex64;
use runner::Runner;
use scenario::Scenario;
use scenario::error::{Result, StudyError, invalid};
use serde::Serialize;
use std::f64::consts::TAU;

/// The most frequencies one request may ask for (checked before anything is allocated).
pub const MAX_FREQUENCIES: usize = 100_000;

/// What to compute: frequencies (Hz, > 0, increasing), where the force acts and where the response is read (m).
#[derive(Debug, Clone, PartialEq)]
pub struct ReceptanceRequest {
    /// f (Hz).
    pub frequencies: Vec<f64>,
    /// x_F (m).
    pub excite: f64,
    /// x (m): equal to `excite` for the point receptance.
    pub at: f64,
}

/// The receptance at one frequency.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReceptancePoint {
    /// f (Hz).
    pub frequency: f64,
    /// Re α (m/N).
    pub real: f64,
    /// Im α (m/N).
    pub imaginary: f64,
    /// |α| (m/N).
    pub magnitude: f64,
    /// arg α (degrees, in (−180, 180]): −90 and below is the response lagging the force.
    pub phase: f64,
    /// |iωα| = 2πf|α| (m/s/N).
    pub mobility: f64,
}

impl ReceptancePoint {
    fn of(frequency: f64, alpha: Complex64) -> Self {
        Self {
            frequency,
            real: alpha.re,
            imaginary: alpha.im,
            magnitude: alpha.norm(),
            phase: alpha.arg().to_degrees(),
            mobility: TAU * frequency * alpha.norm(),
        }
    }
}

/// The receptance of a scenario's track.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReceptanceStudy {
    /// The scenario's title.
    pub title: String,
    /// x_F (m).
    pub excite: f64,
    /// x (m).
    pub at: f64,
    /// "point" (x = x_F) or "transfer".
    pub kind: &'static str,
    /// The rail: "Euler–Bernoulli" or "Timoshenko (G = …, κ = …)".
    pub rail: String,
    /// The loss factors of rail and foundation.
    pub loss_factors: [f64; 2],
    /// What carries the rail, in words: the continuous foundation and/or the sleepers with their pads and ballast.
    pub support: String,
    /// Where the response is read among the sleepers ("above sleeper 166", "mid-span between sleepers 166 and
    /// 167", "0.15 m past sleeper 166"); empty without sleepers.
    pub place: String,
    /// One point per frequency.
    pub points: Vec<ReceptancePoint>,
    /// The peaks of |α|.
    pub resonances: Vec<Resonance>,
    /// What makes the numbers doubtful (mesh, reflections).
    pub warnings: Vec<String>,
}

/// The frequencies from, from + step, … ≤ to (Hz, up to round-off), checked: from > 0, step > 0, to ≥ from, at
/// most [`MAX_FREQUENCIES`] of them (counted before any is made).
pub fn frequency_range(from: f64, to: f64, step: f64) -> Result<Vec<f64>> {
    if !(from.is_finite() && from > 0.0) {
        return Err(invalid("frequencies", from, "must start above 0 Hz"));
    }
    if !(step.is_finite() && step > 0.0) {
        return Err(invalid("frequencies", step, "the step must be finite and > 0 (Hz)"));
    }
    if !(to.is_finite() && to >= from) {
        return Err(invalid("frequencies", to, format!("must end at or above its start, {from} Hz")));
    }
    let count = ((to - from) / step * (1.0 + 1e-12)).floor() + 1.0;
    if count > MAX_FREQUENCIES as f64 {
        return Err(invalid("frequencies", count, format!("at most {MAX_FREQUENCIES} frequencies")));
    }
    Ok((0..count as usize).map(|i| from + i as f64 * step).collect())
}

/// A list of frequencies (Hz) checked: 1 … [`MAX_FREQUENCIES`] of them, finite, > 0, increasing (`frequencies`).
pub fn check_frequencies(frequencies: &[f64]) -> Result<()> {
    let count = frequencies.len();
    if count == 0 || count > MAX_FREQUENCIES {
        return Err(invalid("frequencies", count, format!("must be 1 … {MAX_FREQUENCIES} frequencies")));
    }
    if let Some(f) = frequencies.iter().find(|f| !(f.is_finite() && **f > 0.0)) {
        return Err(invalid("frequencies", f, "must be finite and > 0 (Hz)"));
    }
    if frequencies.windows(2).any(|w| w[1] <= w[0]) {
        return Err(invalid("frequencies", "not increasing", "must increase"));
    }
    Ok(())
}

impl ReceptanceRequest {
    /// Check the frequencies (count, > 0, finite, increasing) and the places (on the beam of length `length`).
    pub fn validate(&self, length: f64) -> Result<()> {
        check_frequencies(&self.frequencies)?;
        for (name, x) in [("at", self.at), ("excite", self.excite)] {
            if !(x.is_finite() && (0.0..=length).contains(&x)) {
                return Err(invalid(name, x, format!("must lie on the beam, in [0, {length}] m")));
            }
        }
        Ok(())
    }
}

/// What carries the rail of `model`, in words (MN/m, kN·s/m: the units the literature quotes pads and ballast in).
fn support(model: &fem_beam::BeamModel) -> String {
    let f = model.foundation();
    let soil = format!("a foundation of k_f = {:.4e} N/m² (η {})", f.stiffness, f.loss_factor);
    let Some(sleepers) = report::sleeper_output::track_in_words(model) else { return soil };
    if f.stiffness > 0.0 { format!("{sleepers}, on {soil}") } else { sleepers }
}

impl ReceptanceStudy {
    /// The receptance of `scenario`'s track (a linear foundation) for `request`, on `runner`'s threads.
    pub fn of(scenario: &Scenario, request: &ReceptanceRequest, runner: &Runner<'_>) -> Result<Self> {
        if scenario.ground.is_some() {
            return Self::on_the_ground(scenario, request, runner);
        }
        let model = scenario.model()?;
        if !model.foundation().law.is_linear() {
            return Err(invalid(
                "foundation.law",
                model.foundation().law.name(),
                "the receptance is that of a linear track: give a linear foundation",
            ));
        }
        if let Some((sleepers, _)) = model.sleepers()
            && !sleepers.is_linear()
        {
            return Err(invalid(
                "sleepers.exceptions",
                "unilateral ballast or friction",
                "the receptance is that of a linear track: voided, tensionless and frictional sleepers are run in \
                 time (scaled stiffnesses are linear and taken)",
            ));
        }
        request.validate(model.mesh().length)?;
        let response = FrequencyResponse::new(&model);
        let alpha = |f: f64| -> Result<Complex64> {
            Ok(response.receptance(TAU * f, request.excite, &[request.at]).map_err(StudyError::from)?[0])
        };
        let (dofs, count) = (model.dofs().free_len(), request.frequencies.len());
        runner.announce(runner::cost::Estimate::receptance(dofs, count, runner.threads()));
        let (points, mut resonances) = sampled(&request.frequencies, runner, &alpha)?;
        let unresolved = crate::receptance::peaks::keep_resolved(&model, &mut resonances);
        crate::receptance::peaks::name_resonances(&model, &mut resonances);
        let mut warnings = warnings(&model, &request.frequencies, request.excite);
        // A point on a held node: the rail's deflection is zero there, and with it α.
        let mesh = model.mesh();
        for (what, x) in [("the response is read", request.at), ("the force acts", request.excite)] {
            let held = mesh.nearest_node(x).ok().filter(|&n| (mesh.node_x(n) - x).abs() <= 1e-9 * mesh.length);
            if held.is_some_and(|n| model.dofs().free_index(2 * n).is_none()) {
                warnings.push(format!(
                    "{what} at x = {x} m, where a support holds the rail: its deflection there is zero, and so is \
                     |α| — take a point away from the supports (--at, --excite)"
                ));
            }
        }
        if unresolved > 0 {
            warnings.push(format!(
                "{unresolved} peak(s) of |α| where the mesh has fewer than {} elements a bending wavelength are not \
                 listed as resonances: there the curve is the mesh's, not the track's",
                crate::receptance::peaks::LISTED_ELEMENTS_PER_WAVELENGTH
            ));
        }
        Ok(Self {
            title: scenario.title.clone(),
            excite: request.excite,
            at: request.at,
            kind: if request.at == request.excite { "point" } else { "transfer" },
            rail: model.beam().theory.describe(),
            loss_factors: [model.beam().loss_factor, model.foundation().loss_factor],
            support: support(&model),
            place: place_among_sleepers(&model, request.at),
            points,
            resonances,
            warnings,
        })
    }
}

/// α at each of `frequencies` (Hz) on `runner`'s threads, stopping when asked, and the peaks of |α| refined between
/// them: what every receptance does with its α(f), the finite track's and the ground's.
pub(crate) fn sampled(
    frequencies: &[f64],
    runner: &Runner<'_>,
    alpha: &(dyn Fn(f64) -> Result<Complex64> + Sync),
) -> Result<(Vec<ReceptancePoint>, Vec<Resonance>)> {
    let values = runner.map(frequencies, |&f| match runner.is_stopped() {
        true => Err(StudyError::Interrupted),
        false => alpha(f),
    })?;
    let points: Vec<ReceptancePoint> =
        frequencies.iter().zip(&values).map(|(&f, &a)| ReceptancePoint::of(f, a)).collect();
    let curve: Vec<(f64, f64)> = points.iter().map(|p| (p.frequency, p.magnitude)).collect();
    let resonances = resonances(&curve, |f| alpha(f).map(|a| a.norm()))?;
    Ok((points, resonances))
}

/// Where `x` (m) lies among the sleepers of `model`, in words (to 1 mm): "above sleeper 166", "mid-span between
/// sleepers 166 and 167", "0.15 m past sleeper 166"; empty without sleepers. A receptance above a sleeper and one at
/// mid-span differ most at the pinned–pinned frequency.
fn place_among_sleepers(model: &fem_beam::BeamModel, x: f64) -> String {
    let Some((_, nodes)) = model.sleepers() else { return String::new() };
    let xs: Vec<f64> = nodes.iter().map(|&n| model.mesh().node_x(n)).collect();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-3;
    let Some(behind) = xs.partition_point(|&s| s <= x + 1e-3).checked_sub(1) else {
        return format!("{:.3} m before sleeper 0", xs[0] - x);
    };
    match xs.get(behind + 1) {
        _ if close(xs[behind], x) => format!("above sleeper {behind}"),
        Some(&next) if close(0.5 * (xs[behind] + next), x) => {
            format!("mid-span between sleepers {behind} and {}", behind + 1)
        }
        _ => format!("{:.3} m past sleeper {behind}", x - xs[behind]),
    }
}
