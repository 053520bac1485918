//! `frictrack reproduce [--out DIR] [--resolution coarse|paper]`: the six studies of docs/theory.md §7, the HSLM
//! study of §10, the vehicle study of §12 and the stationary wave of §14, their data, figures and a `report.md` that
//! shows every figure with a two-line summary of what it shows.

use crate::files::write_atomically;
use crate::study_cmd::{StudyOptions, run_study};
use anyhow::Result;
use clap::Args;
use std::fmt::Write as _;
use std::time::Instant;
use study::presets::Preset;

/// Options of `frictrack reproduce`.
#[derive(Debug, Args)]
pub struct ReproduceArgs {
    #[command(flatten)]
    options: StudyOptions,
}

/// Execute `frictrack reproduce`.
pub fn run(args: &ReproduceArgs) -> Result<()> {
    let (options, base) = (&args.options, args.options.base()?);
    crate::files::prepare_output_folder("--out", &options.out)?;
    crate::files::check_output_file("--out", &options.out.join("report.md"))?;
    let workers = options.workers()?;
    let start = Instant::now();
    let mut report = report_header(&base, options)?;
    // Journals stay until the report is written, so that --resume after an interruption re-runs nothing.
    let mut journals = Vec::new();
    // A study that fails, or cannot run on this scenario (its own set-up does not fit it: 199 devices on a mesh of
    // 39 interior nodes), is recorded in the report and the others still run; the command then exits non-zero naming
    // it, its journal kept for --resume. The base scenario itself was checked before the first study; an interruption
    // ends the command.
    let mut failed = Vec::new();
    for (i, preset) in Preset::REPRODUCED.into_iter().enumerate() {
        let timer = Instant::now();
        // The journals of the studies before this one: a run they finished is not run again (the stationary-wave
        // study's finite-beam curves are the distributed-speed study's).
        let before: Vec<std::path::PathBuf> =
            Preset::REPRODUCED[..i].iter().map(|p| options.out.join(format!(".{}.journal", p.name()))).collect();
        let (data, journal) = match run_study(preset, options, &base, &workers, &before) {
            Ok(done) => done,
            Err(e) if crate::error_code(&e) != crate::interrupt::EXIT_CODE => {
                let verdict = if crate::error_code(&e) == 2 { "not run on this scenario" } else { "failed" };
                let message = format!("{e:#}");
                eprintln!("{}: {verdict} after {:.1} s: {message}", preset.name(), timer.elapsed().as_secs_f64());
                let _ = writeln!(report, "## {}. {} — {verdict}\n\n{message}\n", i + 1, preset.name());
                failed.push(format!("{}: {verdict}: {message}", preset.name()));
                continue;
            }
            Err(e) => return Err(e),
        };
        if !options.quiet {
            eprintln!("{}: {} runs in {:.1} s", preset.name(), data.runs, timer.elapsed().as_secs_f64());
        }
        let _ = writeln!(report, "## {}. {}\n", i + 1, data.title);
        if data.failures.is_empty() {
            journals.push(journal);
        } else {
            // The study's other runs are in its data; the failed ones are listed first, the journal kept.
            let lines = crate::study_cmd::failure_lines(&data);
            eprintln!("{}: {} run(s) failed:\n{}", preset.name(), data.failures.len(), lines.join("\n"));
            let _ = writeln!(report, "**{} run(s) failed** (left out of the curves below):\n", data.failures.len());
            for line in &lines {
                let _ = writeln!(report, "- {}", line.trim_start());
            }
            let _ = writeln!(report);
            failed.push(format!("{}: {} run(s) failed", preset.name(), data.failures.len()));
        }
        study_section(&mut report, &data);
    }
    let _ = writeln!(report, "All {} studies took {:.1} s.", Preset::REPRODUCED.len(), start.elapsed().as_secs_f64());
    write_atomically(&options.out.join("report.md"), report.as_bytes())?;
    for journal in journals {
        journal.remove()?;
    }
    if !options.quiet {
        eprintln!("wrote {}", options.out.join("report.md").display());
    }
    if !failed.is_empty() {
        anyhow::bail!(
            "{} of {} studies failed, could not run on this scenario or had failed runs (the report has everything else; \
             their finished runs are kept for --resume):\n  {}",
            failed.len(),
            Preset::REPRODUCED.len(),
            failed.join("\n  ")
        );
    }
    Ok(())
}

/// The report's opening: the base case in numbers and how to read the figures.
fn report_header(base: &scenario::Scenario, options: &crate::study_cmd::StudyOptions) -> Result<String> {
    let mut report = String::new();
    let _ = writeln!(report, "# frictrack — the studies of docs/theory.md §7, §10, §12 and §14\n");
    let model = base.model()?;
    let (beam, foundation, mesh) = (model.beam(), model.foundation(), model.mesh());
    let v_cr = scenario::speeds::SpeedScale::of(base)?.critical_speed;
    let _ = writeln!(
        report,
        "{}: EI = {:.4} MN·m², ρA = {:.3} kg/m on a Winkler soil of k_f = {:.1} kN/m² (v_cr = {}), {} m beam of {} \
         Hermite elements ({:?}/{:?} ends), load F = {:.1} kN, integrated by the {}, load advance {} m per step. Resolution: {}. \
         Every figure has its data beside it (`<study>.csv`, SI units) and its metadata (`<study>.json`: the scenario, \
         what the study set itself, the CSV's units).\n",
        if base.title.is_empty() { "The reference case (UIC60 rail on soft soil)" } else { base.title.as_str() },
        beam.bending_stiffness() / 1e6,
        beam.mass_per_length(),
        foundation.stiffness / 1e3,
        v_cr.map_or("none without a foundation".to_string(), |v| format!("{v:.2} m/s")),
        mesh.length,
        mesh.elements,
        model.supports().left,
        model.supports().right,
        base.load.force / 1e3,
        base.scheme_used(),
        base.integration.load_advance,
        options.resolution.name()
    );
    let _ = writeln!(
        report,
        "Deflections are magnitudes in mm, downward solid and upward dashed; \"max\" is over the whole run from rest, \
         which near v_cr includes the exit transient at x ≈ L — the CSVs also give the extremes while the load is in \
         the middle third of the beam (`window_*` columns). A critical speed at an end of the speed range is a bound \
         and is marked so (`critical_speed_location`).\n"
    );
    Ok(report)
}

/// A study's section after its title (and its failures): the headline, the figures, the data and the per-curve
/// lines.
fn study_section(report: &mut String, data: &study::presets::StudyData) {
    for line in &data.headline {
        let _ = writeln!(report, "{line}  ");
    }
    let _ = writeln!(report);
    for plot in &data.plots {
        let _ = writeln!(report, "![{}]({}.png)\n", plot.title, plot.stem);
        let _ = writeln!(report, "*{}* — [SVG]({}.svg)\n", plot.title, plot.stem);
    }
    let _ = writeln!(
        report,
        "Data: [{name}.csv]({name}.csv), metadata: [{name}.json]({name}.json); {} simulations.\n",
        data.runs,
        name = data.name
    );
    let _ = writeln!(report, "<details><summary>Per curve</summary>\n");
    for line in &data.lines {
        let _ = writeln!(report, "- {line}");
    }
    let _ = writeln!(report, "\n</details>\n");
}
