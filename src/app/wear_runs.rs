//! The steps every wear study of a job shares (the wear job, the paper's study, the runs
//! under a load spectrum): where each run starts, the checkpoint logs, a progress task per
//! mode, progress after every update, and the early stops told to the observer.

use super::checkpoints::{open_checkpoints, starting_runs};
use super::observer::{keep_going, Observer, Task, Unit};
use super::{publish, JobError};
use crate::store::checkpoint::checkpoint_name;
use crate::store::checkpoint_set::CheckpointSet;
use crate::store::RunMetadata;
use crate::study::wear_loop::{StopKind, WearMode, WearRun, WearStop};
use crate::study::Model;

/// The wear runs of a job, and its output folder still to publish.
pub struct Runs<T> {
    /// The wear runs (one per mode, or a train's).
    pub runs: T,
    /// The output folder, its results not yet published (`None`: nothing written).
    pub out: Option<crate::io::OutputDir>,
}

/// The steps every wear study shares (the wear job, the paper's study): where each run
/// starts (afresh, or from its checkpoint), the output folder with its checkpoint logs,
/// a progress task per mode, and `study` run with a callback that checkpoints, reports
/// progress and stops on request after every update.
pub fn run_modes<T>(
    command: &str,
    model: &Model,
    modes: &[WearMode],
    meta: &RunMetadata,
    (out, resume, replace): (Option<&std::path::Path>, bool, bool),
    observer: &dyn Observer,
    study: impl FnOnce(
        &Model,
        Vec<WearRun>,
        &(dyn Fn(WearMode, &WearRun) -> anyhow::Result<()> + Sync),
    ) -> anyhow::Result<T>,
) -> Result<Runs<T>, JobError> {
    if let (Some(o), true) = (out, resume) {
        super::checkpoints::require_folder(o)?;
    }
    // The folder first (locked, its state read through its handle), then the checkpoints
    // in it, each verified before anything runs.
    let mut dir = publish::open_if(out, None, command, replace)?;
    let starts = starting_runs(
        dir.as_ref(),
        modes,
        resume,
        &meta.case_sha256,
        model,
        observer,
    )?;
    let logs: Option<CheckpointSet> = match dir.as_mut() {
        Some(d) => Some(open_checkpoints(d, &starts, &meta.case_sha256)?),
        None => None,
    };
    let root = dir.as_ref().map(|d| d.root().to_path_buf());
    let tasks = mode_tasks(modes, model.case.wear.total_cycles);
    for t in &tasks {
        observer.start(t);
    }
    let on_update = |mode: WearMode, run: &WearRun| -> anyhow::Result<()> {
        if let (Some(logs), Some(root)) = (&logs, &root) {
            logs.record(run)?;
            observer.checkpoint(&root.join(checkpoint_name(mode)));
        }
        if let Some(r) = run.last() {
            report_update(observer, &tasks, mode, run.records.len() - 1, &r.wear);
        }
        keep_going(observer)
    };
    let result = study(model, starts, &on_update);
    for t in &tasks {
        observer.finish(t);
    }
    drop(logs);
    Ok(Runs {
        runs: result?,
        out: dir,
    })
}

/// A progress task per wear mode, in load cycles up to `total`.
pub fn mode_tasks(modes: &[WearMode], total: f64) -> Vec<Task> {
    modes
        .iter()
        .map(|m| Task {
            id: m.name(),
            label: m.label(),
            total,
            unit: Unit::Cycles,
        })
        .collect()
}

/// Progress of `mode`'s run: `updates` made, now at `wear`.
pub fn report_update(
    observer: &dyn Observer,
    tasks: &[Task],
    mode: WearMode,
    updates: usize,
    wear: &crate::wear::WearState,
) {
    if let Some(t) = tasks.iter().find(|t| t.id == mode.name()) {
        let status = format!(
            "{updates} updates, max pinion wear {:.3} µm",
            wear.max_pinion_m() * 1e6
        );
        observer.advance(t, wear.cycles, &status);
    }
}

/// Tell `observer` about every wear run that stopped early (its outputs are written up to
/// the stop). A stop because the worn teeth left the model's domain is a result; one for
/// want of a steady state is a failure of the solver the user should act on: returned.
pub fn stops(runs: &[&WearRun], observer: &dyn Observer) -> Option<String> {
    let modes: Vec<(WearMode, Option<&WearStop>)> =
        runs.iter().map(|r| (r.mode, r.stopped.as_ref())).collect();
    stops_of(&modes, observer)
}

/// [`stops`] of any wear runs, each given by its mode and its stop.
pub fn stops_of(runs: &[(WearMode, Option<&WearStop>)], observer: &dyn Observer) -> Option<String> {
    let mut failed = None;
    for (mode, stopped) in runs {
        if let Some(stop) = stopped {
            let message = format!(
                "the {} wear run stopped early: {}",
                mode.name(),
                stop.reason
            );
            observer.warning(&message);
            if stop.kind == StopKind::Numerical {
                failed = Some(message);
            }
        }
    }
    failed
}
