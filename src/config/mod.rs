//! The case file: schema, defaults (the paper's case), loading and validation.

pub mod case;
pub mod derivable;
mod docs;
pub mod load;
pub mod problem;
pub mod schema;
pub mod teeth;

pub use case::Case;
pub use docs::{commented_template, markdown_reference, new_pair_template};
pub use load::{load_case, ConfigError};
pub use problem::Problem;
