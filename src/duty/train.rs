//! The wear loop of a gear train (`[[stage]]`) under a load spectrum: the train's loop
//! (`study::train_wear`) with every bin advancing at every update, as the single pair's
//! spectrum loop (`duty::wear`) does (docs/MODEL.md, section 10.1).
//!
//! Every bin is the train at the bin's operating point (`Case::at_bin`: the input speed
//! and the torque on the input shaft, or on the output shaft, the last stage's gear,
//! with `torque_shaft = "gear"`); each stage's speed and torque follow from the ratios
//! through the train's operating point (`dynamics::params::TrainOperatingPoint`),
//! computed once per bin when its model is built. The meshes' flanks are shared by every
//! bin. Shares are shares of input cycles; mesh k's pinion turns c_k times per input
//! cycle whatever the bin (c_k is the product of the ratios before it), so a bin of share
//! s_i gives every mesh s_i of its pinion cycles too. At each update:
//!
//! 1. **Block.** Mesh k's wear per input cycle under the spectrum is
//!    c_k sum_i s_i inc_ik (inc_ik: its wear per pinion cycle at bin i, paper eq. 14-16);
//!    the block of n input cycles is `wear.block_cycles` cut by the threshold of eq. 17
//!    on the fastest mesh (`study::wear_loop::block_length`, as the train's loop does)
//!    and to the total.
//! 2. **Advance.** Each mesh k gets s_i n c_k pinion cycles of bin i's wear, bins in
//!    their order (paper eq. 17 per bin and mesh), all on the profiles at the start of
//!    the block.
//! 3. **Respond.** Every bin solves the whole train on the new worn flanks (warm-started
//!    from its own previous periodic state); the bins run in parallel.
//!
//! A spectrum of one bin at the operating point is the train's loop bit for bit (s = 1
//! makes every product exact). A bin whose response leaves the model's domain at some
//! mesh, or finds no steady state, stops the run naming the bin and the stage.

use super::model::SpectrumModel;
use crate::study::train::TrainModel;
use crate::study::train_wear::{
    new_teeth, respond_to_block, Block, TrainNext, TrainUpdate, TrainWearRun,
};
use crate::study::wear_loop::{fastest_block, start_of, UpdateRecord, WearMode, WearStop};
use crate::study::Model;
use crate::wear::{WearIncrement, WearState};
use rayon::prelude::*;

/// A spectrum on a train: the bins' models (each a train) and their trains.
pub struct TrainSpectrum<'a> {
    /// The bins' models, shares and monitoring bin.
    pub sm: &'a SpectrumModel,
    /// The train of every bin, in the spectrum's order.
    pub trains: Vec<&'a TrainModel>,
}

impl<'a> TrainSpectrum<'a> {
    /// The trains of `sm`'s bins; None when a bin is not a train.
    pub fn of(sm: &'a SpectrumModel) -> Option<Self> {
        let trains = sm
            .bins
            .iter()
            .map(|m| m.train.as_ref())
            .collect::<Option<Vec<_>>>()?;
        Some(Self { sm, trains })
    }

    /// Number of meshes (stages).
    pub fn meshes(&self) -> usize {
        self.trains[0].stages.len()
    }

    /// Pinion revolutions of each mesh per input revolution, c_k (the same at every bin:
    /// the ratios).
    pub fn cycle_factors(&self) -> Vec<f64> {
        self.trains[0].cycle_factors()
    }

    /// The model of bin `i`.
    fn model(&self, i: usize) -> &Model {
        &self.sm.bins[i]
    }
}

/// One update under the spectrum.
#[derive(Debug, Clone, PartialEq)]
pub struct TrainSpectrumRecord {
    /// Revolutions of the input (stage 1's pinion).
    pub input_cycles: f64,
    /// The mesh (0-based) whose threshold cut the block that led here.
    pub limited_by: Option<usize>,
    /// Per bin: the whole train's update on the shared flanks (each mesh's record: the
    /// mesh's shared wear, the bin's response, its wear per pinion cycle at that bin).
    pub bins: Vec<TrainUpdate>,
    /// Wear bin i has added so far to mesh k's pinion flank, per profile point, m
    /// (`[i][k]`).
    pub by_bin_pinion_m: Vec<Vec<Vec<f64>>>,
    /// The same for the gear flank, m.
    pub by_bin_gear_m: Vec<Vec<Vec<f64>>>,
}

