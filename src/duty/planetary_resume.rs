//! A planetary set's run under a spectrum read back from its checkpoints: one log per bin
//! and mesh, each an ordinary wear run's records (bin i's view of mesh j: the shared
//! flank with bin i's response and wear per pinion cycle), and whether this model
//! computes it. As for the set's own logs (`study::planetary_wear_check`), nothing the
//! files say about the run is trusted:
//!
//! - **Replayed** ([`from_logs`]): each record's shape is checked
//!   (`planetary_wear_check::record_problem`); the input cycles, the flank that cut each
//!   block and the wear each bin added are recomputed from the update before with the
//!   loop's own step (`duty::planetary::next_spectrum_block`), and every stored flank must
//!   equal the replayed one bit for bit (the first update: new teeth). Logs of unequal
//!   length are cut to the updates every log holds.
//! - **Recomputed** ([`verify`]): the first and last updates and a random sample of the
//!   others (at most `wear_check::MAX_RECOMPUTED`) are computed again from their replayed
//!   flanks, every bin's whole set, and must equal the stored records bit for bit
//!   (compared as JSON, which carries every double exactly).

use super::planetary::{new_record, next_spectrum_block, respond_bins, PlanetarySpectrum};
use super::planetary::{PlanetarySpectrumRecord, PlanetarySpectrumRun};
use crate::study::planetary_wear_check::{planetary_mesh_name, record_problem};
use crate::study::planetary_wear_loop::PlanetaryUpdate;
use crate::study::wear_check::{random_sample, StoredRunError, MAX_RECOMPUTED};
use crate::study::wear_loop::{UpdateRecord, WearMode, WearRun};
use crate::wear::WearState;

/// The wear and the record (without its bins) that update `j` must hold, replayed from
/// the update before it.
fn replayed(
    ps: &PlanetarySpectrum,
    run: &PlanetarySpectrumRun,
    j: usize,
) -> Result<(Vec<WearState>, PlanetarySpectrumRecord), StoredRunError> {
    match run.records.last() {
        None => Ok(new_record(ps)),
        Some(prev) => next_spectrum_block(ps, prev, &run.shares).ok_or_else(|| {
            StoredRunError::Mismatch(format!(
                "update {j} (line {}): the run had reached wear.total_cycles at the update before it",
                j + 2
            ))
        }),
    }
}

/// The run of `mode` whose logs are `logs` (`logs[i][j]`: bin i, mesh j), replayed and
/// checked (see the module docs); the error names the update, its line, bin and mesh.
pub fn from_logs(
    ps: &PlanetarySpectrum,
    mode: WearMode,
    logs: &[Vec<WearRun>],
) -> Result<PlanetarySpectrumRun, StoredRunError> {
    let (nb, nm) = (ps.bins(), ps.meshes());
    if logs.len() != nb || logs.iter().any(|l| l.len() != nm) {
        return Err(StoredRunError::Mismatch(format!(
            "the logs are not one per bin ({nb}) and mesh ({nm})"
        )));
    }
    let n = logs
        .iter()
        .flatten()
        .map(|l| l.records.len())
        .min()
        .unwrap_or(0);
    let mut run = PlanetarySpectrumRun::new(mode, ps.shares.clone());
    for j in 0..n {
        let (wears, mut next) = replayed(ps, &run, j)?;
        for (i, bin) in logs.iter().enumerate() {
            let meshes: Vec<UpdateRecord> = bin.iter().map(|l| l.records[j].clone()).collect();
            for (k, r) in meshes.iter().enumerate() {
                let at = |what: &str| {
                    StoredRunError::Mismatch(format!(
                        "update {j} (line {}), bin {}, mesh {}: {what}",
                        j + 2,
                        i + 1,
                        planetary_mesh_name(&ps.models[i], k)
                    ))
                };
                if let Some(p) = record_problem(&ps.models[i], k, r) {
                    return Err(at(&p));
                }
                if r.wear != wears[k] {
                    return Err(at(
                        "its wear is not the previous update's advanced over the block at every bin's previous rate",
                    ));
                }
            }
            next.bins.push(PlanetaryUpdate {
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
pub fn verify(ps: &PlanetarySpectrum, run: &PlanetarySpectrumRun) -> Result<(), StoredRunError> {
    let n = run.records.len();
    let json = |r: &UpdateRecord| serde_json::to_string(r).ok();
    for j in random_sample(n, MAX_RECOMPUTED, &[0, n.saturating_sub(1)]) {
        let line = j + 2;
        let stored = &run.records[j];
        // The replay put this update's cycles, cutting flank and wear where the loop's
        // own step puts them; the responses are what is recomputed here.
        let wears: Vec<WearState> = stored.bins[0]
            .meshes
            .iter()
            .map(|r| r.wear.clone())
            .collect();
        let again = respond_bins(ps, run.mode, (stored.input_cycles, stored.limited_by), &wears)
            .map_err(|s| {
                StoredRunError::Mismatch(format!("update {j} (line {line}): this case's model makes no such update when it is recomputed from the update before it ({}): the records are not this case's", s.reason))
            })?;
        for (i, (a, b)) in again.iter().zip(&stored.bins).enumerate() {
            if let Some(k) = a
                .meshes
                .iter()
                .zip(&b.meshes)
                .position(|(x, y)| json(x) != json(y))
            {
                return Err(StoredRunError::Mismatch(format!(
                    "update {j} (line {line}), bin {}, mesh {}: not what this case's model computes from the update before it: the records are not this case's, or were edited",
                    i + 1,
                    planetary_mesh_name(&ps.models[i], k)
                )));
            }
        }
    }
    Ok(())
}
