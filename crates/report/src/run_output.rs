//! The files of one run (`frictrack run --out DIR`): histories at the recorded sections and whole-beam snapshots
//! as long-format CSV, their column units, and their figures (docs/theory.md §6).
//!
//! - `histories.csv`: `section,time,load_position,deflection,velocity,acceleration,moment,friction_force` — one row
//!   per recorded section and time step (m, s, m, m, m/s, m/s², N·m, N). Velocity is ẇ after the step, acceleration
//!   the step's mean (ẇ_{k+1} − ẇ_k)/h, the moment comes from element end forces at the nearest node, the friction
//!   force is the impulse of a friction section at that position divided by h (0 where there is none).
//! - `snapshots.csv`: `time,load_position,x,deflection,moment` — one row per node and snapshot (s, m, m, m, N·m).
//!
//! Deflection is positive upward, the moment sagging-positive; every number in shortest round-trip form.

use crate::columns::{Column, header};
use crate::figures::{Curves, quantity_figure};
use crate::plot::{Mark, PlotSpec, Series};
use scenario::axis::{Axis, Shown};
use scenario::error::Result;
use scenario::number::row;
use scenario::quantities::unit;
use scenario::{Case, Scenario};
use std::fmt::Write as _;
use std::sync::atomic::AtomicBool;
use track::{RunResult, Snapshot, SnapshotAt, SnapshotTaker};

/// The figures of one run, without extension (PNG and SVG each): histories then snapshots, deflection then moment.
pub const FIGURE_STEMS: [&str; 4] =
    ["histories-deflection", "histories-moment", "snapshots-deflection", "snapshots-moment"];

/// Columns of `histories.csv`: name and unit.
pub const HISTORY_COLUMNS: [Column; 8] = [
    ("section", unit("section")),
    ("time", unit("time")),
    ("load_position", unit("load_position")),
    ("deflection", unit("deflection")),
    ("velocity", unit("velocity")),
    ("acceleration", unit("acceleration")),
    ("moment", unit("moment")),
    ("friction_force", unit("friction_force")),
];

/// Columns of `snapshots.csv`: name and unit.
pub const SNAPSHOT_COLUMNS: [Column; 5] = [
    ("time", unit("time")),
    ("load_position", unit("load_position")),
    ("x", unit("x")),
    ("deflection", unit("deflection")),
    ("moment", unit("moment")),
];

/// A recorded run's scenario: `scenario` with mid-span as its recorded section when it names none (a run that writes
/// its histories records at least there).
pub fn recording(mut scenario: Scenario) -> Scenario {
    if scenario.output.sections.is_empty() {
        scenario.output.sections = vec![scenario.mesh.length / 2.0];
    }
    scenario
}

/// The snapshots a recorded run of `case` (built from `scenario`) takes: the scenario's requests over the first
/// axle's travel — while the whole train is on the beam where it fits, else from its start position (static or
/// steady starts begin on the beam) to L + the train's length.
pub fn snapshot_requests(scenario: &Scenario, case: &Case) -> Vec<SnapshotAt> {
    let (start, length, train) =
        (case.settings.start_position(), scenario.mesh.length, case.settings.moving.load.length());
    // While the whole train is on the beam (its last axle, `train` behind the first, past 0) where one fits: its
    // first axle at the end hits the support (a rail car's exit spike took a default moment snapshot over); else (a
    // single load, a train longer than the beam) the whole travel, from the start to the last axle's exit.
    let on = start.max(train);
    let travel = if train > 0.0 && on < length { (on, length) } else { (start, length + train) };
    let mut requests = scenario.output.snapshots(travel);
    // By default also the first axle over the first sleeper of the exceptions (a void, a tensionless or softer
    // sleeper): the quarters of the travel pass it by.
    let asked = !scenario.output.snapshot_times.is_empty() || !scenario.output.snapshot_load_positions.is_empty();
    if let Some(x) = first_exceptional_sleeper(case).filter(|x| !asked && travel.0 < *x) {
        let at = requests.partition_point(|r| matches!(r, SnapshotAt::LoadPosition(p) if *p < x));
        requests.insert(at, SnapshotAt::LoadPosition(x));
    }
    requests
}

