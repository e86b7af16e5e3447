//! The record a finished sweep case leaves on disk (`cases/<case_id>.json`): its results,
//! what it was the result of, and for a continuation point the state it started from and
//! ended in, sealed by a checksum so that a rerun can tell a finished case from an edited
//! or foreign file.

use super::case_run::{CaseResults, SweepRun};
use super::continuation::Branch;
use crate::study::wear_check::StoredRunError;
use serde::{Deserialize, Serialize};

/// Why a sweep case record cannot be read back; the message names the file.
#[derive(Debug, thiserror::Error)]
pub enum CaseRecordError {
    /// The file cannot be read (missing is not an error: [`CaseRecord::read`] gives
    /// `None`).
    #[error(transparent)]
    Unreadable(#[from] crate::io::input::InputError),
    /// The file is not a case record's JSON.
    #[error("{path}: not a sweep case record: {source}")]
    NotARecord {
        /// The file.
        path: String,
        /// Why its JSON is not a record.
        source: serde_json::Error,
    },
    /// The record fails [`CaseRecord::verify`] (edited, or not whole).
    #[error("{path}: {source}")]
    Refused {
        /// The file.
        path: String,
        /// What is wrong with it.
        source: StoredRunError,
    },
}

/// What a finished case writes to `cases/<case_id>.json`: enough to rebuild its row and to
/// tell whether it belongs to the sweep being run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CaseRecord {
    /// The case's id in the sweep.
    pub case_id: usize,
    /// SHA-256 of the resolved case (`RunMetadata::case_sha256`).
    pub case_sha256: String,
    /// What the case ran.
    pub run: SweepRun,
    /// The varied keys.
    pub keys: Vec<String>,
    /// Labels of the case's varied values, one per key.
    pub values: Vec<String>,
    /// Names of the result columns.
    pub columns: Vec<String>,
    /// In `columns` order; null for a non-finite number.
    pub results: Vec<Option<f64>>,
    /// Continuation sweeps only: the branch, and the state the point started from
    /// (absent: static equilibrium) and ended in, as the bits of each f64 (exact in JSON).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub continuation: Option<ContinuationLink>,
    /// SHA-256 of the record's JSON without this field ([`CaseRecord::sealed`]), so an
    /// edited record is detected ([`CaseRecord::verify`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub checksum: Option<String>,
}

/// Where a continuation point sits on its branch (see [`CaseRecord::continuation`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ContinuationLink {
    /// The branch the point is on.
    pub branch: Branch,
    /// `f64::to_bits` of the start state; `None` for the static equilibrium.
    pub start_state_bits: Option<Vec<u64>>,
    /// `f64::to_bits` of the end state (the next point's start).
    pub end_state_bits: Vec<u64>,
}

impl ContinuationLink {
    /// The link of a point on `branch` that started from `start` (`None`: the static
    /// equilibrium) and ended in `end`.
    pub fn new(branch: Branch, start: Option<&[f64]>, end: &[f64]) -> Self {
        Self {
            branch,
            start_state_bits: start.map(state_bits),
            end_state_bits: state_bits(end),
        }
    }

    /// The end state, if the record holds one (a state of the case's model: a start of
    /// another length is not taken, `period_search::MeshPeriodSearch`).
    pub fn end_state(&self) -> Option<Vec<f64>> {
        (!self.end_state_bits.is_empty()).then(|| {
            self.end_state_bits
                .iter()
                .map(|b| f64::from_bits(*b))
                .collect()
        })
    }

    /// Whether this point was started from `start` (bit for bit).
    pub fn started_from(&self, start: Option<&[f64]>) -> bool {
        self.start_state_bits == start.map(state_bits)
    }
}

fn state_bits(s: &[f64]) -> Vec<u64> {
    s.iter().map(|x| x.to_bits()).collect()
}

impl CaseRecord {
    /// The record of case `case_id` (resolved case `case_sha256`, value labels `values`
    /// of `keys`) with `results`, sealed.
    pub fn of(
        case_id: usize,
        case_sha256: &str,
        keys: &[String],
        values: &[String],
        results: &CaseResults,
        continuation: Option<ContinuationLink>,
    ) -> Self {
        let run = results.run();
        CaseRecord {
            case_id,
            case_sha256: case_sha256.to_owned(),
            run,
            keys: keys.to_vec(),
            values: values.to_vec(),
            columns: results.columns(),
            results: results
                .values()
                .iter()
                .map(|x| x.is_finite().then_some(*x))
                .collect(),
            continuation,
            checksum: None,
        }
        .sealed()
    }

    /// The record's results (null numbers as NaN), if its columns are this version's.
    pub fn case_results(&self) -> Option<CaseResults> {
        let (run, stages, planets) = SweepRun::shape_of(&self.columns)?;
        if run != self.run {
            return None;
        }
        let v: Vec<f64> = self.results.iter().map(|x| x.unwrap_or(f64::NAN)).collect();
        CaseResults::from_values_of(self.run, stages, planets, &v)
    }

