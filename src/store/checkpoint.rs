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
//! A run in progress writes `checkpoint_MODE.partial.jsonl`; publishing the run's set
//! renames it to `checkpoint_MODE.jsonl`, so a folder's published results and its
//! checkpoints always belong to one case, even when a later run of another case was
//! interrupted there. A resumed run continues the partial file if there is one, else the
//! published one; it writes a new file (the records read, then its own), never into the
//! file it read.
//!
//! Loading checks the checksum of every line, the schema, the mode and the case; a last
//! line without its newline is what a killed write leaves and is dropped; anything else
//! that does not check out is an error naming the file and the line, never a silent
//! restart. The records' physics is checked by `study::wear_check` against the model,
//! and the last update is recomputed.

use crate::io::error::OutputError;
use crate::io::output_dir::{sha256_hex, OutputDir};
use crate::remedy::{Arg, Problem, Remedy, Words};
use crate::study::wear_loop::{UpdateRecord, WearMode, WearRun};
use serde::{Deserialize, Serialize};
use std::fs::File;
use std::io::Write;

const FORMAT: &str = "gearwear-wear-checkpoint";
/// Version of the format; a file of another version is refused with a clear message.
pub(crate) const SCHEMA: u32 = 2;

#[derive(Serialize, Deserialize)]
struct Header {
    format: String,
    schema: u32,
    mode: WearMode,
    case_sha256: String,
}

/// File name of a mode's published checkpoint, relative to the output folder.
pub(crate) fn checkpoint_name(mode: WearMode) -> String {
    format!("checkpoint_{}.jsonl", mode.name())
}

/// File name of a mode's checkpoint while its run is in progress.
#[cfg(test)]
pub(crate) fn partial_checkpoint_name(mode: WearMode) -> String {
    partial_of(&checkpoint_name(mode))
}

/// The name a checkpoint `NAME.jsonl` has while its run goes on: `NAME.partial.jsonl`.
pub(crate) fn partial_of(name: &str) -> String {
    match name.strip_suffix(".jsonl") {
        Some(stem) => format!("{stem}.partial.jsonl"),
        None => format!("{name}.partial"),
    }
}

/// Whether `bytes` begin like a gearwear checkpoint (its header line), so a file at a
/// checkpoint's name may be replaced by a new checkpoint.
pub(crate) fn is_checkpoint(bytes: &[u8]) -> bool {
    let line = bytes.split(|b| *b == b'\n').next().unwrap_or(&[]);
    let text = String::from_utf8_lossy(line);
    text.split_once(' ').is_some_and(|(sum, json)| {
        sha256_hex(json.as_bytes()) == sum
            && serde_json::from_str::<Header>(json).is_ok_and(|h| h.format == FORMAT)
    })
}

