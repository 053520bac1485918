//! Snapshots of a long beam, zoomed: a bowl 3 m wide drawn over 200 m of beam is a needle, so where every snapshot's
//! deflection is confined to a small part of the beam each instant gets a panel of its own around its load.

use crate::plot::{PanelY, PlotSpec, Series};
use scenario::axis::Axis;

/// A snapshot's deflection counts as significant where it reaches this fraction of its own largest magnitude.
const SIGNIFICANT: f64 = 0.01;
/// Zoom only where the windows together cover less than this fraction of the beam.
const NARROW: f64 = 0.25;

/// The half-width (m) of the window around each load that holds every snapshot's significant deflection (with a
/// fifth to spare, at least 2 m), or None where the snapshots are not narrow against the beam (`extent`, m) —
/// then one panel shows them best. `instants` are (load position, [x, w, …] points) per snapshot.
pub fn zoom_half_width(instants: &[(f64, &[[f64; 3]])], extent: f64) -> Option<f64> {
    let mut half: f64 = 0.0;
    for (at, points) in instants {
        let largest = points.iter().fold(0.0f64, |m, p| m.max(p[1].abs()));
        let reach = points.iter().filter(|p| p[1].abs() >= SIGNIFICANT * largest).map(|p| (p[0] - at).abs());
        half = half.max(reach.fold(0.0, f64::max));
    }
    let half = (1.2 * half).max(2.0);
    (!instants.is_empty() && 2.0 * half * instants.len() as f64 <= NARROW * extent).then_some(half)
}

/// A curve hides another where both reach this fraction of the largest deflection of all the instants.
pub const HIDES: f64 = 0.25;
/// Stack the instants in panels of their own where one's region of large deflection ([`HIDES`]) overlaps another's
/// by more than this fraction of the shorter: drawn together, the curves interleave and hide each other.
pub const OVERLAP: f64 = 0.25;

/// Whether the snapshots' large deflections overlap along the beam ([`HIDES`], [`OVERLAP`]): a train's waves, 100 m
/// long, at instants 40 m apart — not a single wheel's bowls, whose small residue at a void each later snapshot
/// keeps. `instants` as for [`zoom_half_width`].
pub fn overlapping(instants: &[(f64, &[[f64; 3]])]) -> bool {
    let largest = instants.iter().flat_map(|(_, points)| points.iter()).fold(0.0f64, |m, p| m.max(p[1].abs()));
    let regions: Vec<(f64, f64)> = instants
        .iter()
        .filter_map(|(_, points)| {
            let xs = points.iter().filter(|p| largest > 0.0 && p[1].abs() >= HIDES * largest).map(|p| p[0]);
            xs.fold(None, |r: Option<(f64, f64)>, x| Some(r.map_or((x, x), |(a, b)| (a.min(x), b.max(x)))))
        })
        .collect();
    regions.iter().enumerate().any(|(i, a)| {
        regions[i + 1..].iter().any(|b| {
            let common = a.1.min(b.1) - a.0.max(b.0);
            common > OVERLAP * (a.1 - a.0).min(b.1 - b.0)
        })
    })
}

/// `spec` (one curve per instant, in the order of `loads`, each marked at its load; reference lines after them) as
/// one panel per instant over the whole beam, the panels' y ranges shared (the instants compare at a glance).
pub fn stacked(spec: PlotSpec, loads: &[f64]) -> PlotSpec {
    PlotSpec { panel_y: PanelY::SharedPerQuantity, ..zoomed(spec, loads, f64::INFINITY) }
}

/// `spec` (one curve per instant, in the order of `loads`, each marked at its load; reference lines after them)
/// as one panel per instant over [load − half, load + half], each with its own ranges.
pub fn zoomed(spec: PlotSpec, loads: &[f64], half: f64) -> PlotSpec {
    let inside = |lo: f64, hi: f64| move |p: &(f64, f64)| (lo..=hi).contains(&p.0);
    let references: Vec<&Series> = spec.series.iter().skip(loads.len()).collect();
    let panels = loads
        .iter()
        .enumerate()
        .filter_map(|(i, &at)| {
            let (lo, hi) = (at - half, at + half);
            let curve = spec.series.get(i)?;
            let title = curve.label.clone().unwrap_or_default();
            let mut panel =
                PlotSpec { x_label: spec.x_label.clone(), ..PlotSpec::new("", title, &Axis::none(), &Axis::none()) };
            panel.y_label.clone_from(&spec.y_label);
            let points: Vec<(f64, f64)> = curve.points.iter().copied().filter(inside(lo, hi)).collect();
            panel.series.push(Series { label: None, points, ..curve.clone() });
            for reference in references.iter().filter(|r| r.points.iter().all(inside(lo, hi))) {
                panel.series.push((*reference).clone());
            }
            panel.marks = spec.marks.iter().filter(|m| m.color == curve.color).cloned().collect();
            panel.mark_label.clone_from(&spec.mark_label);
            Some(panel)
        })
        .collect();
    PlotSpec { panels, panel_y: PanelY::EachOwn, series: Vec::new(), marks: Vec::new(), ..spec }
}

#[cfg(test)]
mod tests {
    use super::{overlapping, stacked, zoom_half_width, zoomed};
    use crate::plot::{Mark, PanelY, PlotSpec, Series, Stroke};
    use scenario::axis::{Axis, Shown};

