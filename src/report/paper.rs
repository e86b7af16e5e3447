//! The paper's section 4 as one report (`gearwear run`): Fig. 2 and 4-13 with the table
//! behind each, the summary with the paper comparison, and the self-contained HTML report.

use super::artifacts::{Artifacts, FigureFile, PLOT_H, PLOT_W};
use super::comparison::{compare, comparison_json, Compared};
use super::figures::{panel, single, spectrum_panel, Curve};
use super::html::{self, ComparisonRow, FigureBlock, Report, Section};
use super::plot::Figure;
use super::stiffness::{figure2, stiffness_table};
use super::wear::{wear_figures, wear_summary};
use crate::dynamics::model::dof;
use crate::dynamics::summary::velocity_y_spectrum;
use crate::io::{RunMetadata, Table};
use crate::study::paper::PaperStudy;
use crate::study::wear_loop::WearRun;
use crate::study::Model;
use serde_json::json;

/// Mesh periods shown in the time plots.
const SHOWN_PERIODS: usize = 3;

/// A figure with the table behind it.
pub struct Fig {
    pub file: String,
    pub caption: String,
    pub figure: Figure,
    pub table: Table,
}

fn label(w: f64) -> String {
    format!("{w} um wear")
}

/// Figures 4, 5, 8 (time series of the three wear states) and 6, 7, 9, 10.
pub fn section41_figures(model: &Model, study: &PaperStudy) -> Vec<Fig> {
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
            file: file.into(),
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
            file: "fig06_spectrum".into(),
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
        file: "fig07_mesh_harmonics".into(),
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
            file: file.into(),
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

/// The tables behind Fig. 11-13 (each figure's own data).
fn wear_figure_tables(runs: &[&WearRun]) -> [Table; 3] {
    let mut t11 = Table::new();
    let mut t12 = Table::new();
    let mut t13 = Table::new();
    for run in runs {
        let m = run.mode.name();
        if let Some(r0) = run.records.first() {
            t11 = t11
                .col(
                    &format!("path_rho1_mm_{m}"),
                    r0.path_rho1_m.iter().map(|x| x * 1e3).collect(),
                )
                .col(&format!("pair_load_n_{m}"), r0.path_load_n.clone());
        }
        for (i, r) in run.records.iter().enumerate() {
            t12 = t12.col(
                &format!(
                    "wear_rate_um_per_kcycle_{m}_update{i}_at_{}_cycles",
                    crate::io::format_number(r.wear.cycles)
                ),
                r.increment_pinion_m.iter().map(|x| x * 1e9).collect(),
            );
        }
        t13 = t13.col(&format!("cycles_{m}"), run.cycles()).col(
            &format!("max_wear_pinion_um_{m}"),
            run.max_wear_pinion_m().iter().map(|x| x * 1e6).collect(),
        );
    }
    [t11, t12, t13]
}

/// Everything `gearwear run` writes: figures (PNG) with their CSVs under `csv/`, the
/// wear-study tables, `summary.json` and `report.html`. `meta` is stamped on the summary and
/// the report footer.
pub fn run_artifacts(model: &Model, study: &PaperStudy, meta: &RunMetadata) -> Artifacts {
    let (st_table, st_json) = stiffness_table(model);
    let mut figs = vec![Fig {
        file: "fig02_mesh_stiffness".into(),
        caption: "Fig. 2: time-varying mesh stiffness and quasi-static transmission error over one mesh period".into(),
        figure: figure2(model, &st_table),
        table: st_table,
    }];
    figs.extend(section41_figures(model, study));
    let runs = [&study.dynamic, &study.quasi_static];
    let [t11, mut t12, t13] = wear_figure_tables(&runs);
    let rho: Vec<f64> = model.grid.rho_pinion_m.iter().map(|x| x * 1e3).collect();
    t12 = Table::new()
        .col("rho1_mm", rho.clone())
        .col(
            "pinion_radius_mm",
            model.grid.radius_pinion_m.iter().map(|x| x * 1e3).collect(),
        )
        .append(t12);
    let mut tables = [Some(t11), Some(t12), Some(t13)].into_iter();
    for (name, figure) in wear_figures(model, &runs) {
        figs.push(Fig {
            file: name.trim_end_matches(".png").to_owned(),
            caption: figure.title.clone(),
            figure,
            table: tables.next().flatten().unwrap_or_default(),
        });
    }
    let mut a = Artifacts::default();
    for r in runs {
        for (name, t) in super::wear::run_tables(model, r) {
            a.table(format!("csv/{name}"), t);
        }
    }
    let files: Vec<FigureFile> = figs
        .iter()
        .map(|f| FigureFile {
            path: format!("{}.png", f.file),
            figure: f.figure.clone(),
            width_px: PLOT_W,
            height_px: PLOT_H,
        })
        .collect();
    let pngs = super::artifacts::render_figures(&files).unwrap_or_default();
    let mut blocks = Vec::new();
    for (i, f) in figs.iter().enumerate() {
        let png = pngs.get(i).cloned().unwrap_or_default();
        a.documents.push((format!("{}.png", f.file), png.clone()));
        a.table(format!("csv/{}.csv", f.file), f.table.clone());
        blocks.push(FigureBlock {
            caption: f.caption.clone(),
            png,
            csv_name: Some(format!("csv/{}.csv", f.file)),
        });
    }
    let rows = compare(study);
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
    summary["metadata"] = serde_json::to_value(meta).unwrap_or_default();
    let report = build_report(model, &rows, blocks, meta);
    a.documents
        .push(("report.html".into(), html::render(&report).into_bytes()));
    a.headline = rows
        .iter()
        .map(|r| {
            format!(
                "{:<70} ours {:>10.4}  paper {:>8.3}  ({:+.1} %)",
                r.quantity,
                r.ours,
                r.paper,
                100.0 * r.relative_deviation()
            )
        })
        .collect::<Vec<_>>()
        .join("\n");
    a.summary = summary;
    a
}

pub fn build_report(
    model: &Model,
    rows: &[Compared],
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
