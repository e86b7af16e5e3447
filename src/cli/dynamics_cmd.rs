//! `gearwear dynamics`: one steady-state evaluation of the tribo-dynamic model.

use super::args::DynamicsArgs;
use super::output::{build_model, json_write, save_png, um};
use super::CliError;
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::model::dof;
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::summary::{velocity_y_spectrum, ResponseSummary};
use crate::io::{RunMetadata, Table};
use crate::report::figures::{panel, single, spectrum_panel, Curve};
use crate::report::modes::{self as report_modes, modes_json};
use crate::study::{ModalAnalysis, Model};
use serde_json::{json, Value};
use std::path::Path;

/// Read a transmission-error file: CSV with header `pinion_angle_deg,error_um`, one row per
/// sample over (at least) one mesh period; angles are reduced modulo the mesh period.
pub fn read_transmission_error(
    path: &Path,
    mesh_angle_rad: f64,
) -> Result<ExternalError, CliError> {
    let bad = |m: String| CliError::input(format!("--transmission-error {}: {m}", path.display()));
    let mut r = csv::Reader::from_path(path).map_err(|e| bad(format!("cannot read: {e}")))?;
    let headers = r.headers().map_err(|e| bad(e.to_string()))?.clone();
    let col = |name: &str| headers.iter().position(|h| h.trim() == name);
    let (Some(ia), Some(ie)) = (col("pinion_angle_deg"), col("error_um")) else {
        return Err(bad(format!(
            "expected the header `pinion_angle_deg,error_um`, found `{}`",
            headers.iter().collect::<Vec<_>>().join(",")
        )));
    };
    let mut samples = Vec::new();
    for (line, rec) in r.records().enumerate() {
        let rec = rec.map_err(|e| bad(e.to_string()))?;
        let parse = |i: usize| -> Result<f64, CliError> {
            let s = rec.get(i).unwrap_or("").trim();
            s.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| bad(format!("row {}: `{s}` is not a finite number", line + 2)))
        };
        samples.push((parse(ia)?.to_radians(), parse(ie)? * 1e-6));
    }
    if samples.len() < 2 {
        return Err(bad("needs at least two rows".into()));
    }
    Ok(ExternalError::new(&samples, mesh_angle_rad))
}

