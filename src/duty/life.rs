//! Wear life: the cycles until the maximum pinion wear depth reaches a limit, under the
//! spectrum and at each of its bins alone.
//!
//! Between updates the wear grows linearly in cycles (paper eq. 17), so the crossing is
//! exact within its block: the first n with max_i (h_i + n inc_i) >= L, the minimum over
//! rising points of (L - h_i) / inc_i. A life run continues a wear study until the limit
//! is passed; its blocks are cut by the wear threshold only (`wear.block_cycles` is lifted),
//! so every run reaches the limit in about L / threshold updates whatever its wear rate,
//! and the runs at different bins are made at the same wear states.
//!
//! Beside the life under the spectrum and each bin's own life L_i, the table gives the
//! life a linear mix would predict, 1 / sum_i (s_i / L_i): each bin wearing the flanks at
//! its own rate as if the others did not change the profile it runs on (Palmgren-Miner's
//! rule read for wear). Where the spectrum's life differs from it, the bins interact
//! through the worn profile.

use super::model::SpectrumModel;
use super::wear::{run_spectrum_wear, SpectrumRun};
use crate::config::Case;
use crate::study::model::ModelError;
use crate::study::wear_loop::{UpdateRecord, WearMode};
use rayon::prelude::*;
use serde::Serialize;

/// Cycles at which the maximum pinion wear of `records` (each with its per-cycle wear
/// for the block after it; of any tooth when per tooth) first reaches `limit_m`, within
/// `end` cycles (the last block ends there); None if not reached.
pub(crate) fn first_crossing(records: &[UpdateRecord], end: f64, limit_m: f64) -> Option<f64> {
    for (j, r) in records.iter().enumerate() {
        let profiles = r.pinion_profiles();
        if profiles
            .iter()
            .any(|(h, _)| h.iter().any(|x| *x >= limit_m))
        {
            return Some(r.wear.cycles);
        }
        let block_end = records.get(j + 1).map_or(end, |x| x.wear.cycles);
        let n = profiles
            .iter()
            .flat_map(|(h, d)| h.iter().zip(d.iter()))
            .filter(|(_, d)| **d > 0.0)
            .map(|(a, d)| (limit_m - a) / d)
            .fold(f64::INFINITY, f64::min);
        if r.wear.cycles + n <= block_end {
            return Some(r.wear.cycles + n);
        }
    }
    None
}

/// Where a life run ended.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "status")]
pub enum Life {
    /// The limit is reached at this many cycles.
    Reached {
        /// Pinion load cycles at which the limit is reached.
        cycles: f64,
    },
    /// Not reached: the run stopped (the model's domain ended, or the cap) at `cycles`.
    Beyond {
        /// Pinion load cycles at which the run stopped.
        cycles: f64,
        /// Why the run stopped, in words.
        reason: String,
    },
}

impl Life {
    /// The cycles, when reached.
    pub fn cycles(&self) -> Option<f64> {
        match self {
            Life::Reached { cycles } => Some(*cycles),
            Life::Beyond { .. } => None,
        }
    }
}

/// The life under one bin alone.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BinLife {
    /// 1-based.
    pub bin: usize,
    /// The bin's torque, N m.
    pub torque_nm: f64,
    /// The bin's input (pinion) speed, Hz.
    pub input_speed_hz: f64,
    /// The bin's share of the load cycles.
    pub share: f64,
    /// Life at this bin alone.
    pub life: Life,
    /// Hours at the bin's speed, when reached.
    pub hours: Option<f64>,
}

/// Lives under the spectrum and at each bin.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LifeTable {
    /// The wear mode of the runs the lives come from.
    pub mode: WearMode,
    /// Wear limit: the maximum wear depth of the pinion flank at end of life, um.
    pub limit_um: f64,
    /// Life under the whole spectrum.
    pub spectrum: Life,
    /// Hours under the spectrum: cycles x sum_i (s_i / f_i) / 3600.
    pub spectrum_hours: Option<f64>,
    /// Life at each bin alone, in the case's order.
    pub bins: Vec<BinLife>,
    /// 1 / sum_i (s_i / L_i), when every bin with a share reaches the limit.
    pub linear_mix_cycles: Option<f64>,
}

