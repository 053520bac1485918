//! The figures of a speed sweep (`frictrack sweep --out FILE.csv`, and `frictrack plot FILE.csv` from the file
//! afterwards): the max deflections against speed (whole run, and while the load is in the window), the max
//! acceleration, the dissipated energy when there is friction or damping, and with vehicles the wheel forces and
//! the bodies' accelerations.

use crate::figures::{
    Curves, DeflectionCurve, deflection_figure, dissipated_energy_axis, load_speed_axis, quantity_figure,
};
use crate::plot::PlotSpec;
use crate::tables::Table;
use fem_beam::{DeflectionExtremes, Extreme};
use nscd::EnergyBalance;
use runner::{CSV_COLUMNS, CriticalSpeed, SweepPoint, VEHICLE_CSV_COLUMNS, VehicleColumns};
use scenario::Scenario;
use scenario::axis::{Axis, Shown};
use scenario::error::Result;

/// The figures' names after the sweep's stem: `{stem}-{suffix}` (each only when it has something to draw).
pub const FIGURE_SUFFIXES: [&str; 5] = ["deflection", "acceleration", "energy", "wheel-forces", "body-acceleration"];

/// What a sweep figure says of its case under the title, so that it reads alone in a report: the load, the soil
/// with its damping, the friction — "F = 83.4 kN; k_f = 250 kN/m², undamped; friction: 31 devices × 50 kN".
pub fn case_line(s: &Scenario) -> String {
    let load = match &s.load.train {
        Some(train) => format!("train {train}"),
        None if s.vehicle.is_some() => "vehicles".to_string(),
        None => format!("F = {} kN", scenario::number::significant(s.load.force / 1e3, 4)),
    };
    let f = &s.foundation;
    let soil = match (f.stiffness > 0.0, f.damping, f.damping_ratio) {
        (false, _, _) => "no foundation (a span)".to_string(),
        (true, Some(c), _) if c > 0.0 => format!("k_f = {} kN/m², c_f = {c} N·s/m²", f.stiffness / 1e3),
        (true, _, Some(z)) if z > 0.0 => format!("k_f = {} kN/m², ζ = {z}", f.stiffness / 1e3),
        (true, _, _) => format!("k_f = {} kN/m², undamped", f.stiffness / 1e3),
    };
    let friction = s.friction.describe().unwrap_or_else(|| "none".to_string());
    format!("{load}; {soil}; friction: {friction}")
}

/// The figures of `points` (in speed order), named `{stem}-deflection`, `{stem}-acceleration`, `{stem}-energy`,
/// `{stem}-wheel-forces`, `{stem}-body-acceleration`; headed by the scenario's title (else "speed sweep") and
/// [`case_line`] where the scenario is known; an interior `critical` speed is marked and its refinement runs drawn.
pub fn sweep_plots(
    points: &[SweepPoint],
    stem: &str,
    scenario: Option<&Scenario>,
    critical: Option<&CriticalSpeed>,
) -> Vec<PlotSpec> {
    let title = match scenario.map(|s| s.title.as_str()).filter(|t| !t.is_empty()) {
        Some(t) => t.to_string(),
        None => "speed sweep".to_string(),
    };
    // Markers where the points are few enough to tell apart (the renderer drops them past its own limit).
    let markers = points.len() <= crate::plot::MAX_MARKED_POINTS;
    let sheet = Sheet { points, stem, title, case: scenario.map(case_line), markers };
    let mut plots = vec![sheet.deflection(critical)];
    let mut accelerations = Vec::new();
    if points.iter().any(|p| p.max_acceleration.is_some()) {
        accelerations.push((
            "at the nodes".into(),
            0,
            sheet.series(&|p| p.max_acceleration.map_or(f64::NAN, |a| a.value)),
        ));
    }
    if points.iter().any(|p| p.band_acceleration.is_some()) {
        let band = scenario.and_then(|s| s.acceleration_band().ok().flatten());
        let name = match band {
            Some(fem_beam::modal_band::BandLimit::Frequency(f)) => format!("in the modes up to {f} Hz"),
            _ => "in the deck's EN 1990 band".to_string(),
        };
        accelerations.push((name, 1, sheet.series(&|p| p.band_acceleration.map_or(f64::NAN, |a| a.value))));
    }
    if !accelerations.is_empty() {
        plots.push(sheet.quantity(
            "acceleration",
            "max acceleration",
            &Axis::new("max vertical acceleration", "max_acceleration", Shown::Si),
            accelerations,
        ));
    }
    if points.iter().any(|p| p.energy.dissipated > 0.0) {
        let kilojoules = dissipated_energy_axis();
        let kj = kilojoules.factor();
        plots.push(sheet.quantity(
            "energy",
            "dissipated energy",
            &kilojoules,
            vec![("dissipated".into(), 0, sheet.series(&|p| p.energy.dissipated * kj))],
        ));
    }
    if points.iter().all(|p| p.vehicles.is_some()) && !points.is_empty() {
        plots.extend(sheet.vehicles());
    }
    plots
}

