//! Running a job from Python: on a thread of a pool of its own (`pool`: built with fewer
//! threads when the system refuses them, replaced after an interrupted call) with the GIL
//! released, while the calling thread waits, calls the progress callback and watches for
//! Ctrl-C.
//!
//! Why a thread: Python runs signal handlers (KeyboardInterrupt) only on its main thread,
//! and only when that thread checks for them; the job's own updates happen on the
//! pool's threads. So the caller waits in short slices (`POLL`), checks for signals between
//! them, and calls the progress callable itself (Python code only ever runs on the
//! calling thread). The job's observer ([`Ctx`]) sends progress here, keeps its warnings,
//! and tells the job to stop once asked: on Ctrl-C the caller sets the stop flag, which
//! the job sees at its next update (`Observer::cancelled`); it waits up to `GRACE` for
//! that, then raises KeyboardInterrupt. A single evaluation has no update to stop at: if
//! it is still running after `GRACE`, the caller returns all the same and the evaluation
//! finishes in the background, its result dropped.

use crate::errors::job_error;
use gearwear::app::{Job, JobError, Observer, Task};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{channel, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Jobs running now, including those whose caller has returned (an interrupted single
/// evaluation finishing in the background).
static RUNNING: AtomicUsize = AtomicUsize::new(0);

/// Number of jobs still running on the pool (see [`RUNNING`]).
#[pyfunction]
pub fn _running_jobs() -> usize {
    RUNNING.load(Ordering::Relaxed)
}

/// Longest wait between two checks for Ctrl-C.
const POLL: Duration = Duration::from_millis(20);
/// How long an interrupted job gets to stop before control returns anyway.
const GRACE: Duration = Duration::from_millis(500);

enum Msg<T> {
    Progress(&'static str, f64, f64),
    Done(Result<T, JobError>),
}

/// The job's observer: where to send progress, the warnings, and whether to stop.
struct Ctx<T> {
    tx: Mutex<Sender<Msg<T>>>,
    stop: Arc<AtomicBool>,
    progress: bool,
    warnings: Mutex<Vec<String>>,
}

impl<T: Send> Observer for Ctx<T> {
    fn advance(&self, task: &Task, done: f64, _status: &str) {
        if self.progress {
            if let Ok(tx) = self.tx.lock() {
                // The receiver is gone only when the caller has returned: nothing to report to.
                let _ = tx.send(Msg::Progress(task.id, done, task.total));
            }
        }
    }

    fn warning(&self, text: &str) {
        if let Ok(mut w) = self.warnings.lock() {
            w.push(text.to_owned());
        }
    }

    fn cancelled(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
    }
}

/// Receive with the GIL released (the receiver moves into the closure and back, as a
/// `&Receiver` may not cross threads).
fn recv<T: Send>(
    py: Python<'_>,
    rx: Receiver<Msg<T>>,
    wait: Duration,
) -> (Result<Msg<T>, RecvTimeoutError>, Receiver<Msg<T>>) {
    py.detach(move || (rx.recv_timeout(wait), rx))
}

/// Tell the job to stop and give it `GRACE` to do so; if it has not ended by then, its
/// pool is abandoned to it (`pool::abandon`), so the next call does not wait behind it.
fn stop_and_wait<T: Send>(py: Python<'_>, stop: &AtomicBool, mut rx: Receiver<Msg<T>>) {
    stop.store(true, Ordering::Relaxed);
    let deadline = Instant::now() + GRACE;
    while let Some(left) = deadline.checked_duration_since(Instant::now()) {
        let (got, back) = recv(py, rx, left);
        rx = back;
        match got {
            Ok(Msg::Progress(..)) => continue,
            Ok(Msg::Done(_)) | Err(RecvTimeoutError::Disconnected) => return,
            Err(RecvTimeoutError::Timeout) => break,
        }
    }
    crate::pool::abandon();
}

/// Run `job` on its own thread with the GIL released (see the module docs); `progress`
/// is called as `progress(task, done, total)` on the calling thread. Returns the job's
/// output and its warnings.
pub fn run_job<J: Job + 'static>(
    py: Python<'_>,
    job: J,
    progress: Option<Bound<'_, PyAny>>,
) -> PyResult<(J::Output, Vec<String>)> {
    let (tx, mut rx) = channel::<Msg<(J::Output, Vec<String>)>>();
    let stop = Arc::new(AtomicBool::new(false));
    let ctx = Ctx {
        tx: Mutex::new(tx),
        stop: stop.clone(),
        progress: progress.is_some(),
        warnings: Mutex::new(Vec::new()),
    };
    // On a pool (`pool`) rather than a new thread: spawning one per call cost ~0.1-0.2 ms,
    // 5-10 % of a dynamics call. A panic is caught here (rayon would abort the process)
    // and becomes an error of the call.
    let pool = crate::pool::current().map_err(PyRuntimeError::new_err)?;
    RUNNING.fetch_add(1, Ordering::Relaxed);
    pool.spawn(move || {
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| job.run(&ctx)))
            .unwrap_or_else(|_| {
                Err(JobError::Failed(anyhow::anyhow!(
                    "the study panicked (a bug: please report it)"
                )))
            });
        let warnings = ctx.warnings.lock().map(|w| w.clone()).unwrap_or_default();
        if let Ok(tx) = ctx.tx.lock() {
            let _ = tx.send(Msg::Done(r.map(|o| (o, warnings))));
        }
        RUNNING.fetch_sub(1, Ordering::Relaxed);
    });
    loop {
        let (got, back) = recv(py, rx, POLL);
        rx = back;
        match got {
            Ok(Msg::Done(r)) => return r.map_err(|e| job_error(py, e)),
            Ok(Msg::Progress(what, done, total)) => {
                if let Some(cb) = &progress {
                    if let Err(e) = cb.call1((what, done, total)) {
                        stop_and_wait(py, &stop, rx);
                        return Err(e);
                    }
                }
            }
            Err(RecvTimeoutError::Timeout) => {}
            Err(RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err(
                    "the study's thread ended without a result (a bug: please report it)",
                ))
            }
        }
        if let Err(e) = py.check_signals() {
            stop_and_wait(py, &stop, rx);
            return Err(e);
        }
    }
}
