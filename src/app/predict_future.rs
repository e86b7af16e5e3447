//! The future duty of a prediction as a front end gives it: a `[load_spectrum]` section
//! (a file, or its TOML text, spelled as in a case file) and the pinion cycles from which
//! it applies, checked and resolved into a [`FutureDuty`].
//!
//! The cycle count has no default: a prediction counts cycles from new teeth, and only the
//! user knows where "now" is on that axis (a posterior file does not record its
//! observations' cycles), so a future spectrum without it is refused.

use super::JobError;
use crate::config::load_spectrum_section;
use crate::prognostics::forward::FutureDuty;
use crate::remedy::{Arg, Problem};
use std::path::{Path, PathBuf};

/// Where the future `[load_spectrum]` section comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum SpectrumSource {
    /// A TOML file; a relative `file` in it is read from the file's folder.
    File(PathBuf),
    /// TOML text; a relative `file` in it is read from the current folder.
    Text(String),
}

/// A future duty as given (see the module docs).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FutureInput {
    /// The future load spectrum (`None`: the case's own duty to the end).
    pub spectrum: Option<SpectrumSource>,
    /// Pinion cycles from new teeth at which the future spectrum takes over.
    pub from_cycles: Option<f64>,
}

impl FutureInput {
    /// The future duty (None without a spectrum), its cycle count checked against the
    /// prediction's horizon `horizon_cycles`. Every problem names its argument.
    pub fn resolve(&self, horizon_cycles: f64) -> Result<Option<FutureDuty>, JobError> {
        let Some(source) = &self.spectrum else {
            return match self.from_cycles {
                None => Ok(None),
                Some(n) => Err(Problem::given(
                    Arg::FutureFromCycles,
                    n.to_string(),
                    "given without a future load spectrum",
                )
                .into()),
            };
        };
        let mut bad = Vec::new();
        let (shown, text, dir) = match source {
            SpectrumSource::File(p) => {
                let shown = p.display().to_string();
                // Only a regular file of bounded size, as every input (a FIFO would block).
                match crate::io::input::read_input_text(
                    p,
                    "future load spectrum",
                    crate::io::input::MAX_CASE_BYTES,
                ) {
                    Ok(t) => (shown, t, p.parent().unwrap_or(Path::new(".")).to_path_buf()),
                    Err(e) => {
                        return Err(Problem::given(
                            Arg::FutureSpectrum,
                            shown,
                            format!("cannot read: {}", e.reason),
                        )
                        .into())
                    }
                }
            }
            SpectrumSource::Text(t) => ("(TOML text)".to_string(), t.clone(), PathBuf::from(".")),
        };
        let spectrum = match load_spectrum_section(&text, &dir) {
            Ok(s) => Some(s),
            Err(e) => {
                bad.extend(
                    e.problems
                        .into_iter()
                        .map(|w| Problem::given(Arg::FutureSpectrum, &shown, w)),
                );
                None
            }
        };
        let range =
            format!("expected pinion cycles from new teeth in [0, {horizon_cycles}) (the horizon)");
        match self.from_cycles {
            None => bad.push(Problem::of(
                Arg::FutureFromCycles,
                format!("required with a future load spectrum: {range}"),
            )),
            Some(n) if !(n.is_finite() && n >= 0.0 && n < horizon_cycles) => {
                bad.push(Problem::given(Arg::FutureFromCycles, n.to_string(), range))
            }
            Some(_) => {}
        }
        match (spectrum, self.from_cycles) {
            (Some(spectrum), Some(from_cycles)) if bad.is_empty() => Ok(Some(FutureDuty {
                from_cycles,
                spectrum,
            })),
            _ => Err(JobError::Input(bad)),
        }
    }
}
