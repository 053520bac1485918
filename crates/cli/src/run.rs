//! `frictrack run`: one Moreau–Jean simulation of a scenario (default: the reference case of docs/theory.md §2) with flags
//! overriding it; prints the key inputs, the whole-run extremes and the extremes while the load is in the middle
//! third (or `--extremes-window`), energies, solver statistics and wall time; with vehicles, their wheel forces,
//! losses of contact and body accelerations. With `--out DIR` it also writes `summary.json`, `histories.csv`,
//! `snapshots.csv` and their figures ([`study::run_output`]), and with vehicles `wheels.csv` and its figure
//! ([`study::vehicle_output`]).

use crate::Format;
use crate::files::{check_output_file, prepare_output_folder, write_atomically};
use crate::scenario_args::ScenarioArgs;
use anyhow::Result;
use clap::Args;
use friction::InteractionKind;
use serde::Serialize;
use std::path::PathBuf;
use std::time::Instant;
use study::{Case, Scenario};
use track::vehicle::consist::VehicleSettings;
use track::{RunResult, SnapshotAt};

/// Options of `frictrack run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    #[command(flatten)]
    scenario: ScenarioArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Write summary.json, histories.csv, snapshots.csv and figures (PNG + SVG) into this folder.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Sections (m) whose histories are recorded, e.g. 50,100 (default: the scenario's `[output]` sections, or
    /// mid-span with --out).
    #[arg(long, value_delimiter = ',', value_name = "X,…", allow_negative_numbers = true)]
    record: Vec<f64>,
    /// Load positions (m) at which whole-beam snapshots are taken, e.g. 50,100,150 (default: the scenario's
    /// `[output]` snapshots, or the first axle at ¼, ½ and ¾ of its travel: L/4, L/2, 3L/4 from rest).
    #[arg(long, value_delimiter = ',', value_name = "X,…", allow_negative_numbers = true)]
    snapshot_at_load: Vec<f64>,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
}

/// Extremes in the JSON report (m, m, s; magnitudes).
#[derive(Debug, Serialize)]
struct ExtremeReport {
    deflection: f64,
    position: f64,
    time: f64,
    load_position: f64,
}

/// What the text report says of the extremes window, true for the run: whose position it is (the load, or a
/// train's first axle), why it is there (the default middle third, or given), and what lies around it.
#[derive(Debug, Default)]
struct WindowWording {
    /// "load" or "first axle".
    load: &'static str,
    /// Why the window is where it is.
    why: &'static str,
}

impl WindowWording {
    fn of(scenario: &Scenario, case: &Case) -> Self {
        let load = if case.settings.moving.train.is_some() && case.settings.moving.vehicles.is_none() {
            "first axle"
        } else {
            "load"
        };
        let span = scenario.foundation.stiffness == 0.0;
        let why = match (scenario.output.extremes_window.is_some(), span) {
            (true, _) => "the window given by [output] extremes_window or --extremes-window",
            (false, true) => "the middle third of the span",
            (false, false) => "the middle third, away from the ends: the response of a long track",
        };
        Self { load, why }
    }
}

/// An extreme that happened: a magnitude of 0 is no extreme at all (no step deflected that way), whose place and
/// time would be placeholders.
fn happened(x: &track::simulation::Extreme) -> Option<&track::simulation::Extreme> {
    (x.magnitude > 0.0).then_some(x)
}

