//! `gearwear run`: the paper's whole section 4 from one command, with a report.

use super::args::RunArgs;
use super::output::{build_model, json_write, PLOT_H, PLOT_W};
use super::stiffness_cmd::{figure2, stiffness_table};
use super::wear_cmd::{
    checkpoint_path, load_checkpoint, report_stops, wear_figures, wear_summary, write_run_tables,
};
use super::CliError;
use crate::dynamics::model::dof;
use crate::dynamics::summary::velocity_y_spectrum;
use crate::io::{write_atomic, RunMetadata, Table};
use crate::report::comparison::{compare, comparison_json};
use crate::report::figures::{panel, single, spectrum_panel, Curve};
use crate::report::html::{self, ComparisonRow, FigureBlock, Report, Section};
use crate::report::plot::{render_png, Figure};
use crate::study::paper::{run_paper_study, PaperStudy};
use crate::study::wear_loop::{WearMode, WearRun};
use crate::study::Model;
use indicatif::{MultiProgress, ProgressBar, ProgressStyle};
use serde_json::json;

/// Mesh periods shown in the time plots.
const SHOWN_PERIODS: usize = 3;

/// A figure with the table behind it.
struct Fig {
    file: &'static str,
    caption: String,
    figure: Figure,
    table: Table,
}

fn label(w: f64) -> String {
    format!("{w} um wear")
}

