//! `frictrack stationary`: the stationary wave of the scenario's load on the infinite track (docs/theory.md §14), at
//! one speed or over a speed range by continuation, as typed points (JSON), the wave's shape (CSV) and figures. A
//! speed whose wave was not found carries its status and residual and no peaks: nothing is reported as an answer
//! that is not one. Deflections (m, from the settled rail, upward positive; peaks as magnitudes), moments (N·m,
//! sagging positive), positions s = x − vt (m, positive ahead of the load), powers (W).

pub use crate::stationary::csv::{POINT_COLUMNS, WAVE_COLUMNS, points_csv, wave_csv};

use fem_beam::{DeflectionExtremes, Extreme, LiftOffZone};
use scenario::Scenario;
use scenario::error::Result;
use serde::Serialize;
use stationary::refine::ERROR_FACTOR;
use stationary::{
    ContactGuess, Control, Convergence, Domain, PowerBalance, StationaryError, StationaryProblem, StationaryWave,
};

/// One slip zone of a wave: where the rail slides over the ballast.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SlipSummary {
    /// From (s, m).
    pub from: f64,
    /// To (s, m).
    pub to: f64,
    /// "up" where the rail rises as the load passes, "down" where it sinks.
    pub direction: &'static str,
}

/// The stationary wave at one speed, summarised.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StationaryPoint {
    /// v (m/s).
    pub speed: f64,
    /// "converged", "not converged", "domain too short" or "no stationary wave".
    pub status: &'static str,
    /// Newton solves taken (0 where no wave exists).
    pub iterations: usize,
    /// The relative residual of the last iterate (0 where no wave exists).
    pub residual: f64,
    /// Largest downward deflection (m, magnitude) and largest upward one (m), each where (s, m); None unless
    /// converged.
    #[serde(flatten)]
    pub deflection: DeflectionExtremes<Option<Extreme>>,
    /// Largest sagging moment (N·m) and where.
    pub max_moment: Option<Extreme>,
    /// Largest hogging moment (N·m, magnitude) and where.
    pub max_hogging_moment: Option<Extreme>,
    /// Deflection under the load (m, signed).
    pub deflection_under_load: Option<f64>,
    /// Deflection at the domain's rear end (m, signed): the residual deflection left behind.
    pub deflection_behind: Option<f64>,
    /// Where the rail left the soil (s, m), the largest gap of each zone (m) and where.
    pub lift_off_zones: Vec<LiftOffZone>,
    /// Where the rail slides over the ballast (none without friction).
    pub slip_zones: Vec<SlipSummary>,
    /// The power balance (W): the load's power against the dashpots', the friction's and what is left behind.
    pub power: Option<PowerBalance>,
    /// The domain behind and ahead of the load (m) and its element length (m).
    pub domain: (f64, f64, f64),
    /// The estimated discretisation error of the peaks (one halving of the elements), where estimated.
    pub discretisation_error: Option<PeakErrors>,
}

/// The estimated discretisation error of a wave's peaks: 2|P_h − P_{h/2}| with P_{h/2} the same wave solved on
/// elements half as long (`stationary::refine`: Richardson's estimate for first-order convergence, an upper one for
/// these peaks).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PeakErrors {
    /// Of the max downward deflection (m).
    pub max_downward_deflection: f64,
    /// Of the max sagging moment (N·m).
    pub max_moment: f64,
}

impl PeakErrors {
    /// The larger of the two errors relative to its peak.
    pub fn relative(&self, point: &StationaryPoint) -> f64 {
        let share = |e: f64, p: Option<f64>| p.map_or(0.0, |p| e / p.abs().max(f64::MIN_POSITIVE));
        let value = |e: Option<Extreme>| e.map(|e| e.value);
        share(self.max_downward_deflection, value(point.deflection.max_downward))
            .max(share(self.max_moment, value(point.max_moment)))
    }
}

