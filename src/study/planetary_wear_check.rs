//! A planetary set's wear run read back from its checkpoints (one log per mesh, each an
//! ordinary wear run's records: `store::part_logs`), and whether this model computes it.
//! As for a train's logs (`study::train_wear_check`), nothing the files say about the run
//! is trusted:
//!
//! - **Replayed** (`planetary_run_from_logs`): each record's shape is checked (one value
//!   per point of its mesh's grid, finite and >= 0, none of what a planetary mesh's record
//!   leaves empty: `planetary_wear_loop::mesh_record`; per-tooth increments exactly on a
//!   faulty member's meshes: `planetary_teeth::teeth_problem`); the input cycles and the member
//!   flank that cut each block are not stored, they are recomputed from the update before
//!   with the loop's own step (`planetary_wear_loop::next_block`), and every mesh's stored
//!   wear must equal the previous update's advanced over that block bit for bit (the
//!   first update: new teeth at input cycle 0). Logs of unequal length (a kill between
//!   the appends of one update) are cut to the updates every log holds.
//! - **Recomputed** (`verify_planetary_resumable`): the first and last updates and a
//!   random sample of the others (at most `wear_check::MAX_RECOMPUTED` in all) are
//!   computed again from the update before, the whole set's response with every mesh,
//!   and must equal the stored records bit for bit (compared as JSON, which carries every
//!   double exactly): a record of another case, an edit with recomputed checksums, or a
//!   mesh's log copied over another's is refused, naming the update, its line and mesh.

use super::planetary_teeth::teeth_problem;
use super::planetary_wear::{new_teeth, PlanetaryWearModel};
use super::planetary_wear_loop::{next_block, update_of, PlanetaryUpdate, PlanetaryWearRun};
use super::wear_check::{random_sample, MAX_RECOMPUTED};
use super::wear_loop::{UpdateRecord, WearMode, WearRun};
use crate::config::case::WearSection;

/// Mesh `j`'s name in messages and file names, e.g. `ring_planet_3` (module order: the
/// sun meshes of planets 1..N, then their ring meshes).
pub fn planetary_mesh_name(model: &PlanetaryWearModel, j: usize) -> String {
    let (kind, p) = model.kind_of(j);
    format!("{}_planet_{}", ["sun", "ring"][kind], p + 1)
}

/// What is wrong with the shape of mesh `j`'s record `r` (see the module docs), if anything.
pub(crate) fn record_problem(
    model: &PlanetaryWearModel,
    j: usize,
    r: &UpdateRecord,
) -> Option<String> {
    if let Some(p) = r.profile_problem(model.grids[model.kind_of(j).0].len()) {
        return Some(p);
    }
    if r.wear.teeth.is_some() {
        return Some(
            "holds per-tooth wear depths, but a planetary set's wear state is each member's mean"
                .into(),
        );
    }
    if let Some(p) = teeth_problem(model, j, r.increment_teeth.as_ref()) {
        return Some(p);
    }
    if r.end_state.is_some() {
        return Some(
            "holds a periodic end state, which a planetary set's records never keep".into(),
        );
    }
    if !r.path_rho1_m.is_empty() || !r.path_load_n.is_empty() {
        return Some("holds path loads, which a planetary set's records never keep".into());
    }
    (r.roughness_um != 0.0).then(|| {
        format!(
            "roughness {} µm: a planetary set's records hold 0 (its model has no friction)",
            r.roughness_um
        )
    })
}

/// The run of `mode` whose mesh logs are `logs` (module order), replayed and checked
/// against `model` (see the module docs); the error names the update, its line in the
/// logs (the header is line 1) and the mesh.
pub(crate) fn planetary_run_from_logs(
    model: &PlanetaryWearModel,
    wear: &WearSection,
    mode: WearMode,
    logs: &[WearRun],
) -> Result<PlanetaryWearRun, String> {
    let meshes = 2 * model.planets();
    if logs.len() != meshes {
        return Err(format!(
            "{} mesh logs for a set of {meshes} meshes",
            logs.len()
        ));
    }
    let n = logs.iter().map(|l| l.records.len()).min().unwrap_or(0);
    let mut run = PlanetaryWearRun::new(mode);
    for i in 0..n {
        let at = |j: usize, what: &str| {
            format!(
                "update {i} (line {}), mesh {}: {what}",
                i + 2,
                planetary_mesh_name(model, j)
            )
        };
        let records: Vec<UpdateRecord> = logs.iter().map(|l| l.records[i].clone()).collect();
        if let Some((j, p)) = records
            .iter()
            .enumerate()
            .find_map(|(j, r)| record_problem(model, j, r).map(|p| (j, p)))
        {
            return Err(at(j, &p));
        }
        let (input_cycles, limited_by, wears) = match run.updates.last() {
            None => (0.0, None, new_teeth(model)),
            Some(prev) => next_block(model, wear, prev).ok_or_else(|| {
                format!(
                    "update {i} (line {}): the run had reached wear.total_cycles at the update before it",
                    i + 2
                )
            })?,
        };
        if let Some(j) = records.iter().zip(&wears).position(|(r, w)| r.wear != *w) {
            return Err(at(
                j,
                &if i == 0 {
                    "its wear is not the new teeth at cycle 0".to_string()
                } else {
                    format!("its wear is not the previous update's advanced over the block to {input_cycles} input cycles at the previous rate")
                },
            ));
        }
        run.updates.push(PlanetaryUpdate {
            input_cycles,
            meshes: records,
            limited_by,
        });
    }
    Ok(run)
}

/// Recompute updates of `run` (replayed by [`planetary_run_from_logs`]) and require them
/// equal to the stored ones (see the module docs); the error names the first that is not.
pub(crate) fn verify_planetary_resumable(
    model: &PlanetaryWearModel,
    run: &PlanetaryWearRun,
) -> Result<(), String> {
    let n = run.updates.len();
    let json = |r: &UpdateRecord| serde_json::to_string(r).ok();
    for i in random_sample(n, MAX_RECOMPUTED, &[0, n.saturating_sub(1)]) {
        let stored = &run.updates[i];
        let line = i + 2;
        // The replay put this update's cycles, cutting flank and wear where the loop's
        // own step puts them; the response is what is recomputed here.
        let wears = stored.meshes.iter().map(|r| r.wear.clone()).collect();
        let again = update_of(
            model,
            run.mode,
            (stored.input_cycles, stored.limited_by),
            wears,
        )
        .map_err(|(e, _)| {
            format!("update {i} (line {line}): this case's model makes no such update when it is recomputed from the update before it ({e}): the records are not this case's")
        })?;
        let differs = again
            .meshes
            .iter()
            .zip(&stored.meshes)
            .position(|(a, b)| json(a) != json(b));
        if let Some(j) = differs {
            let (a, b) = (&again.meshes[j], &stored.meshes[j]);
            return Err(format!(
                "update {i} (line {line}), mesh {}: not what this case's model computes from the update before it, the whole set recomputed (recomputed: max pinion wear rate {:.6e} m per cycle, mean mesh force {:.6} N; stored: {:.6e} m, {:.6} N): the records are not this case's, or were edited",
                planetary_mesh_name(model, j),
                a.max_increment_pinion_m(),
                a.summary.mesh_force_mean_n,
                b.max_increment_pinion_m(),
                b.summary.mesh_force_mean_n,
            ));
        }
    }
    Ok(())
}
