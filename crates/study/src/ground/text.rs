//! The report of the ground (`frictrack ground`, `frictrack.ground` in Python): the text, the JSON (every number's
//! unit in `units`), the CSV of the fundamental mode, the folder (ground.json, dispersion.csv, modes.csv,
//! speeds.csv, equivalent_stiffness.csv) and three figures — the dispersion curves with the beam's and the critical
//! speeds, the deflection over speed, |k_eq| over k_x at a few speeds.

use crate::ground::GroundStudy;
use crate::ground::numbers::{TrackKind, beam_phase_velocity};
use report::columns::{Column, ColumnMeta, header, listed_once, units_line};
use report::output::{Output, pretty};
use report::plot::{Mark, PlotSpec, Series, Stroke};
use scenario::axis::{Axis, Shown};
use scenario::number::row;
use scenario::quantities::unit;
use std::fmt::{self, Formatter};

/// The columns of the fundamental mode's table.
pub const DISPERSION_COLUMNS: [Column; 2] =
    [("frequency", unit("frequency")), ("phase_velocity", unit("phase_velocity"))];
/// The columns of the speed curve.
pub const SPEED_COLUMNS: [Column; 3] = [
    ("speed", unit("speed")),
    ("max_downward_deflection", unit("max_downward_deflection")),
    ("max_upward_deflection", unit("max_upward_deflection")),
];
/// The columns of k_eq along the load's line.
pub const STIFFNESS_COLUMNS: [Column; 5] = [
    ("speed", unit("speed")),
    ("wavenumber", unit("wavenumber")),
    ("frequency", unit("frequency")),
    ("stiffness_real", unit("stiffness_real")),
    ("stiffness_imaginary", unit("stiffness_imaginary")),
];
/// The numbers of the JSON outside its tables, with their units.
const NUMBERS: [&str; 15] = [
    "force",
    "bending_stiffness",
    "mass_per_length",
    "width",
    "minimum_phase_velocity",
    "minimum_phase_velocity_frequency",
    "static_strip_stiffness",
    "static_deflection",
    "winkler_critical_speed",
    "dispersion_crossing_speed",
    "dispersion_crossing_frequency",
    "free_beam_crossing_speed",
    "free_beam_crossing_frequency",
    "critical_speed",
    "critical_deflection",
];
/// The files `frictrack ground --out` writes.
const FILES: [&str; 11] = [
    "ground.json",
    "dispersion.csv",
    "modes.csv",
    "speeds.csv",
    "equivalent_stiffness.csv",
    "ground-dispersion.png",
    "ground-dispersion.svg",
    "ground-speeds.png",
    "ground-speeds.svg",
    "ground-stiffness.png",
    "ground-stiffness.svg",
];

/// Create `folder` if missing and check that none of the ground's files there is a link, device or directory.
pub fn check_folder(folder: &std::path::Path, what: &str) -> scenario::error::Result<bool> {
    let created = report::files::prepare_output_folder(what, folder)?;
    FILES.iter().try_for_each(|name| report::files::check_output_file(what, &folder.join(name)))?;
    Ok(created)
}

/// Every number's unit in the JSON: the tables' columns and the single numbers.
fn units() -> Vec<ColumnMeta> {
    let singles = NUMBERS.iter().map(|&name| (name, unit(name)));
    let columns = DISPERSION_COLUMNS.into_iter().chain(SPEED_COLUMNS).chain(STIFFNESS_COLUMNS);
    listed_once(singles.chain(columns).chain([("phase_velocities", unit("phase_velocities"))]))
}

/// `rows` as CSV under the header of `columns`, each row's numbers from `values`.
pub(crate) fn table<T>(columns: &[Column], rows: &[T], values: impl Fn(&T) -> Vec<f64>) -> String {
    let mut csv = header(columns) + "\n";
    for r in rows {
        csv.push_str(&row(&values(r)));
        csv.push('\n');
    }
    csv
}

impl GroundStudy {
    /// The fundamental mode, one row per frequency where it is trapped.
    pub fn dispersion_csv(&self) -> String {
        table(&DISPERSION_COLUMNS, &self.dispersion, |p| vec![p.frequency, p.phase_velocity])
    }

