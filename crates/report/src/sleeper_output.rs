//! What a run on sleepers reports of them (docs/theory.md §18): the track in words, the frequencies a discrete track
//! adds — sleeper passing v/a, the bay's lumped resonances, pinned–pinned —, the largest pad and ballast forces where
//! the results are read, the sleepers that differ from the rest, and the rail's deflection under the load over a bay.
//! Forces in N (compression positive), lengths in m, times in s, frequencies in Hz.

use fem_beam::{BallastContact, BeamModel, Extreme, Layer, Sleepers};
use scenario::axis::{Axis, Shown};
use scenario::quantities::unit;
use serde::Serialize;
use std::fmt::Write as _;
use track::simulation::{SleeperPeaks, SleeperResults};
use track::{PlacedInteractions, SectionKind};

/// Columns of `sleepers.csv`, the histories of the sleepers under recorded sections: name and unit. One row per
/// sleeper and step; the sleeper numbered from 0 as in `[[sleepers.exceptions]]`, its deflection upward, its
/// acceleration the step's mean, the forces compression positive from the settled state; a ballast body's acceleration
/// (the step's mean) under it, an empty field on rigidly founded ballast.
pub const SLEEPER_COLUMNS: [crate::columns::Column; 10] = [
    ("section", unit("section")),
    ("sleeper", unit("sleeper")),
    ("x", unit("x")),
    ("time", unit("time")),
    ("load_position", unit("load_position")),
    ("sleeper_deflection", unit("sleeper_deflection")),
    ("sleeper_acceleration", unit("sleeper_acceleration")),
    ("pad_force", unit("pad_force")),
    ("sleeper_ballast_force", unit("sleeper_ballast_force")),
    ("ballast_body_acceleration", unit("ballast_body_acceleration")),
];

/// `sleepers.csv` ([`SLEEPER_COLUMNS`]) of the recorded sleepers; None where no recorded section is over a sleeper.
pub fn sleepers_csv(results: Option<&SleeperResults>) -> Option<String> {
    let histories = &results?.histories;
    if histories.is_empty() {
        return None;
    }
    let mut out = SLEEPER_COLUMNS.iter().map(|(name, _)| *name).collect::<Vec<_>>().join(",") + "\n";
    for h in histories {
        for k in 0..h.time.len() {
            let values = [
                h.section,
                h.index as f64,
                h.x,
                h.time[k],
                h.load_position[k],
                h.deflection[k],
                h.acceleration[k],
                h.pad_force[k],
                h.ballast_force[k],
                h.ballast_acceleration.as_ref().map_or(f64::NAN, |a| a[k]),
            ];
            let _ = writeln!(out, "{}", scenario::number::row_with_gaps(&values));
        }
    }
    Some(out)
}

/// Bins of the bay (positions of the load between two sleepers) the deflection under the load is averaged over.
pub const BAY_BINS: usize = 20;

/// The sleepers in words (MN/m, kN·s/m: the units the literature quotes pads and ballast in), `count` of them.
pub fn sleepers_in_words(s: &Sleepers, count: usize) -> String {
    // Four significant digits: a sleeper derived from a soil (a tenth of the rail's mass over a bay) reads 3.596 kg,
    // not 3.596112.
    let n = |x: f64| scenario::number::significant(x, 4);
    let layer = |name: &str, l: &Layer| {
        format!("{name} {} MN/m, {} kN·s/m, η {}", n(l.stiffness / 1e6), n(l.damping / 1e3), n(l.loss_factor))
    };
    let body = s.ballast_body.map_or(String::new(), |b| {
        format!("; a ballast body of {} kg on the {}", n(b.mass), layer("subgrade", &b.subgrade))
    });
    format!(
        "{count} sleepers every {} m ({} kg; {}; {}{body})",
        n(s.spacing),
        n(s.mass),
        layer("pads", &s.pad),
        layer("ballast", &s.ballast)
    )
}