/// Figures 4, 5, 8 (time series of the three wear states) and 6, 7, 9, 10.
fn section41_figures(model: &Model, study: &PaperStudy) -> Vec<Fig> {
    let mut out = Vec::new();
    let states = &study.wear_states;
    let series = |f: &dyn Fn(&crate::dynamics::response::Signals, usize) -> f64,
                  title: &str,
                  y: &str,
                  file: &'static str,
                  unit_col: &str| {
        let mut curves = Vec::new();
        let mut table = Table::new();
        for s in states {
            let sig = &s.response.signals;
            let per = sig.time_s.len() / model.settings.evaluated_mesh_periods.max(1);
            let n = (per * SHOWN_PERIODS).min(sig.time_s.len());
            let t0 = sig.time_s[0];
            let t: Vec<f64> = sig.time_s[..n].iter().map(|t| (t - t0) * 1e3).collect();
            let v: Vec<f64> = (0..n).map(|k| f(sig, k)).collect();
            table = table
                .col(&format!("time_ms_{}um", s.max_wear_um), t.clone())
                .col(&format!("{unit_col}_{}um", s.max_wear_um), v.clone());
            curves.push(Curve::new(label(s.max_wear_um), t, v));
        }
        Fig {
            file,
            caption: title.to_string(),
            figure: single(title, panel("time (ms)", y, curves)),
            table,
        }
    };
    out.push(series(
        &|s, k| s.dte_m[k] * 1e6,
        "Fig. 4: dynamic transmission error at three wear states",
        "DTE (um)",
        "fig04_dte",
        "dte_um",
    ));
    out.push(series(
        &|s, k| s.velocity[k][dof::YP] * 1e3,
        "Fig. 5: pinion y velocity at three wear states",
        "dy_p/dt (mm/s)",
        "fig05_velocity_y_pinion",
        "velocity_mm_per_s",
    ));
    let f_mesh = model.params.mesh_frequency_hz(&model.pair);
    if let Some(mid) = states.iter().find(|s| (s.max_wear_um - 0.5).abs() < 1e-9) {
        let spec = velocity_y_spectrum(&mid.response);
        let amp: Vec<f64> = spec.amplitude.iter().map(|a| a * 1e3).collect();
        out.push(Fig {
            file: "fig06_spectrum",
            caption: "Fig. 6: spectrum of dy_p/dt at 0.5 um wear (MF = mesh frequency)".into(),
            figure: single(
                "Fig. 6: spectrum of dy_p/dt at 0.5 um wear",
                spectrum_panel(
                    "amplitude (mm/s)",
                    &spec.frequency_hz,
                    &amp,
                    5.0 * f_mesh,
                    f_mesh,
                ),
            ),
            table: Table::new()
                .col("frequency_hz", spec.frequency_hz.clone())
                .col("amplitude_mm_per_s", amp),
        });
    }
    let wear: Vec<f64> = states.iter().map(|s| s.max_wear_um).collect();
    let mut curves = Vec::new();
    let mut table = Table::new().col("max_wear_um", wear.clone());
    for h in 0..4 {
        let a: Vec<f64> = states
            .iter()
            .map(|s| s.summary.velocity_y_pinion_harmonics_m_per_s[h] * 1e3)
            .collect();
        table = table.col(&format!("harmonic{}_mm_per_s", h + 1), a.clone());
        curves.push(Curve::new(format!("{} MF", h + 1), wear.clone(), a));
    }
    out.push(Fig {
        file: "fig07_mesh_harmonics",
        caption:
            "Fig. 7: amplitudes of the first four mesh-frequency harmonics of dy_p/dt against wear"
                .into(),
        figure: single(
            "Fig. 7: mesh-harmonic amplitudes of dy_p/dt against wear",
            panel("maximum wear depth (um)", "amplitude (mm/s)", curves),
        ),
        table,
    });
    out.push(series(
        &|s, k| s.mesh_force_n[k],
        "Fig. 8: mesh force at three wear states",
        "F (N)",
        "fig08_mesh_force",
        "mesh_force_n",
    ));
    let path = |f: &dyn Fn(&crate::dynamics::response::PathSample) -> f64,
                title: &str,
                y: &str,
                file: &'static str,
                col: &str| {
        let mut curves = Vec::new();
        let mut table = Table::new();
        for s in states {
            let x: Vec<f64> = s.response.path.iter().map(|p| p.rho1_m * 1e3).collect();
            let v: Vec<f64> = s.response.path.iter().map(f).collect();
            table = table
                .col(&format!("rho1_mm_{}um", s.max_wear_um), x.clone())
                .col(&format!("{col}_{}um", s.max_wear_um), v.clone());
            curves.push(Curve::new(label(s.max_wear_um), x, v));
        }
        Fig {
            file,
            caption: title.to_string(),
            figure: single(
                title,
                panel(
                    "pinion roll distance rho1 along the path of contact (mm)",
                    y,
                    curves,
                ),
            ),
            table,
        }
    };
    out.push(path(
        &|p| p.friction_coefficient,
        "Fig. 9: friction coefficient of a tooth pair through its engagement",
        "mu (-)",
        "fig09_friction_coefficient",
        "friction_coefficient",
    ));
    out.push(path(
        &|p| p.friction_n,
        "Fig. 10: friction force of a tooth pair through its engagement",
        "f (N)",
        "fig10_friction_force",
        "friction_force_n",
    ));
    out
}