    /// Every trapped mode: frequency, then the modes' phase velocities (m/s), slowest first, as many as there are.
    fn modes_csv(&self) -> String {
        let most = self.modes.iter().map(|m| m.phase_velocities.len()).max().unwrap_or(0);
        let names: Vec<String> = (0..most).map(|i| format!("phase_velocity_{i}")).collect();
        let mut csv = format!("frequency,{}\n", names.join(","));
        for m in &self.modes {
            let cells: Vec<String> = m.phase_velocities.iter().map(|c| c.to_string()).collect();
            csv.push_str(&format!("{},{}{}\n", m.frequency, cells.join(","), ",".repeat(most - cells.len())));
        }
        csv
    }

    /// The JSON: the study and `units`.
    fn to_json(&self) -> serde_json::Result<String> {
        let mut value = serde_json::to_value(self)?;
        value["units"] = serde_json::to_value(units())?;
        pretty(&value)
    }

    /// Write the folder (created if missing; every file checked first, each written atomically), `what` naming it
    /// in errors; the figures' file names.
    pub fn write_folder(&self, folder: &std::path::Path, what: &str) -> scenario::error::Result<Vec<String>> {
        use report::files::{write_atomically, write_figures};
        check_folder(folder, what)?;
        let json = self.to_json().map_err(|e| scenario::error::StudyError::Io {
            path: folder.join("ground.json").display().to_string(),
            message: e.to_string(),
        })?;
        write_atomically(&folder.join("ground.json"), json.as_bytes())?;
        write_atomically(&folder.join("dispersion.csv"), self.dispersion_csv().as_bytes())?;
        write_atomically(&folder.join("modes.csv"), self.modes_csv().as_bytes())?;
        let speeds =
            table(&SPEED_COLUMNS, &self.speeds, |p| vec![p.speed, p.deflection.max_downward, p.deflection.max_upward]);
        write_atomically(&folder.join("speeds.csv"), speeds.as_bytes())?;
        let stiffness = table(&STIFFNESS_COLUMNS, &self.equivalent_stiffness, |p| {
            vec![p.speed, p.wavenumber, p.frequency, p.stiffness_real, p.stiffness_imaginary]
        });
        write_atomically(&folder.join("equivalent_stiffness.csv"), stiffness.as_bytes())?;
        write_figures(what, &[self.dispersion_figure(), self.speeds_figure(), self.stiffness_figure()], folder)
    }

    /// The title of every figure.
    fn heading(&self, what: &str) -> String {
        match self.title.is_empty() {
            true => what.to_string(),
            false => format!("{what} — {}", self.title),
        }
    }

    /// The beam and the ground in one line, for the figures' subtitles.
    fn subtitle(&self) -> String {
        let beam = match self.track {
            TrackKind::CompositeBeam => "beam",
            TrackKind::RailOnEmbankment => "rail on sleepers over the embankment (estimates on its whole-track twin)",
        };
        format!(
            "{beam} EI = {:.3e} N·m², {:.0} kg/m on a {} m strip; ground: {}",
            self.bending_stiffness, self.mass_per_length, self.width, self.profile
        )
    }

    /// A dashed horizontal (or, `vertical`, vertical) line at `value` across `span`, labelled.
    fn line(label: String, color: usize, value: f64, span: (f64, f64), vertical: bool) -> Series {
        let points = match vertical {
            true => vec![(value, span.0), (value, span.1)],
            false => vec![(span.0, value), (span.1, value)],
        };
        Series { label: Some(label), color, stroke: Stroke::Dashed, markers: false, points }
    }

