//! A dataset's kept files checked by recomputation (docs/RELIABILITY.md, "Datasets"):
//! a run-to-failure trajectory against the wear law that made it, and which physical
//! states of a folder are recomputed bit for bit, with the chance that the sample finds
//! a forged one.
//!
//! Checksums cannot stop someone who recomputes them; recomputation can. A trajectory's
//! updates are recomputed from the update before each (`study::wear_check`, the same
//! check as a wear checkpoint's: monotone, finite, non-negative wear, each profile the
//! previous one advanced by its Archard increment at the recorded load and cycles), its
//! end recomputed (the loop must stop where the trajectory stops), and its failure and
//! end cycles derived again from the updates. Records are too many to recompute on every
//! resume: the first and last physical state and a random sample of the others are.
//!
//! A train's trajectory (`super::trajectory`) is checked as a train's wear checkpoints
//! are (`study::train_wear_check`): its meshes' records replayed block by block (each
//! mesh's wear the previous update's advanced by the loop's own step), a sample of its
//! updates recomputed with the whole train's response, its end recomputed, its cycle
//! factors the model's, its failure derived again from every mesh.

use super::trajectory::{deepest_m, trajectory_model, Trajectory};
use crate::study::train_wear::{next_train_update, TrainNext};
use crate::study::train_wear_check::{train_run_from_logs, verify_train_resumable, TrainRunError};
use crate::study::wear_check::{verify_resumable, StoredRunError};
use crate::study::wear_loop::{next_update, Next, WearMode, WearRun};
use crate::study::Model;

/// Most physical states recomputed when a dataset is resumed or verified (the first, the
/// last, and a random sample of the others).
pub const MAX_RECOMPUTED_STATES: usize = 8;

/// Which of `n` physical states to recompute: all of at most `k`, else the first, the
/// last and `k - 2` others drawn uniformly without replacement by a SplitMix64 stream of
/// `seed` (the job seeds it from the operating system, so a forger cannot know it).
/// Ascending.
pub fn states_to_recompute(n: usize, k: usize, seed: u64) -> Vec<usize> {
    if n <= k {
        return (0..n).collect();
    }
    let mut picked: std::collections::BTreeSet<usize> = [0, n - 1].into_iter().collect();
    let mut z = seed;
    // (At most `n`: a single state with a sample of 0 or 1 is the first and the last;
    // the draw below would wrap past `n - 2`.)
    while picked.len() < k.max(2).min(n) {
        z = z.wrapping_add(1);
        // Modulo bias is below n / 2^64 (n is at most 2^53).
        picked.insert(1 + (super::plan::splitmix64(z) % (n as u64 - 2)) as usize);
    }
    picked.into_iter().collect()
}

/// How many states [`states_to_recompute`] returns for `n` states and a sample of `k`:
/// all `n` when `n <= k`, else the first and the last and `k - 2` others, so never fewer
/// than two of them (a sample of 0 or 1 still recomputes the first and the last).
pub fn recomputed_count(n: usize, k: usize) -> usize {
    n.min(k.max(2))
}

/// Probability that [`states_to_recompute`] with `k` of `n` states recomputes at least one
/// of `m` forged states lying among the `n - 2` others (the first and last are always
/// recomputed): one minus the chance that all `k - 2` drawn states are genuine,
/// hypergeometric: `1 - C(n-2-m, k-2) / C(n-2, k-2)` = `1 - prod_{i<k-2} (n-2-m-i) /
/// (n-2-i)`; 1 when `n <= k` (every state recomputed), 0 when `m` is 0.
pub fn detection_probability(n: usize, m: usize, k: usize) -> f64 {
    if m == 0 {
        return 0.0;
    }
    if n <= k {
        return 1.0;
    }
    let (others, draws) = ((n - 2) as f64, k.saturating_sub(2));
    let mut miss = 1.0;
    for i in 0..draws {
        let i = i as f64;
        miss *= ((others - m as f64 - i) / (others - i)).max(0.0);
    }
    1.0 - miss
}

/// Check the kept trajectory `t` of a condition whose case gives `model` (at the case's
/// own operating point) against the wear law (module docs): under `max_cycles` and the
/// wear limit `limit_m`, the trajectory the dataset job would run. The error says what
/// differs.
pub fn verify_trajectory(
    model: &Model,
    max_cycles: f64,
    limit_m: f64,
    t: &Trajectory,
) -> Result<(), StoredRunError> {
    let m2 =
        trajectory_model(model, max_cycles).map_err(|e| StoredRunError::Model(e.to_string()))?;
    if m2.train.is_some() {
        return verify_train_trajectory(&m2, limit_m, t);
    }
    if !t.later_stages.is_empty() || !t.cycle_factors.is_empty() {
        return Err(StoredRunError::Mismatch(
            "it holds a train's stages, but the condition's case is a single pair".into(),
        ));
    }
    let mut run = WearRun::new(WearMode::Dynamic);
    run.records = t.records.clone();
    verify_resumable(&run, &m2).map_err(|e| e.lines_named("record line "))?;
    let n = t.records.len();
    if let Some(i) = t.records[..n - 1]
        .iter()
        .position(|r| deepest_m(&r.wear) >= limit_m)
    {
        return Err(goes_on(i));
    }
    let last = &t.records[n - 1];
    let stopped = if deepest_m(&last.wear) >= limit_m {
        None
    } else {
        match next_update(&m2, WearMode::Dynamic, Some(last)) {
            Ok(Next::Finished) => None,
            Ok(Next::Stop(s)) => Some(s.reason),
            Ok(Next::Record(_)) | Err(_) => return Err(cut_short(last.wear.cycles, max_cycles)),
        }
    };
    let again = Trajectory::from_records(t.records.clone(), stopped, limit_m);
    same_end(t, &again)
}

