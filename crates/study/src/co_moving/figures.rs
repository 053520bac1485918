//! The figures of a co-moving run (docs/theory.md §15): the wave in the load's frame at the end, and how much it
//! changed over each window length travelled. Deflections in mm, s and distances in m.

use crate::co_moving::output::{CoMovingSummary, STATIONARY_CHANGE};
use report::plot::{PlotSpec, Series, Stroke};
use scenario::axis::{Axis, Shown};
use track::co_moving::CoMovingResult;

/// The figures of a co-moving run: the wave in the frame at the end, and its change per window length travelled
/// (logarithmic: the approach to the stationary state).
pub fn figures(summary: &CoMovingSummary, result: &CoMovingResult) -> Vec<PlotSpec> {
    let title = if summary.title.is_empty() { "co-moving window" } else { summary.title.as_str() };
    let friction = match summary.distributed_friction > 0.0 {
        true => format!("f_u = {:.1} kN/m", summary.distributed_friction / 1e3),
        false => "no friction".to_string(),
    };
    let subtitle = format!(
        "{} at {:.1} m/s over {:.0} m of track, {} soil, {friction}, window {:.0} m (zones {:.0} m)",
        summary.what_moves(),
        summary.speed,
        summary.track_length,
        summary.soil,
        summary.window,
        summary.zones
    );
    let line = |label: &str, points: Vec<(f64, f64)>| Series {
        label: Some(label.into()),
        color: 1,
        stroke: Stroke::Solid,
        markers: false,
        points,
    };
    let mut wave = PlotSpec::new(
        "co-moving-wave",
        title,
        &Axis::new("s = x − x_load", "s", Shown::Si),
        &Axis::new("w", "deflection", Shown::Milli),
    );
    wave.subtitle = format!("{subtitle}; the wave in the frame at the end");
    wave.series.push(line("W(s)", result.wave.iter().map(|(s, w)| (*s, w * 1e3)).collect()));
    let y = Axis::new("max |ΔW| per window length / peak", "wave_change", Shown::Si);
    let mut change = PlotSpec::new(
        "co-moving-convergence",
        format!("{title}: approach to the stationary wave"),
        &Axis::new("track travelled", "position", Shown::Si),
        &y,
    );
    change.subtitle = subtitle;
    change.log_y = true;
    let positive: Vec<(f64, f64)> = result.changes.iter().copied().filter(|(_, c)| *c > 0.0).collect();
    let ends = (positive.first().map_or(0.0, |p| p.0), positive.last().map_or(1.0, |p| p.0));
    change.series.push(Series { markers: true, ..line("change of the wave", positive) });
    let threshold = format!("stationary below {STATIONARY_CHANGE:.0e}");
    change.series.push(Series::reference(threshold, (ends.0, STATIONARY_CHANGE), (ends.1, STATIONARY_CHANGE)));
    vec![wave, change]
}
