//! The text report of one run (`frictrack run`'s text, Python's `str(run)`): the inputs echoed, the extremes with
//! where and when, the energy terms, the solver's statistics and fallbacks, and with vehicles their wheels, losses of
//! contact and bodies.

use crate::run_summary::RunSummary;
use std::fmt::{self, Formatter};

/// The fixed interactions by kind: friction (devices, ballast), soil on a nonlinear foundation, sleepers' unilateral
/// ballast and sliders — "N friction sections" where friction is all there is, else "N sections (a friction, b soil,
/// …)".
fn section_count(r: &RunSummary) -> String {
    let soil = r.soil.as_ref().map_or(0, |s| s.sections);
    let (unilateral, sliders) = r.sleepers.as_ref().map_or((0, 0), |s| (s.unilateral, s.sliders));
    let friction = r.stepping.sections - soil - unilateral - sliders;
    if soil + unilateral + sliders == 0 {
        return format!("{friction} friction sections");
    }
    let parts = [(soil, "soil"), (unilateral, "sleepers' ballast"), (sliders, "sleepers' friction")];
    let named = parts.iter().filter(|(n, _)| *n > 0).map(|(n, what)| format!(", {n} {what}")).collect::<String>();
    format!("{} sections ({friction} friction{named})", r.stepping.sections)
}

/// The foundation a run takes for the ground, in one line: "ground: a foundation fitted to it at … m/s over k = …"
/// (under the embankment of the two-beam track where `over_embankment`).
pub fn ground_fit_line(fit: &analytic::ground::FittedFoundation, over_embankment: bool) -> String {
    let (under, rail) = match over_embankment {
        true => ("the embankment (whole track)", "the rail's "),
        false => ("the beam", "its "),
    };
    format!(
        "ground: a foundation fitted to it at {:.2} m/s over k = {:.3}–{:.3} rad/m — k_f = {:.4e} N/m², c = {:.4e} \
         N·s/m², {:.0} kg/m of ground moving with {under}; {rail}steady wave is the exact one on the ground to {:.1} % \
         (deepest point {:+.1} %)",
        fit.speed,
        fit.wavenumbers.0,
        fit.wavenumbers.1,
        fit.stiffness,
        fit.damping,
        fit.co_vibrating_mass,
        100.0 * fit.wave_error,
        100.0 * fit.peak_error
    )
}

/// The whole report.
fn write_text(f: &mut Formatter<'_>, r: &RunSummary) -> fmt::Result {
    let title = if r.title.is_empty() { String::new() } else { format!(" — {}", r.title) };
    let load = r.load_description();
    writeln!(f, "frictrack run{title}: {load} {}", r.speed_description())?;
    if let Some(theory) = &r.rail_theory {
        writeln!(f, "  rail: {theory} beam, shear deformation and rotary inertia included")?;
    }
    if let Some(v_cr) = r.critical_speed {
        let (track, soil) = match (&r.sleepers, r.over_embankment) {
            (_, true) => ("the rail, sleepers and half the embankment as one beam on half the soil", "the soil's"),
            (Some(_), false) => ("the equivalent continuous track (sleepers' mass and support spread)", "foundation"),
            (None, false) => ("the infinite track", "foundation"),
        };
        writeln!(
            f,
            "  critical speed of {track} v_cr = {v_cr:.2} m/s; {soil} damping ζ = {}",
            scenario::number::significant(r.damping_ratio, 12)
        )?;
    }
    if let Some(fit) = &r.ground_fit {
        writeln!(f, "  {}", ground_fit_line(fit, r.over_embankment))?;
    }
    write_friction(f, r)?;
    if let Some(soil) = &r.soil {
        write_soil(f, soil)?;
    }
    if let Some(sleepers) = &r.sleepers {
        crate::sleeper_output::write_sleepers(f, sleepers)?;
    }
    write_extremes(f, r)?;
    write_numbers(f, r)?;
    if let Some(v) = &r.vehicles {
        write_vehicles(f, v)?;
    }
    if let Some(check) = &r.resolution_check {
        crate::resolution_check::write_check(f, check)?;
    }
    if let Some(accuracy) = &r.accuracy {
        crate::resolution_check::write_accuracy(f, accuracy)?;
    }
    writeln!(
        f,
        "  wall time {:.3} s (the time loop {:.3} s; set-up, statics and the static envelope the rest)",
        r.wall_time, r.time_loop
    )
}