    /// A bowl of `width` m at `at` on a 200 m beam, sampled every 0.25 m: w = −exp(−((x − at)/width)²).
    fn bowl(at: f64, width: f64) -> Vec<[f64; 3]> {
        (0..=800).map(|i| 0.25 * i as f64).map(|x| [x, -(-((x - at) / width).powi(2)).exp(), 0.0]).collect()
    }

    /// Three bowls 1 m wide on 200 m (the discrete track's needles) are zoomed, each panel around its own load and
    /// holding its curve, its triangle and only the reference lines inside it; waves that reach along the beam
    /// (a load near the critical speed) are not.
    #[test]
    fn narrow_bowls_get_a_panel_each_and_long_waves_do_not() {
        let shapes: Vec<Vec<[f64; 3]>> = [50.0, 100.0, 150.0].iter().map(|&at| bowl(at, 1.0)).collect();
        let instants: Vec<(f64, &[[f64; 3]])> =
            [50.0, 100.0, 150.0].iter().zip(&shapes).map(|(&a, s)| (a, s.as_slice())).collect();
        // |w| ≥ 1 % within √ln 100 = 2.15 m of the load: the half-width 1.2 × 2.15 = 2.6 m (at 0.25 m sampling).
        let half = zoom_half_width(&instants, 200.0).expect("narrow");
        assert!((2.4..2.8).contains(&half), "{half}");
        let wide: Vec<Vec<[f64; 3]>> = [50.0, 100.0].iter().map(|&at| bowl(at, 30.0)).collect();
        let long: Vec<(f64, &[[f64; 3]])> = [50.0, 100.0].iter().zip(&wide).map(|(&a, s)| (a, s.as_slice())).collect();
        assert_eq!(zoom_half_width(&long, 200.0), None);

        let (x, w) = (Axis::new("x", "x", Shown::Si), Axis::new("w", "deflection", Shown::Milli));
        let mut spec = PlotSpec::new("snapshots-deflection", "shape", &x, &w);
        for (i, (at, s)) in instants.iter().enumerate() {
            let points = s.iter().map(|p| (p[0], p[1])).collect();
            let label = Some(format!("load at {at} m"));
            spec.series.push(Series { label, color: 1 + i, stroke: Stroke::Solid, markers: false, points });
            spec.marks.push(Mark { color: 1 + i, point: (*at, -1.0) });
        }
        spec.series.push(Series::reference("sleeper: void", (99.0, -1.0), (99.0, 0.0)));
        let zoomed = zoomed(spec, &[50.0, 100.0, 150.0], half);
        assert_eq!((zoomed.panels.len(), zoomed.panel_y, zoomed.series.len()), (3, PanelY::EachOwn, 0));
        for (panel, at) in zoomed.panels.iter().zip([50.0, 100.0, 150.0]) {
            assert!(panel.series[0].points.iter().all(|p| (p.0 - at).abs() <= half), "{}", panel.title);
            assert_eq!(panel.marks.len(), 1);
            assert_eq!(panel.title, format!("load at {at} m"));
            assert_eq!(panel.series.len(), if at == 100.0 { 2 } else { 1 }, "{}", panel.title);
        }
    }

    /// A train's waves, 30 m wide bowls 40 m apart on 200 m (each above a quarter of the largest within ±35 m),
    /// overlap and are stacked, a panel each over the whole beam with the y range shared; bowls 3 m wide 50 m apart
    /// do not overlap.
    #[test]
    fn overlapping_waves_are_stacked_over_the_whole_beam() {
        let at = [60.0, 100.0, 140.0];
        let wide: Vec<Vec<[f64; 3]>> = at.iter().map(|&a| bowl(a, 30.0)).collect();
        let instants: Vec<(f64, &[[f64; 3]])> = at.iter().zip(&wide).map(|(&a, s)| (a, s.as_slice())).collect();
        assert!(overlapping(&instants) && zoom_half_width(&instants, 200.0).is_none());
        let narrow: Vec<Vec<[f64; 3]>> = [50.0, 100.0, 150.0].iter().map(|&a| bowl(a, 3.0)).collect();
        let apart: Vec<(f64, &[[f64; 3]])> =
            [50.0, 100.0, 150.0].iter().zip(&narrow).map(|(&a, s)| (a, s.as_slice())).collect();
        assert!(!overlapping(&apart));
        let (x, w) = (Axis::new("x", "x", Shown::Si), Axis::new("w", "deflection", Shown::Milli));
        let mut spec = PlotSpec::new("snapshots", "deflected shape", &x, &w);
        for (i, shape) in wide.iter().enumerate() {
            spec.series.push(Series {
                label: Some(format!("load at {} m", at[i])),
                color: 1 + i,
                stroke: Stroke::Solid,
                markers: false,
                points: shape.iter().map(|p| (p[0], p[1])).collect(),
            });
        }
        let stacked = stacked(spec, &at);
        assert_eq!((stacked.panels.len(), stacked.panel_y), (3, PanelY::SharedPerQuantity));
        assert!(stacked.panels.iter().all(|p| p.series[0].points.len() == 801), "the whole beam in each panel");
    }
}
