//! The run budget's estimate (`study::budget`) against what the solvers measurably do:
//! integrator steps, periods to settle, recorded samples and wear updates.

mod common;

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

/// `stiffness` counts the figures it writes (`study::budget::output`: a PNG figure costs
/// 8-11 ms of CPU, more than the stiffness itself; issue 33: the cracked train's run was
/// estimated at 12 ms against 66 ms): the count against the figures the command writes,
/// for a pair, a pair with a cracked tooth, the two-stage example and that train with a
/// cracked tooth on stage 1's pinion (one more figure: the faulty stage's teeth).
#[test]
fn stiffness_counts_the_figures_it_writes() {
    use gearwear::study::budget::output::stiffness_figures;
    use gearwear::study::budget::teeth::faulty_train_stages;
    let train = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/two_stage_reducer.toml"),
    )
    .unwrap();
    let crack = "\n[[fault]]\nkind = \"crack\"\nstage = 1\ngear = \"pinion\"\ntooth = 0\ncrack_depth_mm = 1.0\n";
    let pair_crack = [
        "fault.kind=crack",
        "fault.gear=pinion",
        "fault.tooth=0",
        "fault.crack_depth_mm=1",
    ];
    let cases: [(&str, String, &[&str]); 4] = [
        ("pair", String::new(), &[]),
        ("cracked pair", String::new(), &pair_crack),
        ("train", train.clone(), &[]),
        ("cracked train", format!("{train}{crack}"), &[]),
    ];
    for (what, text, sets) in cases {
        let d = tempfile::tempdir().unwrap();
        let file = d.path().join("case.toml");
        std::fs::write(&file, &text).unwrap();
        let out = d.path().join("out");
        let mut args = vec![
            "stiffness",
            "-q",
            "--config",
            file.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ];
        for s in sets {
            args.extend(["--set", s]);
        }
        common::ok(&args);
        let written = std::fs::read_dir(&out)
            .unwrap()
            .filter(|e| e.as_ref().unwrap().path().extension() == Some("png".as_ref()))
            .count();
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        let case = load_case(&text, &sets).unwrap();
        let counted = stiffness_figures(&case, faulty_train_stages(&case));
        assert_eq!(counted, written, "{what}");
    }
}

/// A record given in revolutions of the gear's shaft is as long as the seconds those
/// revolutions take at the gear's speed, f z1 / z2 (here 30 Hz x 19 / 95 = 6 Hz: 20
/// revolutions are 3.33 s); the budget counted them at the input speed (0.67 s), five
/// times too short, and admitted a 600-revolution record that went past 2 GiB.
#[test]
fn a_record_in_gear_revolutions_is_counted_at_the_gears_speed() {
    use gearwear::study::budget::estimate_signals;
    let base = ["gear.teeth_gear=95", "signals.tachometer_shaft=\"gear\""];
    let with = |extra: &[&str]| {
        let sets: Vec<String> = base.iter().chain(extra).map(|s| s.to_string()).collect();
        let e = estimate_signals(&load_case("", &sets).unwrap(), 2);
        (e.seconds(), e.memory_bytes())
    };
    let seconds = 20.0 / (30.0 * 19.0 / 95.0);
    for extra in [vec![], vec!["signals.torque_fluctuation_rms_nm=2"]] {
        let mut revs = extra.clone();
        revs.extend([
            "signals.record_length_unit=\"revolutions\"",
            "signals.record_length=20",
        ]);
        let secs_set = format!("signals.record_length={seconds}");
        let mut secs = extra.clone();
        secs.push(&secs_set);
        let (a, b) = (with(&revs), with(&secs));
        // The same record either way: equal to rounding of the duration.
        assert!(
            (a.0 / b.0 - 1.0).abs() < 1e-9 && (a.1 / b.1 - 1.0).abs() < 1e-9,
            "{extra:?}: revolutions {a:?} against seconds {b:?}"
        );
    }
}