/// What every figure of one sweep shares: its points, file stem, title, the case line under it, and markers.
struct Sheet<'a> {
    points: &'a [SweepPoint],
    stem: &'a str,
    title: String,
    case: Option<String>,
    markers: bool,
}

impl Sheet<'_> {
    /// (speed, value) of every point.
    fn series(&self, value: &dyn Fn(&SweepPoint) -> f64) -> Vec<(f64, f64)> {
        self.points.iter().map(|p| (p.speed, value(p))).collect()
    }

    /// The deflections over speed, whole run and load in the window, with the refined critical speed's runs drawn
    /// on the curve so that the refined peak lies on it.
    fn deflection(&self, critical: Option<&CriticalSpeed>) -> PlotSpec {
        let mut downward = self.series(&|p| p.deflection.max_downward.value);
        downward.extend(critical.iter().flat_map(|c| c.evaluations.iter().copied()));
        downward.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut deflection = deflection_figure(
            &format!("{}-deflection", self.stem),
            &format!("{}: max deflection vs speed", self.title),
            &load_speed_axis(),
            vec![
                DeflectionCurve {
                    label: "whole run".into(),
                    color: 0,
                    downward,
                    upward: self.series(&|p| p.deflection.max_upward.value),
                    optimum: critical.filter(|c| c.is_interior()).map(|c| (c.speed, c.max_downward_deflection)),
                },
                DeflectionCurve {
                    label: "load in the window".into(),
                    color: 1,
                    downward: self.series(&|p| p.window_deflection.max_downward.value),
                    upward: self.series(&|p| p.window_deflection.max_upward.value),
                    optimum: None,
                },
            ],
            &match critical.filter(|c| c.is_interior()) {
                Some(c) => format!("critical speed {:.1} m/s", c.speed),
                None => "refined critical speed".to_string(),
            },
        );
        deflection.subtitle = match &self.case {
            Some(c) => format!("{c}; downward solid, upward dashed"),
            None => "downward solid, upward dashed".to_string(),
        };
        deflection
    }

    /// A quantity over speed, in figure `<stem>-<name>`.
    fn quantity(&self, name: &str, what: &str, y: &Axis, curves: Curves) -> PlotSpec {
        let title = format!("{}: {what} vs speed", self.title);
        let stem = format!("{}-{name}", self.stem);
        let mut spec = quantity_figure(&stem, &title, &load_speed_axis(), y, curves, self.markers);
        if let Some(c) = &self.case {
            spec.subtitle = c.clone();
        }
        spec
    }

    /// The vehicles' wheel forces and body accelerations over speed.
    fn vehicles(&self) -> [PlotSpec; 2] {
        let wheel =
            |f: &dyn Fn(&VehicleColumns) -> f64| self.series(&|p: &SweepPoint| p.vehicles.map_or(f64::NAN, |v| f(&v)));
        let kilonewtons = Axis::noted("contact force Q", "max_wheel_force", Shown::Kilo, "compressive > 0");
        let kn = kilonewtons.factor();
        [
            self.quantity(
                "wheel-forces",
                "wheel–rail contact forces",
                &kilonewtons,
                vec![
                    ("largest of any wheel".into(), 0, wheel(&|v: &VehicleColumns| v.max_wheel_force * kn)),
                    (
                        "smallest of any wheel (0: contact lost)".into(),
                        1,
                        wheel(&|v: &VehicleColumns| v.min_wheel_force * kn),
                    ),
                ],
            ),
            self.quantity(
                "body-acceleration",
                "body accelerations",
                &Axis::new("body acceleration", "max_body_acceleration", Shown::Si),
                vec![
                    ("largest of any body".into(), 0, wheel(&|v: &VehicleColumns| v.max_body_acceleration)),
                    ("largest RMS".into(), 1, wheel(&|v: &VehicleColumns| v.rms_body_acceleration)),
                ],
            ),
        ]
    }
}

