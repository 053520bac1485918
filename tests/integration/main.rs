//! Workspace-level integration tests: results that cross crate boundaries or cover a whole field.

mod accuracy;
mod figures;
mod infinite_track;
mod layers;
mod limits;
mod receptance_in_time;
mod recipes;
mod references;
mod resolution_check;
mod static_shape;
mod study_curves;

/// Every file under `folder`, recursively, whose name `keep` accepts, skipping build output, version control and
/// snapshot folders.
fn files_under(folder: &std::path::Path, keep: &dyn Fn(&str) -> bool, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(folder).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if path.is_dir() {
            if !matches!(name, "target" | ".git" | "snapshots") {
                files_under(&path, keep, out);
            }
        } else if keep(name) {
            out.push(path);
        }
    }
}