/// The soil's lines of the text report: its law, the settlement, where the rail lifted off and the soil's energy.
fn write_soil(f: &mut Formatter<'_>, s: &crate::soil_output::SoilSummary) -> fmt::Result {
    let tension = match s.law {
        "bilinear" => format!("k_t = {} k_c", scenario::number::significant(s.tension_ratio, 6)),
        _ => "no tension".to_string(),
    };
    let weight = match s.settlement > 0.0 {
        true => format!("self-weight settlement {:.3} mm", s.settlement * 1e3),
        false => "no self-weight".to_string(),
    };
    writeln!(
        f,
        "  soil: {} (k_c = {:.4e} N/m², {tension}), {} sections, {weight}",
        s.law, s.compression_stiffness, s.sections
    )?;
    let [a, b] = s.read_region;
    match s.largest_gap.place() {
        Some((x, t)) => {
            let zones = s.lift_off_zones.len();
            let first = s.lift_off_zones.iter().filter_map(|z| z.first_time).fold(f64::INFINITY, f64::min);
            writeln!(
                f,
                "    the rail lifted off the soil in {zones} zone{} reaching where the results are read (x = {a:.1}–\
                 {b:.1} m), over {} sections (first at t = {first:.4} s); largest gap {:.3} mm at x = {x:.1} m, t = \
                 {t:.4} s",
                if zones == 1 { "" } else { "s" },
                s.lifted_sections,
                s.largest_gap.value * 1e3
            )?;
            for z in s.lift_off_zones.iter().take(MAX_ZONES_LISTED) {
                writeln!(
                    f,
                    "      {:.2}–{:.2} m, t = {:.4}–{:.4} s, largest gap {:.3} mm",
                    z.from,
                    z.to,
                    z.first_time.unwrap_or(f64::NAN),
                    z.last_time.unwrap_or(f64::NAN),
                    z.largest_gap.value * 1e3
                )?;
            }
            if zones > MAX_ZONES_LISTED {
                writeln!(f, "      … {} more zones in the JSON summary", zones - MAX_ZONES_LISTED)?;
            }
        }
        None => writeln!(f, "    where the results are read (x = {a:.1}–{b:.1} m) the rail stayed on the soil")?,
    }
    if let Some(end) = fem_beam::extreme::largest_zone(&s.end_effect_zones) {
        writeln!(
            f,
            "    outside it, end effects (the supports, absorbing zones, the load's entry and exit — not the response \
             of a long track): {} zone{}, largest gap {:.3} mm at x = {:.1} m",
            s.end_effect_zones.len(),
            if s.end_effect_zones.len() == 1 { "" } else { "s" },
            end.largest_gap.value * 1e3,
            end.largest_gap.position.unwrap_or(f64::NAN)
        )?;
    }
    writeln!(
        f,
        "    soil work on the rail {:.4e} J, energy its springs hold at the end {:.4e} J",
        s.soil_work, s.soil_energy
    )?;
    Ok(())
}

/// Lift-off zones listed in the text report (all are in the JSON).
const MAX_ZONES_LISTED: usize = 5;