/// The JSON report of `frictrack run`. Deflections are positive magnitudes (m), relative to the self-weight state.
#[derive(Debug, Serialize)]
pub struct RunReport {
    title: String,
    speed: f64,
    load: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    train: Option<crate::trains::TrainSummary>,
    /// With a train: what the beam carries of its axles (`[load] carries`), by which the train's forces were scaled.
    #[serde(skip_serializing_if = "Option::is_none")]
    axle_share: Option<AxleShareReport>,
    critical_speed: Option<f64>,
    damping_ratio: f64,
    devices: usize,
    device_force: f64,
    device_positions: Vec<f64>,
    distributed_friction: f64,
    max_downward_deflection: f64,
    max_downward_deflection_position: Option<f64>,
    max_downward_deflection_time: Option<f64>,
    max_upward_deflection: f64,
    max_upward_deflection_position: Option<f64>,
    max_upward_deflection_time: Option<f64>,
    max_acceleration: f64,
    max_acceleration_position: Option<f64>,
    max_acceleration_time: Option<f64>,
    static_max_downward_deflection: f64,
    dynamic_amplification: f64,
    extremes_window: (f64, f64),
    extremes_nodes: Option<(f64, f64)>,
    window_max_downward: Option<ExtremeReport>,
    window_max_upward: Option<ExtremeReport>,
    /// How the text names the extremes window (not in JSON: the numbers are).
    #[serde(skip)]
    window_wording: WindowWording,
    global_norm: f64,
    load_work: f64,
    friction_work: f64,
    friction_dissipation: f64,
    viscous_dissipation: f64,
    dissipated_energy: f64,
    numerical_dissipation: f64,
    energy_residual: f64,
    steps: usize,
    time_step: f64,
    sections: usize,
    mean_iterations: f64,
    max_iterations: usize,
    max_residual: f64,
    mean_sections_solved: f64,
    solver: String,
    fallback_steps: usize,
    fallbacks: Vec<FallbackReport>,
    wall_time: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    vehicles: Option<study::vehicle_output::VehicleReport>,
}

/// What the beam carries of a train's axles.
#[derive(Debug, Serialize)]
struct AxleShareReport {
    /// `one-rail` or `whole-axle`.
    carries: &'static str,
    /// The factor on the axle loads (½ or 1).
    factor: f64,
    /// In words.
    #[serde(skip)]
    meaning: &'static str,
}

/// Steps of the run solved by one fallback solver (the run's solver failed on them).
#[derive(Debug, Serialize)]
struct FallbackReport {
    solver: &'static str,
    steps: usize,
}

/// Execute `frictrack run`.
pub fn run(args: &RunArgs) -> Result<()> {
    let start = Instant::now();
    let mut scenario = args.scenario.load()?;
    if !args.record.is_empty() {
        scenario.output.sections = args.record.clone();
    }
    if !args.snapshot_at_load.is_empty() {
        scenario.output.snapshot_times.clear();
        scenario.output.snapshot_load_positions = args.snapshot_at_load.clone();
    }
    if args.out.is_some() && scenario.output.sections.is_empty() {
        scenario.output.sections = vec![scenario.mesh.length / 2.0];
    }
    let case = scenario.build()?;
    crate::scenario_args::print_warnings(&scenario, &case);
    if let Some(out) = &args.out {
        prepare_output_folder("--out", out)?;
        let figures = study::run_output::FIGURE_STEMS.iter().flat_map(|f| [format!("{f}.png"), format!("{f}.svg")]);
        let files = ["summary.json", "histories.csv", "snapshots.csv"].map(String::from).into_iter();
        let wheel_files = ["wheels.csv", "wheel-forces.png", "wheel-forces.svg"].map(String::from).into_iter();
        let wheel_files = wheel_files.filter(|_| case.settings.moving.vehicles.is_some());
        for name in files.chain(figures).chain(wheel_files) {
            check_output_file("--out", &out.join(name))?;
        }
    }
    // The first axle's travel: from the start position (static or steady starts begin on the beam) to L + the
    // train's length.
    let travel = (case.settings.start_position(), scenario.mesh.length + case.settings.moving.train_length());
    let requests = if args.out.is_some() { scenario.output.snapshots(travel) } else { Vec::new() };
    let steps = case.settings.step_count(scenario.mesh.length);
    if !args.quiet {
        crate::progress::announce_cost(&study::cost::RunCost::of(&case), 1, 1);
    }
    let bar = crate::progress::steps_bar(steps as u64, args.quiet || args.format == Format::Json);
    let progress = |fraction: f64| bar.set_position((fraction * steps) as u64);
    let stop = Some(crate::interrupt::stop_flag());
    let ran = study::run_output::run_with_snapshots(&case, &requests, stop, &progress);
    bar.finish_and_clear();
    let (result, snapshots) = crate::interrupt::explain(ran, None)?;
    let report = report(&scenario, &case, &result, start.elapsed().as_secs_f64())?;
    for warning in study::plausibility::result_warnings(&case, &result) {
        eprintln!("warning: {warning}");
    }
    match args.format {
        Format::Json => println!("{}", serde_json::to_string_pretty(&report)?),
        Format::Text => print_text(&report),
    }
    if let Some(out) = &args.out {
        write_outputs(out, &scenario, &report, &result, &snapshots)?;
        if args.format == Format::Text {
            let wheels = if result.vehicles.is_some() { ", wheels.csv" } else { "" };
            println!("  wrote {}/summary.json, histories.csv, snapshots.csv{wheels} and figures", out.display());
        }
    }
    Ok(())
}

