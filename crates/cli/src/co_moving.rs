//! `frictrack run` through a co-moving window (`[co_moving]` or `--co-moving`): the load crosses any length of
//! endless track at a cost per step set by the window alone (docs/theory.md §15).

use crate::Format;
use crate::files::{check_output_file, prepare_output_folder, write_atomically, write_figures};
use anyhow::Result;
use scenario::CoMovingSection;
use scenario::Scenario;

/// Run `scenario` through its window and print or write the result.
pub fn run(
    scenario: &Scenario,
    section: &CoMovingSection,
    format: Format,
    out: Option<&std::path::Path>,
) -> Result<()> {
    if let Some(folder) = out {
        prepare_output_folder("--out", folder)?;
        for name in ["co-moving.json", "wave.csv"] {
            check_output_file("--out", &folder.join(name))?;
        }
    }
    // On a [ground], the window runs on the foundation fitted to it, fitted once here and said.
    let fitted;
    let scenario = match &scenario.ground {
        Some(_) => {
            let fit;
            (fitted, fit) = scenario.on_fitted_foundation()?;
            eprintln!("note: {}", report::run_text::ground_fit_line(&fit, false));
            if let Some(warning) = scenario::diagnostics::ground_fit_warning(&fit) {
                eprintln!("warning: {warning}");
            }
            &fitted
        }
        None => scenario,
    };
    let (summary, result) = study::co_moving::output::run(scenario, section)?;
    crate::print_output(&summary, format)?;
    if let Some(folder) = out {
        let metadata = summary.file("wave.csv");
        write_atomically(&folder.join("co-moving.json"), serde_json::to_string_pretty(&metadata)?.as_bytes())?;
        write_atomically(&folder.join("wave.csv"), study::co_moving::output::wave_csv(&result).as_bytes())?;
        let drawn = write_figures("--out", &study::co_moving::figures::figures(&summary, &result), folder)?;
        if format == Format::Text {
            println!("  wrote {}/co-moving.json, wave.csv and {}", folder.display(), drawn.join(", "));
        }
    }
    Ok(())
}