/// The vehicles' lines of the text report.
fn write_vehicles(f: &mut Formatter<'_>, v: &crate::vehicle_output::VehicleReport) -> fmt::Result {
    let count = v.wheels.len();
    writeln!(
        f,
        "  vehicles: {count} wheel{}, {} contact; wheel force {:.1} … {:.1} kN, largest ΔQ/Q₀ {:.3}",
        if count == 1 { "" } else { "s" },
        v.contact,
        v.min_wheel_force / 1e3,
        v.max_wheel_force / 1e3,
        v.max_dynamic_increment
    )?;
    write_wheels(f, &v.wheels)?;
    for l in v.losses.iter().take(5) {
        let landing = l.landing_position.map_or("still flying at the end".to_string(), |x| {
            format!("landed at {x:.3} m after {:.2} ms, impact {:.1} kN", l.duration * 1e3, l.impact_force / 1e3)
        });
        writeln!(
            f,
            "    wheel {} left the rail at {:.3} m (t = {:.4} s), {landing}",
            l.wheel, l.lift_off_position, l.lift_off_time
        )?;
    }
    if v.losses.len() > 5 {
        writeln!(f, "    … {} more losses of contact in the JSON report", v.losses.len() - 5)?;
    }
    for (i, b) in v.bodies.iter().enumerate().take(4) {
        writeln!(
            f,
            "    body {} ({}): acceleration max {:.3} m/s², RMS {:.3} m/s²",
            i + 1,
            b.name,
            b.max_acceleration,
            b.rms_acceleration
        )?;
    }
    if v.bodies.len() > 4 {
        writeln!(f, "    … {} more bodies (largest RMS {:.3} m/s²)", v.bodies.len() - 4, v.max_rms_body_acceleration)?;
    }
    writeln!(
        f,
        "  contacts: work on beam and vehicles {:.4e} J, dissipated (landings, implicit law) {:.4e} J, held at the end \
         {:.4e} J",
        v.contact_work, v.contact_loss, v.spring_energy
    )?;
    if v.projection_work != 0.0 {
        writeln!(
            f,
            "  rigid contacts: position projection changed the strain energy by {:.4e} J (the velocity-level drift, \
             O(h))",
            v.projection_work
        )?;
    }
    Ok(())
}

/// The first eight wheels' lines: static and dynamic forces, the rail under each, its losses of contact.
fn write_wheels(f: &mut Formatter<'_>, wheels: &[crate::vehicle_output::WheelReport]) -> fmt::Result {
    for w in wheels.iter().take(8) {
        // A glued contact pulls instead of letting go: its negative force is tension, never a loss of contact.
        let tension = if w.min_force < 0.0 {
            format!(
                " (in tension down to {:.1} kN: the glued contact pulls the wheel onto the rail)",
                w.min_force / 1e3
            )
        } else {
            String::new()
        };
        writeln!(
            f,
            "    wheel {:>2} (vehicle {}, {:.2} m behind): Q₀ {:.1} kN, Q {:.1} … {:.1} kN{tension}, rail under it \
             {:.3} mm, {:.1} kN·m; {} {} of contact",
            w.wheel,
            w.vehicle,
            w.offset,
            w.static_force / 1e3,
            w.min_force / 1e3,
            w.max_force / 1e3,
            w.max_rail_deflection * 1e3,
            w.max_moment / 1e3,
            w.losses_of_contact,
            if w.losses_of_contact == 1 { "loss" } else { "losses" }
        )?;
    }
    if wheels.len() > 8 {
        writeln!(f, "    … {} more wheels in the JSON report and wheels.csv", wheels.len() - 8)?;
    }
    Ok(())
}

/// The friction lines: none, the devices (the first five positions), the distributed friction.
fn write_friction(f: &mut Formatter<'_>, r: &RunSummary) -> fmt::Result {
    let sliders = r.sleepers.as_ref().map_or(0, |s| s.sliders);
    if sliders > 0 {
        let force = r.sleepers.as_ref().map_or(0.0, |s| s.slider_force);
        let plural = if sliders == 1 { "" } else { "s" };
        writeln!(
            f,
            "  friction between sleepers and ballast: {sliders} sleeper{plural}, {:.1} kN in all",
            force / 1e3
        )?;
    }
    match (r.devices, r.distributed_friction > 0.0) {
        (0, false) if sliders > 0 => {}
        (0, false) => writeln!(f, "  friction: none")?,
        (n, distributed) => {
            if n > 0 {
                let shown: Vec<String> = r.device_positions.iter().take(5).map(|x| format!("{x}")).collect();
                let more = if n > 5 { ", …" } else { "" };
                writeln!(
                    f,
                    "  friction devices: {n} × {:.1} kN at {}{more} m",
                    r.device_force / 1e3,
                    shown.join(", ")
                )?;
            }
            if distributed {
                writeln!(f, "  distributed friction: {:.1} N/m", r.distributed_friction)?;
            }
        }
    }
    Ok(())
}

