//! Speeds that follow the case (docs/theory.md §2, §7): sweeps and studies sample around the critical speed of the
//! infinite beam on the case's foundation, v_cr = (4 k_f EI/(ρA)²)^¼, instead of a fixed range.
//!
//! The reference case (v_cr = 205.57 m/s) gets exactly the range of docs/theory.md §7: a step of v_cr/20.557 rounded to a
//! "nice" number (1, 2, 2.5 or 5 × 10ᵏ m/s: 10 m/s), from one step to 1.46·v_cr rounded to the step (10–300 m/s).
//! A stiff soil, k_f = 10 MN/m² (v_cr ≈ 517 m/s), gets 25–750 m/s by 25. Without a foundation (k_f = 0, a bridge
//! span) there is no v_cr and the reference range is kept; on sleepers the scale is the equivalent continuous
//! track's; over an `[embankment]` that of both rails, their sleepers and the embankment as one beam on the soil (one
//! rail's share on half of it moves alike). Fixed-speed studies scale the same way: a fraction f of v_cr rounded to
//! five steps (the reference's 50, 100, 150, 200 m/s), the optimal-force speed to a tenth of a step (206 m/s).

use crate::error::Result;
use crate::{Scenario, SweepSection};
use analytic::MovingBeam;

/// The most speeds one sweep, stationary solve or closed-form table takes, from the command line, a scenario's
/// `[sweep]` or Python: a million runs of even a 10 ms case are ~3 h on all cores of a workstation.
pub const MAX_SPEEDS: usize = 1_000_000;

/// Refuse more than [`MAX_SPEEDS`] speeds, naming `field` and the count (before anything runs or is allocated for
/// them).
pub fn check_count(field: &str, count: usize) -> Result<()> {
    if count > MAX_SPEEDS {
        return Err(crate::error::invalid(field, count, format!("speeds: at most {MAX_SPEEDS} are taken at once")));
    }
    Ok(())
}

/// The speed scale of a case.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedScale {
    /// v_cr of the infinite beam (m/s); `None` without a foundation.
    pub critical_speed: Option<f64>,
    /// The sweep step (m/s).
    pub step: f64,
    /// β = (k_f/4EI)^¼ of the same track (1/m; [`MovingBeam::bending_wavenumber`]); `None` without a foundation.
    pub bending_wavenumber: Option<f64>,
}

/// v_cr of the reference case divided by its sweep step of 10 m/s.
const STEPS_TO_CRITICAL: f64 = 20.557;
/// The top of a default range as a multiple of v_cr (300 m/s for the reference case).
const TOP_OVER_CRITICAL: f64 = 1.46;

impl SpeedScale {
    /// The scale of `scenario`: the critical speed of its track ([`MovingBeam::of_track`]: the rail as it is, on
    /// sleepers their long-wave twin), none on a beam without any support (k_f = 0, no sleepers).
    pub fn of(scenario: &Scenario) -> Result<Self> {
        if scenario.sleepers.is_none() && scenario.foundation.stiffness <= 0.0 {
            return Ok(Self { critical_speed: None, step: 10.0, bending_wavenumber: None });
        }
        let sleepers = scenario.sleepers.as_ref().map(|s| s.sleepers()).transpose()?;
        if let (Some(embankment), Some(sleepers)) = (&scenario.embankment, &sleepers) {
            // The two-beam track's long wave: both rails, their sleepers and the embankment as one beam on the soil.
            let one = embankment.embankment()?.whole_track(&scenario.beam, sleepers);
            let soil = fem_beam::Foundation::linear(scenario.foundation.stiffness, 0.0);
            return Ok(Self::of_beam(&MovingBeam::new(&one, &soil)?));
        }
        let foundation = fem_beam::Foundation::linear(scenario.foundation.stiffness, 0.0);
        Ok(Self::of_beam(&MovingBeam::of_track(&scenario.beam, &foundation, sleepers.as_ref())?))
    }

    /// The scale of a track whose moving frame is `beam`.
    fn of_beam(beam: &MovingBeam) -> Self {
        let critical = beam.critical_speed();
        Self {
            critical_speed: Some(critical),
            step: nice(critical / STEPS_TO_CRITICAL),
            bending_wavenumber: Some(beam.bending_wavenumber()),
        }
    }

    /// The default sweep: one step to 1.46·v_cr, rounded to the step (10–300 m/s by 10 for the reference case).
    pub fn default_range(&self) -> SweepSection {
        let top = self.critical_speed.map_or(300.0, |v| (TOP_OVER_CRITICAL * v / self.step).round() * self.step);
        SweepSection { from: self.step, to: top, step: self.step }
    }

    /// `fraction`·v_cr rounded to five steps (at least five steps); `fallback` without a foundation.
    pub fn fraction(&self, fraction: f64, fallback: f64) -> f64 {
        let unit = 5.0 * self.step;
        self.critical_speed.map_or(fallback, |v| ((fraction * v / unit).round() * unit).max(unit))
    }

    /// v_cr rounded to a tenth of a step (206 m/s for the reference case); `fallback` without a foundation.
    pub fn near_critical(&self, fallback: f64) -> f64 {
        let unit = 0.1 * self.step;
        self.critical_speed.map_or(fallback, |v| (v / unit).round() * unit)
    }
}

/// The number of the form {1, 2, 2.5, 5}·10ᵏ nearest to `x` > 0 in ratio.
fn nice(x: f64) -> f64 {
    let decade = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0]
        .into_iter()
        .map(|m| m * decade)
        .min_by(|a, b| (x / a).ln().abs().total_cmp(&(x / b).ln().abs()))
        .expect("five candidates")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_case_keeps_the_ranges_of_model_md() {
        let scale = SpeedScale::of(&Scenario::default()).unwrap();
        assert_eq!(scale.default_range(), SweepSection { from: 10.0, to: 300.0, step: 10.0 });
        let fixed: Vec<f64> = [0.25, 0.5, 0.75, 1.0].iter().map(|&f| scale.fraction(f, 0.0)).collect();
        assert_eq!(fixed, [50.0, 100.0, 150.0, 200.0]);
        assert_eq!(scale.near_critical(0.0), 206.0);
    }

    #[test]
    fn stiff_soil_range_covers_its_critical_speed() {
        let mut stiff = Scenario::default();
        stiff.foundation.stiffness = 1e7;
        let scale = SpeedScale::of(&stiff).unwrap();
        let v_cr = scale.critical_speed.unwrap();
        assert!((v_cr - 517.0).abs() < 1.0, "{v_cr}");
        let range = scale.default_range();
        assert_eq!((range.from, range.to, range.step), (25.0, 750.0, 25.0));
        assert!(range.from < 0.1 * v_cr && range.to > 1.4 * v_cr);
    }

    #[test]
    fn nice_numbers() {
        assert_eq!(nice(10.0), 10.0);
        assert_eq!(nice(25.2), 25.0);
        assert_eq!(nice(0.13), 0.1);
        assert_eq!(nice(3.4), 2.5);
        assert_eq!(nice(3.6), 5.0);
    }
}
