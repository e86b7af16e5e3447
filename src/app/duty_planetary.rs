//! The wear job on a planetary set (`[planetary]`) under a load spectrum
//! (`duty::planetary`): every bin is the set at the bin's operating point (the input
//! member's torque and speed), every update advances every mesh by every bin's share; a
//! checkpoint log per mode, bin and mesh (`checkpoint_MODE_binI_sun_planet_N.jsonl`,
//! `..._ring_planet_N.jsonl`, each an ordinary wear run's records) appended after every
//! update, and `--resume` continues from them once they are replayed and recomputed
//! (`duty::planetary_resume`). The results are the set's own (`report::wear_planetary`)
//! of the spectrum's run, read at the monitoring bin, with what the spectrum adds
//! (`report::duty_planetary`). The run job on a set under a spectrum
//! (`app::run_planetary`) runs its wear studies here too.

use super::observer::{keep_going, Observer};
use super::part_checkpoints::{starting_part_runs, Parts};
use super::wear_planetary::planetary_stops;
use super::wear_runs::{mode_tasks, Runs};
use super::{publish, JobError, Outcome, WearJob};
use crate::duty::planetary::{
    combined_planetary_run, run_planetary_spectrum_modes, PlanetarySpectrum, PlanetarySpectrumRun,
};
use crate::duty::planetary_resume::{from_logs, verify};
use crate::io::OutputDir;
use crate::report::duty_planetary::add_planetary_duty;
use crate::report::figure_output::FigureOutput;
use crate::report::wear_planetary::planetary_wear_artifacts;
use crate::store::part_logs::{PartLogs, PartStarts};
use crate::store::RunMetadata;
use crate::study::budget::planetary::{
    estimate_planetary_spectrum_wear, max_planetary_spectrum_checkpoint_bytes,
};
use crate::study::planetary_wear_check::planetary_mesh_name;
use crate::study::planetary_wear_loop::PlanetaryWearRun;
use crate::study::wear_loop::{WearMode, WearRun};
use std::path::Path;

/// File name of the checkpoint of bin `i` and mesh `j` (0-based, module order) of a
/// mode's run.
pub fn bin_mesh_checkpoint_name(
    ps: &PlanetarySpectrum,
    mode: WearMode,
    i: usize,
    j: usize,
) -> String {
    format!(
        "checkpoint_{}_bin{}_{}.jsonl",
        mode.name(),
        i + 1,
        planetary_mesh_name(ps.reference(), j)
    )
}

/// The names of a mode's logs, bin-major (bin 1's meshes, then bin 2's, ...).
fn names(ps: &PlanetarySpectrum, mode: WearMode) -> Vec<String> {
    (0..ps.bins())
        .flat_map(|i| (0..ps.meshes()).map(move |j| bin_mesh_checkpoint_name(ps, mode, i, j)))
        .collect()
}

