//! A train's wear run read back from its checkpoints (one log per mesh, each an ordinary
//! wear run's records: `store::checkpoint`), and whether this model computes it. The
//! files are never trusted for what they say about themselves:
//!
//! - **Replayed** ([`train_run_from_logs`]): the input cycles and the mesh that cut each
//!   block are not stored, they are recomputed from the update before with the loop's own
//!   step (`train_wear::next_block`), and every mesh's stored wear must equal the previous
//!   update's advanced over that block bit for bit (the first update: new teeth at input
//!   cycle 0). Each record's shape is checked first (one value per grid point of its
//!   stage, a profile per tooth exactly on a stage with a tooth fault, finite and >= 0
//!   rates, the roughness the case's law gives at its wear, the
//!   periodic end state with mesh 1's record in the dynamic mode and nowhere else).
//!   Logs of unequal length (a kill between the appends of one update) are cut to the
//!   updates every log holds.
//! - **Recomputed** ([`verify_train_resumable`]): the first and last updates and a random
//!   sample of the others (at most `wear_check::MAX_RECOMPUTED` in all) are computed again
//!   from the update before, the whole train's response with every mesh, and must equal
//!   the stored records bit for bit (compared as JSON, which carries every double
//!   exactly): a record of another case, an edit with recomputed checksums, or a stage's
//!   log copied over another's is refused, naming the update and its line.

use super::model::Model;
use super::train::TrainModel;
use super::train_wear::{
    new_teeth, next_block, next_train_update, Block, TrainNext, TrainUpdate, TrainWearRun,
};
use super::wear_check::{random_sample, tooth_problem_of, MAX_RECOMPUTED};
use super::wear_loop::{UpdateRecord, WearMode, WearRun};

/// Why a train's mesh logs are not a run this case's model computes (see the module docs).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TrainRunError {
    /// Not one log per stage.
    #[error("{logs} mesh logs for a train of {stages} stages")]
    StageCount {
        /// Logs given.
        logs: usize,
        /// Stages of the train.
        stages: usize,
    },
    /// An update that is not what the model computes from the update before it.
    #[error(
        "update {update} (line {line}){}: {problem}",
        stage.map_or(String::new(), |s| format!(", stage {s}"))
    )]
    Update {
        /// The update, 0-based (0: new teeth).
        update: usize,
        /// Its line in the logs (the header is line 1).
        line: usize,
        /// The stage (1-based) whose record is at fault; `None`: the update as a whole.
        stage: Option<usize>,
        /// What is wrong.
        problem: String,
    },
}

impl TrainRunError {
    /// Update `update` (0-based) is wrong, in the record of `stage` (0-based; `None`: the
    /// update as a whole): its line is `update` + 2 (the header is line 1).
    fn update(update: usize, stage: Option<usize>, problem: impl Into<String>) -> Self {
        TrainRunError::Update {
            update,
            line: update + 2,
            stage: stage.map(|m| m + 1),
            problem: problem.into(),
        }
    }
}

/// What is wrong with the shape of mesh `m`'s record `r` (see the module docs), if anything.
pub(crate) fn record_problem(
    model: &Model,
    train: &TrainModel,
    mode: WearMode,
    m: usize,
    r: &UpdateRecord,
) -> Option<String> {
    if let Some(p) = r.profile_problem(train.stages[m].grid.len()) {
        return Some(p);
    }
    let s = &train.stages[m];
    let resolved = s
        .tooth_inputs
        .as_ref()
        .map(|_| [s.pair.pinion.teeth, s.pair.gear.teeth]);
    let whose = ("the stage", "a tooth fault on it, `fault.stage`");
    if let Some(p) = tooth_problem_of(resolved, s.grid.len(), r, whose) {
        return Some(p);
    }
    if r.path_rho1_m.len() != r.path_load_n.len() {
        return Some("path positions and loads differ in length".into());
    }
    let len = model.state_len();
    match (mode == WearMode::Dynamic && m == 0, &r.end_state) {
        (true, Some(y)) if y.len() == len && y.iter().all(|v| v.is_finite()) => {}
        (true, _) => {
            return Some(format!(
                "stage 1's record of a dynamic update must hold the train's periodic end state ({len} finite numbers)"
            ))
        }
        (false, None) => {}
        (false, Some(_)) => {
            return Some(if mode == WearMode::Dynamic {
                "holds a periodic end state, which a train keeps with stage 1's record only".into()
            } else {
                "holds a dynamic end state: this is a dynamic run's record, not a quasi-static one"
                    .into()
            })
        }
    }
    let want = model.roughness_for(&r.wear);
    (r.roughness_um != want).then(|| {
        format!(
            "roughness {} µm is not the case's {want} µm at this wear depth",
            r.roughness_um
        )
    })
}

