//! The figures of the HSLM study ([`super::hslm`]), speeds in km/h as the field reads them: per friction set-up the
//! ten trains' max downward deflection and max acceleration (ten hues, with each train's
//! resonance speeds f₁·D/i marked on its curve), and the envelopes over the trains with and without
//! friction, the critical train and speed marked, the static envelope and — on a span — the EN 1990 acceleration
//! limit drawn for reference.

use super::results::{Results, TrainCurve, coach_length, interpolate, millimetres};
use report::plot::{Mark, Palette, PlotSpec, Series, Stroke};
use runner::SweepPoint;
use scenario::axis::{Axis, Shown};
use scenario::units::KMH;

const DEFLECTION_AXIS: &str = "max downward deflection";
const ACCELERATION_AXIS: &str = "max vertical acceleration";

/// The speed axis of every HSLM figure: "train speed v (km/h)".
fn speed_axis() -> Axis {
    Axis::new("train speed v", "speed", Shown::KilometresPerHour)
}

fn deflection_mm(p: &SweepPoint) -> f64 {
    p.deflection.max_downward.value * 1e3
}

fn acceleration(p: &SweepPoint) -> f64 {
    p.deck_acceleration()
}

/// The colour index of HSLM-A`k` in [`Palette::Ten`]: ten trains, ten hues, all solid.
fn train_colour(k: usize) -> usize {
    k - 1
}

/// A horizontal reference line at `y` across the figure's speed range.
fn level(results: &Results, label: String, y: f64) -> Series {
    let points = &results.curves[0].points;
    let (from, to) = (points[0].speed * KMH, points[points.len() - 1].speed * KMH);
    Series::reference(label, (from, y), (to, y))
}

impl Results {
    /// The y-axis label of `quantity` with its unit, naming the nodes it is taken over when not all.
    fn axis(&self, caption: &str, quantity: &str, shown: Shown) -> Axis {
        match self.extremes_nodes {
            Some([a, b]) => Axis::new(format!("{caption} at {a:.0}–{b:.0} m"), quantity, shown),
            None => Axis::new(caption, quantity, shown),
        }
    }

    /// The acceleration axis: on a span, the deck acceleration in its EN 1990 band of modes (what the runs report
    /// there, docs/theory.md §10.4); on a track, the nodal one.
    fn acceleration_axis(&self) -> Axis {
        match (&self.frequencies, self.acceleration_limit) {
            (Some(f), Some(_)) if f.len() >= 3 => {
                let band = fem_beam::modal_band::deck_band(f[0], f[2]);
                self.axis(&format!("deck acceleration, modes ≤ {band:.1} Hz"), "deck_acceleration", Shown::Si)
            }
            _ => self.axis(ACCELERATION_AXIS, "max_acceleration", Shown::Si),
        }
    }

    /// On a span, the EN 1990 limit of the deck's track as a line across the speed range.
    fn limit_line(&self) -> Option<Series> {
        self.acceleration_limit.map(|limit| {
            level(self, format!("EN 1990 limit {} m/s², {}", limit.value, limit.track.name()), limit.value)
        })
    }

    /// Every figure of the study.
    pub(in crate::presets) fn figures(&self) -> Vec<PlotSpec> {
        let mut plots = Vec::new();
        for friction in 0..2 {
            let suffix = if friction == 0 { "" } else { "-friction" };
            let label = self.friction_label(friction);
            plots.push(self.trains_figure(
                &format!("hslm-deflection{suffix}"),
                &format!("HSLM-A1 … A10, {label}: max deflection vs speed"),
                &self.axis(DEFLECTION_AXIS, "max_downward_deflection", Shown::Milli),
                friction,
                deflection_mm,
            ));
            let mut trains = self.trains_figure(
                &format!("hslm-acceleration{suffix}"),
                &format!("HSLM-A1 … A10, {label}: max acceleration vs speed"),
                &self.acceleration_axis(),
                friction,
                acceleration,
            );
            trains.series.extend(self.limit_line());
            plots.push(trains);
        }
        plots.push(self.deflection_envelope());
        plots.push(self.acceleration_envelope());
        plots
    }

