//! Everything `gearwear run` writes on a gear train (`[[stage]]`): each study's outputs in
//! its own folder, exactly as that study's job writes them (`stiffness/`: each stage's
//! mesh stiffness, `report::stiffness_train`; `dynamics/`: the train's steady state with
//! new teeth, `report::dynamics`; `wear/`: each mesh worn at its own cycle count,
//! `report::wear_train`), each with its own `summary.json`; beside them the report
//! (`report.html`: the train's overview, then a section per stage, `run_train_report`),
//! the figures it adds (`stageK_mesh_force.png`, `stageK_fig11..13_*.png`, their data
//! under `csv/`) and `summary.json` (the train, every mesh's key numbers from the three
//! studies, the mesh that limits the life, where each study's files are).

use super::artifacts::{embed_existing, embed_figures, nest, Artifacts, EmbeddedFigure};
use super::duty_train::TrainDutyParts;
use super::dynamics::dynamics_artifacts;
use super::figure_output::FigureOutput;
use super::figures::{panel, Curve};
use super::html::{self, FigureBlock};
use super::plot::Figure;
pub use super::run_train_report::TrainRun;
use super::run_train_report::{overall_ratio, StageResults};
use super::stiffness_train::train_stiffness_artifacts;
use super::teeth::own_and_others_line;
use super::wear::wear_figures;
use super::wear_train::train_wear_artifacts;
use crate::io::Table;
use crate::store::RunMetadata;
use crate::study::wear_loop::WearRun;
use crate::wear::tooth_wear::deepest_own_and_others;
use serde_json::{json, Value};

/// Mesh periods of a stage shown in its force figure.
const SHOWN_PERIODS: f64 = 3.0;

/// A study's metadata: the run's with the study's command, as its own job stamps it.
pub(super) fn study_meta(meta: &RunMetadata, command: &str) -> RunMetadata {
    RunMetadata {
        command: command.to_owned(),
        ..meta.clone()
    }
}

/// The artifacts of a train's run (see the module docs); `meta` is the run's.
pub fn train_run_artifacts(
    run: &TrainRun,
    meta: &RunMetadata,
    figures: FigureOutput,
) -> Result<Artifacts, super::artifacts::WriteError> {
    train_run_artifacts_with(run, meta, figures, None)
}

/// [`train_run_artifacts`] with what a load spectrum adds (`duty`: its summary and lines
/// in the wear study's and the run's outputs, its section at the end of the report).
pub fn train_run_artifacts_with(
    run: &TrainRun,
    meta: &RunMetadata,
    figures: FigureOutput,
    duty: Option<&TrainDutyParts>,
) -> Result<Artifacts, super::artifacts::WriteError> {
    let (model, train) = (run.model, run.train);
    let mut a = Artifacts::default().with_figure_output(figures);
    let stiffness = train_stiffness_artifacts(model, run.stages);
    let dynamics = dynamics_artifacts(model, run.response, "new teeth");
    let mut wear = train_wear_artifacts(model, train, run.runs);
    if let Some(d) = duty {
        d.add_to(&mut wear);
    }
    let headline = [
        ("stiffness", &stiffness.headline),
        ("dynamics, new teeth", &dynamics.headline),
        ("wear", &wear.headline),
    ]
    .map(|(k, h)| format!("{k}:\n{h}"))
    .join("\n");
    let s = nest(
        &mut a,
        "stiffness",
        stiffness,
        &study_meta(meta, "stiffness"),
    )?;
    let d = nest(&mut a, "dynamics", dynamics, &study_meta(meta, "dynamics"))?;
    let w = nest(&mut a, "wear", wear, &study_meta(meta, "wear"))?;
    let no_meshes = Vec::new();
    let dyn_meshes = d["meshes"].as_array().unwrap_or(&no_meshes);
    let mut stages = Vec::new();
    for (m, stage) in run.stages.iter().enumerate() {
        let n = m + 1;
        let wear: Vec<WearRun> = run
            .runs
            .iter()
            .map(|r| WearRun {
                mode: r.mode,
                records: r.mesh_records(m),
                stopped: None,
            })
            .collect();
        let mut blocks: Vec<FigureBlock> = embed_existing(
            &mut a,
            &format!("stiffness/mesh_stiffness_stage{n}.png"),
            format!("Stage {n}: mesh stiffness over a mesh period (from the stiffness study)."),
        )
        .into_iter()
        .collect();
        let mut figs = vec![force_figure(run, m)];
        let refs: Vec<&WearRun> = wear.iter().collect();
        figs.extend(
            wear_figures(stage, &refs)
                .into_iter()
                .map(|f| EmbeddedFigure {
                    stem: format!("stage{n}_{}", f.stem),
                    caption: format!(
                        "Stage {n}: {} (cycles of the stage's pinion).",
                        lower_first(&f.figure.title)
                    ),
                    figure: f.figure,
                    table: f.table,
                }),
        );
        blocks.extend(embed_figures(&mut a, figs));
        let teeth = faulty_stage_parts(&mut a, n, stage, &train.stages[m], &wear, &mut blocks);
        stages.push(StageResults {
            n,
            model: stage,
            dynamics: dyn_meshes.get(m).unwrap_or(&Value::Null),
            wear,
            figures: blocks,
            teeth,
        });
    }
    let spectrum = embed_existing(
        &mut a,
        "dynamics/spectrum_velocity_y_pinion.png",
        "Spectrum of the first stage pinion's y velocity, new teeth (from the dynamics study)."
            .into(),
    );
    a.summary = summary(run, &s, &d, &w);
    a.headline = headline;
    let mut report = super::run_train_report::build(run, &stages, &w, spectrum, meta);
    if let Some(d) = duty {
        a.summary["load_spectrum"] = d.summary.clone();
        report.sections.push(d.section.clone());
    }
    a.documents
        .push(("report.html".into(), html::render(&report).into_bytes()));
    Ok(a)
}

