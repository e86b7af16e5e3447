//! The wear loop under a load spectrum, and its quasi-static twin.
//!
//! One wear state (both profiles, the cycles run) is shared by every bin: the flanks are
//! the same whatever the operating point. At each update, in this order:
//!
//! 1. **Block.** The spectrum's per-cycle wear is the share-weighted sum of the bins'
//!    per-cycle wear, inc = sum_i s_i inc_i (one spectrum cycle holds s_i cycles of bin
//!    i). The block of n cycles is the case's `wear.block_cycles`, cut by the wear
//!    threshold on inc exactly as the single-point loop cuts it
//!    (`study::wear_loop::block_length`), and to the total.
//! 2. **Advance.** Each bin gets its share of the block, s_i n cycles, and adds its
//!    Archard increment s_i n inc_i (paper eq. 17, per bin), bins in their spectrum order.
//!    Every bin's increment was computed on the profile at the start of the block, so the
//!    order changes only the rounding of the sum; the scheme is the paper's explicit
//!    update applied to the spectrum's mean wear rate, first order in the block length
//!    like the single-point loop (a test shows convergence as blocks shrink).
//! 3. **Respond.** Every bin computes its response on the new worn profile, the dynamic
//!    one warm-started from the periodic state its previous response ended on, and the
//!    per-cycle wear it gives. The bins are independent here and run in parallel.
//!
//! A spectrum of one bin is the single-point loop, bit for bit: s = 1 makes every
//! product above exact. The run stops, keeping its records, where any bin leaves the
//! model's domain (the teeth out of contact for more than half the mesh period at that
//! bin) or finds no steady state, naming the bin: the wear law must hold at every
//! operating point the flanks see.

use super::model::{mixed_increment, mixed_maps, SpectrumModel};
use crate::dynamics::period_search::DynamicsError;
use crate::dynamics::response::DynamicResponse;
use crate::study::wear_loop::{
    block_length, record, solve, start_of, StopKind, UpdateRecord, WearMode, WearStop,
    MAX_CONTACT_LOSS_FRACTION,
};
use crate::wear::{WearIncrement, WearState};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// One update under the spectrum.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpectrumRecord {
    /// The shared wear state reached.
    pub wear: WearState,
    /// Composite RMS roughness on this wear state, um (the case's roughness law).
    pub roughness_um: f64,
    /// Per bin: its response on this state and the wear per cycle of that bin it gives
    /// (each record's `wear` is this state).
    pub bins: Vec<UpdateRecord>,
    /// Wear each bin has added so far, per profile point, m (sum over bins: `wear`, to
    /// rounding).
    pub by_bin_pinion_m: Vec<Vec<f64>>,
    /// Wear each bin has added so far to the gear flank, per profile point, m.
    pub by_bin_gear_m: Vec<Vec<f64>>,
}

impl SpectrumRecord {
    /// The spectrum's per-cycle wear: sum_i s_i inc_i, m per cycle, on the common profiles
    /// (`model::mixed_increment`) and, when every bin's increment is per tooth or per face
    /// slice, on every tooth or face slice (`model::mixed_maps`).
    pub fn increment(&self, shares: &[f64]) -> WearIncrement {
        let common = self.bins.iter().map(|b| {
            (
                b.increment_pinion_m.as_slice(),
                b.increment_gear_m.as_slice(),
            )
        });
        WearIncrement {
            teeth: mixed_maps(self.bins.iter().map(|b| b.increment_teeth.as_ref()), shares),
            slices: mixed_maps(
                self.bins.iter().map(|b| b.increment_slices.as_ref()),
                shares,
            ),
            ..mixed_increment(common, shares)
        }
    }
}

/// A wear run under a spectrum: its mode, the bins' shares, and every update so far.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpectrumRun {
    /// The wear mode (quasi-static or dynamic load) of the run.
    pub mode: WearMode,
    /// Each bin's share of the load cycles, in the case's order (summing to 1).
    pub shares: Vec<f64>,
    /// Every wear update so far, in order of cycles.
    pub records: Vec<SpectrumRecord>,
    /// Why the run stopped before its end, if it did.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stopped: Option<WearStop>,
}

impl SpectrumRun {
    /// An empty run of mode `mode` with the bins' shares `shares`.
    pub fn new(mode: WearMode, shares: Vec<f64>) -> Self {
        Self {
            mode,
            shares,
            records: Vec::new(),
            stopped: None,
        }
    }

