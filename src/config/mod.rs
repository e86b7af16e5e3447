//! The case file: schema, defaults (the paper's case), loading and validation.

pub mod case;
pub mod derivable;
mod docs;
pub mod gear;
mod key_spec;
pub mod load;
pub mod load_spectrum;
pub mod lumped;
pub mod operating;
pub mod output;
mod overrides;
pub mod paper_case;
mod parse;
pub mod planetary;
pub mod planetary_fault;
pub mod problem;
pub mod schema;
pub mod signals;
pub mod spectrum_merge;
pub mod teeth;
mod teeth_checks;
pub mod train;

#[cfg(test)]
mod tests_fields;
#[cfg(test)]
mod tests_load;
#[cfg(test)]
mod tests_load_spectrum;
#[cfg(test)]
mod tests_teeth;

pub use case::Case;
pub use docs::{commented_template, markdown_reference, new_pair_template};
pub(crate) use load::load_spectrum_section;
pub use load::{load_case, load_case_in, ConfigError};
pub use operating::{LoadSpectrumSection, SpectrumBin};
pub use problem::Problem;