/// The deflection extremes: over the whole run, and while the load was in the extremes window.
fn write_extremes(f: &mut Formatter<'_>, r: &RunSummary) -> fmt::Result {
    let load = r.window.load;
    let line =
        |f: &mut Formatter<'_>, what: &str, d: f64, place: Option<(f64, f64)>, at: (Option<f64>, Option<f64>)| {
            match place {
                Some((x, t)) => {
                    let speed = at.1.map_or(String::new(), |v| format!(" at {v:.2} m/s"));
                    let load = at.0.map_or(String::new(), |x| format!(", {load} at {x:.1} m{speed}"));
                    writeln!(f, "    max {what:<8} deflection {:>9.3} mm at x = {x:.1} m, t = {t:.4} s{load}", d * 1e3)
                }
                None => writeln!(f, "    max {what:<8} deflection      none"),
            }
        };
    match r.extremes.extremes_nodes {
        Some((a, b)) => {
            writeln!(f, "  extremes over the nodes at {a:.1}–{b:.1} m ([output] extremes_nodes); whole run:")?
        }
        None => writeln!(f, "  whole run (includes the entry transient from rest and the exit near x = L):")?,
    }
    let whole = [("downward", r.extremes.deflection.max_downward), ("upward", r.extremes.deflection.max_upward)];
    for (what, e) in whole {
        line(f, what, e.value, e.place(), (None, None))?;
    }
    let (a, b) = r.extremes.extremes_window;
    let why = r.window.why;
    let nodes = if r.extremes.extremes_nodes.is_some() { "the nodes above" } else { "every node" };
    writeln!(f, "  while the {load} is at {a:.1}–{b:.1} m ({why}), over {nodes}:")?;
    let window =
        [("downward", r.extremes.window_deflection.max_downward), ("upward", r.extremes.window_deflection.max_upward)];
    match window.iter().all(|(_, e)| e.extreme.happened().is_none()) {
        true => writeln!(f, "    none: the {load} never was in that range during the run")?,
        false => {
            for (what, e) in window {
                line(f, what, e.extreme.value, e.extreme.place(), (e.load_position, e.load_speed))?;
            }
        }
    }
    Ok(())
}

/// The static envelope and amplification, the acceleration, W̄, the energy ledger and the solver's statistics.
fn write_numbers(f: &mut Formatter<'_>, r: &RunSummary) -> fmt::Result {
    writeln!(
        f,
        "  static (the {} standing at every position): max downward {:.3} mm; dynamic amplification {:.3}",
        if r.train.is_some() { "train" } else { "load" },
        r.extremes.static_max_downward_deflection * 1e3,
        r.extremes.dynamic_amplification
    )?;
    write_accelerations(f, r)?;
    writeln!(f, "  global norm W̄          {:>9.4} m²", r.extremes.global_norm)?;
    writeln!(
        f,
        "  energy (J): load work {:.4e}, dissipated {:.4e} (friction {:.4e}, viscous {:.4e}), numerical {:.4e}, balance residual {:.2e}",
        r.energy.load_work,
        r.energy.dissipated,
        r.energy.friction_dissipation,
        r.energy.viscous_dissipation,
        r.energy.numerical_dissipation,
        r.energy.residual
    )?;
    writeln!(
        f,
        "  {} steps of {:.3e} s by the {}, {} ({:.0} re-solved per step), solver {}: {:.2} iterations/step \
         (max {}), max residual {:.2e} m/s",
        r.stepping.steps,
        r.stepping.time_step,
        r.stepping.scheme,
        section_count(r),
        r.stepping.mean_sections_solved,
        r.stepping.solver,
        r.stepping.mean_iterations,
        r.stepping.max_iterations,
        r.stepping.max_residual
    )?;
    if r.stepping.work.mean_factorisations > 0.0 {
        let events = match r.stepping.work.max_events {
            0 => String::new(),
            max => format!(
                ", {:.1} events/step (max {max}), {} repairs",
                r.stepping.work.mean_events, r.stepping.work.repairs
            ),
        };
        writeln!(
            f,
            "  {:.2} banded factorisations/step (max {}), {:.2} banded solves/step{events}",
            r.stepping.work.mean_factorisations, r.stepping.work.max_factorisations, r.stepping.work.mean_solves
        )?;
    }
    if r.stepping.fallback_steps > 0 {
        let by: Vec<String> = r.stepping.fallbacks.iter().map(|b| format!("{} ({})", b.solver, b.steps)).collect();
        writeln!(
            f,
            "  fallback: {} failed on {} of {} steps (after 3 failures in a row the fallback takes steps without it, \
             trying it again at doubling intervals), solved instead by {} (docs/theory.md §5)",
            r.stepping.solver,
            r.stepping.fallback_steps,
            r.stepping.steps,
            by.join(", ")
        )?;
    }
    Ok(())
}