/// The sleepers of `model` in words ([`sleepers_in_words`]) and, where their ballast rests on an embankment beam,
/// that beam and its soil (MN·m², t/m, MN/m², kN·s/m² for the whole track: the rail carries half); None on a
/// continuous track.
pub fn track_in_words(model: &BeamModel) -> Option<String> {
    let (s, nodes) = model.sleepers()?;
    let sleepers = sleepers_in_words(s, nodes.len());
    let Some(below) = model.embankment() else { return Some(sleepers) };
    let n = |x: f64| scenario::number::significant(x, 4);
    let (beam, soil) = (&below.beam, &below.foundation);
    Some(format!(
        "{sleepers} over an embankment of EI {} MN·m², {} t/m (half under this rail), on soil of {} MN/m² and {} \
         kN·s/m²",
        n(2.0 * beam.bending_stiffness() / 1e6),
        n(2.0 * beam.mass_per_length() / 1e3),
        n(2.0 * soil.stiffness / 1e6),
        n(2.0 * soil.damping / 1e3)
    ))
}

/// A sleeper of an exception, over the run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExceptionalSleeper {
    /// Its number (0-based).
    pub index: usize,
    /// Where it sits (m).
    pub x: f64,
    /// What differs, in words ("void 1 mm", "tensionless", "friction 2 kN", "ballast × 0.5").
    pub what: String,
    /// Largest pad and ballast forces (N).
    pub pad_force: f64,
    /// See `pad_force`.
    pub ballast_force: f64,
    /// Its lowest position (m, downward).
    pub lowest: f64,
    /// Unilateral ballast: the largest gap under it (m) and when it first pressed (s).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub largest_gap: Option<f64>,
    /// See `largest_gap`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub first_contact: Option<f64>,
}

/// The rail's deflection under the load against the load's place in the bay.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BayProfile {
    /// The bins' centres ξ = (x − x_s)/a ∈ [0, 1) from the sleeper behind the load, and the mean downward deflection
    /// under the load there (m; None where no step fell) while the load was where the results are read.
    pub bins: Vec<(f64, Option<f64>)>,
    /// Above a sleeper (ξ = 0) and at mid-span (ξ = ½), m downward.
    pub above_sleeper: Option<f64>,
    /// See `above_sleeper`.
    pub mid_span: Option<f64>,
    /// Whether the bays beside the sleepers of the exceptions (within a spacing of one) were left out of the means:
    /// a void or a softer ballast there is not the track's bay. False when there are none, or when no other bay is
    /// read (then every bay is averaged).
    pub exceptions_left_out: bool,
    /// The load's steps a bay, a/(v h): below [`MIN_STEPS_PER_BAY`] the bins are sampled too sparsely for a profile
    /// (the figure is not drawn, and the text says why).
    pub steps_per_bay: f64,
}

/// The fewest load steps a bay the bay's profile is drawn from: one a bin (a load advance ≤ a/20, what the sleeper
/// passing frequency needs too), so that every bin is sampled whatever the load's phase against the sleepers.
pub const MIN_STEPS_PER_BAY: f64 = BAY_BINS as f64;

/// The sleepers under one run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SleepersSummary {
    /// The sleepers in words.
    pub track: String,
    /// How many sleepers.
    pub count: usize,
    /// a (m).
    pub spacing: f64,
    /// v/a (Hz).
    pub passing_frequency: f64,
    /// The bay lumped: track on ballast (on the subgrade under ballast bodies), rail on pads (Hz).
    pub track_resonance: f64,
    /// Under ballast bodies: the sleeper on the ballast (Hz).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sleeper_on_ballast_resonance: Option<f64>,
    /// See `track_resonance`.
    pub rail_on_pads_resonance: f64,
    /// The pinned–pinned frequency (Hz).
    pub pinned_pinned: f64,
    /// Sleepers on ballast that cannot pull (the engine's unilateral laws).
    pub unilateral: usize,
    /// Sleepers with friction on the ballast (the engine's Coulomb sliders), and their forces' sum F (N).
    pub sliders: usize,
    /// See `sliders`.
    pub slider_force: f64,
    /// The largest pad and ballast forces over the sleepers where the results are read (N), where and when.
    pub max_pad_force: Extreme,
    /// See `max_pad_force`.
    pub max_ballast_force: Extreme,
    /// Under ballast bodies: the largest subgrade force (N), where and when.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_subgrade_force: Option<Extreme>,
    /// The sleepers' largest |acceleration| where the results are read (m/s²), where and when: low-pass filtered
    /// like the rail's where the run filters (`acceleration_band`), else the step's mean.
    pub max_sleeper_acceleration: Extreme,
    /// Under ballast bodies: their largest |acceleration| (m/s², as the sleepers'), where and when.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_ballast_acceleration: Option<Extreme>,
    /// The band (Hz, −3 dB) the accelerations are filtered to, 0.443/T of the window T (s); None: the step's mean.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub acceleration_band: Option<f64>,
    /// The sleepers of `[[sleepers.exceptions]]`.
    pub exceptions: Vec<ExceptionalSleeper>,
    /// The deflection under the load over a bay.
    pub bay: BayProfile,
    /// The mesh's element length (m): between nodes the cubic element under-reads the deflection under a point load
    /// (the element ripple), so [`bay_plot`] draws the bins at nodes.
    pub element_length: f64,
    /// Where the results are read (m).
    pub read_region: [f64; 2],
}

