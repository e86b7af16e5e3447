//! Results of one steady-state dynamic evaluation (`gearwear dynamics`): the time
//! series, the path of contact, the modes, the spectrum, their figures and the summary.

use super::artifacts::{um, Artifacts};
use super::figures::{panel, single, spectrum_panel_meshes, spectrum_rows, Curve};
use super::modes::{self as report_modes, modes_json};
use super::plot::Figure;
use crate::dynamics::model::dof;
use crate::dynamics::response::{Coordinates, DynamicResponse, PathSample, Signals};
use crate::dynamics::spectrum::Spectrum;
use crate::dynamics::summary::{velocity_y_spectrum, ResponseSummary};
use crate::format::shown;
use crate::io::Table;
use crate::study::{ModalAnalysis, Model};
use serde_json::{json, Value};

/// Names and units of the 8 generalised coordinates, in `dynamics::model::dof` order.
pub const COORDINATE_NAMES: [&str; 8] = [
    "x_pinion",
    "y_pinion",
    "x_gear",
    "y_gear",
    "phi_motor",
    "phi_pinion",
    "phi_gear",
    "phi_brake",
];
/// SI unit of each coordinate of [`COORDINATE_NAMES`].
pub const COORDINATE_UNITS: [&str; 8] = ["m", "m", "m", "m", "rad", "rad", "rad", "rad"];

/// Everything `gearwear dynamics` writes for one evaluation (`label` names the state in
/// figure titles, e.g. "new teeth").
pub fn dynamics_artifacts(model: &Model, r: &DynamicResponse, label: &str) -> Artifacts {
    let mut a = Artifacts::default();
    let s = &r.signals;
    // Long runs (a hunting period) go to Parquet, at every k-th row unless the case asks
    // for full tables (`Artifacts::per_point_table`).
    let full = model.case.output.full_tables;
    let thinned: Vec<Value> = [
        a.per_point_table("timeseries.csv", timeseries_table(model, s), full),
        a.per_point_table("path.csv", path_table(model, &r.meshes[0].path), full),
    ]
    .into_iter()
    .flatten()
    .collect();

    // Damped poles and undamped modes of the linearised model.
    let modal = ModalAnalysis::of(model);
    a.table("modes.csv", report_modes::damped_table(&modal));
    a.table("modes_undamped.csv", report_modes::undamped_table(&modal));

    let t_ms = ms(&s.time_s);
    let has_velocity = s.velocity.iter().any(|v| v[dof::YP] != 0.0);
    // The spectrum of dy_p/dt, computed once for its table and both of its figures.
    let spec = has_velocity.then(|| velocity_y_spectrum(r));
    if let Some(spec) = &spec {
        add_velocity_figures(&mut a, model, r, spec, &t_ms, label);
    }
    add_time_figures(&mut a, model, s, t_ms, label);
    add_path_figures(&mut a, &r.meshes[0].path, label);
    a.summary = dynamics_summary(model, r);
    a.headline = dynamics_headline(&a.summary);
    if !thinned.is_empty() {
        a.headline.push_str(&thinned_line(&thinned));
        a.summary["output"] = json!({
            "thinned_tables": thinned,
            "full_tables_key": "output.full_tables = true",
        });
    }
    super::teeth::add_teeth_artifacts(model, &mut a);
    if let Some(spec) = &spec {
        super::teeth::add_sideband_artifacts(model, r, spec, label, &mut a);
    }
    a
}

/// The headline's note on thinned tables: "timeseries.parquet (1 row in 10),
/// path.parquet (1 row in 4): a long run's tables thinned; output.full_tables = true
/// writes every point".
fn thinned_line(thinned: &[Value]) -> String {
    let files: Vec<String> = thinned
        .iter()
        .map(|t| {
            format!(
                "{} (1 row in {})",
                t["file"].as_str().unwrap_or("?"),
                t["every_kth_row"]
            )
        })
        .collect();
    format!(
        "\n{}: a long run's tables thinned; output.full_tables = true writes every point",
        files.join(", ")
    )
}

