//! What the stationary-wave study computes on the infinite track, as its figures and summary read it: the soils
//! (linear at each ballast friction level, tensionless, bilinear), one curve of waves over speed per soil, and where
//! each curve peaks. Speeds in m/s, deflections in m, friction in N/m.

use crate::presets::setups::with_distributed;
use crate::stationary::output::StationaryStudy;
use scenario::{FoundationLawKind, Scenario};
use serde::Serialize;
use stationary::StationaryWave;

/// The ballast friction levels (N/m), as in the distributed-speed study.
pub(in crate::presets) const FRICTION: [f64; 5] = [0.0, 1e3, 2e3, 5e3, 10e3];

/// The bilinear soil's tension ratio α = k_t/k_c.
pub(in crate::presets) const TENSION_RATIO: f64 = 0.5;

/// One soil of the infinite track.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub(in crate::presets) struct Soil {
    /// "linear", "tensionless" or "bilinear".
    pub(in crate::presets) foundation: &'static str,
    /// f_u (N/m).
    pub(in crate::presets) force_per_length: f64,
}

impl Soil {
    /// The curves of the study: the linear soil at every friction level, then the nonlinear ones without friction.
    pub(in crate::presets) fn all() -> Vec<Soil> {
        let linear = FRICTION.iter().map(|&f| Soil { foundation: "linear", force_per_length: f });
        let nonlinear = ["tensionless", "bilinear"].map(|foundation| Soil { foundation, force_per_length: 0.0 });
        linear.chain(nonlinear).collect()
    }

    /// Legend text.
    pub(in crate::presets) fn label(&self) -> String {
        match (self.foundation, self.force_per_length) {
            ("linear", 0.0) => "no friction".into(),
            ("linear", f) => format!("f_u = {} kN/m", f / 1e3),
            ("bilinear", _) => format!("bilinear soil, α = {TENSION_RATIO}"),
            (other, _) => format!("{other} soil"),
        }
    }

    /// `base` with this soil: its law (with the rail's weight on a nonlinear one) and its ballast friction.
    pub(in crate::presets) fn scenario(&self, base: &Scenario) -> Scenario {
        let mut s = with_distributed(base, self.force_per_length);
        let f = &mut s.foundation;
        (f.law, f.tension_ratio, f.self_weight) = match self.foundation {
            "tensionless" => (FoundationLawKind::Tensionless, None, true),
            "bilinear" => (FoundationLawKind::Bilinear, Some(TENSION_RATIO), true),
            _ => (FoundationLawKind::Linear, None, f.self_weight),
        };
        s
    }
}

/// Where a curve of the infinite track peaks.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "location")]
pub enum InfiniteCritical {
    /// Between two sampled speeds, refined by golden section to 2 % of the speed step.
    Interior {
        /// v (m/s).
        speed: f64,
        /// Max downward deflection there (m).
        peak: f64,
    },
    /// At the first or last speed with a wave (the sampled largest).
    AtEnd {
        /// v (m/s).
        speed: f64,
        /// Max downward deflection there (m).
        peak: f64,
    },
    /// Growing without bound towards v_cr: undamped and without friction no wave exists from v_cr on.
    Unbounded {
        /// v_cr (m/s).
        critical_speed: f64,
        /// The largest sampled peak below it (m).
        last_peak: f64,
    },
    /// No speed had a wave.
    None,
}

/// One curve of the infinite track: its soil, its waves, where it peaks.
pub(in crate::presets) struct InfiniteCurve {
    pub(in crate::presets) soil: Soil,
    pub(in crate::presets) study: StationaryStudy,
    pub(in crate::presets) critical: InfiniteCritical,
    /// The refinement's waves: (speed m/s, max downward deflection m), drawn with the sweep so that the refined peak
    /// lies on its curve (near an undamped resonance the sampled speeds miss it by a factor of three).
    pub(in crate::presets) refinement: Vec<(f64, f64)>,
    /// The waves at the shape speeds (None where none was found).
    pub(in crate::presets) shapes: Vec<Option<StationaryWave>>,
}