fn write_outputs(
    out: &std::path::Path,
    scenario: &Scenario,
    report: &RunReport,
    result: &RunResult,
    snapshots: &[track::Snapshot],
) -> Result<()> {
    use study::run_output::{HISTORY_COLUMNS, RunCurves, SNAPSHOT_COLUMNS, histories_csv, run_plots, snapshots_csv};
    let columns = |list: &[(&str, &str)]| {
        list.iter().map(|(name, unit)| serde_json::json!({ "name": name, "unit": unit })).collect::<Vec<_>>()
    };
    let requested: Vec<String> = snapshots
        .iter()
        .map(|s| match s.requested {
            SnapshotAt::Time(t) => format!("time {t} s"),
            SnapshotAt::LoadPosition(x) => format!("load at {x} m"),
        })
        .collect();
    let mut files = serde_json::json!({
        "histories.csv": { "columns": columns(&HISTORY_COLUMNS), "sections": scenario.output.sections },
        "snapshots.csv": { "columns": columns(&SNAPSHOT_COLUMNS), "requested": requested },
    });
    if result.vehicles.is_some() {
        files["wheels.csv"] = serde_json::json!({ "columns": columns(&study::vehicle_output::WHEEL_COLUMNS) });
    }
    let title = if scenario.title.is_empty() { format!("v = {} m/s", report.speed) } else { scenario.title.clone() };
    let load = if report.train.is_some() { "first axle" } else { "load" };
    let subtitle = figure_subtitle(report);
    let summary = serde_json::json!({
        "report": report,
        "files": files,
        // What the figures are titled, so that `frictrack plot DIR` draws them again as they were.
        "figures": { "title": title, "subtitle": subtitle, "positions_of": load },
        "conventions": "deflection positive upward; moment sagging-positive; extremes are magnitudes",
        "frictrack_version": env!("CARGO_PKG_VERSION"),
        "scenario": scenario,
    });
    write_atomically(&out.join("summary.json"), serde_json::to_string_pretty(&summary)?.as_bytes())?;
    write_atomically(&out.join("histories.csv"), histories_csv(result).as_bytes())?;
    write_atomically(&out.join("snapshots.csv"), snapshots_csv(snapshots).as_bytes())?;
    for mut spec in run_plots(&RunCurves::of(result, snapshots), &title, load) {
        spec.subtitle.clone_from(&subtitle);
        study::plot::render(&spec, out)?;
    }
    if let Some(vehicles) = &result.vehicles {
        write_atomically(&out.join("wheels.csv"), study::vehicle_output::wheels_csv(vehicles).as_bytes())?;
        let range = report.extremes_nodes.unwrap_or((0.0, scenario.mesh.length));
        let mut spec = study::vehicle_output::wheel_plot(vehicles, &title, range);
        if spec.subtitle.is_empty() {
            spec.subtitle = subtitle;
        }
        study::plot::render(&spec, out)?;
    }
    Ok(())
}

