//! File mechanics, the ground floor: output folders published as one set under gearwear's
//! own record of what it wrote (never following, truncating or deleting anything else),
//! inputs read only from regular files of bounded size, CSV and Parquet tables, locks,
//! and the process's streams and limits. Nothing here knows a gear: it imports only the
//! other ground modules (`format`, `remedy`, `checksum`). What the studies store
//! (checkpoints, run metadata, input files of a domain meaning) is in `store`.

pub mod columns_csv;
pub mod console;
pub mod dir;
pub mod error;
pub mod input;
pub mod lock;
pub mod output_dir;
pub mod parquet;
pub mod runtime;
pub mod set_state;
pub mod table;

pub use crate::format::format_number;
pub use error::OutputError;
pub use input::{read_input, read_input_text, InputError};
pub use output_dir::{Manifest, OtherSet, OutputDir};
pub use table::Table;
