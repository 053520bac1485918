//! `frictrack run` through a co-moving window (`[co_moving]`, `--co-moving`; docs/theory.md §15): the window built
//! from the scenario's rail, soil, friction and element length, checked against the wave it must hold, run, and
//! summarised. Deflections (m, from the settled rail, magnitudes for peaks), positions s = x − x_load (m), energies
//! (J).

use analytic::MovingBeam;
use fem_beam::{AbsorbingZones, BeamModel, DeflectionExtremes, Extreme, Foundation, Mesh, Support, Supports};
use nscd::EnergyBalance;
use scenario::error::{Result, invalid};
use scenario::quantities::unit;
use scenario::{CoMovingSection, Scenario};
use serde::Serialize;
use track::co_moving::{CoMovingResult, CoMovingSettings, run_co_moving};

/// Where the wave must have fallen to, relative to its peak, before it reaches a window's absorbing zone: 1 %.
pub const WINDOW_DECAY: f64 = 0.01;

/// A co-moving run, summarised.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CoMovingSummary {
    /// The scenario's title.
    pub title: String,
    /// v (m/s).
    pub speed: f64,
    /// F (N).
    pub load: f64,
    /// Ballast friction f_u (N/m), 0 without.
    pub distributed_friction: f64,
    /// The soil's law: "linear", "tensionless" or "bilinear".
    pub soil: &'static str,
    /// Window length, track travelled, the load's place in the window, absorbing zones, element length (m).
    pub window: f64,
    /// Track travelled (m).
    pub track_length: f64,
    /// The load's place in the window (m from its rear).
    pub load_at: f64,
    /// Absorbing zone at each end (m).
    pub zones: f64,
    /// Element length (m).
    pub element_length: f64,
    /// Steps and shifts.
    pub steps: usize,
    /// Shifts of the window.
    pub shifts: usize,
    /// Largest downward and upward deflections between the absorbing zones over the run (m, magnitudes), where on
    /// the track (m from where the window started) and when (s).
    #[serde(flatten)]
    pub deflection: DeflectionExtremes,
    /// The wave in the frame at the end: its largest downward deflection (m) and where (s, m).
    pub wave_max_downward_deflection: Extreme,
    /// After each window length: (distance travelled m, max change of the wave / its peak).
    pub changes: Vec<(f64, f64)>,
    /// The energy balance (J), with what the window carried out behind as `transported`.
    pub energy: EnergyBalance,
    /// The solver that ran ("none" without interactions).
    pub solver: &'static str,
    /// Wall time of the loop (s).
    pub wall_time: f64,
    /// Whether the rail under the vehicles is irregular: then the wave keeps changing and no stationary state comes.
    pub irregular_rail: bool,
    /// With vehicles: wheel forces, losses of contact and body accelerations over the run (positions on the track,
    /// m from where the window started).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vehicles: Option<report::vehicle_output::VehicleReport>,
}

/// The co-moving window's length where neither the scenario nor the wave asks for more (m).
pub const DEFAULT_WINDOW: f64 = 120.0;

