//! Archard wear and the update loop against independent facts.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::geometry::ProfileGrid;
use gearwear::study::wear_loop::{run_wear, WearMode, WearRun};
use gearwear::study::Model;
use gearwear::wear::profile_wear::wear_transmission_error;
use gearwear::wear::{per_cycle_wear, WearState};

fn model(sets: &[&str]) -> Model {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    Model::from_case(&load_case("", &sets).unwrap()).unwrap()
}

fn qs_path(m: &Model) -> Vec<gearwear::dynamics::response::PathSample> {
    m.quasi_static(&WearState::new(m.grid.len()), &ExternalError::none())
        .meshes
        .swap_remove(0)
        .path
}

#[test]
fn no_wear_at_the_pitch_point() {
    // At the pitch point the surfaces roll without sliding (u_p = u_g), so s = 0.
    let m = model(&[]);
    let path = qs_path(&m);
    let mut grid = ProfileGrid::new(&m.pair, 3);
    grid.rho_pinion_m = vec![
        m.pair.rho_start_m + 1e-4,
        m.pair.rho_pitch_m,
        m.pair.rho_end_m - 1e-4,
    ];
    let inc = per_cycle_wear(&grid, &path, 2.5e-16, 19.0 / 31.0);
    let scale = inc.pinion_m[0].max(inc.pinion_m[2]);
    assert!(scale > 0.0);
    // Round-off of u_p - u_g at the pitch point is ~1e-16 of u_p.
    assert!(inc.pinion_m[1] < 1e-9 * scale, "{}", inc.pinion_m[1]);
    assert!(inc.gear_m[1] < 1e-9 * scale);
}

#[test]
fn gear_to_pinion_wear_ratio_is_sliding_ratio_times_z1_over_z2() {
    // Same pressure and sliding speed at conjugate points: h_g/h_p = (s_g/s_p)(z1/z2)
    // = (u_p/u_g)(z1/z2), with u = omega rho at nominal speed (independent of the code path).
    let m = model(&[]);
    let inc = per_cycle_wear(&m.grid, &qs_path(&m), 2.5e-16, 19.0 / 31.0);
    let (wp, wg) = (
        m.params.operating.pinion_speed_rad_s,
        m.params.operating.gear_speed_rad_s,
    );
    let mut checked = 0;
    for i in 0..m.grid.len() {
        if inc.pinion_m[i] < 1e-3 * inc.max_m() {
            continue; // near the pitch point both vanish; the ratio is ill-conditioned
        }
        let up = wp * m.grid.rho_pinion_m[i];
        let ug = wg * m.grid.rho_gear_m[i];
        let expected = up / ug * 19.0 / 31.0;
        let got = inc.gear_m[i] / inc.pinion_m[i];
        assert!(
            (got / expected - 1.0).abs() < 1e-12,
            "point {i}: {got} vs {expected}"
        );
        checked += 1;
    }
    assert!(checked > 80);
}

#[test]
fn wear_is_linear_in_the_coefficient_and_in_cycles_under_a_fixed_load() {
    // One block covering all cycles and a threshold never reached: the load is never
    // renewed, so H = N k p s exactly (eq. 17 with a single update).
    let run = |k: &str, cycles: &str| -> f64 {
        let m = model(&[
            &format!("wear.coefficient_m2_per_n={k}"),
            &format!("wear.total_cycles={cycles}"),
            &format!("wear.block_cycles={cycles}"),
            "wear.threshold_um=1e6",
        ]);
        let r = run_wear(&m, WearRun::new(WearMode::QuasiStatic), &mut |_| Ok(())).unwrap();
        assert_eq!(r.records.len(), 2, "a single block");
        r.last().unwrap().wear.max_pinion_m()
    };
    let base = run("2.5e-16", "1e4");
    assert!(base > 0.0);
    // Exact linearity up to round-off (products of the same doubles).
    assert!((run("5e-16", "1e4") / base - 2.0).abs() < 1e-12);
    assert!((run("2.5e-16", "3e4") / base - 3.0).abs() < 1e-12);
}

