//! Writing result files: checked before any work starts, and written so that a finished file is never half-written
//! (temporary file beside it, then rename). Only regular files are ever replaced: a device node, FIFO, symlink or
//! folder at the target is refused, so `--out /dev/full` or a link to somewhere else cannot be destroyed. Result
//! files read back (a report's sources) are read only up to a bounded size ([`read_text`]).

use scenario::error::{Result, StudyError, invalid};
use std::io::Write;
use std::path::Path;

/// Check that `path` can take a result file: it is absent or a regular file (not a symlink, device, FIFO or
/// folder), and its folder exists and accepts new files. `option` names the flag in the error (exit code 2).
pub fn check_output_file(option: &str, path: &Path) -> Result<()> {
    if let Ok(meta) = std::fs::symlink_metadata(path) {
        let kind = meta.file_type();
        if !kind.is_file() {
            let what = if kind.is_dir() {
                "a folder"
            } else if kind.is_symlink() {
                "a symbolic link"
            } else {
                "not a regular file (a device, FIFO or socket)"
            };
            return Err(invalid(option, path.display(), format!("is {what}; give the path of a regular file")));
        }
    }
    check_folder_writable(option, folder_of(path))
}

/// Check that `folder` is a folder (created if missing) that accepts new files, before any run starts; whether it
/// was created here (an interrupted command removes a folder it created and left empty).
pub fn prepare_output_folder(option: &str, folder: &Path) -> Result<bool> {
    let created = std::fs::symlink_metadata(folder).is_err();
    if let Ok(meta) = std::fs::symlink_metadata(folder)
        && !meta.is_dir()
        && !(meta.file_type().is_symlink() && folder.is_dir())
    {
        return Err(invalid(option, folder.display(), "is not a folder"));
    }
    std::fs::create_dir_all(folder)
        .map_err(|e| invalid(option, folder.display(), format!("cannot be created: {e}")))?;
    check_folder_writable(option, folder)?;
    Ok(created)
}

fn folder_of(path: &Path) -> &Path {
    path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."))
}

/// Create and remove a probe file in `folder`.
fn check_folder_writable(option: &str, folder: &Path) -> Result<()> {
    let probe = folder.join(format!(".frictrack-probe-{}", std::process::id()));
    match std::fs::OpenOptions::new().write(true).create_new(true).open(&probe) {
        Ok(_) => {
            let _ = std::fs::remove_file(&probe);
            Ok(())
        }
        Err(e) => Err(invalid(option, folder.display(), format!("is not a writable folder: {e}"))),
    }
}

/// Write `bytes` to `path` atomically (a temporary file in the same folder, flushed, then renamed over `path`);
/// refuses a target that exists and is not a regular file.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<()> {
    check_output_file("output file", path)?;
    let folder = folder_of(path);
    let io = |message: String| StudyError::Io { path: path.display().to_string(), message };
    let name = path.file_name().ok_or_else(|| io("is not a file path".into()))?;
    let temporary = folder.join(format!(".{}.tmp-{}", name.to_string_lossy(), std::process::id()));
    let result = (|| -> std::io::Result<()> {
        let mut file = std::fs::File::create(&temporary)?;
        file.write_all(bytes)?;
        file.sync_all()?;
        std::fs::rename(&temporary, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    result.map_err(|e| io(format!("cannot be written: {e}")))
}

/// Draw `plots` into `folder` (PNG and SVG each, [`crate::plot::render`]), every target checked first like any
/// output (`option` names where the folder was given in an error); the names of the figures drawn.
pub fn write_figures(option: &str, plots: &[crate::plot::PlotSpec], folder: &Path) -> Result<Vec<String>> {
    for spec in plots {
        for extension in ["png", "svg"] {
            check_output_file(option, &folder.join(format!("{}.{extension}", spec.stem)))?;
        }
    }
    let mut drawn = Vec::with_capacity(plots.len());
    for spec in plots {
        crate::plot::render(spec, folder)?;
        drawn.push(format!("{}.png/.svg", spec.stem));
    }
    Ok(drawn)
}

/// The largest result file read back (a result's JSON, a figure, report.md): 64 MiB. frictrack's own are well under a
/// megabyte; a larger file in a result folder is not one of them, and is refused before it is read.
pub const LARGEST_FILE: u64 = 64 << 20;

/// The text of `path`, or an error naming it: unreadable, or larger than [`LARGEST_FILE`] (checked before reading).
pub fn read_text(path: &Path) -> Result<String> {
    let io = |e: std::io::Error| StudyError::Io { path: path.display().to_string(), message: e.to_string() };
    let size = std::fs::metadata(path).map_err(io)?.len();
    if size > LARGEST_FILE {
        return Err(StudyError::InvalidField {
            path: path.display().to_string(),
            value: format!("{size} bytes"),
            allowed: format!("a file frictrack wrote, at most {LARGEST_FILE} bytes"),
        });
    }
    std::fs::read_to_string(path).map_err(io)
}

#[cfg(test)]
mod tests {
    use super::{LARGEST_FILE, read_text};

    #[test]
    fn a_file_too_large_to_be_a_result_is_refused_before_it_is_read() {
        let path = std::env::temp_dir().join(format!("frictrack-large-{}.json", std::process::id()));
        // Sparse: the size is set, nothing is written.
        std::fs::File::create(&path).unwrap().set_len(LARGEST_FILE + 1).unwrap();
        let error = read_text(&path).unwrap_err().to_string();
        let _ = std::fs::remove_file(&path);
        assert!(error.contains(&format!("{} bytes", LARGEST_FILE + 1)) && error.contains("at most"), "{error}");
    }
}
