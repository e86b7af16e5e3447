//! Run metadata written into every `summary.json`: program version, the whole resolved
//! case, and a hash of it, so a result can always be traced to its inputs.

use crate::config::Case;
use serde::Serialize;
use sha2::{Digest, Sha256};

#[derive(Debug, Clone, Serialize)]
pub struct RunMetadata {
    pub program: &'static str,
    pub version: &'static str,
    pub command: String,
    /// SHA-256 of the resolved case serialised as canonical TOML.
    pub case_sha256: String,
    pub case: Case,
}

impl RunMetadata {
    pub fn new(command: &str, case: &Case) -> Self {
        let text = toml::to_string(case).unwrap_or_default();
        let hash = Sha256::digest(text.as_bytes());
        Self {
            program: "gearwear",
            version: env!("CARGO_PKG_VERSION"),
            command: command.to_owned(),
            case_sha256: hash.iter().map(|b| format!("{b:02x}")).collect(),
            case: case.clone(),
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
