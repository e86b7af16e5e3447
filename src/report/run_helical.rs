//! Everything `gearwear run` writes on a helical pair (docs/MODEL.md 11.5): each study's
//! outputs in its own folder, exactly as that study's job writes them (`stiffness/`: the
//! slice stiffness, ISO 6336's values and the face load, `report::stiffness_helical` and
//! `report::face_load`; `dynamics/`: the steady state of the new teeth, `report::dynamics`
//! with the dynamic face load; `wear/`: both wear runs with the wear maps,
//! `report::wear` and `report::helical_wear`), each with its own `summary.json`; beside
//! them the figures of the dynamic response at the wear states (the spur run's Fig. 4-10,
//! `report::paper::section41_figures`, new teeth as the 0 µm state; their data under
//! `csv/`), the report (`report.html`, `run_helical_report`) embedding the studies'
//! figures, and `summary.json` (`helical_run`: the studies' key numbers copied from their
//! summaries, the wear states, where each study's files are). Under a load spectrum
//! (docs/MODEL.md 11.7) `wear/` is what `gearwear wear` writes under it (the spectrum's
//! wear maps and the duty tables and figures, `report::duty`), the studies read at the
//! monitoring bin, and the report adds the duty-cycle section (`report::duty::duty_section`).

use super::artifacts::{embed_existing, embed_figures, nest, Artifacts, EmbeddedFigure};
use super::duty::{duty_section, duty_summary};
use super::figure_output::FigureOutput;
use super::html::{self, FigureBlock};
use super::paper::{section41_figures, wear_states_json};
use super::run_helical_report::Parts;
use super::run_train::study_meta;
use crate::duty::life::LifeTable;
use crate::duty::wear::SpectrumRun;
use crate::duty::SpectrumModel;
use crate::store::RunMetadata;
use crate::study::paper::PaperStudy;
use crate::study::wear_loop::WearMode;
use crate::study::Model;
use serde_json::{json, Value};

/// The studies of a helical pair's run, as their jobs compute them.
pub struct HelicalRun<'a> {
    /// The planar model of the pair (`Model::helical_from_case`).
    pub model: &'a Model,
    /// Both wear runs, and the dynamic response at the wear states: the new teeth
    /// (0 µm) first, then the paper's states taken from the dynamic run.
    pub study: &'a PaperStudy,
    /// What `gearwear stiffness` writes for the pair.
    pub stiffness: Artifacts,
    /// The metadata `gearwear stiffness` stamps (its case as given: the slice model does
    /// not resolve the case as the planar model does).
    pub stiffness_meta: RunMetadata,
    /// What `gearwear dynamics` writes for the new teeth.
    pub dynamics: Artifacts,
    /// What `gearwear wear` writes for the wear runs (`report::wear::wear_artifacts`, or
    /// under a load spectrum `report::duty::duty_wear_artifacts`).
    pub wear: Artifacts,
    /// The runs under a load spectrum, when the case has one (docs/MODEL.md 11.7).
    pub duty: Option<HelicalDuty<'a>>,
}

/// A helical pair's runs under a load spectrum, for the report's duty-cycle section.
pub struct HelicalDuty<'a> {
    /// The bins' models (the run's `model` is the monitoring bin's).
    pub sm: &'a SpectrumModel,
    /// The spectrum runs, dynamic first.
    pub runs: &'a [SpectrumRun],
    /// The life table.
    pub life: Option<&'a LifeTable>,
}

/// The artifacts of a helical pair's run (see the module docs); `meta` is the run's.
pub fn helical_run_artifacts(
    run: HelicalRun,
    meta: &RunMetadata,
    figures: FigureOutput,
) -> Result<Artifacts, super::artifacts::WriteError> {
    let (model, study) = (run.model, run.study);
    let mut a = Artifacts::default().with_figure_output(figures);
    let wear = run.wear;
    let headline = [
        ("stiffness", &run.stiffness.headline),
        ("dynamics, new teeth", &run.dynamics.headline),
        ("wear", &wear.headline),
    ]
    .map(|(k, h)| format!("{k}:\n{h}"))
    .join("\n");
    let s = nest(&mut a, "stiffness", run.stiffness, &run.stiffness_meta)?;
    let d = nest(
        &mut a,
        "dynamics",
        run.dynamics,
        &study_meta(meta, "dynamics"),
    )?;
    let w = nest(&mut a, "wear", wear, &study_meta(meta, "wear"))?;
    let stiffness_figures = embed_all(
        &mut a,
        &[
            ("stiffness/mesh_stiffness.png", "from the stiffness study"),
            (
                "stiffness/face_load.png",
                "static, from the stiffness study",
            ),
        ],
    );
    let mut dynamics_figures = embed_all(
        &mut a,
        &[(
            "dynamics/face_load.png",
            "new teeth, from the dynamics study",
        )],
    );
    dynamics_figures.extend(embed_figures(&mut a, state_figures(model, study)));
    let mut wear_paths: Vec<String> = [
        "fig11_force_and_wear_initial",
        "fig12_wear_rate_evolution",
        "fig13_max_accumulated_wear",
    ]
    .iter()
    .map(|stem| format!("wear/{stem}.png"))
    .collect();
    for r in [&study.dynamic, &study.quasi_static] {
        wear_paths.push(format!("wear/wear_map_{}.png", r.mode.name()));
        wear_paths.push(format!("wear/worn_profiles_{}.png", r.mode.name()));
    }
    let note = "from the wear study";
    let refs: Vec<(&str, &str)> = wear_paths.iter().map(|p| (p.as_str(), note)).collect();
    let wear_figures = embed_all(&mut a, &refs);
    let states = wear_states_json(&study.wear_states);
    a.summary = summary(&s, &d, &w, &states, model);
    a.headline = headline;
    let parts = Parts {
        stiffness: s,
        dynamics: d,
        wear: w,
        stiffness_figures,
        dynamics_figures,
        wear_figures,
    };
    let mut report = super::run_helical_report::build(&parts, study, &states, meta);
    if let Some(d) = &run.duty {
        add_duty(&mut a, &mut report, d);
    }
    a.documents
        .push(("report.html".into(), html::render(&report).into_bytes()));
    Ok(a)
}

