//! What a run with vehicles reports of them (docs/theory.md §12): per wheel the contact force's extremes, ΔQ/Q₀,
//! losses of contact and impacts, the rail's deflection and moment under it; per vehicle the body's acceleration; the
//! contacts' energy terms — as a serialisable summary, a long-format CSV of the wheel histories and a figure.
//!
//! `wheels.csv`: `vehicle,wheel,time,position,force,rail_deflection,moment` — one row per wheel and step (–, –, s, m,
//! N, m, N·m); vehicles and wheels numbered from 1, the wheel by its number in the run as in the text report. The force is the step's mean contact force p/h (compressive > 0), the rail deflection upward > 0 (0 off
//! the beam, where the rail is rigid ground), the moment EI·w″ of the rail under the wheel, sagging > 0.

use crate::figures::{Curves, quantity_figure};
use crate::mesh_ripple::element_ripple;
use crate::plot::PlotSpec;
use scenario::axis::{Axis, Shown};
use scenario::number::row;
use scenario::quantities::unit;
use serde::Serialize;
use std::fmt::Write as _;
use track::simulation::VehicleResults;

/// The figure of a run with vehicles, without extension (PNG and SVG each).
pub const WHEEL_FIGURE: &str = "wheel-forces";

/// Most vehicles drawn in the figure, a panel each (all are in the CSV): beyond four the panels grow too small.
pub const MAX_VEHICLES_DRAWN: usize = 4;

/// Columns of `wheels.csv`: name and unit.
pub const WHEEL_COLUMNS: [crate::columns::Column; 7] = [
    ("vehicle", unit("vehicle")),
    ("wheel", unit("wheel")),
    ("time", unit("time")),
    ("position", unit("position")),
    ("force", unit("force")),
    ("rail_deflection", unit("rail_deflection")),
    ("moment", unit("moment")),
];

/// One wheel. Wheels and vehicles are numbered from 1 in every output (text, JSON, CSV, figures): `wheel` is the
/// wheel's number in the run, front to back, as in the text report and `wheels.csv`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WheelReport {
    /// Its number in the run (from 1).
    pub wheel: usize,
    /// Its vehicle (from 1).
    pub vehicle: usize,
    /// Its number within its vehicle (from 1).
    pub vehicle_wheel: usize,
    /// Offset behind the first wheel (m).
    pub offset: f64,
    /// Static wheel load Q₀ (N).
    pub static_force: f64,
    /// Smallest and largest contact force (N).
    pub min_force: f64,
    /// Largest contact force (N).
    pub max_force: f64,
    /// max |Q − Q₀|/Q₀.
    pub dynamic_increment: f64,
    /// Number of losses of contact.
    pub losses_of_contact: usize,
    /// Total time without contact (s).
    pub time_off_rail: f64,
    /// Largest landing impact force (N), 0 without a landing.
    pub max_impact_force: f64,
    /// Largest downward rail deflection under the wheel (m).
    pub max_rail_deflection: f64,
    /// Largest |rail bending moment| under the wheel (N·m).
    pub max_moment: f64,
    /// Amplitude of the wheel force's component with the element period where results are read (N): a mesh
    /// artefact on a uniform track ([`crate::mesh_ripple`]); None where too few periods or samples to read it.
    pub element_ripple: Option<f64>,
}

/// One loss of contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LossReport {
    /// Which wheel of the run (from 1, as [`WheelReport::wheel`]).
    pub wheel: usize,
    /// Where and when it lifted off (m, s).
    pub lift_off_position: f64,
    /// Time of lift-off (s).
    pub lift_off_time: f64,
    /// Where it landed (m), None if still flying at the end.
    pub landing_position: Option<f64>,
    /// Time off the rail (s).
    pub duration: f64,
    /// Largest force within 10 ms of landing (N).
    pub impact_force: f64,
}

/// One vehicle's body.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyReport {
    /// The vehicle's name.
    pub name: String,
    /// Largest |acceleration| (m/s²).
    pub max_acceleration: f64,
    /// RMS acceleration (m/s²).
    pub rms_acceleration: f64,
}

