//! Gear trains in a limit whose answer is known without the train: a second stage that
//! cannot move is the first stage's pair alone, with the second stage's bodies carried
//! as rigid inertia on its gear.

use gearwear::dynamics::excitation::{ExternalError, PairGap};
use gearwear::dynamics::response::DynamicResponse;
use gearwear::dynamics::summary::ResponseSummary;
use gearwear::study::Model;
use gearwear::wear::WearState;

mod common;
use common::train::model;

/// Stage 2 as rigid as the case allows: a 31-tooth pinion (so mesh 2 repeats with mesh 1
/// and the base period is one mesh period) and a 62-tooth gear (ratio 1/2 exactly), module
/// 20 mm and `width_mm` wide (mesh 2's stiffness about width/20 x mesh 1's, its radius
/// 10x), bearings and shaft at the top of their ranges.
fn stiff_second_stage(width_mm: f64) -> String {
    format!(
        r#"
[[stage]]
shaft_torsional_stiffness_nm_per_rad = 1e10

[[stage]]
module_mm = 20
teeth_pinion = 31
teeth_gear = 62
face_width_mm = {width_mm}
hub_bore_radius_pinion_mm = "derived"
hub_bore_radius_gear_mm = "derived"
mass_pinion_kg = 2.0
mass_gear_kg = 5.0
inertia_pinion_kg_m2 = 4e-4
inertia_gear_kg_m2 = 6e-3
bearing_stiffness_pinion_n_per_m = 1e12
bearing_stiffness_gear_n_per_m = 1e12
"#
    )
}

fn steady(m: &Model) -> DynamicResponse {
    m.dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
        .unwrap()
}

/// The first stage alone with the rigid second stage reflected onto its gear's shaft
/// (ratio rho = 1/2): gear inertia J_g1 + J_p2 + J_g2 rho^2, the brake's coupling and
/// inertia times rho^2, and the mesh damping ratio that gives the train's mesh-1 damper
/// c_m (which the train computes from J_g1 alone).
fn reflected_pair(train: &Model) -> Model {
    let t = train.train.as_ref().unwrap();
    let (s1, s2) = (&t.stages[0].lumped, &t.stages[1].lumped);
    let rho: f64 = 0.5;
    let d = &train.case.dynamics;
    let j_gear =
        s1.inertia_gear_kg_m2 + s2.inertia_pinion_kg_m2 + s2.inertia_gear_kg_m2 * rho * rho;
    let edits = |zeta: f64| -> Vec<String> {
        vec![
            format!("dynamics.inertia_gear_kg_m2={j_gear:e}"),
            format!(
                "dynamics.inertia_brake_kg_m2={:e}",
                d.inertia_brake_kg_m2 * rho * rho
            ),
            format!(
                "dynamics.coupling_stiffness_brake_nm_per_rad={:e}",
                d.coupling_stiffness_brake_nm_per_rad * rho * rho
            ),
            format!(
                "dynamics.coupling_damping_brake_nm_s_per_rad={:e}",
                d.coupling_damping_brake_nm_s_per_rad * rho * rho
            ),
            format!("dynamics.mesh_damping_ratio={zeta:e}"),
            "friction.model=none".to_string(),
            // The train's own contact model.
            format!(
                "contact.path={}",
                serde_json::to_value(train.case.contact.path).unwrap()
            ),
        ]
    };
    let build = |zeta: f64| {
        let sets = edits(zeta);
        let sets: Vec<&str> = sets.iter().map(String::as_str).collect();
        model("", &sets)
    };
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let c_train = train.system(&gap, &ext, 0.2).mesh(0).mesh_damping_n_s_per_m;
    let zeta = d.mesh_damping_ratio;
    let first = build(zeta);
    let c_first = first.system(&gap, &ext, 0.2).mesh(0).mesh_damping_n_s_per_m;
    // c_m is proportional to zeta.
    build(zeta * c_train / c_first)
}