/// Stops a life run once the limit is passed.
#[derive(Debug, thiserror::Error)]
#[error("the wear limit is reached")]
struct LimitReached;

/// The life of `case` (its spectrum, or its operating point) in `mode`: a run to the limit
/// (at most `max_cycles`).
fn life_of(case: &Case, mode: WearMode, limit_m: f64, max_cycles: f64) -> Result<Life, ModelError> {
    let mut c = case.clone();
    c.wear.total_cycles = max_cycles;
    c.wear.block_cycles = max_cycles;
    let sm = SpectrumModel::dynamics_from_case(&c)?;
    let mut records: Vec<UpdateRecord> = Vec::new();
    let mut stopped: Option<String> = None;
    let result = run_spectrum_wear(&sm, SpectrumRun::new(mode, sm.shares.clone()), &mut |r| {
        stopped = r.stopped.as_ref().map(|s| s.reason.clone());
        if let Some(last) = r.records.last() {
            if records.last().map(|x| x.wear.cycles) != Some(last.wear.cycles) {
                records.push(super::contribution::combined_record(r, last, 0));
            }
            if last.wear.max_pinion_m() >= limit_m {
                return Err(LimitReached.into());
            }
        }
        Ok(())
    });
    let end = match &result {
        Ok(run) => run.last().map_or(0.0, |r| r.wear.cycles),
        Err(_) => records.last().map_or(0.0, |r| r.wear.cycles),
    };
    if let Some(n) = first_crossing(&records, end, limit_m) {
        return Ok(Life::Reached { cycles: n });
    }
    let reason = match (result, stopped) {
        (Err(e), _) if !e.is::<LimitReached>() => format!("{e:#}"),
        (_, Some(s)) => s,
        _ => format!("not reached within {max_cycles:e} cycles"),
    };
    Ok(Life::Beyond {
        cycles: end,
        reason,
    })
}

/// Lives to `limit_um` of maximum pinion wear under `case`'s spectrum and at each of its
/// bins alone, in `mode`; every run in parallel, each capped at `max_cycles`.
pub fn life_table(
    case: &Case,
    mode: WearMode,
    limit_um: f64,
    max_cycles: f64,
) -> Result<LifeTable, ModelError> {
    let limit_m = limit_um * 1e-6;
    let bins = case.bin_cases().unwrap_or_else(|| vec![case.clone()]);
    let spectrum = case.load_spectrum.clone();
    let mut cases = vec![case.clone()];
    cases.extend(bins.iter().cloned());
    let lives: Vec<Result<Life, ModelError>> = cases
        .par_iter()
        .map(|c| life_of(c, mode, limit_m, max_cycles))
        .collect();
    let mut lives = lives
        .into_iter()
        .collect::<Result<Vec<Life>, ModelError>>()?;
    let under = lives.remove(0);
    let shares: Vec<f64> = match &spectrum {
        Some(s) => s.bins.iter().map(|b| b.share).collect(),
        None => vec![1.0],
    };
    let seconds_per_cycle = spectrum
        .as_ref()
        .map_or(1.0 / case.operating.input_speed_hz, |s| {
            s.seconds_per_cycle()
        });
    let bins: Vec<BinLife> = bins
        .iter()
        .zip(lives)
        .zip(&shares)
        .enumerate()
        .map(|(i, ((c, life), share))| BinLife {
            bin: i + 1,
            torque_nm: c.operating.load_torque_nm,
            input_speed_hz: c.operating.input_speed_hz,
            share: *share,
            hours: life
                .cycles()
                .map(|n| n / c.operating.input_speed_hz / 3600.0),
            life,
        })
        .collect();
    let mix: Option<f64> = bins
        .iter()
        .filter(|b| b.share > 0.0)
        .map(|b| b.life.cycles().map(|l| b.share / l))
        .sum::<Option<f64>>()
        .map(|x| 1.0 / x);
    Ok(LifeTable {
        mode,
        limit_um,
        spectrum_hours: under.cycles().map(|n| n * seconds_per_cycle / 3600.0),
        spectrum: under,
        bins,
        linear_mix_cycles: mix,
    })
}
