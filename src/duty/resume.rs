//! A spectrum run kept as one single-point log per bin, and read back.
//!
//! Bin i's log holds, at every update, the shared wear state with bin i's response and
//! per-cycle wear (`contribution::bin_run`): an ordinary wear run's records, so the checkpoint format
//! of single-point runs serves unchanged. What the bins added is not stored: it is
//! replayed from the logs with the arithmetic of the loop itself, and the replayed wear
//! must equal the stored wear bit for bit, so an edited, truncated or foreign log is
//! refused and a resumed run continues exactly as an uninterrupted one.
//!
//! The logs are appended one after another after each update; an interruption between
//! two appends leaves some logs one update longer: the run resumes from the updates every
//! log holds.

use super::model::SpectrumModel;
use super::wear::{SpectrumRecord, SpectrumRun};
use crate::study::wear_check::{check_spectrum_view, StoredRunError};
use crate::study::wear_loop::{UpdateRecord, WearMode, WearRun};

/// The spectrum run whose bin logs are `logs` (bin order), checked against `sm`. The logs
/// are cut to the updates all of them hold.
pub(crate) fn from_bin_runs(
    sm: &SpectrumModel,
    mode: WearMode,
    logs: &[WearRun],
) -> Result<SpectrumRun, StoredRunError> {
    if logs.len() != sm.len() {
        return Err(StoredRunError::Mismatch(format!(
            "{} bin logs for a spectrum of {} bins",
            logs.len(),
            sm.len()
        )));
    }
    let n = logs.iter().map(|l| l.records.len()).min().unwrap_or(0);
    let mut run = SpectrumRun::new(mode, sm.shares.clone());
    for j in 0..n {
        let bins: Vec<UpdateRecord> = logs.iter().map(|l| l.records[j].clone()).collect();
        let wear = bins[0].wear.clone();
        for (i, b) in bins.iter().enumerate() {
            let ok = |v: &[f64]| {
                v.len() == wear.pinion_m.len() && v.iter().all(|x| x.is_finite() && *x >= 0.0)
            };
            if !(ok(&b.increment_pinion_m) && ok(&b.increment_gear_m)) {
                return Err(StoredRunError::Mismatch(format!(
                    "update {j}: bin {}'s wear per cycle is not one finite value >= 0 per profile point",
                    i + 1
                )));
            }
        }
        if let Some(i) = bins.iter().position(|b| b.wear != wear) {
            return Err(StoredRunError::Mismatch(format!(
                "update {j}: the log of bin {} holds another wear state than bin 1's",
                i + 1
            )));
        }
        let record = match run.records.last() {
            None => SpectrumRecord {
                roughness_um: bins[0].roughness_um,
                by_bin_pinion_m: vec![vec![0.0; wear.pinion_m.len()]; sm.len()],
                by_bin_gear_m: vec![vec![0.0; wear.gear_m.len()]; sm.len()],
                wear,
                bins,
            },
            Some(prev) => {
                // A helical pair's block is recomputed, as its single-point chain is
                // (`study::wear_check`), so every face slice of every record is the
                // replayed one bit for bit, its cycles included.
                let n = if sm.bins[0].helical.is_some() {
                    super::wear::block_after(sm, prev, &run.shares).ok_or_else(|| {
                        StoredRunError::Mismatch(format!(
                            "update {j}: it follows an update where wear.total_cycles is reached"
                        ))
                    })?
                } else {
                    wear.cycles - prev.wear.cycles
                };
                let mut next = super::wear::advance(prev, &run.shares, n);
                if next.wear != wear {
                    return Err(StoredRunError::Mismatch(format!(
                        "update {j}: the wear is not the previous wear advanced by every bin's share of the block"
                    )));
                }
                next.roughness_um = bins[0].roughness_um;
                next.bins = bins;
                next
            }
        };
        run.records.push(record);
    }
    // The physics of each bin's records (grid, finite values, roughness law, end states)
    // and of the spectrum's chain, read as single-point runs.
    for (i, m) in sm.bins.iter().enumerate() {
        let mut view = super::contribution::combined_run(&run, i);
        for (v, b) in view.records.iter_mut().zip(&logs[i].records) {
            v.end_state = b.end_state.clone();
        }
        check_spectrum_view(&view, m)
            .map_err(|e| StoredRunError::Mismatch(format!("bin {}: {e}", i + 1)))?;
    }
    Ok(run)
}
