//! A train's run under a spectrum read back from its checkpoints: one log per bin and
//! mesh, each an ordinary wear run's records (bin i's view of mesh k: the shared flank
//! with bin i's response and wear per cycle), and whether this model computes it. As for
//! the train's own logs (`study::train_wear_check`), nothing the files say about the run
//! is trusted:
//!
//! - **Replayed** ([`from_logs`]): each record's shape is checked
//!   (`train_wear_check::record_problem`); the input cycles, the mesh that cut each block
//!   and the wear each bin added are recomputed from the update before with the loop's
//!   own step (`duty::train::next_spectrum_block`), and every stored flank must equal the
//!   replayed one bit for bit (the first update: new teeth). Logs of unequal length are
//!   cut to the updates every log holds.
//! - **Recomputed** ([`verify`]): the first and last updates and a random sample of the
//!   others (at most `wear_check::MAX_RECOMPUTED`) are computed again from the update
//!   before, every bin's whole train, and must equal the stored records bit for bit
//!   (compared as JSON, which carries every double exactly).

use super::train::{
    first_record, next_spectrum_block, respond_bins, TrainSpectrum, TrainSpectrumRecord,
    TrainSpectrumRun,
};
use crate::study::train_wear::{new_teeth, TrainUpdate};
use crate::study::train_wear_check::record_problem;
use crate::study::wear_check::{random_sample, StoredRunError, MAX_RECOMPUTED};
use crate::study::wear_loop::{start_of, UpdateRecord, WearMode, WearRun};

/// The run of `mode` whose logs are `logs` (`logs[i][k]`: bin i, mesh k), replayed and
/// checked (see the module docs); the error names the update, its line, bin and stage.
pub fn from_logs(
    ts: &TrainSpectrum,
    mode: WearMode,
    logs: &[Vec<WearRun>],
) -> Result<TrainSpectrumRun, StoredRunError> {
    let (nb, nk) = (ts.trains.len(), ts.meshes());
    if logs.len() != nb || logs.iter().any(|l| l.len() != nk) {
        return Err(StoredRunError::Mismatch(format!(
            "the logs are not one per bin ({nb}) and stage ({nk})"
        )));
    }
    let n = logs
        .iter()
        .flatten()
        .map(|l| l.records.len())
        .min()
        .unwrap_or(0);
    let mut run = TrainSpectrumRun::new(mode, ts.sm.shares.clone());
    for j in 0..n {
        let at = |i: usize, k: usize, what: &str| {
            StoredRunError::Mismatch(format!(
                "update {j} (line {}), bin {}, stage {}: {what}",
                j + 2,
                i + 1,
                k + 1
            ))
        };
        let (wears, mut next) = match run.records.last() {
            None => {
                let wears = new_teeth(ts.trains[0]);
                let zeros: Vec<Vec<f64>> =
                    wears.iter().map(|w| vec![0.0; w.pinion_m.len()]).collect();
                let first = TrainSpectrumRecord {
                    input_cycles: 0.0,
                    limited_by: None,
                    bins: Vec::new(),
                    by_bin_pinion_m: vec![zeros.clone(); nb],
                    by_bin_gear_m: vec![zeros; nb],
                };
                (wears, first)
            }
            Some(prev) => next_spectrum_block(ts, prev, &run.shares)
                .map(|(block, added)| (block.wears, added))
                .ok_or_else(|| {
                    StoredRunError::Mismatch(format!(
                        "update {j} (line {}): the run had reached wear.total_cycles at the update before it",
                        j + 2
                    ))
                })?,
        };
        for (i, bin) in logs.iter().enumerate() {
            let meshes: Vec<UpdateRecord> = bin.iter().map(|l| l.records[j].clone()).collect();
            for (k, r) in meshes.iter().enumerate() {
                let (m, t) = (&ts.sm.bins[i], ts.trains[i]);
                if let Some(p) = record_problem(m, t, mode, k, r) {
                    return Err(at(i, k, &p));
                }
                if r.wear != wears[k] {
                    return Err(at(
                        i,
                        k,
                        "its wear is not the previous update's advanced over the block at every bin's previous rate",
                    ));
                }
            }
            next.bins.push(TrainUpdate {
                input_cycles: next.input_cycles,
                meshes,
                limited_by: next.limited_by,
            });
        }
        run.records.push(next);
    }
    Ok(run)
}

/// Recompute updates of `run` (replayed by [`from_logs`]) and require them equal to the
/// stored ones (see the module docs); the error names the first that is not.
pub fn verify(ts: &TrainSpectrum, run: &TrainSpectrumRun) -> Result<(), StoredRunError> {
    let n = run.records.len();
    let json = |r: &UpdateRecord| serde_json::to_string(r).ok();
    for j in random_sample(n, MAX_RECOMPUTED, &[0, n.saturating_sub(1)]) {
        let line = j + 2;
        let again = match j.checked_sub(1).map(|p| &run.records[p]) {
            None => first_record(ts, run.mode).map_err(|e| e.to_string()),
            Some(prev) => {
                let (block, mut next) = next_spectrum_block(ts, prev, &run.shares)
                    .ok_or_else(|| {
                        StoredRunError::Mismatch(format!(
                            "update {j} (line {line}): no block leads to it"
                        ))
                    })?;
                let starts: Vec<Option<Vec<f64>>> =
                    prev.bins.iter().map(|b| start_of(&b.meshes[0])).collect();
                respond_bins(ts, run.mode, &block, &starts)
                    .map(|bins| {
                        next.bins = bins;
                        next
                    })
                    .map_err(|s| s.reason)
            }
        }
        .map_err(|e| {
            StoredRunError::Mismatch(format!("update {j} (line {line}): this case's model makes no such update when it is recomputed from the update before it ({e}): the records are not this case's"))
        })?;
        for (i, (a, b)) in again.bins.iter().zip(&run.records[j].bins).enumerate() {
            if let Some(k) = a
                .meshes
                .iter()
                .zip(&b.meshes)
                .position(|(x, y)| json(x) != json(y))
            {
                return Err(StoredRunError::Mismatch(format!(
                    "update {j} (line {line}), bin {}, stage {}: not what this case's model computes from the update before it: the records are not this case's, or were edited",
                    i + 1,
                    k + 1
                )));
            }
        }
    }
    Ok(())
}
