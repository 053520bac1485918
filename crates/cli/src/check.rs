//! `frictrack check <scenario>…`: parse and validate scenario files without running them, echoing what each
//! describes (title, beam, foundation and damping, friction set-up, load, sweep) and its warnings.

use anyhow::Result;
use clap::Args;
use scenario::Scenario;
use std::path::PathBuf;

/// Options of `frictrack check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// Scenario files (TOML), e.g. examples/*.toml.
    #[arg(required = true)]
    scenarios: Vec<PathBuf>,
}

/// Execute `frictrack check`: one file's error is the command's; with several, every file is checked, each error
/// printed, and the count returned as an invalid-input error (exit code 2).
pub fn run(args: &CheckArgs) -> Result<()> {
    if let [path] = args.scenarios.as_slice() {
        return check(path);
    }
    let mut invalid = 0;
    for path in &args.scenarios {
        if let Err(e) = check(path) {
            eprintln!("error: {e:#}");
            invalid += 1;
        }
    }
    if invalid > 0 {
        let count = format!("{invalid} of {}", args.scenarios.len());
        return Err(scenario::error::invalid("scenario files", count, "see the errors above").into());
    }
    Ok(())
}

fn check(path: &std::path::Path) -> Result<()> {
    let mut scenario = Scenario::from_path(path)?;
    // A single run's accuracy is checked as `run` takes it; the rest as any run builds it.
    scenario.take_accuracy()?;
    if scenario.ground.is_some() {
        return check_on_the_ground(path, &scenario);
    }
    let case = scenario.build()?;
    if let Some(section) = &scenario.co_moving {
        // The window is checked as `run` would build it (too short for the wave, the load between its zones).
        study::co_moving::output::window(&scenario, section)?;
    }
    let _ = crate::scenario_args::print_warnings(&scenario, &case);
    let range = scenario.speed_range()?;
    let mesh = case.model.mesh();
    let foundation = case.model.foundation();
    let damping = match (foundation.stiffness > 0.0, case.model.sleepers()) {
        (true, _) => format!("ζ = {:.4}", foundation.damping_ratio(case.model.beam())),
        (false, None) => "no foundation".into(),
        (false, Some(_)) if case.model.embankment().is_some() => "no soil under the rail".into(),
        (false, Some(_)) => "no soil".into(),
    };
    let damping = match report::sleeper_output::track_in_words(&case.model) {
        Some(track) => format!("{damping}, on {track}"),
        None => damping,
    };
    let friction = match (&scenario.friction.devices, &scenario.friction.distributed) {
        (None, None) => "no friction".to_string(),
        (devices, distributed) => {
            let mut parts = Vec::new();
            if let Some(d) = devices {
                let placed = case.interactions.count(track::SectionKind::Device);
                parts.push(format!("{placed} devices of {:.1} kN", d.force.unwrap_or(0.0) / 1e3));
            }
            if let Some(d) = distributed {
                parts.push(format!("distributed {:.1} N/m", d.force_per_length));
            }
            parts.join(" and ")
        }
    };
    let soil_sections = case.interactions.count(track::SectionKind::Foundation);
    let friction = match soil_sections {
        0 => format!("{friction} ({} sections)", case.interactions.len()),
        n => format!(
            "{friction} ({} sections), {} soil ({n} sections)",
            case.interactions.len() - n,
            foundation.law.describe()
        ),
    };
    let title = if scenario.title.is_empty() { String::new() } else { format!(" \"{}\"", scenario.title) };
    let load = match &case.settings.moving.load {
        track::Load::Vehicles { vehicles: v, .. } => {
            let count = v.vehicles.len();
            format!("{count} vehicle{} ({} wheels)", if count == 1 { "" } else { "s" }, v.wheels().count())
        }
        track::Load::Train(t) => format!("train {} ({} axles, {:.3} m)", t.name, t.axles.len(), t.length()),
        track::Load::Force(force) => format!("load {:.1} kN", force / 1e3),
    };
    let beam = match scenario.beam.theory {
        fem_beam::BeamTheory::EulerBernoulli => "beam".to_string(),
        theory => format!("{} beam", theory.describe()),
    };
    println!(
        "{}{title}: ok — {} m {beam}, {} elements ({} DOFs), k_f = {:.1} kN/m², {damping}, {friction}, {load} at {} m/s, \
         sweep {}–{} m/s by {}",
        path.display(),
        mesh.length,
        mesh.elements,
        case.model.dofs().free_len(),
        foundation.stiffness / 1e3,
        scenario.load.speed,
        range.from,
        range.to,
        range.step
    );
    Ok(())
}

/// A scenario on a `[ground]`: its track and strip checked, described in one line with the commands that take it.
fn check_on_the_ground(path: &std::path::Path, scenario: &Scenario) -> Result<()> {
    let (beam, strip, track) = scenario.ground_track()?;
    let title = if scenario.title.is_empty() { String::new() } else { format!(" \"{}\"", scenario.title) };
    let layers = strip.profile.layers.len();
    let friction = match study::ground::wave::friction_on(scenario, &track)? {
        Some(force) => match track {
            scenario::ground::GroundTrack::Composite => format!("; ballast friction {:.1} kN/m", force / 1e3),
            _ => format!("; ballast friction {:.1} kN/m between the sleepers and the embankment", force / 1e3),
        },
        None => String::new(),
    };
    let (what, commands) = match track {
        scenario::ground::GroundTrack::Composite => (
            format!("composite beam EI = {:.3e} N·m², {:.0} kg/m", beam.bending_stiffness(), beam.mass_per_length()),
            "`frictrack ground`, `stationary`, `receptance` and `run` (on a fitted foundation) compute it",
        ),
        scenario::ground::GroundTrack::RailOnEmbankment { sleepers, embankment, interface } => (
            format!(
                "rail EI = {:.3e} N·m² on sleepers every {} m over an embankment of EI = {:.3e} N·m²{}",
                beam.bending_stiffness(),
                sleepers.spacing,
                embankment.bending_stiffness,
                match interface {
                    scenario::ground::Interface::Bonded => "",
                    scenario::ground::Interface::Tensionless { .. } => ", the ballast tensionless",
                }
            ),
            match interface {
                scenario::ground::Interface::Bonded => "`frictrack stationary` and `receptance` compute it",
                scenario::ground::Interface::Tensionless { .. } => {
                    "`frictrack stationary` computes its steady wave with the sleepers' lift-off, `receptance` its \
                     small vibrations about the weight's contact"
                }
            },
        ),
    };
    println!(
        "{}{title}: ok — {what} on a {} m strip of a layered ground ({layers} layer{} on a half-space of C_s {} m/s)\
         {friction}; {commands}",
        path.display(),
        strip.width,
        if layers == 1 { "" } else { "s" },
        strip.profile.half_space.shear_wave_speed
    );
    Ok(())
}
