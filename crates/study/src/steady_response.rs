//! The closed-form steady state of the infinite beam on its viscoelastic foundation under a scenario's moving
//! loads (docs/theory.md §8, §10): at each speed the largest downward and upward deflections and where they sit in
//! the moving frame, and their amplification over the static response of the same loads.

use analytic::moving_beam::MovingBeam;
use fem_beam::DeflectionExtremes;
use fem_beam::{Foundation, Train};
use scenario::Scenario;
use scenario::error::{Result, invalid};
use serde::Serialize;

/// The steady state at one speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SteadyPoint {
    /// Load speed v (m/s).
    pub speed: f64,
    /// Largest downward deflection (m, magnitude) and largest upward one (m), each where in the moving frame s (m;
    /// s = x − vt for one load, x − x_head for a train).
    #[serde(flatten)]
    pub deflection: DeflectionExtremes,
    /// Downward deflection over the static one w₀.
    pub amplification_downward: f64,
    /// Upward deflection over w₀.
    pub amplification_upward: f64,
}

/// The steady response over speeds, with what it was computed for.
#[derive(Debug, Clone, PartialEq)]
pub struct SteadyResponse {
    /// The foundation used (its damping from the given ratio, if one was given).
    pub foundation: Foundation,
    /// The infinite track of the scenario's beam (either rail theory) on that foundation.
    pub beam: MovingBeam,
    /// The rail the closed form took: the scenario's, on sleepers their long-wave twin's (the sleepers' moving mass
    /// on it, [`Scenario::uniform_support`]).
    pub rail: fem_beam::Beam,
    /// The train, as the beam carries it; None for the single load.
    pub train: Option<Train>,
    /// The single load F (N), used without a train.
    pub load: f64,
    /// The static response w₀ of the same loads (m): the largest downward deflection at v = 0.
    pub static_deflection: f64,
    /// One point per speed, in the order given.
    pub points: Vec<SteadyPoint>,
}

impl SteadyResponse {
    /// The steady state of `scenario`'s loads at `speeds` (m/s): its single load, or `train` (as given, or the
    /// scenario's, scaled to what the beam carries), on its foundation with damping ratio `damping_ratio` if given.
    /// Vehicles and load patches are refused: the closed form takes moving forces on axles.
    pub fn of(scenario: &Scenario, damping_ratio: Option<f64>, train: Option<Train>, speeds: &[f64]) -> Result<Self> {
        let case = scenario.reference_case()?;
        let foundation = match damping_ratio {
            Some(ratio) => case.foundation.with_damping_ratio(ratio, &case.beam)?,
            None => case.foundation,
        };
        let beam = MovingBeam::new(&case.beam, &foundation)?;
        if scenario.vehicle.is_some() {
            return Err(invalid(
                "vehicle",
                "given",
                "the closed-form steady state takes moving forces, not vehicles: drop [vehicle] (the train's axles, \
                 or the single load, are used) or use `frictrack run`",
            ));
        }
        let train = match train {
            Some(t) => Some(t),
            None => scenario::trains::resolve(&scenario.load)?,
        }
        .map(|t| scenario.on_the_beam(t));
        if let Some(t) = train.as_ref().filter(|t| !t.patches.is_empty()) {
            return Err(invalid(
                "load.patches",
                t.patches.len(),
                "the closed-form steady state takes axles only: give the train as axles, or use `frictrack run`",
            ));
        }
        let extremes = |v: f64| -> Result<DeflectionExtremes> {
            Ok(match &train {
                Some(t) => beam.train_steady_state(v, t)?.extremes(),
                None => beam.steady_state(v, case.load)?.extremes(),
            })
        };
        // The static response of the same load (v = 0): a train's superposed static shapes.
        let w0 = match &train {
            Some(_) => extremes(0.0)?.max_downward.value,
            None => beam.static_deflection(case.load)?,
        };
        let points = speeds
            .iter()
            .map(|&v| {
                let e = extremes(v)?;
                Ok(SteadyPoint {
                    speed: v,
                    deflection: e,
                    amplification_downward: e.max_downward.value / w0,
                    amplification_upward: e.max_upward.value / w0,
                })
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Self { foundation, beam, rail: case.beam, train, load: case.load, static_deflection: w0, points })
    }

    /// Warnings for the reader: undamped within [`RESONANCE_BAND`] of the critical speed the closed form is the
    /// resonance itself — its peaks grow without bound as v → v_cr (∝ 1/√|1 − v/v_cr| for one load), so the number
    /// printed says how close the speed is, not how the track responds.
    pub fn warnings(&self) -> Vec<String> {
        let v_cr = self.beam.critical_speed();
        if self.foundation.damping > 0.0 {
            return Vec::new();
        }
        self.points
            .iter()
            .filter(|p| (p.speed / v_cr - 1.0).abs() <= RESONANCE_BAND)
            .map(|p| {
                format!(
                    "v = {} m/s is {:.3} % from the critical speed v_cr = {v_cr:.2} m/s of the undamped track: there \
                     the closed form is the undamped resonance and grows without bound as v → v_cr (amplification \
                     {:.0} here); it is not a response a track would show — give the foundation damping for a \
                     bounded steady state",
                    p.speed,
                    100.0 * (p.speed / v_cr - 1.0).abs(),
                    p.amplification_downward
                )
            })
            .collect()
    }
}

/// How close to v_cr (relative) an undamped speed is warned about: 1 % from it the reference track's amplification
/// is 7.1, 1e-4 from it 78, 1e-5 from it 177.
pub const RESONANCE_BAND: f64 = 0.01;