/// The compliance the rigid-stage limit neglects, relative to mesh 1's: mesh 2's
/// torsional compliance seen from the intermediate shaft, 1 / (k_m2 r_p2^2), the shaft's
/// 1 / k_s, and stage 2's bearings' 1 / (k_b r_p2^2) (each against mesh 1's
/// 1 / (k_m1 r_g1^2)).
fn neglected_compliance(train: &Model) -> f64 {
    let t = train.train.as_ref().unwrap();
    let (s1, s2) = (&t.stages[0], &t.stages[1]);
    let r_g1 = s1.pair.gear.base_radius_m;
    let r_p2 = s2.pair.pinion.base_radius_m;
    let k1 = s1.mesh.mean_stiffness_n_per_m() * r_g1 * r_g1;
    let k2 = s2.mesh.mean_stiffness_n_per_m() * r_p2 * r_p2;
    let k_b = s2.lumped.bearing_stiffness_pinion_n_per_m * r_p2 * r_p2;
    k1 / k2 + k1 / 1e10 + k1 / k_b
}

/// The differences of the train's mesh 1 from the reflected pair, relative to the pair's
/// dynamic amplitudes: DTE peak-to-peak, mean and extremes of the mesh force, and the
/// pinion's first velocity harmonic.
fn difference(train: &Model, pair: &Model) -> f64 {
    let t = train.train.as_ref().unwrap();
    let r = steady(train);
    let a = ResponseSummary::of_mesh(&r, 0, 1.0 / t.operating.meshes[0].mesh_frequency_hz, 1);
    let b = ResponseSummary::of(&steady(pair));
    let dte_pp = b.dte_max_m - b.dte_min_m;
    let force_pp = b.mesh_force_max_n - b.mesh_force_min_n;
    let v1 = b.velocity_y_pinion_harmonics_m_per_s[0];
    [
        ((a.dte_max_m - a.dte_min_m) - dte_pp).abs() / dte_pp,
        (a.dte_mean_m - b.dte_mean_m).abs() / dte_pp,
        (a.mesh_force_mean_n - b.mesh_force_mean_n).abs() / force_pp,
        (a.mesh_force_max_n - b.mesh_force_max_n).abs() / force_pp,
        (a.mesh_force_min_n - b.mesh_force_min_n).abs() / force_pp,
        (a.velocity_y_pinion_harmonics_m_per_s[0] - v1).abs() / v1,
    ]
    .into_iter()
    .fold(0.0, f64::max)
}

#[test]
fn a_second_stage_that_cannot_move_leaves_the_first_pair_alone() {
    // Friction off: a rigid stage 2 still has its mesh's friction torque, which the
    // reflection would have to carry too. The train's mesh 1 against the first pair alone
    // with stage 2 reflected as rigid inertia: they differ by the order of the compliance the reflection neglects (mesh
    // 2, the shaft and stage 2's bearings against mesh 1), and the difference falls with
    // it: stage 2's mesh 3.8 times stiffer (its face width 500 -> 1900 mm, 100 modules
    // being the most a stage may have) cuts the neglected compliance by more than half
    // (the shaft's and bearings' share stays) and the difference by at least a third
    // (first order in the compliance; the solver's own error, ~1e-6 of the amplitudes,
    // is far below both). Measured: compliance 3.9e-4 -> 1.3e-4, difference 2.2e-4 ->
    // 1.2e-4 of the amplitudes.
    // The paper's contact model: with corner contact the difference fell by 22 %, not a
    // third, when this was written (a corner's engagement moves with the deflection the
    // reflection changes): open (issue 32).
    let mut previous: Option<(f64, f64)> = None;
    for width in [500.0, 1900.0] {
        let train = model(
            &stiff_second_stage(width),
            &["friction.model=none", "contact.path=nominal"],
        );
        let pair = reflected_pair(&train);
        let eps = neglected_compliance(&train);
        let diff = difference(&train, &pair);
        println!("face width {width} mm: neglected compliance {eps:.2e}, difference {diff:.2e}");
        assert!(diff < 3.0 * eps, "difference {diff:e} beyond 3 x {eps:e}");
        if let Some((eps0, diff0)) = previous {
            assert!(eps < 0.5 * eps0, "{eps:e} vs {eps0:e}");
            assert!(diff < 0.67 * diff0, "{diff:e} vs {diff0:e}");
        }
        previous = Some((eps, diff));
    }
}