/// Seconds (or m/s) as milliseconds (mm/s).
fn ms(v: &[f64]) -> Vec<f64> {
    v.iter().map(|x| x * 1e3).collect::<Vec<_>>()
}

/// Label of the time axis.
const TIME: &str = "time (ms)";

/// `timeseries.csv`: every recorded signal and the 8 coordinates, their velocities and
/// accelerations.
fn timeseries_table(model: &Model, s: &Signals) -> Table {
    let col = |k: usize, which: &Coordinates| which.column(k);
    let coordinates = model.coordinate_names();
    let m0 = &s.meshes[0];
    let mut t = Table::new()
        .col("time_s", s.time_s.clone())
        .col("mesh_phase_rad", m0.phase_rad.clone())
        .col("dte_um", um(&m0.dte_m))
        .col("mesh_force_n", m0.mesh_force_n.clone())
        .col("mesh_stiffness_n_per_m", m0.mesh_stiffness_n_per_m.clone())
        .col(
            "friction_coefficient_pair0",
            m0.friction_coefficient[0].clone(),
        )
        .col(
            "friction_coefficient_pair1",
            m0.friction_coefficient[1].clone(),
        )
        .col("friction_force_pair0_n", m0.friction_n[0].clone())
        .col("friction_force_pair1_n", m0.friction_n[1].clone())
        .col("load_pair0_n", m0.pair_load_n[0].clone())
        .col("load_pair1_n", m0.pair_load_n[1].clone());
    if let Some(a) = super::dynamics_helical::axial_force_pinion_n(model, &m0.mesh_force_n) {
        t = t.col("axial_force_pinion_n", a);
    }
    for (k, (name, unit)) in coordinates.iter().enumerate() {
        t = t.col(&format!("{name}_{unit}"), col(k, &s.displacement));
    }
    for (k, (name, unit)) in coordinates.iter().enumerate() {
        t = t.col(&format!("d{name}_{unit}_per_s"), col(k, &s.velocity));
    }
    for (k, (name, unit)) in coordinates.iter().enumerate() {
        t = t.col(&format!("dd{name}_{unit}_per_s2"), col(k, &s.acceleration));
    }
    // A train's later meshes (the first mesh's columns lead the table).
    for (m, ms) in s.meshes.iter().enumerate().skip(1) {
        let n = m + 1;
        t = t
            .col(&format!("mesh{n}_phase_rad"), ms.phase_rad.clone())
            .col(&format!("mesh{n}_dte_um"), um(&ms.dte_m))
            .col(&format!("mesh{n}_force_n"), ms.mesh_force_n.clone())
            .col(
                &format!("mesh{n}_stiffness_n_per_m"),
                ms.mesh_stiffness_n_per_m.clone(),
            );
    }
    t
}

/// `path.csv`: the contact along the path of contact.
fn path_table(model: &Model, p: &[PathSample]) -> Table {
    Table::new()
        .col("rho1_mm", p.iter().map(|x| x.rho1_m * 1e3).collect())
        .col(
            "pinion_radius_mm",
            p.iter()
                .map(|x| model.pair.pinion.radius_at_rho(x.rho1_m) * 1e3)
                .collect(),
        )
        .col("load_n", p.iter().map(|x| x.load_n).collect())
        .col(
            "hertz_pressure_mpa",
            p.iter().map(|x| x.pressure_pa * 1e-6).collect(),
        )
        .col(
            "half_width_um",
            p.iter().map(|x| x.half_width_m * 1e6).collect(),
        )
        .col(
            "friction_coefficient",
            p.iter().map(|x| x.friction_coefficient).collect(),
        )
        .col("friction_force_n", p.iter().map(|x| x.friction_n).collect())
        .col(
            "sliding_m_per_s",
            p.iter()
                .map(|x| x.pinion_surface_speed_m_per_s - x.gear_surface_speed_m_per_s)
                .collect(),
        )
}