    /// Phase velocity over frequency: the soil's fundamental mode and higher modes, the beam's free waves on k_w, the
    /// critical speeds as lines, the least phase velocity and the crossing marked.
    pub fn dispersion_figure(&self) -> PlotSpec {
        let mut figure = PlotSpec::new(
            "ground-dispersion",
            self.heading("Dispersion of the ground and the track"),
            &Axis::new("frequency f", "frequency", Shown::Si),
            &Axis::new("phase velocity c", "phase_velocity", Shown::Si),
        );
        figure.subtitle = self.subtitle();
        let fundamental = self.dispersion.iter().map(|p| (p.frequency, p.phase_velocity)).collect();
        figure.series.push(Series {
            label: Some("soil, fundamental Rayleigh mode".into()),
            color: 1,
            stroke: Stroke::Solid,
            markers: false,
            points: fundamental,
        });
        let most = self.modes.iter().map(|m| m.phase_velocities.len()).max().unwrap_or(0);
        for index in 1..most {
            let points: Vec<(f64, f64)> =
                self.modes.iter().filter_map(|m| m.phase_velocities.get(index).map(|&c| (m.frequency, c))).collect();
            let label = (index == 1).then(|| "soil, higher modes (the n-th slowest at each frequency)".to_string());
            figure.series.push(Series { label, color: 2, stroke: Stroke::Solid, markers: false, points });
        }
        figure.series.extend(self.beam_curves());
        let span = (self.modes.first().map_or(0.0, |m| m.frequency), self.modes.last().map_or(1.0, |m| m.frequency));
        if let Some(v) = self.critical_speed {
            figure.series.push(Self::line(format!("critical speed on the ground, {v:.1} m/s"), 4, v, span, false));
        }
        let v = self.winkler_critical_speed;
        figure.series.push(Self::line(
            format!("Winkler control (beam on the static strip stiffness), {v:.1} m/s"),
            6,
            v,
            span,
            false,
        ));
        if let (Some(f), Some(c)) = (self.minimum_phase_velocity_frequency, self.minimum_phase_velocity) {
            figure.marks.push(Mark { color: 1, point: (f, c) });
        }
        if let (Some(f), Some(c)) = (self.dispersion_crossing_frequency, self.dispersion_crossing_speed) {
            figure.marks.push(Mark { color: 3, point: (f, c) });
        }
        if let (Some(f), Some(c)) = (self.free_beam_crossing_frequency, self.free_beam_crossing_speed) {
            figure.marks.push(Mark { color: 3, point: (f, c) });
        }
        figure.mark_label = match (self.minimum_phase_velocity.is_some(), figure.marks.len()) {
            (_, 0) => String::new(),
            (true, 1) => "the soil's least phase velocity".into(),
            (true, _) => "the soil's least phase velocity; where a beam's curve meets the soil's".into(),
            (false, _) => "where a beam's curve meets the soil's".into(),
        };
        figure
    }

    /// The beam's free waves over the frequencies of the modes, on k_w (solid) and without it (dashed), up to 1.5
    /// times the soil's fastest fundamental phase velocity.
    fn beam_curves(&self) -> Vec<Series> {
        let ceiling = self.dispersion.iter().map(|p| p.phase_velocity).fold(0.0, f64::max) * 1.5;
        let curve = |spring: f64| -> Vec<(f64, f64)> {
            self.modes
                .iter()
                .map(|m| {
                    (
                        m.frequency,
                        beam_phase_velocity(self.bending_stiffness, self.mass_per_length, spring, m.frequency),
                    )
                })
                .filter(|&(_, c)| c <= ceiling)
                .collect()
        };
        [
            (self.static_strip_stiffness, "beam on the static strip stiffness", Stroke::Solid),
            (0.0, "free beam (no stiffness under it)", Stroke::Dashed),
        ]
        .into_iter()
        .map(|(spring, label, stroke)| Series {
            label: Some(label.into()),
            color: 3,
            stroke,
            markers: false,
            points: curve(spring),
        })
        .filter(|series| !series.points.is_empty())
        .collect()
    }

    /// The largest downward and upward deflections over speed, the critical speeds as vertical lines.
    pub fn speeds_figure(&self) -> PlotSpec {
        let mut figure = PlotSpec::new(
            "ground-speeds",
            self.heading("Steady deflection over speed, on the ground"),
            &Axis::new("speed v", "speed", Shown::Si),
            &Axis::new("deflection", "deflection", Shown::Milli),
        );
        figure.subtitle = format!("one force of {:.0} kN; {}", self.force / 1e3, self.subtitle());
        let curve = |label: &str, color, values: Vec<(f64, f64)>| Series {
            label: Some(label.into()),
            color,
            stroke: Stroke::Solid,
            markers: true,
            points: values,
        };
        let down: Vec<(f64, f64)> = self.speeds.iter().map(|p| (p.speed, p.deflection.max_downward * 1e3)).collect();
        let up: Vec<(f64, f64)> = self.speeds.iter().map(|p| (p.speed, p.deflection.max_upward * 1e3)).collect();
        let top = down.iter().map(|p| p.1).fold(0.0, f64::max);
        figure.series.push(curve("largest downward deflection", 1, down));
        figure.series.push(curve("largest upward deflection (the wake)", 2, up));
        if let Some(v) = self.critical_speed {
            figure.series.push(Self::line(format!("critical speed on the ground, {v:.1} m/s"), 4, v, (0.0, top), true));
        }
        let v = self.winkler_critical_speed;
        figure.series.push(Self::line(
            format!("Winkler control (beam on the static strip stiffness), {v:.1} m/s"),
            6,
            v,
            (0.0, top),
            true,
        ));
        if let Some(c) = self.minimum_phase_velocity {
            figure.series.push(Self::line(format!("soil's least phase velocity, {c:.1} m/s"), 3, c, (0.0, top), true));
        }
        figure
    }

