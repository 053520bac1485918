//! The text report of a run through a co-moving window (`frictrack run --co-moving`'s text): the window, the wave
//! in the frame at the end, how it settled, the energy carried out behind, the vehicles and the solver.

use crate::co_moving::output::{CoMovingSummary, Settling};
use report::output::{Output, pretty};
use std::fmt::{self, Formatter};

impl Output for CoMovingSummary {
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let s = self;
        let title = if s.title.is_empty() { String::new() } else { format!(" — {}", s.title) };
        writeln!(
            f,
            "frictrack run{title}, co-moving window: {} at {:.2} m/s over {:.0} m of track",
            s.what_moves(),
            s.speed,
            s.track_length
        )?;
        writeln!(
            f,
            "  window {:.1} m of {:.3} m elements, the load {:.1} m from its rear, absorbing zones {:.1} m at both ends",
            s.window, s.element_length, s.load_at, s.zones
        )?;
        let friction = match s.distributed_friction > 0.0 {
            true => format!("ballast friction f_u = {:.1} kN/m", s.distributed_friction / 1e3),
            false => "no friction".to_string(),
        };
        writeln!(f, "  {} soil, {friction}", s.soil)?;
        writeln!(
            f,
            "  the wave in the frame at the end: max downward {:.3} mm at s = {:.2} m (s = x − x_load)",
            s.wave_max_downward_deflection.value * 1e3,
            s.wave_max_downward_deflection.position.unwrap_or(f64::NAN) + 0.0
        )?;
        writeln!(
            f,
            "  over the run between the zones: max downward {:.3} mm, max upward {:.3} mm",
            s.deflection.max_downward.value * 1e3,
            s.deflection.max_upward.value * 1e3
        )?;
        if let (Some(&(distance, change)), Some(settling)) = (s.changes.last(), s.settling()) {
            let first = s.changes.first().map_or(change, |c| c.1);
            writeln!(
                f,
                "  change of the wave per window length travelled: {first:.1e} after the first, {change:.1e} at {distance:.0} m{}",
                match settling {
                    Settling::Irregular =>
                        " (an irregular rail keeps the wave changing: no stationary state)".to_string(),
                    Settling::Stationary { .. } => " (stationary)".to_string(),
                    Settling::Falling { .. } => " (still settling: a longer track_length)".to_string(),
                    Settling::Levelled { level } => format!(
                        " (levelled off near {level:.1e}: the ballast's stick–slip keeps the wave changing this much, and a \
                         longer track_length will not lower it)"
                    ),
                }
            )?;
        }
        writeln!(
            f,
            "  energy (J): load work {:.4e}, friction {:.4e}, viscous {:.4e}, carried out behind {:.4e}, balance residual {:.2e}",
            s.energy.load_work,
            s.energy.friction_work,
            s.energy.viscous_dissipation,
            s.energy.transported,
            s.energy.residual
        )?;
        if let Some(v) = &s.vehicles {
            writeln!(
                f,
                "  vehicles ({} contact): wheel force {:.1}–{:.1} kN, largest ΔQ/Q₀ {:.3}, {} losses of contact, body \
                 acceleration up to {:.3} m/s² (RMS {:.3})",
                v.contact,
                v.min_wheel_force / 1e3,
                v.max_wheel_force / 1e3,
                v.max_dynamic_increment,
                v.losses_of_contact,
                v.max_body_acceleration,
                v.max_rms_body_acceleration
            )?;
        }
        writeln!(
            f,
            "  {} steps, {} shifts of the window, solver {}; wall time {:.3} s",
            s.steps, s.shifts, s.solver, s.wall_time
        )
    }

    fn json(&self) -> serde_json::Result<String> {
        pretty(self)
    }
}