#[test]
fn transmission_error_of_known_wear_matches_hand_computation() {
    // Pinion wear h_p = a (rho1 - rho_A), no gear wear. In single contact the error is the
    // gap of the one pair; in double contact the stiffness-weighted mean of the two gaps.
    let m = model(&[]);
    let a = 1e-4; // 0.1 um per mm
    let mut w = WearState::new(m.grid.len());
    for (h, r) in w.pinion_m.iter_mut().zip(&m.grid.rho_pinion_m) {
        *h = a * (r - m.pair.rho_start_m);
    }
    let gap = w.pair_gap(&m.grid);
    let te = wear_transmission_error(&m.pair, &m.mesh, &gap, 50);
    for (phase, e) in te {
        let rho0 = m.pair.rho_start_m + m.pair.pinion.base_radius_m * phase;
        let rho1 = rho0 + m.pair.base_pitch_m;
        let g0 = a * (rho0 - m.pair.rho_start_m);
        let expected = if rho1 <= m.pair.rho_end_m {
            let (k0, k1) = (
                m.mesh.pair_stiffness_n_per_m(rho0),
                m.mesh.pair_stiffness_n_per_m(rho1),
            );
            (k0 * g0 + k1 * a * (rho1 - m.pair.rho_start_m)) / (k0 + k1)
        } else {
            g0
        };
        // The gap table is linear between grid points, exact for linear wear.
        assert!(
            (e - expected).abs() < 1e-15 + 1e-12 * expected,
            "{phase}: {e} vs {expected}"
        );
    }
}

#[test]
fn a_resumed_run_equals_an_uninterrupted_one() {
    let m = model(&["wear.total_cycles=2e4"]);
    let full = run_wear(&m, WearRun::new(WearMode::Dynamic), &mut |_| Ok(())).unwrap();
    assert!(full.records.len() > 4);
    // Interrupt after the third record, as a kill after a checkpoint would.
    let mut saved = None;
    let interrupted = run_wear(&m, WearRun::new(WearMode::Dynamic), &mut |r| {
        if r.records.len() == 3 {
            saved = Some(r.clone());
            anyhow::bail!("interrupted");
        }
        Ok(())
    });
    assert!(interrupted.is_err());
    // Resume from the checkpoint as it would be read back from JSON.
    let text = serde_json::to_string(&saved.unwrap()).unwrap();
    let back: WearRun = serde_json::from_str(&text).unwrap();
    let resumed = run_wear(&m, back, &mut |_| Ok(())).unwrap();
    // Bit-for-bit: the checkpoint must restore every double exactly (serde_json with
    // float_roundtrip) and the loop must be deterministic.
    assert!(
        resumed == full,
        "resumed run differs from the uninterrupted one"
    );
}

#[test]
fn halving_block_and_threshold_changes_final_wear_by_less_than_two_percent() {
    let final_max = |block: &str, thr: &str| {
        let m = model(&[
            &format!("wear.block_cycles={block}"),
            &format!("wear.threshold_um={thr}"),
        ]);
        let r = run_wear(&m, WearRun::new(WearMode::Dynamic), &mut |_| Ok(())).unwrap();
        (r.last().unwrap().wear.max_pinion_m(), r.records.len())
    };
    let (a, na) = final_max("1e4", "0.5");
    let (b, nb) = final_max("5e3", "0.25");
    assert!(nb > na, "halving must add updates: {na} vs {nb}");
    let rel = (a - b).abs() / b;
    assert!(rel < 0.02, "final max wear {a} vs {b}: {rel}");
}

#[test]
fn a_failing_wear_run_stops_its_sibling_and_its_own_error_is_reported() {
    // The dynamic run fails at its first update (as a failed checkpoint write would); the
    // quasi-static twin, which would take 1e4 updates, must stop at its next update and
    // the error returned must be the dynamic run's own.
    use gearwear::study::wear_loop::run_wear_modes;
    use std::sync::atomic::{AtomicUsize, Ordering};
    let m = Model::from_case(
        &load_case(
            "",
            &[
                "wear.total_cycles=1e8".into(),
                "wear.block_cycles=1e4".into(),
            ],
        )
        .unwrap(),
    )
    .unwrap();
    let qs_updates = AtomicUsize::new(0);
    let r = run_wear_modes(
        &m,
        vec![
            WearRun::new(WearMode::Dynamic),
            WearRun::new(WearMode::QuasiStatic),
        ],
        &|mode, _| {
            if mode == WearMode::Dynamic {
                anyhow::bail!("disk full (injected)");
            }
            qs_updates.fetch_add(1, Ordering::Relaxed);
            Ok(())
        },
    );
    let e = r.expect_err("the dynamic failure is reported");
    assert!(e.to_string().contains("injected"), "{e}");
    // The dynamic run's first update costs one steady state (tens of ms); the
    // quasi-static one costs well under a millisecond per update, so it may get a few
    // hundred updates in, never the 1e4 of the whole study.
    assert!(qs_updates.load(Ordering::Relaxed) < 5000);
}
