//! The wear runs of a job under a load spectrum: where each starts (afresh, or resumed
//! from its bin logs, checked before anything is computed: `duty::resume`), a checkpoint
//! log per mode and bin appended after every update, progress per mode, cancellation.

use super::observer::{keep_going, Observer};
use super::part_checkpoints::{starting_part_runs, Parts};
use super::wear_runs::{mode_tasks, report_update, Runs};
use super::{publish, JobError};
use crate::duty::resume::from_bin_runs;
use crate::duty::wear::SpectrumRun;
use crate::duty::SpectrumModel;
use crate::io::OutputDir;
use crate::store::part_logs::{PartLogs, PartStarts};
use crate::store::RunMetadata;
use crate::study::wear_loop::{WearMode, WearRun};
use std::path::Path;

/// File name of the checkpoint of bin `i` (0-based) of a mode's spectrum run.
pub fn bin_checkpoint_name(mode: WearMode, i: usize) -> String {
    format!("checkpoint_{}_bin{}.jsonl", mode.name(), i + 1)
}

/// The runs of `modes`: fresh, or (resuming from `resume_from`) read back from their bin
/// logs (`part_checkpoints::starting_part_runs`), replayed by `duty::resume` and
/// recomputed by `duty::verify`.
fn starting_runs(
    sm: &SpectrumModel,
    modes: &[WearMode],
    resume_from: Option<&OutputDir>,
    case_sha256: &str,
    observer: &dyn Observer,
) -> Result<Vec<SpectrumRun>, JobError> {
    let fresh = |m: WearMode| SpectrumRun::new(m, sm.shares.clone());
    let parts = Parts {
        what: "the spectrum's bins",
        names: &|m| (0..sm.len()).map(|i| bin_checkpoint_name(m, i)).collect(),
        shown: &|m| bin_checkpoint_name(m, 0),
        part: "a bin",
        max_bytes: &|m| crate::study::budget::max_checkpoint_bytes(&sm.case, m),
    };
    let replay = |m: WearMode, logs: Vec<WearRun>| {
        let run = from_bin_runs(sm, m, &logs).map_err(|e| e.to_string())?;
        crate::duty::verify::verify_spectrum_run(sm, &run).map_err(|e| e.to_string())?;
        Ok(run)
    };
    starting_part_runs(
        resume_from,
        modes,
        &parts,
        case_sha256,
        (&fresh, &replay),
        observer,
    )
}

/// One log per mode and bin, started from the run it starts at (a resumed run's logs are
/// cut back to the updates every bin holds; a fresh run's start with the first update).
fn open_logs(
    out: &mut OutputDir,
    runs: &[SpectrumRun],
    case_sha256: &str,
) -> Result<PartLogs, JobError> {
    let starts: Vec<PartStarts> = runs
        .iter()
        .map(|run| {
            let parts = (0..run.shares.len())
                .map(|i| {
                    let name = bin_checkpoint_name(run.mode, i);
                    let start = if run.records.is_empty() {
                        WearRun::new(run.mode)
                    } else {
                        crate::duty::contribution::bin_run(run, i)
                    };
                    (name, start)
                })
                .collect();
            (run.mode, parts)
        })
        .collect();
    Ok(PartLogs::open(out, case_sha256, &starts)?)
}

/// As `app::wear_runs::run_modes` for a spectrum: the starting runs, the output folder with a
/// checkpoint log per mode and bin, a progress task per mode, and `study` run with a
/// callback that checkpoints, reports progress and stops on request after every update.
pub fn run_spectrum_job_modes<T>(
    command: &str,
    sm: &SpectrumModel,
    modes: &[WearMode],
    meta: &RunMetadata,
    (out, resume, replace): (Option<&Path>, bool, bool),
    observer: &dyn Observer,
    study: impl FnOnce(
        &SpectrumModel,
        Vec<SpectrumRun>,
        &(dyn Fn(WearMode, &SpectrumRun) -> anyhow::Result<()> + Sync),
    ) -> anyhow::Result<T>,
) -> Result<Runs<T>, JobError> {
    if let (Some(o), true) = (out, resume) {
        super::checkpoints::require_folder(o)?;
    }
    // The folder first, then the checkpoints in it (read through its handle).
    let mut dir = publish::open_if(out, None, command, replace)?;
    let resume_from = dir.as_ref().filter(|_| resume);
    let starts = starting_runs(sm, modes, resume_from, &meta.case_sha256, observer)?;
    let logs = match dir.as_mut() {
        Some(d) => Some(open_logs(d, &starts, &meta.case_sha256)?),
        None => None,
    };
    let root = dir.as_ref().map(|d| d.root().to_path_buf());
    let tasks = mode_tasks(modes, sm.case.wear.total_cycles);
    for t in &tasks {
        observer.start(t);
    }
    let on_update = |mode: WearMode, run: &SpectrumRun| -> anyhow::Result<()> {
        if let (Some(logs), Some(root)) = (&logs, &root) {
            logs.record(mode, run.records.len(), &|i, j| &run.records[j].bins[i])?;
            observer.checkpoint(&root.join(bin_checkpoint_name(mode, 0)));
        }
        if let Some(r) = run.last() {
            report_update(observer, &tasks, mode, run.records.len() - 1, &r.wear);
        }
        keep_going(observer)
    };
    let result = study(sm, starts, &on_update);
    for t in &tasks {
        observer.finish(t);
    }
    drop(logs);
    Ok(Runs {
        runs: result?,
        out: dir,
    })
}
