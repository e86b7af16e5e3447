//! What the studies keep on disk, above the models it stores: wear-study checkpoints and
//! their verified resume, the run metadata stamped on every summary, and the readers of
//! input files that carry a domain meaning (a measured transmission error, a transfer
//! path, the tables of sweep shards). The file mechanics under it (bounded reads, output
//! folders, tables) are in `io`.

pub mod checkpoint;
pub mod checkpoint_set;
pub mod metadata;
pub(crate) mod part_logs;
pub mod sweep_inputs;
pub(crate) mod transfer_path;
pub mod transmission_error;

pub use metadata::RunMetadata;
