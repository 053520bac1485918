//! Where the command line puts the files beside a result: the journal and the metadata of a sweep's CSV. Writing
//! files (checked first, written atomically) is the library's (`report::files`), shared with Python.

use std::path::{Path, PathBuf};

pub use report::files::{check_output_file, prepare_output_folder, write_atomically, write_figures};

/// The journal of finished runs kept beside the output `out`: `out.journal`.
pub fn journal_beside(out: &Path) -> PathBuf {
    let mut name = out.as_os_str().to_owned();
    name.push(".journal");
    name.into()
}

/// The JSON file that describes the CSV `out`: the same name with the extension `.json` (`sweep.csv` →
/// `sweep.json`).
pub fn metadata_beside(out: &Path) -> PathBuf {
    out.with_extension("json")
}
