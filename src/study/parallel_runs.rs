//! Several wear runs side by side (a study and its quasi-static twin): each on its own
//! thread, stopped together when one fails (`study::wear_loop::run_wear_modes` and the
//! train's and planetary set's jobs).

/// Marks a run stopped because a sibling run of [`run_in_parallel`] failed.
#[derive(Debug, thiserror::Error)]
#[error("stopped because a parallel wear run failed")]
pub struct SiblingFailed;

/// Runs one wear run `R` from its start to its end, calling its argument after every
/// update.
pub type RunOne<'a, R> =
    dyn Fn(R, &mut dyn FnMut(&R) -> anyhow::Result<()>) -> anyhow::Result<R> + Sync + 'a;

/// Run (or continue) several wear runs `R` in parallel (a single pair's, a train's, a
/// planetary set's; e.g. the dynamic study and its quasi-static twin): `mode_of` names a
/// run's mode `M`, `one(start, on_update)` runs one to its end, `on_update(mode, run)`
/// after every update of each. Results in the order of `starts`. When one run fails, the
/// others stop at their next update, so the failure is reported at once rather than after
/// the slower run has finished; the error returned is the first run's own, not a
/// sibling's stop.
pub fn run_in_parallel<R: Send, M: Copy>(
    starts: Vec<R>,
    mode_of: fn(&R) -> M,
    one: &RunOne<'_, R>,
    on_update: &(dyn Fn(M, &R) -> anyhow::Result<()> + Sync),
) -> anyhow::Result<Vec<R>> {
    use rayon::prelude::*;
    use std::sync::atomic::{AtomicBool, Ordering};
    let failed = AtomicBool::new(false);
    let results: Vec<anyhow::Result<R>> = starts
        .into_par_iter()
        .map(|start| {
            let mode = mode_of(&start);
            let r = one(start, &mut |r| {
                if failed.load(Ordering::Relaxed) {
                    return Err(SiblingFailed.into());
                }
                on_update(mode, r)
            });
            if r.is_err() {
                failed.store(true, Ordering::Relaxed);
            }
            r
        })
        .collect();
    let (ok, errors): (Vec<_>, Vec<_>) = results.into_iter().partition(Result::is_ok);
    let mut errors = errors.into_iter().filter_map(Result::err);
    if let Some(first) = errors.next() {
        return Err(if first.is::<SiblingFailed>() {
            errors.find(|e| !e.is::<SiblingFailed>()).unwrap_or(first)
        } else {
            first
        });
    }
    Ok(ok.into_iter().filter_map(Result::ok).collect())
}
