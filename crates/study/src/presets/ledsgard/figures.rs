//! The Ledsgård study's figures: the deepest deflection over speed with and without ballast friction, the critical
//! speeds and the measured peaks marked; and the computed wave beside each measured record.

use crate::ground::measured::MeasuredRecord;
use crate::ground::numbers::GroundStudy;
use crate::ground::wave::GroundWaveStudy;
use report::plot::{Mark, PlotSpec, Series, Stroke};
use scenario::axis::{Axis, Shown};
use scenario::units::KMH;

/// The figures: `ledsgard-speeds`, then `ledsgard-70-kmh` and `ledsgard-185-kmh`.
pub(super) fn figures(
    ground: &GroundStudy,
    curves: &[(f64, GroundWaveStudy)],
    compared: &[(f64, GroundWaveStudy, MeasuredRecord)],
) -> Vec<PlotSpec> {
    let mut plots = vec![speeds_figure(ground, curves, compared)];
    for (speed, study, record) in compared {
        let mut figure = study.figure(Some(record));
        figure.stem = format!("ledsgard-{speed:.0}-kmh");
        figure.title = format!("Ledsgård, X2000 at {speed:.0} km/h: computed and measured");
        plots.push(figure);
    }
    plots
}

fn speeds_figure(
    ground: &GroundStudy,
    curves: &[(f64, GroundWaveStudy)],
    compared: &[(f64, GroundWaveStudy, MeasuredRecord)],
) -> PlotSpec {
    let mut figure = PlotSpec::new(
        "ledsgard-speeds",
        "Ledsgård: the X2000's deepest deflection over speed, with ballast friction",
        &Axis::new("train speed", "speed", Shown::KilometresPerHour),
        &Axis::new("deepest deflection", "deflection", Shown::Milli),
    );
    let subtitle = curves.first().map(|(_, s)| s.subtitle()).unwrap_or_default();
    figure.subtitle = format!("{subtitle}; linear small-strain soil; the curves sampled, not refined");
    let mut top: f64 = 0.0;
    for (i, (friction, study)) in curves.iter().enumerate() {
        let points: Vec<(f64, f64)> =
            study.points.iter().map(|p| (p.speed * KMH, p.deflection.max_downward.value * 1e3)).collect();
        top = points.iter().map(|p| p.1).fold(top, f64::max);
        let label = match *friction {
            0.0 => "no ballast friction".to_string(),
            f => format!("ballast friction f_u = {} kN/m", f / 1e3),
        };
        figure.series.push(Series { label: Some(label), color: i + 1, stroke: Stroke::Solid, markers: true, points });
    }
    for (speed, study, _) in compared {
        if let Some(c) = &study.comparison {
            top = top.max(c.measured_max_downward * 1e3);
            figure.marks.push(Mark { color: 0, point: (*speed, c.measured_max_downward * 1e3) });
        }
    }
    figure.mark_label = "measured deepest deflection (Madshus & Kaynia 2000)".into();
    let vertical = |label: String, color: usize, v: f64| Series {
        label: Some(label),
        color,
        stroke: Stroke::Dashed,
        markers: false,
        points: vec![(v * KMH, 0.0), (v * KMH, top)],
    };
    if let Some(v) = ground.critical_speed {
        figure.series.push(vertical(format!("critical speed on the ground (one load), {:.0} km/h", v * KMH), 6, v));
    }
    let v = ground.winkler_critical_speed;
    figure.series.push(vertical(format!("Winkler control on the static strip stiffness, {:.0} km/h", v * KMH), 7, v));
    figure
}
