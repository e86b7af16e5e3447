//! A run-to-failure trajectory: the dynamic wear loop of a condition's case, run until
//! the deepest wear reaches the limit (failure) or to the largest cycle count asked for,
//! and the wear state at any cycle count along it.
//!
//! Between two updates the loop holds the per-cycle wear of the earlier one (paper eq.
//! 17), so the state at c cycles is the earlier record advanced by its increment for
//! the cycles since: exactly what the loop itself would have reached at c. The failure
//! cycle count is where the deepest wear (pinion or gear profile) reaches the limit,
//! found the same way (linear within the block). A run that stops before (at the edge
//! of the model's domain, or at the largest cycle count) leaves the failure unobserved:
//! its remaining life is right-censored at the trajectory's end.

use crate::study::wear_loop::{run_wear, UpdateRecord, WearMode, WearRun};
use crate::study::Model;
use crate::wear::{WearIncrement, WearState};
use serde::{Deserialize, Serialize};

/// The updates of a trajectory and where it ended.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Trajectory {
    /// The wear run's updates, in order of cycles.
    pub records: Vec<UpdateRecord>,
    /// Cycle count at which the deepest wear reached the limit, if it did.
    pub failure_cycles: Option<f64>,
    /// Last cycle count the trajectory covers.
    pub end_cycles: f64,
    /// Why the wear loop stopped before `end_cycles` asked for, if it did.
    pub stopped: Option<String>,
}

/// Deepest wear of a state (pinion or gear), m.
pub fn deepest_m(w: &WearState) -> f64 {
    w.max_pinion_m().max(w.max_gear_m())
}

/// The per-cycle wear the loop held after update `r` (every tooth's own with a
/// tooth-resolved mesh, so that a state between updates advances each tooth).
fn increment(r: &UpdateRecord) -> WearIncrement {
    WearIncrement {
        pinion_m: r.increment_pinion_m.clone(),
        gear_m: r.increment_gear_m.clone(),
        teeth: r.increment_teeth.clone(),
        ..Default::default()
    }
}

/// Marks the early stop of a run at the wear limit (not an error).
#[derive(Debug, thiserror::Error)]
#[error("the wear limit was reached")]
struct LimitReached;

/// The model a condition's trajectory runs: its case with `wear.total_cycles` set to
/// the design's `max_cycles` (warnings dropped: the dataset reports its own).
pub fn trajectory_model(model: &Model, max_cycles: f64) -> anyhow::Result<Model> {
    let mut m2 = Model::from_case(&{
        let mut c = model.case.clone();
        c.wear.total_cycles = max_cycles;
        c
    })
    .map_err(|e| anyhow::anyhow!("{e}"))?;
    m2.warnings.clear();
    Ok(m2)
}

/// Run the trajectory of `model` (its case at its operating point) up to `max_cycles`
/// or until the deepest wear reaches `limit_m`.
pub fn run_trajectory(model: &Model, max_cycles: f64, limit_m: f64) -> anyhow::Result<Trajectory> {
    let m2 = trajectory_model(model, max_cycles)?;
    let mut last = WearRun::new(WearMode::Dynamic);
    let result = run_wear(&m2, WearRun::new(WearMode::Dynamic), &mut |r| {
        last = r.clone();
        match r.last() {
            Some(rec) if deepest_m(&rec.wear) >= limit_m => Err(LimitReached.into()),
            _ => Ok(()),
        }
    });
    let run = match result {
        Ok(run) => run,
        Err(e) if e.is::<LimitReached>() => last,
        Err(e) => return Err(e),
    };
    Ok(Trajectory::from_records(
        run.records,
        run.stopped.map(|s| s.reason),
        limit_m,
    ))
}

impl Trajectory {
    /// The trajectory of the wear loop's `records` (and why it stopped early, if it did)
    /// under the wear limit `limit_m`: its end and failure cycles derived from the
    /// records (so a kept trajectory's derived fields can be checked by deriving them
    /// again, `super::verify`).
    pub fn from_records(records: Vec<UpdateRecord>, stopped: Option<String>, limit_m: f64) -> Self {
        let end = records.last().map_or(0.0, |r| r.wear.cycles);
        // Failure inside the last block: where the deepest wear crossed the limit.
        let failure_cycles = records.windows(2).find_map(|w| {
            let (a, b) = (deepest_m(&w[0].wear), deepest_m(&w[1].wear));
            (a < limit_m && b >= limit_m).then(|| {
                // Per point the wear is linear in cycles within the block; the deepest point
                // may change inside it, so bisect on the state itself.
                let (mut lo, mut hi) = (w[0].wear.cycles, w[1].wear.cycles);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    let mut s = w[0].wear.clone();
                    s.advance(&increment(&w[0]), mid - w[0].wear.cycles);
                    if deepest_m(&s) >= limit_m {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                hi
            })
        });
        let failure_cycles = failure_cycles.or_else(|| {
            records
                .first()
                .and_then(|r| (deepest_m(&r.wear) >= limit_m).then_some(0.0))
        });
        Trajectory {
            stopped,
            end_cycles: end,
            failure_cycles,
            records,
        }
    }

    /// The wear state at `cycles` (at most the trajectory's end; see the module docs).
    pub fn state_at(&self, cycles: f64) -> Option<WearState> {
        if cycles > self.end_cycles * (1.0 + 1e-12) || self.records.is_empty() {
            return None;
        }
        let i = self
            .records
            .partition_point(|r| r.wear.cycles <= cycles)
            .saturating_sub(1);
        let r = &self.records[i];
        let mut s = r.wear.clone();
        let extra = cycles - r.wear.cycles;
        if extra > 0.0 {
            s.advance(&increment(r), extra);
        }
        Some(s)
    }

    /// The cycle counts of `count` states evenly spaced from 0 to the trajectory's end
    /// (to the failure, when it was reached).
    pub fn even_states(&self, count: usize) -> Vec<f64> {
        let end = self
            .failure_cycles
            .unwrap_or(self.end_cycles)
            .min(self.end_cycles);
        if count <= 1 {
            return vec![0.0];
        }
        (0..count)
            .map(|i| (end * i as f64 / (count - 1) as f64).round())
            .collect()
    }

    /// Remaining cycles to failure from `cycles`, and whether that is censored (the
    /// failure not reached: the remaining cycles to the trajectory's end, a lower bound).
    pub fn remaining(&self, cycles: f64) -> (f64, bool) {
        match self.failure_cycles {
            Some(f) => ((f - cycles).max(0.0), false),
            None => ((self.end_cycles - cycles).max(0.0), true),
        }
    }
}