/// Where the first sleeper of the exceptions of `case` sits (m); None when every sleeper is one (tensionless
/// ballast throughout: no sleeper stands out to be looked at).
fn first_exceptional_sleeper(case: &Case) -> Option<f64> {
    let (sleepers, nodes) = case.model.sleepers()?;
    if (0..nodes.len()).all(|i| sleepers.differs(i)) {
        return None;
    }
    let first = nodes.iter().enumerate().find(|&(i, _)| sleepers.differs(i))?;
    Some(case.model.mesh().node_x(*first.1))
}

/// At most this many sleepers of the exceptions are drawn as lines across the snapshots (beyond, the lines would
/// hide the curves: tensionless ballast under every sleeper is an exception too).
const MARKED_SLEEPERS: usize = 20;

/// Vertical reference lines across `spec`'s curves at the sleepers `exceptions` ((x m, what in words), in order):
/// one legend entry per kind ("sleeper: void 1.5 mm"), none when there are more than [`MARKED_SLEEPERS`].
fn mark_sleepers(spec: &mut PlotSpec, exceptions: &[(f64, String)]) {
    if exceptions.is_empty() || exceptions.len() > MARKED_SLEEPERS {
        return;
    }
    let ys = spec.series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
    let (low, high) = ys.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| (a.min(y), b.max(y)));
    if low.partial_cmp(&high) != Some(std::cmp::Ordering::Less) {
        return;
    }
    let mut named: Vec<&str> = Vec::new();
    for (x, what) in exceptions {
        let mut line = Series::reference(format!("sleeper: {what}"), (*x, low), (*x, high));
        if named.contains(&what.as_str()) {
            line.label = None;
        } else {
            named.push(what);
        }
        spec.series.push(line);
    }
}

/// One run with histories (the case's recorded sections) and the requested snapshots, reporting the finished
/// fraction of steps to `progress` every 1 % and abandoned with [`scenario::StudyError::Interrupted`] at the first step after
/// `stop` is raised.
pub fn run_with_snapshots(
    case: &Case,
    requests: &[SnapshotAt],
    stop: Option<&AtomicBool>,
    progress: &dyn Fn(f64),
) -> Result<(RunResult, Vec<Snapshot>)> {
    let settings = &case.settings;
    let mut taker = SnapshotTaker::new(&case.model, &case.interactions, settings, requests)?;
    let total = settings.step_count(case.model.mesh().length).max(1.0);
    // Every 0.1 % of the run: often enough for a run of hours, one call in a thousand steps.
    let every = ((total / 1000.0).ceil() as usize).max(1);
    let result = runner::simulate_observed(case, settings, stop, &mut |view| {
        if view.step % every == 0 {
            progress(view.step as f64 / total);
        }
        taker.observe(view)
    })?;
    Ok((result, taker.finish()?))
}

/// `histories.csv` of a run with step `h` (s).
pub fn histories_csv(result: &RunResult) -> String {
    let mut out = header(&HISTORY_COLUMNS) + "\n";
    let h = result.step;
    for s in &result.histories {
        for k in 0..s.time.len() {
            let force = s.impulse.as_ref().map_or(0.0, |p| p[k] / h);
            let values = [
                s.position,
                s.time[k],
                s.load_position[k],
                s.deflection[k],
                s.velocity[k],
                s.acceleration[k],
                s.moment[k],
                force,
            ];
            let _ = writeln!(out, "{}", row(&values));
        }
    }
    out
}

/// `snapshots.csv`.
pub fn snapshots_csv(snapshots: &[Snapshot]) -> String {
    let mut out = header(&SNAPSHOT_COLUMNS) + "\n";
    for s in snapshots {
        for i in 0..s.x.len() {
            let _ = writeln!(out, "{}", row(&[s.time, s.load_position, s.x[i], s.deflection[i], s.moment[i]]));
        }
    }
    out
}

