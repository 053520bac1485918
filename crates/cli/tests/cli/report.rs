//! `frictrack report DIR`: one self-contained HTML file of a run, study or reproduce folder — every figure inline,
//! the warnings, the scenario, where it came from — and bad folders refused with exit code 2.

use super::{frictrack, temporary_folder};
use std::path::Path;

/// `frictrack report ARGS` succeeded; the HTML it wrote at `html`.
fn report(args: &[&str], html: &Path) -> String {
    let out = frictrack(&[&["report"], args].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stdout).contains(&html.display().to_string()));
    std::fs::read_to_string(html).unwrap()
}

/// What every report must be: one file that needs nothing else (no script, no stylesheet, image or link to
/// fetch), with its table of contents and a print stylesheet that keeps figures whole.
fn self_contained(html: &str) {
    assert!(html.starts_with("<!DOCTYPE html>"));
    for outside in ["<script", "<link", "src=", "href=\"http", "url("] {
        assert!(!html.contains(outside), "the report reaches outside itself: {outside}");
    }
    assert!(html.contains("<nav class=\"toc\""));
    assert!(html.contains("@media print") && html.contains("figure, pre, .warnings { break-inside: avoid"));
}

/// The commit `git` reports for the source tree the binary was built from (None outside a repository).
fn head_commit() -> Option<String> {
    let out = std::process::Command::new("git").args(["rev-parse", "--short=12", "HEAD"]).output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

#[test]
fn a_run_folder_becomes_one_page_with_its_figures_warnings_scenario_and_provenance() {
    let dir = temporary_folder("report-run");
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/voided-sleeper.toml");
    let out = frictrack(&["run", example, "--out", dir.to_str().unwrap(), "--quiet"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let html = report(&[dir.to_str().unwrap()], &dir.join("report.html"));
    self_contained(&html);
    // Every figure of the folder, inline, once.
    let svgs: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "svg"))
        .collect();
    assert!(svgs.len() >= 6, "{} figures", svgs.len());
    assert_eq!(html.matches("<figure id=").count(), svgs.len());
    assert_eq!(html.matches("<svg ").count(), svgs.len());
    for svg in &svgs {
        assert!(html.contains(&format!("<code>{}</code>", svg.file_name().to_string_lossy())));
    }
    // The warning the run printed (a step too long for the pads' resonance), the scenario as TOML, the command.
    let stderr = String::from_utf8_lossy(&out.stderr);
    let warning = stderr.lines().find_map(|l| l.strip_prefix("warning: ")).expect("the example warns");
    assert!(html.contains("Warnings (1)"), "one warning");
    assert!(html.contains(&warning.replace('\'', "&#39;").replace('"', "&quot;")[..60]));
    assert!(html.contains("[[sleepers.exceptions]]") && html.contains("gap = 0.0015"));
    assert!(html.contains("examples/voided-sleeper.toml --out"));
    assert!(html.contains("frictrack run: voided sleepers"));
    if let Some(commit) = head_commit() {
        assert!(html.contains(&format!("<code>{commit}</code>")), "the build's commit {commit}");
    }
    // The key numbers are the summary's (the deepest deflection, in mm).
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let deepest = summary["report"]["max_downward_deflection"]["value"].as_f64().unwrap() * 1e3;
    assert!(
        html.contains(&format!("<td class=\"num\">{deepest:.4}</td>"))
            || html.contains(&format!("<td class=\"num\">{deepest:.3}</td>")),
        "{deepest}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn study_and_reproduce_folders_report_each_study_in_order() {
    let dir = temporary_folder("report-studies");
    for study in ["receptance", "amplification"] {
        let out = frictrack(&["study", study, "--out", dir.to_str().unwrap(), "--quiet"]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let page = dir.join("both.html");
    let html = report(&[dir.to_str().unwrap(), "--out", page.to_str().unwrap()], &page);
    self_contained(&html);
    // Without reproduce's report.md the studies come by name; each has its headline, figures and per-curve lines.
    let (amplification, receptance) =
        (html.find("id=\"amplification\"").unwrap(), html.find("id=\"receptance\"").unwrap());
    assert!(amplification < receptance);
    for study in ["amplification", "receptance"] {
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join(format!("{study}.json"))).unwrap()).unwrap();
        let headline = json["headline"][0].as_str().unwrap();
        assert!(html.contains(&headline.replace('\'', "&#39;")[..40]), "{study}'s headline");
        for stem in json["plots"].as_array().unwrap() {
            assert!(html.contains(&format!("<code>{}.svg</code>", stem.as_str().unwrap())));
        }
        assert_eq!(json["command"].as_str().unwrap().split(' ').nth(1), Some("study"));
    }
    // A reproduce folder: its report.md sets the order and opens the page.
    std::fs::write(
        dir.join("report.md"),
        "# frictrack — the studies\n\nThe base case, in `numbers`.\n\n## 1. receptance\n\nData: [receptance.json](receptance.json)\n\n## 2. amplification\n\n[amplification.json](amplification.json)\n",
    )
    .unwrap();
    let html = report(&[dir.to_str().unwrap()], &dir.join("report.html"));
    assert!(html.find("id=\"receptance\"").unwrap() < html.find("id=\"amplification\"").unwrap());
    assert!(html.contains("frictrack reproduce") && html.contains("The base case, in <code>numbers</code>."));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_folder_without_results_is_refused_by_name() {
    let dir = temporary_folder("report-empty");
    std::fs::write(dir.join("notes.json"), "{\"study\": 3").unwrap();
    for (folder, why) in [
        (dir.clone(), "has no summary.json of a run, no <study>.json of a study and no command"),
        (dir.join("missing"), "not a folder"),
    ] {
        let out = frictrack(&["report", folder.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(&format!("invalid DIR = {}", folder.display())) && err.contains(why), "{err}");
        assert!(err.contains("frictrack run --out") && err.contains("stationary --out"), "{err}");
    }
    assert!(!dir.join("report.html").exists(), "nothing written");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The folders of `stationary`, `receptance`, `ground` and a sweep become a page too (they were refused, so none of
/// the ground's results could become a report): their numbers with units — an extreme's value and position in
/// columns of their own, not its JSON in one cell —, their warnings, every figure inline, self-contained.
#[test]
fn the_folders_of_the_other_commands_become_pages() {
    let dir = temporary_folder("report-commands");
    let example = |name: &str| format!("{}/../../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    let (soft, receptance) = (example("soft-ground.toml"), example("receptance.toml"));
    let folder = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let sweep_csv = dir.join("sweep").join("sweep.csv");
    std::fs::create_dir_all(dir.join("sweep")).unwrap();
    let commands: [(&[&str], &str, &str); 4] = [
        (
            &["stationary", &soft, "--speed", "300", "--out", &folder("stationary")],
            "stationary",
            "frictrack stationary",
        ),
        (
            &["receptance", &receptance, "--frequencies", "10:200:10", "--out", &folder("receptance")],
            "receptance",
            "frictrack receptance",
        ),
        (&["ground", &soft, "--frequencies", "2:20:2", "--out", &folder("ground")], "ground", "frictrack ground"),
        (
            &["sweep", "--speeds", "100:250:50", "--quiet", "--out", sweep_csv.to_str().unwrap()],
            "sweep",
            "frictrack sweep",
        ),
    ];
    for (args, name, title) in commands {
        let ran = frictrack(args);
        assert!(ran.status.success(), "{args:?}: {}", String::from_utf8_lossy(&ran.stderr));
        if name == "sweep" {
            assert!(frictrack(&["plot", sweep_csv.to_str().unwrap()]).status.success());
        }
        let html = report(&[&folder(name)], &dir.join(name).join("report.html"));
        self_contained(&html);
        assert!(html.contains(&format!("<title>{title}")), "{name}: {}", &html[..300]);
        assert!(html.contains("Figure 1:") && !html.contains("\"position\":"), "{name}");
    }
    // A run on the ground: its key results say the foundation was fitted to the ground, how, and how far its wave is
    // from the exact one (the damping ratio was given with no word that it is the fitted dashpot's).
    let run = folder("run");
    assert!(frictrack(&["run", &soft, "--speed", "40", "--quiet", "--out", &run]).status.success());
    let html = report(&[&run], &dir.join("run").join("report.html"));
    assert!(html.contains("damping ratio ζ of the foundation fitted to the ground"), "{html}");
    assert!(html.contains("ground: fitted spring k_f") && html.contains("fitted wave&#39;s error against the exact"));
    // The wave at 300 m/s reaches the window's end: the page carries the warning, and the extremes' columns.
    let html = std::fs::read_to_string(dir.join("stationary").join("report.html")).unwrap();
    assert!(html.contains("lies at the window") && html.contains("deflection.<wbr>position (m)"));
    let _ = std::fs::remove_dir_all(&dir);
}
