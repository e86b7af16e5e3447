//! Duty cycles (issue 20): wear and life under a load spectrum, and the spectrum of a
//! measured load-time history.
//!
//! Pieces, data flowing down: the `[load_spectrum]` of a case (`config::operating`,
//! validated before anything is computed) -> [`model`] (one model per bin, built from the
//! case at the bin's operating point) -> [`wear`] (the wear loop advancing every bin at
//! every update, and its quasi-static twin) -> [`contribution`] (what each bin wore, the
//! ranking, the dynamic factor per bin, the one-run view the single-point readers take)
//! and [`life`] (cycles to a wear limit under the spectrum and at each bin alone);
//! [`study`] puts them together as the `wear` and `run` jobs use them.
//! [`history`] reads a measured time series of torque and speed and [`ldd`] turns it into
//! a load duration distribution (time at level, ISO 6336-6) and a spectrum.
//! A gear train under a spectrum is [`train`] ([`train_life`], [`train_resume`]); a
//! planetary set under one [`planetary`] ([`planetary_life`], [`planetary_resume`]).
//! docs/MODEL.md, section 10 (10.1 the train; 12.12 the set) states the method and its
//! checks.

pub mod contribution;
pub mod history;
pub mod ldd;
pub mod life;
pub mod model;
pub mod planetary;
pub mod planetary_life;
pub mod planetary_resume;
pub(crate) mod resume;
pub mod study;
pub mod train;
pub mod train_life;
pub mod train_resume;
pub(crate) mod verify;
pub mod wear;

pub use model::SpectrumModel;
pub use wear::{run_spectrum_wear, SpectrumRecord, SpectrumRun};
