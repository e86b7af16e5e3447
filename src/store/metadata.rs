//! Run metadata written into every `summary.json`: program version, the whole resolved
//! case, and a hash of it, so a result can always be traced to its inputs; and beside the
//! case as given, the values the model used for its `"derived"` keys and the operating
//! point.

use crate::config::Case;
use crate::study::domain::Resolved;
use crate::study::Model;
use serde::Serialize;
use sha2::{Digest, Sha256};

/// What a run records about itself in `metadata.json`: the program, the command, the
/// resolved case and its checksum.
#[derive(Debug, Clone, Serialize)]
pub struct RunMetadata {
    /// Always `"gearwear"`.
    pub program: &'static str,
    /// The crate version that wrote the run.
    pub version: &'static str,
    /// The command that made the run (`run`, `wear`, ...).
    pub command: String,
    /// SHA-256 of the resolved case serialised as canonical TOML.
    pub case_sha256: String,
    /// The resolved case the run used.
    pub case: Case,
    /// The values the model used where the case leaves them to the geometry (hub bores,
    /// masses, inertias: `"derived"` or given), and the operating point; absent when no
    /// model was built.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resolved: Option<Resolved>,
}

impl RunMetadata {
    /// The metadata of a run of `command` on `case`, without the model's resolved values.
    pub fn new(command: &str, case: &Case) -> Self {
        let text = toml::to_string(case).unwrap_or_default();
        let hash = Sha256::digest(text.as_bytes());
        Self {
            program: "gearwear",
            version: env!("CARGO_PKG_VERSION"),
            command: command.to_owned(),
            case_sha256: hash.iter().map(|b| format!("{b:02x}")).collect(),
            case: case.clone(),
            resolved: None,
        }
    }

    /// The metadata of a run of `model` (its case, with what it resolved).
    pub(crate) fn of_model(command: &str, model: &Model) -> Self {
        Self {
            resolved: Some(model.resolved()),
            ..Self::new(command, &model.case)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hash_changes_with_case_and_not_otherwise() {
        let a = RunMetadata::new("x", &Case::default());
        let b = RunMetadata::new("y", &Case::default());
        let mut c = Case::default();
        c.operating.input_speed_hz = 31.0;
        let c = RunMetadata::new("x", &c);
        assert_eq!(a.case_sha256, b.case_sha256);
        assert_ne!(a.case_sha256, c.case_sha256);
        assert_eq!(a.case_sha256.len(), 64);
    }
}
