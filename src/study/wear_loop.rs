//! The two-way loop of the paper's Figure 3: dynamics -> wear -> gap (transmission
//! error) -> dynamics, and its quasi-static twin.
//!
//! Update scheme (paper eq. 17 and the text around it): the per-cycle wear of the current
//! state is held for a block of m cycles; if the block would add more than the threshold
//! epsilon^m at any point of either profile, it is shortened to the whole number of cycles
//! that adds at most epsilon^m there (at least one cycle); then the gap, the roughness and the response are renewed. The loop
//! runs to the case's total number of cycles (the last block is cut to land on it).
//!
//! Every update is a record; the records are the whole state of the run, so a checkpoint
//! after each update lets an interrupted run resume and reach the same numbers.

use super::model::Model;
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::steady::DynamicsError;
use crate::dynamics::summary::ResponseSummary;
use crate::wear::{per_cycle_wear, WearIncrement, WearState};
use serde::{Deserialize, Serialize};

/// Which solver feeds the wear model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum WearMode {
    Dynamic,
    QuasiStatic,
}

impl WearMode {
    pub fn name(&self) -> &'static str {
        match self {
            WearMode::Dynamic => "dynamic",
            WearMode::QuasiStatic => "quasi_static",
        }
    }

    /// The mode in words, for figures and messages.
    pub fn label(&self) -> &'static str {
        match self {
            WearMode::Dynamic => "dynamic",
            WearMode::QuasiStatic => "quasi-static",
        }
    }
}

/// One update: the wear state reached, the response computed on it, and the per-cycle
/// wear that response gives (used for the next block).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct UpdateRecord {
    pub wear: WearState,
    pub roughness_um: f64,
    pub summary: ResponseSummary,
    pub increment_pinion_m: Vec<f64>,
    pub increment_gear_m: Vec<f64>,
    /// Mesh force and pair load along the path (rho1, load) for the wear-depth figures.
    pub path_rho1_m: Vec<f64>,
    pub path_load_n: Vec<f64>,
}

/// A wear run: its mode and every update so far.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WearRun {
    pub mode: WearMode,
    pub records: Vec<UpdateRecord>,
}

impl WearRun {
    pub fn new(mode: WearMode) -> Self {
        Self {
            mode,
            records: Vec::new(),
        }
    }

    pub fn cycles(&self) -> Vec<f64> {
        self.records.iter().map(|r| r.wear.cycles).collect()
    }

    pub fn max_wear_pinion_m(&self) -> Vec<f64> {
        self.records.iter().map(|r| r.wear.max_pinion_m()).collect()
    }

    pub fn max_wear_gear_m(&self) -> Vec<f64> {
        self.records.iter().map(|r| r.wear.max_gear_m()).collect()
    }

    pub fn last(&self) -> Option<&UpdateRecord> {
        self.records.last()
    }
}

/// Length of the next block, cycles: m, cut to the threshold and to the total.
pub fn block_length(inc_max_m: f64, block_cycles: f64, threshold_m: f64, remaining: f64) -> f64 {
    let mut n = block_cycles.min(remaining);
    if inc_max_m > 0.0 && n * inc_max_m > threshold_m {
        n = (threshold_m / inc_max_m).floor().max(1.0);
    }
    n.min(remaining)
}

fn solve(
    model: &Model,
    mode: WearMode,
    wear: &WearState,
) -> Result<DynamicResponse, DynamicsError> {
    let none = ExternalError::none();
    match mode {
        WearMode::Dynamic => model.dynamic(wear, &none),
        WearMode::QuasiStatic => Ok(model.quasi_static(wear, &none)),
    }
}

fn record(model: &Model, wear: WearState, r: &DynamicResponse) -> UpdateRecord {
    let inc: WearIncrement = per_cycle_wear(
        &model.grid,
        &r.path,
        model.case.wear.coefficient_m2_per_n,
        model.pair.pinion.teeth as f64 / model.pair.gear.teeth as f64,
    );
    UpdateRecord {
        roughness_um: model.roughness_for(&wear),
        wear,
        summary: ResponseSummary::of(r),
        increment_pinion_m: inc.pinion_m,
        increment_gear_m: inc.gear_m,
        path_rho1_m: r.path.iter().map(|p| p.rho1_m).collect(),
        path_load_n: r.path.iter().map(|p| p.load_n).collect(),
    }
}

/// Run (or continue) a wear study to the case's total cycles. `on_update` is called after
/// every update with the run so far (checkpointing, progress); an error it returns stops
/// the run.
pub fn run_wear(
    model: &Model,
    mut run: WearRun,
    on_update: &mut dyn FnMut(&WearRun) -> anyhow::Result<()>,
) -> anyhow::Result<WearRun> {
    let w = &model.case.wear;
    let threshold_m = w.threshold_um * 1e-6;
    if run.records.is_empty() {
        let state = WearState::new(model.grid.len());
        let r = solve(model, run.mode, &state)?;
        run.records.push(record(model, state, &r));
        on_update(&run)?;
    }
    loop {
        let last = run.records.last().expect("at least one record");
        let remaining = w.total_cycles - last.wear.cycles;
        if remaining <= 0.5 {
            break;
        }
        let inc = WearIncrement {
            pinion_m: last.increment_pinion_m.clone(),
            gear_m: last.increment_gear_m.clone(),
            ..Default::default()
        };
        let n = block_length(inc.max_m(), w.block_cycles, threshold_m, remaining);
        let mut state = last.wear.clone();
        state.advance(&inc, n);
        let r = solve(model, run.mode, &state)?;
        run.records.push(record(model, state, &r));
        on_update(&run)?;
    }
    Ok(run)
}

/// Marks a run stopped because a sibling run of [`run_wear_modes`] failed.
#[derive(Debug, thiserror::Error)]
#[error("stopped because a parallel wear run failed")]
pub struct SiblingFailed;

/// Run (or continue) several wear runs in parallel (e.g. the dynamic study and its
/// quasi-static twin); `on_update(mode, run)` after every update of each. Results in the
/// order of `starts`. When one run fails, the others stop at their next update, so the
/// failure is reported at once rather than after the slower run has finished; the error
/// returned is the first run's own, not a sibling's stop.
pub fn run_wear_modes(
    model: &Model,
    starts: Vec<WearRun>,
    on_update: &(dyn Fn(WearMode, &WearRun) -> anyhow::Result<()> + Sync),
) -> anyhow::Result<Vec<WearRun>> {
    use rayon::prelude::*;
    use std::sync::atomic::{AtomicBool, Ordering};
    let failed = AtomicBool::new(false);
    let results: Vec<anyhow::Result<WearRun>> = starts
        .into_par_iter()
        .map(|start| {
            let mode = start.mode;
            let r = run_wear(model, start, &mut |r| {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn block_is_cut_to_threshold_and_total() {
        // 1e-10 m per cycle, threshold 0.5 um: 5000 cycles, not the 1e4 of the block.
        assert_eq!(block_length(1e-10, 1e4, 0.5e-6, 4e4), 5000.0);
        // Slow wear: the full block.
        assert_eq!(block_length(1e-12, 1e4, 0.5e-6, 4e4), 1e4);
        // Near the end: what remains.
        assert_eq!(block_length(1e-12, 1e4, 0.5e-6, 300.0), 300.0);
        // No wear at all: the full block (no division by zero).
        assert_eq!(block_length(0.0, 1e4, 0.5e-6, 4e4), 1e4);
    }
}
