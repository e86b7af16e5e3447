//! Helpers shared by the commands: model building with warnings, JSON and PNG writing.

use super::CliError;
use crate::config::Case;
use crate::io::write_atomic;
use crate::report::plot::{render_png, Figure};
use crate::study::Model;
use std::path::Path;

/// Plot size, px.
pub const PLOT_W: u32 = 900;
pub const PLOT_H: u32 = 420;

/// Build the model; geometry problems are input errors (exit 2); warnings go to stderr.
pub fn build_model(case: &Case) -> Result<Model, CliError> {
    let m = Model::from_case(case).map_err(|e| CliError::Input(e.0))?;
    for w in &m.warnings {
        eprintln!("warning: {w}");
    }
    Ok(m)
}

/// Pretty JSON, written atomically. Non-finite numbers become null (serde_json's rule),
/// never "NaN".
pub fn json_write(path: &Path, v: &serde_json::Value) -> anyhow::Result<()> {
    let text = serde_json::to_string_pretty(v)?;
    write_atomic(path, text.as_bytes())?;
    Ok(())
}

/// A figure as PNG, written atomically.
pub fn save_png(fig: &Figure, path: &Path) -> anyhow::Result<()> {
    let bytes = render_png(fig, PLOT_W, PLOT_H)?;
    write_atomic(path, &bytes)?;
    Ok(())
}

/// Metres to micrometres.
pub fn um(v: &[f64]) -> Vec<f64> {
    v.iter().map(|x| x * 1e6).collect()
}
