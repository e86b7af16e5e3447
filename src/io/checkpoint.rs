//! Checkpoints of wear runs: an append-only log, one line per update, so an interrupted
//! study resumes where it stopped and reaches the same numbers, and the cost of writing a
//! checkpoint stays flat however long the run (the history is never rewritten).
//!
//! Format (`checkpoint_MODE.jsonl`), one line each, `SHA256 JSON\n`, the SHA-256 (hex) of
//! the JSON text after the space:
//! - line 1, the header: `{"format": "gearwear-wear-checkpoint", "schema": 2, "mode": ...,
//!   "case_sha256": ...}`;
//! - then one `UpdateRecord` per line, in order.
//!
//! Loading checks the checksum of every line, the schema, the mode and the case; a last
//! line without its newline is what a killed write leaves and is dropped (the file is cut
//! back to the last whole line when the run resumes); anything else that does not check
//! out is an error naming the file and the line, never a silent restart. The records'
//! physics is checked by `study::wear_check` against the model.

use super::error::OutputError;
use super::output_dir::sha256_hex;
use super::write_atomic;
use crate::remedy::{Arg, Problem, Remedy, Words};
use crate::study::wear_loop::{UpdateRecord, WearMode, WearRun};
use serde::{Deserialize, Serialize};
use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};

const FORMAT: &str = "gearwear-wear-checkpoint";
/// Version of the format; a file of another version is refused with a clear message.
pub const SCHEMA: u32 = 2;

#[derive(Serialize, Deserialize)]
struct Header {
    format: String,
    schema: u32,
    mode: WearMode,
    case_sha256: String,
}

/// File name of a mode's checkpoint, relative to the output folder.
pub fn checkpoint_name(mode: WearMode) -> String {
    format!("checkpoint_{}.jsonl", mode.name())
}

/// Why a checkpoint cannot be used (an input problem: the message names the file).
#[derive(Debug, thiserror::Error)]
#[error("{}", self.problem())]
pub struct CheckpointError {
    pub path: String,
    pub reason: String,
    /// What to do, when more than replacing the file (`crate::remedy`).
    pub remedy: Option<Box<Remedy>>,
}

impl CheckpointError {
    /// The error as a problem of resuming: `resuming: PATH: REASON; REMEDY`.
    pub fn problem(&self) -> Problem {
        let p = Problem::of(Arg::Resume, format!("{}: {}", self.path, self.reason));
        match &self.remedy {
            Some(r) => p.remedy((**r).clone().path(&self.path)),
            None => p,
        }
    }
}

fn line_of(json: &str) -> String {
    format!("{} {json}\n", sha256_hex(json.as_bytes()))
}

fn short(s: &str) -> String {
    s.chars().take(12).collect()
}

/// A checkpoint read back: the run, and the length of the file up to its last whole line.
#[derive(Debug)]
pub struct LoadedCheckpoint {
    pub run: WearRun,
    pub valid_len: u64,
}

