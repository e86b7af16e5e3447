//! Everything a command shows or writes, built from results by pure functions that the
//! command line and the Python binding share: summaries, tables, figures, the HTML report.

pub mod artifacts;
pub mod case;
pub mod comparison;
pub mod dataset_trends;
pub(crate) mod decimate;
pub mod duty;
pub mod duty_figures;
pub mod duty_planetary;
pub mod duty_train;
pub mod dynamics;
pub mod dynamics_helical;
pub mod dynamics_planetary;
pub mod face_load;
pub mod figure_output;
pub mod figures;
pub mod helical_wear;
pub mod html;
pub mod ldd;
pub mod modes;
pub mod pair_load;
pub mod paper;
pub mod plot;
pub mod prognostics;
pub mod prognostics_tables;
pub mod run_planetary;
pub(crate) mod run_planetary_report;
pub mod run_report;
pub mod run_train;
pub(crate) mod run_train_report;
pub mod runup;
pub mod signals;
pub mod signals_planetary;
pub mod stiffness;
pub mod stiffness_helical;
pub mod stiffness_planetary;
pub mod stiffness_train;
pub mod sweep_figure;
pub mod teeth;
pub mod wear;
pub mod wear_planetary;
pub mod wear_planetary_figures;
pub mod wear_train;
pub mod worn_profile;

pub use artifacts::{publish_artifacts, write_artifacts, Artifacts};
