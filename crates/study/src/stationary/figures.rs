//! The figures of `frictrack stationary` (docs/theory.md §14): one speed's wave — deflection, bending moment and,
//! with ballast friction, the ballast's force along s — or several speeds' peaks against the speed. Deflections in
//! mm, moments in kN·m, forces in kN/m, s in m.

use crate::stationary::output::{StationaryPoint, StationaryStudy};
use report::plot::{PlotSpec, Series, Stroke};
use scenario::axis::{Axis, Shown};

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
        if let [Some(wave)] = self.waves.as_slice() {
            let mut shape =
                PlotSpec::new("stationary-wave", title, &Axis::new("s = x − vt", "s", Shown::Si), &Axis::none());
            shape.subtitle = format!("{subtitle}, v = {:.1} m/s", wave.speed);
            let line = |label: &str, color: usize, values: Vec<(f64, f64)>| Series {
                label: Some(label.into()),
                color,
                stroke: Stroke::Solid,
                markers: false,
                points: values,
            };
            let mut deflection = PlotSpec::new(
                "",
                "deflection from the settled rail",
                &Axis::new("s = x − vt", "s", Shown::Si),
                &Axis::new("w", "deflection", Shown::Milli),
            );
            deflection.series.push(line(
                "W(s)",
                1,
                wave.s.iter().zip(&wave.deflection).map(|(s, w)| (*s, w * 1e3)).collect(),
            ));
            let mut moment = PlotSpec::new(
                "",
                "bending moment",
                &Axis::new("s = x − vt", "s", Shown::Si),
                &Axis::new("M", "moment", Shown::Kilo),
            );
            moment.series.push(line(
                "EI W″(s)",
                2,
                wave.s.iter().zip(&wave.moment).map(|(s, m)| (*s, m / 1e3)).collect(),
            ));
            shape.panels = vec![deflection, moment];
            if self.friction > 0.0 {
                let mut resistance = PlotSpec::new(
                    "",
                    "ballast friction (flat at ±f_u where the rail slides)",
                    &Axis::new("s = x − vt", "s", Shown::Si),
                    &Axis::new("r", "force_per_length", Shown::Kilo),
                );
                resistance.series.push(line(
                    "r(s)",
                    3,
                    wave.s.iter().zip(&wave.friction_force).map(|(s, r)| (*s, r / 1e3)).collect(),
                ));
                shape.panels.push(resistance);
            }
            return vec![shape];
        }
        let mut peaks = PlotSpec::new(
            "stationary-peaks",
            title,
            &Axis::new("speed v", "speed", Shown::Si),
            &Axis::new("peak deflection", "deflection", Shown::Milli),
        );
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
        for (label, stroke, values) in [
            (
                "downward",
                Stroke::Solid,
                converged.iter().filter_map(|p| Some((p.speed, p.deflection.max_downward?.value * 1e3))).collect(),
            ),
            (
                "upward",
                Stroke::Dashed,
                converged.iter().filter_map(|p| Some((p.speed, p.deflection.max_upward?.value * 1e3))).collect(),
            ),
        ] {
            peaks.series.push(Series { label: Some(label.into()), color: 1, stroke, markers: true, points: values });
        }
        vec![peaks]
    }
}
