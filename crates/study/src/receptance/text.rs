//! The report of a receptance (`frictrack receptance`'s text, JSON and CSV, `frictrack.receptance` in Python) and
//! its figure in the form the literature draws: |α| (m/N, logarithmic) over a logarithmic frequency axis, the phase
//! (degrees) below.

use crate::receptance::ReceptanceStudy;
use report::columns::{Column, header, units_line};
use report::output::{Output, pretty};
use report::plot::{PanelY, PlotSpec, Series, Stroke};
use scenario::axis::{Axis, Shown};
use scenario::number::row;
use scenario::quantities::unit;
use std::fmt::{self, Formatter};

/// The CSV's columns.
pub const RECEPTANCE_COLUMNS: [Column; 6] = [
    ("frequency", unit("frequency")),
    ("real", unit("real")),
    ("imaginary", unit("imaginary")),
    ("magnitude", unit("magnitude")),
    ("phase", unit("phase")),
    ("mobility", unit("mobility")),
];

/// The place of a receptance on the ground: under the force on the infinite beam.
pub const ON_THE_INFINITE_BEAM: &str = "on the infinite beam";

/// The files a receptance writes into its folder.
const FILES: [&str; 4] = ["receptance.csv", "receptance.json", "receptance.png", "receptance.svg"];

/// Create `folder` if missing and check that none of a receptance's files there is a link, device or directory
/// (`what` names the folder in errors): before the work, so that a bad folder costs nothing. Whether the folder was
/// created here.
pub fn check_folder(folder: &std::path::Path, what: &str) -> scenario::error::Result<bool> {
    let created = report::files::prepare_output_folder(what, folder)?;
    FILES.iter().try_for_each(|name| report::files::check_output_file(what, &folder.join(name)))?;
    Ok(created)
}

impl ReceptanceStudy {
    /// One row per frequency ([`RECEPTANCE_COLUMNS`]).
    pub fn csv(&self) -> String {
        let mut csv = header(&RECEPTANCE_COLUMNS) + "\n";
        for p in &self.points {
            csv.push_str(&row(&[p.frequency, p.real, p.imaginary, p.magnitude, p.phase, p.mobility]));
            csv.push('\n');
        }
        csv
    }

    /// Write receptance.csv, receptance.json and the figure into `folder` (created if missing; every file checked
    /// first, written atomically), `what` naming the folder in errors (`--out`, `out`); the figures' file names.
    pub fn write_folder(&self, folder: &std::path::Path, what: &str) -> scenario::error::Result<Vec<String>> {
        use report::files::{write_atomically, write_figures};
        check_folder(folder, what)?;
        let json = pretty(self).map_err(|e| scenario::error::StudyError::Io {
            path: folder.join("receptance.json").display().to_string(),
            message: e.to_string(),
        })?;
        write_atomically(&folder.join("receptance.csv"), ReceptanceStudy::csv(self).as_bytes())?;
        write_atomically(&folder.join("receptance.json"), json.as_bytes())?;
        write_figures(what, &[self.figure()], folder)
    }

    /// What was computed: where, the rail as `rail` names it, what carries it.
    fn describe(&self, rail: &str) -> String {
        let among = if self.place.is_empty() { String::new() } else { format!(" ({})", self.place) };
        let place = match self.kind {
            "point" if self.place == ON_THE_INFINITE_BEAM => "point receptance of the infinite beam".to_string(),
            "point" => format!("point receptance at x = {} m{among}", self.at),
            _ => format!("transfer receptance at x = {} m{among}, force at {} m", self.at, self.excite),
        };
        match self.place == ON_THE_INFINITE_BEAM {
            true => format!("{place}; {rail}, η {}; on {}", self.loss_factors[0], self.support),
            false => format!("{place}; {rail} rail, η {}; {}", self.loss_factors[0], self.support),
        }
    }

