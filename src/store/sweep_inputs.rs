//! Reading the inputs of a sweep merge: a sweep table and the description the sweep
//! wrote beside it (`STEM.csv` and `STEM.json`), both regular files of bounded size.
//!
//! The description is required: a table alone does not say which sweep it belongs to
//! (its axes, run kind and base case), and tables of two different sweeps can have
//! disjoint case ids that would merge silently.

use crate::io::input::{read_input_if_present, read_input_text, MAX_SWEEP_TABLE_BYTES};
use crate::study::sweep::SweepTable;
use std::path::Path;

/// The table at `csv` and its description (`csv` with the extension `.json`); errors name
/// the file.
pub(crate) fn merge_input(csv: &Path) -> Result<(SweepTable, serde_json::Value), String> {
    let src = csv.display();
    let text =
        read_input_text(csv, "sweep table", MAX_SWEEP_TABLE_BYTES).map_err(|e| e.to_string())?;
    let table = SweepTable::from_csv(&text).map_err(|e| format!("{src}: {e}"))?;
    let json = csv.with_extension("json");
    let Some(bytes) = read_input_if_present(&json, "sweep description", MAX_SWEEP_TABLE_BYTES)
        .map_err(|e| e.to_string())?
    else {
        return Err(format!(
            "{src} has no description {} beside it, so which sweep it belongs to cannot be checked: merge the tables with the JSON files their sweeps wrote",
            json.display()
        ));
    };
    let meta: serde_json::Value = serde_json::from_slice(&bytes)
        .map_err(|_| format!("{}: not a sweep description (not JSON)", json.display()))?;
    let is_sweep =
        (meta["command"] == "sweep" || meta["command"] == "sweep-merge") && !meta["vary"].is_null();
    if !is_sweep {
        return Err(format!(
            "{}: not a gearwear sweep description (no `command` sweep and `vary`)",
            json.display()
        ));
    }
    Ok((table, meta))
}