/// The run of each of `modes`: afresh, or read back from its logs in `resume_from`
/// (`part_checkpoints::starting_part_runs`, replayed and recomputed by
/// `duty::planetary_resume`).
fn starting_runs(
    ps: &PlanetarySpectrum,
    modes: &[WearMode],
    resume_from: Option<&OutputDir>,
    case_sha256: &str,
    observer: &dyn Observer,
) -> Result<Vec<PlanetarySpectrumRun>, JobError> {
    let fresh = |m: WearMode| PlanetarySpectrumRun::new(m, ps.shares.clone());
    let max = resume_from.map_or(0, |_| {
        max_planetary_spectrum_checkpoint_bytes(&ps.models, &ps.shares, &ps.case.wear)
    });
    let nm = ps.meshes();
    let parts = Parts {
        what: "the planetary set's meshes under the load spectrum",
        names: &|m| names(ps, m),
        shown: &|m| format!("{}, ...", bin_mesh_checkpoint_name(ps, m, 0, 0)),
        part: "a bin or mesh",
        max_bytes: &|_| max,
    };
    let replay = |m: WearMode, logs: Vec<WearRun>| {
        let by_bin: Vec<Vec<WearRun>> = logs.chunks(nm).map(|c| c.to_vec()).collect();
        from_logs(ps, m, &by_bin)
            .and_then(|run| verify(ps, &run).map(|_| run))
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
    ps: &PlanetarySpectrum,
    runs: &[PlanetarySpectrumRun],
    case_sha256: &str,
) -> Result<PartLogs, JobError> {
    let starts: Vec<PartStarts> = runs
        .iter()
        .map(|run| {
            let parts = (0..ps.bins())
                .flat_map(|i| {
                    (0..ps.meshes())
                        .map(|j| {
                            let log = WearRun {
                                mode: run.mode,
                                records: run
                                    .records
                                    .iter()
                                    .map(|r| r.bins[i].meshes[j].clone())
                                    .collect(),
                                stopped: None,
                            };
                            (bin_mesh_checkpoint_name(ps, run.mode, i, j), log)
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
/// (as `app::wear_planetary::run_planetary_modes` for one operating point); the run job
/// on a set under a spectrum (`app::run_planetary`) runs its wear studies here too.
pub(super) fn run_modes(
    command: &str,
    ps: &PlanetarySpectrum,
    modes: &[WearMode],
    meta: &RunMetadata,
    (out, resume, replace): (Option<&Path>, bool, bool),
    observer: &dyn Observer,
) -> Result<Runs<Vec<PlanetarySpectrumRun>>, JobError> {
    if let (Some(o), true) = (out, resume) {
        super::checkpoints::require_folder(o)?;
    }
    if modes.contains(&WearMode::QuasiStatic) {
        if let Some(p) = ps.reference().quasi_static_problem() {
            return Err(JobError::input(p));
        }
    }
    let mut dir = publish::open_if(out, None, command, replace)?;
    let resume_from = dir.as_ref().filter(|_| resume);
    let starts = starting_runs(ps, modes, resume_from, &meta.case_sha256, observer)?;
    let logs = match dir.as_mut() {
        Some(d) => Some(open_logs(d, ps, &starts, &meta.case_sha256)?),
        None => None,
    };
    let root = dir.as_ref().map(|d| d.root().to_path_buf());
    let tasks = mode_tasks(modes, ps.case.wear.total_cycles);
    for t in &tasks {
        observer.start(t);
    }
    let nm = ps.meshes();
    let on_update = |mode: WearMode, run: &PlanetarySpectrumRun| -> anyhow::Result<()> {
        if let (Some(logs), Some(root)) = (&logs, &root) {
            logs.record(mode, run.records.len(), &|p, j| {
                &run.records[j].bins[p / nm].meshes[p % nm]
            })?;
            observer.checkpoint(&root.join(bin_mesh_checkpoint_name(ps, mode, 0, 0)));
        }
        let task = tasks.iter().find(|t| t.id == mode.name());
        if let (Some(t), Some(r)) = (task, run.records.last()) {
            let deepest = r
                .combined(&run.shares, ps.monitoring)
                .flanks(ps.reference())
                .iter()
                .flat_map(|f| f.depth_m.iter())
                .fold(0.0_f64, |a, b| a.max(*b));
            let status = format!(
                "{} updates, deepest wear {:.3} µm",
                run.records.len() - 1,
                deepest * 1e6
            );
            observer.advance(t, r.input_cycles, &status);
        }
        keep_going(observer)
    };
    let result = run_planetary_spectrum_modes(ps, starts, &on_update);
    for t in &tasks {
        observer.finish(t);
    }
    drop(logs);
    Ok(Runs {
        runs: result?,
        out: dir,
    })
}

/// The wear job of a planetary set under its case's spectrum (see the module docs): the
/// bins' models and the budget (every bin counted) before the folder is opened.
pub fn wear_of_planetary_under_spectrum(
    job: &WearJob,
    figures: FigureOutput,
    observer: &dyn Observer,
) -> Result<Outcome, JobError> {
    let ps = PlanetarySpectrum::from_case(&job.case)?;
    super::budget::check_estimate(
        &estimate_planetary_spectrum_wear(&ps.models, &ps.shares, &job.case.wear, &job.modes),
        job.budget.as_ref(),
    )?;
    let mut warnings: Vec<&String> = Vec::new();
    for w in ps.models.iter().flat_map(|m| &m.dynamics.study.warnings) {
        if !warnings.contains(&w) {
            observer.warning(w);
            warnings.push(w);
        }
    }
    let meta = RunMetadata::new("wear", &job.case);
    let out = (job.out.as_deref(), job.resume, job.replace);
    let runs = run_modes("wear", &ps, &job.modes, &meta, out, observer)?;
    let refs: Vec<&PlanetarySpectrumRun> = runs.runs.iter().collect();
    let combined: Vec<PlanetaryWearRun> = refs
        .iter()
        .map(|r| combined_planetary_run(r, ps.monitoring))
        .collect();
    let crefs: Vec<&PlanetaryWearRun> = combined.iter().collect();
    let mut artifacts =
        planetary_wear_artifacts(ps.reference(), &crefs).with_figure_output(figures);
    add_planetary_duty(&ps, &refs, &mut artifacts);
    let mut outcome = publish::publish(runs.out, artifacts, Some(&meta), observer)?;
    outcome.incomplete = planetary_stops(&crefs, observer);
    Ok(outcome)
}
