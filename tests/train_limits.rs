//! Gear trains in a limit whose answer is known without the train: a second stage that
//! cannot move is the first stage's pair alone, with the second stage's bodies carried
//! as rigid inertia on its gear.

use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::response::DynamicResponse;
use gearwear::dynamics::summary::ResponseSummary;
use gearwear::study::Model;
use gearwear::wear::WearState;

mod common;
use common::train::{model, neglected_compliance, reflected_pair, stiff_second_stage};

fn steady(m: &Model) -> DynamicResponse {
    m.dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
        .unwrap()
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
        let pair = reflected_pair(&train, &[]);
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
