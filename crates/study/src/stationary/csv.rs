//! The stationary solver's tables as CSV, in the units convention of [`report::columns`]: a wave's shape along the
//! moving coordinate, and the points of a speed sweep (one row per speed, the JSON keys of
//! [`StationaryPoint`] as column names).

use crate::stationary::output::StationaryPoint;
use fem_beam::Extreme;
use report::columns::{Column, header};
use scenario::quantities::unit;
use stationary::StationaryWave;

/// Columns of a wave's shape: s = x − vt, deflection (upward), slope, sagging moment, the soil's reaction and the
/// ballast's friction force (the resistance r: the rail feels −r).
pub const WAVE_COLUMNS: [Column; 6] = [
    ("s", unit("s")),
    ("deflection", unit("deflection")),
    ("slope", unit("slope")),
    ("moment", unit("moment")),
    ("soil_reaction", unit("soil_reaction")),
    ("friction_force", unit("force_per_length")),
];

/// Columns of a sweep's points: the [`StationaryPoint`] fields of the same names; `lift_off_zones` and
/// `slip_zones` counted, `largest_gap` the largest of the lift-off zones'.
pub const POINT_COLUMNS: [Column; 16] = [
    ("speed", unit("speed")),
    ("status", unit("status")),
    ("iterations", unit("iterations")),
    ("residual", unit("residual")),
    ("max_downward_deflection", unit("max_downward_deflection")),
    ("max_downward_deflection_position", unit("max_downward_deflection_position")),
    ("max_upward_deflection", unit("max_upward_deflection")),
    ("max_upward_deflection_position", unit("max_upward_deflection_position")),
    ("max_moment", unit("max_moment")),
    ("max_hogging_moment", unit("max_hogging_moment")),
    ("deflection_behind", unit("deflection_behind")),
    ("lift_off_zones", unit("lift_off_zones")),
    ("largest_gap", unit("largest_gap")),
    ("slip_zones", unit("slip_zones")),
    ("friction_power", unit("friction_power")),
    ("power_imbalance", unit("power_imbalance")),
];

/// The wave's shape as CSV ([`WAVE_COLUMNS`]).
pub fn wave_csv(wave: &StationaryWave) -> String {
    let mut out = header(&WAVE_COLUMNS) + "\n";
    for i in 0..wave.s.len() {
        out.push_str(&format!(
            "{},{},{},{},{},{}\n",
            wave.s[i], wave.deflection[i], wave.slope[i], wave.moment[i], wave.soil_reaction[i], wave.friction_force[i]
        ));
    }
    out
}

/// The points of a stationary sweep as CSV ([`POINT_COLUMNS`]), a missing value (no wave found) empty.
pub fn points_csv(points: &[StationaryPoint]) -> String {
    let cell = |x: Option<f64>| x.map_or(String::new(), |x| x.to_string());
    let mut out = header(&POINT_COLUMNS) + "\n";
    for p in points {
        let gap = fem_beam::extreme::largest_zone(&p.lift_off_zones).map(|z| z.largest_gap.value);
        let value = |e: Option<Extreme>| e.map(|e| e.value);
        let position = |e: Option<Extreme>| e.and_then(|e| e.position);
        let cells = [
            p.speed.to_string(),
            p.status.to_string(),
            p.iterations.to_string(),
            p.residual.to_string(),
            cell(value(p.deflection.max_downward)),
            cell(position(p.deflection.max_downward)),
            cell(value(p.deflection.max_upward)),
            cell(position(p.deflection.max_upward)),
            cell(value(p.max_moment)),
            cell(value(p.max_hogging_moment)),
            cell(p.deflection_behind),
            p.lift_off_zones.len().to_string(),
            cell(gap),
            p.slip_zones.len().to_string(),
            cell(p.power.map(|b| b.friction)),
            cell(p.power.map(|b| b.imbalance)),
        ];
        out.push_str(&cells.join(","));
        out.push('\n');
    }
    out
}