/// The largest acceleration at the nodes (undefined for a Timoshenko rail under a point force) and the
/// band-limited one.
fn write_accelerations(f: &mut Formatter<'_>, r: &RunSummary) -> fmt::Result {
    match r.extremes.max_acceleration.map(|a| (a, a.place())) {
        Some((a, Some((x, t)))) => writeln!(
            f,
            "  max acceleration {:.3} m/s² at x = {x:.1} m, t = {t:.4} s (at the nodes, the step's mean)",
            a.value
        )?,
        Some((_, None)) => writeln!(f, "  max acceleration none (the beam never moved)")?,
        None => writeln!(
            f,
            "  max acceleration undefined at the nodes: a Timoshenko rail's acceleration under a passing point force \
             grows without bound as the step shrinks{}",
            match (&r.extremes.band_acceleration, &r.extremes.filtered_acceleration) {
                (Some(_), _) => " (the band-limited one below is defined)",
                (None, Some(_)) => " (the filtered one below is defined)",
                (None, None) => "",
            }
        )?,
    }
    if let Some(a) = &r.extremes.filtered_acceleration {
        let place = a.extreme.place().map_or(String::new(), |(x, t)| format!(" at x = {x:.1} m, t = {t:.4} s"));
        // The step can be longer than the window the band asks for: then the band is the step's, and said so.
        let asked = match a.band < 0.9 * a.band_asked {
            true => format!("; {:.0} Hz asked, but the step is longer than its window", a.band_asked),
            false => String::new(),
        };
        writeln!(
            f,
            "  filtered acceleration {:.3} m/s²{place} (low-pass to {:.0} Hz, −3 dB: the velocity's change over {:.3e} \
             s{asked})",
            a.extreme.value, a.band, a.window
        )?;
    }
    if let Some(b) = &r.extremes.band_acceleration {
        let place = b.extreme.place().map_or(String::new(), |(x, t)| format!(" at x = {x:.1} m, t = {t:.4} s"));
        writeln!(
            f,
            "  band-limited acceleration {:.3} m/s²{place} (the {} mode{} up to {:.1} Hz: {} Hz; a deck's EN 1990 \
             check value)",
            b.extreme.value,
            b.mode_frequencies.len(),
            if b.mode_frequencies.len() == 1 { "" } else { "s" },
            b.band,
            b.mode_frequencies.iter().map(|f| format!("{f:.2}")).collect::<Vec<_>>().join(", ")
        )?;
    }
    Ok(())
}

impl crate::output::Output for RunSummary {
    fn write_text(&self, f: &mut Formatter<'_>) -> fmt::Result {
        write_text(f, self)
    }

    fn json(&self) -> serde_json::Result<String> {
        crate::output::pretty(self)
    }
}