/// Load the checkpoint `path` of `mode` for the case with hash `case_sha256`: `Ok(None)`
/// when there is none, an error when it cannot be trusted.
pub fn load_checkpoint(
    path: &Path,
    mode: WearMode,
    case_sha256: &str,
) -> Result<Option<LoadedCheckpoint>, CheckpointError> {
    let err = |reason: String| CheckpointError {
        path: path.display().to_string(),
        reason,
        remedy: None,
    };
    let bytes = match std::fs::read(path) {
        Ok(b) => b,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(err(format!("cannot read: {e}"))),
    };
    // Whole lines only: a last line without its newline is an interrupted append.
    let valid_len = bytes.iter().rposition(|b| *b == b'\n').map_or(0, |i| i + 1);
    let mut records = Vec::new();
    for (i, raw) in bytes[..valid_len].split(|b| *b == b'\n').enumerate() {
        if i > 0 && raw.is_empty() {
            continue; // the end of the last line
        }
        let line_no = i + 1;
        let text = std::str::from_utf8(raw)
            .map_err(|_| err(format!("line {line_no} is not UTF-8 text")))?;
        let (sum, json) = text
            .split_once(' ')
            .ok_or_else(|| err(format!("line {line_no} is not `checksum json`")))?;
        if sha256_hex(json.as_bytes()) != sum {
            return Err(err(format!(
                "line {line_no} does not match its checksum: the file was changed"
            )));
        }
        if i == 0 {
            let h: Header = serde_json::from_str(json)
                .map_err(|e| err(format!("not a gearwear checkpoint: {e}")))?;
            if h.format != FORMAT || h.schema != SCHEMA {
                return Err(err(format!(
                    "format {} version {} is not {FORMAT} version {SCHEMA}",
                    h.format, h.schema
                )));
            }
            if h.mode != mode {
                return Err(err(format!(
                    "holds a {} run, not a {} one",
                    h.mode.label(),
                    mode.label()
                )));
            }
            if h.case_sha256 != case_sha256 {
                return Err(CheckpointError {
                    remedy: Some(Box::new(Remedy::new(
                        Words::new()
                            .text("rerun without ")
                            .arg(Arg::Resume)
                            .text(" or with the same case"),
                    ))),
                    ..err(format!(
                        "belongs to another case (hash {} != {})",
                        short(&h.case_sha256),
                        short(case_sha256)
                    ))
                });
            }
        } else {
            let r: UpdateRecord = serde_json::from_str(json)
                .map_err(|e| err(format!("line {line_no}: not an update record: {e}")))?;
            records.push(r);
        }
    }
    if valid_len == 0 {
        return Err(err("has no header line".into()));
    }
    Ok(Some(LoadedCheckpoint {
        run: WearRun {
            mode,
            records,
            stopped: None,
        },
        valid_len: valid_len as u64,
    }))
}

/// An open checkpoint, appended to after every update.
pub struct CheckpointLog {
    file: File,
    path: PathBuf,
    /// Records already in the file.
    written: usize,
}

fn open_append(path: &Path) -> std::io::Result<File> {
    let mut o = OpenOptions::new();
    o.write(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        o.custom_flags(libc::O_NOFOLLOW);
    }
    o.open(path)
}

impl CheckpointLog {
    /// Start a new checkpoint at `path` (replacing any earlier one) for `run` so far.
    pub fn create(path: &Path, case_sha256: &str, run: &WearRun) -> Result<Self, OutputError> {
        let header = Header {
            format: FORMAT.into(),
            schema: SCHEMA,
            mode: run.mode,
            case_sha256: case_sha256.into(),
        };
        let json = serde_json::to_string(&header)
            .map_err(|e| OutputError::new("write", path, e.to_string(), None))?;
        write_atomic(path, line_of(&json).as_bytes())?;
        let file = open_append(path).map_err(|e| OutputError::io("open", path, &e))?;
        let mut log = Self {
            file,
            path: path.to_path_buf(),
            written: 0,
        };
        log.append_new(run)?;
        Ok(log)
    }

    /// Continue a loaded checkpoint: cut it back to its last whole line.
    pub fn resume(path: &Path, loaded: &LoadedCheckpoint) -> Result<Self, OutputError> {
        let file = open_append(path).map_err(|e| OutputError::io("open", path, &e))?;
        file.set_len(loaded.valid_len)
            .map_err(|e| OutputError::io("write", path, &e))?;
        Ok(Self {
            file,
            path: path.to_path_buf(),
            written: loaded.run.records.len(),
        })
    }