/// The pinion's y velocity: its spectrum's table, and its time and spectrum figures.
fn add_velocity_figures(
    a: &mut Artifacts,
    model: &Model,
    r: &DynamicResponse,
    spec: &Spectrum,
    t_ms: &[f64],
    label: &str,
) {
    let s = &r.signals;
    let f_mesh = model.params.operating.mesh_frequency_hz;
    a.table(
        "spectrum.csv",
        Table::new()
            .col("frequency_hz", spec.frequency_hz.clone())
            .col("velocity_y_pinion_amplitude_mm_per_s", ms(&spec.amplitude)),
    );
    let vy: Vec<f64> = s.velocity.iter().map(|v| v[dof::YP] * 1e3).collect();
    a.figure_with_data(
        "velocity_y_pinion.png",
        single(
            &format!("Pinion velocity in y ({label})"),
            panel(
                TIME,
                "pinion y velocity (mm/s)",
                vec![Curve::new("", t_ms.to_vec(), vy.clone())],
            ),
        ),
        Table::new()
            .col("time_ms", t_ms.to_vec())
            .col("velocity_y_pinion_mm_per_s", vy),
    );
    let (f, amp) = spectrum_rows(&spec.frequency_hz, &ms(&spec.amplitude), 5.0 * f_mesh);
    a.figure_with_data(
        "spectrum_velocity_y_pinion.png",
        single(
            &format!("Spectrum of the pinion y velocity ({label})"),
            spectrum_panel_meshes("amplitude (mm/s)", &f, &amp, &mesh_frequencies_hz(model)),
        ),
        Table::new()
            .col("frequency_hz", f)
            .col("velocity_y_pinion_amplitude_mm_per_s", amp),
    );
}

/// Every mesh's frequency, Hz: the pair's, or each stage's of a train (the train's
/// operating point, computed once).
fn mesh_frequencies_hz(model: &Model) -> Vec<f64> {
    match &model.train {
        None => vec![model.params.operating.mesh_frequency_hz],
        Some(t) => t
            .operating
            .meshes
            .iter()
            .map(|m| m.mesh_frequency_hz)
            .collect(),
    }
}

/// The name of each mesh's panel: none for a single pair; "stage k (z1/z2)" for each
/// mesh of a train.
fn mesh_labels(model: &Model) -> Vec<String> {
    match &model.train {
        None => vec![String::new()],
        Some(t) => t
            .stages
            .iter()
            .enumerate()
            .map(|(k, st)| {
                let g = &st.case.gear;
                format!("stage {} ({}/{}): ", k + 1, g.teeth_pinion, g.teeth_gear)
            })
            .collect(),
    }
}

/// The dynamic transmission error and the mesh force over time: a panel per mesh, one
/// above the other on one time axis (a train's later meshes as `meshN_` columns of the
/// figure's table, as in `timeseries.csv`).
fn add_time_figures(a: &mut Artifacts, model: &Model, s: &Signals, t_ms: Vec<f64>, label: &str) {
    let labels = mesh_labels(model);
    // A train's panels name their stage, so the axis label is kept short.
    let per_mesh = |v: &dyn Fn(usize) -> Vec<f64>, col: &str, axis: &str, short: &str| {
        let axis = if model.train.is_some() { short } else { axis };
        let mut panels = Vec::new();
        let mut table = Table::new().col("time_ms", t_ms.clone());
        for (m, name) in labels.iter().enumerate().take(s.meshes.len()) {
            let y = v(m);
            panels.push(panel(
                TIME,
                &format!("{name}{axis}"),
                vec![Curve::new("", t_ms.clone(), y.clone())],
            ));
            let c = if m == 0 {
                col.to_owned()
            } else {
                format!("mesh{}_{col}", m + 1)
            };
            table = table.col(&c, y);
        }
        (panels, table)
    };
    let (panels, table) = per_mesh(
        &|m| um(&s.meshes[m].dte_m),
        "dte_um",
        "dynamic transmission error (µm)",
        "DTE (µm)",
    );
    let figure = |title: String, panels| Figure { title, panels };
    a.figure_with_data(
        "dte.png",
        figure(format!("Dynamic transmission error ({label})"), panels),
        table,
    );
    let (panels, table) = per_mesh(
        &|m| s.meshes[m].mesh_force_n.clone(),
        "mesh_force_n",
        "mesh force (N)",
        "mesh force (N)",
    );
    a.figure_with_data(
        "mesh_force.png",
        figure(format!("Mesh force ({label})"), panels),
        table,
    );
}