    fn content_checksum(&self) -> String {
        let plain = CaseRecord {
            checksum: None,
            ..self.clone()
        };
        crate::checksum::sha256_hex(serde_json::to_string(&plain).unwrap_or_default().as_bytes())
    }

    /// The record with its checksum set, ready to be written.
    pub fn sealed(mut self) -> Self {
        self.checksum = Some(self.content_checksum());
        self
    }

    /// Read back: the checksum matches the content, and the results match the columns.
    pub fn verify(&self) -> Result<(), StoredRunError> {
        match &self.checksum {
            None => return Err(StoredRunError::Mismatch("has no checksum".into())),
            Some(c) if *c != self.content_checksum() => {
                return Err(StoredRunError::Mismatch(
                    "does not match its checksum: the file was changed".into(),
                ))
            }
            Some(_) => {}
        }
        if self.results.len() != self.columns.len() {
            return Err(StoredRunError::Mismatch(format!(
                "holds {} results for {} columns",
                self.results.len(),
                self.columns.len()
            )));
        }
        if self.keys.len() != self.values.len() {
            return Err(StoredRunError::Mismatch(
                "its varied keys and values differ in number".into(),
            ));
        }
        Ok(())
    }

    /// Read the record at `path`: `Ok(None)` when there is none, an error (naming the
    /// file) when it is unreadable, not a record, or fails [`CaseRecord::verify`].
    pub fn read(path: &std::path::Path) -> Result<Option<Self>, CaseRecordError> {
        use crate::io::input::{read_input_if_present, MAX_CASE_RECORD_BYTES};
        let Some(bytes) = read_input_if_present(path, "sweep case record", MAX_CASE_RECORD_BYTES)?
        else {
            return Ok(None);
        };
        let shown = || path.display().to_string();
        let r: CaseRecord =
            serde_json::from_slice(&bytes).map_err(|source| CaseRecordError::NotARecord {
                path: shown(),
                source,
            })?;
        r.verify().map_err(|source| CaseRecordError::Refused {
            path: shown(),
            source,
        })?;
        Ok(Some(r))
    }

    /// Whether this record is the finished result of the given case: same id, resolved
    /// case, run kind, varied keys and values, and the columns this version writes. A
    /// continuation point is not the result of an ordinary case (see
    /// [`CaseRecord::continuation`] for its own check).
    pub fn is_result_of(
        &self,
        case_id: usize,
        hash: &str,
        run: SweepRun,
        keys: &[String],
        values: &[String],
    ) -> bool {
        self.case_id == case_id
            && self.case_sha256 == hash
            && self.run == run
            && self.keys == keys
            && self.values == values
            && SweepRun::shape_of(&self.columns).map(|(r, _, _)| r) == Some(run)
            && self.results.len() == self.columns.len()
            && self.continuation.is_none()
    }

    /// Whether this record is the finished result of continuation point `case_id` on
    /// `branch`, started from `start`: [`CaseRecord::is_result_of`] apart from the link,
    /// and the same branch and start state, so that a resumed branch follows the same
    /// path as an uninterrupted one.
    pub fn is_continuation_result_of(
        &self,
        case_id: usize,
        hash: &str,
        keys: &[String],
        values: &[String],
        branch: Branch,
        start: Option<&[f64]>,
    ) -> bool {
        let Some(link) = &self.continuation else {
            return false;
        };
        let plain = CaseRecord {
            continuation: None,
            checksum: None,
            ..self.clone()
        };
        plain.is_result_of(case_id, hash, SweepRun::Dynamics, keys, values)
            && link.branch == branch
            && link.started_from(start)
            && link.end_state().is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn record_matches_only_its_case() {
        let keys = vec!["operating.input_speed_hz".to_string()];
        let values = vec!["30".to_string()];
        let r = CaseRecord {
            case_id: 3,
            case_sha256: "abc".into(),
            run: SweepRun::Dynamics,
            keys: keys.clone(),
            values: values.clone(),
            columns: SweepRun::Dynamics.columns(),
            results: vec![Some(1.0); 9],
            continuation: None,
            checksum: None,
        };
        assert!(r.is_result_of(3, "abc", SweepRun::Dynamics, &keys, &values));
        assert!(!r.is_result_of(4, "abc", SweepRun::Dynamics, &keys, &values));
        assert!(!r.is_result_of(3, "abd", SweepRun::Dynamics, &keys, &values));
        assert!(!r.is_result_of(3, "abc", SweepRun::Wear, &keys, &values));
        assert!(!r.is_result_of(3, "abc", SweepRun::Dynamics, &keys, &["31".to_string()]));
    }
}
