//! The case files of a sweep: `cases/<case_id>.json`, one per finished case or
//! continuation point, written first and atomically, read back before anything is
//! computed. Shared by `sweep_cmd` (parallel cases) and `sweep_continuation` (branches).

use crate::config::Case;
use crate::io::write_atomic;
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

/// Write the record of a finished case (or continuation point); the record is the first
/// and only file a case writes.
pub fn write_record(
    dir: &Path,
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
    write_atomic(&case_path(dir, p.id), text.as_bytes()).map_err(|e| CaseError::Solve(e.into()))?;
    Ok(rec)
}