/// The friction coefficient and force along the path of contact.
fn add_path_figures(a: &mut Artifacts, p: &[PathSample], label: &str) {
    let rho_mm: Vec<f64> = p.iter().map(|x| x.rho1_m * 1e3).collect();
    let along = "pinion roll distance along the path of contact (mm)";
    let mu: Vec<f64> = p.iter().map(|x| x.friction_coefficient).collect();
    a.figure_with_data(
        "friction_coefficient.png",
        single(
            &format!("Friction coefficient along the path of contact ({label})"),
            panel(
                along,
                "friction coefficient (-)",
                vec![Curve::new("", rho_mm.clone(), mu.clone())],
            ),
        ),
        Table::new()
            .col("rho1_mm", rho_mm.clone())
            .col("friction_coefficient", mu),
    );
    let friction: Vec<f64> = p.iter().map(|x| x.friction_n).collect();
    a.figure_with_data(
        "friction_force.png",
        single(
            &format!("Friction force along the path of contact ({label})"),
            panel(
                along,
                "friction force (N)",
                vec![Curve::new("", rho_mm.clone(), friction.clone())],
            ),
        ),
        Table::new()
            .col("rho1_mm", rho_mm)
            .col("friction_force_n", friction),
    );
}

/// The summary of one dynamic evaluation (the keys of `summary.json`, display units in
/// the names).
pub fn dynamics_summary(model: &Model, r: &DynamicResponse) -> serde_json::Value {
    let meshes = model.train.as_ref().map(|t| train_meshes(t, r));
    let s = &match &meshes {
        Some(m) => m[0].1,
        None => ResponseSummary::of(r),
    };
    let c_m = model
        .params
        .mesh_damping_n_s_per_m(&model.pair, model.mesh.mean_stiffness_n_per_m());
    let mut v = json!({
        "mesh_frequency_hz": model.params.operating.mesh_frequency_hz,
        "mesh_damping_n_s_per_m": c_m,
        "dte": {"max_um": s.dte_max_m * 1e6, "min_um": s.dte_min_m * 1e6, "mean_um": s.dte_mean_m * 1e6},
        "mesh_force": {"mean_n": s.mesh_force_mean_n, "max_n": s.mesh_force_max_n, "min_n": s.mesh_force_min_n, "dynamic_factor": s.dynamic_factor},
        "velocity_y_pinion": {"rms_mm_per_s": s.velocity_y_pinion_rms_m_per_s * 1e3},
        "mesh_harmonics": {
            "unit": "mm/s (amplitude of dy_p/dt at 1-4 x mesh frequency)",
            "velocity_y_pinion": s.velocity_y_pinion_harmonics_m_per_s.iter().map(|a| a * 1e3).collect::<Vec<_>>(),
        },
        "friction_coefficient": {"max": s.friction_coefficient_max, "mean_in_contact": s.friction_coefficient_mean_in_contact},
        "friction_force": {"max_abs_n": s.friction_force_max_n},
        "steady_state": {
            "periods_to_converge": r.periods_to_converge,
            "periodicity_error": r.periodicity_error,
            "mesh_period_s": r.mesh_period_s,
            "integrator_steps": r.steps,
            "rhs_evaluations": r.rhs_evaluations,
            "lu_factorizations": r.factorizations,
        },
        "warnings": model.warnings,
    });
    if let (Some(v), Value::Object(m)) = (v.as_object_mut(), modes_json(&ModalAnalysis::of(model)))
    {
        v.extend(m);
    }
    if let (Some(t), Some(meshes), Some(obj)) = (&model.train, meshes, v.as_object_mut()) {
        obj.insert(
            "meshes".into(),
            Value::Array(meshes.into_iter().map(|m| m.0).collect()),
        );
        obj.insert("train".into(), train_json(t, r));
        if let Some(f) = super::teeth::train_faults_json(t) {
            obj.insert("faults".into(), f);
        }
    }
    if let (Some(h), Some(obj)) = (
        super::dynamics_helical::helical_summary(model, r),
        v.as_object_mut(),
    ) {
        obj.insert("helical".into(), h);
    }
    v
}

