//! The checkpoints of a train's wear runs: one log per mode and mesh
//! (`checkpoint_MODE_stageK.jsonl`, each an ordinary wear run's records:
//! `store::part_logs`), appended after every update of the whole train; where each run
//! starts when it resumes (the logs replayed and recomputed before anything else is
//! computed: `study::train_wear_check`).

use super::observer::Observer;
use super::JobError;
use crate::io::OutputDir;
use crate::remedy::{Arg, Problem, Remedy};
use crate::store::part_logs::{load_parts, PartLogs, PartStarts};
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

/// A refusal to resume from the logs of `mode` in `dir`, saying why.
fn refused(dir: &std::path::Path, mode: WearMode, stages: usize, why: &str) -> JobError {
    Problem::of(
        Arg::Resume,
        format!(
            "{}: the {} checkpoints of the train's meshes ({}): {why}; they cannot be resumed",
            dir.display(),
            mode.label(),
            names(mode, stages).join(", "),
        ),
    )
    .remedy(Remedy::start_afresh().path(dir))
    .into()
}

/// The run of each of `modes`: afresh, or (resuming from `resume_from`) read back from
/// its mesh logs, which must belong to this case and mode (their headers), replay to a
/// run of this train and reproduce its recomputed updates (logs of unequal length: the
/// updates every log holds). A mode without logs, or with only their headers, starts
/// afresh with a note; finding none at all is an error.
pub fn starting_runs(
    model: &Model,
    train: &TrainModel,
    modes: &[WearMode],
    resume_from: Option<&OutputDir>,
    case_sha256: &str,
    observer: &dyn Observer,
) -> Result<Vec<TrainWearRun>, JobError> {
    let Some(out) = resume_from else {
        return Ok(modes.iter().map(|m| TrainWearRun::new(*m)).collect());
    };
    let dir = out.root();
    let stages = train.stages.len();
    let mut starts = Vec::new();
    let mut found = false;
    for m in modes {
        let max = crate::study::budget::max_checkpoint_bytes(&model.case, *m);
        let logs = load_parts(out, &names(*m, stages), *m, case_sha256, max)
            .map_err(|e| JobError::from(e.problem()))?;
        if logs.iter().flatten().all(|l| l.records.is_empty()) {
            observer.note(&format!(
                "note: no {} checkpoint: that run starts afresh",
                m.label()
            ));
            starts.push(TrainWearRun::new(*m));
            continue;
        }
        found = true;
        let Some(logs) = logs.into_iter().collect::<Option<Vec<WearRun>>>() else {
            return Err(refused(dir, *m, stages, "the log of a stage is missing"));
        };
        let run = train_run_from_logs(model, train, *m, &logs)
            .and_then(|run| verify_train_resumable(model, train, &run).map(|_| run))
            .map_err(|e| refused(dir, *m, stages, &e.to_string()))?;
        starts.push(run);
    }
    if !found {
        return Err(Problem::of(
            Arg::Resume,
            format!(
                "no checkpoint to resume from in {} (looked for {} and their .partial files)",
                dir.display(),
                names(modes[0], stages).join(", ")
            ),
        )
        .remedy(Remedy::start_afresh().path(dir))
        .into());
    }
    Ok(starts)
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
