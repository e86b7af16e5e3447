//! The dataset jobs: a study design to a folder of labelled records ([`folder`] for the
//! layout), sharded, resumable, streamed to disk ([`DatasetJob`]); and the merge of shards
//! ([`DatasetMergeJob`]).
//!
//! Steps: check the design against the signal chain and the disk budget (before any
//! work); run the trajectories the shard needs (kept in `state/`, reused when present);
//! compute the shard's physical states in parallel, each writing its records as soon as
//! they are made (never all records in memory); then, for an unsharded run, build the
//! index and metadata from the files. A finished record (its sidecar present, under the
//! same dataset key, with its signal file intact) is not computed again.
//!
//! Files: [`request`] (what a step is given and gives back), [`plan`] (the design checked
//! against the chain and the disk budget, its key and description), [`run`] (trajectories
//! and physical states computed and written), [`merge`] (shards joined), [`folder`] (the
//! files of a dataset folder), [`jobs`] (the two jobs).

pub mod claim;
pub mod folder;
pub mod index_files;
pub mod jobs;
mod kept;
mod label_check;
pub mod merge;
pub mod merge_verify;
pub mod plan;
mod plan_planetary;
pub mod request;
pub mod run;
pub mod state_files;
pub mod verify;

pub use jobs::{DatasetJob, DatasetMergeJob, DesignSource};