    /// The figure: magnitude over frequency (both logarithmic) above the phase, the resonances marked.
    pub fn figure(&self) -> PlotSpec {
        let title = if self.title.is_empty() { "Track receptance" } else { self.title.as_str() };
        let mut figure =
            PlotSpec::new("receptance", title, &Axis::new("frequency f", "frequency", Shown::Si), &Axis::none());
        // The rail's theory without its parameters: the subtitle must stay one readable line.
        figure.subtitle = self.describe(self.rail.split(" (").next().unwrap_or(&self.rail));
        let curve = |label: &str, points: Vec<(f64, f64)>| Series {
            label: Some(label.into()),
            color: 1,
            stroke: Stroke::Solid,
            markers: false,
            points,
        };
        // The resonances named in the panel's title: the triangles say where, the title what.
        let named: Vec<String> = self
            .resonances
            .iter()
            .map(|r| format!("{:.0} Hz{}", r.frequency, r.name.map_or(String::new(), |n| format!(" {n}"))))
            .collect();
        let heading = match named.is_empty() {
            true => "magnitude".to_string(),
            false => format!("magnitude; resonances (▲, refined): {}", named.join(", ")),
        };
        let mut magnitude = PlotSpec::new(
            "",
            heading,
            &Axis::new("frequency f", "frequency", Shown::Si),
            &Axis::new("|α|", "magnitude", Shown::Si),
        );
        (magnitude.log_x, magnitude.log_y) = (true, true);
        // The refined resonances are points of the curve: a peak between the grid's frequencies stands on it.
        let mut points: Vec<(f64, f64)> = self.points.iter().map(|p| (p.frequency, p.magnitude)).collect();
        for r in &self.resonances {
            report::figures::insert_refined(&mut points, (r.frequency, r.magnitude));
        }
        magnitude.series.push(curve("|α|", points));
        magnitude.marks = self
            .resonances
            .iter()
            .map(|r| report::plot::Mark { color: 1, point: (r.frequency, r.magnitude) })
            .collect();
        if !magnitude.marks.is_empty() {
            magnitude.mark_label = "resonance (refined)".into();
        }
        let mut phase = PlotSpec::new(
            "",
            "phase (−90° and below: the rail lags the force)",
            &Axis::new("frequency f", "frequency", Shown::Si),
            &Axis::new("arg α", "phase", Shown::Si),
        );
        phase.log_x = true;
        phase.series.push(curve("arg α", self.points.iter().map(|p| (p.frequency, p.phase)).collect()));
        figure.panels = vec![magnitude, phase];
        figure.panel_y = PanelY::EachOwn;
        figure
    }
}

impl Output for ReceptanceStudy {
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let title = if self.title.is_empty() { String::new() } else { format!(" — {}", self.title) };
        writeln!(f, "frictrack receptance{title}: {}", self.describe(&self.rail))?;
        let (first, last) = (self.points[0], self.points[self.points.len() - 1]);
        writeln!(
            f,
            "  {} frequencies, {} … {} Hz: |α| from {:.3e} to {:.3e} m/N",
            self.points.len(),
            first.frequency,
            last.frequency,
            first.magnitude,
            last.magnitude
        )?;
        match self.resonances.as_slice() {
            [] => writeln!(f, "  no resonance peak in that range")?,
            peaks => {
                writeln!(
                    f,
                    "  resonances (peaks of |α| 5 % or more above their bases, refined between the frequencies given):"
                )?;
                for r in peaks {
                    writeln!(
                        f,
                        "    {:>10.2} Hz  |α| = {:.3e} m/N  (prominence {:.2}){}",
                        r.frequency,
                        r.magnitude,
                        r.prominence,
                        r.name.map_or(String::new(), |n| format!("  {n}"))
                    )?;
                }
            }
        }
        Ok(())
    }

    fn json(&self) -> serde_json::Result<String> {
        pretty(self)
    }

    fn csv(&self) -> Option<String> {
        Some(format!("{}# {}\n", ReceptanceStudy::csv(self), units_line(RECEPTANCE_COLUMNS.iter().copied())))
    }
}