fn progress(multi: &MultiProgress, total: f64, name: &str) -> ProgressBar {
    let pb = multi.add(ProgressBar::new(total as u64));
    pb.set_style(
        ProgressStyle::with_template("{prefix:>12} [{bar:30}] {pos}/{len} cycles (eta {eta})")
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    pb.set_prefix(name.to_owned());
    pb
}

fn png(fig: &Figure) -> Result<Vec<u8>, CliError> {
    render_png(fig, PLOT_W, PLOT_H).map_err(|e| CliError::Failed(e.into()))
}

pub fn run(a: &RunArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    let model = build_model(&case)?;
    let meta = RunMetadata::new("run", &case);
    let out = &a.out;
    std::fs::create_dir_all(out.join("csv"))?;

    let multi = MultiProgress::new();
    let bars = [
        progress(&multi, case.wear.total_cycles, "dynamic"),
        progress(&multi, case.wear.total_cycles, "quasi-static"),
    ];
    let ckpt = |mode: WearMode, run: &WearRun| -> anyhow::Result<()> {
        let i = match mode {
            WearMode::Dynamic => 0,
            WearMode::QuasiStatic => 1,
        };
        let c = json!({"case_sha256": meta.case_sha256, "run": run});
        write_atomic(
            &checkpoint_path(out, mode),
            serde_json::to_string(&c)?.as_bytes(),
        )?;
        if let Some(r) = run.last() {
            bars[i].set_position(r.wear.cycles as u64);
        }
        Ok(())
    };
    // Each wear run starts afresh, or from its checkpoint with --resume (a checkpoint of
    // another case is an input error).
    let start = |mode| -> Result<WearRun, CliError> {
        if a.resume {
            load_checkpoint(out, mode, &meta.case_sha256)
        } else {
            Ok(WearRun::new(mode))
        }
    };
    let (d0, q0) = (start(WearMode::Dynamic)?, start(WearMode::QuasiStatic)?);
    let study = run_paper_study(&model, d0, q0, &ckpt).map_err(CliError::Failed)?;
    for b in &bars {
        b.finish_and_clear();
    }

    // Figures and the CSV behind each.
    let (st_table, st_json) = stiffness_table(&model);
    let mut figs = vec![Fig {
        file: "fig02_mesh_stiffness",
        caption: "Fig. 2: time-varying mesh stiffness and quasi-static transmission error over one mesh period".into(),
        figure: figure2(&model, &st_table),
        table: st_table,
    }];
    figs.extend(section41_figures(&model, &study));
    let runs = [&study.dynamic, &study.quasi_static];
    for (name, figure) in wear_figures(&model, &runs) {
        let file: &'static str = match name {
            "fig11_force_and_wear_initial.png" => "fig11_force_and_wear_initial",
            "fig12_wear_rate_evolution.png" => "fig12_wear_rate_evolution",
            _ => "fig13_max_accumulated_wear",
        };
        let table = Table::new()
            .col("cycles_dynamic", study.dynamic.cycles())
            .col(
                "max_wear_pinion_um_dynamic",
                study
                    .dynamic
                    .max_wear_pinion_m()
                    .iter()
                    .map(|x| x * 1e6)
                    .collect(),
            )
            .col("cycles_quasi_static", study.quasi_static.cycles())
            .col(
                "max_wear_pinion_um_quasi_static",
                study
                    .quasi_static
                    .max_wear_pinion_m()
                    .iter()
                    .map(|x| x * 1e6)
                    .collect(),
            );
        figs.push(Fig {
            file,
            caption: figure.title.clone(),
            figure,
            table,
        });
    }
    for r in runs {
        write_run_tables(&model, r, &out.join("csv"))?;
    }
    let mut blocks = Vec::new();
    for f in &figs {
        let bytes = png(&f.figure)?;
        write_atomic(&out.join(format!("{}.png", f.file)), &bytes)?;
        f.table
            .save(&out.join("csv").join(format!("{}.csv", f.file)))?;
        blocks.push(FigureBlock {
            caption: f.caption.clone(),
            png: bytes,
            csv_name: Some(format!("csv/{}.csv", f.file)),
        });
    }

    // Numbers beside the paper's.
    let rows = compare(&study);
    let mut summary = json!({
        "paper_comparison": comparison_json(&rows),
        "stiffness": st_json,
        "wear_study": wear_summary(Some(&study.dynamic), Some(&study.quasi_static)),
        "wear_states": study.wear_states.iter().map(|s| json!({
            "max_wear_um": s.max_wear_um,
            "roughness_um": s.roughness_um,
            "dte_max_um": s.summary.dte_max_m * 1e6,
            "velocity_y_pinion_rms_mm_per_s": s.summary.velocity_y_pinion_rms_m_per_s * 1e3,
            "mesh_force_mean_n": s.summary.mesh_force_mean_n,
            "mesh_force_max_n": s.summary.mesh_force_max_n,
            "mesh_harmonics_mm_per_s": s.summary.velocity_y_pinion_harmonics_m_per_s.iter().map(|x| x * 1e3).collect::<Vec<_>>(),
            "friction_coefficient_max": s.summary.friction_coefficient_max,
            "friction_force_max_abs_n": s.summary.friction_force_max_n,
        })).collect::<Vec<_>>(),
        "warnings": model.warnings,
    });
    summary["metadata"] = serde_json::to_value(&meta).map_err(anyhow::Error::from)?;
    json_write(&out.join("summary.json"), &summary)?;
    let report = build_report(&model, &rows, blocks, &meta);
    write_atomic(&out.join("report.html"), html::render(&report).as_bytes())?;
    for r in &rows {
        eprintln!(
            "{:<70} ours {:>10.4}  paper {:>8.3}  ({:+.1} %)",
            r.quantity,
            r.ours,
            r.paper,
            100.0 * r.relative_deviation()
        );
    }
    eprintln!(
        "run: report, summary.json, figures and csv/ -> {}",
        out.display()
    );
    report_stops(&[&study.dynamic, &study.quasi_static])
}