    /// The latest update, if any.
    pub fn last(&self) -> Option<&SpectrumRecord> {
        self.records.last()
    }

    /// Pinion load cycles at each update.
    pub fn cycles(&self) -> Vec<f64> {
        self.records.iter().map(|r| r.wear.cycles).collect()
    }
}

/// Why a bin's response cannot be kept.
pub(super) enum BinFailure {
    /// Out of contact too long: the model's domain is left.
    Validity(f64),
    Solver(DynamicsError),
}

/// Every bin's response on `wear`, in parallel; `starts[i]` warm-starts bin i. The first
/// failing bin (lowest index) and why, if any.
pub(super) fn respond(
    sm: &SpectrumModel,
    mode: WearMode,
    wear: &WearState,
    starts: &[Option<Vec<f64>>],
) -> Result<Vec<UpdateRecord>, (usize, BinFailure)> {
    let solved: Vec<Result<DynamicResponse, DynamicsError>> = sm
        .bins
        .par_iter()
        .zip(starts.par_iter())
        .map(|(m, s)| solve(m, mode, wear, s.as_deref()))
        .collect();
    let mut out = Vec::with_capacity(solved.len());
    for (i, r) in solved.into_iter().enumerate() {
        match r {
            Ok(r) if r.contact_loss_fraction() > MAX_CONTACT_LOSS_FRACTION => {
                return Err((i, BinFailure::Validity(r.contact_loss_fraction())))
            }
            Ok(r) => out.push(record(&sm.bins[i], mode, wear.clone(), &r)),
            Err(e) => return Err((i, BinFailure::Solver(e))),
        }
    }
    Ok(out)
}

/// The block after `last`, cycles (module docs, step 1): `wear.block_cycles` cut by the
/// threshold on the spectrum's wear per cycle and to the total; None when the total is
/// reached. The run, its recomputation (`duty::verify`) and the replay of a helical
/// pair's logs (`duty::resume`) take this one step.
pub(super) fn block_after(
    sm: &SpectrumModel,
    last: &SpectrumRecord,
    shares: &[f64],
) -> Option<f64> {
    let w = &sm.case.wear;
    let remaining = w.total_cycles - last.wear.cycles;
    if remaining <= 0.5 {
        return None;
    }
    let inc = last.increment(shares);
    Some(block_length(
        inc.max_m(),
        w.block_cycles,
        w.threshold_um * 1e-6,
        remaining,
    ))
}

/// The state after a block of `n` cycles from `last`: each bin adds s_i n inc_i, in bin
/// order (module docs, step 2).
pub(super) fn advance(last: &SpectrumRecord, shares: &[f64], n: f64) -> SpectrumRecord {
    let mut next = SpectrumRecord {
        wear: last.wear.clone(),
        roughness_um: last.roughness_um,
        bins: Vec::new(),
        by_bin_pinion_m: last.by_bin_pinion_m.clone(),
        by_bin_gear_m: last.by_bin_gear_m.clone(),
    };
    for (i, (b, s)) in last.bins.iter().zip(shares).enumerate() {
        let cycles = s * n;
        // Paper eq. 17 for this bin: every tooth its own when the mesh is tooth-resolved,
        // every face slice its own on a helical pair.
        next.wear.advance(&b.increment(), cycles);
        for (w, d) in next.by_bin_pinion_m[i]
            .iter_mut()
            .zip(&b.increment_pinion_m)
        {
            *w += cycles * d;
        }
        for (w, d) in next.by_bin_gear_m[i].iter_mut().zip(&b.increment_gear_m) {
            *w += cycles * d;
        }
    }
    // The block is n cycles whatever the rounding of sum_i s_i n.
    next.wear.cycles = last.wear.cycles + n;
    next
}

