//! The report of a train's steady wave on the ground (`frictrack stationary` on a `[ground]`): the text, the JSON
//! (`stationary.json`: the points, the beam, the ground and the axles, every number's unit in `units`), the CSV
//! (`wave.csv` for one speed, `speeds.csv` for several) and the figure — the wave along the train with its axles
//! marked, or the peaks over speed.

use crate::ground::comparison::Comparison;
use crate::ground::measured::MeasuredRecord;
use crate::ground::numbers::describe;
use crate::ground::text::table;
use crate::ground::wave::{GroundWave, GroundWavePoint, GroundWaveStudy};
use crate::ground::wave_point::LiftOffPoint;
use report::columns::{Column, ColumnMeta, listed_once, units_line};
use report::output::{Output, pretty};
use report::plot::{Mark, PlotSpec, Series, Stroke};
use scenario::axis::{Axis, Shown};
use scenario::ground::{GroundTrack, Interface};
use scenario::quantities::unit;
use serde::Serialize;
use std::fmt::{self, Formatter};

/// The columns of one speed's wave.
pub const WAVE_COLUMNS: [Column; 2] = [("s", unit("s")), ("deflection", unit("deflection"))];
/// The columns of one speed's wave where the sleepers may lift off a tensionless ballast: the opening and the
/// ballast's push beside the rail's deflection.
pub const LIFT_OFF_WAVE_COLUMNS: [Column; 4] = [
    ("s", unit("s")),
    ("deflection", unit("deflection")),
    ("gap", unit("gap")),
    ("ballast_force", unit("ballast_force")),
];
/// The columns of the points over speeds (the JSON keys of [`GroundWavePoint`], the extremes' positions beside them).
pub const POINT_COLUMNS: [Column; 8] = [
    ("speed", unit("speed")),
    ("max_downward_deflection", unit("max_downward_deflection")),
    ("max_downward_deflection_position", unit("max_downward_deflection_position")),
    ("max_upward_deflection", unit("max_upward_deflection")),
    ("max_upward_deflection_position", unit("max_upward_deflection_position")),
    ("deflection_under_load", unit("deflection_under_load")),
    ("deflection_behind", unit("deflection_behind")),
    ("spectrum_samples", unit("spectrum_samples")),
];
/// The numbers of the JSON outside its tables, with their units.
const NUMBERS: [&str; 23] = [
    "force_per_length",
    "lift_off_zones",
    "lifted_length",
    "largest_gap",
    "preload",
    "newton_iterations",
    "krylov_iterations",
    "friction_power",
    "slipping_length",
    "rear_force_ratio",
    "bending_stiffness",
    "mass_per_length",
    "width",
    "force",
    "offset",
    "direction",
    "shift",
    "rms_misfit",
    "rms_measured",
    "measured_max_downward",
    "measured_max_upward",
    "computed_max_downward",
    "computed_max_upward",
];
/// How far the figure reaches beyond a compared record and the train (m).
const MARGIN: f64 = 20.0;
/// The most waves one figure draws (more speeds: the peaks over speed).
const MOST_WAVES: usize = 4;

/// What `stationary.json` holds on a `[ground]`.
#[derive(Debug, Serialize)]
pub struct GroundWaveFile<'a> {
    /// "wave.csv" (one speed's wave) or "speeds.csv" (the points).
    pub csv: &'static str,
    /// The scenario's title.
    pub title: &'a str,
    /// EI (N·m²) of the beam: the composite beam, or the rail on the two-beam track.
    pub bending_stiffness: f64,
    /// ρA (kg/m) of the beam.
    pub mass_per_length: f64,
    /// 2b (m).
    pub width: f64,
    /// The profile in words.
    pub ground: String,
    /// The train's name ("single" for one load).
    pub train: &'a str,
    /// The axles as the beam carries them: offset behind the first (m) and force (N, downward).
    pub axles: Vec<AxleRow>,
    /// The ballast's friction f_u (N/m), where it has any — under the composite beam, or between the two-beam track's
    /// sleepers and embankment (each point then says how its
    /// wave was found and what the ballast takes, under `friction`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub force_per_length: Option<f64>,
    /// One point per speed.
    pub points: &'a [GroundWavePoint],
    /// What the points give warning of ([`GroundWaveStudy::warnings`]), as the command line prints them.
    pub warnings: Vec<String>,
    /// The measured record beside the wave, where one was given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub measured: Option<&'a Comparison>,
    /// Every number's unit.
    pub units: Vec<ColumnMeta>,
    /// The version that wrote it.
    pub frictrack_version: &'static str,
}