impl SleepersSummary {
    /// The sleepers of `model` (with the interactions `placed` on it) under `results` at `speed` (m/s), forces read over `read` = [a, b] (m); None on a
    /// continuous track.
    pub fn of(
        model: &BeamModel,
        placed: &PlacedInteractions,
        results: Option<&SleeperResults>,
        speed: f64,
        read: [f64; 2],
    ) -> Option<Self> {
        let ((s, nodes), results) = (model.sleepers()?, results?);
        let inside = |p: &&SleeperPeaks| (read[0]..=read[1]).contains(&p.x);
        let largest = |value: fn(&SleeperPeaks) -> Option<(f64, f64)>| {
            results.sleepers.iter().filter(inside).fold(Extreme::default(), |mut e, p| {
                if let Some((v, t)) = value(p) {
                    e.raise(v, p.x, t);
                }
                e
            })
        };
        let lumped = s.bay_resonances(model.beam().mass_per_length());
        let exceptions = exceptional(s, results);
        Some(Self {
            track: track_in_words(model).unwrap_or_default(),
            count: nodes.len(),
            spacing: s.spacing,
            passing_frequency: speed / s.spacing,
            track_resonance: lumped.track,
            sleeper_on_ballast_resonance: lumped.sleeper_on_ballast,
            rail_on_pads_resonance: lumped.rail_on_pads,
            pinned_pinned: analytic::dispersion::pinned_pinned(model.beam(), s.spacing),
            unilateral: placed.count(SectionKind::SleeperBallast),
            sliders: placed.count(SectionKind::SleeperFriction),
            slider_force: (0..nodes.len()).map(|i| s.support(i).friction).sum(),
            max_pad_force: largest(|p| Some(p.pad_force)),
            max_ballast_force: largest(|p| Some(p.ballast_force)),
            max_subgrade_force: s.ballast_body.map(|_| largest(|p| p.subgrade_force)),
            max_sleeper_acceleration: largest(|p| Some(p.acceleration)),
            max_ballast_acceleration: s.ballast_body.map(|_| largest(|p| p.ballast_acceleration)),
            acceleration_band: results.acceleration_window.map(|t| track::simulation::filtered_record::HALF_POWER / t),
            bay: BayProfile::of(results, read, &exceptions.iter().map(|e| e.x).collect::<Vec<_>>()),
            exceptions,
            element_length: model.mesh().element_length(),
            read_region: read,
        })
    }
}

/// The sleepers named by an exception, in order.
fn exceptional(s: &Sleepers, results: &SleeperResults) -> Vec<ExceptionalSleeper> {
    results
        .sleepers
        .iter()
        .enumerate()
        .filter(|(i, _)| s.differs(*i))
        .map(|(index, p)| {
            let support = s.support(index);
            let mut what = Vec::new();
            match support.contact {
                BallastContact::Unilateral { gap } if gap > 0.0 => what.push(format!("void {} mm", gap * 1e3)),
                BallastContact::Unilateral { .. } => what.push("tensionless".into()),
                BallastContact::Bonded => {}
            }
            if support.friction > 0.0 {
                what.push(format!("friction {} kN", support.friction / 1e3));
            }
            for (name, layer, normal) in [("pad", support.pad, s.pad), ("ballast", support.ballast, s.ballast)] {
                if layer.stiffness != normal.stiffness {
                    what.push(format!("{name} × {}", layer.stiffness / normal.stiffness));
                }
            }
            ExceptionalSleeper {
                index,
                x: p.x,
                what: what.join(", "),
                pad_force: p.pad_force.0,
                ballast_force: p.ballast_force.0,
                lowest: p.lowest,
                largest_gap: p.largest_gap,
                first_contact: p.first_contact,
            }
        })
        .collect()
}

