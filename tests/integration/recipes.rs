//! The recipes of docs/architecture.md ("How to add …") name the files a contribution touches: every path they name
//! exists, so that a recipe cannot point a newcomer at a file that was moved or split.

use std::path::Path;

/// The recipes the architecture promises, by their bold titles.
const RECIPES: [&str; 7] =
    ["A soil law", "A vehicle", "A study preset", "A solver", "An override", "An output", "A support type"];

/// The backticked paths of `text`: tokens with a `/` ending in a file name with an extension, or in `/` (a folder).
fn paths(text: &str) -> Vec<&str> {
    text.split('`')
        .skip(1)
        .step_by(2)
        .filter(|t| {
            t.contains('/')
                && !t.contains(' ')
                && (t.ends_with('/') || t.rsplit('/').next().is_some_and(|f| f.contains('.')))
        })
        .collect()
}

#[test]
fn every_file_a_recipe_names_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let doc = std::fs::read_to_string(root.join("docs/architecture.md")).unwrap();
    let start = doc.find("## How to add").expect("a section of recipes");
    let section = &doc[start..];
    let section = &section[..section[3..].find("\n## ").map_or(section.len(), |end| end + 3)];
    for recipe in RECIPES {
        assert!(section.contains(&format!("**{recipe}")), "no recipe for {recipe}");
    }
    let named = paths(section);
    // Each of the seven recipes names files: a parse that finds few has lost them.
    assert!(named.len() >= 30, "{} paths: {named:?}", named.len());
    let missing: Vec<&&str> = named
        .iter()
        .filter(|p| {
            let at_root = ["tests/", "docs/", "crates/"].iter().any(|top| p.starts_with(top));
            let under = if at_root { root.join(p) } else { root.join("crates").join(p) };
            !under.exists()
        })
        .collect();
    assert!(missing.is_empty(), "the recipes name files that do not exist: {missing:?}");
}

#[test]
fn paths_are_read_from_backticks_only() {
    let text = "a `track/src/co_moving.rs` and `nscd/src/solver/`, not `Support::held` or `a b/c.rs` or `x.rs`";
    assert_eq!(paths(text), ["track/src/co_moving.rs", "nscd/src/solver/"]);
}