/// The points of a sweep CSV as `frictrack sweep` writes it (columns [`CSV_COLUMNS`], and [`VEHICLE_CSV_COLUMNS`]
/// with vehicles, [`runner::SLEEPER_CSV_COLUMNS`] on sleepers; an older file's names of the extremes' node and time too); the rows of failed runs (empty fields)
/// are left out.
pub fn read_sweep_csv(text: &str, source: &str) -> Result<Vec<SweepPoint>> {
    let table = Table::parse(text, source)?;
    // Files of frictrack before result format 5 name the extremes' node and time `max_downward_position`, …: read
    // under either name.
    let index = |name: &str| {
        table.column(name, source).or_else(|e| {
            let old = name.replace("_deflection_position", "_position").replace("_deflection_time", "_time");
            if old == name { Err(e) } else { table.column(&old, source).map_err(|_| e) }
        })
    };
    let base: Vec<usize> = CSV_COLUMNS.iter().map(|(n, _, _)| index(n)).collect::<Result<_>>()?;
    let vehicles: Option<Vec<usize>> = VEHICLE_CSV_COLUMNS.iter().map(|(n, _, _)| index(n).ok()).collect();
    let sleepers: Option<Vec<usize>> = runner::SLEEPER_CSV_COLUMNS.iter().map(|(n, _, _)| index(n).ok()).collect();
    let band = index(runner::BAND_CSV_COLUMNS[0].0).ok();
    Ok(table
        .rows
        .iter()
        .filter(|r| !r[base[1]].is_nan())
        .map(|r| {
            let v: Vec<f64> = base.iter().map(|&i| r[i]).collect();
            let place = |x: f64| (!x.is_nan()).then_some(x);
            let extreme =
                |value: f64, position: f64, time: f64| Extreme { value, position: place(position), time: place(time) };
            SweepPoint {
                speed: v[0],
                deflection: DeflectionExtremes {
                    max_downward: extreme(v[1], v[5], v[6]),
                    max_upward: extreme(v[2], f64::NAN, f64::NAN),
                },
                window_deflection: DeflectionExtremes {
                    max_downward: extreme(v[10], v[11], v[12]),
                    max_upward: extreme(v[13], v[14], v[15]),
                },
                max_acceleration: place(v[16]).map(|a| extreme(a, f64::NAN, f64::NAN)),
                band_acceleration: band.and_then(|c| place(r[c])).map(|a| extreme(a, f64::NAN, f64::NAN)),
                global_norm: v[4],
                // The CSV holds three of the balance's terms; the others are not known from it.
                energy: EnergyBalance { load_work: v[7], dissipated: v[3], residual: v[8], ..EnergyBalance::unknown() },
                mean_iterations: v[9],
                vehicles: vehicles.as_ref().map(|c| VehicleColumns {
                    min_wheel_force: r[c[0]],
                    max_wheel_force: r[c[1]],
                    max_dynamic_increment: r[c[2]],
                    losses_of_contact: r[c[3]] as usize,
                    max_body_acceleration: r[c[4]],
                    rms_body_acceleration: r[c[5]],
                }),
                sleepers: sleepers.as_ref().map(|c| {
                    let present = |x: f64| (!x.is_nan()).then_some(x);
                    runner::SleeperColumns {
                        max_pad_force: r[c[0]],
                        max_ballast_force: r[c[1]],
                        exception_ballast_force: present(r[c[2]]),
                        neighbour_ballast_force: present(r[c[3]]),
                        exception_lowest: present(r[c[4]]),
                    }
                }),
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::read_sweep_csv;
    use fem_beam::{DeflectionExtremes, Extreme};
    use nscd::EnergyBalance;
    use runner::{SweepPoint, write_csv};

    /// What `write_csv` writes, `read_sweep_csv` reads back to the bit (the sleepers' columns with an absent one).
    #[test]
    fn a_sweep_csv_reads_back() {
        let point = |speed: f64| SweepPoint {
            speed,
            deflection: DeflectionExtremes {
                max_downward: Extreme::at(0.1 + speed * 1e-3, 100.0, 0.5),
                max_upward: Extreme { value: 0.05, position: None, time: None },
            },
            window_deflection: DeflectionExtremes {
                max_downward: Extreme::at(0.09, 99.0, 0.45),
                max_upward: Extreme::at(0.04, 98.0, 0.44),
            },
            max_acceleration: Some(Extreme { value: 12.0, position: None, time: None }),
            band_acceleration: Some(Extreme { value: 3.0 + speed * 1e-2, position: None, time: None }),
            global_norm: 0.3,
            energy: EnergyBalance { load_work: 1e3, dissipated: 12.5, residual: 1e-12, ..EnergyBalance::unknown() },
            mean_iterations: 3.0,
            vehicles: None,
            sleepers: Some(runner::SleeperColumns {
                max_pad_force: 4e4,
                max_ballast_force: 3.9e4,
                exception_ballast_force: None,
                neighbour_ballast_force: Some(5.5e4 + speed),
                exception_lowest: Some(1.6e-3),
            }),
        };
        let points = vec![point(10.0), point(20.0), point(30.0)];
        let mut csv = Vec::new();
        write_csv(&points, &mut csv).unwrap();
        let text = String::from_utf8(csv).unwrap() + "# failed_run {}\n";
        // Debug forms compare the balance's unknown terms (NaN: not in the CSV) as equal.
        let same = |a: &[SweepPoint], b: &[SweepPoint]| assert_eq!(format!("{a:?}"), format!("{b:?}"));
        same(&read_sweep_csv(&text, "sweep.csv").unwrap(), &points);
        // An extreme that never happened (no upward deflection in the window) has no place nor time: empty fields.
        let mut still = point(40.0);
        still.window_deflection.max_upward = Extreme::default();
        let mut csv = Vec::new();
        write_csv(std::slice::from_ref(&still), &mut csv).unwrap();
        let text = String::from_utf8(csv).unwrap();
        assert!(text.lines().nth(1).unwrap().contains(",0,,,"), "{text}");
        let back = &read_sweep_csv(&text, "sweep.csv").unwrap()[0];
        assert_eq!(back.window_deflection.max_upward, Extreme::default());
        // A file of the earlier format (`max_downward_position`, …) reads back the same.
        let mut csv = Vec::new();
        write_csv(&points, &mut csv).unwrap();
        let old = String::from_utf8(csv).unwrap().replacen("_deflection_position", "_position", 3).replacen(
            "_deflection_time",
            "_time",
            3,
        );
        assert!(old.starts_with("speed,") && old.lines().next().unwrap().contains(",max_downward_position,"));
        same(&read_sweep_csv(&old, "old.csv").unwrap(), &points);
    }
}
