//! The paper's section 4 as one report (`gearwear run`): the figures of its Fig. 2 and
//! 4-13 with the table behind each, the summary, and the self-contained HTML report. The
//! paper comparison appears only when the case is the paper's (`case::is_paper_case`);
//! otherwise a summary of the case that was run takes its place (`run_report`).

use super::artifacts::{embed_figures, Artifacts, EmbeddedFigure};
use super::case::{case_json, is_paper_case, paper_case_differences};
use super::comparison::{compare, comparison_json, with_twin};
use super::figure_output::FigureOutput;
use super::figures::{panel, points_panel, single, spectrum_panel, spectrum_rows, Curve, Fig};
use super::html;
use super::plot::{Figure, LineStyle};
use super::run_report::{build_report, case_headline, comparison_headline, results_json};
use super::stiffness::{figure2, stiffness_table};
use super::wear::{wear_figures, wear_summary};
use crate::dynamics::model::dof;
use crate::dynamics::response::{PathSample, Signals};
use crate::dynamics::summary::velocity_y_spectrum;
use crate::io::Table;
use crate::store::RunMetadata;
use crate::study::paper::{PaperStudy, WearStateResult};
use crate::study::Model;
use serde_json::json;

/// Mesh periods shown in the time plots.
const SHOWN_PERIODS: usize = 3;

fn fig(file: &str, paper_figure: u32, figure: Figure, table: Table) -> Fig {
    Fig {
        file: file.into(),
        paper_figure,
        caption: figure.title.clone(),
        figure,
        table,
    }
}

fn state_label(w: f64) -> String {
    format!("{w} µm wear")
}

/// A time series of the three wear states over the first [`SHOWN_PERIODS`] mesh periods.
fn time_figure(
    model: &Model,
    study: &PaperStudy,
    f: &dyn Fn(&Signals, usize) -> f64,
    (title, y, col): (&str, &str, &str),
) -> (Figure, Table) {
    let mut curves = Vec::new();
    let mut table = Table::new();
    for s in &study.wear_states {
        let sig = &s.response.signals;
        let per = sig.time_s.len() / model.settings.evaluated_mesh_periods.max(1);
        let n = (per * SHOWN_PERIODS).min(sig.time_s.len());
        let t0 = sig.time_s.first().copied().unwrap_or(0.0);
        let t: Vec<f64> = sig.time_s[..n].iter().map(|t| (t - t0) * 1e3).collect();
        let v: Vec<f64> = (0..n).map(|k| f(sig, k)).collect();
        table = table
            .col(&format!("time_ms_{}um", s.max_wear_um), t.clone())
            .col(&format!("{col}_{}um", s.max_wear_um), v.clone());
        curves.push(Curve::new(state_label(s.max_wear_um), t, v));
    }
    (single(title, panel("time (ms)", y, curves)), table)
}

/// A quantity along the path of contact at the three wear states.
fn path_figure(
    study: &PaperStudy,
    f: &dyn Fn(&PathSample) -> f64,
    (title, y, col): (&str, &str, &str),
) -> (Figure, Table) {
    let mut curves = Vec::new();
    let mut table = Table::new();
    for s in &study.wear_states {
        let x: Vec<f64> = s.response.meshes[0]
            .path
            .iter()
            .map(|p| p.rho1_m * 1e3)
            .collect();
        let v: Vec<f64> = s.response.meshes[0].path.iter().map(f).collect();
        table = table
            .col(&format!("rho1_mm_{}um", s.max_wear_um), x.clone())
            .col(&format!("{col}_{}um", s.max_wear_um), v.clone());
        curves.push(Curve::new(state_label(s.max_wear_um), x, v));
    }
    let along = "pinion roll distance along the path of contact (mm)";
    (single(title, panel(along, y, curves)), table)
}