    /// |k_eq| over k_x (both logarithmic) along the load's line at each speed computed.
    pub fn stiffness_figure(&self) -> PlotSpec {
        let mut figure = PlotSpec::new(
            "ground-stiffness",
            self.heading("The ground's stiffness under the track"),
            &Axis::new("wavenumber k_x", "wavenumber", Shown::Si),
            &Axis::new("|k_eq(k_x, k_x v)|", "equivalent_stiffness", Shown::Si),
        );
        figure.subtitle = self.subtitle();
        (figure.log_x, figure.log_y) = (true, true);
        let mut speeds: Vec<f64> = self.equivalent_stiffness.iter().map(|p| p.speed).collect();
        speeds.dedup();
        for (i, &v) in speeds.iter().enumerate() {
            let points = self
                .equivalent_stiffness
                .iter()
                .filter(|p| p.speed == v)
                .map(|p| (p.wavenumber, p.stiffness_real.hypot(p.stiffness_imaginary)))
                .collect();
            let label = format!("v = {v:.1} m/s ({:.0} km/h)", v * scenario::units::KMH);
            figure.series.push(Series {
                label: Some(label),
                color: i + 1,
                stroke: Stroke::Solid,
                markers: false,
                points,
            });
        }
        figure
    }
}

/// "62.3 m/s (224 km/h)", or "undefined (see the warnings)".
fn speed(value: Option<f64>) -> String {
    value
        .map_or("undefined (see the warnings)".into(), |v| format!("{v:.2} m/s ({:.0} km/h)", v * scenario::units::KMH))
}

impl Output for GroundStudy {
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let title = if self.title.is_empty() { String::new() } else { format!(" — {}", self.title) };
        writeln!(f, "frictrack ground{title}: {}", self.subtitle())?;
        let least = match (self.minimum_phase_velocity, self.minimum_phase_velocity_frequency) {
            (Some(c), Some(at)) => format!("{c:.2} m/s at {at:.2} Hz"),
            (Some(c), None) => format!("{c:.2} m/s at every frequency (not dispersive)"),
            (None, _) => "undefined (see the warnings)".into(),
        };
        writeln!(
            f,
            "  soil: fundamental Rayleigh mode over {} frequencies; least phase velocity {least}",
            self.modes.len()
        )?;
        let (whose, spring) = match self.track {
            TrackKind::CompositeBeam => ("", "the Winkler spring with that deflection"),
            TrackKind::RailOnEmbankment => {
                ("the rail ", "the Winkler spring under which the whole-track twin deflects as on the ground")
            }
        };
        writeln!(
            f,
            "  static: {whose}{:.3} mm under {:.0} kN; {spring} k_w = {:.4e} N/m²",
            self.static_deflection * 1e3,
            self.force / 1e3,
            self.static_strip_stiffness
        )?;
        writeln!(f, "  critical speed on the ground:      {}", speed(self.critical_speed))?;
        if let Some(w) = self.critical_deflection {
            writeln!(f, "    largest downward deflection there: {:.3} mm", w * 1e3)?;
        }
        writeln!(f, "  Winkler control (beam on k_w):     {}", speed(Some(self.winkler_critical_speed)))?;
        writeln!(f, "  beam on k_w meets the soil's mode: {}", speed(self.dispersion_crossing_speed))?;
        writeln!(f, "  free beam meets the soil's mode:   {}", speed(self.free_beam_crossing_speed))?;
        Ok(())
    }

    fn json(&self) -> serde_json::Result<String> {
        self.to_json()
    }

    fn csv(&self) -> Option<String> {
        Some(format!("{}# {}\n", self.dispersion_csv(), units_line(DISPERSION_COLUMNS.iter().copied())))
    }
}