    /// The ten trains of one friction set-up, one quantity, resonance speeds f₁·D/i marked on each curve; each
    /// curve draws the sweep and the refinements' runs, so that the refined peaks lie on it.
    fn trains_figure(
        &self,
        stem: &str,
        title: &str,
        y: &Axis,
        friction: usize,
        value: fn(&SweepPoint) -> f64,
    ) -> PlotSpec {
        let mut spec = PlotSpec::new(stem, title, &speed_axis(), y);
        spec.palette = Palette::Ten;
        for c in self.set(friction) {
            // Neighbouring trains (A9 and A10: coaches of 26 and 27 m) can trace nearly the same curve: the even
            // ones dashed, so that the one drawn first shows through the other.
            let stroke = if c.train % 2 == 0 { Stroke::Dashed } else { Stroke::Solid };
            let color = train_colour(c.train);
            let points: Vec<(f64, f64)> = c.drawn.iter().map(|p| (p.speed * KMH, value(p))).collect();
            spec.series.push(Series {
                label: Some(format!("HSLM-A{} (D = {} m)", c.train, coach_length(c.train))),
                color,
                stroke,
                markers: true,
                points,
            });
            for r in c.resonances.iter().filter(|r| r.mode == 1) {
                spec.marks.push(Mark { color, point: (r.speed * KMH, interpolate(&c.drawn, r.speed, value)) });
            }
        }
        match (&self.frequencies, self.acceleration_limit) {
            (Some(f), _) => {
                spec.subtitle = format!("f₁ = {:.2} Hz of the span; triangles on each curve at v = f₁·D/i", f[0]);
                spec.mark_label = "resonance v = f₁·D/i".into();
            }
            (None, None) => {
                spec.subtitle = "a track on a Winkler foundation: no natural frequencies to resonate".into()
            }
            (None, Some(_)) => {}
        }
        spec
    }

    /// The two envelopes of `value` (no friction, friction), each with its critical point marked and described.
    fn envelope_figure(
        &self,
        (stem, title, y): (&str, &str, &Axis),
        value: fn(&SweepPoint) -> f64,
        critical: &dyn Fn(usize) -> ((f64, f64), String),
        mark_label: &str,
    ) -> PlotSpec {
        let mut spec = PlotSpec::new(stem, title, &speed_axis(), y);
        let mut described = Vec::new();
        for friction in 0..2 {
            spec.series.push(Series {
                label: Some(self.friction_label(friction)),
                color: friction,
                stroke: Stroke::Solid,
                // The envelope passes through every run of every train: too many for markers.
                markers: false,
                points: self.envelope(friction, value).iter().map(|&(v, y)| (v * KMH, y)).collect(),
            });
            let (point, text) = critical(friction);
            spec.marks.push(Mark { color: friction, point });
            described.push(text);
        }
        spec.subtitle = described.join("; ");
        spec.mark_label = mark_label.into();
        spec
    }

    /// Envelopes of the max downward deflection over the ten trains, the critical (refined) train and speed marked,
    /// and the static envelope of the heaviest train.
    fn deflection_envelope(&self) -> PlotSpec {
        let axis = self.axis(DEFLECTION_AXIS, "max_downward_deflection", Shown::Milli);
        let titles = ("hslm-envelope-deflection", "HSLM-A1 … A10: envelope of the max deflection", &axis);
        let critical = |friction: usize| {
            let c = self.critical(friction);
            let point = (c.critical.speed * KMH, c.critical.max_downward_deflection * 1e3);
            (point, describe(c, self.friction_label(friction)))
        };
        let mut spec = self.envelope_figure(titles, deflection_mm, &critical, "critical train and speed");
        let heaviest = self.curves.iter().map(|c| c.static_max).fold(0.0, f64::max);
        spec.series.push(level(self, "static, heaviest train".into(), heaviest * 1e3));
        spec
    }

    /// Envelopes of the max acceleration over the ten trains, the largest refined peak marked, and on a span the
    /// EN 1990 limit of the deck's track.
    fn acceleration_envelope(&self) -> PlotSpec {
        let axis = self.acceleration_axis();
        let titles = ("hslm-envelope-acceleration", "HSLM-A1 … A10: envelope of the max acceleration", &axis);
        let critical = |friction: usize| {
            let c = self.acceleration_critical(friction);
            let p = &c.acceleration;
            let text = format!(
                "{}: HSLM-A{} at {}{:.0} km/h, {:.2} m/s²",
                self.friction_label(friction),
                c.train,
                bound_sign(p.location),
                p.speed * KMH,
                p.value
            );
            ((p.speed * KMH, p.value), text)
        };
        // A largest value at an end of the range is a bound, not a refined peak: the legend says which it is.
        let bounded = (0..2).any(|f| !self.acceleration_critical(f).acceleration.is_interior());
        let label = if bounded { "largest (≥: range end)" } else { "refined peak" };
        let mut spec = self.envelope_figure(titles, acceleration, &critical, label);
        spec.series.extend(self.limit_line());
        spec
    }
}

/// "≥ " / "≤ " before the speed of a bound at the upper / lower end of the range, nothing for an interior peak.
fn bound_sign(location: runner::PeakLocation) -> &'static str {
    match location {
        runner::PeakLocation::Interior => "",
        runner::PeakLocation::LowerEnd => "≤ ",
        runner::PeakLocation::UpperEnd => "≥ ",
    }
}

/// "no friction: HSLM-A4 at 331 km/h, 1.42 mm", with "≥" / "≤" for a bound at an end of the range.
fn describe(c: &TrainCurve, label: String) -> String {
    let bound = bound_sign(c.critical.location);
    format!(
        "{label}: HSLM-A{} at {bound}{:.0} km/h, {}",
        c.train,
        c.critical.speed * KMH,
        millimetres(c.critical.max_downward_deflection)
    )
}
