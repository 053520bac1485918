//! Finished work survives: an append-only journal with one JSON line per finished run, written and flushed to the
//! operating system as soon as the run ends, so that a killed or interrupted sweep loses at most the runs that were
//! in flight. A resumed sweep reads the journal back and skips every run whose key (case fingerprint + speed, see
//! [`scenario::Case::fingerprint`]) it holds; floats are written in shortest round-trip form and read back exactly, so a
//! resumed sweep writes the same bytes as an uninterrupted one.
//!
//! Format: a first line `{"frictrack_journal":N}` with N the [`scenario::RESULT_FORMAT`] of what its runs
//! report, then lines `{"key":"…","value":…}`. A journal of another format is refused by name, never read back. A
//! last line cut short by a kill is dropped (and truncated away) when the journal is reopened.

use scenario::error::{Result, StudyError};
use serde::Serialize;
use serde::de::DeserializeOwned;
use serde_json::Value;
use std::collections::HashMap;
use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// The first line of a journal of this version's results.
fn header() -> String {
    format!("{{\"frictrack_journal\":{}}}", scenario::RESULT_FORMAT)
}

/// An append-only record of finished runs; shared by all worker threads.
#[derive(Debug)]
pub struct Journal {
    path: PathBuf,
    file: Mutex<File>,
    finished: HashMap<String, Value>,
}

#[derive(Serialize)]
struct Entry<'a, R> {
    key: &'a str,
    value: &'a R,
}

impl Journal {
    /// Open the journal at `path`. A journal already there is an error unless `resume`, in which case its finished
    /// runs are loaded; without one, `resume` starts an empty journal.
    pub fn open(path: &Path, resume: bool) -> Result<Self> {
        let error = |message: String| StudyError::Journal { path: path.display().to_string(), message };
        let mut finished = HashMap::new();
        let existing = match std::fs::read(path) {
            Ok(bytes) => Some(bytes),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
            Err(e) => return Err(error(e.to_string())),
        };
        let file = match existing {
            Some(bytes) => {
                let good = read_entries(&bytes, &mut finished).map_err(error)?;
                // A journal without a finished run (a command refused before its first run) keeps nothing to lose.
                if !resume && !finished.is_empty() {
                    return Err(error(
                        "results of an unfinished earlier run are kept here: pass --resume to continue it, or \
                         delete the file to start over"
                            .into(),
                    ));
                }
                let mut file = OpenOptions::new().append(true).open(path).map_err(|e| error(e.to_string()))?;
                // Drop a line cut short by a kill so that appends start on a fresh line (appends go to the new end).
                file.set_len(good as u64).map_err(|e| error(e.to_string()))?;
                if good == 0 {
                    writeln!(file, "{}", header()).map_err(|e| error(e.to_string()))?;
                }
                file
            }
            None => {
                if let Some(folder) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
                    std::fs::create_dir_all(folder).map_err(|e| error(e.to_string()))?;
                }
                let mut file = File::create(path).map_err(|e| error(e.to_string()))?;
                writeln!(file, "{}", header()).map_err(|e| error(e.to_string()))?;
                file
            }
        };
        Ok(Self { path: path.to_path_buf(), file: Mutex::new(file), finished })
    }

    /// Take the finished runs of another journal at `path` (read only; nothing is written to it or copied into this
    /// one's file) as if this one held them: `reproduce` runs the distributed-speed study's finite-beam curves and then
    /// the stationary-wave study runs the same cases at the same speeds (same keys), ~4 min at paper resolution.
    /// Returns how many were taken; a journal that is not there takes nothing.
    pub fn borrow_from(&mut self, path: &Path) -> Result<usize> {
        let error = |message: String| StudyError::Journal { path: path.display().to_string(), message };
        let bytes = match std::fs::read(path) {
            Ok(bytes) => bytes,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(0),
            Err(e) => return Err(error(e.to_string())),
        };
        let mut other = HashMap::new();
        read_entries(&bytes, &mut other).map_err(error)?;
        let taken = other.len();
        for (key, value) in other {
            self.finished.entry(key).or_insert(value);
        }
        Ok(taken)
    }

    /// Where it is.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// How many finished runs were read back when it was opened.
    pub fn resumed(&self) -> usize {
        self.finished.len()
    }

    /// Whether a result is stored under `key`.
    pub fn contains(&self, key: &str) -> bool {
        self.finished.contains_key(key)
    }

    /// The result stored under `key` by an earlier run, if any.
    pub fn get<R: DeserializeOwned>(&self, key: &str) -> Option<R> {
        self.finished.get(key).and_then(|v| R::deserialize(v).ok())
    }

    /// Append `value` under `key` as one line, written in one call and handed to the operating system at once.
    pub fn record<R: Serialize>(&self, key: &str, value: &R) -> Result<()> {
        let error = |message: String| StudyError::Journal { path: self.path.display().to_string(), message };
        let mut line = serde_json::to_string(&Entry { key, value }).map_err(|e| error(e.to_string()))?;
        line.push('\n');
        let mut file = self.file.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        file.write_all(line.as_bytes()).and_then(|()| file.flush()).map_err(|e| error(e.to_string()))
    }

    /// Delete the journal once the final result files are written.
    pub fn remove(self) -> Result<()> {
        std::fs::remove_file(&self.path)
            .map_err(|e| StudyError::Journal { path: self.path.display().to_string(), message: e.to_string() })
    }
}

