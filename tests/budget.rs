//! The run budget's estimate (`study::budget`) against what the solvers measurably do:
//! integrator steps, periods to settle, recorded samples and wear updates.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::study::budget::{estimate, Job};
use gearwear::study::wear_loop::{run_wear, WearMode, WearRun};
use gearwear::study::Model;
use gearwear::wear::WearState;

fn case(sets: &[&str]) -> gearwear::config::Case {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    load_case("", &sets).expect("valid case")
}

#[test]
fn step_and_sample_counts_are_bounded_by_the_estimate() {
    // The solver's own counts against the estimate: the steps taken (error-controlled,
    // over the periods it took to settle) and the samples recorded never exceed the
    // estimate's S_d (P_c + P_e) and S_d P_e, and the grid nodes alone give the floor
    // S P_e of the recorded samples (every node is a sample). Cases: the built-in one,
    // a coarse grid with more recorded periods, a looser settling tolerance, a slow mesh
    // (0.5 Hz: the error control adds the most steps) and a tight integration tolerance.
    for sets in [
        vec![],
        vec![
            "numerics.steps_per_mesh_period=100",
            "numerics.evaluated_mesh_periods=8",
        ],
        vec![
            "operating.input_speed_hz=45",
            "numerics.steady_state_tolerance=1e-5",
        ],
        vec!["operating.input_speed_hz=0.5"],
        vec![
            "operating.input_speed_hz=0.5",
            "numerics.integration_tolerance=1e-9",
        ],
    ] {
        let c = case(&sets);
        let e = estimate(&c, Job::Dynamics);
        let m = Model::from_case(&c).unwrap();
        let r = m
            .dynamic(&WearState::new(m.grid.len()), &ExternalError::none())
            .unwrap();
        let (s, p_e) = (
            c.numerics.steps_per_mesh_period as f64,
            c.numerics.evaluated_mesh_periods as f64,
        );
        let samples = r.signals.time_s.len() as f64;
        assert!(
            r.steps as f64 <= e.steps_per_evaluation,
            "{sets:?}: {} steps, estimate {}",
            r.steps,
            e.steps_per_evaluation
        );
        assert!(r.steps as f64 <= e.steps_to_give_up);
        assert!(
            samples <= e.recorded_samples,
            "{sets:?}: {samples} samples, estimate {}",
            e.recorded_samples
        );
        assert!(samples >= s * p_e, "{sets:?}: {samples} samples");
    }
}

#[test]
fn wear_update_counts_match_the_wear_loop() {
    // Quasi-static studies (cheap) cut by the threshold, by the block and by the total.
    // The estimate's wear per cycle (Archard at the nominal load, 65 points along the path)
    // and the wear model's first increment (the quasi-static path on the 101-point grid)
    // are two computations of one quantity: 2 % covers the different sampling of the
    // path. The update count may drift from the estimate as the profile wears and the
    // roughness falls, which the estimate ignores: a factor 1.5 is asked (measured: equal
    // on all five cases). On the nominal path: the estimate's Archard rate takes the
    // paper's eq. (7) shares; with corner contact (the default, shares by compression)
    // the first increment came out 22 % above it when this was written (open, issue 32).
    for sets in [
        vec![],
        vec!["wear.coefficient_m2_per_n=1e-15"],
        vec!["wear.block_cycles=2500"],
        vec!["wear.threshold_um=0.2", "wear.total_cycles=1e5"],
        vec!["operating.load_torque_nm=150", "wear.threshold_um=0.25"],
    ] {
        let mut c = case(&sets);
        c.contact.path = gearwear::config::case::ContactPathModel::Nominal;
        let e = estimate(
            &c,
            Job::Wear {
                dynamic: false,
                quasi_static: true,
            },
        );
        let m = Model::from_case(&c).unwrap();
        let run = run_wear(&m, WearRun::new(WearMode::QuasiStatic), &mut |_| Ok(())).unwrap();
        let first = &run.records[0];
        let rate = first
            .increment_pinion_m
            .iter()
            .chain(&first.increment_gear_m)
            .fold(0.0_f64, |a, b| a.max(*b));
        let est_rate = e.wear_per_cycle_m.unwrap();
        assert!(
            (est_rate / rate - 1.0).abs() < 0.02,
            "{sets:?}: {est_rate} vs {rate}"
        );
        let measured = run.records.len() as f64;
        let ratio = e.wear_updates_quasi_static / measured;
        assert!(
            (1.0 / 1.5..=1.5).contains(&ratio),
            "{sets:?}: estimated {} updates, measured {measured}",
            e.wear_updates_quasi_static
        );
    }
}