fn report(scenario: &Scenario, case: &Case, result: &RunResult, wall_time: f64) -> Result<RunReport> {
    let e = &result.energy;
    let s = &result.statistics;
    let settings = &case.settings;
    let device_positions: Vec<f64> = (0..case.interactions.len())
        .filter(|&j| case.interactions.kinds()[j] == InteractionKind::Device)
        .map(|j| case.interactions.positions()[j])
        .collect();
    let window = result.window.unwrap_or_default();
    let x0 = settings.start_position();
    let extreme = |x: &track::simulation::Extreme| {
        happened(x).map(|x| ExtremeReport {
            deflection: x.magnitude,
            position: x.position,
            time: x.time,
            load_position: x0 + settings.moving.speed * x.time,
        })
    };
    let critical = study::speeds::SpeedScale::of(scenario)?.critical_speed;
    let statics = track::statics::static_envelope(
        &case.model,
        &settings.moving.train(),
        settings.integration.load_advance,
        settings.record.extremes_nodes,
    )?;
    let foundation = case.model.foundation();
    Ok(RunReport {
        title: scenario.title.clone(),
        speed: settings.moving.speed,
        load: settings.moving.force,
        train: settings.moving.train.as_ref().map(crate::trains::TrainSummary::of),
        axle_share: settings.moving.train.as_ref().filter(|t| t.name != "single").map(|_| {
            let share = scenario.axle_share();
            AxleShareReport { carries: share.name(), factor: share.factor(), meaning: share.describe() }
        }),
        critical_speed: critical,
        damping_ratio: foundation.damping_ratio(case.model.beam()),
        devices: device_positions.len(),
        device_force: scenario.friction.devices.as_ref().and_then(|d| d.force).unwrap_or(0.0),
        device_positions,
        distributed_friction: scenario.friction.distributed.as_ref().map_or(0.0, |d| d.force_per_length),
        max_downward_deflection: result.max_downward.magnitude,
        max_downward_deflection_position: happened(&result.max_downward).map(|x| x.position),
        max_downward_deflection_time: happened(&result.max_downward).map(|x| x.time),
        max_upward_deflection: result.max_upward.magnitude,
        max_upward_deflection_position: happened(&result.max_upward).map(|x| x.position),
        max_upward_deflection_time: happened(&result.max_upward).map(|x| x.time),
        max_acceleration: result.max_acceleration.magnitude,
        max_acceleration_position: happened(&result.max_acceleration).map(|x| x.position),
        max_acceleration_time: happened(&result.max_acceleration).map(|x| x.time),
        static_max_downward_deflection: statics.max_downward,
        dynamic_amplification: if statics.max_downward > 0.0 {
            result.max_downward.magnitude / statics.max_downward
        } else {
            0.0
        },
        extremes_window: window.load_range,
        extremes_nodes: settings.record.extremes_nodes,
        window_max_downward: extreme(&window.max_downward),
        window_max_upward: extreme(&window.max_upward),
        window_wording: WindowWording::of(scenario, case),
        global_norm: result.global_norm,
        load_work: e.load_work,
        friction_work: e.friction_work,
        // Positive, as `viscous_dissipation` and `dissipated_energy`: the energy friction removed (0 − W, not −W:
        // no "-0" without friction).
        friction_dissipation: 0.0 - e.friction_work,
        viscous_dissipation: e.viscous_dissipation,
        dissipated_energy: e.dissipated(),
        numerical_dissipation: e.numerical_dissipation,
        energy_residual: e.residual(),
        steps: s.steps,
        time_step: result.step,
        sections: s.sections,
        mean_iterations: s.mean_iterations,
        max_iterations: s.max_iterations,
        max_residual: s.max_residual,
        mean_sections_solved: s.mean_sections_solved,
        solver: s.solver_name().to_string(),
        fallback_steps: s.fallback_steps(),
        fallbacks: s.fallbacks.iter().map(|f| FallbackReport { solver: f.solver.name(), steps: f.steps }).collect(),
        wall_time,
        vehicles: result.vehicles.as_ref().map(|v| {
            let contact = settings.moving.vehicles.as_ref().map_or("", VehicleSettings::contact_name);
            study::vehicle_output::VehicleReport::of(v, contact)
        }),
    })
}

/// What ran, in words: the load, train or vehicles.
fn load_description(r: &RunReport) -> String {
    match (&r.vehicles, &r.train) {
        (Some(v), _) => {
            let total: f64 = v.wheels.iter().map(|w| w.static_force).sum();
            let plural = if v.bodies.len() == 1 { "" } else { "s" };
            format!("{} vehicle{plural} ({}) weighing {:.1} kN", v.bodies.len(), v.bodies[0].name, total / 1e3)
        }
        (None, Some(t)) => format!(
            "train {} ({} axles, {} patches, {:.3} m, {:.1} kN on the beam{})",
            t.name,
            t.axles,
            t.patches,
            t.length,
            t.total_force / 1e3,
            r.axle_share.as_ref().map_or(String::new(), |s| format!(": {}", s.meaning))
        ),
        (None, None) => format!("load {:.1} kN", r.load / 1e3),
    }
}