/// The result format a journal's first line names, if it is one.
fn journal_format(line: &str) -> Option<u64> {
    serde_json::from_str::<Value>(line).ok()?.get("frictrack_journal")?.as_u64()
}

/// Load the entries of a journal; returns the length in bytes of its well-formed prefix.
fn read_entries(bytes: &[u8], finished: &mut HashMap<String, Value>) -> std::result::Result<usize, String> {
    let mut good = 0;
    for (number, line) in bytes.split_inclusive(|&b| b == b'\n').enumerate() {
        let complete = line.ends_with(b"\n");
        let text = std::str::from_utf8(line).map(str::trim_end);
        if number == 0 {
            let header = header();
            if text != Ok(header.as_str()) {
                if !complete && header.as_bytes().starts_with(line) {
                    return Ok(0);
                }
                return Err(match text.ok().and_then(journal_format) {
                    Some(format) => format!(
                        "a journal of results of format {format}, another version of frictrack (this one writes \
                         format {}): its runs are not results of this version; delete it to run them afresh",
                        scenario::RESULT_FORMAT
                    ),
                    None => "not a frictrack journal (first line differs); delete it or choose another output".into(),
                });
            }
        } else {
            let entry: Option<(String, Value)> = text
                .ok()
                .and_then(|t| serde_json::from_str::<Value>(t).ok())
                .and_then(|mut v| Some((v.get("key")?.as_str()?.to_string(), v.get_mut("value").map(Value::take)?)));
            match entry {
                Some((key, value)) if complete => {
                    finished.insert(key, value);
                }
                // Only the very last line may be cut short (the process was killed while writing it).
                _ if !complete => break,
                _ => return Err(format!("line {} is not a journal entry", number + 1)),
            }
        }
        good += line.len();
    }
    Ok(good)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A journal written by a version whose runs report another shape is refused by its format, with what to do;
    /// one of this version reads back.
    #[test]
    fn a_journal_of_another_result_format_is_refused_by_name() {
        let mut finished = HashMap::new();
        let old = b"{\"frictrack_journal\":1}\n{\"key\":\"a\",\"value\":{\"max_downward_deflection\":0.001}}\n";
        let message = read_entries(old, &mut finished).unwrap_err();
        assert!(message.contains("format 1") && message.contains(&format!("format {}", scenario::RESULT_FORMAT)));
        assert!(message.contains("delete it"), "{message}");
        assert!(finished.is_empty());
        let current = format!("{}\n{{\"key\":\"a\",\"value\":1.5}}\n", header());
        assert_eq!(read_entries(current.as_bytes(), &mut finished), Ok(current.len()));
        assert_eq!(finished["a"], 1.5);
        let foreign = b"speed,max\n";
        assert!(read_entries(foreign, &mut HashMap::new()).unwrap_err().contains("not a frictrack journal"));
    }
}
