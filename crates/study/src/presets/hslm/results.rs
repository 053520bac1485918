//! What the HSLM study found, as its figures, headline and summary read it: a curve per train and friction set-up
//! (the sweep, its refined peaks, the train's static maximum and resonances) and the queries over them (the critical
//! curve, the envelope over the trains, the trains that fail the deck check). Speeds in m/s, deflections in m,
//! accelerations in m/s².

use super::resonances::Resonance;
use super::verdict::DeckLimit;
use fem_beam::train::HSLM_A;
use runner::{CriticalSpeed, RefinedPeak, SweepPoint};

/// Coach length D (m) of HSLM-A`k`, k = 1 … 10.
pub(in crate::presets) fn coach_length(k: usize) -> f64 {
    HSLM_A[k - 1].1
}

/// One train under one friction set-up.
pub(in crate::presets) struct TrainCurve {
    /// k of HSLM-Ak.
    pub(in crate::presets) train: usize,
    /// 0 = no friction, 1 = the friction set-up.
    pub(in crate::presets) friction: usize,
    /// The sweep: the study's speeds and this train's resonance speeds f₁·D/i inside the range, in increasing speed.
    pub(in crate::presets) points: Vec<SweepPoint>,
    /// The refined critical speed of the max downward deflection.
    pub(in crate::presets) critical: CriticalSpeed,
    /// The refined peak of the max acceleration.
    pub(in crate::presets) acceleration: RefinedPeak,
    /// The sweep and both refinements' runs, in increasing speed: what the figures draw, so that every refined
    /// peak sits on its curve.
    pub(in crate::presets) drawn: Vec<SweepPoint>,
    /// Largest static downward deflection of the train over its crossing (m).
    pub(in crate::presets) static_max: f64,
    /// Resonance speeds inside the swept range.
    pub(in crate::presets) resonances: Vec<Resonance>,
}

impl TrainCurve {
    /// The refined peak of the max downward deflection over the train's static maximum.
    pub(in crate::presets) fn peak_amplification(&self) -> f64 {
        self.critical.max_downward_deflection / self.static_max
    }
}

/// Everything the study found.
pub(in crate::presets) struct Results {
    /// The curves, friction set-up major, train minor.
    pub(in crate::presets) curves: Vec<TrainCurve>,
    /// What the beam carries of the HSLM axles (a rail: half; a deck: all).
    pub(in crate::presets) axle_share: scenario::AxleShare,
    /// The friction set-up, in words.
    pub(in crate::presets) friction: String,
    /// f₁ … f₃ (Hz), if the model's eigenproblem was solved.
    pub(in crate::presets) frequencies: Option<Vec<f64>>,
    /// The deck-acceleration limit each train is checked against (spans only).
    pub(in crate::presets) acceleration_limit: Option<DeckLimit>,
    /// The load advance used (m).
    pub(in crate::presets) load_advance: f64,
    /// Refinement tolerance (m/s): golden section stops on a bracket this wide.
    pub(in crate::presets) tolerance: f64,
    /// The nodes the extremes are taken over (m), if not all.
    pub(in crate::presets) extremes_nodes: Option<[f64; 2]>,
}

impl Results {
    /// The curves of one friction set-up.
    pub(in crate::presets) fn set(&self, friction: usize) -> impl Iterator<Item = &TrainCurve> {
        self.curves.iter().filter(move |c| c.friction == friction)
    }

    /// Legend text of a friction set-up.
    pub(in crate::presets) fn friction_label(&self, friction: usize) -> String {
        if friction == 0 { "no friction".into() } else { self.friction.clone() }
    }

    /// The critical curve of a friction set-up: the largest refined peak of the max downward deflection.
    pub(in crate::presets) fn critical(&self, friction: usize) -> &TrainCurve {
        let by_peak = |a: &&TrainCurve, b: &&TrainCurve| {
            a.critical.max_downward_deflection.total_cmp(&b.critical.max_downward_deflection)
        };
        self.set(friction).max_by(by_peak).expect("ten trains")
    }

    /// The curve with the largest refined peak of the max acceleration of a friction set-up.
    pub(in crate::presets) fn acceleration_critical(&self, friction: usize) -> &TrainCurve {
        let peak = |c: &&TrainCurve| c.acceleration.value;
        self.set(friction).max_by(|a, b| peak(a).total_cmp(&peak(b))).expect("ten trains")
    }

    /// The trains (k of HSLM-Ak) of a friction set-up that fail the deck check (none without a limit).
    pub(in crate::presets) fn failing(&self, friction: usize) -> Vec<usize> {
        let fails = |c: &&TrainCurve| self.acceleration_limit.is_some_and(|l| l.verdict(&c.acceleration).fails());
        self.set(friction).filter(fails).map(|c| c.train).collect()
    }

    /// The envelope of `value` over the ten trains of a friction set-up: at every speed any curve drew (the sweep
    /// and the refinements' runs), the largest of the trains' curves there (each linearly interpolated between its
    /// own speeds), so that it passes through every refined peak.
    pub(in crate::presets) fn envelope(&self, friction: usize, value: fn(&SweepPoint) -> f64) -> Vec<(f64, f64)> {
        let curves: Vec<&TrainCurve> = self.set(friction).collect();
        let mut speeds: Vec<f64> = curves.iter().flat_map(|c| c.drawn.iter().map(|p| p.speed)).collect();
        speeds.sort_by(f64::total_cmp);
        speeds.dedup();
        speeds
            .into_iter()
            .map(|v| (v, curves.iter().map(|c| interpolate(&c.drawn, v, value)).fold(f64::NEG_INFINITY, f64::max)))
            .collect()
    }
}

/// `value` of the sweep linearly interpolated at `speed` (m/s) inside its range.
pub(in crate::presets) fn interpolate(points: &[SweepPoint], speed: f64, value: fn(&SweepPoint) -> f64) -> f64 {
    let i = points.partition_point(|p| p.speed < speed).clamp(1, points.len() - 1);
    let (a, b) = (&points[i - 1], &points[i]);
    let t = if b.speed > a.speed { (speed - a.speed) / (b.speed - a.speed) } else { 0.0 };
    value(a) + t * (value(b) - value(a))
}

/// A deflection (m) in mm with three significant digits: bridges deflect ~1 mm, the soft-soil track ~300 mm.
pub(in crate::presets) fn millimetres(w: f64) -> String {
    let mm = w * 1e3;
    let decimals = (2 - mm.abs().max(1e-12).log10().floor() as i32).clamp(0, 6) as usize;
    format!("{mm:.decimals$} mm")
}

/// The name of a friction set-up in the files: 0 "none", 1 "with".
pub(in crate::presets) fn friction_name(friction: usize) -> &'static str {
    if friction == 0 { "none" } else { "with" }
}