/// The friction that ran, in words.
fn friction_description(r: &RunReport) -> String {
    let devices = (r.devices > 0).then(|| format!("{} devices × {:.1} kN", r.devices, r.device_force / 1e3));
    let distributed = (r.distributed_friction > 0.0).then(|| format!("{:.1} N/m distributed", r.distributed_friction));
    match (devices, distributed) {
        (None, None) => "none".into(),
        (a, b) => [a, b].into_iter().flatten().collect::<Vec<_>>().join(" and "),
    }
}

/// The subtitle of the run's figures: what ran, at which speed, with which friction.
fn figure_subtitle(r: &RunReport) -> String {
    format!(
        "{} at {:.2} m/s ({:.0} km/h); friction: {}",
        load_description(r),
        r.speed,
        r.speed * 3.6,
        friction_description(r)
    )
}

fn print_text(r: &RunReport) {
    let title = if r.title.is_empty() { String::new() } else { format!(" — {}", r.title) };
    let load = load_description(r);
    println!("frictrack run{title}: {load} at {:.2} m/s ({:.0} km/h)", r.speed, r.speed * 3.6);
    if let Some(v_cr) = r.critical_speed {
        println!(
            "  critical speed of the infinite track v_cr = {v_cr:.2} m/s; foundation damping ζ = {}",
            study::number::significant(r.damping_ratio, 12)
        );
    }
    match (r.devices, r.distributed_friction > 0.0) {
        (0, false) => println!("  friction: none"),
        (n, distributed) => {
            if n > 0 {
                let shown: Vec<String> = r.device_positions.iter().take(5).map(|x| format!("{x}")).collect();
                let more = if n > 5 { ", …" } else { "" };
                println!("  friction devices: {n} × {:.1} kN at {}{more} m", r.device_force / 1e3, shown.join(", "));
            }
            if distributed {
                println!("  distributed friction: {:.1} N/m", r.distributed_friction);
            }
        }
    }
    let load = r.window_wording.load;
    let line = |what: &str, d: f64, place: Option<(f64, f64)>, x_load: Option<f64>| match place {
        Some((x, t)) => {
            let load = x_load.map_or(String::new(), |x| format!(", {load} at {x:.1} m"));
            println!("    max {what:<8} deflection {:>9.3} mm at x = {x:.1} m, t = {t:.4} s{load}", d * 1e3);
        }
        None => println!("    max {what:<8} deflection      none"),
    };
    match r.extremes_nodes {
        Some((a, b)) => println!("  extremes over the nodes at {a:.1}–{b:.1} m ([output] extremes_nodes); whole run:"),
        None => println!("  whole run (includes the entry transient from rest and the exit near x = L):"),
    }
    let place = |x: Option<f64>, t: Option<f64>| x.zip(t);
    line(
        "downward",
        r.max_downward_deflection,
        place(r.max_downward_deflection_position, r.max_downward_deflection_time),
        None,
    );
    line(
        "upward",
        r.max_upward_deflection,
        place(r.max_upward_deflection_position, r.max_upward_deflection_time),
        None,
    );
    let (a, b) = r.extremes_window;
    let why = r.window_wording.why;
    let nodes = if r.extremes_nodes.is_some() { "the nodes above" } else { "every node" };
    println!("  while the {load} is at {a:.1}–{b:.1} m ({why}), over {nodes}:");
    match (&r.window_max_downward, &r.window_max_upward) {
        (None, None) => println!("    none: the {load} never was in that range during the run"),
        (down, up) => {
            for (what, e) in [("downward", down), ("upward", up)] {
                let d = e.as_ref().map_or(0.0, |e| e.deflection);
                line(what, d, e.as_ref().map(|e| (e.position, e.time)), e.as_ref().map(|e| e.load_position));
            }
        }
    }
    println!(
        "  static (the {} standing at every position): max downward {:.3} mm; dynamic amplification {:.3}",
        if r.train.is_some() { "train" } else { "load" },
        r.static_max_downward_deflection * 1e3,
        r.dynamic_amplification
    );
    match place(r.max_acceleration_position, r.max_acceleration_time) {
        Some((x, t)) => println!(
            "  max acceleration {:.3} m/s² at x = {x:.1} m, t = {t:.4} s (the step's mean; a bridge deck's check value)",
            r.max_acceleration
        ),
        None => println!("  max acceleration none (the beam never moved)"),
    }
    println!("  global norm W̄          {:>9.4} m²", r.global_norm);
    println!(
        "  energy (J): load work {:.4e}, dissipated {:.4e} (friction {:.4e}, viscous {:.4e}), numerical {:.4e}, balance residual {:.2e}",
        r.load_work,
        r.dissipated_energy,
        r.friction_dissipation,
        r.viscous_dissipation,
        r.numerical_dissipation,
        r.energy_residual
    );
    println!(
        "  {} steps of {:.3e} s, {} friction sections ({:.0} re-solved per step), solver {}: {:.2} iterations/step \
         (max {}), max residual {:.2e} m/s",
        r.steps,
        r.time_step,
        r.sections,
        r.mean_sections_solved,
        r.solver,
        r.mean_iterations,
        r.max_iterations,
        r.max_residual
    );
    if r.fallback_steps > 0 {
        let by: Vec<String> = r.fallbacks.iter().map(|f| format!("{} ({})", f.solver, f.steps)).collect();
        println!(
            "  fallback: {} failed on {} of {} steps, solved instead by {} (docs/theory.md §5)",
            r.solver,
            r.fallback_steps,
            r.steps,
            by.join(", ")
        );
    }
    if let Some(v) = &r.vehicles {
        print_vehicles(v);
    }
    println!("  wall time {:.3} s", r.wall_time);
}