impl TrainSpectrumRecord {
    /// Mesh `k`'s wear per pinion cycle under the spectrum, sum_i s_i inc_ik, m.
    pub fn increment(&self, shares: &[f64], k: usize) -> WearIncrement {
        let per_bin = self.bins.iter().map(|b| {
            let r = &b.meshes[k];
            (
                r.increment_pinion_m.as_slice(),
                r.increment_gear_m.as_slice(),
            )
        });
        super::model::mixed_increment(per_bin, shares)
    }

    /// Each mesh's shared wear (stage order).
    pub fn wears(&self) -> Vec<&WearState> {
        self.bins[0].meshes.iter().map(|r| &r.wear).collect()
    }
}

/// A train's wear run under a spectrum: its mode, the bins' shares, every update.
#[derive(Debug, Clone, PartialEq)]
pub struct TrainSpectrumRun {
    /// The wear mode of the run.
    pub mode: WearMode,
    /// Each bin's share of the input cycles (sum 1).
    pub shares: Vec<f64>,
    /// Every update so far.
    pub records: Vec<TrainSpectrumRecord>,
    /// Why the run stopped before the case's total, if it did.
    pub stopped: Option<WearStop>,
}

impl TrainSpectrumRun {
    /// A run in `mode` with no update yet.
    pub fn new(mode: WearMode, shares: Vec<f64>) -> Self {
        Self {
            mode,
            shares,
            records: Vec::new(),
            stopped: None,
        }
    }

    /// Bin `i`'s view: the shared flanks with that bin's responses (its checkpoint logs).
    pub fn bin_run(&self, i: usize) -> TrainWearRun {
        TrainWearRun {
            mode: self.mode,
            updates: self.records.iter().map(|r| r.bins[i].clone()).collect(),
            stopped: self.stopped.clone(),
        }
    }
}

/// The block after `last` (module docs, steps 1 and 2): the input cycles reached, the
/// mesh that cut it, every mesh's wear at its end, and the wear each bin added to each
/// mesh by then. None when the total is reached. The replay of checkpoints takes the
/// same step (`duty::train_resume`).
pub fn next_spectrum_block(
    ts: &TrainSpectrum,
    last: &TrainSpectrumRecord,
    shares: &[f64],
) -> Option<(Block, TrainSpectrumRecord)> {
    let w = &ts.sm.case.wear;
    let remaining = w.total_cycles - last.input_cycles;
    if remaining <= 0.5 {
        return None;
    }
    let c = ts.cycle_factors();
    let incs: Vec<WearIncrement> = (0..c.len()).map(|k| last.increment(shares, k)).collect();
    let (n, limited_by) = fastest_block(
        incs.iter().zip(&c).map(|(inc, ck)| inc.max_m() * ck),
        w,
        remaining,
    );
    let mut added = TrainSpectrumRecord {
        input_cycles: last.input_cycles + n,
        limited_by,
        bins: Vec::new(),
        by_bin_pinion_m: last.by_bin_pinion_m.clone(),
        by_bin_gear_m: last.by_bin_gear_m.clone(),
    };
    let mut wears: Vec<WearState> = last.wears().into_iter().cloned().collect();
    for (k, (wk, ck)) in wears.iter_mut().zip(&c).enumerate() {
        let start = wk.cycles;
        for (i, (b, s)) in last.bins.iter().zip(shares).enumerate() {
            let r = &b.meshes[k];
            // Paper eq. 17 for bin i on mesh k: s_i n c_k of its pinion cycles.
            let cycles = s * n * ck;
            wk.advance(&r.increment(), cycles);
            for (h, d) in added.by_bin_pinion_m[i][k]
                .iter_mut()
                .zip(&r.increment_pinion_m)
            {
                *h += cycles * d;
            }
            for (h, d) in added.by_bin_gear_m[i][k]
                .iter_mut()
                .zip(&r.increment_gear_m)
            {
                *h += cycles * d;
            }
        }
        // The block is n c_k pinion cycles whatever the rounding of sum_i s_i n c_k.
        wk.cycles = start + n * ck;
    }
    let block = Block {
        input_cycles: added.input_cycles,
        limited_by,
        wears,
    };
    Some((block, added))
}

/// Every bin's update on `block` (in parallel; `starts[i]` warm-starts bin i), or the
/// first bin's stop (lowest index), its reason naming the bin.
pub fn respond_bins(
    ts: &TrainSpectrum,
    mode: WearMode,
    block: &Block,
    starts: &[Option<Vec<f64>>],
) -> Result<Vec<TrainUpdate>, WearStop> {
    let next: Vec<TrainNext> = (0..ts.trains.len())
        .into_par_iter()
        .map(|i| {
            let (m, t) = (ts.model(i), ts.trains[i]);
            respond_to_block(m, t, mode, block.clone(), starts[i].as_deref())
        })
        .collect();
    let mut out = Vec::with_capacity(next.len());
    for (i, n) in next.into_iter().enumerate() {
        match n {
            TrainNext::Update(u) => out.push(*u),
            TrainNext::Stop(s) => {
                return Err(WearStop {
                    reason: format!("{}: {}", ts.sm.label(i), s.reason),
                    ..s
                })
            }
            TrainNext::Finished => unreachable!("a response is an update or a stop"),
        }
    }
    Ok(out)
}

