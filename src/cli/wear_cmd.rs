//! `gearwear wear`: the coupled dynamics-wear study and its quasi-static twin, with a
//! checkpoint after every update.

use super::args::{WearArgs, WearModeArg};
use super::output::{build_model, finish, open_out};
use super::progress::{multi, show_wear, wear_bar};
use super::resume::{open_checkpoints, starting_runs};
use super::stops::report_stops;
use super::CliError;
use crate::io::RunMetadata;
use crate::report::wear::wear_artifacts;
use crate::study::wear_loop::{run_wear_modes, WearMode, WearRun};

pub fn run(a: &WearArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    let model = build_model(&case)?;
    let meta = RunMetadata::new("wear", &case);
    let modes: Vec<WearMode> = match a.mode {
        WearModeArg::Dynamic => vec![WearMode::Dynamic],
        WearModeArg::QuasiStatic => vec![WearMode::QuasiStatic],
        WearModeArg::Both => vec![WearMode::Dynamic, WearMode::QuasiStatic],
    };
    super::resume::require_folder(&a.out, a.resume)?;
    let mut out = open_out(&a.out, "wear")?;
    let starts = starting_runs(&out, &modes, a.resume, &meta.case_sha256, &model)?;
    let checkpoints = open_checkpoints(&mut out, &starts, &meta.case_sha256)?;
    let bars_group = multi();
    let bars: Vec<_> = modes
        .iter()
        .map(|m| (*m, wear_bar(&bars_group, case.wear.total_cycles, *m)))
        .collect();
    let runs = run_wear_modes(&model, starts, &|mode, run: &WearRun| {
        checkpoints.record(run)?;
        if let Some((_, pb)) = bars.iter().find(|(m, _)| *m == mode) {
            show_wear(pb, run);
        }
        Ok(())
    })?;
    for (_, pb) in &bars {
        pb.finish_and_clear();
    }
    drop(checkpoints);
    let refs: Vec<&WearRun> = runs.iter().collect();
    finish(out, wear_artifacts(&model, &refs), &meta)?;
    report_stops(&refs)
}
