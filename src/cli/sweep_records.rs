//! The case files of a sweep: `cases/<case_id>.json`, one per finished case or
//! continuation point, written first and atomically, read back before anything is
//! computed. Shared by `sweep_cmd` (parallel cases) and `sweep_continuation` (branches).

use crate::config::Case;
use crate::io::output_dir::StateFolder;
use crate::study::sweep::{CaseError, CaseRecord, ContinuationLink, SweepRun};
use std::path::{Path, PathBuf};

/// One case of this shard, resolved and validated.
pub struct Planned {
    pub id: usize,
    pub values: Vec<String>,
    pub case: Case,
    pub hash: String,
}

/// What ran now: each case id with its warnings or its error.
pub type Outcomes = Vec<(usize, Result<Vec<String>, CaseError>)>;

/// Where the record of case `id` lives.
pub fn case_path(dir: &Path, id: usize) -> PathBuf {
    dir.join("cases").join(format!("{id}.json"))
}

/// Whether the first bytes of a file are a sweep case record's (so a new record may
/// replace it).
pub fn is_case_record(b: &[u8]) -> bool {
    let t = String::from_utf8_lossy(b);
    t.trim_start().starts_with('{') && t.contains("\"case_id\"") && t.contains("\"case_sha256\"")
}

/// Write the record of a finished case (or continuation point) into `cases` (the set's
/// `cases` folder); the record is the first and only file a case writes.
pub fn write_record(
    cases: &StateFolder,
    p: &Planned,
    run: SweepRun,
    keys: &[String],
    results: &[f64],
    continuation: Option<ContinuationLink>,
) -> Result<CaseRecord, CaseError> {
    let rec = CaseRecord {
        case_id: p.id,
        case_sha256: p.hash.clone(),
        run,
        keys: keys.to_vec(),
        values: p.values.clone(),
        columns: run.columns(),
        results: results
            .iter()
            .map(|x| x.is_finite().then_some(*x))
            .collect(),
        continuation,
        checksum: None,
    }
    .sealed();
    let text = serde_json::to_string_pretty(&rec).map_err(|e| CaseError::Solve(e.into()))?;
    cases
        .write(&format!("{}.json", p.id), text.as_bytes(), is_case_record)
        .map_err(|e| CaseError::Solve(e.into()))?;
    Ok(rec)
}
