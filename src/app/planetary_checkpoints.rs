//! The checkpoints of a planetary set's wear runs: one log per mode and mesh
//! (`checkpoint_MODE_sun_planet_N.jsonl`, `checkpoint_MODE_ring_planet_N.jsonl`, each an
//! ordinary wear run's records: `store::part_logs`), appended after every update of the
//! whole set; where each run starts when it resumes (the logs replayed and recomputed
//! before anything else is computed: `study::planetary_wear_check`).

use super::observer::Observer;
use super::part_checkpoints::{starting_part_runs, Parts};
use super::JobError;
use crate::io::OutputDir;
use crate::store::part_logs::{PartLogs, PartStarts};
use crate::study::budget::planetary::max_planetary_checkpoint_bytes;
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::study::planetary_wear_check::{
    planetary_mesh_name, planetary_run_from_logs, verify_planetary_resumable,
};
use crate::study::planetary_wear_loop::PlanetaryWearRun;
use crate::study::wear_loop::{WearMode, WearRun};

/// File name of the checkpoint of mesh `j` (module order) of a mode's planetary run.
pub fn planetary_checkpoint_name(model: &PlanetaryWearModel, mode: WearMode, j: usize) -> String {
    format!(
        "checkpoint_{}_{}.jsonl",
        mode.name(),
        planetary_mesh_name(model, j)
    )
}

/// The names of a mode's mesh logs, in module order.
fn names(model: &PlanetaryWearModel, mode: WearMode) -> Vec<String> {
    (0..2 * model.planets())
        .map(|j| planetary_checkpoint_name(model, mode, j))
        .collect()
}

/// The run of each of `modes`: afresh, or (resuming from `resume_from`) read back from
/// its mesh logs, which must belong to this case and mode (their headers), replay to a
/// run of this set and reproduce its recomputed updates (logs of unequal length: the
/// updates every log holds), as `part_checkpoints::starting_part_runs` reads them.
pub fn starting_runs(
    model: &PlanetaryWearModel,
    wear: &crate::config::case::WearSection,
    modes: &[WearMode],
    resume_from: Option<&OutputDir>,
    case_sha256: &str,
    observer: &dyn Observer,
) -> Result<Vec<PlanetaryWearRun>, JobError> {
    let max = resume_from.map_or(0, |_| max_planetary_checkpoint_bytes(model, wear));
    let parts = Parts {
        what: "the planetary set's meshes",
        names: &|m| names(model, m),
        shown: &|m| format!("{}, ...", planetary_checkpoint_name(model, m, 0)),
        part: "a mesh",
        max_bytes: &|_| max,
    };
    let replay = |m: WearMode, logs: Vec<WearRun>| {
        planetary_run_from_logs(model, wear, m, &logs)
            .and_then(|run| verify_planetary_resumable(model, &run).map(|_| run))
    };
    starting_part_runs(
        resume_from,
        modes,
        &parts,
        case_sha256,
        (&PlanetaryWearRun::new, &replay),
        observer,
    )
}

/// One log per mode and mesh in `out`, started from the runs `runs` start at.
pub fn open_logs(
    out: &mut OutputDir,
    model: &PlanetaryWearModel,
    runs: &[PlanetaryWearRun],
    case_sha256: &str,
) -> Result<PartLogs, JobError> {
    let starts: Vec<PartStarts> = runs
        .iter()
        .map(|run| {
            let parts = (0..2 * model.planets())
                .map(|j| {
                    let mesh = WearRun {
                        mode: run.mode,
                        records: run.updates.iter().map(|u| u.meshes[j].clone()).collect(),
                        stopped: None,
                    };
                    (planetary_checkpoint_name(model, run.mode, j), mesh)
                })
                .collect();
            (run.mode, parts)
        })
        .collect();
    Ok(PartLogs::open(out, case_sha256, &starts)?)
}