    /// Append the records of `run` not yet in the file, and sync.
    pub fn append_new(&mut self, run: &WearRun) -> Result<(), OutputError> {
        if run.records.len() <= self.written {
            return Ok(());
        }
        let mut text = String::new();
        for r in &run.records[self.written..] {
            let json = serde_json::to_string(r)
                .map_err(|e| OutputError::new("write", &self.path, e.to_string(), None))?;
            text.push_str(&line_of(&json));
        }
        use std::io::{Seek, SeekFrom};
        self.file
            .seek(SeekFrom::End(0))
            .and_then(|_| self.file.write_all(text.as_bytes()))
            .and_then(|_| self.file.sync_data())
            .map_err(|e| OutputError::io("write", &self.path, &e))?;
        self.written = run.records.len();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wear::WearState;

    fn run_of(n: usize) -> WearRun {
        let mut run = WearRun::new(WearMode::Dynamic);
        for i in 0..n {
            let mut w = WearState::new(3);
            w.cycles = 10.0 * i as f64;
            run.records.push(UpdateRecord {
                wear: w,
                roughness_um: 0.21,
                summary: Default::default(),
                increment_pinion_m: vec![0.0; 3],
                increment_gear_m: vec![0.0; 3],
                increment_teeth: None,
                path_rho1_m: vec![],
                path_load_n: vec![],
                // Digits JSON must carry exactly for a resumed run to match.
                end_state: Some(vec![std::f64::consts::PI / (i + 3) as f64; 16]),
            });
        }
        run
    }

    #[test]
    fn appends_round_trip_and_a_torn_last_line_is_dropped() {
        let d = tempfile::tempdir().unwrap();
        let p = d.path().join(checkpoint_name(WearMode::Dynamic));
        let full = run_of(3);
        let mut log = CheckpointLog::create(&p, "abc", &run_of(1)).unwrap();
        log.append_new(&run_of(2)).unwrap();
        log.append_new(&full).unwrap();
        let l = load_checkpoint(&p, WearMode::Dynamic, "abc")
            .unwrap()
            .unwrap();
        assert_eq!(l.run, full);
        // A killed append leaves half a line: it is dropped, and resuming cuts it off.
        let mut f = OpenOptions::new().append(true).open(&p).unwrap();
        f.write_all(b"0123 {\"wear\":").unwrap();
        let l = load_checkpoint(&p, WearMode::Dynamic, "abc")
            .unwrap()
            .unwrap();
        assert_eq!(l.run, full);
        CheckpointLog::resume(&p, &l).unwrap();
        assert_eq!(std::fs::metadata(&p).unwrap().len(), l.valid_len);
    }

    #[test]
    fn edits_modes_and_cases_are_refused_with_the_line() {
        let d = tempfile::tempdir().unwrap();
        let p = d.path().join("c.jsonl");
        CheckpointLog::create(&p, "abc", &run_of(3)).unwrap();
        let e = load_checkpoint(&p, WearMode::QuasiStatic, "abc").unwrap_err();
        assert!(e.to_string().contains("not a quasi-static"), "{e}");
        let e = load_checkpoint(&p, WearMode::Dynamic, "xyz").unwrap_err();
        assert!(e.to_string().contains("another case"), "{e}");
        let text = std::fs::read_to_string(&p).unwrap();
        std::fs::write(&p, text.replacen("0.21", "0.31", 1)).unwrap();
        let e = load_checkpoint(&p, WearMode::Dynamic, "abc").unwrap_err();
        assert!(
            e.to_string().contains("line 2") && e.to_string().contains("checksum"),
            "{e}"
        );
        let mut bytes = text.into_bytes();
        let at = bytes.len() - 5;
        bytes[at] = 0xff;
        std::fs::write(&p, &bytes).unwrap();
        let e = load_checkpoint(&p, WearMode::Dynamic, "abc").unwrap_err();
        assert!(e.to_string().contains("UTF-8"), "{e}");
        // A multibyte character in the stored hash is named, never a panic.
        let h = r#"{"format":"gearwear-wear-checkpoint","schema":2,"mode":"dynamic","case_sha256":"ééééééééééééé"}"#;
        std::fs::write(&p, line_of(h)).unwrap();
        let e = load_checkpoint(&p, WearMode::Dynamic, "abc").unwrap_err();
        assert!(e.to_string().contains("another case"), "{e}");
    }
}