/// A faulty stage's lines ([`faulty_stage_lines`]) and its every tooth's wear maps of
/// each run (written by the wear study) added to `blocks`; nothing for a healthy stage.
fn faulty_stage_parts(
    a: &mut Artifacts,
    n: usize,
    stage: &crate::study::Model,
    st: &crate::study::train::Stage,
    wear: &[WearRun],
    blocks: &mut Vec<FigureBlock>,
) -> Vec<String> {
    let (Some(inputs), Some(tm)) = (&st.tooth_inputs, &st.teeth) else {
        return Vec::new();
    };
    for r in wear {
        let path = format!("wear/teeth_wear_{}_stage{n}.png", r.mode.name());
        let caption = format!(
            "Stage {n}: wear of every tooth at the end of the {} wear run (from the wear study).",
            r.mode.label()
        );
        blocks.extend(embed_existing(a, &path, caption));
    }
    faulty_stage_lines(n, stage, inputs, tm.periods(), wear)
}

/// What the report says of a faulty stage `n` (its pair `stage`, its teeth `inputs`, its
/// excitation of `periods` mesh periods): how its teeth are resolved, each fault, and per
/// wear run the faulty tooth's deepest wear beside the deepest of its gear's other teeth.
fn faulty_stage_lines(
    n: usize,
    stage: &crate::study::Model,
    inputs: &crate::study::teeth::ToothInputs,
    periods: usize,
    wear: &[WearRun],
) -> Vec<String> {
    let (z1, z2) = (stage.pair.pinion.teeth, stage.pair.gear.teeth);
    let mut lines = vec![format!(
        "Stage {n}'s teeth are resolved one by one: its mesh cycle c engages pinion tooth c mod {z1} and gear tooth c mod {z2}, the stage's excitation repeats after {periods} of its mesh periods, and each tooth wears from its own contacts (docs/MODEL.md 9.10)."
    )];
    for f in inputs.faults.iter().filter(|f| f.changes_tooth()) {
        lines.push(format!(
            "Fault: {} on {} tooth {}.",
            f.kind().name(),
            f.gear.name(),
            f.tooth
        ));
        for r in wear {
            let Some(teeth) = r.last().and_then(|l| l.wear.teeth.as_ref()) else {
                continue;
            };
            let profiles = match f.gear {
                crate::config::case::Member::Pinion => &teeth.pinion_m,
                crate::config::case::Member::Gear => &teeth.gear_m,
            };
            let Some((own, others)) = deepest_own_and_others(profiles, f.tooth) else {
                continue;
            };
            let um = |x: f64| crate::format::shown(x * 1e6);
            lines.push(own_and_others_line(
                r.mode.label(),
                &format!("{} tooth {}", f.gear.name(), f.tooth),
                f.gear.name(),
                (&um(own), &um(others)),
            ));
        }
    }
    lines
}