/// The vehicles' lines of the text report.
fn print_vehicles(v: &study::vehicle_output::VehicleReport) {
    let count = v.wheels.len();
    println!(
        "  vehicles: {count} wheel{}, {} contact; wheel force {:.1} … {:.1} kN, largest ΔQ/Q₀ {:.3}",
        if count == 1 { "" } else { "s" },
        v.contact,
        v.min_wheel_force / 1e3,
        v.max_wheel_force / 1e3,
        v.max_dynamic_increment
    );
    for w in v.wheels.iter().take(8) {
        // A glued contact pulls instead of letting go: its negative force is tension, never a loss of contact.
        let tension = if w.min_force < 0.0 {
            format!(
                " (in tension down to {:.1} kN: the glued contact pulls the wheel onto the rail)",
                w.min_force / 1e3
            )
        } else {
            String::new()
        };
        println!(
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
        );
    }
    if v.wheels.len() > 8 {
        println!("    … {} more wheels in the JSON report and wheels.csv", v.wheels.len() - 8);
    }
    for l in v.losses.iter().take(5) {
        let landing = l.landing_position.map_or("still flying at the end".to_string(), |x| {
            format!("landed at {x:.3} m after {:.2} ms, impact {:.1} kN", l.duration * 1e3, l.impact_force / 1e3)
        });
        println!(
            "    wheel {} left the rail at {:.3} m (t = {:.4} s), {landing}",
            l.wheel, l.lift_off_position, l.lift_off_time
        );
    }
    if v.losses.len() > 5 {
        println!("    … {} more losses of contact in the JSON report", v.losses.len() - 5);
    }
    for (i, b) in v.bodies.iter().enumerate().take(4) {
        println!(
            "    body {} ({}): acceleration max {:.3} m/s², RMS {:.3} m/s²",
            i + 1,
            b.name,
            b.max_acceleration,
            b.rms_acceleration
        );
    }
    if v.bodies.len() > 4 {
        println!("    … {} more bodies (largest RMS {:.3} m/s²)", v.bodies.len() - 4, v.max_rms_body_acceleration);
    }
    println!(
        "  contacts: work on beam and vehicles {:.4e} J, dissipated (landings, implicit law) {:.4e} J, held at the end \
         {:.4e} J",
        v.contact_work, v.contact_loss, v.spring_energy
    );
    if v.projection_work != 0.0 {
        println!(
            "  rigid contacts: position projection changed the strain energy by {:.4e} J (the velocity-level drift, \
             O(h))",
            v.projection_work
        );
    }
}