/// Whether the stationary waves' peaks get a discretisation-error estimate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorEstimate {
    /// Each wave solved again on halved elements (about twice the cost).
    Halving,
    /// None: a study that fixes its own resolution.
    Skip,
}

/// What a reader of a nonlinear soil's waves must know: they need not be unique, and which branch is reported
/// (docs/theory.md §14); None on a linear soil, whose wave is.
pub fn branch_note(law: &str) -> Option<String> {
    (law != "linear").then(|| {
        format!(
            "on a {law} soil the stationary wave need not be unique (the tensionless reference track has two at \
             100 m/s, 61.5 and 68.6 mm deep): these are the branch continuation in speed from the static state \
             follows, the one a load brought up to speed reaches (docs/theory.md §14)"
        )
    })
}

/// The relative discretisation error of a peak above which `frictrack stationary` warns.
pub const ERROR_TOLERANCE: f64 = 1e-2;

/// The stationary waves of a scenario over its speeds.
#[derive(Debug, Clone)]
pub struct StationaryStudy {
    /// The rail in words where it is not Euler–Bernoulli's ("Timoshenko (G = 81 GPa, κ = 0.4)").
    pub rail_theory: Option<String>,
    /// The soil's law ("linear", "tensionless", "bilinear").
    pub law: &'static str,
    /// F (N).
    pub load: f64,
    /// The self-weight settlement (m), 0 on a linear soil or without weight.
    pub settlement: f64,
    /// The ballast's friction f_u (N/m), 0 without.
    pub friction: f64,
    /// One point per speed.
    pub points: Vec<StationaryPoint>,
    /// The waves, where found (None where no stationary wave exists at that speed).
    pub waves: Vec<Option<StationaryWave>>,
    /// Speeds (m/s) whose wave was found but whose error estimate was not: the wave on elements half as long did not
    /// converge there (above the critical speed of an undamped track with friction, often).
    pub unestimated: Vec<f64>,
}

impl StationaryStudy {
    /// Solve `speeds` (m/s, in the order given: each starts from the last one's contact set and wave, on the domain
    /// the last one grew to) on `domain`.
    pub fn of(scenario: &Scenario, speeds: &[f64], domain: Domain, estimate: ErrorEstimate) -> Result<Self> {
        Self::of_until(scenario, speeds, domain, estimate, None, &|_| {})
    }

    /// As [`Self::of`], stopping with [`StudyError::Interrupted`](scenario::StudyError::Interrupted) before the next
    /// speed (and before each error estimate) once `stop` is raised — a speed takes 1–75 ms (up to ~1 s where the
    /// domain grows with friction), so Ctrl-C is answered within about that — and telling `progress` the number of
    /// speeds done after each.
    pub fn of_until(
        scenario: &Scenario,
        speeds: &[f64],
        domain: Domain,
        estimate: ErrorEstimate,
        stop: Option<&std::sync::atomic::AtomicBool>,
        progress: &dyn Fn(usize),
    ) -> Result<Self> {
        let stopped = || stop.is_some_and(|s| s.load(std::sync::atomic::Ordering::Relaxed));
        let first = scenario.stationary_problem(speeds.first().copied().unwrap_or(0.0), domain)?;
        let law = first.foundation.law.name();
        let mut guess = ContactGuess::default();
        let (mut points, mut waves) = (Vec::with_capacity(speeds.len()), Vec::with_capacity(speeds.len()));
        let mut unestimated = Vec::new();
        // Each speed starts on the domain the last one grew to, where its wave (the guess) fits.
        let mut domain = domain;
        for &speed in speeds {
            if stopped() {
                return Err(scenario::StudyError::Interrupted);
            }
            let problem = StationaryProblem { speed, domain, ..first };
            match stationary::solve_within(&problem, &mut guess, &Control::new(stop)) {
                Ok(wave) => {
                    if wave.convergence.is_converged() {
                        (domain.behind, domain.ahead) = (-wave.s[0], *wave.s.last().unwrap_or(&domain.ahead));
                    }
                    let mut point = StationaryPoint::of(&wave);
                    if estimate == ErrorEstimate::Halving && wave.convergence.is_converged() && !stopped() {
                        point.discretisation_error = peak_errors(&problem, &wave, &Control::new(stop))?;
                        if point.discretisation_error.is_none() {
                            unestimated.push(speed);
                        }
                    }
                    points.push(point);
                    waves.push(Some(wave));
                }
                Err(StationaryError::NoRadiationCondition { .. }) => {
                    points.push(StationaryPoint::missing(speed, domain));
                    waves.push(None);
                }
                Err(other) => return Err(other.into()),
            }
            progress(points.len());
        }
        let friction = first.friction.force_per_length;
        let rail_theory = scenario.beam.theory.unless_default();
        let settlement = -first.far_level();
        Ok(Self { rail_theory, law, load: first.load, settlement, friction, points, waves, unestimated })
    }

