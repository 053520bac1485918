//! Every quantity frictrack writes into a table, with its SI unit — the one list the columns of every CSV, the JSON
//! written beside them and Python's `units` take their units from. A column's unit is [`unit()`] of its quantity, at
//! compile time: a column whose quantity is not listed here does not build. Names are snake_case quantities without
//! units; "1" marks counts and ratios, "text" words.

/// (name, SI unit) of every quantity, each name once, by topic.
pub const QUANTITIES: &[(&str, &str)] = &[
    // Where and when.
    ("speed", "m/s"),
    ("time", "s"),
    ("x", "m"),
    ("s", "m"),
    ("section", "m"),
    ("position", "m"),
    ("load_position", "m"),
    ("frequency", "Hz"),
    // The rail's response.
    ("deflection", "m"),
    ("deflection_behind", "m"),
    ("deflection_under_load", "m"),
    ("rail_deflection", "m"),
    ("slope", "rad"),
    ("velocity", "m/s"),
    ("acceleration", "m/s²"),
    ("moment", "N·m"),
    ("max_moment", "N·m"),
    ("max_hogging_moment", "N·m"),
    ("max_downward_deflection", "m"),
    ("max_downward_deflection_position", "m"),
    ("max_downward_deflection_time", "s"),
    ("max_upward_deflection", "m"),
    ("max_upward_deflection_position", "m"),
    ("static_max_downward_deflection", "m"),
    ("window_max_downward_deflection", "m"),
    ("window_max_downward_deflection_position", "m"),
    ("window_max_downward_deflection_time", "s"),
    ("window_max_upward_deflection", "m"),
    ("window_max_upward_deflection_position", "m"),
    ("window_max_upward_deflection_time", "s"),
    ("max_acceleration", "m/s²"),
    ("band_acceleration", "m/s²"),
    ("deck_acceleration", "m/s²"),
    ("global_norm", "m²"),
    ("dynamic_amplification", "1"),
    ("phi_w", "1"),
    ("phi_m", "1"),
    ("wave_change", "1"),
    // Forces and energy.
    ("force", "N"),
    ("force_per_length", "N/m"),
    ("friction_force", "N"),
    ("soil_reaction", "N/m"),
    ("device_force", "N"),
    ("cost", "N"),
    ("impulse", "N·s"),
    ("load_work", "J"),
    ("dissipated_energy", "J"),
    ("energy_residual", "J"),
    ("friction_power", "W"),
    ("two_beam_max_downward_deflection", "m"),
    ("two_beam_max_upward_deflection", "m"),
    ("two_beam_friction_power", "W"),
    ("power_imbalance", "1"),
    ("mobilised_friction", "1"),
    // The track's receptance.
    ("real", "m/N"),
    ("imaginary", "m/N"),
    ("magnitude", "m/N"),
    ("phase", "deg"),
    ("mobility", "m/(s·N)"),
    // The ground under the track.
    ("phase_velocity", "m/s"),
    ("phase_velocities", "m/s"),
    ("minimum_phase_velocity", "m/s"),
    ("minimum_phase_velocity_frequency", "Hz"),
    ("wavenumber", "rad/m"),
    ("stiffness_real", "N/m²"),
    ("stiffness_imaginary", "N/m²"),
    ("equivalent_stiffness", "N/m²"),
    ("static_strip_stiffness", "N/m²"),
    ("static_deflection", "m"),
    ("critical_speed", "m/s"),
    ("critical_deflection", "m"),
    ("winkler_critical_speed", "m/s"),
    ("dispersion_crossing_speed", "m/s"),
    ("dispersion_crossing_frequency", "Hz"),
    ("free_beam_crossing_speed", "m/s"),
    ("free_beam_crossing_frequency", "Hz"),
    ("width", "m"),
    ("bending_stiffness", "N·m²"),
    ("mass_per_length", "kg/m"),
    ("spectrum_samples", "1"),
    ("offset", "m"),
    ("direction", "1"),
    ("shift", "m"),
    ("rms_misfit", "m"),
    ("rms_measured", "m"),
    ("measured_max_downward", "m"),
    ("measured_max_upward", "m"),
    ("computed_max_downward", "m"),
    ("computed_max_upward", "m"),
    ("deflection_at_185_km_per_h", "m"),
    // The rail's profile.
    ("irregularity", "m"),
    ("psd", "m²/(rad/m)"),
    // Vehicles.
    ("vehicle", "1"),
    ("wheel", "1"),
    ("min_wheel_force", "N"),
    ("max_wheel_force", "N"),
    ("max_dynamic_increment", "1"),
    ("losses_of_contact", "1"),
    ("max_body_acceleration", "m/s²"),
    ("rms_body_acceleration", "m/s²"),
    // Sleepers.
    ("max_pad_force", "N"),
    ("max_ballast_force", "N"),
    ("exception_ballast_force", "N"),
    ("neighbour_ballast_force", "N"),
    ("exception_lowest", "m"),
    ("voided", "1"),
    ("sleepers", "1"),
    ("gap", "m"),
    ("largest_gap", "m"),
    ("lifted_length", "m"),
    ("preload", "m"),
    ("ballast_force", "N/m"),
    ("sleeper", "1"),
    ("sleeper_deflection", "m"),
    ("sleeper_acceleration", "m/s²"),
    ("pad_force", "N"),
    ("sleeper_ballast_force", "N"),
    ("ballast_body_acceleration", "m/s²"),
    // The solvers and the study's set-ups.
    ("status", "text"),
    ("iterations", "1"),
    ("mean_iterations", "1"),
    ("residual", "1"),
    ("lift_off_zones", "1"),
    ("slip_zones", "1"),
    ("newton_iterations", "1"),
    ("krylov_iterations", "1"),
    ("slipping_length", "m"),
    ("rear_force_ratio", "1"),
    ("devices", "1"),
    ("tau", "1"),
    ("model", "text"),
    ("train", "text"),
    ("friction", "text"),
    ("rail", "text"),
    ("foundation", "text"),
    ("support", "text"),
    ("place", "text"),
];

/// Whether two names are the same, in a constant.
const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// The SI unit of the quantity `name`; a name not in [`QUANTITIES`] stops the build (in a constant) or panics.
pub const fn unit(name: &str) -> &'static str {
    match unit_of(name) {
        Some(unit) => unit,
        None => panic!("a column whose quantity is not in scenario::quantities::QUANTITIES"),
    }
}

/// The SI unit of the quantity `name`, `None` for a name not listed.
pub const fn unit_of(name: &str) -> Option<&'static str> {
    let mut i = 0;
    while i < QUANTITIES.len() {
        if same(QUANTITIES[i].0, name) {
            return Some(QUANTITIES[i].1);
        }
        i += 1;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_quantity_is_listed_once_with_a_unit() {
        for (i, (name, unit)) in QUANTITIES.iter().enumerate() {
            assert!(!unit.is_empty(), "{name}");
            assert!(QUANTITIES[..i].iter().all(|(other, _)| other != name), "{name} listed twice");
        }
        assert_eq!((unit("speed"), unit_of("phase"), unit_of("fast")), ("m/s", Some("deg"), None));
    }
}
