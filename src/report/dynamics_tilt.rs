//! The `tilt` block of a helical pair's `summary.json` (docs/MODEL.md 11.8): each tilting
//! body's tilt about the plane of action's normal n (a, the axis the face load tilts) and
//! about the transverse line of action d (b), its mean and half peak-to-peak, the mean
//! moment on each tilting bearing, the mesh's tilting terms, and the K_Hbeta the mean
//! relative tilt implies.

use crate::dynamics::assembly::elements::Elements;
use crate::dynamics::assembly::single_pair::{GEAR, PINION};
use crate::dynamics::assembly::{Assembly, Dof};
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::spectrum::time_mean_with_slopes;
use crate::study::helical_tilt::{k_h_beta_of_tilt, relative_tilt_rad};
use crate::study::Model;
use serde_json::{json, Value};

/// Mean (slope-corrected trapezoid over `window_s`) and half peak-to-peak of a signal x
/// with slope dx at times t.
fn mean_and_amplitude(t: &[f64], x: &[f64], dx: &[f64], window_s: f64) -> (f64, f64) {
    let (lo, hi) = x
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        });
    (time_mean_with_slopes(t, x, dx, window_s), 0.5 * (hi - lo))
}

/// The block (module docs); None without tilting coordinates.
pub fn tilt_summary(model: &Model, r: &DynamicResponse) -> Option<Value> {
    let support = model.params.tilt?;
    let h = model.helical.as_ref()?;
    let asm = Assembly::new(Elements::single_pair(&model.params, &model.pair)).ok()?;
    let geo = &asm.meshes()[0];
    let d = geo.line_of_action;
    let spin = asm.spin()[PINION];
    let n = [spin * d[1], -spin * d[0]];
    let s = &r.signals;
    let t = &s.time_s;
    let period = r.mesh_period_s * r.excitation_periods.max(1) as f64;
    let span = t.last().copied().unwrap_or(0.0) - t.first().copied().unwrap_or(0.0);
    let window = period * (span / period).ceil().max(1.0);
    let body = |b: usize, which: usize| {
        let (Some(x), Some((k, c))) = (asm.index(b, Dof::TiltX), support.bearings[which]) else {
            return json!({ "bearing": "rigid" });
        };
        let project = |u: [f64; 2], q: &crate::dynamics::response::Coordinates| -> Vec<f64> {
            q.iter().map(|qi| u[0] * qi[x] + u[1] * qi[x + 1]).collect()
        };
        let (a, da) = (project(n, &s.displacement), project(n, &s.velocity));
        let (bb, db) = (project(d, &s.displacement), project(d, &s.velocity));
        let (a_mean, a_amp) = mean_and_amplitude(t, &a, &da, window);
        let (b_mean, b_amp) = mean_and_amplitude(t, &bb, &db, window);
        json!({
            "bearing": "elastic",
            "stiffness_nm_per_rad": k,
            "damping_nm_s_per_rad": c,
            "diametral_inertia_kg_m2": support.diametral_inertia_kg_m2[which],
            "about_plane_normal_mean_rad": a_mean,
            "about_plane_normal_amplitude_rad": a_amp,
            "about_line_of_action_mean_rad": b_mean,
            "about_line_of_action_amplitude_rad": b_amp,
            "moment_about_plane_normal_mean_nm": k * a_mean,
            "moment_about_line_of_action_mean_nm": k * b_mean,
        })
    };
    let tau = relative_tilt_rad(model, r)?;
    let dtau: Vec<f64> = {
        let h = asm.relative_tilt_gradient(0);
        s.velocity
            .iter()
            .map(|v| h.iter().map(|(k, hk)| hk * v[*k]).sum())
            .collect()
    };
    let (tau_mean, tau_amp) = mean_and_amplitude(t, &tau, &dtau, window);
    let k_mean = model.mesh.mean_stiffness_n_per_m();
    let f_mean = r.meshes[0].mean_mesh_force_n;
    let m = support.mesh;
    Some(json!({
        "unit": "rad and N m; a about n = d x z (the plane of action's normal: the axis the face load tilts), b about the transverse line of action d; z along the pinion's angular velocity",
        "pinion": body(PINION, 0),
        "gear": body(GEAR, 1),
        "relative_tilt_mean_rad": tau_mean,
        "relative_tilt_amplitude_rad": tau_amp,
        "mesh_centre_lever_m": m.centre_lever_m,
        "mesh_tilting_stiffness_nm_per_rad": m.tilting_stiffness_nm_per_rad,
        "mesh_gap_moment_nm": m.gap_moment_nm,
        "k_h_beta_of_mean_tilt": if model.helical.as_ref().is_some_and(|h| h.lead.is_some()) {
            Value::Null
        } else {
            k_h_beta_of_tilt(&h.pair, h.slices, k_mean, f_mean, tau_mean).map_or(Value::Null, Value::from)
        },
    }))
}
