//! The figures of the stationary-wave study: peaks against speed on the infinite track beside the finite beam, the
//! three soils, the deflection friction leaves behind the load, and the waves' shapes at three speeds.

use super::curves::{FRICTION, InfiniteCritical, InfiniteCurve};
use crate::presets::curves::Curves;
use crate::stationary::output::StationaryPoint;
use report::figures::{DeflectionCurve, deflection_figure, load_speed_axis};
use report::plot::{Mark, PanelY, PlotSpec, Series, Stroke};
use scenario::Scenario;
use scenario::axis::{Axis, Shown};

/// The four figures.
pub(in crate::presets) fn plots(
    infinite: &[InfiniteCurve],
    finite: &Curves,
    shape_speeds: &[f64],
    base: &Scenario,
) -> Vec<PlotSpec> {
    vec![friction(infinite, finite), soils(infinite), behind(infinite, base), shapes(infinite, shape_speeds)]
}

/// Max downward deflection against speed: the infinite track solid (the stationary wave), the finite beam dashed
/// (the distributed-speed study's runs), one colour per friction level.
fn friction(infinite: &[InfiniteCurve], finite: &Curves) -> PlotSpec {
    let mut spec = PlotSpec::new(
        "stationary-wave-friction",
        "Infinite track and finite beam: max downward deflection vs speed",
        &load_speed_axis(),
        &Axis::new("max downward deflection", "deflection", Shown::Milli),
    );
    spec.subtitle =
        "solid: stationary wave, infinite track; dashed: finite beam (distributed-speed study); gap: no wave".into();
    for (c, curve) in infinite.iter().enumerate().filter(|(_, c)| c.soil.foundation == "linear") {
        // The refinement's waves with the sweep's, so that each refined peak sits on its curve.
        let mut series = sampled(curve, c, |p| p.deflection.max_downward.map(|e| e.value));
        series.points.extend(curve.refinement.iter().map(|&(v, w)| (v, w * 1e3)));
        series.points.sort_by(|a, b| a.0.total_cmp(&b.0));
        series.markers = false;
        spec.series.push(series);
    }
    for (c, curve) in infinite.iter().enumerate() {
        if let InfiniteCritical::Interior { speed, peak } = curve.critical
            && curve.soil.foundation == "linear"
        {
            spec.marks.push(Mark { color: c, point: (speed, peak * 1e3) });
        }
    }
    for (c, &f) in FRICTION.iter().enumerate() {
        let Some(k) = finite.find("force_per_length", f) else { continue };
        let mut points: Vec<(f64, f64)> =
            finite.points[k].iter().map(|p| (p.speed, p.deflection.max_downward.value * 1e3)).collect();
        // The refinement's runs too, so that the finite beam's refined peak sits on its curve.
        let refined = finite.critical[k].iter().flat_map(|c| c.evaluations.iter().map(|&(v, w)| (v, w * 1e3)));
        points.extend(refined);
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        spec.series.push(Series { label: None, color: c, stroke: Stroke::Dashed, markers: false, points });
        if let Some(critical) = finite.critical[k].as_ref().filter(|k| k.is_interior()) {
            spec.marks.push(Mark { color: c, point: (critical.speed, critical.max_downward_deflection * 1e3) });
        }
    }
    // Where a curve has no wave from v_cr on (undamped, frictionless: the closed form is unbounded there), a line at
    // v_cr says why it ends.
    let top = spec.series.iter().flat_map(|s| s.points.iter().map(|p| p.1)).fold(0.0f64, f64::max);
    if let Some(v_cr) = infinite.iter().find_map(|curve| match curve.critical {
        InfiniteCritical::Unbounded { critical_speed, .. } => Some(critical_speed),
        _ => None,
    }) {
        spec.series.push(Series::reference(format!("v_cr {v_cr:.1} m/s: unbounded"), (v_cr, 0.0), (v_cr, top)));
    }
    spec.key = vec![(Stroke::Solid, "infinite track".into()), (Stroke::Dashed, "finite beam".into())];
    spec.mark_label = "refined peak".into();
    spec
}

