//! The unit of every column a study's CSV may hold.

/// The unit of a column of a study's CSV (SI; "1" for counts and ratios); None for a column not listed here — a new
/// column must be given its unit (a test runs every study and fails on one without).
fn unit_of(column: &str) -> Option<&'static str> {
    Some(match column {
        "speed" => "m/s",
        "device_force" | "cost" => "N",
        "force_per_length" => "N/m",
        "dissipated_energy" => "J",
        "global_norm" => "m²",
        "time" => "s",
        "impulse" => "N·s",
        "model" | "train" | "friction" | "rail" | "foundation" | "status" | "support" | "place" => "text",
        "frequency" => "Hz",
        "magnitude" | "real" | "imaginary" => "m/N",
        "phase" => "degrees",
        "voided" | "sleepers" => "1",
        "gap" | "exception_lowest" => "m",
        "max_pad_force" | "max_ballast_force" | "exception_ballast_force" | "neighbour_ballast_force" => "N",
        "max_acceleration" | "deck_acceleration" | "max_body_acceleration" | "rms_body_acceleration" => "m/s²",
        "min_wheel_force" | "max_wheel_force" => "N",
        "devices"
        | "tau"
        | "phi_w"
        | "phi_m"
        | "dynamic_amplification"
        | "max_dynamic_increment"
        | "losses_of_contact" => "1",
        "deflection"
        | "deflection_behind"
        | "load_position"
        | "max_downward_deflection"
        | "max_upward_deflection"
        | "static_max_downward_deflection"
        | "window_max_downward_deflection"
        | "window_max_upward_deflection" => "m",
        _ => return None,
    })
}

/// The unit the study's files give a column: its unit, or "unknown" (never a guess).
pub(super) fn column_unit(column: &str) -> &'static str {
    unit_of(column).unwrap_or("unknown")
}
