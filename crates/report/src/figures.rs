//! The figures of the studies, drawn one way ([`crate::plot`]'s convention): deflections as magnitudes in mm,
//! downward solid and upward dashed in the configuration's colour, markers on sampled points, refined optima marked,
//! forces in kN.

use crate::plot::{Mark, PlotSpec, Series, Stroke};
use scenario::axis::{Axis, Shown};

/// One configuration's curve pair: downward and upward deflection magnitudes (m) against x.
pub struct DeflectionCurve {
    /// Legend text.
    pub label: String,
    /// Colour index (one per configuration across a study).
    pub color: usize,
    /// (x, max downward deflection in m).
    pub downward: Vec<(f64, f64)>,
    /// (x, max upward deflection in m).
    pub upward: Vec<(f64, f64)>,
    /// A refined optimum (x, max downward deflection in m), marked with a triangle.
    pub optimum: Option<(f64, f64)>,
}

/// Max downward (solid) and upward (dashed) deflection magnitudes in mm against `x`, one colour per curve.
pub fn deflection_figure(
    stem: &str,
    title: &str,
    x: &Axis,
    curves: Vec<DeflectionCurve>,
    mark_label: &str,
) -> PlotSpec {
    let y = Axis::new("max deflection magnitude", "deflection", Shown::Milli);
    let mut spec = PlotSpec::new(stem, title, x, &y);
    let mm = |p: &[(f64, f64)]| p.iter().map(|&(x, w)| (x, w * y.factor())).collect();
    for c in curves {
        let (label, color) = (Some(c.label), c.color);
        // The refined optimum is a run of its own: the curve passes through it (drawn from the grid alone, it ran
        // under its triangle, 100–200 mm below a resonance the grid steps over).
        let mut downward = c.downward.clone();
        if let Some(optimum) = c.optimum {
            insert_refined(&mut downward, optimum);
        }
        spec.series.push(Series { label, color, stroke: Stroke::Solid, markers: true, points: mm(&downward) });
        spec.series.push(Series { label: None, color, stroke: Stroke::Dashed, markers: true, points: mm(&c.upward) });
        if let Some((x, w)) = c.optimum {
            spec.marks.push(Mark { color, point: (x, w * y.factor()) });
        }
    }
    spec.key = vec![(Stroke::Solid, "downward".into()), (Stroke::Dashed, "upward".into())];
    spec.mark_label = mark_label.into();
    spec
}

/// The speed axis of a sweep: "load speed v (m/s)".
pub fn load_speed_axis() -> Axis {
    Axis::new("load speed v", "speed", Shown::Si)
}

/// The axis of the energy a sweep's runs dissipated: "energy dissipated by friction and damping (kJ)".
pub fn dissipated_energy_axis() -> Axis {
    Axis::new("energy dissipated by friction and damping", "dissipated_energy", Shown::Kilo)
}

/// Put a refined point (a peak found between the grid's samples, a run or evaluation of its own) into the sampled
/// curve `points` (increasing x), so that the curve passes through it; nothing where a sample already sits at its x.
pub fn insert_refined(points: &mut Vec<(f64, f64)>, refined: (f64, f64)) {
    if points.iter().all(|&(x, _)| x != refined.0) {
        points.insert(points.partition_point(|&(x, _)| x < refined.0), refined);
    }
}

/// Curves of one quantity: (legend text, colour index, points).
pub type Curves = Vec<(String, usize, Vec<(f64, f64)>)>;

/// One quantity against x for several configurations, solid, with markers if asked.
pub fn quantity_figure(stem: &str, title: &str, x: &Axis, y: &Axis, curves: Curves, markers: bool) -> PlotSpec {
    let mut spec = PlotSpec::new(stem, title, x, y);
    for (label, color, points) in curves {
        spec.series.push(Series { label: Some(label), color, stroke: Stroke::Solid, markers, points });
    }
    spec
}

/// The colour of a device count N ∈ {3, 7, 15, 31} (0, black, is "no friction"), the same in every study.
pub fn device_color(count: usize) -> usize {
    match count {
        0 => 0,
        3 => 1,
        7 => 2,
        15 => 3,
        31 => 4,
        _ => 7,
    }
}
