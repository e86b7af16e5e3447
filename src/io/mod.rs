//! Files: output folders published as one set under gearwear's own record of what it
//! wrote (never following, truncating or deleting anything else), inputs read only from
//! regular files of bounded size, checkpoints, CSV tables, run metadata, and the
//! process's streams and limits.

pub mod checkpoint;
pub mod checkpoint_set;
pub mod columns_csv;
pub mod console;
pub mod dir;
pub mod error;
pub mod input;
pub mod lock;
pub mod metadata;
pub mod output_dir;
pub mod parquet;
pub mod runtime;
pub mod set_state;
pub mod sweep_inputs;
pub mod table;
pub mod transfer_path;
pub mod transmission_error;

pub use crate::format::format_number;
pub use error::OutputError;
pub use input::{read_input, read_input_text, InputError};
pub use metadata::RunMetadata;
pub use output_dir::{Manifest, OtherSet, OutputDir};
pub use table::Table;
