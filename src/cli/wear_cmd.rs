//! `gearwear wear`: the coupled dynamics-wear study and its quasi-static twin.

use super::args::{WearArgs, WearModeArg};
use super::output::{build_model, json_write, save_png};
use super::CliError;
use crate::io::{write_atomic, RunMetadata, Table};
use crate::report::figures::{panel, single, Curve};
use crate::report::plot::Figure;
use crate::study::wear_loop::{run_wear, StopKind, WearMode, WearRun};
use crate::study::Model;
use indicatif::{MultiProgress, ProgressBar, ProgressStyle};
use serde::{Deserialize, Serialize};
use serde_json::json;
use std::path::{Path, PathBuf};

/// What a checkpoint file holds: the case it belongs to and the run so far.
#[derive(Serialize, Deserialize)]
struct Checkpoint {
    case_sha256: String,
    run: WearRun,
}

pub fn checkpoint_path(dir: &Path, mode: WearMode) -> PathBuf {
    dir.join(format!("checkpoint_{}.json", mode.name()))
}

/// Load a checkpoint for `--resume`; a missing file starts afresh, a file of another
/// case is an input error.
pub fn load_checkpoint(dir: &Path, mode: WearMode, hash: &str) -> Result<WearRun, CliError> {
    let p = checkpoint_path(dir, mode);
    let Ok(text) = std::fs::read_to_string(&p) else {
        return Ok(WearRun::new(mode));
    };
    let c: Checkpoint = serde_json::from_str(&text).map_err(|e| {
        CliError::input(format!(
            "--resume: {} is not a gearwear checkpoint: {e}",
            p.display()
        ))
    })?;
    if c.case_sha256 != hash {
        return Err(CliError::input(format!(
            "--resume: {} belongs to another case (hash {} != {}); rerun without --resume or with the same case",
            p.display(),
            &c.case_sha256[..12.min(c.case_sha256.len())],
            &hash[..12]
        )));
    }
    Ok(c.run)
}

