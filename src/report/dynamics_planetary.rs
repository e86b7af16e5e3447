//! Results of `gearwear dynamics` on a planetary case: `summary.json` with each mesh's
//! mean and largest force over the steady-state mesh period, the load sharing factor per
//! planet, the dynamic factor and the run's numerics; `mesh_forces.csv` (every mesh's
//! force over the period) and `motions.csv` (every coordinate of the lumped model)
//! (docs/MODEL.md 12.5); `load_sharing.csv`, per planet its pin errors and load sharing
//! factors (quasi-static, sun and ring meshes' means, the sun mesh's peak).

use super::artifacts::Artifacts;
use crate::dynamics::planetary_steady::PlanetaryResponse;
use crate::format::shown;
use crate::io::Table;
use crate::study::planetary_dynamics::{shares, PlanetaryDynamics};
use serde_json::json;

/// Load sharing factors of the sun meshes (docs/MODEL.md 12.5): per planet n, its mean
/// load over the mean of all planets' (from the meshes' means `mean`), and the largest
/// over the samples `forces` of N F_sn(t) / sum_k F_sk(t) (the instantaneous share).
pub fn load_sharing(mean: &[f64], forces: &[Vec<f64>], planets: usize) -> (Vec<f64>, Vec<f64>) {
    let by_mean = shares(&mean[..planets]);
    let peak = (0..planets)
        .map(|p| {
            forces
                .iter()
                .map(|r| {
                    let s: f64 = r[..planets].iter().sum();
                    if s > 0.0 {
                        planets as f64 * r[p] / s
                    } else {
                        0.0
                    }
                })
                .fold(0.0, f64::max)
        })
        .collect();
    (by_mean, peak)
}

/// Everything `gearwear dynamics` writes for a planetary case.
pub fn planetary_dynamics_artifacts(d: &PlanetaryDynamics, r: &PlanetaryResponse) -> Artifacts {
    let n = d.study.set.planets();
    let max = r.max_forces_n();
    let mean = &r.mean_forces_n;
    let (lsf, lsf_peak) = load_sharing(mean, &r.mesh_forces_n, n);
    let lsf_ring = shares(&mean[n..2 * n]);
    // The quasi-static shares: the static equilibrium at mean stiffness with the pin
    // errors' gaps and contact loss (checked solvable when the model was built).
    let static_f = d
        .model
        .static_mesh_forces()
        .unwrap_or_else(|| vec![0.0; 2 * n]);
    let lsf_static = shares(&static_f[..n]);
    let section = &d.study.section;
    let errors_um: Vec<(f64, f64)> = section
        .pin_errors_m()
        .iter()
        .map(|(t, r)| (t * 1e6, r * 1e6))
        .collect();
    let nominal = d.nominal_mesh_force_n();
    let dyn_factor = |range: std::ops::Range<usize>| {
        max[range].iter().fold(0.0, |a: f64, b| a.max(*b)) / nominal
    };
    let meshes: Vec<_> = (0..2 * n)
        .map(|j| {
            json!({
                "mesh": if j < n { format!("sun_planet_{}", j + 1) } else { format!("ring_planet_{}", j - n + 1) },
                "mean_force_n": mean[j],
                "max_force_n": max[j],
            })
        })
        .collect();
    let mut v = json!({
        "planetary_dynamics": {
            "input": d.study.set.input.name(),
            "input_torque_nm": d.input_torque_nm,
            "mesh_frequency_hz": d.model.mesh_frequency_hz,
            "nominal_mesh_force_n": nominal,
            "meshes": meshes,
            "load_sharing_factor": lsf,
            "load_sharing_factor_peak": lsf_peak,
            "load_sharing_factor_ring": lsf_ring,
            "load_sharing_factor_static": lsf_static,
            "planet_tangential_error_um": errors_um.iter().map(|e| e.0).collect::<Vec<_>>(),
            "planet_radial_error_um": errors_um.iter().map(|e| e.1).collect::<Vec<_>>(),
            "floating_sun": section.floating_sun,
            "lumped_parameters": super::stiffness_planetary::lumped_json(&d.study),
            "dynamic_factor_sun_planet": dyn_factor(0..n),
            "dynamic_factor_ring_planet": dyn_factor(n..2 * n),
            "rotating_frame": "carrier frame without centripetal and gyroscopic terms",
            "periods_to_steady_state": r.periods_to_steady,
            "periodicity": r.periodicity,
            "steps": r.steps,
        },
        "warnings": d.study.warnings,
    });
    if let Some(f) = d.study.meshes.fault() {
        // Only a faulty set states its fault (a healthy set's summary is unchanged).
        v["planetary_dynamics"]["fault"] = json!({
            "member": f.member.name(),
            "tooth": f.tooth,
            "period_mesh_periods": r.mesh_periods,
            "period_s": r.mesh_periods as f64 / d.model.mesh_frequency_hz,
            "fault_frequency_hz": d.model.mesh_frequency_hz / r.mesh_periods as f64,
        });
    }
    let mut a = Artifacts {
        headline: format!(
            "planetary dynamics, {n} planets at {} Hz mesh frequency: mean sun-planet mesh force {} N (nominal {} N), dynamic factor {}, largest load sharing factor {}",
            shown(d.model.mesh_frequency_hz),
            shown(mean[..n].iter().sum::<f64>() / n as f64),
            shown(nominal),
            shown(dyn_factor(0..n)),
            shown(lsf_peak.iter().fold(0.0, |a: f64, b| a.max(*b))),
        ),
        summary: v,
        ..Default::default()
    };
    a.table("mesh_forces.csv", forces_table(r, n));
    a.table("motions.csv", motions_table(r, n));
    a.table(
        "load_sharing.csv",
        Table::new()
            .col("planet", (1..=n).map(|p| p as f64).collect())
            .col(
                "tangential_error_um",
                errors_um.iter().map(|e| e.0).collect(),
            )
            .col("radial_error_um", errors_um.iter().map(|e| e.1).collect())
            .col("static_share", lsf_static)
            .col("sun_mesh_share", lsf)
            .col("ring_mesh_share", lsf_ring)
            .col("sun_mesh_peak_share", lsf_peak),
    );
    a
}

/// `time_s`, then `sun_planet_N_force_n` and `ring_planet_N_force_n`.
fn forces_table(r: &PlanetaryResponse, n: usize) -> Table {
    let mut t = Table::new().col("time_s", r.times_s.clone());
    for j in 0..2 * n {
        let name = if j < n {
            format!("sun_planet_{}_force_n", j + 1)
        } else {
            format!("ring_planet_{}_force_n", j - n + 1)
        };
        t = t.col(&name, r.mesh_forces_n.iter().map(|f| f[j]).collect());
    }
    t
}

/// `time_s`, then every coordinate in metres: carrier, ring, sun x, y, u, then each
/// planet's radial, tangential and u.
fn motions_table(r: &PlanetaryResponse, n: usize) -> Table {
    let mut t = Table::new().col("time_s", r.times_s.clone());
    let mut names = Vec::new();
    for m in ["carrier", "ring", "sun"] {
        for c in ["x", "y", "u"] {
            names.push(format!("{m}_{c}_m"));
        }
    }
    for p in 1..=n {
        for c in ["radial", "tangential", "u"] {
            names.push(format!("planet_{p}_{c}_m"));
        }
    }
    for (j, name) in names.iter().enumerate() {
        t = t.col(name, r.displacements_m.iter().map(|q| q[j]).collect());
    }
    t
}