/// What a run's figures draw: per recorded section its position (m) and (load position m, w m, M N·m) per step;
/// per snapshot its time (s), load position (m) and (x m, w m, M N·m) per node. Made from a run, or read back from
/// the `histories.csv` and `snapshots.csv` it wrote ([`RunCurves::from_csv`], for `frictrack plot`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RunCurves {
    /// (section position, points).
    pub sections: Vec<(f64, Vec<[f64; 3]>)>,
    /// (time, load position, points).
    pub instants: Vec<(f64, f64, Vec<[f64; 3]>)>,
}

impl RunCurves {
    /// The curves of a run's histories and snapshots.
    pub fn of(result: &RunResult, snapshots: &[Snapshot]) -> Self {
        let sections = result
            .histories
            .iter()
            .map(|s| {
                let points = (0..s.time.len()).map(|k| [s.load_position[k], s.deflection[k], s.moment[k]]).collect();
                (s.position, points)
            })
            .collect();
        let instants = snapshots
            .iter()
            .map(|s| {
                let points = (0..s.x.len()).map(|n| [s.x[n], s.deflection[n], s.moment[n]]).collect();
                (s.time, s.load_position, points)
            })
            .collect();
        Self { sections, instants }
    }

    /// The curves of the files a run wrote: `histories` and `snapshots` are the texts of `histories.csv` and
    /// `snapshots.csv` (columns [`HISTORY_COLUMNS`], [`SNAPSHOT_COLUMNS`]); rows grouped by section and by instant
    /// in file order.
    pub fn from_csv(histories: &str, snapshots: &str) -> Result<Self> {
        let h = crate::tables::Table::parse(histories, "histories.csv")?;
        let cols = |t: &crate::tables::Table, names: &[&str], source: &str| -> Result<Vec<usize>> {
            names.iter().map(|n| t.column(n, source)).collect()
        };
        let c = cols(&h, &["section", "load_position", "deflection", "moment"], "histories.csv")?;
        let mut sections: Vec<(f64, Vec<[f64; 3]>)> = Vec::new();
        for r in &h.rows {
            match sections.last_mut() {
                Some((x, points)) if *x == r[c[0]] => points.push([r[c[1]], r[c[2]], r[c[3]]]),
                _ => sections.push((r[c[0]], vec![[r[c[1]], r[c[2]], r[c[3]]]])),
            }
        }
        let t = crate::tables::Table::parse(snapshots, "snapshots.csv")?;
        let c = cols(&t, &["time", "load_position", "x", "deflection", "moment"], "snapshots.csv")?;
        let mut instants: Vec<(f64, f64, Vec<[f64; 3]>)> = Vec::new();
        for r in &t.rows {
            match instants.last_mut() {
                Some((time, _, points)) if *time == r[c[0]] => points.push([r[c[2]], r[c[3]], r[c[4]]]),
                _ => instants.push((r[c[0]], r[c[1]], vec![[r[c[2]], r[c[3]], r[c[4]]]])),
            }
        }
        Ok(Self { sections, instants })
    }
}

/// What a run's load position is the position of: "load" for a single force, "first axle" for a train, "first wheel"
/// for vehicles (the wheels stand at their offsets behind it).
pub fn position_noun(load: &track::Load) -> &'static str {
    match load {
        track::Load::Force(_) => "load",
        track::Load::Train(_) => "first axle",
        track::Load::Vehicles { .. } => "first wheel",
    }
}

