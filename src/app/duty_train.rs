//! The wear and run jobs on a gear train (`[[stage]]`) under a load spectrum
//! (`duty::train`): every bin is the train at the bin's operating point, every update
//! advances every mesh by every bin's share; a checkpoint log per mode, bin and mesh
//! (`checkpoint_MODE_binI_stageK.jsonl`, each an ordinary wear run's records) appended
//! after every update, and `--resume` continues from them once they are replayed and
//! recomputed (`duty::train_resume`). The results are the train's own
//! (`report::wear_train`, `report::run_train`) of the spectrum's run, read at the
//! monitoring bin, with what the spectrum adds (`report::duty_train`).

use super::duty::build_spectrum_model;
use super::observer::{keep_going, Observer};
use super::part_checkpoints::{starting_part_runs, Parts};
use super::wear_runs::{mode_tasks, report_update, Runs};
use super::wear_train::train_stops;
use super::{publish, JobError, Outcome};
use crate::duty::train::{
    combined_train_run, run_train_spectrum_modes, TrainSpectrum, TrainSpectrumRun,
};
use crate::duty::train_resume::{from_logs, verify};
use crate::duty::SpectrumModel;
use crate::dynamics::excitation::ExternalError;
use crate::io::OutputDir;
use crate::remedy::Problem;
use crate::report::duty_train::TrainDutyParts;
use crate::report::figure_output::FigureOutput;
use crate::report::run_train::{train_run_artifacts_with, TrainRun};
use crate::report::wear_train::train_wear_artifacts;
use crate::store::part_logs::{PartLogs, PartStarts};
use crate::store::RunMetadata;
use crate::study::train_stages::stage_models;
use crate::study::train_wear::TrainWearRun;
use crate::study::wear_loop::{WearMode, WearRun};
use crate::wear::WearState;
use std::path::Path;

/// File name of the checkpoint of bin `i` and mesh `k` (0-based) of a mode's run.
pub fn bin_mesh_checkpoint_name(mode: WearMode, i: usize, k: usize) -> String {
    format!(
        "checkpoint_{}_bin{}_stage{}.jsonl",
        mode.name(),
        i + 1,
        k + 1
    )
}

/// The names of a mode's logs, bin-major (bin 1's stages, then bin 2's, ...).
fn names(mode: WearMode, bins: usize, meshes: usize) -> Vec<String> {
    (0..bins)
        .flat_map(|i| (0..meshes).map(move |k| bin_mesh_checkpoint_name(mode, i, k)))
        .collect()
}

/// The trains of `sm`'s bins, or an input error.
fn trains(sm: &SpectrumModel) -> Result<TrainSpectrum<'_>, JobError> {
    TrainSpectrum::of(sm)
        .ok_or_else(|| JobError::input(Problem::new("this case has no [[stage]] tables")))
}

