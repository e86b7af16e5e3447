//! Running a study from Python: on a thread of rayon's pool with the GIL released, while the
//! calling thread waits, calls the progress callback and watches for Ctrl-C.
//!
//! Why a thread: Python runs signal handlers (KeyboardInterrupt) only on its main thread,
//! and only when that thread checks for them; the study's own updates happen on rayon's
//! threads. So the caller waits in short slices (`POLL`), checks for signals between
//! them, and calls the progress callable itself (Python code only ever runs on the
//! calling thread). On Ctrl-C it sets the stop flag, which the study's per-update callback
//! turns into an error that ends the study at its next update; it waits up to `GRACE` for
//! that, then raises KeyboardInterrupt. A single evaluation has no update to stop at: if
//! it is still running after `GRACE`, the caller returns all the same and the evaluation
//! finishes in the background, its result dropped.

use crate::errors::{Failure, Interrupt};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{channel, Receiver, RecvTimeoutError, Sender};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Longest wait between two checks for Ctrl-C.
const POLL: Duration = Duration::from_millis(20);
/// How long an interrupted study gets to stop before control returns anyway.
const GRACE: Duration = Duration::from_millis(500);

enum Msg<T> {
    Progress(&'static str, f64, f64),
    Done(Result<T, Failure>),
}

/// What the study's thread holds: where to send progress, and whether to stop.
pub struct Ctx<T> {
    tx: Sender<Msg<T>>,
    stop: Arc<AtomicBool>,
    progress: bool,
}

impl<T> Ctx<T> {
    /// Whether the study was told to stop.
    pub fn stopped(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
    }

    /// After each update: report progress (`what`, done, total) and stop the study (an
    /// [`Interrupt`] error) once told to.
    pub fn update(&self, what: &'static str, done: f64, total: f64) -> anyhow::Result<()> {
        if self.stopped() {
            return Err(Interrupt.into());
        }
        if self.progress {
            // The receiver is gone only when the caller has returned: nothing to report to.
            let _ = self.tx.send(Msg::Progress(what, done, total));
        }
        Ok(())
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

/// Tell the study to stop and give it `GRACE` to do so; if it has not ended by then, its
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
/// is called as `progress(what, done, total)` on the calling thread.
pub fn run_study<T, F>(py: Python<'_>, progress: Option<Bound<'_, PyAny>>, job: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce(&Ctx<T>) -> Result<T, Failure> + Send + 'static,
{
    let (tx, mut rx) = channel();
    let stop = Arc::new(AtomicBool::new(false));
    let ctx = Ctx {
        tx,
        stop: stop.clone(),
        progress: progress.is_some(),
    };
    // On rayon's pool rather than a new thread: spawning one per call cost ~0.1-0.2 ms,
    // 5-10 % of a dynamics call. A panic is caught here (rayon would abort the process)
    // and becomes an error of the call.
    let pool = crate::pool::current().map_err(PyRuntimeError::new_err)?;
    pool.spawn(move || {
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| job(&ctx)))
            .unwrap_or_else(|_| {
                Err(Failure::Failed(anyhow::anyhow!(
                    "the study panicked (a bug: please report it)"
                )))
            });
        let _ = ctx.tx.send(Msg::Done(r));
    });
    loop {
        let (got, back) = recv(py, rx, POLL);
        rx = back;
        match got {
            Ok(Msg::Done(r)) => return r.map_err(|f| f.into_pyerr(py)),
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
