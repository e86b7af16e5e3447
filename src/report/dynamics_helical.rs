//! What `gearwear dynamics` adds for a helical pair (`study::helical_dynamics`): the axial
//! force on the pinion over time (`timeseries.csv`, column `axial_force_pinion_n`) and the
//! `helical` block of `summary.json` (slices, helix, contact ratios, the mean mesh
//! stiffness, the axial force and its mean: the axial bearing reaction; with axial degrees
//! of freedom each axial bearing's load and its body's axial motion, docs/MODEL.md 11.6).

use crate::dynamics::assembly::elements::Elements;
use crate::dynamics::assembly::single_pair::{GEAR, PINION};
use crate::dynamics::assembly::{Assembly, Dof};
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::spectrum::time_mean_with_slopes;
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
        "hand_pinion": model.case.gear.helix_hand_pinion,
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
        "model": if model.params.tilt.is_some() {
            "tilting: the slice mesh stiffness on the transverse line of action, pinion and gear on tilting bearings (docs/MODEL.md 11.8), axial bearings where given (11.6)"
        } else if model.params.axial.is_some() {
            "axial: the slice mesh stiffness on the transverse line of action, pinion and gear on axial bearings (docs/MODEL.md 11.6)"
        } else {
            "planar: the slice mesh stiffness on the transverse line of action; the axial force has no degree of freedom (docs/MODEL.md 11.1)"
        },
        "axial_bearings": axial_bearings(model, r, &axial),
    }))
    .map(|mut v| {
        // Only with tilting coordinates: the planar and axial summaries stay as they were.
        if let Some(t) = super::dynamics_tilt::tilt_summary(model, r) {
            v["tilt"] = t;
        }
        v
    })
}

/// Extremes (min, max) of a signal.
fn range(x: &[f64]) -> (f64, f64) {
    x.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        })
}

/// The axial load on each bearing, N (+ along the pinion's angular velocity: the force the
/// body puts on its bearing, the mesh's axial force on it in the mean), and its body's
/// axial motion (docs/MODEL.md 11.6). A body on an axial bearing of stiffness k and
/// damping c carries R = k z + c dz/dt, its time mean k times the mean of z by the
/// slope-corrected trapezoid on the recorded samples over the whole periods of the window
/// (dz/dt its slope, recorded): the damper's mean is c (z(T) - z(0)) / T, zero on the
/// periodic orbit (computed, it would be the solver's periodicity residual, ~1e-6 of the
/// reaction with the paper's bearing damping: left out); a rigid bearing carries the mesh's
/// axial force itself (`pinion_force`: the pinion's, the gear's its opposite).
fn axial_bearings(model: &Model, r: &DynamicResponse, pinion_force: &[f64]) -> Value {
    let asm = Assembly::new(Elements::single_pair(&model.params, &model.pair)).ok();
    let bearings = model.case.dynamics.axial_bearings();
    let s = &r.signals;
    let t = &s.time_s;
    let period = r.mesh_period_s * r.excitation_periods.max(1) as f64;
    let span = t.last().copied().unwrap_or(0.0) - t.first().copied().unwrap_or(0.0);
    // The samples cover [t_0, t_0 + n P): their span lies within the last period's steps.
    let window = period * (span / period).ceil().max(1.0);
    let body = |b: usize, which: usize, sign: f64| {
        let z_index = asm.as_ref().and_then(|a| a.index(b, Dof::Axial));
        match (z_index, bearings[which]) {
            (Some(i), Some((k, c))) => {
                let (z, v) = (s.displacement.column(i), s.velocity.column(i));
                let load: Vec<f64> = z.iter().zip(&v).map(|(z, v)| k * z + c * v).collect();
                let (lo, hi) = range(&load);
                let (z_lo, z_hi) = range(&z);
                let z_mean = time_mean_with_slopes(t, &z, &v, window);
                json!({
                    "bearing": "elastic",
                    "stiffness_n_per_m": k,
                    "damping_n_s_per_m": c,
                    "reaction_mean_n": k * z_mean,
                    "reaction_max_n": hi,
                    "reaction_min_n": lo,
                    "displacement_mean_m": z_mean,
                    "displacement_amplitude_m": 0.5 * (z_hi - z_lo),
                })
            }
            _ => {
                let load: Vec<f64> = pinion_force.iter().map(|f| sign * f).collect();
                let (lo, hi) = range(&load);
                let h = model
                    .helical
                    .as_ref()
                    .map_or(0.0, |h| h.pinion_axial_sign() * h.axial_per_transverse());
                json!({
                    "bearing": "rigid",
                    "reaction_mean_n": sign * h * r.meshes[0].mean_mesh_force_n,
                    "reaction_max_n": hi,
                    "reaction_min_n": lo,
                    "displacement_amplitude_m": 0.0,
                })
            }
        }
    };
    json!({
        "unit": "N and m, + along the pinion's angular velocity; the reaction is the axial load the body puts on its bearing",
        "pinion": body(PINION, 0, 1.0),
        "gear": body(GEAR, 1, -1.0),
    })
}
