//! Properties over the input domain (issue 13), checked on random cases: every value of
//! every numeric key is accepted or refused naming the key; every valid case builds a
//! model with finite, positive mesh stiffness and a finite quasi-static evaluation, or
//! is refused with a message; its budget estimate is finite. Cheap evaluations only
//! (no dynamics), so the whole file runs in a few seconds.

use gearwear::config::load_case;
use gearwear::config::schema::{Valid, KEYS};
use gearwear::dynamics::excitation::ExternalError;
use gearwear::study::budget::{estimate, Budget, Job};
use gearwear::study::Model;
use gearwear::wear::WearState;
use proptest::prelude::*;

/// A float from anywhere: ordinary magnitudes, extremes, zeros, subnormals, non-finite.
fn any_number() -> impl Strategy<Value = f64> {
    prop_oneof![
        -1e3..1e3f64,
        (-300i32..300).prop_map(|e| 10f64.powi(e)),
        Just(0.0),
        Just(5e-324),
        Just(f64::MAX),
        Just(f64::NAN),
        Just(f64::INFINITY),
        any::<f64>(),
    ]
}

/// TOML text of a float that reads back to the same value (non-finite as TOML's words).
fn toml_number(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.into()
    } else {
        format!("{x:e}")
    }
}

fn numeric_keys() -> Vec<&'static str> {
    KEYS.iter()
        .filter(|k| {
            matches!(
                k.valid,
                Valid::Num(_) | Valid::NumOrDerived(_) | Valid::Int(..)
            )
        })
        .map(|k| k.key)
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn any_number_for_any_key_is_accepted_in_range_or_refused_by_name(
        key in proptest::sample::select(numeric_keys()),
        x in any_number(),
    ) {
        let spec = gearwear::config::schema::spec(key).unwrap();
        let in_range = match spec.valid {
            Valid::Num(r) | Valid::NumOrDerived(r) => r.contains(x),
            Valid::Int(lo, hi) => x.fract() == 0.0 && x >= lo as f64 && x <= hi as f64,
            _ => unreachable!(),
        };
        match load_case("", &[format!("{key}={}", toml_number(x))]) {
            Ok(_) => prop_assert!(in_range, "{key} = {x} accepted"),
            Err(e) => {
                let text = e.to_string();
                // Out of range: the key is named. In range, only a relation between keys
                // (face width against module, viscosity with Xu) may refuse it.
                prop_assert!(text.contains(key) || in_range, "{key} = {x}: {text}");
                prop_assert!(text.len() < 2000);
            }
        }
    }
}

/// A random case inside the keys' ranges, as `--set` overrides.
fn valid_case() -> impl Strategy<Value = Vec<String>> {
    (
        (
            0.5..8.0f64,
            12..80i64,
            20..150i64,
            15.0..25.0f64,
            5.0..20.0f64,
        ),
        (-0.3..0.6f64, -0.3..0.6f64, 0.9..1.2f64, 1.15..1.4f64),
        (
            1.0..200.0f64,
            1.0..500.0f64,
            0usize..3,
            0usize..2,
            any::<bool>(),
        ),
        (
            16..300i64,
            20..200i64,
            11..80i64,
            prop_oneof![Just(None), (1.5..6.0f64).prop_map(Some)],
        ),
    )
        .prop_map(
            |(
                (m, z1, z2, alpha, b_over_m),
                (x1, x2, ha, hf),
                (speed, torque, fric, share, junction),
                (table, steps, grid, h_f),
            )| {
                let bore = |z: i64, x: f64| match h_f {
                    None => "derived".to_string(),
                    Some(h) => format!("{}", m * (z as f64 / 2.0 - hf + x) / h),
                };
                vec![
                    format!("gear.module_mm={m}"),
                    format!("gear.teeth_pinion={z1}"),
                    format!("gear.teeth_gear={z2}"),
                    format!("gear.pressure_angle_deg={alpha}"),
                    format!("gear.face_width_mm={}", b_over_m * m),
                    format!("gear.profile_shift_pinion={x1}"),
                    format!("gear.profile_shift_gear={x2}"),
                    format!("gear.addendum_coefficient={ha}"),
                    format!("gear.dedendum_coefficient={hf}"),
                    format!("gear.hub_bore_radius_pinion_mm={}", bore(z1, x1)),
                    format!("gear.hub_bore_radius_gear_mm={}", bore(z2, x2)),
                    "dynamics.mass_pinion_kg=derived".into(),
                    "dynamics.inertia_gear_kg_m2=derived".into(),
                    format!("operating.input_speed_hz={speed}"),
                    format!("operating.load_torque_nm={torque}"),
                    format!("friction.model={}", ["xu2007", "constant", "none"][fric]),
                    format!("contact.load_sharing={}", ["pedrero", "stiffness"][share]),
                    format!(
                        "stiffness.fillet_root_angle={}",
                        if junction {
                            "fillet_junction"
                        } else {
                            "flank_extension"
                        }
                    ),
                    "stiffness.allow_fillet_extrapolation=true".into(),
                    format!("stiffness.table_points_per_mesh_period={table}"),
                    format!("numerics.steps_per_mesh_period={steps}"),
                    format!("wear.points_per_profile={grid}"),
                ]
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn valid_cases_give_finite_stiffness_and_quasi_static_results_or_a_message(
        sets in valid_case(),
    ) {
        let case = match load_case("", &sets) {
            Ok(c) => c,
            Err(e) => {
                prop_assert!(!e.problems.is_empty() && e.messages().iter().all(|p| p.contains('`')), "{e}");
                return Ok(());
            }
        };
        let cost = estimate(&case, Job::Run);
        prop_assert!(cost.seconds().is_finite() && cost.memory_bytes().is_finite());
        if let Err(e) = cost.check(&Budget::DEFAULT) {
            // Over budget (a fast-wearing pair makes many updates): refused with the keys.
            let e = e.to_string();
            prop_assert!(e.contains("budget") && e.contains('`'), "{e}");
            return Ok(());
        }
        let model = match Model::from_case(&case) {
            Ok(m) => m,
            Err(e) => {
                // Geometry that cannot mesh, a load no flank carries: a message per problem.
                prop_assert!(!e.0.is_empty() && e.0.iter().all(|p| p.len() > 20), "{e}");
                return Ok(());
            }
        };
        let mesh = &model.mesh;
        for k in [mesh.min_stiffness_n_per_m(), mesh.mean_stiffness_n_per_m(), mesh.max_stiffness_n_per_m()] {
            prop_assert!(k.is_finite() && k > 0.0, "{k}");
        }
        prop_assert!(mesh.min_stiffness_n_per_m() <= mesh.mean_stiffness_n_per_m());
        let r = model.quasi_static(&WearState::new(model.grid.len()), &ExternalError::none());
        prop_assert!(r.meshes[0].mean_mesh_force_n.is_finite() && r.meshes[0].mean_mesh_force_n > 0.0);
        prop_assert!(r.signals.meshes[0].dte_m.iter().all(|x| x.is_finite()));
        prop_assert!(r.meshes[0].path.iter().all(|p| p.load_n.is_finite() && p.pressure_pa.is_finite() && p.friction_n.is_finite()));
        let p = model.resolved_parameters();
        prop_assert!(p.values.iter().all(|v| v.value.is_finite() && v.value > 0.0));
    }
}
