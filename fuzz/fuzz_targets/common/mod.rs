//! What both fuzz targets do with a case: load it, and if it is valid and cheap, build
//! its model and evaluate it once; every number must be finite.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::study::budget::{estimate, Budget, Job};
use gearwear::study::Model;
use gearwear::wear::WearState;

/// What one fuzz input may cost: a quarter of a second, 256 MB.
const FUZZ_BUDGET: Budget = Budget {
    memory_bytes: 256e6,
    seconds: 0.25,
    figures: gearwear::study::budget::FigureLoad::NONE,
};

/// Largest quasi-static grid evaluated (2.4 us a step: 50 ms).
const MAX_STEPS: i64 = 20_000;

/// Load `case_text` with `sets`; evaluate a valid, cheap case. Panics on any non-finite
/// or non-physical number.
pub fn check_case(case_text: &str, sets: &[String]) {
    let Ok(case) = load_case(case_text, sets) else {
        return;
    };
    let cost = estimate(&case, Job::Stiffness);
    assert!(cost.seconds().is_finite() && cost.memory_bytes().is_finite());
    if cost.check(&FUZZ_BUDGET).is_err() || case.numerics.steps_per_mesh_period > MAX_STEPS {
        return;
    }
    let Ok(model) = Model::from_case(&case) else {
        return;
    };
    let mesh = &model.mesh;
    for k in [
        mesh.min_stiffness_n_per_m(),
        mesh.mean_stiffness_n_per_m(),
        mesh.max_stiffness_n_per_m(),
    ] {
        assert!(k.is_finite() && k > 0.0, "mesh stiffness {k}");
    }
    for v in model.resolved_parameters().values {
        assert!(v.value.is_finite() && v.value > 0.0, "{v:?}");
    }
    let r = model.quasi_static(&WearState::new(model.grid.len()), &ExternalError::none());
    for (mesh, signals) in r.meshes.iter().zip(&r.signals.meshes) {
        assert!(mesh.mean_mesh_force_n.is_finite() && mesh.mean_mesh_force_n > 0.0);
        assert!(mesh.mean_dte_m.is_finite());
        for x in signals.dte_m.iter().chain(&signals.mesh_force_n) {
            assert!(x.is_finite(), "non-finite quasi-static signal");
        }
        for p in &mesh.path {
            assert!(
                p.load_n.is_finite() && p.pressure_pa.is_finite() && p.friction_n.is_finite(),
                "non-finite path sample {p:?}"
            );
        }
    }
}