/// The window of `scenario`'s track and its settings: `window` m in the mesh's element length, free rear, clamped
/// front, absorbing zones; refused where the linear wave would not have fallen to [`WINDOW_DECAY`] of its peak
/// between the load and a zone (the window too short for the wave).
pub fn window(scenario: &Scenario, section: &CoMovingSection) -> Result<(BeamModel, CoMovingSettings)> {
    if scenario.sleepers.is_some() {
        return Err(invalid(
            "sleepers",
            "given",
            "a co-moving window shifts the track under the load an element at a time, which holds for a uniform \
             (continuous) support only: run the load across a rail on sleepers (frictrack run)",
        ));
    }
    let l = scenario.mesh.length / scenario.mesh.elements.max(1) as f64;
    let model = scenario.model()?;
    let foundation: Foundation = *model.foundation();
    // The 1 % decay lengths of the linear wave behind and ahead of the load (None where no linear wave decays:
    // undamped at or above v_cr, or without a foundation).
    let reach = (foundation.stiffness > 0.0)
        .then(|| MovingBeam::new(model.beam(), &foundation).and_then(|i| i.steady_state(scenario.load.speed, 1.0)))
        .and_then(std::result::Result::ok)
        .map(|state| {
            let (rate_ahead, rate_behind) = state.decay_rates();
            (-WINDOW_DECAY.ln() / rate_behind, -WINDOW_DECAY.ln() / rate_ahead)
        });
    let window = section.window.unwrap_or_else(|| {
        let needed = reach.map_or(0.0, |(behind, ahead)| 4.0 * behind.max(ahead));
        DEFAULT_WINDOW.max((needed / 10.0).ceil() * 10.0)
    });
    let elements = (window / l).round();
    if !(window.is_finite() && (8.0..=1e6).contains(&elements)) {
        return Err(invalid("co_moving.window", window, format!("must hold 8 to 1e6 elements of {l} m")));
    }
    let length = elements * l;
    let zones = section.zones.unwrap_or(length / 4.0);
    let load_at = section.load_at.unwrap_or(length / 2.0);
    if !(zones.is_finite() && zones >= 0.0 && 2.0 * zones < length) {
        return Err(invalid(
            "co_moving.zones",
            zones,
            format!("must be ≥ 0 m and leave room in the {length} m window"),
        ));
    }
    if !(load_at.is_finite() && zones < load_at && load_at < length - zones) {
        return Err(invalid(
            "co_moving.load_at",
            load_at,
            format!("must lie between the absorbing zones ({zones} m at each end of the {length} m window)"),
        ));
    }
    // The wave must fade before the zones: e^{−Re r·d} ≤ 1 % over the distance d from the load to each zone.
    // (Undamped at or above the critical speed no linear wave decays; friction alone may hold it: not checked.)
    if let Some((behind, ahead)) = reach
        && (load_at - zones < behind || length - zones - load_at < ahead)
    {
        return Err(invalid(
            "co_moving.window",
            window,
            format!(
                "is too short for the wave at {} m/s: it falls to 1 % only {behind:.1} m behind and {ahead:.1} m \
                 ahead of the load, so the window needs about {:.0} m with its zones of {zones} m (or more \
                 foundation damping)",
                scenario.load.speed,
                behind + ahead + 2.0 * zones
            ),
        ));
    }
    let mesh = Mesh::new(length, elements as usize)?;
    let peak_damping = AbsorbingZones { length: zones, peak_damping: foundation.critical_damping(model.beam()) };
    let damping = match zones > 0.0 {
        true => peak_damping.element_damping(&mesh, foundation.damping)?,
        false => vec![foundation.damping; mesh.elements],
    };
    let supports = Supports { left: Support::Free, right: Support::Clamped };
    let window = BeamModel::with_element_damping(*model.beam(), foundation, mesh, supports, damping)?;
    let settings = CoMovingSettings { load_at, track_length: section.track_length, middle: (zones, length - zones) };
    Ok((window, settings))
}

impl CoMovingSummary {
    /// "F = 83.4 kN", or "3 vehicles (3 wheels)" with the first wheel at s = 0.
    pub fn what_moves(&self) -> String {
        match &self.vehicles {
            Some(v) => format!(
                "{} vehicle{} ({} wheel{}, the first at s = 0)",
                v.bodies.len(),
                if v.bodies.len() == 1 { "" } else { "s" },
                v.wheels.len(),
                if v.wheels.len() == 1 { "" } else { "s" }
            ),
            None => format!("F = {:.1} kN", self.load / 1e3),
        }
    }
}

