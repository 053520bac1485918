//! The crates form layers and every dependency points down (docs/architecture.md): a regression here is a lower
//! crate that started to use a higher one. Read from each crate's Cargo.toml (normal, dev and build dependencies).

/// The layers, bottom first: (package name, folder). The closed forms stand on the finite elements' words, never the
/// reverse. The Python bindings stand on top: on the scenario, runner, report and study libraries as the command line
/// does, and on the command line's library for the wheel's `frictrack` console script (one compiled module runs both).
const LAYERS: [(&str, &str); 14] = [
    ("banded", "crates/banded"),
    ("irregularity", "crates/irregularity"),
    ("fem-beam", "crates/fem-beam"),
    ("analytic", "crates/analytic"),
    ("friction", "crates/friction"),
    ("nscd", "crates/nscd"),
    ("track", "crates/track"),
    ("stationary", "crates/stationary"),
    ("scenario", "crates/scenario"),
    ("runner", "crates/runner"),
    ("report", "crates/report"),
    ("study", "crates/study"),
    ("frictrack", "crates/cli"),
    ("frictrack-python", "crates/python"),
];

fn manifest(folder: &str) -> toml::Table {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(folder).join("Cargo.toml");
    std::fs::read_to_string(&path).unwrap().parse().unwrap()
}

/// The workspace crates `folder` depends on in the dependency tables `tables` of its manifest.
fn dependencies_in(folder: &str, tables: &[&str]) -> Vec<String> {
    let manifest = manifest(folder);
    let names: Vec<&str> = LAYERS.iter().map(|(name, _)| *name).collect();
    tables
        .iter()
        .filter_map(|table| manifest.get(*table).and_then(toml::Value::as_table))
        .flat_map(|table| table.keys().cloned())
        .filter(|dependency| names.contains(&dependency.as_str()))
        .collect()
}

/// The workspace crates `folder` depends on, in any dependency table.
fn workspace_dependencies(folder: &str) -> Vec<String> {
    dependencies_in(folder, &["dependencies", "dev-dependencies", "build-dependencies"])
}

/// The workspace crates `folder` reaches through its normal dependencies, directly or through another, once each.
fn transitive_dependencies(folder: &str) -> Vec<String> {
    let mut reached: Vec<String> = Vec::new();
    let mut queue = normal_dependencies(folder);
    while let Some(name) = queue.pop() {
        if !reached.contains(&name) {
            let (_, below) = LAYERS.iter().find(|(n, _)| *n == name).unwrap();
            queue.extend(normal_dependencies(below));
            reached.push(name);
        }
    }
    reached
}

/// The workspace crates `folder` depends on in its `[dependencies]` (what its library links).
fn normal_dependencies(folder: &str) -> Vec<String> {
    dependencies_in(folder, &["dependencies"])
}

#[test]
fn every_dependency_points_down() {
    for (layer, (name, folder)) in LAYERS.iter().enumerate() {
        let package = manifest(folder)["package"]["name"].as_str().unwrap().to_string();
        assert_eq!(&package, name, "{folder}");
        for dependency in workspace_dependencies(folder) {
            let below = LAYERS.iter().position(|(n, _)| *n == dependency).unwrap();
            assert!(below < layer, "{name} depends on {dependency}, which is not below it");
        }
    }
    // The bottom crate knows nothing of the others; nscd reaches the banded algebra directly, not through fem-beam.
    assert!(workspace_dependencies("crates/banded").is_empty());
    assert!(workspace_dependencies("crates/irregularity").is_empty(), "rail profiles know no beam and no engine");
    assert!(workspace_dependencies("crates/nscd").contains(&"banded".to_string()));
    // The wheel's console script runs the command line's library: one compiled module, no second executable.
    assert!(normal_dependencies("crates/python").contains(&"frictrack".to_string()), "the console script's command");
    // Through another crate too: a lower crate reaches no higher one by any path.
    for (layer, (name, folder)) in LAYERS.iter().enumerate() {
        for reached in transitive_dependencies(folder) {
            let below = LAYERS.iter().position(|(n, _)| *n == reached).unwrap();
            assert!(below < layer, "{name} reaches {reached}, which is not below it");
        }
    }
}

/// The laws and interaction rows know no beam and the engine reaches no beam crate, directly or through another
/// (the friction placed on a beam, devices and ballast sections, lives in `track`).
#[test]
fn the_laws_and_the_engine_reach_no_beam() {
    assert!(transitive_dependencies("crates/friction").is_empty(), "{:?}", transitive_dependencies("crates/friction"));
    let engine = transitive_dependencies("crates/nscd");
    assert!(!engine.contains(&"fem-beam".to_string()) && !engine.contains(&"irregularity".to_string()), "{engine:?}");
    assert!(transitive_dependencies("crates/track").contains(&"fem-beam".to_string()));
}

/// Every `.rs` file under `folder`, recursively.
fn rust_files(folder: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
    super::files_under(folder, &|name| name.ends_with(".rs"), out);
}

/// The engine knows no beam (issue 16, docs/architecture.md): nscd depends on no beam crate in any dependency table,
/// and none of its sources, tests or examples names the beam crate or a beam type; the beam application lives in
/// `track`.
#[test]
fn the_engine_uses_no_beam_type() {
    assert!(!transitive_dependencies("crates/nscd").contains(&"fem-beam".to_string()));
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("crates/nscd");
    let mut files = Vec::new();
    rust_files(&root, &mut files);
    assert!(files.len() > 10, "nscd's sources found: {}", files.len());
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        for word in ["fem_beam", "BeamModel", "DofMap", "Mesh", "MovingLoad", "Simulation"] {
            assert!(!text.contains(word), "{} names `{word}`", file.display());
        }
    }
}

/// The engine's top-level modules `use` each other without a circle (issue 26: the stepper, the problem and Hertz's
/// law; the error, the solvers and Clarabel used to import each other): each module's `crate::…` paths outside
/// comments and tests, followed until they come back.
#[test]
fn the_engine_modules_import_without_circles() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../crates/nscd/src");
    let mut files = Vec::new();
    rust_files(&root, &mut files);
    let mut uses: std::collections::BTreeMap<String, std::collections::BTreeSet<String>> = Default::default();
    for file in &files {
        let relative = file.strip_prefix(&root).unwrap();
        let module = relative.iter().next().unwrap().to_str().unwrap().trim_end_matches(".rs").to_string();
        let text = std::fs::read_to_string(file).unwrap();
        let code = text.split("#[cfg(test)]").next().unwrap();
        for line in code.lines().filter(|l| !l.trim_start().starts_with("//")) {
            for (i, _) in line.match_indices("crate::") {
                let name: String = line[i + 7..].chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                if name != module && name.starts_with(|c: char| c.is_lowercase()) {
                    uses.entry(module.clone()).or_default().insert(name);
                }
            }
        }
    }
    assert!(uses.len() >= 8, "the engine's modules found: {uses:?}");
    // Depth-first from every module: a module reached again along its own path closes a circle.
    fn visit(
        module: &str,
        path: &mut Vec<String>,
        uses: &std::collections::BTreeMap<String, std::collections::BTreeSet<String>>,
    ) {
        for next in uses.get(module).into_iter().flatten() {
            assert!(!path.contains(next), "import circle: {} -> {next}", path.join(" -> "));
            path.push(next.clone());
            visit(next, path, uses);
            path.pop();
        }
    }
    for module in uses.keys() {
        visit(module, &mut vec![module.clone()], &uses);
    }
}
