//! The crates form layers and every dependency points down (docs/architecture.md): a regression here is a lower
//! crate that started to use a higher one. Read from each crate's Cargo.toml (normal, dev and build dependencies).

/// The layers, bottom first: (package name, folder).
const LAYERS: [(&str, &str); 6] = [
    ("banded", "crates/banded"),
    ("fem-beam", "crates/fem-beam"),
    ("friction", "crates/friction"),
    ("nscd", "crates/nscd"),
    ("study", "crates/study"),
    ("frictrack", "crates/cli"),
];

fn manifest(folder: &str) -> toml::Table {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(folder).join("Cargo.toml");
    std::fs::read_to_string(&path).unwrap().parse().unwrap()
}

/// The workspace crates `folder` depends on, in any dependency table.
fn workspace_dependencies(folder: &str) -> Vec<String> {
    let manifest = manifest(folder);
    let names: Vec<&str> = LAYERS.iter().map(|(name, _)| *name).collect();
    ["dependencies", "dev-dependencies", "build-dependencies"]
        .iter()
        .filter_map(|table| manifest.get(*table).and_then(toml::Value::as_table))
        .flat_map(|table| table.keys().cloned())
        .filter(|dependency| names.contains(&dependency.as_str()))
        .collect()
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
    assert!(workspace_dependencies("crates/nscd").contains(&"banded".to_string()));
}
