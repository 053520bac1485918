//! The two sentences of the train study's report section: the critical train without and with friction, and by how
//! much friction moves the peak.

use super::results::{Results, TrainCurve, millimetres};
use runner::PeakLocation;
use scenario::units::KMH;

impl Results {
    /// Without friction the critical train, its speed, peak, amplification and the largest acceleration; with
    /// friction the same and the change of the peak.
    pub(in crate::presets) fn headline(&self) -> Vec<String> {
        let (none, with) = (self.envelope_text(0), self.envelope_text(1));
        let peak = |friction| self.critical(friction).critical.max_downward_deflection;
        let cut = 1.0 - peak(1) / peak(0);
        vec![
            format!("Without friction the critical train is {none}."),
            format!(
                "With {} the peak deflection is {:.0} % {}: {with}.",
                self.friction,
                100.0 * cut.abs(),
                if cut >= 0.0 { "lower" } else { "higher" },
            ),
        ]
    }

    /// The envelope of the ten trains under friction set-up `friction`, in words. On a span the beam is the deck and
    /// EN 1990 limits its acceleration; on a track it is the rail.
    fn envelope_text(&self, friction: usize) -> String {
        let c: &TrainCurve = self.critical(friction);
        let a = self.acceleration_critical(friction);
        let speed = c.critical.speed;
        let at = match c.critical.location {
            PeakLocation::UpperEnd => "at or above",
            PeakLocation::LowerEnd => "at or below",
            PeakLocation::Interior => "at",
        };
        let acceleration = a.acceleration.value;
        let acceleration = match self.acceleration_limit {
            Some(l) => {
                let failing = self.failing(friction);
                let failing = match failing.len() {
                    0 => "every train passes".to_string(),
                    n => {
                        let trains: Vec<String> = failing.iter().map(|k| format!("A{k}")).collect();
                        format!("{n} of the ten trains fail: HSLM-{}", trains.join(", "))
                    }
                };
                format!(
                    "deck acceleration, {acceleration:.2} m/s² ({:.2} × {}: {failing})",
                    acceleration / l.value,
                    l.describe()
                )
            }
            None => format!("rail acceleration, {acceleration:.0} m/s²"),
        };
        format!(
            "HSLM-A{} {at} {:.0} km/h ({speed:.1} m/s): max downward deflection {}, dynamic amplification {:.2}; the \
             largest {acceleration}, comes from HSLM-A{} at {:.0} km/h",
            c.train,
            KMH * speed,
            millimetres(c.critical.max_downward_deflection),
            c.peak_amplification(),
            a.train,
            KMH * a.acceleration.speed
        )
    }
}
