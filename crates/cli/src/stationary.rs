//! `frictrack stationary`: the stationary wave of the scenario's load on the infinite track, in moving coordinates
//! (docs/theory.md §14) — at one speed (its shape) or over a speed range by continuation (its peaks).

use crate::TableFormat;
use crate::files::{check_output_file, prepare_output_folder, write_atomically, write_figures};
use anyhow::Result;
use clap::Args;
use scenario::Scenario;
use stationary::Domain;
use std::path::PathBuf;
use study::ground::measured::MeasuredRecord;
use study::stationary::output::{ErrorEstimate, StationaryStudy};
use study::stationary::text::StationaryReport;

/// Options of `frictrack stationary`.
#[derive(Debug, Args)]
pub struct StationaryArgs {
    /// Scenario file (its beam, soil with its law and damping, ballast friction `[friction.distributed]`, and single
    /// load); without it, the reference case.
    scenario: Option<PathBuf>,
    /// The speeds, solved in order, each starting from the last one's contact set.
    #[command(flatten)]
    speed: crate::analytic::SpeedChoice,
    /// Domain behind:ahead of the load (m); grown where the rail leaves the soil at an end. Default 60:60.
    #[arg(long, value_name = "BEHIND:AHEAD", allow_hyphen_values = true)]
    domain: Option<String>,
    /// Element length of the moving domain (m). Default 0.25. Elements longer than the shortest length of the
    /// track's waves at the speed (1/|r|, 2.25 m for the reference track at rest) are refused; the peaks'
    /// discretisation error is estimated by solving again on elements half as long, and warned about above 1 %.
    #[arg(long, allow_negative_numbers = true)]
    element_length: Option<f64>,
    /// Foundation damping ratio ζ (of c_cr = 2√(k_f ρA)), in place of the scenario's (as `run --damping-ratio`).
    #[arg(long, allow_negative_numbers = true)]
    damping_ratio: Option<f64>,
    /// Ballast friction f_u (N/m) along the track, in place of the scenario's (as `run --distributed-friction`).
    #[arg(long, allow_negative_numbers = true)]
    distributed_friction: Option<f64>,
    /// On a `[ground]`: a measured record (CSV `x_m,displacement_mm`, or x and deflection in m; upward positive) set
    /// beside the wave at one speed, aligned by the best-fitting shift — peaks and RMS misfit, drawn in the figure.
    #[arg(long, value_name = "FILE.csv")]
    measured: Option<PathBuf>,
    /// Output format on standard output (csv: one speed's wave, or the points over several speeds).
    #[arg(long, value_enum, default_value_t = TableFormat::Text)]
    format: TableFormat,
    /// Folder for stationary.json, the CSV (wave.csv for one speed, speeds.csv for several) and the figure.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// The steady wave of the scenario's axles on its `[ground]` (docs/theory.md §19): a Fourier integral per speed, no
/// mesh — `--element-length` and the Winkler soil's and the ballast's options are refused by name.
fn on_the_ground(args: &StationaryArgs, scenario: &Scenario, speeds: &[f64]) -> Result<()> {
    let why = "on a [ground] the wave is a Fourier integral of the track on the strip, with no mesh and no Winkler \
               damping";
    for (name, given) in [("--element-length", args.element_length), ("--damping-ratio", args.damping_ratio)] {
        if let Some(value) = given {
            return Err(scenario::error::invalid(name, value, format!("leave it out: {why}")).into());
        }
    }
    scenario.check_speeds_on_the_ground("--speed", speeds)?;
    let mut window = study::ground::WaveWindow::default();
    if let Some(text) = &args.domain {
        (window.behind, window.ahead) = behind_ahead(text)?;
    }
    let record = args.measured.as_deref().map(|path| MeasuredRecord::read(path, "--measured")).transpose()?;
    if let Some(record) = &record {
        record.check_speeds(speeds.len(), "--measured")?;
        window = record.widened(window);
    }
    checked_folder(args, &["stationary.json", "wave.csv", "speeds.csv", "ground-wave.png", "ground-wave.svg"])?;
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    crate::progress::announce("stationary", &study::ground::wave::cost(scenario, speeds.len(), threads));
    let stop = Some(crate::interrupt::stop_flag());
    let bar = crate::progress::bar("stationary", Some(speeds.len() as u64), args.format != TableFormat::Text);
    let progress = |done: usize| bar.set_position(done as u64);
    let study = study::ground::GroundWaveStudy::of(scenario, speeds, window, stop, &progress);
    let mut study = crate::interrupt::explain(study)?;
    bar.finish_and_clear();
    for warning in study.warnings() {
        eprintln!("warning: {warning}");
    }
    if let Some(record) = &record {
        study.compare_with(record, "--measured")?;
    }
    crate::print_output(&study, args.format)?;
    if let Some(folder) = &args.out {
        let (name, _, csv) = study.table();
        write_atomically(&folder.join("stationary.json"), serde_json::to_string_pretty(&study.file())?.as_bytes())?;
        write_atomically(&folder.join(name), csv.as_bytes())?;
        let drawn = write_figures("--out", &[study.figure(record.as_ref())], folder)?;
        eprintln!("wrote {} (stationary.json, {name}, {})", folder.display(), drawn.join(", "));
    }
    Ok(())
}

/// `--domain BEHIND:AHEAD` (m) as two numbers.
fn behind_ahead(text: &str) -> Result<(f64, f64)> {
    let bad = || scenario::error::invalid("--domain", text, "expected BEHIND:AHEAD in metres, e.g. 60:60");
    let (behind, ahead) = text.split_once(':').ok_or_else(bad)?;
    Ok((behind.trim().parse().map_err(|_| bad())?, ahead.trim().parse().map_err(|_| bad())?))
}

fn domain(args: &StationaryArgs) -> Result<Domain> {
    let mut domain = Domain::default();
    if let Some(text) = &args.domain {
        (domain.behind, domain.ahead) = behind_ahead(text)?;
    }
    if let Some(l) = args.element_length {
        domain.element_length = l;
    }
    domain.validate().map_err(|e| scenario::StudyError::from(e).into()).map(|()| domain)
}

/// Execute `frictrack stationary`.
pub fn run(args: &StationaryArgs) -> Result<()> {
    let scenario = match &args.scenario {
        Some(path) => Scenario::from_path(path)?,
        None => Scenario::default(),
    };
    let overrides = scenario::overrides::Overrides {
        damping_ratio: args.damping_ratio,
        distributed_friction: args.distributed_friction,
        ..Default::default()
    };
    let scenario = overrides.apply(scenario)?;
    if let (Some(path), None) = (&args.measured, &scenario.ground) {
        let why = "a measured record is compared with the steady wave on a [ground] only";
        return Err(scenario::error::invalid("--measured", path.display(), why).into());
    }
    let speeds = args.speed.speeds()?;
    if let Some(&v) = speeds.iter().find(|v| !(v.is_finite() && **v >= 0.0)) {
        return Err(scenario::error::invalid("--speed", v, "must be finite and ≥ 0 (m/s)").into());
    }
    if scenario.ground.is_some() {
        return on_the_ground(args, &scenario, &speeds);
    }
    let domain = domain(args)?;
    checked_folder(args, &["stationary.json", "wave.csv", "speeds.csv"])?;
    let first = scenario.stationary_problem(speeds.first().copied().unwrap_or(0.0), domain)?;
    crate::scenario_args::print_uniform_support_note(&scenario, "the stationary wave")?;
    crate::progress::announce("stationary", &runner::cost::Estimate::stationary(&first, &speeds, true));
    let stop = Some(crate::interrupt::stop_flag());
    let bar = crate::progress::bar("stationary", Some(speeds.len() as u64), args.format != TableFormat::Text);
    let progress = |done: usize| bar.set_position(done as u64);
    let study = StationaryStudy::of_until(&scenario, &speeds, domain, ErrorEstimate::Halving, stop, &progress);
    let study = crate::interrupt::explain(study)?;
    bar.finish_and_clear();
    for warning in study.warnings() {
        eprintln!("warning: {warning}");
    }
    let report = StationaryReport { title: &scenario.title, study: &study };
    let table = report.table();
    crate::print_output(&report, args.format)?;
    if args.format == TableFormat::Text && study.points.iter().any(|p| p.status != "converged") {
        println!(
            "  where no wave was found (—), run the load across a long finite track in time (`frictrack run` with \
             absorbing zones): the stationary wave may not exist there (a tensionless soil lets the rail be thrown \
             off at speed), or needs foundation damping (undamped at or above the critical speed); with friction, a \
             co-moving window (`frictrack run --co-moving`) gives the wave by time stepping"
        );
    }
    if let Some(folder) = &args.out {
        let metadata = study.file(table.name, table.columns);
        write_atomically(&folder.join("stationary.json"), serde_json::to_string_pretty(&metadata)?.as_bytes())?;
        write_atomically(&folder.join(table.name), table.csv.as_bytes())?;
        let title = if scenario.title.is_empty() { "stationary wave on the infinite track" } else { &scenario.title };
        let drawn = write_figures("--out", &study.figures(title), folder)?;
        eprintln!("wrote {} (stationary.json, {}, {})", folder.display(), table.name, drawn.join(", "));
    }
    Ok(())
}

/// The `--out` folder, if given, created if missing and checked to take each of `files`, before any work; an
/// interruption then says nothing was written there (and removes it if it was created here and left empty).
fn checked_folder(args: &StationaryArgs, files: &[&str]) -> Result<()> {
    crate::interrupt::keep_nothing_in(args.out.as_deref(), |folder| {
        let created = prepare_output_folder("--out", folder)?;
        files.iter().try_for_each(|name| check_output_file("--out", &folder.join(name)))?;
        Ok(created)
    })
}