/// The three soils without friction on the infinite track: max downward (solid) and upward (dashed) deflection.
fn soils(infinite: &[InfiniteCurve]) -> PlotSpec {
    // The tensionless curve drawn last: it ends near 104 m/s, and below that it lies on the bilinear one, which
    // would hide it.
    let mut order: Vec<(usize, &InfiniteCurve)> =
        infinite.iter().enumerate().filter(|(_, c)| c.soil.force_per_length == 0.0).collect();
    order.sort_by_key(|(_, c)| c.soil.foundation == "tensionless");
    let curves = order
        .into_iter()
        .map(|(c, curve)| {
            let points = &curve.study.points;
            DeflectionCurve {
                label: curve.soil.label().replace("no friction", "linear soil"),
                color: c,
                downward: points.iter().filter_map(|p| Some((p.speed, p.deflection.max_downward?.value))).collect(),
                upward: points.iter().filter_map(|p| Some((p.speed, p.deflection.max_upward?.value))).collect(),
                optimum: None,
            }
        })
        .collect();
    let mut spec = deflection_figure(
        "stationary-wave-soils",
        "Infinite track without friction: linear, tensionless and bilinear soils",
        &load_speed_axis(),
        curves,
        "",
    );
    spec.subtitle = "nonlinear soils carry the rail's weight; a curve stops where no wave is found".into();
    spec
}

/// The deflection friction leaves behind the load (signed, mm), with the bound ±f_u/k of each level.
fn behind(infinite: &[InfiniteCurve], base: &Scenario) -> PlotSpec {
    let mut spec = PlotSpec::new(
        "stationary-wave-behind",
        "Infinite track: the deflection ballast friction leaves behind the load",
        &load_speed_axis(),
        &Axis::noted("residual deflection", "deflection", Shown::Milli, "+ above the rail's level"),
    );
    spec.subtitle = format!(
        "solid: what the wave leaves behind; dashed: the bound ±f_u/k (k = {:.0} kN/m²) of each f_u",
        base.foundation.stiffness / 1e3
    );
    spec.key = vec![(Stroke::Solid, "left behind".into()), (Stroke::Dashed, "bound ±f_u/k".into())];
    let speeds: Vec<f64> = infinite.first().map_or(Vec::new(), |c| c.study.points.iter().map(|p| p.speed).collect());
    let (first, last) = (speeds.first().copied().unwrap_or(0.0), speeds.last().copied().unwrap_or(1.0));
    for (c, curve) in infinite.iter().enumerate().filter(|(_, c)| c.soil.force_per_length > 0.0) {
        spec.series.push(sampled(curve, c, |p| p.deflection_behind));
        let bound = 1e3 * curve.soil.force_per_length / base.foundation.stiffness;
        for sign in [1.0, -1.0] {
            let points = vec![(first, sign * bound), (last, sign * bound)];
            spec.series.push(Series { label: None, color: c, stroke: Stroke::Dashed, markers: false, points });
        }
    }
    spec
}

/// A curve's `value` (m) in mm against speed, solid with markers, in colour `color`: the speeds with a wave only.
fn sampled(curve: &InfiniteCurve, color: usize, value: fn(&StationaryPoint) -> Option<f64>) -> Series {
    let points = curve.study.points.iter().filter_map(|p| Some((p.speed, value(p)? * 1e3))).collect();
    Series { label: Some(curve.soil.label()), color, stroke: Stroke::Solid, markers: true, points }
}

/// W(s) at each shape speed, one panel per speed, every soil that has a wave there.
fn shapes(infinite: &[InfiniteCurve], speeds: &[f64]) -> PlotSpec {
    let mut spec = PlotSpec::new(
        "stationary-wave-shapes",
        "The stationary wave at three speeds",
        &Axis::new("s = x − vt", "s", Shown::Si),
        &Axis::new("W", "deflection", Shown::Milli),
    );
    spec.subtitle =
        "from the settled rail, s > 0 ahead of the load, each panel on its own scales (its waves' domain); absent: \
         no wave"
            .into();
    spec.panel_y = PanelY::EachOwn;
    for (k, &speed) in speeds.iter().enumerate() {
        let mut panel = PlotSpec::new(
            "",
            format!("v = {speed:.0} m/s"),
            &Axis::new("s = x − vt", "s", Shown::Si),
            &Axis::new("W", "deflection", Shown::Milli),
        );
        for (c, curve) in infinite.iter().enumerate() {
            let Some(wave) = curve.shapes.get(k).and_then(Option::as_ref) else { continue };
            let points = wave.s.iter().zip(&wave.deflection).map(|(s, w)| (*s, w * 1e3)).collect();
            let label = Some(curve.soil.label());
            panel.series.push(Series { label, color: c, stroke: Stroke::Solid, markers: false, points });
        }
        spec.panels.push(panel);
    }
    spec
}