    /// The point whose peaks have the largest relative discretisation error over the speeds estimated, and that
    /// error.
    pub fn largest_error(&self) -> Option<(&StationaryPoint, f64)> {
        let estimated = self.points.iter().filter_map(|p| Some((p, p.discretisation_error?.relative(p))));
        estimated.max_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// Warnings for the reader: peaks whose estimated discretisation error exceeds [`ERROR_TOLERANCE`], with the
    /// element length that would bring it under (the moment converges at second order: l·√(tolerance/error)).
    /// And the speeds whose peaks went unchecked because their error estimate failed.
    pub fn warnings(&self) -> Vec<String> {
        let mut warnings = Vec::new();
        if let Some((point, error)) = self.largest_error().filter(|&(_, e)| e > ERROR_TOLERANCE) {
            let (speed, l) = (point.speed, point.domain.2);
            warnings.push(format!(
                "domain.element_length = {l} m: the peaks are resolved only to {:.1} % at {speed} m/s (estimated from \
                 one halving of the elements); elements of {:.3} m or less bring them to {} %",
                100.0 * error,
                0.9 * l * (ERROR_TOLERANCE / error).sqrt(),
                100.0 * ERROR_TOLERANCE
            ));
        }
        if !self.unestimated.is_empty() {
            warnings.push(format!(
                "the peaks' discretisation error is not estimated at {} of {} speeds ({}): the wave on elements \
                 half as long did not converge there; compare with a solve on shorter elements \
                 (domain.element_length) to check them",
                self.unestimated.len(),
                self.points.len(),
                listed(&self.unestimated)
            ));
        }
        warnings
    }
}

/// The JSON a stationary sweep writes beside its CSV (`stationary --out DIR` writes `DIR/stationary.json`): the CSV's
/// name and columns with units, and the points.
#[derive(Debug, Clone, Serialize)]
pub struct StationaryFile<'a> {
    /// "wave.csv" (one speed's shape) or "speeds.csv" (the points).
    pub csv: &'static str,
    /// Name and unit of each column.
    pub columns: Vec<report::columns::ColumnMeta>,
    /// The points, one per speed.
    pub points: &'a [StationaryPoint],
    /// The version that wrote it.
    pub frictrack_version: &'static str,
}

