//! The HTML report of `gearwear run` on a gear train (`report::run_train`): the train's
//! overview (stages, ratios, speeds, torques, every mesh's force and wear, the mesh that
//! limits the life), then a section per stage (its mesh stiffness, force and wear
//! figures and its wear table). Every number comes from the run's studies.

use super::html::{FigureBlock, Report, Section, TableBlock};
use crate::dynamics::response::DynamicResponse;
use crate::format::shown;
use crate::store::RunMetadata;
use crate::study::train::TrainModel;
use crate::study::train_wear::TrainWearRun;
use crate::study::wear_loop::WearRun;
use crate::study::Model;
use serde_json::Value;

/// The studies of a train's run, as their jobs compute them.
pub struct TrainRun<'a> {
    /// The train's model and its train.
    pub model: &'a Model,
    /// The train (stages, meshes, operating point).
    pub train: &'a TrainModel,
    /// Each stage's single-pair model (`study::train_stages::stage_models`).
    pub stages: &'a [Model],
    /// The train's steady state with new teeth.
    pub response: &'a DynamicResponse,
    /// The wear runs, one per mode.
    pub runs: &'a [&'a TrainWearRun],
}

/// What the report of a stage shows, gathered from the three studies.
pub(crate) struct StageResults<'a> {
    /// 1-based stage number.
    pub n: usize,
    pub model: &'a Model,
    /// The stage's entry of the dynamics summary's `meshes`.
    pub dynamics: &'a Value,
    /// The stage's mesh worn in each mode, as a single pair's run.
    pub wear: Vec<WearRun>,
    pub figures: Vec<FigureBlock>,
    /// A faulty stage's lines on its teeth, fault and per-tooth wear (empty otherwise).
    pub teeth: Vec<String>,
}

/// The train's overall ratio: the product of its stages' z_gear / z_pinion (input speed
/// over output speed).
pub(crate) fn overall_ratio(train: &TrainModel) -> f64 {
    train
        .stages
        .iter()
        .map(|s| s.pair.gear.teeth as f64 / s.pair.pinion.teeth as f64)
        .product()
}

/// A number of a summary at `pointer` under `v`, shown (NaN, shown "NaN", when absent).
pub(super) fn at(v: &Value, pointer: &str) -> String {
    shown(
        v.pointer(pointer)
            .and_then(Value::as_f64)
            .unwrap_or(f64::NAN),
    )
}

/// Revolutions per second to revolutions per minute.
const RPM_PER_RAD_S: f64 = 30.0 / std::f64::consts::PI;

/// The report (see the module docs): `w` is the wear study's summary, `spectrum` the
/// dynamics study's spectrum figure.
pub(crate) fn build(
    run: &TrainRun,
    stages: &[StageResults],
    w: &Value,
    spectrum: Option<FigureBlock>,
    meta: &RunMetadata,
) -> Report {
    let n = stages.len();
    let mut sections = vec![overview(run, stages, w, spectrum)];
    sections.extend(stages.iter().map(stage_section));
    Report {
        title: format!("gearwear: dynamic wear prediction of a {n}-stage gear train"),
        intro_html: format!(
            "<p>Dynamic wear study of a {n}-stage parallel-axis gear train, every mesh worn at its own cycle count by the response of the whole train (docs/MODEL.md sections 4.1 and 5.1). Each study's files are in its folder, as its own command writes them: <code>stiffness/</code>, <code>dynamics/</code>, <code>wear/</code>.</p>"
        ),
        sections,
        footer: format!(
            "gearwear {} | case sha256 {} | command: run",
            meta.version, meta.case_sha256
        ),
    }
}

