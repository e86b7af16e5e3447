//! The checkpoints of a train's wear runs: one log per mode and mesh
//! (`checkpoint_MODE_stageK.jsonl`, each an ordinary wear run's records:
//! `store::part_logs`), appended after every update of the whole train; where each run
//! starts when it resumes (the logs replayed and recomputed before anything else is
//! computed: `study::train_wear_check`).

use super::observer::Observer;
use super::part_checkpoints::{starting_part_runs, Parts};
use super::JobError;
use crate::io::OutputDir;
use crate::store::part_logs::{PartLogs, PartStarts};
use crate::study::train::TrainModel;
use crate::study::train_wear::TrainWearRun;
use crate::study::train_wear_check::{train_run_from_logs, verify_train_resumable};
use crate::study::wear_loop::{WearMode, WearRun};
use crate::study::Model;

/// File name of the checkpoint of mesh `m` (0-based: stage m + 1) of a mode's train run.
pub fn mesh_checkpoint_name(mode: WearMode, m: usize) -> String {
    format!("checkpoint_{}_stage{}.jsonl", mode.name(), m + 1)
}

/// The names of a mode's mesh logs, in stage order.
fn names(mode: WearMode, stages: usize) -> Vec<String> {
    (0..stages).map(|m| mesh_checkpoint_name(mode, m)).collect()
}

/// The run of each of `modes`: afresh, or (resuming from `resume_from`) read back from
/// its mesh logs, which must belong to this case and mode (their headers), replay to a
/// run of this train and reproduce its recomputed updates (logs of unequal length: the
/// updates every log holds), as `part_checkpoints::starting_part_runs` reads them.
pub fn starting_runs(
    model: &Model,
    train: &TrainModel,
    modes: &[WearMode],
    resume_from: Option<&OutputDir>,
    case_sha256: &str,
    observer: &dyn Observer,
) -> Result<Vec<TrainWearRun>, JobError> {
    let stages = train.stages.len();
    let parts = Parts {
        what: "the train's meshes",
        names: &|m| names(m, stages),
        shown: &|m| names(m, stages).join(", "),
        part: "a stage",
        max_bytes: &|m| crate::study::budget::max_checkpoint_bytes(&model.case, m),
    };
    let replay = |m: WearMode, logs: Vec<WearRun>| {
        train_run_from_logs(model, train, m, &logs)
            .and_then(|run| verify_train_resumable(model, train, &run).map(|_| run))
            .map_err(|e| e.to_string())
    };
    starting_part_runs(
        resume_from,
        modes,
        &parts,
        case_sha256,
        (&TrainWearRun::new, &replay),
        observer,
    )
}

/// One log per mode and mesh in `out`, started from the runs `runs` start at.
pub fn open_logs(
    out: &mut OutputDir,
    runs: &[TrainWearRun],
    stages: usize,
    case_sha256: &str,
) -> Result<PartLogs, JobError> {
    let starts: Vec<PartStarts> = runs
        .iter()
        .map(|run| {
            let parts = (0..stages)
                .map(|m| {
                    let mesh = WearRun {
                        mode: run.mode,
                        records: run.mesh_records(m),
                        stopped: None,
                    };
                    (mesh_checkpoint_name(run.mode, m), mesh)
                })
                .collect();
            (run.mode, parts)
        })
        .collect();
    Ok(PartLogs::open(out, case_sha256, &starts)?)
}