impl BayProfile {
    /// Whether the load takes [`MIN_STEPS_PER_BAY`] steps a bay, up to the round-off of its positions (0.6/0.03 m
    /// reads 19.999 999…).
    pub fn profiled(&self) -> bool {
        self.steps_per_bay >= MIN_STEPS_PER_BAY * (1.0 - 1e-6)
    }

    /// The mean downward deflection under the load in each of [`BAY_BINS`] bins of the bay, over the load's positions
    /// in `read` (m) outside the bays beside the sleepers at `exceptions` (m), where any remain.
    fn of(results: &SleeperResults, read: [f64; 2], exceptions: &[f64]) -> Self {
        let inside = |x: f64| (read[0]..=read[1]).contains(&x);
        let regular = |x: f64| exceptions.iter().all(|e| (x - e).abs() >= results.spacing);
        let left_out = !exceptions.is_empty()
            && results.under_load.iter().any(|&(x, _)| inside(x) && regular(x))
            && results.under_load.iter().any(|&(x, _)| inside(x) && !regular(x));
        let mut sums = [(0.0, 0usize); BAY_BINS];
        for &(x, w) in results.under_load.iter().filter(|&&(x, _)| inside(x) && (!left_out || regular(x))) {
            let xi = ((x - results.first) / results.spacing).rem_euclid(1.0);
            let bin = (xi * BAY_BINS as f64).round() as usize % BAY_BINS;
            sums[bin].0 -= w;
            sums[bin].1 += 1;
        }
        let bins: Vec<(f64, Option<f64>)> = (0..BAY_BINS)
            .map(|j| (j as f64 / BAY_BINS as f64, (sums[j].1 > 0).then(|| sums[j].0 / sums[j].1 as f64)))
            .collect();
        // The load's advance a step, from its first two positions on the rail.
        let advance = match results.under_load.as_slice() {
            [(a, _), (b, _), ..] => (b - a).abs(),
            _ => f64::INFINITY,
        };
        Self {
            above_sleeper: bins[0].1,
            mid_span: bins[BAY_BINS / 2].1,
            bins,
            exceptions_left_out: left_out,
            steps_per_bay: results.spacing / advance,
        }
    }
}

/// The sleepers' lines of a run's text report.
pub(crate) fn write_sleepers(f: &mut std::fmt::Formatter<'_>, s: &SleepersSummary) -> std::fmt::Result {
    let [a, b] = s.read_region;
    writeln!(f, "  track: {}", s.track)?;
    let lumped = match s.sleeper_on_ballast_resonance {
        None => format!("{:.0} Hz (track on ballast)", s.track_resonance),
        Some(middle) => format!("{:.0} Hz (track on subgrade), {middle:.0} Hz (sleeper on ballast)", s.track_resonance),
    };
    writeln!(
        f,
        "    sleeper passing v/a = {:.1} Hz; a bay lumped resonates at {lumped} and {:.0} Hz (rail on pads); \
         pinned–pinned {:.0} Hz",
        s.passing_frequency, s.rail_on_pads_resonance, s.pinned_pinned
    )?;
    let force = |e: &Extreme| match e.place() {
        Some((x, t)) => format!("{:.2} kN at x = {x:.1} m, t = {t:.4} s", e.value / 1e3),
        None => "none".into(),
    };
    let subgrade = s.max_subgrade_force.map_or(String::new(), |e| format!(", subgrade {}", force(&e)));
    writeln!(
        f,
        "    largest forces on the sleepers at x = {a:.1}–{b:.1} m: pad {}, ballast {}{subgrade}",
        force(&s.max_pad_force),
        force(&s.max_ballast_force)
    )?;
    let acceleration = |e: &Extreme| match e.place() {
        Some((x, t)) => format!("{:.3} m/s² at x = {x:.1} m, t = {t:.4} s", e.value),
        None => "none".into(),
    };
    let body = s.max_ballast_acceleration.map_or(String::new(), |e| format!(", ballast bodies {}", acceleration(&e)));
    let how = s.acceleration_band.map_or("the step's mean".into(), |band| format!("low-pass to {band:.0} Hz"));
    writeln!(
        f,
        "    largest accelerations there ({how}): sleepers {}{body}",
        acceleration(&s.max_sleeper_acceleration)
    )?;
    if !s.bay.profiled() {
        writeln!(
            f,
            "    deflection under the load over a bay: not profiled — the load takes {:.1} steps a bay ({MIN_STEPS_PER_BAY} \
             needed, one a bin: a load advance ≤ {:.4} m)",
            s.bay.steps_per_bay,
            s.spacing / MIN_STEPS_PER_BAY
        )?;
    } else if let (Some(above), Some(mid)) = (s.bay.above_sleeper, s.bay.mid_span) {
        writeln!(
            f,
            "    deflection under the load (mean over the bays there{}): {:.4} mm above a sleeper, {:.4} mm at mid-span \
             ({:+.2} %)",
            if s.bay.exceptions_left_out { ", those beside the exceptions left out" } else { "" },
            above * 1e3,
            mid * 1e3,
            (mid / above - 1.0) * 100.0
        )?;
    }
    for e in s.exceptions.iter().take(12) {
        let contact = match (e.largest_gap, e.first_contact) {
            (Some(_), Some(t)) => format!("; on the ballast first at t = {t:.4} s"),
            (Some(_), None) => "; never reached the ballast".into(),
            (None, _) => String::new(),
        };
        writeln!(
            f,
            "    sleeper {} at x = {:.2} m ({}): pad {:.2} kN, ballast {:.2} kN, lowest {:.3} mm{contact}",
            e.index,
            e.x,
            e.what,
            e.pad_force / 1e3,
            e.ballast_force / 1e3,
            e.lowest * 1e3
        )?;
    }
    if s.exceptions.len() > 12 {
        writeln!(f, "    … and {} more sleepers of the exceptions (the JSON lists them all)", s.exceptions.len() - 12)?;
    }
    Ok(())
}

