//! The `[output]` section of a case: how much of a long run the commands write. The
//! model ignores it; only the files change (docs/CONFIG.md, `report::decimate`).

use serde::{Deserialize, Serialize};

/// `[output]`: what the commands write of long runs.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct OutputSection {
    /// Write the per-point tables of a long run (`timeseries`, `path`: over 1e6 values,
    /// a hunting period's) at every recorded point; false (the default) writes them at
    /// every k-th row, k the smallest that leaves at most 5e5 values, and says so in
    /// `summary.json` (`output.thinned_tables`). Shorter tables are always whole.
    pub full_tables: bool,
}

impl OutputSection {
    /// Whether the section holds its defaults (then left out of a case's serialisation,
    /// so cases and their checksums stay as before the section existed).
    pub(crate) fn is_default(&self) -> bool {
        *self == Self::default()
    }
}