/// The first record of a run on `state`: every bin's response, cold-started (from the
/// static equilibrium), and no wear attributed to any bin yet. An error names the bin
/// whose response fails or leaves the model's domain.
pub(super) fn first_record(
    sm: &SpectrumModel,
    mode: WearMode,
    state: WearState,
) -> anyhow::Result<SpectrumRecord> {
    let nbins = sm.len();
    let bins = respond(sm, mode, &state, &vec![None; nbins]).map_err(|(i, f)| match f {
        BinFailure::Solver(e) => anyhow::anyhow!("{}: {e}", sm.label(i)),
        BinFailure::Validity(x) => anyhow::anyhow!(
            "{}: at {:.0} cycles (maximum pinion wear {:.2} µm) the teeth are out of contact for {:.0} % of the mesh period (more than {:.0} %): the wear model of a steady contact does not apply",
            sm.label(i),
            state.cycles,
            state.max_pinion_m() * 1e6,
            100.0 * x,
            100.0 * MAX_CONTACT_LOSS_FRACTION
        ),
    })?;
    let zeros = vec![vec![0.0; state.pinion_m.len()]; nbins];
    Ok(SpectrumRecord {
        roughness_um: sm.bins[0].roughness_for(&state),
        wear: state,
        bins,
        by_bin_pinion_m: zeros.clone(),
        by_bin_gear_m: zeros,
    })
}

impl SpectrumRun {
    /// A run under `sm`'s spectrum that starts from the worn `state` (e.g. the end of a
    /// run under another spectrum: a change of duty), its first record that state with
    /// every bin's response on it; wear attributed to the bins counts from there.
    pub(crate) fn starting_at(
        sm: &SpectrumModel,
        mode: WearMode,
        state: WearState,
    ) -> anyhow::Result<Self> {
        let mut run = Self::new(mode, sm.shares.clone());
        run.records.push(first_record(sm, mode, state)?);
        Ok(run)
    }
}

/// Run (or continue) a wear study under `sm`'s spectrum to the case's total cycles.
/// `on_update` is called after every update (checkpoints, progress); an error it returns
/// stops the run. The run may stop early ([`SpectrumRun::stopped`], naming the bin); only
/// the response of new teeth failing at some bin is an error.
pub fn run_spectrum_wear(
    sm: &SpectrumModel,
    mut run: SpectrumRun,
    on_update: &mut dyn FnMut(&SpectrumRun) -> anyhow::Result<()>,
) -> anyhow::Result<SpectrumRun> {
    if run.records.is_empty() {
        let state = sm.bins[0].new_wear_state();
        run.records.push(first_record(sm, run.mode, state)?);
        on_update(&run)?;
    }
    while run.stopped.is_none() {
        let last = run.records.last().expect("at least one record");
        let Some(n) = block_after(sm, last, &run.shares) else {
            break;
        };
        let mut next = advance(last, &run.shares, n);
        let starts: Vec<Option<Vec<f64>>> = last.bins.iter().map(start_of).collect();
        let state = &next.wear;
        match respond(sm, run.mode, state, &starts) {
            Ok(bins) => {
                next.roughness_um = sm.bins[0].roughness_for(state);
                next.bins = bins;
                run.records.push(next);
            }
            Err((i, f)) => {
                let (kind, why) = match f {
                    BinFailure::Validity(x) => (
                        StopKind::ModelValidity,
                        format!(
                            "the teeth are out of contact for {:.0} % of the mesh period (more than {:.0} %): the wear model of a steady contact no longer applies",
                            100.0 * x,
                            100.0 * MAX_CONTACT_LOSS_FRACTION
                        ),
                    ),
                    BinFailure::Solver(e) => (
                        StopKind::Numerical,
                        format!("no steady state was found, even from the static equilibrium with a 10x tighter numerics.integration_tolerance and 2x the numerics.steps_per_mesh_period: {e}"),
                    ),
                };
                run.stopped = Some(WearStop {
                    cycles: state.cycles,
                    kind,
                    reason: format!(
                        "at {:.0} cycles (maximum pinion wear {:.2} µm), at {}: {why}",
                        state.cycles,
                        state.max_pinion_m() * 1e6,
                        sm.label(i)
                    ),
                });
            }
        }
        on_update(&run)?;
    }
    Ok(run)
}

/// Run (or continue) spectrum wear runs in parallel (the dynamic study and its
/// quasi-static twin), `on_update(mode, run)` after every update of each; results in the
/// order of `starts`. The first error is returned once both have ended.
pub fn run_spectrum_modes(
    sm: &SpectrumModel,
    starts: Vec<SpectrumRun>,
    on_update: &(dyn Fn(WearMode, &SpectrumRun) -> anyhow::Result<()> + Sync),
) -> anyhow::Result<Vec<SpectrumRun>> {
    let results: Vec<anyhow::Result<SpectrumRun>> = starts
        .into_par_iter()
        .map(|start| {
            let mode = start.mode;
            run_spectrum_wear(sm, start, &mut |r| on_update(mode, r))
        })
        .collect();
    results.into_iter().collect()
}
