//! Output: atomic file writes, CSV tables, run metadata.

pub mod atomic;
pub mod metadata;
pub mod table;

pub use atomic::write_atomic;
pub use metadata::RunMetadata;
pub use table::Table;
