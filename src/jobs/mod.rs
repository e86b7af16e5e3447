//! Jobs of the signal studies: the orchestration of a dataset (and its merge) below the
//! front ends, which only parse arguments, attach a progress observer and print. Written
//! to move into the application layer (`src/app/`) as it lands.

pub mod dataset;
pub mod dataset_dir;

/// What a job tells its caller while it runs (progress bars, warnings); `()` ignores it.
pub trait Progress: Sync {
    fn progress(&self, _done: u64, _total: u64) {}
    fn warning(&self, _message: &str) {}
}

impl Progress for () {}