impl StationaryStudy {
    /// The JSON beside the CSV `csv` of `columns`.
    pub fn file(&self, csv: &'static str, columns: &[report::columns::Column]) -> StationaryFile<'_> {
        StationaryFile {
            csv,
            columns: report::columns::listed(columns.iter().copied()),
            points: &self.points,
            frictrack_version: env!("CARGO_PKG_VERSION"),
        }
    }
}

/// The peaks' discretisation errors of `wave` (of `problem`) from its solution on halved elements; None where that
/// solve finds no wave.
/// Up to six speeds, then how many more: "208, 210, 212 m/s" or "200, 202, 204, 206, 208, 210 m/s and 5 more".
fn listed(speeds: &[f64]) -> String {
    let shown: Vec<String> = speeds.iter().take(6).map(|v| format!("{v}")).collect();
    match speeds.len() {
        n if n > 6 => format!("{} m/s and {} more", shown.join(", "), n - 6),
        _ => format!("{} m/s", shown.join(", ")),
    }
}

fn peak_errors(problem: &StationaryProblem, wave: &StationaryWave, control: &Control) -> Result<Option<PeakErrors>> {
    let halved = stationary::solve_halved(problem, wave, control)?;
    Ok(halved.convergence.is_converged().then(|| PeakErrors {
        max_downward_deflection: ERROR_FACTOR * (wave.max_downward().value - halved.max_downward().value).abs(),
        max_moment: ERROR_FACTOR * (wave.max_moment().value - halved.max_moment().value).abs(),
    }))
}

impl StationaryPoint {
    fn of(wave: &StationaryWave) -> Self {
        let (status, iterations, residual) = match wave.convergence {
            Convergence::Converged { iterations, residual } => ("converged", iterations, residual),
            Convergence::NotConverged { iterations, residual } => ("not converged", iterations, residual),
            Convergence::DomainTooShort { .. } => ("domain too short", 0, f64::NAN),
        };
        let found = status == "converged";
        let some = |x: f64| found.then_some(x);
        let peak = |x: Extreme| found.then_some(x);
        Self {
            speed: wave.speed,
            status,
            iterations,
            residual,
            deflection: DeflectionExtremes { max_downward: wave.max_downward(), max_upward: wave.max_upward() }
                .map(peak),
            max_moment: peak(wave.max_moment()),
            max_hogging_moment: peak(wave.min_moment()),
            deflection_under_load: some(wave.under_load()),
            deflection_behind: some(wave.behind()),
            lift_off_zones: match found {
                true => wave.lift_off.clone(),
                false => Vec::new(),
            },
            slip_zones: match found {
                true => wave
                    .slip_zones
                    .iter()
                    .map(|z| SlipSummary {
                        from: z.from,
                        to: z.to,
                        direction: if z.direction > 0.0 { "up" } else { "down" },
                    })
                    .collect(),
                false => Vec::new(),
            },
            power: found.then(|| wave.power_balance()),
            domain: (-wave.s[0], *wave.s.last().unwrap_or(&0.0), wave.element_length()),
            discretisation_error: None,
        }
    }

    fn missing(speed: f64, domain: Domain) -> Self {
        Self {
            speed,
            status: "no stationary wave",
            iterations: 0,
            residual: 0.0,
            deflection: DeflectionExtremes::default(),
            max_moment: None,
            max_hogging_moment: None,
            deflection_under_load: None,
            deflection_behind: None,
            lift_off_zones: Vec::new(),
            slip_zones: Vec::new(),
            power: None,
            domain: (domain.behind, domain.ahead, domain.element_length),
            discretisation_error: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn study(points: usize, unestimated: Vec<f64>) -> StationaryStudy {
        let point = StationaryPoint::missing(200.0, Domain::default());
        StationaryStudy {
            rail_theory: None,
            law: "linear",
            load: 83.4e3,
            settlement: 0.0,
            friction: 1e3,
            points: vec![point; points],
            waves: vec![None; points],
            unestimated,
        }
    }

    /// A wave whose error estimate failed is said so, by speed, not left out in silence.
    #[test]
    fn speeds_whose_estimate_failed_are_named_in_a_warning() {
        assert!(study(3, Vec::new()).warnings().is_empty());
        let warnings = study(11, vec![208.0, 210.0, 212.0]).warnings();
        assert_eq!(warnings.len(), 1, "{warnings:?}");
        assert!(warnings[0].contains("not estimated at 3 of 11 speeds (208, 210, 212 m/s)"), "{}", warnings[0]);
        let many: Vec<f64> = (0..9).map(|i| 200.0 + 2.0 * i as f64).collect();
        assert!(study(11, many).warnings()[0].contains("(200, 202, 204, 206, 208, 210 m/s and 3 more)"));
    }
}
