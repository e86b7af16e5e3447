//! Everything `gearwear run` writes on a planetary set (`[planetary]`): each study's
//! outputs in its own folder, exactly as that study's job writes them (`stiffness/`:
//! `report::stiffness_planetary`; `dynamics/`: `report::dynamics_planetary`; `signals/`:
//! `report::signals_planetary`, when the ring is fixed and the record steady; `wear/`:
//! `report::wear_planetary`), each with its own `summary.json`; beside them the report
//! (`report.html`, `run_planetary_report`), the ring sensor's sideband figure it adds
//! (`ring_sensor_sidebands.png`, its data under `csv/`) and `summary.json`: the set, its
//! modes, every mesh's force, the planets' load sharing, every member's wear and the
//! limiting member, a faulty tooth's wear beside its member's other teeth, the ring sensor's mesh harmonics, each copied from its study's
//! summary, and where each study's files are. Under a load spectrum (`report::duty_planetary`)
//! `wear/` holds what `gearwear wear` writes under it, the summary a copy of its
//! `load_spectrum` and the report a duty-cycle section.

use super::artifacts::{embed_existing, embed_figures, nest, Artifacts, EmbeddedFigure};
use super::figure_output::FigureOutput;
use super::figures::{panel, Curve};
use super::html;
use super::plot::Figure;
use super::run_planetary_report::Summaries;
use super::run_train::study_meta;
use super::wear_planetary::planetary_wear_artifacts;
use crate::duty::planetary::{PlanetarySpectrum, PlanetarySpectrumRun};
use crate::io::Table;
use crate::store::RunMetadata;
use crate::study::planetary::PlanetaryStudy;
use crate::study::planetary_dynamics::PlanetaryDynamics;
use crate::study::planetary_signals::RingSensorRecord;
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::study::planetary_wear_loop::PlanetaryWearRun;
use serde_json::{json, Value};