/// Write the outputs of one dynamic evaluation into `dir` (CSV, plots); returns the
/// summary numbers as JSON.
pub fn write_dynamic_outputs(
    model: &Model,
    r: &DynamicResponse,
    dir: &Path,
    label: &str,
) -> anyhow::Result<serde_json::Value> {
    let s = &r.signals;
    let ms = |v: &[f64]| v.iter().map(|x| x * 1e3).collect::<Vec<_>>();
    let t_ms = ms(&s.time_s);
    let col = |k: usize, which: &Vec<[f64; 8]>| which.iter().map(|v| v[k]).collect::<Vec<_>>();
    let names = [
        "x_pinion",
        "y_pinion",
        "x_gear",
        "y_gear",
        "phi_motor",
        "phi_pinion",
        "phi_gear",
        "phi_brake",
    ];
    let units = ["m", "m", "m", "m", "rad", "rad", "rad", "rad"];
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
    t.save(&dir.join("timeseries.csv"))?;

    let p = &r.path;
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
        .save(&dir.join("path.csv"))?;

    // Damped poles and undamped modes of the linearised model.
    let modal = ModalAnalysis::of(model);
    report_modes::damped_table(&modal).save(&dir.join("modes.csv"))?;
    report_modes::undamped_table(&modal).save(&dir.join("modes_undamped.csv"))?;

    let summary = ResponseSummary::of(r);
    let f_mesh = model.params.mesh_frequency_hz(&model.pair);
    let has_velocity = s.velocity.iter().any(|v| v[dof::YP] != 0.0);
    if has_velocity {
        let spec = velocity_y_spectrum(r);
        Table::new()
            .col("frequency_hz", spec.frequency_hz.clone())
            .col("velocity_y_pinion_amplitude_mm_per_s", ms(&spec.amplitude))
            .save(&dir.join("spectrum.csv"))?;
        let vy: Vec<f64> = s.velocity.iter().map(|v| v[dof::YP] * 1e3).collect();
        save_png(
            &single(
                &format!("Pinion y velocity ({label})"),
                panel(
                    "time (ms)",
                    "dy_p/dt (mm/s)",
                    vec![Curve::new("", t_ms.clone(), vy)],
                ),
            ),
            &dir.join("velocity_y_pinion.png"),
        )?;
        save_png(
            &single(
                &format!("Spectrum of dy_p/dt ({label})"),
                spectrum_panel(
                    "amplitude (mm/s)",
                    &spec.frequency_hz,
                    &ms(&spec.amplitude),
                    5.0 * f_mesh,
                    f_mesh,
                ),
            ),
            &dir.join("spectrum_velocity_y_pinion.png"),
        )?;
    }
    save_png(
        &single(
            &format!("Dynamic transmission error ({label})"),
            panel(
                "time (ms)",
                "DTE (um)",
                vec![Curve::new("", t_ms.clone(), um(&s.dte_m))],
            ),
        ),
        &dir.join("dte.png"),
    )?;
    save_png(
        &single(
            &format!("Mesh force ({label})"),
            panel(
                "time (ms)",
                "F (N)",
                vec![Curve::new("", t_ms.clone(), s.mesh_force_n.clone())],
            ),
        ),
        &dir.join("mesh_force.png"),
    )?;
    let rho_mm: Vec<f64> = p.iter().map(|x| x.rho1_m * 1e3).collect();
    save_png(
        &single(
            &format!("Friction coefficient along the path of contact ({label})"),
            panel(
                "pinion roll distance rho1 (mm)",
                "mu (-)",
                vec![Curve::new(
                    "",
                    rho_mm.clone(),
                    p.iter().map(|x| x.friction_coefficient).collect(),
                )],
            ),
        ),
        &dir.join("friction_coefficient.png"),
    )?;
    save_png(
        &single(
            &format!("Friction force along the path of contact ({label})"),
            panel(
                "pinion roll distance rho1 (mm)",
                "f (N)",
                vec![Curve::new(
                    "",
                    rho_mm,
                    p.iter().map(|x| x.friction_n).collect(),
                )],
            ),
        ),
        &dir.join("friction_force.png"),
    )?;
    Ok(summary_json(model, r, &summary))
}

/// The promised summary keys of one dynamic evaluation.
pub fn summary_json(model: &Model, r: &DynamicResponse, s: &ResponseSummary) -> serde_json::Value {
    let c_m = model
        .params
        .mesh_damping_n_s_per_m(&model.pair, model.mesh.mean_stiffness_n_per_m());
    let mut v = json!({
        "mesh_frequency_hz": model.params.mesh_frequency_hz(&model.pair),
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
    });
    if let (Some(v), Value::Object(m)) = (v.as_object_mut(), modes_json(&ModalAnalysis::of(model)))
    {
        v.extend(m);
    }
    v
}

pub fn run(a: &DynamicsArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    let model = build_model(&case)?;
    let external = match &a.transmission_error {
        Some(p) => read_transmission_error(p, model.pair.mesh_angle_rad())?,
        None => ExternalError::none(),
    };
    let wear = crate::wear::WearState::new(model.grid.len());
    let r = model
        .dynamic(&wear, &external)
        .map_err(|e| CliError::Failed(e.into()))?;
    std::fs::create_dir_all(&a.out)?;
    let mut v = write_dynamic_outputs(&model, &r, &a.out, "new teeth")?;
    v["metadata"] =
        serde_json::to_value(RunMetadata::new("dynamics", &case)).map_err(anyhow::Error::from)?;
    v["warnings"] = json!(model.warnings);
    json_write(&a.out.join("summary.json"), &v)?;
    eprintln!(
        "dynamics: max DTE {:.3} um, mean mesh force {:.1} N, RMS dy_p/dt {:.4} mm/s -> {}",
        v["dte"]["max_um"].as_f64().unwrap_or(f64::NAN),
        v["mesh_force"]["mean_n"].as_f64().unwrap_or(f64::NAN),
        v["velocity_y_pinion"]["rms_mm_per_s"]
            .as_f64()
            .unwrap_or(f64::NAN),
        a.out.display()
    );
    Ok(())
}
