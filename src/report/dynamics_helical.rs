//! What `gearwear dynamics` adds for a helical pair (`study::helical_dynamics`): the axial
//! force on the pinion over time (`timeseries.csv`, column `axial_force_pinion_n`) and the
//! `helical` block of `summary.json` (slices, helix, contact ratios, the mean mesh
//! stiffness, the axial force and its mean: the axial bearing reaction).

use crate::dynamics::response::DynamicResponse;
use crate::study::helical::HelicalDynamics;
use crate::study::Model;
use serde_json::{json, Value};

/// The axial force on the pinion at each sample, N (+ along the pinion's angular velocity):
/// F_a = s F tan(beta_b), F the transverse mesh force (`HelicalDynamics`); None for a spur
/// pair.
pub fn axial_force_pinion_n(model: &Model, mesh_force_n: &[f64]) -> Option<Vec<f64>> {
    let h = model.helical.as_ref()?;
    let a = h.pinion_axial_sign() * h.axial_per_transverse();
    Some(mesh_force_n.iter().map(|f| a * f).collect())
}

/// The `helical` block of `summary.json` (None for a spur pair). The mean axial force is
/// the time mean of F_a (the mean mesh force by Simpson's rule on the steps, times
/// tan(beta_b)): in the steady state the axial bearings carry it.
pub fn helical_summary(model: &Model, r: &DynamicResponse) -> Option<Value> {
    let h: &HelicalDynamics = model.helical.as_ref()?;
    let p = &h.pair;
    let f = &r.signals.meshes[0].mesh_force_n;
    let axial = axial_force_pinion_n(model, f)?;
    let extreme = |pick: fn(f64, f64) -> f64, init: f64| axial.iter().copied().fold(init, pick);
    let sign = h.pinion_axial_sign();
    Some(json!({
        "helix_angle_deg": p.helix_angle_rad.to_degrees(),
        "base_helix_angle_deg": p.base_helix_angle_rad.to_degrees(),
        "hand_pinion": if sign < 0.0 { "right" } else { "left" },
        "slices": h.slices,
        "transverse_contact_ratio": p.transverse_contact_ratio,
        "overlap_ratio": p.overlap_ratio,
        "total_contact_ratio": p.total_contact_ratio,
        "mean_mesh_stiffness_n_per_m": {
            "slices": h.slice_mean_stiffness_n_per_m,
            "line_table": model.mesh.mean_stiffness_n_per_m(),
        },
        "axial_force_pinion": {
            "unit": "N, + along the pinion's angular velocity; the gear takes the opposite",
            "mean_n": sign * h.axial_per_transverse() * r.meshes[0].mean_mesh_force_n,
            "max_n": extreme(f64::max, f64::NEG_INFINITY),
            "min_n": extreme(f64::min, f64::INFINITY),
        },
        "model": "planar: the slice mesh stiffness on the transverse line of action; the axial force has no degree of freedom (docs/MODEL.md 11.1)",
    }))
}