/// Run `scenario` through its co-moving window (`section`).
pub fn run(scenario: &Scenario, section: &CoMovingSection) -> Result<(CoMovingSummary, CoMovingResult)> {
    let (model, settings) = window(scenario, section)?;
    let placed = scenario.placed_on(&model)?;
    let mut run_settings =
        scenario.run_settings_reaching(scenario.load.speed, model.mesh().length + section.track_length)?;
    // A Timoshenko rail's default filtered acceleration is a finite track's; a window asked for one is refused.
    if scenario.output.acceleration_filter.is_none() {
        run_settings.record.acceleration_filter = None;
    }
    let result = run_co_moving(&model, &placed, &run_settings, &settings)?;
    let wave_peak = result.wave.iter().fold(Extreme::default(), |m, &(s, w)| match -w > m.value {
        true => Extreme::in_frame(-w, s),
        false => m,
    });
    let summary = CoMovingSummary {
        title: scenario.title.clone(),
        speed: scenario.load.speed,
        load: scenario.load.force,
        distributed_friction: scenario.friction.distributed.as_ref().map_or(0.0, |d| d.force_per_length),
        soil: model.foundation().law.name(),
        window: model.mesh().length,
        track_length: settings.track_length,
        load_at: settings.load_at,
        zones: settings.middle.0,
        element_length: model.mesh().element_length(),
        steps: result.steps,
        shifts: result.shifts,
        deflection: result.deflection,
        wave_max_downward_deflection: wave_peak,
        changes: result.changes.clone(),
        energy: result.energy.balance(),
        solver: result.solver.map_or("none", |k| k.name()),
        wall_time: result.wall_time,
        irregular_rail: scenario.vehicle.is_some() && !scenario.rail.is_empty(),
        vehicles: result.vehicles.as_ref().map(|v| {
            let contact =
                run_settings.moving.load.vehicles().map_or("", track::vehicle::consist::VehicleSettings::contact_name);
            report::vehicle_output::VehicleReport::of(v, contact, None)
        }),
    };
    Ok((summary, result))
}

/// The JSON a co-moving run writes beside its wave (`run --co-moving --out DIR` writes `DIR/co-moving.json`): the
/// run's summary, the CSV's name and its columns with units.
#[derive(Debug, Clone, Serialize)]
pub struct CoMovingFile<'a> {
    /// The run's summary.
    #[serde(flatten)]
    pub summary: &'a CoMovingSummary,
    /// The wave's CSV.
    pub csv: &'static str,
    /// Name and unit of each column.
    pub columns: Vec<report::columns::ColumnMeta>,
}

impl CoMovingSummary {
    /// The JSON beside the wave's CSV `csv`.
    pub fn file(&self, csv: &'static str) -> CoMovingFile<'_> {
        CoMovingFile { summary: self, csv, columns: report::columns::listed(WAVE_COLUMNS) }
    }
}

/// Columns of the window's last wave (`wave.csv`): s = x − vt (m) and the deflection (m, upward).
pub const WAVE_COLUMNS: [report::columns::Column; 2] = [("s", unit("s")), ("deflection", unit("deflection"))];

/// The window's last wave as CSV ([`WAVE_COLUMNS`]).
pub fn wave_csv(result: &track::co_moving::CoMovingResult) -> String {
    let mut csv = report::columns::header(&WAVE_COLUMNS) + "\n";
    for (s, w) in &result.wave {
        csv.push_str(&format!("{s},{w}\n"));
    }
    csv
}

/// The change of the wave per window length travelled below which it counts as stationary.
pub const STATIONARY_CHANGE: f64 = 1e-3;

/// How the wave in the window approached its end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Settling {
    /// Its last change is below [`STATIONARY_CHANGE`].
    Stationary {
        /// The last change.
        change: f64,
    },
    /// Still falling over the last half of the run: a longer track would settle it further.
    Falling {
        /// The last change.
        change: f64,
    },
    /// Levelled off above [`STATIONARY_CHANGE`] (the mean of the last third of the second half within a factor 2 of
    /// its first third's): stick–slip of the ballast friction keeps it there, and a longer track does not lower it.
    Levelled {
        /// The mean change over the last third of the run's second half.
        level: f64,
    },
    /// On an irregular rail the wave keeps changing: no stationary state.
    Irregular,
}

impl CoMovingSummary {
    /// How the wave settled (None before the first window length).
    pub fn settling(&self) -> Option<Settling> {
        let &(_, change) = self.changes.last()?;
        if self.irregular_rail {
            return Some(Settling::Irregular);
        }
        if change <= STATIONARY_CHANGE {
            return Some(Settling::Stationary { change });
        }
        let second_half = &self.changes[self.changes.len() / 2..];
        let third = second_half.len() / 3;
        let mean = |c: &[(f64, f64)]| c.iter().map(|c| c.1).sum::<f64>() / c.len().max(1) as f64;
        let (early, late) = (mean(&second_half[..third]), mean(&second_half[second_half.len() - third..]));
        Some(match third > 0 && late > 0.5 * early {
            true => Settling::Levelled { level: late },
            false => Settling::Falling { change },
        })
    }
}