/// Figures 4-10: the dynamic response at the three wear states.
pub fn section41_figures(model: &Model, study: &PaperStudy) -> Vec<Fig> {
    let mut out = Vec::new();
    let (f, t) = time_figure(
        model,
        study,
        &|s, k| s.meshes[0].dte_m[k] * 1e6,
        (
            "Dynamic transmission error at three wear states",
            "dynamic transmission error (µm)",
            "dte_um",
        ),
    );
    out.push(fig("fig04_dte", 4, f, t));
    let (f, t) = time_figure(
        model,
        study,
        &|s, k| s.velocity[k][dof::YP] * 1e3,
        (
            "Pinion velocity in y at three wear states",
            "pinion y velocity (mm/s)",
            "velocity_mm_per_s",
        ),
    );
    out.push(fig("fig05_velocity_y_pinion", 5, f, t));
    out.extend(fig06_spectrum(model, study));
    out.push(fig07_mesh_harmonics(study));
    let (f, t) = time_figure(
        model,
        study,
        &|s, k| s.meshes[0].mesh_force_n[k],
        (
            "Mesh force at three wear states",
            "mesh force (N)",
            "mesh_force_n",
        ),
    );
    out.push(fig("fig08_mesh_force", 8, f, t));
    let (f, t) = path_figure(
        study,
        &|p| p.friction_coefficient,
        (
            "Friction coefficient of a tooth pair through its engagement",
            "friction coefficient (-)",
            "friction_coefficient",
        ),
    );
    out.push(fig("fig09_friction_coefficient", 9, f, t));
    let (f, t) = path_figure(
        study,
        &|p| p.friction_n,
        (
            "Friction force of a tooth pair through its engagement",
            "friction force (N)",
            "friction_force_n",
        ),
    );
    out.push(fig("fig10_friction_force", 10, f, t));
    out
}

/// Figure 6: the spectrum of the pinion's y velocity at the 0.5 µm wear state, up to five
/// mesh frequencies (none when the study has no such state).
fn fig06_spectrum(model: &Model, study: &PaperStudy) -> Option<Fig> {
    let f_mesh = model.params.operating.mesh_frequency_hz;
    if let Some(mid) = study
        .wear_states
        .iter()
        .find(|s| (s.max_wear_um - 0.5).abs() < 1e-9)
    {
        let spec = velocity_y_spectrum(&mid.response);
        let amp: Vec<f64> = spec.amplitude.iter().map(|a| a * 1e3).collect();
        let (fr, amp) = spectrum_rows(&spec.frequency_hz, &amp, 5.0 * f_mesh);
        let title = format!(
            "Spectrum of the pinion y velocity at {} µm wear",
            mid.max_wear_um
        );
        let figure = single(
            &title,
            spectrum_panel("amplitude (mm/s)", &fr, &amp, f_mesh),
        );
        let table = Table::new()
            .col("frequency_hz", fr)
            .col("amplitude_mm_per_s", amp);
        return Some(fig("fig06_spectrum", 6, figure, table));
    }
    None
}

/// Figure 7: the first four mesh-harmonic amplitudes of the pinion's y velocity (mm/s)
/// against the maximum wear depth (µm) of the wear states.
fn fig07_mesh_harmonics(study: &PaperStudy) -> Fig {
    let wear: Vec<f64> = study.wear_states.iter().map(|s| s.max_wear_um).collect();
    let mut curves = Vec::new();
    let mut table = Table::new().col("max_wear_um", wear.clone());
    for h in 0..4 {
        let a: Vec<f64> = study
            .wear_states
            .iter()
            .map(|s| s.summary.velocity_y_pinion_harmonics_m_per_s[h] * 1e3)
            .collect();
        table = table.col(&format!("harmonic{}_mm_per_s", h + 1), a.clone());
        let name = super::figures::harmonic_label(h + 1);
        curves.push(Curve::new(name, wear.clone(), a));
    }
    // Three wear states are three points each: markers only, no line between them that
    // would suggest values at wear depths that were not computed.
    let mut harmonics = points_panel("maximum pinion wear depth (µm)", "amplitude (mm/s)", curves);
    for s in &mut harmonics.series {
        s.style = LineStyle::Points;
    }
    let figure = single(
        "Mesh-harmonic amplitudes of the pinion y velocity against wear",
        harmonics,
    );
    fig("fig07_mesh_harmonics", 7, figure, table)
}

/// `wear_states` of the summary of `gearwear run`: each state's wear, roughness and the
/// headline numbers of its dynamic response.
pub fn wear_states_json(states: &[WearStateResult]) -> serde_json::Value {
    json!(states.iter().map(|s| json!({
        "max_wear_um": s.max_wear_um,
        "roughness_um": s.roughness_um,
        "dte_max_um": s.summary.dte_max_m * 1e6,
        "velocity_y_pinion_rms_mm_per_s": s.summary.velocity_y_pinion_rms_m_per_s * 1e3,
        "mesh_force_mean_n": s.summary.mesh_force_mean_n,
        "mesh_force_max_n": s.summary.mesh_force_max_n,
        "mesh_harmonics_mm_per_s": s.summary.velocity_y_pinion_harmonics_m_per_s.iter().map(|x| x * 1e3).collect::<Vec<_>>(),
        "friction_coefficient_max": s.summary.friction_coefficient_max,
        "friction_force_max_abs_n": s.summary.friction_force_max_n,
    })).collect::<Vec<_>>())
}

