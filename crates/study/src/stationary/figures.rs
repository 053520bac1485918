//! The figures of `frictrack stationary` (docs/theory.md §14): one speed's wave — deflection, bending moment and,
//! with ballast friction, the ballast's force along s — or several speeds' peaks against the speed. Deflections in
//! mm, moments in kN·m, forces in kN/m, s in m.

use crate::stationary::output::{StationaryPoint, StationaryStudy};
use report::plot::{PlotSpec, Series, Stroke};
use scenario::axis::{Axis, Shown};
use stationary::StationaryWave;

impl StationaryStudy {
    /// The figures: with one speed the wave's deflection and moment along s; with several the peak deflections
    /// against speed (converged speeds only).
    pub fn figures(&self, title: &str) -> Vec<PlotSpec> {
        let friction = match self.friction > 0.0 {
            true => format!(", ballast friction f_u = {:.1} kN/m", self.friction / 1e3),
            false => String::new(),
        };
        let subtitle = format!(
            "{} soil{friction}, F = {:.1} kN, s = x − vt (positive ahead of the load)",
            self.law,
            self.load / 1e3
        );
        match self.waves.as_slice() {
            [Some(wave)] => vec![self.wave_figure(wave, title, subtitle)],
            _ => vec![self.peaks_figure(title, subtitle)],
        }
    }

    /// One speed's wave: deflection, moment and — with ballast friction — the ballast's force along s, a panel each.
    fn wave_figure(&self, wave: &StationaryWave, title: &str, subtitle: String) -> PlotSpec {
        let s_axis = Axis::new("s = x − vt", "s", Shown::Si);
        let mut shape = PlotSpec::new("stationary-wave", title, &s_axis, &Axis::none());
        shape.subtitle = format!("{subtitle}, v = {:.1} m/s", wave.speed);
        let panel = |heading: &str, y: Axis, label: &str, color: usize, values: &[f64]| {
            let mut panel = PlotSpec::new("", heading, &s_axis, &y);
            let points = wave.s.iter().zip(values).map(|(s, v)| (*s, v * y.factor())).collect();
            panel.series.push(Series {
                label: Some(label.into()),
                color,
                stroke: Stroke::Solid,
                markers: false,
                points,
            });
            panel
        };
        shape.panels = vec![
            panel(
                "deflection from the settled rail",
                Axis::new("w", "deflection", Shown::Milli),
                "W(s)",
                1,
                &wave.deflection,
            ),
            panel("bending moment", Axis::new("M", "moment", Shown::Kilo), "EI W″(s)", 2, &wave.moment),
        ];
        if self.friction > 0.0 {
            shape.panels.push(panel(
                "ballast friction (flat at ±f_u where the rail slides)",
                Axis::new("r", "force_per_length", Shown::Kilo),
                "r(s)",
                3,
                &wave.friction_force,
            ));
        }
        shape
    }

    /// The peak deflections against speed, downward solid and upward dashed (converged speeds only).
    fn peaks_figure(&self, title: &str, subtitle: String) -> PlotSpec {
        let (speed, peak) =
            (Axis::new("speed v", "speed", Shown::Si), Axis::new("peak deflection", "deflection", Shown::Milli));
        let mut peaks = PlotSpec::new("stationary-peaks", title, &speed, &peak);
        let missing: Vec<f64> = self.points.iter().filter(|p| p.status != "converged").map(|p| p.speed).collect();
        peaks.subtitle = match (missing.first(), missing.last()) {
            (Some(a), Some(b)) => format!(
                "{subtitle}; no wave found at {} of {} speeds ({a:.0}–{b:.0} m/s)",
                missing.len(),
                self.points.len()
            ),
            _ => subtitle,
        };
        let converged: Vec<&StationaryPoint> = self.points.iter().filter(|p| p.status == "converged").collect();
        let mm = peak.factor();
        for (label, stroke, values) in [
            (
                "downward",
                Stroke::Solid,
                converged.iter().filter_map(|p| Some((p.speed, p.deflection.max_downward?.value * mm))).collect(),
            ),
            (
                "upward",
                Stroke::Dashed,
                converged.iter().filter_map(|p| Some((p.speed, p.deflection.max_upward?.value * mm))).collect(),
            ),
        ] {
            peaks.series.push(Series { label: Some(label.into()), color: 1, stroke, markers: true, points: values });
        }
        peaks
    }
}