/// Figures of the histories (deflection and moment against the load position, one curve per section) and of the
/// snapshots (deflected shape and moment along the beam, one curve per instant). `load` names what the positions are
/// of ([`position_noun`]).
pub fn run_plots(curves: &RunCurves, title: &str, load: &str, exceptions: &[(f64, String)]) -> Vec<PlotSpec> {
    let by_section = |value: usize, scale: f64| -> Curves {
        let curve = |(i, (x, points)): (usize, &(f64, Vec<[f64; 3]>))| {
            (format!("x = {x} m"), 1 + i, points.iter().map(|p| (p[0], p[value] * scale)).collect())
        };
        curves.sections.iter().enumerate().map(curve).collect()
    };
    let by_instant = |value: usize, scale: f64| -> Curves {
        let curve = |(i, (time, at, points)): (usize, &(f64, f64, Vec<[f64; 3]>))| {
            let label = format!("{load} at {at:.1} m (t = {time:.3} s)");
            (label, 1 + i, points.iter().map(|p| (p[0], p[value] * scale)).collect())
        };
        curves.instants.iter().enumerate().map(curve).collect()
    };
    let figure = |stem: &str, what: &str, x: &Axis, y: &Axis, curves: Curves| {
        quantity_figure(stem, &format!("{title}: {what}"), x, y, curves, false)
    };
    let deflection = Axis::noted("deflection w", "deflection", Shown::Milli, "upward > 0");
    let moment = Axis::noted("bending moment M", "moment", Shown::Kilo, "sagging > 0");
    let (w_scale, m_scale) = (deflection.factor(), moment.factor());
    let mut plots = Vec::new();
    // Each family as a deflection figure and a moment figure: (stem prefix, x axis, the two titles, the curves).
    let mut pair = |[stem_w, stem_m]: [&str; 2], x: &Axis, (what_w, what_m): (&str, &str), (w, m): (Curves, Curves)| {
        plots.push(figure(stem_w, what_w, x, &deflection, w));
        plots.push(figure(stem_m, what_m, x, &moment, m));
    };
    if !curves.sections.is_empty() {
        pair(
            [FIGURE_STEMS[0], FIGURE_STEMS[1]],
            &Axis::new(format!("{load} position x"), "load_position", Shown::Si),
            ("deflection at the recorded sections", "bending moment at the recorded sections"),
            (by_section(1, w_scale), by_section(2, m_scale)),
        );
    }
    if !curves.instants.is_empty() {
        pair(
            [FIGURE_STEMS[2], FIGURE_STEMS[3]],
            &Axis::new("position along the beam x", "x", Shown::Si),
            ("deflected shape", "bending moment along the beam"),
            (by_instant(1, w_scale), by_instant(2, m_scale)),
        );
        // Where the load is in each snapshot, a triangle on its curve (where it is on the beam).
        let drawn = plots.len();
        for spec in &mut plots[drawn - 2..] {
            for (i, &(_, at, _)) in curves.instants.iter().enumerate() {
                let Some(series) = spec.series.get(i) else { continue };
                if let Some(y) = value_at(&series.points, at) {
                    spec.marks.push(Mark { color: 1 + i, point: (at, y) });
                }
            }
            spec.mark_label = format!("{load} position");
            mark_sleepers(spec, exceptions);
        }
        // On a long beam each instant gets a panel around its load (a bowl of metres over hundreds is a needle).
        let shapes: Vec<(f64, &[[f64; 3]])> = curves.instants.iter().map(|(_, at, p)| (*at, p.as_slice())).collect();
        let extent =
            shapes.first().map_or(0.0, |(_, p)| p.last().map_or(0.0, |l| l[0]) - p.first().map_or(0.0, |f| f[0]));
        // Where their waves overlap (a train's), each instant a panel over the whole beam: drawn together they hide
        // each other.
        let loads: Vec<f64> = shapes.iter().map(|(at, _)| *at).collect();
        if let Some(half) = crate::snapshot_zoom::zoom_half_width(&shapes, extent) {
            for spec in &mut plots[drawn - 2..] {
                *spec = crate::snapshot_zoom::zoomed(spec.clone(), &loads, half);
            }
        } else if crate::snapshot_zoom::overlapping(&shapes) {
            for spec in &mut plots[drawn - 2..] {
                *spec = crate::snapshot_zoom::stacked(spec.clone(), &loads);
            }
        }
    }
    plots
}

/// The polyline `points` (in increasing x) at `x`, linearly interpolated; None outside it.
fn value_at(points: &[(f64, f64)], x: f64) -> Option<f64> {
    let i = points.partition_point(|p| p.0 < x);
    let (a, b) = (points.get(i.checked_sub(1)?)?, points.get(i)?);
    let t = if b.0 > a.0 { (x - a.0) / (b.0 - a.0) } else { 0.0 };
    Some(a.1 + t * (b.1 - a.1))
}