/// The studies of a planetary set's run, as their jobs compute them.
pub struct PlanetaryRun<'a> {
    /// The set's stiffness study (geometry, meshes, kinematics, modes).
    pub study: &'a PlanetaryStudy,
    /// The set's dynamic model, solved.
    pub dynamics: &'a PlanetaryDynamics,
    /// What `gearwear stiffness` writes for the set.
    pub stiffness: Artifacts,
    /// What `gearwear dynamics` writes for the set.
    pub dynamics_artifacts: Artifacts,
    /// What `gearwear signals` writes for the set and the ring sensor's record (`None`:
    /// the ring turns, or the case asks for a record the ring sensor cannot make).
    pub signals: Option<(Artifacts, RingSensorRecord)>,
    /// The set's wear model.
    pub wear_model: &'a PlanetaryWearModel,
    /// The wear runs, one per mode (under a spectrum: read as one run of the set at the
    /// monitoring bin, `duty::planetary::combined_planetary_run`).
    pub runs: &'a [&'a PlanetaryWearRun],
    /// Under a load spectrum: the spectrum and its runs, one per mode (their outputs go to
    /// `wear/` as `gearwear wear` writes them, and the report gets a duty-cycle section).
    pub duty: Option<(&'a PlanetarySpectrum, &'a [&'a PlanetarySpectrumRun])>,
}

/// The artifacts of a planetary set's run (see the module docs); `meta` is the run's.
pub fn planetary_run_artifacts(
    run: PlanetaryRun,
    meta: &RunMetadata,
    figures: FigureOutput,
) -> Result<Artifacts, super::artifacts::WriteError> {
    let mut a = Artifacts::default().with_figure_output(figures);
    let mut wear = planetary_wear_artifacts(run.wear_model, run.runs);
    if let Some((ps, runs)) = run.duty {
        super::duty_planetary::add_planetary_duty(ps, runs, &mut wear);
    }
    let mut headline = vec![
        format!("stiffness:\n{}", run.stiffness.headline),
        format!("dynamics, new teeth:\n{}", run.dynamics_artifacts.headline),
    ];
    let stiffness = nest(
        &mut a,
        "stiffness",
        run.stiffness,
        &study_meta(meta, "stiffness"),
    )?;
    let dynamics = nest(
        &mut a,
        "dynamics",
        run.dynamics_artifacts,
        &study_meta(meta, "dynamics"),
    )?;
    let (signals, record) = match run.signals {
        Some((s, rec)) => {
            headline.push(format!("signals:\n{}", s.headline));
            let v = nest(&mut a, "signals", s, &study_meta(meta, "signals"))?;
            (Some(v), Some(rec))
        }
        None => (None, None),
    };
    headline.push(format!("wear:\n{}", wear.headline));
    let wear = nest(&mut a, "wear", wear, &study_meta(meta, "wear"))?;
    let s = Summaries {
        stiffness,
        dynamics,
        signals,
        wear,
    };
    let mut blocks = Vec::new();
    for r in run.runs {
        let mode = r.mode.name();
        for (stem, what) in [
            ("wear_history", "largest wear depth of every member flank"),
            (
                "wear_profiles",
                "wear depth along each mesh's path of contact",
            ),
        ] {
            blocks.extend(embed_existing(
                &mut a,
                &format!("wear/{stem}_{mode}.png"),
                format!("{}: {what} (from the wear study).", r.mode.label()),
            ));
        }
    }
    let sidebands = match &record {
        Some(rec) => embed_figures(&mut a, vec![sideband_figure(run.study, rec)]),
        None => Vec::new(),
    };
    a.summary = summary(&s, run.runs);
    a.headline = headline.join("\n");
    let mut report = super::run_planetary_report::build(&s, run.runs, (blocks, sidebands), meta);
    if let Some((ps, runs)) = run.duty {
        a.summary["load_spectrum"] = s.wear["load_spectrum"].clone();
        report
            .sections
            .push(super::duty_planetary::planetary_duty_section(ps, runs));
    }
    a.documents
        .push(("report.html".into(), html::render(&report).into_bytes()));
    Ok(a)
}

/// The ring sensor's carrier-order spectrum about the first two mesh harmonics, from
/// z_r - 2 N to 2 z_r + 2 N (two planet-pass multiples either side; the planet-pass
/// modulation at low orders, far larger, is in `signals/orders.csv`), with the table of
/// exactly its data.
fn sideband_figure(study: &PlanetaryStudy, rec: &RingSensorRecord) -> EmbeddedFigure {
    let n = study.set.planets();
    let zr = study.set.teeth_ring();
    let last = (2 * zr + 2 * n).min(rec.order_amplitude_n.len().saturating_sub(1));
    let shown_orders = zr.saturating_sub(2 * n).max(1)..=last;
    let orders: Vec<f64> = shown_orders.clone().map(|k| k as f64).collect();
    let amp: Vec<f64> = shown_orders.map(|k| rec.order_amplitude_n[k]).collect();
    let hz: Vec<f64> = orders.iter().map(|k| k * rec.carrier_hz).collect();
    let title = format!(
        "Ring sensor: spectrum in carrier orders (mesh order {zr}, planet pass every {n} orders)"
    );
    let figure = Figure {
        title: title.clone(),
        panels: vec![panel(
            "carrier order (-)",
            "amplitude (N)",
            vec![Curve::new("ring sensor", orders.clone(), amp.clone())],
        )],
    };
    EmbeddedFigure {
        stem: "ring_sensor_sidebands".into(),
        caption: format!(
            "{title}: the mesh harmonics at multiples of {zr} carrier orders ({} Hz each) and their sidebands, new teeth (from the signals study's orders.csv).",
            crate::format::shown(rec.carrier_hz)
        ),
        figure,
        table: Table::new()
            .col("carrier_order", orders)
            .col("frequency_hz", hz)
            .col("amplitude_n", amp),
    }
}

/// `summary.json` of the run: the studies' key numbers, each copied from its summary.
fn summary(s: &Summaries, runs: &[&PlanetaryWearRun]) -> Value {
    let p = &s.stiffness["planetary"];
    let d = &s.dynamics["planetary_dynamics"];
    let w = &s.wear["planetary_wear"];
    let ring = s.signals.as_ref().map(|g| {
        let g = &g["planetary_signals"];
        json!({
            "mesh_frequency_hz": g["mesh_frequency_hz"],
            "planet_pass_hz": g["planet_pass_hz"],
            "mesh_harmonics": g["mesh_harmonics"],
        })
    });
    let mut studies = json!({
        "stiffness": "stiffness/summary.json",
        "dynamics": "dynamics/summary.json",
        "wear": "wear/summary.json",
    });
    if s.signals.is_some() {
        studies["signals"] = json!("signals/summary.json");
    }
    let mut out = json!({
        "planetary_run": {
            "geometry": p["geometry"],
            "kinematics": p["kinematics"],
            "modes": p["modes"],
            "meshes": d["meshes"],
            "nominal_mesh_force_n": d["nominal_mesh_force_n"],
            "dynamic_factor_sun_planet": d["dynamic_factor_sun_planet"],
            "dynamic_factor_ring_planet": d["dynamic_factor_ring_planet"],
            "load_sharing_factor": d["load_sharing_factor"],
            "load_sharing_factor_ring": d["load_sharing_factor_ring"],
            "load_sharing_factor_peak": d["load_sharing_factor_peak"],
            "load_sharing_factor_static": d["load_sharing_factor_static"],
            "wear_modes": runs.iter().map(|r| r.mode.name()).collect::<Vec<_>>(),
            "members": w["members"],
            "limiting_member": w["limiting_member"],
            "input_cycles": w["input_cycles"],
            "stopped": w["stopped"],
            "ring_sensor": ring,
            "studies": studies,
        },
        "warnings": s.dynamics["warnings"],
    });
    if !w["faulty_tooth"].is_null() {
        out["planetary_run"]["faulty_tooth"] = w["faulty_tooth"].clone();
    }
    out
}