/// One axle in the JSON.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct AxleRow {
    /// m behind the first axle.
    pub offset: f64,
    /// N, downward.
    pub force: f64,
}

/// Every number's unit in the JSON: the single numbers, the points' and the wave's columns.
fn units() -> Vec<ColumnMeta> {
    listed_once(NUMBERS.iter().map(|&name| (name, unit(name))).chain(POINT_COLUMNS).chain(LIFT_OFF_WAVE_COLUMNS))
}

impl GroundWave {
    /// The wave as CSV ([`WAVE_COLUMNS`], or [`LIFT_OFF_WAVE_COLUMNS`] with the ballast beside it).
    pub fn csv(&self) -> String {
        self.columns_and_csv().1
    }

    /// Its columns and its CSV.
    fn columns_and_csv(&self) -> (&'static [Column], String) {
        let rows: Vec<usize> = (0..self.s.len()).collect();
        match &self.ballast {
            None => (&WAVE_COLUMNS, table(&WAVE_COLUMNS, &rows, |&i| vec![self.s[i], self.deflection[i]])),
            Some(b) => {
                let values = |&i: &usize| vec![self.s[i], self.deflection[i], b.gap[i], b.ballast_force[i]];
                (&LIFT_OFF_WAVE_COLUMNS, table(&LIFT_OFF_WAVE_COLUMNS, &rows, values))
            }
        }
    }
}

impl GroundWaveStudy {
    /// The wave at one speed as CSV (`wave.csv`), or the points over several (`speeds.csv`).
    pub fn table(&self) -> (&'static str, &'static [Column], String) {
        match self.waves.as_slice() {
            [wave] => {
                let (columns, csv) = wave.columns_and_csv();
                ("wave.csv", columns, csv)
            }
            _ => {
                let position = |e: fem_beam::Extreme| e.position.unwrap_or(f64::NAN);
                let csv = table(&POINT_COLUMNS, &self.points, |p| {
                    vec![
                        p.speed,
                        p.deflection.max_downward.value,
                        position(p.deflection.max_downward),
                        p.deflection.max_upward.value,
                        position(p.deflection.max_upward),
                        p.deflection_under_load,
                        p.deflection_behind,
                        p.spectrum_samples as f64,
                    ]
                });
                ("speeds.csv", &POINT_COLUMNS, csv)
            }
        }
    }