fn build_report(
    model: &Model,
    rows: &[crate::report::comparison::Compared],
    figs: Vec<FigureBlock>,
    meta: &RunMetadata,
) -> Report {
    let table = html::comparison_table(
        "Our headline numbers beside the paper's (sections 4.1 and 4.2). Deviations are discussed in docs/REPRODUCTION.md.",
        &rows.iter().map(|r| ComparisonRow { quantity: r.quantity.clone(), ours: r.ours, paper: r.paper, explanation: r.explanation.to_string() }).collect::<Vec<_>>(),
    );
    let mut it = figs.into_iter();
    let mut take = |n: usize| it.by_ref().take(n).collect::<Vec<_>>();
    let c = &model.case;
    Report {
        title: "gearwear: dynamic wear prediction of the paper's spur pair".into(),
        intro_html: format!(
            "<p>Reproduction of section 4 of <em>A Dynamic Wear Prediction Model for Studying the Interactions between Surface Wear and Dynamic Response of Spur Gears</em>, Coatings 2022, 12(9), 1250: z = {}/{}, m = {} mm, {} Hz input, {} N m load, wear coefficient {:.2e} m<sup>2</sup>/N, {} cycles. The model as implemented and every choice where the paper is silent or wrong: docs/MODEL.md.</p>",
            c.gear.teeth_pinion, c.gear.teeth_gear, c.gear.module_mm, c.operating.input_speed_hz, c.operating.load_torque_nm, c.wear.coefficient_m2_per_n, c.wear.total_cycles
        ),
        sections: vec![
            Section { heading: "Headline numbers".into(), paragraphs: vec![], figures: vec![], tables: vec![table] },
            Section { heading: "Mesh stiffness (section 2)".into(), paragraphs: vec![format!("Potential energy method with the Sainsot fillet foundation: k_m from {:.3e} to {:.3e} N/m, mean {:.3e} N/m; contact ratio {:.4}.", model.mesh.min_stiffness_n_per_m(), model.mesh.max_stiffness_n_per_m(), model.mesh.mean_stiffness_n_per_m(), model.pair.contact_ratio)], figures: take(1), tables: vec![] },
            Section { heading: "Effects of wear on the dynamic response (section 4.1)".into(), paragraphs: vec!["Wear states: the dynamic wear study's own profile scaled to a maximum pinion wear of 0.1, 0.5 and 1 um, with the roughness the case's law gives at that depth.".into()], figures: take(7), tables: vec![] },
            Section { heading: "Effects of the dynamic response on wear (section 4.2)".into(), paragraphs: vec![], figures: take(3), tables: vec![] },
        ],
        footer: format!("gearwear {} | case sha256 {} | command: run", meta.version, meta.case_sha256),
    }
}
