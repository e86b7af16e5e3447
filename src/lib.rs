#![warn(missing_docs)]
//! gearwear: dynamic wear prediction of spur gears.
//!
//! Implements the model of "A Dynamic Wear Prediction Model for Studying the Interactions
//! between Surface Wear and Dynamic Response of Spur Gears", Coatings 2022, 12(9), 1250,
//! with the corrections listed in `docs/MODEL.md`.
//!
//! Layers, each depending only on those before it (the table of docs/ARCHITECTURE.md,
//! checked by `tests/layers.rs`): the ground (`format`, `checksum`, `remedy`, `rng`, and
//! `io`, the file mechanics) -> `config` -> `geometry` -> `stiffness` -> `contact` ->
//! `dynamics` -> `wear` -> `signals` -> `study` -> `duty` -> `prognostics` -> `store`
//! (checkpoints, run metadata) -> `report` -> `app` (one job per study). The front ends sit on top: the command
//! line (`cli`, behind the default feature `cli`: the `gearwear` binary, and the console
//! script the Python wheel installs) and the Python binding (`python/`).

pub mod app;
pub mod checksum;
#[cfg(feature = "cli")]
pub mod cli;
pub mod config;
pub mod contact;
pub mod duty;
pub mod dynamics;
pub mod format;
pub mod geometry;
pub mod io;
pub mod prognostics;
pub mod remedy;
pub mod report;
pub mod rng;
pub mod signals;
pub mod stiffness;
pub mod store;
pub mod study;
pub mod wear;