/// Every figure of `gearwear run`, in the paper's order, each with its own table
/// (`st_table`: the mesh-stiffness table of `stiffness_table`).
pub fn run_figures(model: &Model, study: &PaperStudy, st_table: Table) -> Vec<Fig> {
    let mut figs = vec![fig(
        "fig02_mesh_stiffness",
        2,
        figure2(model, &st_table),
        st_table,
    )];
    figs.extend(section41_figures(model, study));
    let runs = [&study.dynamic, &study.quasi_static];
    for (n, w) in (11..).zip(wear_figures(model, &runs)) {
        figs.push(fig(w.stem, n, w.figure, w.table));
    }
    // Beyond the paper (no figure number): the worn profiles of both studies.
    for w in super::worn_profile::worn_profile_figures(model, &runs) {
        figs.push(fig(&w.stem, 0, w.figure, w.table));
    }
    figs.extend(super::teeth::run_teeth_figures(model, study));
    figs
}

/// The paper's case run under the other contact model (`contact.path`): its model and
/// study, whose numbers the comparison sets beside the case's own.
pub type ContactTwin<'a> = (&'a Model, &'a PaperStudy);

/// Everything `gearwear run` writes: figures (in the formats and size of `figures`) with
/// their CSVs under `csv/`, the wear-study tables, `summary.json` and `report.html` (which
/// embeds the same figures). `meta` is stamped on the summary and the report footer.
/// `twin`: the case under the other contact model, for the paper comparison's other
/// column (`None`: that column reads "not run").
pub fn run_artifacts(
    model: &Model,
    study: &PaperStudy,
    twin: Option<ContactTwin>,
    meta: &RunMetadata,
    figures: FigureOutput,
) -> Artifacts {
    let paper = is_paper_case(&model.case).then_some(twin);
    let (mut a, report) = run_artifacts_and_report(model, study, meta, paper, figures);
    a.documents
        .push(("report.html".into(), html::render(&report).into_bytes()));
    a
}

/// [`run_artifacts`] with the report not yet rendered (a caller may add sections);
/// `paper`: whether the results are set beside the paper's (`Some`), with the twin of
/// [`run_artifacts`].
pub fn run_artifacts_and_report(
    model: &Model,
    study: &PaperStudy,
    meta: &RunMetadata,
    paper: Option<Option<ContactTwin>>,
    figures: FigureOutput,
) -> (Artifacts, html::Report) {
    let (st_table, st_json) = stiffness_table(model);
    let figs = run_figures(model, study, st_table);
    let mut a = Artifacts::default().with_figure_output(figures);
    for r in [&study.dynamic, &study.quasi_static] {
        for (name, t) in super::wear::run_tables(model, r) {
            a.table(format!("csv/{name}"), t);
        }
    }
    let blocks = embed_figures(
        &mut a,
        figs.into_iter()
            .map(|f| EmbeddedFigure {
                caption: match paper.is_some() {
                    true if f.paper_figure > 0 => {
                        format!("{} (paper Fig. {}).", f.caption, f.paper_figure)
                    }
                    _ => format!("{}.", f.caption),
                },
                stem: f.file.to_string(),
                figure: f.figure,
                table: f.table,
            })
            .collect(),
    );
    let mut summary = json!({
        "paper_case": paper.is_some(),
        "stiffness": st_json,
        "wear_study": wear_summary(Some(&study.dynamic), Some(&study.quasi_static)),
        "wear_states": wear_states_json(&study.wear_states),
        "warnings": model.warnings,
    });
    let rows = if let Some(twin) = paper {
        let twin_rows = twin.map_or(Vec::new(), |(m, s)| compare(m, s));
        let rows = with_twin(compare(model, study), &twin_rows);
        summary["paper_comparison"] = comparison_json(&rows);
        a.headline = comparison_headline(&rows);
        rows
    } else {
        summary["differs_from_paper_case_in"] = json!(paper_case_differences(&model.case));
        summary["case_summary"] = json!({
            "case": case_json(model),
            "results": results_json(study),
        });
        a.headline = case_headline(model, study);
        Vec::new()
    };
    if let Some(t) = super::teeth::teeth_json(model) {
        summary["teeth"] = t;
    }
    summary["metadata"] = serde_json::to_value(meta).unwrap_or_default();
    let report = build_report(model, study, &rows, blocks, meta);
    a.summary = summary;
    (a, report)
}