/// Everything a run reports of its vehicles.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct VehicleReport {
    /// The contact law's name.
    pub contact: String,
    /// Smallest wheel force of any wheel (N).
    pub min_wheel_force: f64,
    /// Largest wheel force (N).
    pub max_wheel_force: f64,
    /// Largest ΔQ/Q₀ of any wheel.
    pub max_dynamic_increment: f64,
    /// Losses of contact over all wheels.
    pub losses_of_contact: usize,
    /// Largest body acceleration of any vehicle (m/s²).
    pub max_body_acceleration: f64,
    /// Largest body RMS acceleration (m/s²).
    pub max_rms_body_acceleration: f64,
    /// Work of the contact forces on beam and vehicles (J).
    pub contact_work: f64,
    /// Energy in the contacts at the end (J).
    pub spring_energy: f64,
    /// Energy the contacts dissipated: landings and the implicit contact law (J).
    pub contact_loss: f64,
    /// Strain energy changed by the position projection of rigid contacts (J; 0 without them).
    pub projection_work: f64,
    /// Every wheel.
    pub wheels: Vec<WheelReport>,
    /// Every loss of contact.
    pub losses: Vec<LossReport>,
    /// Every body.
    pub bodies: Vec<BodyReport>,
}

impl VehicleReport {
    /// The report of `results` with contact law `contact` (its name).
    ///
    /// `ripple_over`: the element length (m) and the region [from, to] (m) where results are read, over which each
    /// wheel's element ripple is measured; None where the wheel positions do not run along the track (a co-moving
    /// window's jump back at each shift).
    pub fn of(results: &VehicleResults, contact: &str, ripple_over: Option<(f64, [f64; 2])>) -> Self {
        let wheels: Vec<WheelReport> = results
            .wheels
            .iter()
            .enumerate()
            .map(|(i, w)| WheelReport {
                wheel: i + 1,
                vehicle: w.vehicle + 1,
                vehicle_wheel: w.wheel + 1,
                offset: w.offset,
                static_force: w.static_force,
                min_force: w.min_force,
                max_force: w.max_force,
                dynamic_increment: w.dynamic_increment(),
                losses_of_contact: w.losses.len(),
                time_off_rail: w.time_off_rail(),
                max_impact_force: w.losses.iter().map(|l| l.impact_force).fold(0.0, f64::max),
                max_rail_deflection: w.max_rail_deflection,
                max_moment: w.max_moment,
                element_ripple: ripple_over
                    .and_then(|(l, read)| element_ripple(&w.history.position, &w.history.force, l, read)),
            })
            .collect();
        let losses = results
            .wheels
            .iter()
            .enumerate()
            .flat_map(|(i, w)| {
                w.losses.iter().map(move |l| LossReport {
                    wheel: i + 1,
                    lift_off_position: l.lift_off_position,
                    lift_off_time: l.lift_off_time,
                    landing_position: l.landing_position,
                    duration: l.duration,
                    impact_force: l.impact_force,
                })
            })
            .collect();
        let bodies: Vec<BodyReport> = results
            .bodies
            .iter()
            .map(|b| BodyReport {
                name: b.name.clone(),
                max_acceleration: b.max_acceleration,
                rms_acceleration: b.rms_acceleration,
            })
            .collect();
        // The aggregates once, as the sweeps' columns.
        let columns = runner::VehicleColumns::of(results);
        Self {
            contact: contact.to_string(),
            min_wheel_force: columns.min_wheel_force,
            max_wheel_force: columns.max_wheel_force,
            max_dynamic_increment: columns.max_dynamic_increment,
            losses_of_contact: columns.losses_of_contact,
            max_body_acceleration: columns.max_body_acceleration,
            max_rms_body_acceleration: columns.rms_body_acceleration,
            contact_work: results.contact_work,
            spring_energy: results.spring_energy,
            contact_loss: results.contact_loss,
            projection_work: results.projection_work,
            wheels,
            losses,
            bodies,
        }
    }
}

/// `wheels.csv`.
pub fn wheels_csv(results: &VehicleResults) -> String {
    let mut out = WHEEL_COLUMNS.iter().map(|(name, _)| *name).collect::<Vec<_>>().join(",") + "\n";
    for (i, w) in results.wheels.iter().enumerate() {
        let h = &w.history;
        for k in 0..h.time.len() {
            let values = [
                (w.vehicle + 1) as f64,
                (i + 1) as f64,
                h.time[k],
                h.position[k],
                h.force[k],
                h.rail_deflection[k],
                h.moment[k],
            ];
            let _ = writeln!(out, "{}", row(&values));
        }
    }
    out
}