/// Why a checkpoint cannot be used (an input problem: the message names the file).
#[derive(Debug, thiserror::Error)]
#[error("{}", self.problem())]
pub struct CheckpointError {
    /// The checkpoint file, as the user named it.
    pub path: String,
    /// Why it cannot be used.
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

/// A checkpoint read back, and where it was read.
#[derive(Debug)]
pub(crate) struct LoadedCheckpoint {
    pub run: WearRun,
    /// Its path relative to the output folder.
    pub rel: String,
}

/// Parse the checkpoint `bytes` (named `source` in messages) of `mode` for the case with
/// hash `case_sha256`. A last line without its newline is dropped.
pub fn parse_checkpoint(
    bytes: &[u8],
    source: &str,
    mode: WearMode,
    case_sha256: &str,
) -> Result<WearRun, CheckpointError> {
    let err = |reason: String| CheckpointError {
        path: source.to_owned(),
        reason,
        remedy: None,
    };
    // Whole lines only: a last line without its newline is an interrupted append.
    let valid_len = bytes.iter().rposition(|b| *b == b'\n').map_or(0, |i| i + 1);
    if valid_len == 0 {
        return Err(err("has no header line".into()));
    }
    let mut records = Vec::new();
    for (i, raw) in bytes[..valid_len - 1].split(|b| *b == b'\n').enumerate() {
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
                .map_err(|_| err("line 1 is not a gearwear checkpoint header".into()))?;
            if h.format != FORMAT || h.schema != SCHEMA {
                return Err(err(format!(
                    "format {} version {} is not {FORMAT} version {SCHEMA}",
                    short(&h.format),
                    h.schema
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
                            .text("start afresh (without ")
                            .arg(Arg::Resume)
                            .text("), or resume with the same case"),
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
    Ok(WearRun {
        mode,
        records,
        stopped: None,
    })
}

/// The checkpoint of `mode` to resume from in `out`: the partial one of an interrupted
/// run if there is one, else the published one; None when there is neither. A file that
/// is not a regular single-link file, or holds more than `max_bytes`, is refused.
pub(crate) fn load_checkpoint(
    out: &OutputDir,
    mode: WearMode,
    case_sha256: &str,
    max_bytes: u64,
) -> Result<Option<LoadedCheckpoint>, CheckpointError> {
    load_checkpoint_named(out, &checkpoint_name(mode), mode, case_sha256, max_bytes)
}

/// As [`load_checkpoint`], for the checkpoint published as `name`.
pub(crate) fn load_checkpoint_named(
    out: &OutputDir,
    name: &str,
    mode: WearMode,
    case_sha256: &str,
    max_bytes: u64,
) -> Result<Option<LoadedCheckpoint>, CheckpointError> {
    for rel in [partial_of(name), name.to_owned()] {
        let source = out.root().join(&rel).display().to_string();
        let bytes = out
            .read_file(&rel, max_bytes)
            .map_err(|e| CheckpointError {
                path: source.clone(),
                reason: e.to_string(),
                remedy: None,
            })?;
        if let Some(b) = bytes {
            let run = parse_checkpoint(&b, &source, mode, case_sha256)?;
            return Ok(Some(LoadedCheckpoint { run, rel }));
        }
    }
    Ok(None)
}

/// An open checkpoint, appended to after every update.
pub(crate) struct CheckpointLog {
    file: File,
    path: std::path::PathBuf,
    /// Records already in the file.
    written: usize,
}

fn lines_of<'a>(
    records: impl Iterator<Item = &'a UpdateRecord>,
    name: &str,
) -> Result<String, OutputError> {
    let mut text = String::new();
    for r in records {
        let json = serde_json::to_string(r).map_err(|e| {
            OutputError::new("write", std::path::Path::new(name), e.to_string(), None)
        })?;
        text.push_str(&line_of(&json));
    }
    Ok(text)
}

impl CheckpointLog {
    /// Start the checkpoint of `run` (a new run, or one resumed with its records) in
    /// `out`, as the partial file that publishing renames to the checkpoint's name.
    pub fn create(
        out: &mut OutputDir,
        case_sha256: &str,
        run: &WearRun,
    ) -> Result<Self, OutputError> {
        let name = checkpoint_name(run.mode);
        Self::create_named(out, &name, case_sha256, run)
    }

    /// As [`CheckpointLog::create`], for the checkpoint published as `name` (written as
    /// its `.partial.jsonl` until the set is published).
    pub(crate) fn create_named(
        out: &mut OutputDir,
        name: &str,
        case_sha256: &str,
        run: &WearRun,
    ) -> Result<Self, OutputError> {
        let partial = partial_of(name);
        let header = Header {
            format: FORMAT.into(),
            schema: SCHEMA,
            mode: run.mode,
            case_sha256: case_sha256.into(),
        };
        let json = serde_json::to_string(&header).map_err(|e| {
            OutputError::new("write", &out.root().join(&partial), e.to_string(), None)
        })?;
        let mut text = line_of(&json);
        text.push_str(&lines_of(run.records.iter(), &partial)?);
        let file = out.create_log(&partial, Some(name), text.as_bytes(), is_checkpoint)?;
        Ok(Self {
            file,
            path: out.root().join(&partial),
            written: run.records.len(),
        })
    }

    /// Append the records of `run` not yet in the file, and sync.
    pub(crate) fn append_new(&mut self, run: &WearRun) -> Result<(), OutputError> {
        self.append_upto(run.records.len(), &|j| &run.records[j])
    }

    /// Append records `written..total` of a run whose record j is `record(j)` (those not
    /// yet in the file), and sync; the records before are not touched, so the cost stays
    /// flat however long the run.
    pub(crate) fn append_upto<'a>(
        &mut self,
        total: usize,
        record: &dyn Fn(usize) -> &'a UpdateRecord,
    ) -> Result<(), OutputError> {
        if total <= self.written {
            return Ok(());
        }
        let text = lines_of(
            (self.written..total).map(record),
            &self.path.to_string_lossy(),
        )?;
        self.file
            .write_all(text.as_bytes())
            .and_then(|_| self.file.sync_data())
            .map_err(|e| OutputError::io("write", &self.path, &e))?;
        self.written = total;
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
                increment_slices: None,
                path_rho1_m: vec![],
                path_load_n: vec![],
                // Digits JSON must carry exactly for a resumed run to match.
                end_state: Some(vec![std::f64::consts::PI / (i + 3) as f64; 16]),
            });
        }
        run
    }

    #[test]
    fn appends_round_trip_a_torn_last_line_is_dropped_and_publishing_renames() {
        let d = tempfile::tempdir().unwrap();
        let mut out = OutputDir::open(d.path(), None, "wear").unwrap();
        let full = run_of(3);
        let mut log = CheckpointLog::create(&mut out, "abc", &run_of(1)).unwrap();
        log.append_new(&run_of(2)).unwrap();
        log.append_new(&full).unwrap();
        let l = load_checkpoint(&out, WearMode::Dynamic, "abc", 1 << 20)
            .unwrap()
            .unwrap();
        assert_eq!(l.run, full);
        assert_eq!(l.rel, partial_checkpoint_name(WearMode::Dynamic));
        // A killed append leaves half a line: it is dropped.
        let p = d.path().join(&l.rel);
        let mut f = std::fs::OpenOptions::new().append(true).open(&p).unwrap();
        f.write_all(b"0123 {\"wear\":").unwrap();
        let l = load_checkpoint(&out, WearMode::Dynamic, "abc", 1 << 20)
            .unwrap()
            .unwrap();
        assert_eq!(l.run, full);
        assert!(is_checkpoint(&std::fs::read(&p).unwrap()));
        out.publish().unwrap();
        assert!(!p.exists());
        let text = std::fs::read(d.path().join(checkpoint_name(WearMode::Dynamic))).unwrap();
        let run = parse_checkpoint(&text, "c", WearMode::Dynamic, "abc").unwrap();
        assert_eq!(run, full);
    }

    #[test]
    fn edits_modes_and_cases_are_refused_with_the_line() {
        let d = tempfile::tempdir().unwrap();
        let mut out = OutputDir::open(d.path(), None, "wear").unwrap();
        CheckpointLog::create(&mut out, "abc", &run_of(3)).unwrap();
        let p = d.path().join(partial_checkpoint_name(WearMode::Dynamic));
        let text = std::fs::read_to_string(&p).unwrap();
        let parse = |b: &[u8], m, h: &str| {
            parse_checkpoint(b, "c.jsonl", m, h)
                .unwrap_err()
                .to_string()
        };
        let e = parse(text.as_bytes(), WearMode::QuasiStatic, "abc");
        assert!(e.contains("not a quasi-static"), "{e}");
        let e = parse(text.as_bytes(), WearMode::Dynamic, "xyz");
        assert!(e.contains("another case"), "{e}");
        let e = parse(
            text.replacen("0.21", "0.31", 1).as_bytes(),
            WearMode::Dynamic,
            "abc",
        );
        assert!(e.contains("line 2") && e.contains("checksum"), "{e}");
        let mut bytes = text.clone().into_bytes();
        let at = bytes.len() - 5;
        bytes[at] = 0xff;
        let e = parse(&bytes, WearMode::Dynamic, "abc");
        assert!(e.contains("UTF-8"), "{e}");
        // A multibyte character in the stored hash is named, never a panic.
        let h = r#"{"format":"gearwear-wear-checkpoint","schema":2,"mode":"dynamic","case_sha256":"ééééééééééééé"}"#;
        let e = parse(line_of(h).as_bytes(), WearMode::Dynamic, "abc");
        assert!(e.contains("another case"), "{e}");
        assert!(!is_checkpoint(b"my notes\n"));
    }
}
