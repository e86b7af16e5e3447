//! Labelled datasets from a study design (docs/SIGNALS.md, "Datasets"): run-to-failure
//! wear trajectories per fault condition, each state recorded at the design's speeds and
//! loads with several noise realisations; every record's channels, tachometer, labels
//! and indicators.

pub mod design;
mod design_checks;
mod design_file;
pub mod index;
pub mod plan;
pub mod planetary;
pub mod planetary_records;
pub mod records;
pub mod trajectory;
pub mod trends;
pub mod verify;

pub(crate) use design::{design_of_cases, Defaults};
pub use design::{parse_design, Condition, DatasetDesign, StateChoice};
pub use plan::{Plan, Shard};
pub use records::RecordLabels;
