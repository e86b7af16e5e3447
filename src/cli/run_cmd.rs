//! `gearwear run`: the paper's whole section 4 from one command, with a report.

use super::args::RunArgs;
use super::output::{build_model, finish, open_out};
use super::progress::{multi, show_wear, wear_bar};
use super::resume::{open_checkpoints, starting_runs};
use super::stops::report_stops;
use super::CliError;
use crate::io::RunMetadata;
use crate::report::paper::run_artifacts;
use crate::study::paper::run_paper_study;
use crate::study::wear_loop::{WearMode, WearRun};

pub fn run(a: &RunArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    let model = build_model(&case)?;
    let meta = RunMetadata::new("run", &case);
    let modes = [WearMode::Dynamic, WearMode::QuasiStatic];
    super::resume::require_folder(&a.out, a.resume)?;
    let mut out = open_out(&a.out, "run")?;
    let starts = starting_runs(&out, &modes, a.resume, &meta.case_sha256, &model)?;
    let checkpoints = open_checkpoints(&mut out, &starts, &meta.case_sha256)?;
    let mut runs = starts.into_iter();
    let (d0, q0) = (
        runs.next().unwrap_or(WearRun::new(WearMode::Dynamic)),
        runs.next().unwrap_or(WearRun::new(WearMode::QuasiStatic)),
    );
    let bars_group = multi();
    let bars = modes.map(|m| wear_bar(&bars_group, case.wear.total_cycles, m));
    let on_update = |mode: WearMode, run: &WearRun| -> anyhow::Result<()> {
        checkpoints.record(run)?;
        show_wear(&bars[usize::from(mode == WearMode::QuasiStatic)], run);
        Ok(())
    };
    let study = run_paper_study(&model, d0, q0, &on_update)?;
    for b in &bars {
        b.finish_and_clear();
    }
    drop(checkpoints);
    finish(out, run_artifacts(&model, &study, &meta), &meta)?;
    report_stops(&[&study.dynamic, &study.quasi_static])
}
