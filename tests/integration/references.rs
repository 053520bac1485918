//! The repository is self-contained: no source, manual or script refers to a file outside it (the project's
//! working notes live outside; what matters of them is written in `docs/`).

use std::path::{Path, PathBuf};

/// Every text file of the repository that a reader or the build reads, outside build output and version control.
fn text_files(folder: &Path, out: &mut Vec<PathBuf>) {
    let text = |name: &str| {
        name == "run"
            || ["rs", "md", "toml", "yml", "yaml", "sh", "py"].iter().any(|e| name.ends_with(&format!(".{e}")))
    };
    super::files_under(folder, &text, out);
}

#[test]
fn nothing_refers_to_a_file_outside_the_repository() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = Vec::new();
    text_files(&root, &mut files);
    assert!(files.len() > 100, "the repository's files found: {}", files.len());
    // Built at run time, so that this file does not name them itself.
    let mut outside: Vec<String> = ["STYLE", "DEPENDENCIES", "MODEL", "SOLVER"].map(|n| format!("{n}.md")).into();
    outside.extend(["../", "/work/"].map(|p| format!("{p}shared")));
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap_or_default();
        for name in &outside {
            assert!(!text.contains(name), "{} refers to `{name}`, outside the repository", file.display());
        }
    }
}
