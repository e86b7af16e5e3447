//! The arguments most commands share: how the case is given, and the figures' formats
//! and size.

use crate::config::{load_case_in, Case};
use clap::Args;
use std::path::PathBuf;

use super::error::CliError;

/// How a case is given: a TOML file and/or `--set` overrides on top of the default.
#[derive(Debug, Clone, Args, Default)]
pub(crate) struct CaseArgs {
    /// Case file (TOML). Omitted keys take the paper's defaults.
    #[arg(long, value_name = "FILE")]
    pub(crate) config: Option<PathBuf>,
    /// Override one key, e.g. --set operating.input_speed_hz=45 (repeatable).
    #[arg(long = "set", value_name = "SECTION.KEY=VALUE")]
    pub(crate) set: Vec<String>,
}

impl CaseArgs {
    /// The case file's text (empty without --config).
    pub(crate) fn text(&self) -> Result<String, CliError> {
        use crate::io::input::{read_input_text, MAX_CASE_BYTES};
        match &self.config {
            // Only a regular file of bounded size (a FIFO or a device is refused at once).
            Some(p) => read_input_text(p, "case file", MAX_CASE_BYTES)
                .map_err(|e| CliError::input(format!("--config {e}"))),
            None => Ok(String::new()),
        }
    }

    /// Read, merge and validate the case; a relative `load_spectrum.file` is read from the
    /// case file's folder.
    pub(crate) fn load(&self) -> Result<Case, CliError> {
        let dir = self
            .config
            .as_deref()
            .and_then(std::path::Path::parent)
            .unwrap_or(std::path::Path::new("."));
        Ok(load_case_in(&self.text()?, &self.set, dir)?)
    }
}

/// The formats and size of a command's figures.
#[derive(Debug, Clone, Args, Default)]
pub(crate) struct FigureArgs {
    /// Figure formats: png, svg (vector) or png,svg [default: png].
    #[arg(long = "figures", value_name = "FORMATS")]
    pub(crate) formats: Option<String>,
    /// Size of a one-panel figure in pixels, WIDTHxHEIGHT (width 400-8192, height
    /// 200-4096; figures of several panels keep their height ratio) [default: 900x420].
    #[arg(long = "figure-size", value_name = "WxH")]
    pub(crate) size: Option<String>,
}

impl FigureArgs {
    pub(crate) fn request(&self) -> crate::report::figure_output::FigureRequest {
        crate::report::figure_output::FigureRequest {
            formats: self.formats.clone(),
            size: self.size.clone(),
        }
    }
}
