//! Output: atomic file writes, output folders published as one set, CSV tables, run
//! metadata.

pub mod atomic;
pub mod checkpoint;
pub mod checkpoint_set;
pub mod columns_csv;
pub mod error;
pub mod lock;
pub mod metadata;
pub mod output_dir;
pub mod parquet;
pub mod table;
pub mod transfer_path;
pub mod transmission_error;

pub use crate::format::format_number;
pub use atomic::write_atomic;
pub use error::OutputError;
pub use metadata::RunMetadata;
pub use output_dir::{Manifest, OutputDir};
pub use table::Table;
