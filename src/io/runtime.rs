//! Process limits met at start: the thread pool and the file-size limit.
//!
//! - **Threads.** Rayon's global pool is built here, once, with the number of threads
//!   asked for (`RAYON_NUM_THREADS`, else one per core), at most [`MAX_THREADS_PER_CORE`]
//!   per core; when the system refuses threads (a process-count limit, `ulimit -u`), it is
//!   built with half as many, down to one. Rayon's own lazy build would panic instead
//!   ("the global thread pool has not been initialized").
//! - **File size.** Exceeding `ulimit -f` sends SIGXFSZ, whose default action kills the
//!   process without a word. The signal is caught (and otherwise ignored), so the write
//!   fails with EFBIG instead, and the error names the file.

/// Most threads per core: gearwear's parallel work is CPU-bound, so threads beyond the
/// cores only add memory (a model per case in flight) and contention.
pub const MAX_THREADS_PER_CORE: usize = 8;

/// Build rayon's global pool (see the module docs). Returns a note for the user when the
/// pool has fewer threads than asked, or when `RAYON_NUM_THREADS` was not understood.
/// Harmless when the pool exists already (a second call, or another library). An error
/// when not even one thread can be started.
pub fn init_threads() -> Result<Option<String>, String> {
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
                    crate::config::load::clip(&v, 40)
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
    let refused = |asked: usize, n: usize| {
        format!("the system refused {asked} threads (a limit on processes?): running on {n}")
    };
    loop {
        match rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global()
        {
            Ok(()) => break,
            // No source: the pool exists already (built before, or by another library).
            Err(e) if std::error::Error::source(&e).is_none() => break,
            Err(e) if n == 1 => {
                return Err(format!(
                    "no thread could be started ({e}): raise the limit on processes (ulimit -u)"
                ))
            }
            Err(_) => {
                n /= 2;
                notes.retain(|l| !l.starts_with("the system refused"));
                notes.push(refused(asked, n));
            }
        }
    }
    Ok((!notes.is_empty()).then(|| notes.join("; ")))
}

/// Catch SIGXFSZ so that exceeding the file-size limit is an EFBIG error naming the file
/// rather than a silent kill (see the module docs).
pub fn catch_file_size_signal() {
    let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let _ = signal_hook::flag::register(signal_hook::consts::SIGXFSZ, flag);
}
