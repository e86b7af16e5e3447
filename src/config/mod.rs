//! The case file: schema, defaults (the paper's case), loading and validation.

pub mod case;
pub mod derivable;
mod docs;
pub mod load;
pub mod load_spectrum;
pub mod problem;
pub mod schema;
pub mod signals;
pub mod teeth;
pub mod train;

pub use case::Case;
pub use docs::{commented_template, markdown_reference, new_pair_template};
pub use load::{load_case, load_case_in, load_spectrum_section, ConfigError};
pub use load_spectrum::{LoadSpectrumSection, SpectrumBin};
pub use problem::Problem;