    /// The JSON file beside the CSV.
    pub fn file(&self) -> GroundWaveFile<'_> {
        GroundWaveFile {
            csv: self.table().0,
            title: &self.title,
            bending_stiffness: self.beam.0,
            mass_per_length: self.beam.1,
            width: self.strip.width,
            ground: describe(&self.strip),
            train: &self.train.name,
            axles: self.train.axles.iter().map(|a| AxleRow { offset: a.offset, force: a.force }).collect(),
            force_per_length: self.friction,
            points: &self.points,
            warnings: self.warnings(),
            measured: self.comparison.as_ref(),
            units: units(),
            frictrack_version: env!("CARGO_PKG_VERSION"),
        }
    }

    /// The beam, the ground and the load in one line.
    pub fn subtitle(&self) -> String {
        let load = match self.train.axles.as_slice() {
            [axle] => format!("one force of {:.0} kN", axle.force / 1e3),
            axles => {
                format!(
                    "{} ({} axles, {:.0} kN on the beam)",
                    self.train.name,
                    axles.len(),
                    self.train.total_force() / 1e3
                )
            }
        };
        let track = match &self.track {
            GroundTrack::Composite => format!("beam EI = {:.3e} N·m², {:.0} kg/m", self.beam.0, self.beam.1),
            GroundTrack::RailOnEmbankment { sleepers, embankment, interface } => format!(
                "rail EI = {:.3e} N·m² on pads, {:.0} kg sleepers every {} m and {}ballast over an embankment of EI = \
                 {:.3e} N·m², {:.0} kg/m",
                self.beam.0,
                sleepers.mass,
                sleepers.spacing,
                match interface {
                    Interface::Bonded => "",
                    Interface::Tensionless { .. } => "tensionless ",
                },
                embankment.bending_stiffness,
                embankment.mass_per_length
            ),
        };
        let friction = self.friction.map_or(String::new(), |f| format!(", ballast friction f_u = {} kN/m", f / 1e3));
        format!("{load}; {track}{friction} on a {} m strip of {}", self.strip.width, describe(&self.strip))
    }

    /// The figure: the waves along the train (up to four speeds; deflection in mm, the axles marked on the axis,
    /// `record` drawn where it was compared), or the peaks over speed where more were asked.
    pub fn figure(&self, record: Option<&MeasuredRecord>) -> PlotSpec {
        let over_speeds = self.waves.len() > MOST_WAVES;
        let what =
            if over_speeds { "Peak steady deflections over speed, on the ground" } else { "Steady wave on the ground" };
        let title = match self.title.is_empty() {
            true => what.to_string(),
            false => format!("{what} — {}", self.title),
        };
        let title = title.as_str();
        if over_speeds {
            let mut peaks = PlotSpec::new(
                "ground-wave-peaks",
                title,
                &Axis::new("speed v", "speed", Shown::Si),
                &Axis::new("peak deflection", "deflection", Shown::Milli),
            );
            peaks.subtitle = self.subtitle();
            for (label, color, value) in [
                ("largest downward deflection", 1, &|p: &GroundWavePoint| p.deflection.max_downward.value),
                ("largest upward deflection", 2, &|p: &GroundWavePoint| p.deflection.max_upward.value),
            ] as [(&str, usize, &dyn Fn(&GroundWavePoint) -> f64); 2]
            {
                let points = self.points.iter().map(|p| (p.speed, value(p) * 1e3)).collect();
                peaks.series.push(Series {
                    label: Some(label.into()),
                    color,
                    stroke: Stroke::Solid,
                    markers: true,
                    points,
                });
            }
            return peaks;
        }
        let mut figure = PlotSpec::new(
            "ground-wave",
            title,
            &Axis::noted("s = x − x_head", "s", Shown::Si, "positive ahead of the first axle"),
            &Axis::noted("deflection w", "deflection", Shown::Milli, "upward positive"),
        );
        figure.subtitle = self.subtitle();
        let placed: Vec<(f64, f64)> = match (&self.comparison, record) {
            (Some(c), Some(record)) => {
                record.x.iter().zip(&record.deflection).map(|(x, w)| (c.direction * x + c.shift, w * 1e3)).collect()
            }
            _ => Vec::new(),
        };
        // The train with its bow wave and wake (the window's), or, with a record, the record's span and the train.
        let (from, to) = match placed.is_empty() {
            true => (f64::NEG_INFINITY, f64::INFINITY),
            false => placed.iter().fold((-self.train.length() - MARGIN, MARGIN), |(a, b), p| (a.min(p.0), b.max(p.0))),
        };
        for (i, wave) in self.waves.iter().enumerate() {
            let inside =
                wave.s.iter().zip(&wave.deflection).filter(|(s, _)| (from - MARGIN..=to + MARGIN).contains(*s));
            let points = inside.map(|(s, w)| (*s, w * 1e3)).collect();
            let computed = if self.comparison.is_some() { "computed, " } else { "" };
            let label = format!("{computed}v = {:.1} m/s ({:.0} km/h)", wave.speed, wave.speed * scenario::units::KMH);
            figure.series.push(Series {
                label: Some(label),
                color: i + 1,
                stroke: Stroke::Solid,
                markers: false,
                points,
            });
        }
        if let Some(c) = &self.comparison {
            figure.series.push(measured_series(c, placed));
        }
        figure.marks = self.train.axles.iter().map(|a| Mark { color: 0, point: (-a.offset, 0.0) }).collect();
        figure.mark_label = "axles".into();
        figure
    }
}

