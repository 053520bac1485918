//! The Ledsgård study's figures: the deepest deflection over speed with and without ballast friction — under the
//! composite beam, and between the sleepers and the embankment of the two-beam track — the critical speeds and the
//! measured peaks marked; and the computed wave beside each measured record.

use crate::ground::measured::MeasuredRecord;
use crate::ground::numbers::GroundStudy;
use crate::ground::wave::GroundWaveStudy;
use report::plot::{Mark, PlotSpec, Series, Stroke};
use scenario::axis::{Axis, Shown};
use scenario::units::KMH;

/// The figures: `ledsgard-speeds` (the composite beam's curves) and `ledsgard-speeds-two-beam` (the two-beam
/// track's), then `ledsgard-70-kmh` and `ledsgard-185-kmh`.
pub(super) fn figures(
    ground: &GroundStudy,
    [composite, two_beam]: [&[(f64, GroundWaveStudy)]; 2],
    compared: &[(f64, GroundWaveStudy, MeasuredRecord)],
) -> Vec<PlotSpec> {
    let composite_title =
        "Ledsgård, the composite beam: the X2000's deepest deflection over speed, with ballast friction";
    let two_beam_title =
        "Ledsgård, the two-beam track: the rail's deepest deflection over speed, with friction under the sleepers";
    let mut two_beam_figure = speeds_figure(
        ground,
        two_beam,
        compared,
        (
            "ledsgard-speeds-two-beam",
            two_beam_title,
            "friction between sleepers and embankment",
            "composite beam, one load",
        ),
    );
    if let Some(Series { label: Some(label), .. }) = two_beam_figure.series.get_mut(two_beam.len() - 1) {
        label.push_str(&format!(" ({})", overlap(two_beam)));
    }
    let mut plots = vec![
        speeds_figure(
            ground,
            composite,
            compared,
            ("ledsgard-speeds", composite_title, "ballast friction", "one load"),
        ),
        two_beam_figure,
    ];
    for (speed, study, record) in compared {
        let mut figure = study.figure(Some(record));
        figure.stem = format!("ledsgard-{speed:.0}-kmh");
        figure.title = format!("Ledsgård, X2000 at {speed:.0} km/h: computed and measured");
        plots.push(figure);
    }
    plots
}

/// The curves' deepest deflection over speed with the measured peaks and the critical speeds: (stem, title, what
/// the friction's legend calls it, what the ground's critical speed is of).
fn speeds_figure(
    ground: &GroundStudy,
    curves: &[(f64, GroundWaveStudy)],
    compared: &[(f64, GroundWaveStudy, MeasuredRecord)],
    (stem, title, friction_name, critical_of): (&str, &str, &str, &str),
) -> PlotSpec {
    let mut figure = PlotSpec::new(
        stem,
        title,
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
            0.0 => format!("no {friction_name}"),
            f => format!("{friction_name} f_u = {} kN/m", f / 1e3),
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
        figure.series.push(vertical(
            format!("critical speed on the ground ({critical_of}), {:.0} km/h", v * KMH),
            6,
            v,
        ));
    }
    let v = ground.winkler_critical_speed;
    figure.series.push(vertical(format!("Winkler control on the static strip stiffness, {:.0} km/h", v * KMH), 7, v));
    figure
}

/// How far the strongest friction's curve lies from the frictionless one: "within 0.10 % of none" (the largest
/// change of the deepest deflection over the speeds, in percent of the frictionless).
fn overlap(curves: &[(f64, GroundWaveStudy)]) -> String {
    let ((_, bare), (_, rubbing)) = (&curves[0], &curves[curves.len() - 1]);
    let largest = bare
        .points
        .iter()
        .zip(&rubbing.points)
        .map(|(a, b)| (1.0 - b.deflection.max_downward.value / a.deflection.max_downward.value).abs())
        .fold(0.0f64, f64::max);
    format!("within {:.2} % of none", 100.0 * largest)
}