fn bar(multi: &MultiProgress, total: f64, mode: WearMode) -> ProgressBar {
    let pb = multi.add(ProgressBar::new(total as u64));
    pb.set_style(
        ProgressStyle::with_template(
            "{prefix:>12} [{bar:30}] {pos}/{len} cycles, {msg} (eta {eta})",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    pb.set_prefix(mode.name());
    pb
}

/// Run one mode with checkpoints after every update.
pub fn run_mode(
    model: &Model,
    mode: WearMode,
    dir: &Path,
    resume: bool,
    hash: &str,
    pb: &ProgressBar,
) -> Result<WearRun, CliError> {
    let start = if resume {
        load_checkpoint(dir, mode, hash)?
    } else {
        WearRun::new(mode)
    };
    let path = checkpoint_path(dir, mode);
    let mut on_update = |run: &WearRun| -> anyhow::Result<()> {
        let c = Checkpoint {
            case_sha256: hash.to_owned(),
            run: run.clone(),
        };
        write_atomic(&path, serde_json::to_string(&c)?.as_bytes())?;
        if let Some(r) = run.last() {
            pb.set_position(r.wear.cycles as u64);
            pb.set_message(format!(
                "{} updates, max pinion wear {:.3} um",
                run.records.len() - 1,
                r.wear.max_pinion_m() * 1e6
            ));
        }
        Ok(())
    };
    let run = run_wear(model, start, &mut on_update).map_err(CliError::Failed)?;
    pb.finish();
    Ok(run)
}

/// Value of a piecewise-linear series (x ascending) at x; wear grows linearly in cycles
/// within a block, so this is exact between updates.
pub fn at_cycles(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    if xs.is_empty() {
        return f64::NAN;
    }
    let j = xs.partition_point(|v| *v < x);
    if j == 0 {
        return ys[0];
    }
    if j == xs.len() {
        return ys[ys.len() - 1];
    }
    let t = (x - xs[j - 1]) / (xs[j] - xs[j - 1]);
    ys[j - 1] + (ys[j] - ys[j - 1]) * t
}

/// CSVs of one run: a row per update, and the profiles of every update.
pub fn write_run_tables(model: &Model, run: &WearRun, dir: &Path) -> anyhow::Result<()> {
    let m = run.mode.name();
    let rec = &run.records;
    let s = |f: &dyn Fn(&crate::study::wear_loop::UpdateRecord) -> f64| {
        rec.iter().map(f).collect::<Vec<_>>()
    };
    Table::new()
        .col("update", (0..rec.len()).map(|i| i as f64).collect())
        .col("cycles", s(&|r| r.wear.cycles))
        .col("max_wear_pinion_um", s(&|r| r.wear.max_pinion_m() * 1e6))
        .col("max_wear_gear_um", s(&|r| r.wear.max_gear_m() * 1e6))
        .col(
            "max_wear_rate_pinion_um_per_kcycle",
            s(&|r| r.increment_pinion_m.iter().fold(0.0_f64, |a, b| a.max(*b)) * 1e9),
        )
        .col("roughness_um", s(&|r| r.roughness_um))
        .col("mesh_force_mean_n", s(&|r| r.summary.mesh_force_mean_n))
        .col("mesh_force_max_n", s(&|r| r.summary.mesh_force_max_n))
        .col("dte_max_um", s(&|r| r.summary.dte_max_m * 1e6))
        .col(
            "velocity_y_pinion_rms_mm_per_s",
            s(&|r| r.summary.velocity_y_pinion_rms_m_per_s * 1e3),
        )
        .col(
            "friction_coefficient_max",
            s(&|r| r.summary.friction_coefficient_max),
        )
        .col(
            "mesh_harmonic1_mm_per_s",
            s(&|r| r.summary.velocity_y_pinion_harmonics_m_per_s[0] * 1e3),
        )
        .col(
            "mesh_harmonic2_mm_per_s",
            s(&|r| r.summary.velocity_y_pinion_harmonics_m_per_s[1] * 1e3),
        )
        .col(
            "mesh_harmonic3_mm_per_s",
            s(&|r| r.summary.velocity_y_pinion_harmonics_m_per_s[2] * 1e3),
        )
        .col(
            "mesh_harmonic4_mm_per_s",
            s(&|r| r.summary.velocity_y_pinion_harmonics_m_per_s[3] * 1e3),
        )
        .save(&dir.join(format!("updates_{m}.csv")))?;
    let g = &model.grid;
    let mut t = Table::new()
        .col("rho1_mm", g.rho_pinion_m.iter().map(|x| x * 1e3).collect())
        .col(
            "pinion_radius_mm",
            g.radius_pinion_m.iter().map(|x| x * 1e3).collect(),
        )
        .col(
            "gear_radius_mm",
            g.radius_gear_m.iter().map(|x| x * 1e3).collect(),
        );
    for (i, r) in rec.iter().enumerate() {
        t = t
            .col(
                &format!("wear_pinion_um_u{i}"),
                r.wear.pinion_m.iter().map(|x| x * 1e6).collect(),
            )
            .col(
                &format!("wear_gear_um_u{i}"),
                r.wear.gear_m.iter().map(|x| x * 1e6).collect(),
            )
            .col(
                &format!("rate_pinion_um_per_kcycle_u{i}"),
                r.increment_pinion_m.iter().map(|x| x * 1e9).collect(),
            );
    }
    t.save(&dir.join(format!("wear_profiles_{m}.csv")))
}

/// Figures 11-13 from the runs present.
pub fn wear_figures(model: &Model, runs: &[&WearRun]) -> Vec<(&'static str, Figure)> {
    let rho_mm: Vec<f64> = model.grid.rho_pinion_m.iter().map(|x| x * 1e3).collect();
    let mut f11_force = Vec::new();
    let mut f11_wear = Vec::new();
    let mut f12 = Vec::new();
    let mut f13 = Vec::new();
    for run in runs {
        let m = run.mode.name();
        if let Some(r0) = run.records.first() {
            f11_force.push(Curve::new(
                m,
                r0.path_rho1_m.iter().map(|x| x * 1e3).collect(),
                r0.path_load_n.clone(),
            ));
            f11_wear.push(Curve::new(
                m,
                rho_mm.clone(),
                r0.increment_pinion_m.iter().map(|x| x * 1e9).collect(),
            ));
        }
        for (i, r) in run.records.iter().enumerate() {
            if i == 0 || i + 1 == run.records.len() || i % 2 == 0 {
                f12.push(Curve::new(
                    format!("{m} {:.0} cycles", r.wear.cycles),
                    rho_mm.clone(),
                    r.increment_pinion_m.iter().map(|x| x * 1e9).collect(),
                ));
            }
        }
        f13.push(Curve::new(
            m,
            run.cycles(),
            run.max_wear_pinion_m().iter().map(|x| x * 1e6).collect(),
        ));
    }
    let x = "pinion roll distance rho1 (mm)";
    vec![
        (
            "fig11_force_and_wear_initial.png",
            Figure {
                title: "Fig. 11: pair load and wear rate along the pinion profile, initial stage"
                    .into(),
                panels: vec![
                    panel(x, "pair load (N)", f11_force),
                    panel(x, "wear rate (um per 1000 cycles)", f11_wear),
                ],
            },
        ),
        (
            "fig12_wear_rate_evolution.png",
            single(
                "Fig. 12: wear rate distribution of the pinion as wear proceeds",
                panel(x, "wear rate (um per 1000 cycles)", f12),
            ),
        ),
        (
            "fig13_max_accumulated_wear.png",
            single(
                "Fig. 13: maximum accumulated pinion wear depth",
                panel("cycles", "max wear depth (um)", f13),
            ),
        ),
    ]
}

/// summary.json content of the wear study (promised keys).
pub fn wear_summary(dynamic: Option<&WearRun>, qs: Option<&WearRun>) -> serde_json::Value {
    let base = dynamic.or(qs).expect("at least one mode");
    let cycles = base.cycles();
    let series = |run: Option<&WearRun>, f: &dyn Fn(&WearRun) -> Vec<f64>| -> serde_json::Value {
        match run {
            Some(r) => json!(cycles
                .iter()
                .map(|c| at_cycles(&r.cycles(), &f(r), *c) * 1e6)
                .collect::<Vec<_>>()),
            None => serde_json::Value::Null,
        }
    };
    let rate = |r: &WearRun| -> f64 {
        r.last().map_or(0.0, |x| {
            x.increment_pinion_m.iter().fold(0.0_f64, |a, b| a.max(*b))
        })
    };
    let mut v = json!({
        "cycles": cycles,
        "max_wear_pinion_um": {"dynamic": series(dynamic, &|r| r.max_wear_pinion_m()), "quasi_static": series(qs, &|r| r.max_wear_pinion_m())},
        "max_wear_gear_um": {"dynamic": series(dynamic, &|r| r.max_wear_gear_m()), "quasi_static": series(qs, &|r| r.max_wear_gear_m())},
        "updates": {
            "dynamic": dynamic.map(|r| r.records.len() - 1),
            "quasi_static": qs.map(|r| r.records.len() - 1),
        },
    });
    // The runs that stopped early, by mode (empty when both reached the total cycles).
    let mut stopped = serde_json::Map::new();
    for r in [dynamic, qs].into_iter().flatten() {
        if let Some(stop) = &r.stopped {
            stopped.insert(r.mode.name().into(), json!(stop));
        }
    }
    v["stopped"] = serde_json::Value::Object(stopped);
    if let (Some(d), Some(q)) = (dynamic, qs) {
        // At the same cycles: a run that stopped early ends before the other.
        let end = d.cycles().last().copied().unwrap_or(0.0);
        let end = end.min(q.cycles().last().copied().unwrap_or(0.0));
        let (hd, hq) = (
            at_cycles(&d.cycles(), &d.max_wear_pinion_m(), end),
            at_cycles(&q.cycles(), &q.max_wear_pinion_m(), end),
        );
        v["ratio_max_wear_dynamic_to_static"] = json!(hd / hq);
        v["ratio_max_wear_rate_dynamic_to_static"] = json!(rate(d) / rate(q));
        v["ratio_notes"] = json!("ratio_max_wear_dynamic_to_static: maximum accumulated pinion wear depth at the final cycle count (paper: ~1.2). ratio_max_wear_rate_dynamic_to_static: maximum pinion wear depth per cycle of the final state (the paper's 'maximum wear depth', ~1.6).");
    }
    v
}

pub fn run(a: &WearArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    let model = build_model(&case)?;
    let meta = RunMetadata::new("wear", &case);
    std::fs::create_dir_all(&a.out)?;
    let modes: Vec<WearMode> = match a.mode {
        WearModeArg::Dynamic => vec![WearMode::Dynamic],
        WearModeArg::QuasiStatic => vec![WearMode::QuasiStatic],
        WearModeArg::Both => vec![WearMode::Dynamic, WearMode::QuasiStatic],
    };
    let multi = MultiProgress::new();
    let bars: Vec<ProgressBar> = modes
        .iter()
        .map(|m| bar(&multi, case.wear.total_cycles, *m))
        .collect();
    let results: Vec<Result<WearRun, CliError>> = {
        use rayon::prelude::*;
        modes
            .par_iter()
            .zip(bars.par_iter())
            .map(|(m, pb)| run_mode(&model, *m, &a.out, a.resume, &meta.case_sha256, pb))
            .collect()
    };
    let mut runs = Vec::new();
    for r in results {
        runs.push(r?);
    }
    let dynamic = runs.iter().find(|r| r.mode == WearMode::Dynamic);
    let qs = runs.iter().find(|r| r.mode == WearMode::QuasiStatic);
    for r in &runs {
        write_run_tables(&model, r, &a.out)?;
    }
    let refs: Vec<&WearRun> = runs.iter().collect();
    for (name, fig) in wear_figures(&model, &refs) {
        save_png(&fig, &a.out.join(name))?;
    }
    let mut v = wear_summary(dynamic, qs);
    v["metadata"] = serde_json::to_value(&meta).map_err(anyhow::Error::from)?;
    v["warnings"] = json!(model.warnings);
    json_write(&a.out.join("summary.json"), &v)?;
    if let Some(x) = v.get("ratio_max_wear_dynamic_to_static") {
        eprintln!(
            "wear: dynamic/quasi-static maximum accumulated pinion wear {x:.3} -> {}",
            a.out.display()
        );
    }
    report_stops(&refs)
}

/// Warns about every wear run that stopped early (its outputs are written up to the
/// stop). A stop because the worn teeth left the model's domain is a result (exit code
/// 0, `stopped` in summary.json); one for want of a steady state is a failure of the
/// solver the user should act on (exit code 1, after all outputs are written).
pub fn report_stops(runs: &[&WearRun]) -> Result<(), CliError> {
    let mut failed = None;
    for run in runs {
        if let Some(stop) = &run.stopped {
            eprintln!(
                "warning: the {} wear run stopped early: {}",
                run.mode.name(),
                stop.reason
            );
            if stop.kind == StopKind::Numerical {
                failed = Some(format!(
                    "the {} wear run stopped early: {}",
                    run.mode.name(),
                    stop.reason
                ));
            }
        }
    }
    match failed {
        Some(m) => Err(CliError::Failed(anyhow::anyhow!(m))),
        None => Ok(()),
    }
}