/// The train's overview: the stages, their ratios, speeds and torques, every mesh's
/// force and wear, and the mesh that limits the life.
fn overview(
    run: &TrainRun,
    stages: &[StageResults],
    w: &Value,
    spectrum: Option<FigureBlock>,
) -> Section {
    let op = &run.train.operating.meshes;
    let (first, last) = (op.first(), op.last());
    let mut paragraphs = vec![format!(
        "{} stages, overall ratio {}: input {} rpm and {} N m on stage 1's pinion, output {} rpm and {} N m on stage {}'s gear.",
        stages.len(),
        shown(overall_ratio(run.train)),
        shown(first.map_or(f64::NAN, |p| p.pinion_speed_rad_s * RPM_PER_RAD_S)),
        shown(first.map_or(f64::NAN, |p| p.pinion_torque_nm)),
        shown(last.map_or(f64::NAN, |p| p.gear_speed_rad_s * RPM_PER_RAD_S)),
        shown(last.map_or(f64::NAN, |p| p.gear_torque_nm)),
        stages.len(),
    )];
    for r in run.runs {
        let mode = r.mode.name();
        let limit = &w["limiting_mesh"][mode];
        if limit.is_null() {
            continue;
        }
        paragraphs.push(format!(
            "{}: after {} input cycles, stage {} limits the life (deepest wear {} µm, either flank): the train's wear life is that of its weakest mesh.",
            r.mode.label(),
            at(w, &format!("/input_cycles/{mode}")),
            at(limit, "/stage"),
            at(limit, "/max_wear_um"),
        ));
    }
    let header = [
        "stage",
        "teeth",
        "module (mm)",
        "ratio (-)",
        "pinion speed (rpm)",
        "mesh frequency (Hz)",
        "pinion torque (N m)",
        "mean / max mesh force (N)",
        "dynamic factor (-)",
        "max DTE (µm)",
    ];
    let mut header: Vec<String> = header.map(String::from).to_vec();
    header.extend(
        run.runs
            .iter()
            .map(|r| format!("max wear, {} (µm)", r.mode.label())),
    );
    let rows = stages
        .iter()
        .map(|s| {
            let (z1, z2) = (s.model.pair.pinion.teeth, s.model.pair.gear.teeth);
            let d = s.dynamics;
            let mut row = vec![
                s.n.to_string(),
                format!("{z1}/{z2}"),
                shown(s.model.case.gear.module_mm),
                shown(z2 as f64 / z1 as f64),
                at(d, "/pinion_speed_rpm"),
                at(d, "/mesh_frequency_hz"),
                at(d, "/pinion_torque_nm"),
                format!(
                    "{} / {}",
                    at(d, "/mesh_force/mean_n"),
                    at(d, "/mesh_force/max_n")
                ),
                at(d, "/mesh_force/dynamic_factor"),
                at(d, "/dte/max_um"),
            ];
            row.extend(s.wear.iter().map(|r| shown(deepest_um(r))));
            row
        })
        .collect();
    Section {
        heading: "The train".into(),
        paragraphs,
        figures: spectrum.into_iter().collect(),
        tables: vec![TableBlock {
            caption: "The stages: geometry and operating point, the steady state with new teeth, and the deepest wear (either flank) at the end of each wear run.".into(),
            header,
            rows,
            highlight_col: None,
        }],
    }
}

/// The deepest wear of a run's last update, either flank, um.
fn deepest_um(r: &WearRun) -> f64 {
    r.last().map_or(f64::NAN, |x| {
        x.wear.max_pinion_m().max(x.wear.max_gear_m()) * 1e6
    })
}

/// A stage's section: its mesh stiffness, its force with new teeth, its wear.
fn stage_section(s: &StageResults) -> Section {
    let (z1, z2) = (s.model.pair.pinion.teeth, s.model.pair.gear.teeth);
    let stiffness = super::run_report::stiffness_section(s.model, String::new(), vec![]);
    let d = s.dynamics;
    let mut paragraphs = stiffness.paragraphs;
    paragraphs.push(format!(
        "New teeth, in the train's steady state: mesh frequency {} Hz, mean mesh force {} N (static {} N), maximum {} N, dynamic factor {}, maximum DTE {} µm.",
        at(d, "/mesh_frequency_hz"),
        at(d, "/mesh_force/mean_n"),
        at(d, "/static_mesh_force_n"),
        at(d, "/mesh_force/max_n"),
        at(d, "/mesh_force/dynamic_factor"),
        at(d, "/dte/max_um"),
    ));
    paragraphs.extend(s.teeth.iter().cloned());
    Section {
        heading: format!(
            "Stage {}: z = {z1}/{z2}, m = {} mm",
            s.n,
            shown(s.model.case.gear.module_mm)
        ),
        paragraphs,
        figures: s.figures.clone(),
        tables: vec![wear_table(s)],
    }
}

/// A stage's wear at the end of each run: its own cycles, its maximum wear on each flank,
/// its largest wear rate.
fn wear_table(s: &StageResults) -> TableBlock {
    let header = [
        "wear run",
        "updates",
        "pinion cycles",
        "max wear, pinion (µm)",
        "max wear, gear (µm)",
        "max wear rate, pinion (µm per 1000 cycles)",
    ];
    let rows = s
        .wear
        .iter()
        .filter_map(|r| {
            let last = r.last()?;
            Some(vec![
                r.mode.label().to_string(),
                r.records.len().saturating_sub(1).to_string(),
                shown(last.wear.cycles),
                shown(last.wear.max_pinion_m() * 1e6),
                shown(last.wear.max_gear_m() * 1e6),
                shown(last.max_increment_pinion_m() * 1e9),
            ])
        })
        .collect();
    TableBlock {
        caption: format!(
            "Stage {}: its wear at the end of each run (cycles of the stage's own pinion).",
            s.n
        ),
        header: header.map(String::from).to_vec(),
        rows,
        highlight_col: None,
    }
}
