//! The thread pool the studies of Python calls run on.
//!
//! Built by `gearwear::io::runtime::thread_pool` (fewer threads when the system refuses
//! them, never a panic), not rayon's global pool. When a call returns before its study
//! has ended (Ctrl-C during one long evaluation, or during a sweep whose cases in flight
//! run to their end), that pool is left to finish the abandoned work on its own and the
//! next call gets a fresh pool, so it does not wait seconds behind work whose result
//! nobody will read.

use std::sync::{Arc, Mutex};

static POOL: Mutex<Option<Arc<rayon::ThreadPool>>> = Mutex::new(None);

/// The pool to run a study on (built on first use, or after [`abandon`]).
pub fn current() -> Result<Arc<rayon::ThreadPool>, String> {
    let mut g = POOL
        .lock()
        .map_err(|_| "the thread pool's lock is poisoned".to_string())?;
    if let Some(p) = g.as_ref() {
        return Ok(p.clone());
    }
    let (pool, _note) = gearwear::io::runtime::thread_pool().map_err(|e| e.to_string())?;
    let p = Arc::new(pool);
    *g = Some(p.clone());
    Ok(p)
}

/// The current pool still runs work nobody waits for: the next call builds a new one
/// (the old one ends its threads once its work is done and its last handle dropped).
pub fn abandon() {
    if let Ok(mut g) = POOL.lock() {
        *g = None;
    }
}