/// The duty-cycle section of a helical pair's run under a spectrum (`report::duty`'s, its
/// figures those the wear study wrote under `wear/`), the summary's `load_spectrum` and
/// every bin's warnings, and the report's title saying so.
fn add_duty(a: &mut Artifacts, report: &mut html::Report, d: &HelicalDuty) {
    let runs: Vec<&SpectrumRun> = d.runs.iter().collect();
    let mut paths = vec!["wear/duty_spectrum.png".to_string()];
    for r in &runs {
        paths.push(format!("wear/duty_wear_by_bin_{}.png", r.mode.name()));
        paths.push(format!("wear/duty_dynamic_factor_{}.png", r.mode.name()));
    }
    paths.push("wear/duty_life.png".into());
    let note = "from the wear study under the spectrum";
    let refs: Vec<(&str, &str)> = paths.iter().map(|p| (p.as_str(), note)).collect();
    let figs = embed_all(a, &refs);
    let main = runs
        .iter()
        .copied()
        .find(|r| r.mode == WearMode::Dynamic)
        .or(runs.first().copied());
    if let Some(main) = main {
        report.sections.push(duty_section(d.sm, main, d.life, figs));
    }
    report.title = format!("{} under a load spectrum", report.title);
    a.summary["load_spectrum"] = duty_summary(d.sm, &runs, d.life);
    a.summary["warnings"] = json!(d.sm.warnings());
}

/// The blocks of the figures of `a` at each path, each captioned by its own title and the
/// note beside it (a figure the study did not write, such as a face load without lead
/// gaps, is left out).
fn embed_all(a: &mut Artifacts, figures: &[(&str, &str)]) -> Vec<FigureBlock> {
    figures
        .iter()
        .filter_map(|(path, note)| {
            let title = a
                .figures
                .iter()
                .find(|f| f.path == *path)?
                .figure
                .title
                .clone();
            embed_existing(a, path, format!("{title} ({note})."))
        })
        .collect()
}

/// Fig. 4-10 of the spur run (`report::paper::section41_figures`) at the run's wear
/// states, the new teeth drawn as the 0 µm state (the time series' titles say so).
fn state_figures(model: &Model, study: &PaperStudy) -> Vec<EmbeddedFigure> {
    section41_figures(model, study)
        .into_iter()
        .map(|mut f| {
            f.figure.title = f
                .figure
                .title
                .replace(SPUR_STATES, "with new teeth and at three wear states");
            EmbeddedFigure {
                caption: format!(
                    "{} (0 µm: new teeth; a worn state is the dynamic run's wear map scaled to that deepest pinion wear; paper Fig. {} for a spur pair).",
                    f.figure.title, f.paper_figure
                ),
                stem: f.file,
                figure: f.figure,
                table: f.table,
            }
        })
        .collect()
}

/// How the spur run's time series name their three wear states (`report::paper`).
const SPUR_STATES: &str = "at three wear states";

/// `summary.json` of the run: the studies' key numbers, each copied from its summary, and
/// the wear states (`report::paper::wear_states_json`).
fn summary(s: &Value, d: &Value, w: &Value, states: &Value, model: &Model) -> Value {
    let keep = |v: &Value, keys: &[&str]| -> Value {
        Value::Object(
            keys.iter()
                .filter(|k| !v[**k].is_null())
                .map(|k| ((*k).to_owned(), v[*k].clone()))
                .collect(),
        )
    };
    json!({
        "helical_run": {
            "stiffness": keep(s, &["helical", "mesh_stiffness", "mesh_stiffness_spur_transverse", "centre_of_pressure_mm", "iso6336", "face_load"]),
            "new_teeth": keep(d, &["mesh_frequency_hz", "dte", "mesh_force", "velocity_y_pinion", "mesh_harmonics", "friction_coefficient", "helical", "face_load"]),
            "wear_states": states,
            "wear": keep(w, &["cycles", "max_wear_pinion_um", "max_wear_gear_um", "updates", "stopped", "ratio_max_wear_dynamic_to_static", "ratio_max_wear_rate_dynamic_to_static", "ratio_at_cycles", "wear_map"]),
            "studies": {
                "stiffness": "stiffness/summary.json",
                "dynamics": "dynamics/summary.json",
                "wear": "wear/summary.json",
            },
        },
        "warnings": model.warnings,
    })
}