/// The run of each of `modes`: afresh, or read back from its logs in `resume_from`
/// (`part_checkpoints::starting_part_runs`, replayed and recomputed by `duty::train_resume`).
fn starting_runs(
    ts: &TrainSpectrum,
    modes: &[WearMode],
    resume_from: Option<&OutputDir>,
    case_sha256: &str,
    observer: &dyn Observer,
) -> Result<Vec<TrainSpectrumRun>, JobError> {
    let fresh = |m: WearMode| TrainSpectrumRun::new(m, ts.sm.shares.clone());
    let (nb, nk) = (ts.trains.len(), ts.meshes());
    let parts = Parts {
        what: "the train's meshes under the load spectrum",
        names: &|m| names(m, nb, nk),
        shown: &|m| bin_mesh_checkpoint_name(m, 0, 0),
        part: "a bin or stage",
        max_bytes: &|m| crate::study::budget::max_checkpoint_bytes(&ts.sm.case, m),
    };
    let replay = |m: WearMode, logs: Vec<WearRun>| {
        let by_bin: Vec<Vec<WearRun>> = logs.chunks(nk).map(|c| c.to_vec()).collect();
        from_logs(ts, m, &by_bin)
            .and_then(|run| verify(ts, &run).map(|_| run))
            .map_err(|e| e.to_string())
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

/// One log per mode, bin and mesh, started from the runs `runs` start at.
fn open_logs(
    out: &mut OutputDir,
    ts: &TrainSpectrum,
    runs: &[TrainSpectrumRun],
    case_sha256: &str,
) -> Result<PartLogs, JobError> {
    let nk = ts.meshes();
    let starts: Vec<PartStarts> = runs
        .iter()
        .map(|run| {
            let parts = (0..ts.trains.len())
                .flat_map(|i| {
                    let view = run.bin_run(i);
                    (0..nk)
                        .map(|k| {
                            let log = WearRun {
                                mode: run.mode,
                                records: view.mesh_records(k),
                                stopped: None,
                            };
                            (bin_mesh_checkpoint_name(run.mode, i, k), log)
                        })
                        .collect::<Vec<_>>()
                })
                .collect();
            (run.mode, parts)
        })
        .collect();
    Ok(PartLogs::open(out, case_sha256, &starts)?)
}

/// The runs of `modes` with the output folder, checkpoints, progress and cancellation
/// (as `app::wear_train::run_train_modes` for one operating point).
fn run_modes(
    command: &str,
    ts: &TrainSpectrum,
    modes: &[WearMode],
    meta: &RunMetadata,
    (out, resume, replace): (Option<&Path>, bool, bool),
    observer: &dyn Observer,
) -> Result<Runs<Vec<TrainSpectrumRun>>, JobError> {
    if let (Some(o), true) = (out, resume) {
        super::checkpoints::require_folder(o)?;
    }
    let mut dir = publish::open_if(out, None, command, replace)?;
    let resume_from = dir.as_ref().filter(|_| resume);
    let starts = starting_runs(ts, modes, resume_from, &meta.case_sha256, observer)?;
    let logs = match dir.as_mut() {
        Some(d) => Some(open_logs(d, ts, &starts, &meta.case_sha256)?),
        None => None,
    };
    let root = dir.as_ref().map(|d| d.root().to_path_buf());
    let tasks = mode_tasks(modes, ts.sm.case.wear.total_cycles);
    for t in &tasks {
        observer.start(t);
    }
    let nk = ts.meshes();
    let on_update = |mode: WearMode, run: &TrainSpectrumRun| -> anyhow::Result<()> {
        if let (Some(logs), Some(root)) = (&logs, &root) {
            logs.record(mode, run.records.len(), &|p, j| {
                &run.records[j].bins[p / nk].meshes[p % nk]
            })?;
            observer.checkpoint(&root.join(bin_mesh_checkpoint_name(mode, 0, 0)));
        }
        if let Some(r) = run.records.last() {
            let n = run.records.len() - 1;
            report_update(observer, &tasks, mode, n, &r.bins[0].meshes[0].wear);
        }
        keep_going(observer)
    };
    let result = run_train_spectrum_modes(ts, starts, &on_update);
    for t in &tasks {
        observer.finish(t);
    }
    drop(logs);
    Ok(Runs {
        runs: result?,
        out: dir,
    })
}

/// The metadata of a job under a spectrum: the whole case (its hash covers the bins) and
/// the values the monitoring bin's model resolved.
fn metadata(command: &str, sm: &SpectrumModel) -> RunMetadata {
    RunMetadata {
        resolved: Some(sm.bins[sm.monitoring].resolved()),
        ..RunMetadata::new(command, &sm.case)
    }
}

/// The runs as train runs read at the monitoring bin (`duty::train::combined_train_run`).
fn combined_runs(sm: &SpectrumModel, runs: &[&TrainSpectrumRun]) -> Vec<TrainWearRun> {
    runs.iter()
        .map(|r| combined_train_run(r, sm.monitoring))
        .collect()
}

/// The wear job of a train under its case's spectrum.
pub fn wear_of_train_under_spectrum(
    job: &super::WearJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let name = "wear";
    let sm = build_spectrum_model(&job.case, observer)?;
    let ts = trains(&sm)?;
    let meta = metadata(name, &sm);
    let out = (job.out.as_deref(), job.resume, job.replace);
    let runs = run_modes(name, &ts, &job.modes, &meta, out, observer)?;
    let refs: Vec<&TrainSpectrumRun> = runs.runs.iter().collect();
    let combined = combined_runs(&sm, &refs);
    let crefs: Vec<&TrainWearRun> = combined.iter().collect();
    let (model, train) = (&sm.bins[sm.monitoring], ts.trains[sm.monitoring]);
    let mut artifacts = train_wear_artifacts(model, train, &crefs).with_figure_output(figures);
    TrainDutyParts::of(&ts, &refs).add_to(&mut artifacts);
    let mut outcome = publish::publish(runs.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = train_stops(&crefs, observer);
    Ok(outcome)
}

/// The run job of a train under its case's spectrum: the studies of
/// `app::run_train` at the monitoring bin, the wear studies under the spectrum.
pub fn run_of_train_under_spectrum(
    job: &super::RunJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let name = "run";
    let sm = build_spectrum_model(&job.case, observer)?;
    let ts = trains(&sm)?;
    let meta = metadata(name, &sm);
    let model = &sm.bins[sm.monitoring];
    let train = ts.trains[sm.monitoring];
    let stages = stage_models(model)?;
    let modes = [WearMode::Dynamic, WearMode::QuasiStatic];
    let out = (job.out.as_deref(), job.resume, job.replace);
    let runs = run_modes(name, &ts, &modes, &meta, out, observer)?;
    let refs: Vec<&TrainSpectrumRun> = runs.runs.iter().collect();
    let combined = combined_runs(&sm, &refs);
    let crefs: Vec<&TrainWearRun> = combined.iter().collect();
    observer.note("run: the train's steady state with new teeth, at the monitoring bin");
    let response = model
        .dynamic(&WearState::new(model.grid.len()), &ExternalError::none())
        .map_err(|e| JobError::Failed(anyhow::anyhow!(e)))?;
    let run = TrainRun {
        model,
        train,
        stages: &stages,
        response: &response,
        runs: &crefs,
    };
    let duty = TrainDutyParts::of(&ts, &refs);
    let artifacts = train_run_artifacts_with(&run, &meta, figures, Some(&duty))
        .map_err(|e| JobError::Failed(e.into()))?;
    let mut outcome = publish::publish(runs.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = train_stops(&crefs, observer);
    Ok(outcome)
}