/// The contact force of each wheel against the wheel's position, in kN, while the wheel is inside `range` (m): the
/// beam, or the nodes the extremes are taken over. Outside it the wheels stand on rigid ground or run over a finite
/// track's ends, whose pinned supports they hit at their slope (docs/theory.md §12); `wheels.csv` has every step.
/// A panel per group of at most two wheels — a vehicle with more (a rail car's four) gets one per half, so that no
/// wheel's curve hides under another's — for the first [`MAX_VEHICLES_DRAWN`] vehicles; one chart for one group.
/// The static wheel load Q₀ is said once in the subtitle where all wheels share it, else in each legend entry.
pub fn wheel_plot(results: &VehicleResults, title: &str, range: (f64, f64)) -> PlotSpec {
    let vehicles = results.wheels.iter().map(|w| w.vehicle + 1).max().unwrap_or(0);
    let first = results.wheels.first().map_or(0.0, |w| w.static_force);
    let shared = results.wheels.iter().all(|w| (w.static_force - first).abs() <= 1e-9 * first.abs());
    // (vehicle, its wheels' indices in `results.wheels`), split in halves where a vehicle has more than two.
    let mut groups: Vec<(usize, Vec<usize>)> = Vec::new();
    for vehicle in 0..vehicles.min(MAX_VEHICLES_DRAWN) {
        let wheels: Vec<usize> = (0..results.wheels.len()).filter(|&i| results.wheels[i].vehicle == vehicle).collect();
        let half = if wheels.len() > 2 { wheels.len().div_ceil(2) } else { wheels.len().max(1) };
        groups.extend(wheels.chunks(half).map(|c| (vehicle, c.to_vec())));
    }
    let panel = |(vehicle, wheels): &(usize, Vec<usize>)| -> PlotSpec {
        let curves: Curves = wheels
            .iter()
            .enumerate()
            .map(|(k, &i)| {
                let w = &results.wheels[i];
                let inside = |x: &f64| (range.0..=range.1).contains(x);
                let points = w.history.position.iter().zip(&w.history.force);
                let points = points.filter(|(x, _)| inside(x)).map(|(&x, &f)| (x, f / 1e3)).collect();
                let label = match shared {
                    true => format!("wheel {}", i + 1),
                    false => format!("wheel {} (Q₀ = {:.1} kN)", i + 1, w.static_force / 1e3),
                };
                (label, 1 + k, points)
            })
            .collect();
        let name = results.bodies.get(*vehicle).map_or(String::new(), |b| format!(" ({})", b.name));
        let which = match (wheels.first(), wheels.last()) {
            (Some(a), Some(b)) if a != b => format!(", wheels {}–{}", a + 1, b + 1),
            (Some(a), _) => format!(", wheel {}", a + 1),
            _ => String::new(),
        };
        let caption = if groups.len() <= 1 { "contact force Q" } else { "Q" };
        quantity_figure(
            WHEEL_FIGURE,
            &format!("vehicle {}{name}{which}", vehicle + 1),
            &Axis::new("wheel position x", "position", Shown::Si),
            &Axis::new(caption, "force", Shown::Kilo),
            curves,
            false,
        )
    };
    let shown = if vehicles > MAX_VEHICLES_DRAWN {
        format!(" (first {MAX_VEHICLES_DRAWN} of {vehicles} vehicles)")
    } else {
        String::new()
    };
    let heading = format!("{title}: wheel–rail contact force Q{shown}");
    let static_load = if shared { format!("; static wheel load Q₀ = {:.1} kN", first / 1e3) } else { String::new() };
    let subtitle = format!("wheels at {:.0}–{:.0} m; Q > 0 in compression{static_load}", range.0, range.1);
    let mut spec = match groups.as_slice() {
        [one] => panel(one),
        _ => {
            let mut spec = PlotSpec::new(WHEEL_FIGURE, "", &Axis::none(), &Axis::none());
            spec.panels = groups.iter().map(panel).collect();
            spec
        }
    };
    spec.title = heading;
    spec.subtitle = subtitle;
    spec
}
