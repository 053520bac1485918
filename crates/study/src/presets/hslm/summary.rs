//! What the HSLM study says of its results (`study hslm --format json`, the report's lines): the set-up, each
//! train's refined peaks and deck verdict, the envelope over the ten trains per friction set-up. Speeds in m/s,
//! deflections in m, accelerations in m/s², frequencies in Hz.

use super::resonances::Resonance;
use super::results::{Results, TrainCurve, coach_length, friction_name, millimetres};
use super::study::PEAK_SCAN;
use report::run_summary::AxleShareSummary;
use runner::PeakLocation;
use scenario::units::KMH;
use serde::Serialize;

/// The HSLM study's summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HslmSummary {
    /// How the peaks were refined, in words.
    pub refinement: String,
    /// The refinement's bracket (m/s).
    pub refinement_tolerance: f64,
    /// What the beam carries of the axle loads.
    pub axle_share: AxleShareSummary,
    /// The friction set-up, in words.
    pub friction_setup: String,
    /// f₁ … f₃ of a span (Hz).
    pub natural_frequencies: Option<Vec<f64>>,
    /// Δx (m).
    pub load_advance: f64,
    /// The nodes the extremes are taken over (m), if not all.
    pub extremes_nodes: Option<[f64; 2]>,
    /// The deck-acceleration limit (m/s²), on a span.
    pub acceleration_limit: Option<f64>,
    /// "ballasted" or "direct-fastening", on a span.
    pub deck_track: Option<&'static str>,
    /// One per train and friction set-up.
    pub curves: Vec<TrainSummary>,
    /// The envelope of the ten trains per friction set-up.
    pub envelopes: Vec<EnvelopeSummary>,
}

/// One train under one friction set-up.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrainSummary {
    /// "hslm-a1" … "hslm-a10".
    pub train: String,
    /// D (m).
    pub coach_length: f64,
    /// "none" or "with".
    pub friction: &'static str,
    /// m.
    pub static_max_downward_deflection: f64,
    /// The refined critical speed of the max downward deflection (m/s) and where it lies.
    pub critical_speed: f64,
    /// Interior or an end of the range.
    pub critical_speed_location: PeakLocation,
    /// m.
    pub peak_max_downward_deflection: f64,
    /// Peak over the static maximum.
    pub peak_dynamic_amplification: f64,
    /// The refined peak of the max acceleration (m/s²), its speed (m/s) and where it lies.
    pub peak_max_acceleration: f64,
    /// m/s.
    pub peak_acceleration_speed: f64,
    /// Interior or an end.
    pub peak_acceleration_location: PeakLocation,
    /// The sampled largest acceleration (m/s²).
    pub peak_max_acceleration_sampled: f64,
    /// Runs added by the refinements.
    pub refinement_runs: usize,
    /// The train's resonance speeds f_j·D/i inside the range.
    pub resonance_speeds: Vec<Resonance>,
    /// Acceleration over the deck limit, on a span.
    pub acceleration_over_limit: Option<f64>,
    /// The deck check's verdict, on a span.
    pub deck_verdict: Option<&'static str>,
}

/// The envelope of the ten trains under one friction set-up.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EnvelopeSummary {
    /// "none" or "with".
    pub friction: &'static str,
    /// The train with the largest refined deflection peak, its speed (m/s) and where it lies.
    pub critical_train: String,
    /// m/s.
    pub critical_speed: f64,
    /// Interior or an end.
    pub critical_speed_location: PeakLocation,
    /// m.
    pub peak_max_downward_deflection: f64,
    /// Peak over that train's static maximum.
    pub dynamic_amplification: f64,
    /// The train with the largest refined acceleration, its speed (m/s) and where it lies.
    pub acceleration_train: String,
    /// m/s.
    pub acceleration_speed: f64,
    /// Interior or an end.
    pub acceleration_location: PeakLocation,
    /// m/s².
    pub peak_max_acceleration: f64,
    /// Over the deck limit, on a span.
    pub acceleration_over_limit: Option<f64>,
    /// The deck check's verdict, on a span.
    pub deck_verdict: Option<&'static str>,
    /// The trains over the limit, on a span.
    pub trains_over_limit: Option<Vec<String>>,
}