/// Each mesh of a train: its summary keys (as `meshes` entries of `summary.json`: mesh
/// frequency, mean and maximum force, DTE, dynamic factor, its pinion's y velocity and
/// harmonics) and its [`ResponseSummary`].
fn train_meshes(
    t: &crate::study::train::TrainModel,
    r: &DynamicResponse,
) -> Vec<(Value, ResponseSummary)> {
    t.operating
        .meshes
        .iter()
        .enumerate()
        .map(|(m, p)| {
            let link = &t.assembly.elements.meshes[m];
            let s = t.mesh_summary(r, m);
            let v = json!({
                "stage": m + 1,
                "teeth": link.teeth,
                "mesh_frequency_hz": p.mesh_frequency_hz,
                "pinion_speed_rpm": p.pinion_speed_rad_s * 30.0 / std::f64::consts::PI,
                "pinion_torque_nm": p.pinion_torque_nm,
                "static_mesh_force_n": p.static_mesh_force_n,
                "dte": {"max_um": s.dte_max_m * 1e6, "min_um": s.dte_min_m * 1e6, "mean_um": s.dte_mean_m * 1e6},
                "mesh_force": {"mean_n": s.mesh_force_mean_n, "max_n": s.mesh_force_max_n, "min_n": s.mesh_force_min_n, "dynamic_factor": s.dynamic_factor},
                "velocity_y_pinion": {
                    "rms_mm_per_s": s.velocity_y_pinion_rms_m_per_s * 1e3,
                    "mesh_harmonics_mm_per_s": s.velocity_y_pinion_harmonics_m_per_s.iter().map(|a| a * 1e3).collect::<Vec<_>>(),
                },
                "friction_coefficient": {"max": s.friction_coefficient_max, "mean_in_contact": s.friction_coefficient_mean_in_contact},
                "contact_loss_fraction": r.contact_loss_fraction_of(m),
            });
            (v, s)
        })
        .collect()
}

/// `train` in `summary.json`: the stages, the base period and how many mesh periods of
/// each mesh it holds, the number of coordinates.
fn train_json(t: &crate::study::train::TrainModel, r: &DynamicResponse) -> Value {
    let counts: Vec<f64> = t
        .operating
        .meshes
        .iter()
        .map(|p| (r.mesh_period_s * p.mesh_frequency_hz).round())
        .collect();
    json!({
        "stages": t.stages.len(),
        "coordinates": t.assembly.len(),
        "base_period_s": r.mesh_period_s,
        "mesh_periods_in_base_period": counts,
        "excitation_periods": r.excitation_periods,
    })
}

/// One line of headline numbers from a dynamics summary.
pub fn dynamics_headline(v: &serde_json::Value) -> String {
    let f = |p: &str| v.pointer(p).and_then(|x| x.as_f64()).unwrap_or(f64::NAN);
    format!(
        "max DTE {} µm, mean mesh force {} N, dynamic factor {}, RMS dy_p/dt {} mm/s",
        shown(f("/dte/max_um")),
        shown(f("/mesh_force/mean_n")),
        shown(f("/mesh_force/dynamic_factor")),
        shown(f("/velocity_y_pinion/rms_mm_per_s")),
    )
}
