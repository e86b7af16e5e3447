//! The case file: schema, defaults (the paper's case), loading and validation.

pub mod case;
pub mod load;
pub mod problem;
pub mod schema;

pub use case::Case;
pub use load::{commented_template, load_case, markdown_reference, ConfigError};
pub use problem::Problem;