/// The train's run of `mode` whose mesh logs are `logs` (stage order), replayed and
/// checked against `model` (see the module docs); the error names the update, its line
/// in the logs (the header is line 1) and the stage.
pub fn train_run_from_logs(
    model: &Model,
    train: &TrainModel,
    mode: WearMode,
    logs: &[WearRun],
) -> Result<TrainWearRun, TrainRunError> {
    if logs.len() != train.stages.len() {
        return Err(TrainRunError::StageCount {
            logs: logs.len(),
            stages: train.stages.len(),
        });
    }
    let n = logs.iter().map(|l| l.records.len()).min().unwrap_or(0);
    let mut run = TrainWearRun::new(mode);
    for j in 0..n {
        let at = |m: usize, what: String| TrainRunError::update(j, Some(m), what);
        let meshes: Vec<UpdateRecord> = logs.iter().map(|l| l.records[j].clone()).collect();
        for (m, r) in meshes.iter().enumerate() {
            if let Some(p) = record_problem(model, train, mode, m, r) {
                return Err(at(m, p));
            }
        }
        let block = match run.updates.last() {
            None => Block {
                input_cycles: 0.0,
                limited_by: None,
                wears: new_teeth(train),
            },
            Some(prev) => next_block(model, train, prev).ok_or_else(|| {
                TrainRunError::update(
                    j,
                    None,
                    "the run had reached wear.total_cycles at the update before it",
                )
            })?,
        };
        for (m, (r, w)) in meshes.iter().zip(&block.wears).enumerate() {
            if r.wear != *w {
                return Err(at(
                    m,
                    if j == 0 {
                        "its wear is not the new teeth at cycle 0".to_string()
                    } else {
                        format!(
                            "its wear is not the previous update's advanced over the block to {} input cycles at the previous rate",
                            block.input_cycles
                        )
                    },
                ));
            }
        }
        run.updates.push(TrainUpdate {
            input_cycles: block.input_cycles,
            meshes,
            limited_by: block.limited_by,
        });
    }
    Ok(run)
}

/// Recompute updates of `run` (replayed by [`train_run_from_logs`]) and require them equal
/// to the stored ones (see the module docs); the error names the first that is not.
pub fn verify_train_resumable(
    model: &Model,
    train: &TrainModel,
    run: &TrainWearRun,
) -> Result<(), TrainRunError> {
    let n = run.updates.len();
    for i in random_sample(n, MAX_RECOMPUTED, &[0, n.saturating_sub(1)]) {
        let prev = i.checked_sub(1).map(|j| &run.updates[j]);
        let stored = &run.updates[i];
        let again = match next_train_update(model, train, run.mode, prev) {
            Ok(TrainNext::Update(u)) => *u,
            Ok(_) | Err(_) => {
                return Err(TrainRunError::update(
                    i,
                    None,
                    "this case's model makes no such update when it is recomputed from the update before it: the records are not this case's",
                ))
            }
        };
        let json = |r: &UpdateRecord| serde_json::to_string(r).ok();
        let differs = again
            .meshes
            .iter()
            .zip(&stored.meshes)
            .position(|(a, b)| json(a) != json(b));
        if let Some(m) = differs {
            let (a, b) = (&again.meshes[m], &stored.meshes[m]);
            return Err(TrainRunError::update(i, Some(m), format!(
                "not what this case's model computes from the update before it, the whole train recomputed (recomputed: max pinion wear rate {:.6e} m per cycle, mean mesh force {:.6} N; stored: {:.6e} m, {:.6} N): the records are not this case's, or were edited",
                a.max_increment_pinion_m(),
                a.summary.mesh_force_mean_n,
                b.max_increment_pinion_m(),
                b.summary.mesh_force_mean_n,
            )));
        }
        if (again.input_cycles, again.limited_by) != (stored.input_cycles, stored.limited_by) {
            return Err(TrainRunError::update(
                i,
                None,
                "its block is not the one this case's model takes",
            ));
        }
    }
    Ok(())
}
