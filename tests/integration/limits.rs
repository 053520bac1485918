//! The limits the project holds itself to (docs/architecture.md, "Limits"): no source file over 500 lines, no
//! function over 80, no crate over 30 % of the workspace's library lines. Read from the sources as rustfmt leaves
//! them: a function runs from its `fn` line to the first line that closes it at the same indentation.

use std::path::{Path, PathBuf};

/// The longest a source file may be (lines).
const FILE_LINES: usize = 500;
/// The longest a function may be, signature to closing brace (lines).
const FUNCTION_LINES: usize = 80;
/// The largest share of the workspace's library lines one crate may hold.
const CRATE_SHARE: f64 = 0.30;

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every Rust source of the workspace: the crates, the workspace tests, benches and xtask.
fn sources() -> Vec<PathBuf> {
    let mut files = Vec::new();
    for folder in ["crates", "tests", "benches", "xtask"] {
        super::files_under(&workspace().join(folder), &|name| name.ends_with(".rs"), &mut files);
    }
    files
}

/// Whether `line` opens a function item (any visibility and qualifiers), returning its indentation.
fn function_start(line: &str) -> Option<&str> {
    let trimmed = line.trim_start();
    let indent = &line[..line.len() - trimmed.len()];
    let mut rest = trimmed;
    for qualifier in ["pub(crate) ", "pub(super) ", "pub ", "const ", "async ", "unsafe ", "extern \"C\" "] {
        rest = rest.strip_prefix(qualifier).unwrap_or(rest);
    }
    rest.starts_with("fn ").then_some(indent)
}

/// The functions of `text` longer than [`FUNCTION_LINES`]: (first line, length).
fn long_functions(text: &str) -> Vec<(usize, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Some(indent) = function_start(line) else { continue };
        // The signature ends at the line that opens the body; a declaration without one (`;`) or a body on one line
        // is no function to measure.
        let Some(open) = (i..lines.len()).find(|&j| {
            let l = lines[j].trim_end();
            l.ends_with('{') || l.ends_with(';') || l.ends_with('}')
        }) else {
            continue;
        };
        if !lines[open].trim_end().ends_with('{') {
            continue;
        }
        let close = format!("{indent}}}");
        if let Some(end) = (open + 1..lines.len()).find(|&j| lines[j] == close) {
            let length = end - i + 1;
            if length > FUNCTION_LINES {
                out.push((i + 1, length));
            }
        }
    }
    out
}

#[test]
fn no_source_file_is_over_500_lines_and_no_function_over_80() {
    let files = sources();
    assert!(files.len() > 200, "sources found: {}", files.len());
    let mut breaches = Vec::new();
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let name = file.strip_prefix(workspace()).unwrap_or(file).display().to_string();
        let lines = text.lines().count();
        if lines > FILE_LINES {
            breaches.push(format!("{name}: {lines} lines"));
        }
        for (line, length) in long_functions(&text) {
            breaches.push(format!("{name}:{line}: a function of {length} lines"));
        }
    }
    assert!(
        breaches.is_empty(),
        "over the limits ({FILE_LINES} lines a file, {FUNCTION_LINES} a function):\n{}",
        breaches.join("\n")
    );
}

/// The scanner finds what it is for: a 81-line function is over, an 80-line one and a declaration are not.
#[test]
fn the_function_scanner_measures_from_fn_to_its_brace() {
    let body = |n: usize| (0..n).map(|i| format!("        let x{i} = {i};\n")).collect::<String>();
    let text = format!(
        "impl A {{\n    pub fn long(&self) {{\n{}    }}\n    fn short() {{\n{}    }}\n    fn declared();\n}}\n",
        body(79),
        body(78)
    );
    assert_eq!(long_functions(&text), vec![(2, 81)]);
}

#[test]
fn no_crate_holds_over_30_percent_of_the_library_lines() {
    let crates = workspace().join("crates");
    let mut sizes = Vec::new();
    for entry in std::fs::read_dir(&crates).unwrap() {
        let source = entry.unwrap().path().join("src");
        if !source.is_dir() {
            continue;
        }
        let mut files = Vec::new();
        super::files_under(&source, &|name| name.ends_with(".rs"), &mut files);
        let lines: usize = files.iter().map(|f| std::fs::read_to_string(f).unwrap().lines().count()).sum();
        sizes.push((source.parent().unwrap().file_name().unwrap().to_string_lossy().into_owned(), lines));
    }
    let total: usize = sizes.iter().map(|(_, n)| n).sum();
    assert!(sizes.len() >= 14 && total > 30_000, "{sizes:?}");
    for (name, lines) in &sizes {
        let share = *lines as f64 / total as f64;
        assert!(share <= CRATE_SHARE, "{name} holds {lines} of {total} library lines ({:.0} %)", 100.0 * share);
    }
}