/// The figure `bay` of a run on sleepers: the rail's mean downward deflection under the first load (mm) against the
/// load's distance from the sleeper behind it (m), over the bays where the results are read, at the mesh's nodes —
/// above a sleeper at both ends (the first bin drawn again at a), mid-span in the middle; the sleepers marked. None
/// where the load takes fewer than [`MIN_STEPS_PER_BAY`] steps a bay, or fewer than three points (the sleeper and
/// two nodes) were sampled: a profile of two or three scattered bins is no profile (the text says so).
pub fn bay_plot(s: &SleepersSummary, title: &str) -> Option<crate::plot::PlotSpec> {
    if !s.bay.profiled() || s.bay.above_sleeper.is_none() {
        return None;
    }
    use crate::plot::{Mark, PlotSpec, Series, Stroke};
    let mut spec = PlotSpec::new(
        "bay",
        format!("{title}: deflection under the load over a bay (v/a = {:.1} Hz)", s.passing_frequency),
        &Axis::new("load's distance from the sleeper behind it", "position", Shown::Si),
        &Axis::new("mean downward deflection under the load", "deflection_under_load", Shown::Milli),
    );
    // The bins centred on a node (within half a bin): between nodes a point load's deflection is under-read by the
    // cubic element, a ripple of the mesh, not of the track.
    let half_bin = 0.5 * s.spacing / BAY_BINS as f64;
    let on_node = |x: f64| (x - (x / s.element_length).round() * s.element_length).abs() <= half_bin;
    let mut points: Vec<(f64, f64)> = s
        .bay
        .bins
        .iter()
        .filter(|(xi, _)| on_node(xi * s.spacing))
        .filter_map(|&(xi, w)| Some((xi * s.spacing, w? * 1e3)))
        .collect();
    if let Some(above) = s.bay.above_sleeper {
        points.push((s.spacing, above * 1e3));
        spec.marks =
            vec![Mark { color: 0, point: (0.0, above * 1e3) }, Mark { color: 0, point: (s.spacing, above * 1e3) }];
        spec.mark_label = "above a sleeper".into();
    }
    let [a, b] = s.read_region;
    let change = match (s.bay.mid_span, s.bay.above_sleeper) {
        (Some(mid), Some(above)) => format!("; mid-span {:+.2} % from above a sleeper", (mid / above - 1.0) * 100.0),
        _ => String::new(),
    };
    let label = format!("on the nodes (every {} m){change}", scenario::number::significant(s.element_length, 6));
    // What the means are over, for the subtitle (its caller puts the run's line before it).
    spec.subtitle = format!(
        "mean over the load at x = {a:.1}–{b:.1} m{}",
        if s.bay.exceptions_left_out { " but the bays beside the exceptional sleepers" } else { "" }
    );
    if points.len() < 4 {
        return None;
    }
    spec.series.push(Series { label: Some(label), color: 0, stroke: Stroke::Solid, markers: true, points });
    Some(spec)
}
