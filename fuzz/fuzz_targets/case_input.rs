//! Fuzz target over everything a user hands gearwear as a case: the TOML text, `--set`
//! overrides and `--vary` axes are parsed and validated; a valid case within a small
//! budget is built into a model and evaluated once, cheaply (the mesh stiffness and the
//! quasi-static twin), and every number it gives must be finite.
//!
//! Input: NUL-separated chunks. The first is the case file; each further chunk is a
//! `--set` override, or, when it starts with `vary:`, a `--vary` axis.
//! Run: scripts/fuzz.sh (docs/RELIABILITY.md).

#![no_main]

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::study::budget::{estimate, Budget, Job};
use gearwear::study::sweep::{parse_vary, SweepPlan};
use gearwear::study::Model;
use gearwear::wear::WearState;
use libfuzzer_sys::fuzz_target;

/// What one fuzz input may cost: a quarter of a second, 256 MB.
const FUZZ_BUDGET: Budget = Budget {
    memory_bytes: 256e6,
    seconds: 0.25,
};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let mut chunks = text.split('\0');
    let case_text = chunks.next().unwrap_or("");
    let mut sets = Vec::new();
    let mut axes = Vec::new();
    for c in chunks {
        match c.strip_prefix("vary:") {
            Some(v) => {
                if let Ok(a) = parse_vary(v) {
                    axes.push(a);
                }
            }
            None => sets.push(c.to_owned()),
        }
    }
    if let Ok(plan) = SweepPlan::new(axes) {
        // Each case of a small plan must load or be refused, never panic.
        for id in 0..plan.len().min(4) {
            let mut s = sets.clone();
            s.extend(plan.overrides_of(id));
            let _ = load_case(case_text, &s);
        }
    }
    let Ok(case) = load_case(case_text, &sets) else {
        return;
    };
    let cost = estimate(&case, Job::Stiffness);
    assert!(cost.seconds().is_finite() && cost.memory_bytes().is_finite());
    if cost.check(&FUZZ_BUDGET).is_err() {
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
    let r = model.quasi_static(&WearState::new(model.grid.len()), &ExternalError::none());
    assert!(r.mean_mesh_force_n.is_finite() && r.mean_mesh_force_n > 0.0);
    assert!(r.mean_dte_m.is_finite());
    for x in r.signals.dte_m.iter().chain(&r.signals.mesh_force_n) {
        assert!(x.is_finite(), "non-finite quasi-static signal");
    }
    for p in &r.path {
        assert!(
            p.load_n.is_finite() && p.pressure_pa.is_finite() && p.friction_n.is_finite(),
            "non-finite path sample {p:?}"
        );
    }
});
