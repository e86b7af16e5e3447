//! Results of one steady-state dynamic evaluation (`gearwear dynamics`): the time
//! series, the path of contact, the modes, the spectrum, their figures and the summary.

use super::artifacts::{um, Artifacts};
use super::figures::{panel, single, spectrum_panel, spectrum_rows, Curve};
use super::modes::{self as report_modes, modes_json};
use crate::dynamics::model::dof;
use crate::dynamics::response::{DynamicResponse, PathSample, Signals};
use crate::dynamics::summary::{velocity_y_spectrum, ResponseSummary};
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
pub const COORDINATE_UNITS: [&str; 8] = ["m", "m", "m", "m", "rad", "rad", "rad", "rad"];

/// Everything `gearwear dynamics` writes for one evaluation (`label` names the state in
/// figure titles, e.g. "new teeth").
pub fn dynamics_artifacts(model: &Model, r: &DynamicResponse, label: &str) -> Artifacts {
    let mut a = Artifacts::default();
    let s = &r.signals;
    a.table("timeseries.csv", timeseries_table(s));
    a.table("path.csv", path_table(model, &r.path));

    // Damped poles and undamped modes of the linearised model.
    let modal = ModalAnalysis::of(model);
    a.table("modes.csv", report_modes::damped_table(&modal));
    a.table("modes_undamped.csv", report_modes::undamped_table(&modal));

    let t_ms = ms(&s.time_s);
    let has_velocity = s.velocity.iter().any(|v| v[dof::YP] != 0.0);
    if has_velocity {
        add_velocity_figures(&mut a, model, r, &t_ms, label);
    }
    add_time_figures(&mut a, s, t_ms, label);
    add_path_figures(&mut a, &r.path, label);
    a.summary = dynamics_summary(model, r);
    a.headline = dynamics_headline(&a.summary);
    super::teeth::add_teeth_artifacts(model, &mut a);
    super::teeth::add_sideband_artifacts(model, r, label, &mut a);
    a
}

/// Seconds (or m/s) as milliseconds (mm/s).
fn ms(v: &[f64]) -> Vec<f64> {
    v.iter().map(|x| x * 1e3).collect::<Vec<_>>()
}

/// Label of the time axis.
const TIME: &str = "time (ms)";

/// `timeseries.csv`: every recorded signal and the 8 coordinates, their velocities and
/// accelerations.
fn timeseries_table(s: &Signals) -> Table {
    let col = |k: usize, which: &Vec<[f64; 8]>| which.iter().map(|v| v[k]).collect::<Vec<_>>();
    let (names, units) = (COORDINATE_NAMES, COORDINATE_UNITS);
    let mut t = Table::new()
        .col("time_s", s.time_s.clone())
        .col("mesh_phase_rad", s.phase_rad.clone())
        .col("dte_um", um(&s.dte_m))
        .col("mesh_force_n", s.mesh_force_n.clone())
        .col("mesh_stiffness_n_per_m", s.mesh_stiffness_n_per_m.clone())
        .col(
            "friction_coefficient_pair0",
            s.friction_coefficient[0].clone(),
        )
        .col(
            "friction_coefficient_pair1",
            s.friction_coefficient[1].clone(),
        )
        .col("friction_force_pair0_n", s.friction_n[0].clone())
        .col("friction_force_pair1_n", s.friction_n[1].clone())
        .col("load_pair0_n", s.pair_load_n[0].clone())
        .col("load_pair1_n", s.pair_load_n[1].clone());
    for k in 0..8 {
        t = t.col(
            &format!("{}_{}", names[k], units[k]),
            col(k, &s.displacement),
        );
    }
    for k in 0..8 {
        t = t.col(
            &format!("d{}_{}_per_s", names[k], units[k]),
            col(k, &s.velocity),
        );
    }
    for k in 0..8 {
        t = t.col(
            &format!("dd{}_{}_per_s2", names[k], units[k]),
            col(k, &s.acceleration),
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
    t_ms: &[f64],
    label: &str,
) {
    let s = &r.signals;
    let f_mesh = model.params.operating.mesh_frequency_hz;
    let spec = velocity_y_spectrum(r);
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
            spectrum_panel("amplitude (mm/s)", &f, &amp, f_mesh),
        ),
        Table::new()
            .col("frequency_hz", f)
            .col("velocity_y_pinion_amplitude_mm_per_s", amp),
    );
}

/// The dynamic transmission error and the mesh force over time.
fn add_time_figures(a: &mut Artifacts, s: &Signals, t_ms: Vec<f64>, label: &str) {
    let dte_um = um(&s.dte_m);
    a.figure_with_data(
        "dte.png",
        single(
            &format!("Dynamic transmission error ({label})"),
            panel(
                TIME,
                "dynamic transmission error (µm)",
                vec![Curve::new("", t_ms.clone(), dte_um.clone())],
            ),
        ),
        Table::new()
            .col("time_ms", t_ms.clone())
            .col("dte_um", dte_um),
    );
    a.figure_with_data(
        "mesh_force.png",
        single(
            &format!("Mesh force ({label})"),
            panel(
                TIME,
                "mesh force (N)",
                vec![Curve::new("", t_ms.clone(), s.mesh_force_n.clone())],
            ),
        ),
        Table::new()
            .col("time_ms", t_ms)
            .col("mesh_force_n", s.mesh_force_n.clone()),
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
    let s = &ResponseSummary::of(r);
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
    v
}

/// One line of headline numbers from a dynamics summary.
pub fn dynamics_headline(v: &serde_json::Value) -> String {
    let f = |p: &str| v.pointer(p).and_then(|x| x.as_f64()).unwrap_or(f64::NAN);
    format!(
        "max DTE {:.4} µm, mean mesh force {:.2} N, dynamic factor {:.4}, RMS dy_p/dt {:.4} mm/s",
        f("/dte/max_um"),
        f("/mesh_force/mean_n"),
        f("/mesh_force/dynamic_factor"),
        f("/velocity_y_pinion/rms_mm_per_s"),
    )
}
