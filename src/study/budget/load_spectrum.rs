//! The cost of `load-spectrum`: counting a measured torque / speed history.

use super::cost::{Estimate, Term};

/// The estimated cost of `load-spectrum` on a history of `bytes` of text: read, parsed
/// into its columns and counted in one pass, about three times the text in memory, and
/// 2e-8 s a byte (a 1e6-sample history, about 30 MB of text, counts in 0.39 s:
/// docs/PERFORMANCE.md, duty-cycle benchmark).
pub fn estimate_history(bytes: u64) -> Estimate {
    Estimate::of_terms(vec![Term {
        what: "the history read and counted",
        seconds: bytes as f64 * 2e-8,
        bytes: 3.0 * bytes as f64,
        keys: &["the size of the history"],
    }])
}