/// The first update: new teeth at input cycle 0, every bin cold-started; a bin that
/// fails is an error naming it.
pub fn first_record(ts: &TrainSpectrum, mode: WearMode) -> anyhow::Result<TrainSpectrumRecord> {
    let block = Block {
        input_cycles: 0.0,
        limited_by: None,
        wears: new_teeth(ts.trains[0]),
    };
    let bins = respond_bins(ts, mode, &block, &vec![None; ts.trains.len()])
        .map_err(|s| anyhow::anyhow!("with new teeth: {}", s.reason))?;
    let zeros: Vec<Vec<f64>> = block
        .wears
        .iter()
        .map(|w| vec![0.0; w.pinion_m.len()])
        .collect();
    Ok(TrainSpectrumRecord {
        input_cycles: 0.0,
        limited_by: None,
        bins,
        by_bin_pinion_m: vec![zeros.clone(); ts.trains.len()],
        by_bin_gear_m: vec![zeros; ts.trains.len()],
    })
}

/// Run (or continue) a train's wear study under the spectrum to the case's total input
/// cycles; `on_update` after every update (an error it returns stops the run).
pub fn run_train_spectrum_wear(
    ts: &TrainSpectrum,
    mut run: TrainSpectrumRun,
    on_update: &mut dyn FnMut(&TrainSpectrumRun) -> anyhow::Result<()>,
) -> anyhow::Result<TrainSpectrumRun> {
    if run.records.is_empty() {
        run.records.push(first_record(ts, run.mode)?);
        on_update(&run)?;
    }
    while run.stopped.is_none() {
        let last = run.records.last().expect("at least one record");
        let Some((block, mut next)) = next_spectrum_block(ts, last, &run.shares) else {
            break;
        };
        // Each bin's periodic end state is with its stage 1's record.
        let starts: Vec<Option<Vec<f64>>> =
            last.bins.iter().map(|b| start_of(&b.meshes[0])).collect();
        match respond_bins(ts, run.mode, &block, &starts) {
            Ok(bins) => {
                next.bins = bins;
                run.records.push(next);
            }
            Err(s) => run.stopped = Some(s),
        }
        on_update(&run)?;
    }
    Ok(run)
}

/// Run (or continue) runs in parallel (the dynamic study and its quasi-static twin),
/// `on_update(mode, run)` after every update of each; results in the order of `starts`.
pub fn run_train_spectrum_modes(
    ts: &TrainSpectrum,
    starts: Vec<TrainSpectrumRun>,
    on_update: &(dyn Fn(WearMode, &TrainSpectrumRun) -> anyhow::Result<()> + Sync),
) -> anyhow::Result<Vec<TrainSpectrumRun>> {
    let results: Vec<anyhow::Result<TrainSpectrumRun>> = starts
        .into_par_iter()
        .map(|start| {
            let mode = start.mode;
            run_train_spectrum_wear(ts, start, &mut |r| on_update(mode, r))
        })
        .collect();
    results.into_iter().collect()
}

/// The run as one train run, for the train's readers (tables, summary, report): each
/// mesh's shared wear, its wear per pinion cycle under the spectrum (sum_i s_i inc_ik:
/// the wear between updates grows exactly as in the run) and the response of bin
/// `observed` (the monitoring bin).
pub fn combined_train_run(run: &TrainSpectrumRun, observed: usize) -> TrainWearRun {
    let updates = run
        .records
        .iter()
        .map(|r| {
            let b = &r.bins[observed.min(r.bins.len() - 1)];
            let meshes: Vec<UpdateRecord> = b
                .meshes
                .iter()
                .enumerate()
                .map(|(k, m)| {
                    let inc = r.increment(&run.shares, k);
                    UpdateRecord {
                        increment_pinion_m: inc.pinion_m,
                        increment_gear_m: inc.gear_m,
                        increment_teeth: None,
                        end_state: None,
                        ..m.clone()
                    }
                })
                .collect();
            TrainUpdate {
                input_cycles: r.input_cycles,
                meshes,
                limited_by: r.limited_by,
            }
        })
        .collect();
    TrainWearRun {
        mode: run.mode,
        updates,
        stopped: run.stopped.clone(),
    }
}