impl Results {
    /// One train's curve: its summary line (into `lines`) and its JSON.
    fn curve_summary(&self, c: &TrainCurve, lines: &mut Vec<String>) -> TrainSummary {
        let a = &c.acceleration;
        let text = if c.critical.is_interior() {
            format!(
                "critical speed {:.1} m/s ({:.0} km/h), peak {} (DAF {:.3})",
                c.critical.speed,
                c.critical.speed * KMH,
                millimetres(c.critical.max_downward_deflection),
                c.peak_amplification()
            )
        } else {
            c.critical.describe()
        };
        let bound = if a.is_interior() { "" } else { " (at an end of the speed range: a bound)" };
        let verdict = self.acceleration_limit.map(|l| l.verdict(a));
        lines.push(format!(
            "HSLM-A{} (D = {} m), {}: {text}; max acceleration {:.3} m/s² at {:.1} km/h{bound}{}",
            c.train,
            coach_length(c.train),
            self.friction_label(c.friction),
            a.value,
            a.speed * KMH,
            verdict.map_or(String::new(), |v| format!("; deck check {}", v.describe())),
        ));
        TrainSummary {
            train: format!("hslm-a{}", c.train),
            coach_length: coach_length(c.train),
            friction: friction_name(c.friction),
            static_max_downward_deflection: c.static_max,
            critical_speed: c.critical.speed,
            critical_speed_location: c.critical.location,
            peak_max_downward_deflection: c.critical.max_downward_deflection,
            peak_dynamic_amplification: c.peak_amplification(),
            peak_max_acceleration: a.value,
            peak_acceleration_speed: a.speed,
            peak_acceleration_location: a.location,
            peak_max_acceleration_sampled: a.sweep_maximum.1,
            refinement_runs: c.drawn.len() - c.points.len(),
            resonance_speeds: c.resonances.clone(),
            acceleration_over_limit: verdict.map(|v| v.utilisation()),
            deck_verdict: verdict.map(|v| v.name()),
        }
    }

    /// The envelope of the ten trains under friction set-up `friction`: its line (into `lines`) and its JSON.
    fn envelope_summary(&self, friction: usize, lines: &mut Vec<String>) -> EnvelopeSummary {
        let c = self.critical(friction);
        let a = self.acceleration_critical(friction);
        let p = &a.acceleration;
        let verdict = self.acceleration_limit.map(|l| l.verdict(p));
        lines.push(format!(
            "{}, envelope of the ten trains: HSLM-A{} at {:.1} m/s ({:.0} km/h), {} (DAF {:.3}){}; max \
             acceleration {:.3} m/s² from HSLM-A{} at {:.1} km/h{}{}",
            self.friction_label(friction),
            c.train,
            c.critical.speed,
            c.critical.speed * KMH,
            millimetres(c.critical.max_downward_deflection),
            c.peak_amplification(),
            if c.critical.is_interior() { "" } else { ", at an end of the speed range: a bound" },
            p.value,
            a.train,
            p.speed * KMH,
            if p.is_interior() { "" } else { " (at an end of the speed range: a bound)" },
            self.acceleration_limit.map_or(String::new(), |l| format!(
                "; deck check against {}: {} of the ten trains fail",
                l.describe(),
                self.failing(friction).len()
            )),
        ));
        EnvelopeSummary {
            friction: friction_name(friction),
            critical_train: format!("hslm-a{}", c.train),
            critical_speed: c.critical.speed,
            critical_speed_location: c.critical.location,
            peak_max_downward_deflection: c.critical.max_downward_deflection,
            dynamic_amplification: c.peak_amplification(),
            acceleration_train: format!("hslm-a{}", a.train),
            acceleration_speed: p.speed,
            acceleration_location: p.location,
            peak_max_acceleration: p.value,
            acceleration_over_limit: verdict.map(|v| v.utilisation()),
            deck_verdict: verdict.map(|v| v.name()),
            trains_over_limit: self
                .acceleration_limit
                .map(|_| self.failing(friction).iter().map(|k| format!("hslm-a{k}")).collect()),
        }
    }

    pub(in crate::presets) fn summary(&self) -> (HslmSummary, Vec<String>) {
        let mut lines = Vec::new();
        let curves = self.curves.iter().map(|c| self.curve_summary(c, &mut lines)).collect();
        let envelopes = (0..2).map(|friction| self.envelope_summary(friction, &mut lines)).collect();
        let refinement = format!(
            "every maximum (deflection and acceleration, per train and the envelopes) is refined on fresh runs around \
             its sampled maximum: {PEAK_SCAN} samples of the bracket between the neighbouring speeds, then golden \
             section to {:.3} m/s ({:.2} km/h); the speeds include each train's resonance speeds f₁·D/i",
            self.tolerance,
            self.tolerance * KMH
        );
        lines.push(refinement.clone());
        lines.push(format!(
            "axle loads as the beam carries them: {} ([load] carries = \"{}\", × {})",
            self.axle_share.describe(),
            self.axle_share.name(),
            self.axle_share.factor()
        ));
        let summary = HslmSummary {
            refinement,
            refinement_tolerance: self.tolerance,
            axle_share: AxleShareSummary::of(self.axle_share),
            friction_setup: self.friction.clone(),
            natural_frequencies: self.frequencies.clone(),
            load_advance: self.load_advance,
            extremes_nodes: self.extremes_nodes,
            acceleration_limit: self.acceleration_limit.map(|l| l.value),
            deck_track: self.acceleration_limit.map(|l| l.track.name()),
            curves,
            envelopes,
        };
        (summary, lines)
    }
}
