//! Helpers of the tests of per-tooth inputs on a helical pair: its model from `--set`
//! lines on the nominal path, its steady and quasi-static responses, and the mesh
//! stiffness a fault takes from the healthy lines.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::response::DynamicResponse;
use gearwear::dynamics::summary::ResponseSummary;
use gearwear::study::Model;

/// The nominal path with stiffness load sharing: the helical lines' own contact model.
pub const NOMINAL: [&str; 2] = [
    "contact.path=\"nominal\"",
    "contact.load_sharing=\"stiffness\"",
];

/// The dynamics model of the built-in case on [`NOMINAL`] with `sets` (`key=value`).
pub fn model(sets: &[&str]) -> Model {
    let mut all: Vec<String> = NOMINAL.iter().map(|s| s.to_string()).collect();
    all.extend(sets.iter().map(|s| s.to_string()));
    Model::dynamics_from_case(&load_case("", &all).expect("valid case")).expect("valid model")
}

/// The steady state of `m` under the external error `e`.
pub fn steady(m: &Model, e: &ExternalError) -> DynamicResponse {
    m.dynamic(&m.new_wear_state(), e).expect("steady state")
}

/// The quasi-static response of `m`, new teeth.
pub fn quasi(m: &Model) -> DynamicResponse {
    m.quasi_static(&m.new_wear_state(), &ExternalError::none())
}

/// Equal to `rel` of the larger magnitude.
pub fn close(a: f64, b: f64, rel: f64, what: &str) {
    assert!(
        (a - b).abs() <= rel * a.abs().max(b.abs()),
        "{what}: {a} against {b}"
    );
}

/// The summaries of two responses equal to `rel` (forces and DTE).
pub fn same_summaries(a: &ResponseSummary, b: &ResponseSummary, rel: f64) {
    close(a.mesh_force_mean_n, b.mesh_force_mean_n, rel, "mean force");
    close(a.mesh_force_max_n, b.mesh_force_max_n, rel, "max force");
    close(a.mesh_force_min_n, b.mesh_force_min_n, rel, "min force");
    close(a.dte_max_m, b.dte_max_m, rel, "max DTE");
    close(a.dte_min_m, b.dte_min_m, rel, "min DTE");
    close(a.dte_mean_m, b.dte_mean_m, rel, "mean DTE");
}

/// The mesh stiffness a fault removes at each quasi-static sample, N/m: the model's
/// healthy contact lines at the sample's phase (its line table) less the sample's
/// stiffness, with each sample's share of pinion roll r_b1 dphi (trapezoid weights, m).
pub fn stiffness_dips(m: &Model, r: &DynamicResponse) -> Vec<(f64, f64)> {
    let s = &r.signals;
    let ms = &s.meshes[0];
    let omega = m.params.operating.pinion_speed_rad_s;
    let rb1 = m.pair.pinion.base_radius_m;
    let n = s.time_s.len();
    let total = r.excitation_periods as f64 * r.mesh_period_s;
    (0..n)
        .map(|k| {
            let healthy: f64 = m
                .pair
                .pairs_in_contact(ms.phase_rad[k])
                .map(|(_, rho)| m.mesh.pair_stiffness_n_per_m(rho))
                .sum();
            let next = if k + 1 < n { s.time_s[k + 1] } else { total };
            let prev = if k > 0 {
                s.time_s[k - 1]
            } else {
                s.time_s[n - 1] - total
            };
            let roll = rb1 * omega * 0.5 * (next - prev);
            (healthy - ms.mesh_stiffness_n_per_m[k], roll)
        })
        .collect()
}