/// Update `i` reaches the limit though the trajectory goes on.
fn goes_on(i: usize) -> StoredRunError {
    StoredRunError::Mismatch(format!(
        "update {i} already reaches the wear limit, yet the trajectory goes on: the run stops there"
    ))
}

/// A trajectory ending at `cycles`, where the wear loop goes on.
fn cut_short(cycles: f64, max_cycles: f64) -> StoredRunError {
    StoredRunError::Mismatch(format!(
        "it ends at {cycles} cycles, below the wear limit and before `run_to_failure.max_cycles` = {max_cycles}, where the wear loop goes on: cut short"
    ))
}

/// The kept trajectory `t` against `again`, derived from its updates.
fn same_end(t: &Trajectory, again: &Trajectory) -> Result<(), StoredRunError> {
    if again != t {
        return Err(StoredRunError::Mismatch(format!(
            "its end ({} cycles, failure {:?}, stopped {:?}) is not what its updates give ({} cycles, failure {:?}, stopped {:?})",
            t.end_cycles, t.failure_cycles, t.stopped.is_some(), again.end_cycles, again.failure_cycles, again.stopped.is_some()
        )));
    }
    Ok(())
}

/// A train run's error in a trajectory's words: its updates per stage (`records` and
/// `later_stages`), not a checkpoint's mesh logs and lines.
fn in_trajectory(e: TrainRunError) -> String {
    match e {
        TrainRunError::StageCount { logs, stages } => format!(
            "it holds the updates of {logs} stages (`records` and `later_stages`) for a train of {stages} stages"
        ),
        TrainRunError::Update {
            update,
            stage,
            problem,
            ..
        } => format!(
            "update {update}{}: {problem}",
            stage.map_or(String::new(), |s| format!(", stage {s}"))
        ),
    }
}

/// [`verify_trajectory`] of a train's trajectory, `m2` the trajectory's model (module
/// docs).
fn verify_train_trajectory(m2: &Model, limit_m: f64, t: &Trajectory) -> Result<(), StoredRunError> {
    let Some(train) = m2.train.as_ref() else {
        return Err(StoredRunError::Model("not a train".into()));
    };
    let mismatch = |m: String| StoredRunError::Mismatch(m);
    let n = t.records.len();
    if n == 0 {
        return Err(mismatch("holds no update".into()));
    }
    let logs = t.mesh_logs();
    if logs.iter().any(|l| l.records.len() != n) {
        return Err(mismatch(
            "its stages hold different numbers of updates".into(),
        ));
    }
    let run = train_run_from_logs(m2, train, WearMode::Dynamic, &logs)
        .map_err(|e| mismatch(in_trajectory(e)))?;
    verify_train_resumable(m2, train, &run).map_err(|e| mismatch(in_trajectory(e)))?;
    let factors = train.cycle_factors();
    if t.cycle_factors != factors {
        return Err(mismatch(format!(
            "its stages' pinion turns per input turn (`cycle_factors` {:?}) are not the train's ({factors:?})",
            t.cycle_factors
        )));
    }
    let deepest = |i: usize| {
        run.updates[i]
            .meshes
            .iter()
            .map(|r| deepest_m(&r.wear))
            .fold(0.0, f64::max)
    };
    if let Some(i) = (0..n - 1).find(|i| deepest(*i) >= limit_m) {
        return Err(goes_on(i));
    }
    let last = &run.updates[n - 1];
    let stopped = if deepest(n - 1) >= limit_m {
        None
    } else {
        match next_train_update(m2, train, WearMode::Dynamic, Some(last)) {
            Ok(TrainNext::Finished) => None,
            Ok(TrainNext::Stop(s)) => Some(s.reason),
            Ok(TrainNext::Update(_)) | Err(_) => {
                return Err(cut_short(last.input_cycles, m2.case.wear.total_cycles))
            }
        }
    };
    let again = Trajectory::from_meshes(
        (t.records.clone(), t.later_stages.clone()),
        factors,
        stopped,
        limit_m,
    );
    same_end(t, &again)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_recomputed_count_is_the_length_of_the_drawn_sample() {
        // Against the sampler itself: every n and k up to 40 and 12, a few seeds.
        for n in 0..40 {
            for k in 0..12 {
                for seed in [0, 1, 99] {
                    assert_eq!(
                        recomputed_count(n, k),
                        states_to_recompute(n, k, seed).len(),
                        "n {n}, k {k}"
                    );
                }
            }
        }
    }
}
