//! Process limits met at start: the thread pool and the file-size limit.
//!
//! - **Threads.** The thread pool is built here with the number of threads asked for
//!   (`RAYON_NUM_THREADS`, else one per core), at most [`MAX_THREADS_PER_CORE`] per core;
//!   when the system refuses threads (a process-count limit, `ulimit -u`), it is built
//!   with half as many, down to one. Rayon's own lazy build of its global pool would
//!   panic instead ("the global thread pool has not been initialized").
//! - **File size.** Exceeding `ulimit -f` sends SIGXFSZ, whose default action kills the
//!   process without a word. The signal is caught (and otherwise ignored), so the write
//!   fails with EFBIG instead, and the error names the file.

/// Most threads per core: gearwear's parallel work is CPU-bound, so threads beyond the
/// cores only add memory (a model per case in flight) and contention.
pub const MAX_THREADS_PER_CORE: usize = 8;

/// Not even one thread could be started (the system's reason).
#[derive(Debug, thiserror::Error)]
#[error("no thread could be started ({0}): raise the limit on processes (ulimit -u)")]
pub struct NoThreadError(pub rayon::ThreadPoolBuildError);

/// Build the thread pool a command runs in (see the module docs): a pool of its own, not
/// rayon's global one, because a failed global build cannot be retried (rayon then
/// panics at the first parallel loop); work run through `ThreadPool::install` or
/// `ThreadPool::spawn` uses this pool for every parallel loop inside. Returns the pool and
/// a note for the user when it has fewer threads than asked, or when `RAYON_NUM_THREADS`
/// was not understood; an error when not even one thread can be started.
pub fn thread_pool() -> Result<(rayon::ThreadPool, Option<String>), NoThreadError> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let cap = cores.saturating_mul(MAX_THREADS_PER_CORE);
    let mut notes = Vec::new();
    let asked = match std::env::var("RAYON_NUM_THREADS") {
        Ok(v) => match v.trim().parse::<usize>() {
            Ok(0) => cores,
            Ok(n) => n,
            Err(_) => {
                notes.push(format!(
                    "RAYON_NUM_THREADS={} is not a whole number: using {cores} threads (one per core)",
                    crate::format::clip(&v, 40)
                ));
                cores
            }
        },
        Err(_) => cores,
    };
    let mut n = asked.min(cap).max(1);
    if n < asked {
        notes.push(format!(
            "RAYON_NUM_THREADS={asked} is more than {MAX_THREADS_PER_CORE} threads for each of the {cores} cores: using {n}"
        ));
    }
    let tried = n;
    loop {
        match rayon::ThreadPoolBuilder::new().num_threads(n).build() {
            Ok(pool) => {
                if n < tried {
                    notes.push(format!(
                        "the system refused {tried} threads (a limit on processes?): running on {n}"
                    ));
                }
                return Ok((pool, (!notes.is_empty()).then(|| notes.join("; "))));
            }
            Err(e) if n == 1 => return Err(NoThreadError(e)),
            Err(_) => {
                // The threads of the failed attempt are ending; they count against the
                // limit until they have.
                std::thread::sleep(std::time::Duration::from_millis(50));
                n /= 2;
            }
        }
    }
}

/// Catch SIGXFSZ so that exceeding the file-size limit is an EFBIG error naming the file
/// rather than a silent kill (see the module docs).
pub fn catch_file_size_signal() {
    let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let _ = signal_hook::flag::register(signal_hook::consts::SIGXFSZ, flag);
}