/// The DTE and mesh force of stage `m` (0-based) over [`SHOWN_PERIODS`] of its mesh
/// periods of the steady state with new teeth, with the table of its data.
fn force_figure(run: &TrainRun, m: usize) -> EmbeddedFigure {
    let n = m + 1;
    let sig = &run.response.signals;
    let period_s = 1.0 / run.train.operating.meshes[m].mesh_frequency_hz;
    let t0 = sig.time_s.first().copied().unwrap_or(0.0);
    let k = sig
        .time_s
        .iter()
        .take_while(|t| **t - t0 <= SHOWN_PERIODS * period_s)
        .count();
    let t_ms: Vec<f64> = sig.time_s[..k].iter().map(|t| (t - t0) * 1e3).collect();
    let mesh = &sig.meshes[m];
    let dte_um: Vec<f64> = mesh.dte_m[..k].iter().map(|x| x * 1e6).collect();
    let force_n = mesh.mesh_force_n[..k].to_vec();
    let title = format!("Stage {n}: dynamic transmission error and mesh force, new teeth");
    let figure = Figure {
        title: title.clone(),
        panels: vec![
            panel(
                "time (ms)",
                "dynamic transmission error (µm)",
                vec![Curve::new("DTE", t_ms.clone(), dte_um.clone())],
            ),
            panel(
                "time (ms)",
                "mesh force (N)",
                vec![Curve::new("mesh force", t_ms.clone(), force_n.clone())],
            ),
        ],
    };
    let table = Table::new()
        .col("time_ms", t_ms)
        .col("dte_um", dte_um)
        .col("mesh_force_n", force_n);
    EmbeddedFigure {
        stem: format!("stage{n}_mesh_force"),
        caption: format!("{title}, over three of its mesh periods."),
        figure,
        table,
    }
}

/// `summary.json` of the run: the train, each mesh's key numbers from the studies'
/// summaries `s`, `d`, `w` (stiffness, dynamics, wear), the mesh that limits the life and
/// where each study's files are.
fn summary(run: &TrainRun, s: &Value, d: &Value, w: &Value) -> Value {
    let train = run.train;
    let meshes: Vec<Value> = train
        .stages
        .iter()
        .enumerate()
        .map(|(m, stage)| {
            let (z1, z2) = (stage.pair.pinion.teeth, stage.pair.gear.teeth);
            let dm = &d["meshes"][m];
            json!({
                "stage": m + 1,
                "teeth": [z1, z2],
                "ratio": z2 as f64 / z1 as f64,
                "module_mm": stage.case.gear.module_mm,
                "contact_ratio": s["meshes"][m]["contact_ratio"],
                "mesh_stiffness": s["meshes"][m]["mesh_stiffness"],
                "mesh_frequency_hz": dm["mesh_frequency_hz"],
                "pinion_speed_rpm": dm["pinion_speed_rpm"],
                "pinion_torque_nm": dm["pinion_torque_nm"],
                "static_mesh_force_n": dm["static_mesh_force_n"],
                "mesh_force": dm["mesh_force"],
                "dte": dm["dte"],
                "wear": w["meshes"][m]["final"],
            })
        })
        .collect();
    json!({
        "train": {
            "stages": train.stages.len(),
            "overall_ratio": overall_ratio(train),
            "input_speed_rpm": run.model.case.operating.input_speed_hz * 60.0,
        },
        "meshes": meshes,
        "limiting_mesh": w["limiting_mesh"],
        "limiting_mesh_notes": w["limiting_mesh_notes"],
        "input_cycles": w["input_cycles"],
        "stopped": w["stopped"],
        "studies": {
            "stiffness": "stiffness/summary.json",
            "dynamics": "dynamics/summary.json",
            "wear": "wear/summary.json",
        },
        "warnings": run.model.warnings,
    })
}

/// `s` with its first letter in lower case (a figure's title inside a caption).
fn lower_first(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_lowercase().chain(c).collect())
        .unwrap_or_default()
}