/// The record placed at s = d·x + c (`placed`: s m, w mm), dashed black, its legend naming the file, the placement
/// and the RMS misfit.
fn measured_series(c: &Comparison, placed: Vec<(f64, f64)>) -> Series {
    let name = std::path::Path::new(&c.record).file_name().map_or(c.record.clone(), |n| n.to_string_lossy().into());
    let label = format!(
        "measured ({name}; placed at {}); RMS misfit {:.2} mm of the record's RMS {:.2} mm",
        placement(c),
        c.rms_misfit * 1e3,
        c.rms_measured * 1e3
    );
    Series { label: Some(label), color: 0, stroke: Stroke::Dashed, markers: false, points: placed }
}

/// A speed's line on the sleepers' lift-off.
fn lift_off_line(f: &mut Formatter<'_>, lift: &LiftOffPoint) -> fmt::Result {
    let held = match lift.preload < 0.0 {
        true => format!("the weight's compression {:.1} µm", -lift.preload * 1e6),
        false => "a weightless track".to_string(),
    };
    let iterations = lift.newton_iterations;
    match lift.lift_off_zones {
        0 => writeln!(
            f,
            "               the sleepers stay on the ballast ({held} is never undone; {iterations} Newton iteration(s))"
        ),
        zones => writeln!(
            f,
            "               the sleepers lift off the ballast over {:.2} m in {zones} stretch(es), by up to {:.1} µm at \
             s = {:.2} m ({held}; {iterations} Newton iterations)",
            lift.lifted_length,
            lift.largest_gap.value * 1e6,
            lift.largest_gap.position.unwrap_or(f64::NAN),
        ),
    }
}

/// Where the record was placed: "s = −x − 1.33 m".
fn placement(c: &Comparison) -> String {
    let x = if c.direction > 0.0 { "x" } else { "−x" };
    let sign = if c.shift < 0.0 { "−" } else { "+" };
    format!("s = {x} {sign} {:.2} m", c.shift.abs())
}

impl Output for GroundWaveStudy {
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let title = if self.title.is_empty() { String::new() } else { format!(" — {}", self.title) };
        writeln!(f, "frictrack stationary on the ground{title}: {}", self.subtitle())?;
        writeln!(
            f,
            "  speed (m/s)  (km/h)   max down (mm) at s (m)   max up (mm) at s (m)   down under the first axle (mm)"
        )?;
        for p in &self.points {
            let at = |e: fem_beam::Extreme| e.position.map_or("—".into(), |s| format!("{s:.2}"));
            writeln!(
                f,
                "  {:>11.2}  {:>6.0}   {:>13.3} {:>8}   {:>11.3} {:>8}   {:>30.3}",
                p.speed,
                p.speed * scenario::units::KMH,
                p.deflection.max_downward.value * 1e3,
                at(p.deflection.max_downward),
                p.deflection.max_upward.value * 1e3,
                at(p.deflection.max_upward),
                -p.deflection_under_load * 1e3
            )?;
            if let Some(friction) = &p.friction {
                writeln!(
                    f,
                    "               the rail slips over {:.1} m and the ballast takes {:.2} kW; the window's last tenth \
                     behind holds {:.2} f_u ({} Newton iterations, {} GMRES steps)",
                    friction.slipping_length,
                    friction.friction_power / 1e3,
                    friction.rear_force_ratio,
                    friction.newton_iterations,
                    friction.krylov_iterations
                )?;
            }
            if let Some(lift) = &p.lift_off {
                lift_off_line(f, lift)?;
            }
        }
        if let Some(c) = &self.comparison {
            writeln!(
                f,
                "  measured ({}): peaks {:.2} mm down, {:.2} mm up; computed at its points {:.2} down, {:.2} up",
                c.record,
                c.measured_max_downward * 1e3,
                c.measured_max_upward * 1e3,
                c.computed_max_downward * 1e3,
                c.computed_max_upward * 1e3
            )?;
            writeln!(
                f,
                "    RMS misfit {:.2} mm against the record's RMS {:.2} mm (placed at {}, the best fit)",
                c.rms_misfit * 1e3,
                c.rms_measured * 1e3,
                placement(c)
            )?;
        }
        Ok(())
    }

    fn json(&self) -> serde_json::Result<String> {
        pretty(&serde_json::to_value(self.file())?)
    }

    fn csv(&self) -> Option<String> {
        let (_, columns, csv) = self.table();
        Some(format!("{csv}# {}\n", units_line(columns.iter().copied())))
    }
}
