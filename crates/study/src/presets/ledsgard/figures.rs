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
    // The ground's critical speed and Winkler control are the composite beam's: not marked on the two-beam track.
    let two_beam_figure = speeds_figure(
        None,
        two_beam,
        compared,
        ("ledsgard-speeds-two-beam", two_beam_title, "friction between sleepers and embankment"),
    );
    let mut plots = vec![
        speeds_figure(Some(ground), composite, compared, ("ledsgard-speeds", composite_title, "ballast friction")),
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

/// The curves' deepest deflection over speed with the measured peaks and, given the `ground` (the composite beam's),
/// its critical speeds: (stem, title, what the friction's legend calls it). Curves with friction that stay within
/// [`COINCIDE`] of the frictionless one at every speed are drawn as one, said in its label (else three of four hide
/// under the last).
fn speeds_figure(
    ground: Option<&GroundStudy>,
    curves: &[(f64, GroundWaveStudy)],
    compared: &[(f64, GroundWaveStudy, MeasuredRecord)],
    (stem, title, friction_name): (&str, &str, &str),
) -> PlotSpec {
    let mut figure = PlotSpec::new(
        stem,
        title,
        &Axis::new("train speed", "speed", Shown::KilometresPerHour),
        &Axis::new("deepest deflection", "deflection", Shown::Milli),
    );
    let subtitle = curves.first().map(|(_, s)| s.subtitle()).unwrap_or_default();
    figure.subtitle = format!("{subtitle}; linear small-strain soil; the curves sampled, not refined");
    let deepest = |study: &GroundWaveStudy| -> Vec<(f64, f64)> {
        study.points.iter().map(|p| (p.speed * KMH, p.deflection.max_downward.value * 1e3)).collect()
    };
    let largest_change = largest_change(curves);
    let (drawn, together) = match largest_change < COINCIDE && curves.len() > 1 {
        true => (&curves[..1], true),
        false => (curves, false),
    };
    let mut top: f64 = 0.0;
    for (i, (friction, study)) in drawn.iter().enumerate() {
        let points = deepest(study);
        top = points.iter().map(|p| p.1).fold(top, f64::max);
        let label = match (*friction, together) {
            (_, true) => {
                let values: Vec<String> = curves.iter().map(|(f, _)| format!("{}", f / 1e3)).collect();
                format!(
                    "{friction_name} f_u = {} kN/m: one curve (within {:.2} % of each other)",
                    values.join(", "),
                    100.0 * largest_change
                )
            }
            (0.0, false) => format!("no {friction_name}"),
            (f, false) => format!("{friction_name} f_u = {} kN/m", f / 1e3),
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
    if let Some(ground) = ground {
        critical_speeds(&mut figure, ground, curves, top);
    }
    figure
}

/// The curves' largest change from the frictionless one at which they are drawn as one: 0.2 %, a pixel of a 12 mm
/// axis over 560 px.
const COINCIDE: f64 = 2e-3;

/// The composite beam's critical speed on the ground and its Winkler control as vertical lines up to `top` (mm),
/// each where it lies within the speeds computed (+10 %); one beyond them is named in the subtitle instead of
/// stretching the axis over empty speeds.
fn critical_speeds(figure: &mut PlotSpec, ground: &GroundStudy, curves: &[(f64, GroundWaveStudy)], top: f64) {
    let fastest = curves.iter().flat_map(|(_, s)| s.points.iter().map(|p| p.speed)).fold(0.0, f64::max);
    let mut beyond = Vec::new();
    let lines = [
        ground.critical_speed.map(|v| ("critical speed on the ground (one load)", 6, v)),
        Some(("Winkler control on the static strip stiffness", 7, ground.winkler_critical_speed)),
    ];
    for (name, color, v) in lines.into_iter().flatten() {
        if v > 1.1 * fastest {
            beyond.push(format!("{name} {:.0} km/h (beyond the speeds computed)", v * KMH));
            continue;
        }
        figure.series.push(Series {
            label: Some(format!("{name}, {:.0} km/h", v * KMH)),
            color,
            stroke: Stroke::Dashed,
            markers: false,
            points: vec![(v * KMH, 0.0), (v * KMH, top)],
        });
    }
    if !beyond.is_empty() {
        figure.subtitle = format!("{}; {}", figure.subtitle, beyond.join("; "));
    }
}

/// The largest change of the deepest deflection over the speeds of any curve with friction from the frictionless
/// one, relative to the frictionless (0 with one curve).
fn largest_change(curves: &[(f64, GroundWaveStudy)]) -> f64 {
    let Some((_, bare)) = curves.first() else { return 0.0 };
    curves[1..]
        .iter()
        .flat_map(|(_, rubbing)| {
            bare.points
                .iter()
                .zip(&rubbing.points)
                .map(|(a, b)| (1.0 - b.deflection.max_downward.value / a.deflection.max_downward.value).abs())
        })
        .fold(0.0f64, f64::max)
}
