//! Prognostics under a load spectrum (issue 20): the k x N invariance extended to several
//! bins and to a change of duty, the surrogate against true runs under a future spectrum,
//! and coverage of the calibrated k.

use gearwear::config::{load_case, Case, LoadSpectrumSection};
use gearwear::prognostics::calibrate::{calibrate, CalibrationSettings};
use gearwear::prognostics::forward::{
    run_duty_trajectory, run_trajectory, Crossing, FutureDuty, Trajectory,
};
use gearwear::prognostics::observations::{Observations, Series};
use gearwear::prognostics::prior::Prior;
use gearwear::prognostics::{Quantity, Surrogate};
use gearwear::rng;
use rand_distr::{Distribution, Normal};
use std::sync::OnceLock;

const THREE: &str = "[load_spectrum]\nbins = [{torque_nm = 40, input_speed_hz = 20, share = 0.5}, {torque_nm = 60, input_speed_hz = 30, share = 0.3}, {torque_nm = 90, input_speed_hz = 45, share = 0.2}]\n";

/// A heavier duty: every torque x 1.3, more time at the top bin.
fn heavier() -> LoadSpectrumSection {
    let c = load_case(
        "[load_spectrum]\nbins = [{torque_nm = 52, input_speed_hz = 20, share = 0.3}, {torque_nm = 78, input_speed_hz = 30, share = 0.3}, {torque_nm = 117, input_speed_hz = 45, share = 0.4}]\n",
        &[],
    )
    .unwrap();
    c.load_spectrum.unwrap()
}

struct Fixture {
    case: Case,
    prior: Prior,
    surrogate: Surrogate,
    truth: Trajectory,
    k_true: f64,
}

const OBS_CYCLES: [f64; 10] = [4e3, 8e3, 12e3, 16e3, 20e3, 24e3, 28e3, 32e3, 36e3, 40e3];

fn fixture() -> &'static Fixture {
    static F: OnceLock<Fixture> = OnceLock::new();
    F.get_or_init(|| {
        let mut case = load_case(THREE, &[]).unwrap();
        let k0 = case.wear.coefficient_m2_per_n;
        case.calibration.wear_coefficient_min_m2_per_n = Some(k0 / 10.0);
        case.calibration.wear_coefficient_max_m2_per_n = Some(3.0 * k0);
        let prior = Prior::from_case(&case).unwrap();
        let surrogate = Surrogate::build(&case, &prior, 4e4, 2, &|| {}).unwrap();
        // The "true" gearbox wears 1.6 times faster than the case assumes.
        let k_true = 1.6 * k0;
        let mut t = case.clone();
        t.wear.coefficient_m2_per_n = k_true;
        let truth = run_trajectory(&t, None, 4e4).unwrap();
        Fixture {
            case,
            prior,
            surrogate,
            truth,
            k_true,
        }
    })
}

/// Largest relative difference of the maximum pinion wear of `a` at N and `b` at N s.
fn wear_mismatch(a: &Trajectory, b: &Trajectory, s: f64, cycles: &[f64]) -> f64 {
    cycles
        .iter()
        .map(|c| {
            let (x, y) = (
                a.value(Quantity::MaxWearPinion, *c).unwrap(),
                b.value(Quantity::MaxWearPinion, c * s).unwrap(),
            );
            (x - y).abs() / x
        })
        .fold(0.0, f64::max)
}

#[test]
fn under_a_spectrum_the_trajectory_depends_on_k_n_only() {
    // Every bin's wear per cycle is proportional to k, so the spectrum's is, and the
    // blocks are cut by the threshold on it: a run at 2 k read at N/2 equals one at k at
    // N up to the rounding of blocks to whole cycles (single point: 3.2e-6 measured).
    let f = fixture();
    let mut c2 = f.case.clone();
    c2.wear.coefficient_m2_per_n = 2.0 * f.k_true;
    let double = run_trajectory(&c2, None, 2e4).unwrap();
    let d = wear_mismatch(&f.truth, &double, 0.5, &OBS_CYCLES);
    println!("spectrum k N invariance: {d:.2e}");
    assert!(d < 2e-5, "{d:e}");
}

#[test]
fn with_a_change_of_duty_k_n_holds_with_the_switch_scaled_too() {
    // The switch to the future duty is at N0 cycles: scaling k by 2 and every cycle count
    // (N0 and N) by 1/2 gives the same trajectory; keeping N0 does not.
    let f = fixture();
    let future = |n0| FutureDuty {
        from_cycles: n0,
        spectrum: heavier(),
    };
    let mut c = f.case.clone();
    c.wear.coefficient_m2_per_n = f.k_true;
    let a = run_duty_trajectory(&c, Some(&future(2e4)), None, 4e4).unwrap();
    c.wear.coefficient_m2_per_n = 2.0 * f.k_true;
    let b = run_duty_trajectory(&c, Some(&future(1e4)), None, 2e4).unwrap();
    let wrong = run_duty_trajectory(&c, Some(&future(2e4)), None, 2e4).unwrap();
    let d = wear_mismatch(&a, &b, 0.5, &OBS_CYCLES);
    let w = wear_mismatch(&a, &wrong, 0.5, &OBS_CYCLES);
    println!("change of duty: scaled switch {d:.2e}, unscaled {w:.2e}");
    assert!(d < 2e-5, "{d:e}");
    assert!(w > 100.0 * d, "{w:e}");
    // The heavier duty wears faster than the old one continued.
    let old = &f.truth;
    let rate = |t: &Trajectory| {
        t.value(Quantity::MaxWearPinion, 4e4).unwrap()
            - t.value(Quantity::MaxWearPinion, 2e4).unwrap()
    };
    assert!(rate(&a) > 1.5 * rate(old), "{} {}", rate(&a), rate(old));
    // Before the switch it is the old duty's run.
    let (x, y) = (
        a.value(Quantity::MaxWearPinion, 1.6e4).unwrap(),
        old.value(Quantity::MaxWearPinion, 1.6e4).unwrap(),
    );
    assert_eq!(x, y);
}

#[test]
fn the_surrogate_of_a_change_of_duty_follows_true_runs() {
    // A k between two nodes of the future chain (ratio 2^(1/4)): the surrogate against a
    // true two-phase run, over the whole horizon.
    let f = fixture();
    let fut = FutureDuty {
        from_cycles: 2e4,
        spectrum: heavier(),
    };
    let k = f.k_true;
    let mut p = Prior::spanning(&[[0.9 * k, 1.0, 60.0], [1.2 * k, 1.0, 60.0]]);
    p.params[0].log = true;
    // On the paper's contact model, where the bound below was measured (with corner
    // contact the error came out 3.5e-4 of the depth when this was written: open,
    // issue 32).
    let mut base = f.case.clone();
    base.contact.path = gearwear::config::case::ContactPathModel::Nominal;
    let s = Surrogate::build_for_duty(&base, Some(&fut), &p, 4e4, 2, &|| {}).unwrap();
    let theta = [1.05 * k, 1.0, 60.0];
    let mut c = base.clone();
    c.wear.coefficient_m2_per_n = theta[0];
    let truth = run_duty_trajectory(&c, Some(&fut), None, 4e4).unwrap();
    let cycles: Vec<f64> = (1..=40).map(|i| 1e3 * i as f64).collect();
    let e = s
        .max_error_against(&truth, &theta, Quantity::MaxWearPinion, &cycles)
        .unwrap();
    let scale = truth.value(Quantity::MaxWearPinion, 4e4).unwrap();

    println!(
        "future-duty surrogate: {e:.3e} um of {scale:.3} um ({} nodes)",
        s.chains[0].k.len()
    );
    // Measured 6.4e-4 um (6e-5 of the depth, after the switch: the second-order error of
    // the interpolation in k); 3e-4 of the depth leaves a factor 5, and is far below the
    // 0.2 um noise of a wear measurement.
    assert!(e < 3e-4 * scale, "{e} of {scale}");
    // The life from it agrees with the true run's to the same order.
    let (a, b) = (s.cycles_to_wear(&theta, 8.0), truth.cycles_to_wear(8.0));
    match (a, b) {
        (Crossing::Reached(x), Crossing::Reached(y)) => {
            assert!((x - y).abs() < 1e-3 * y, "{x} {y}")
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn calibrated_under_a_spectrum_the_90_percent_interval_covers_k() {
    // 30 replicates of noise on one true run under the spectrum (wear sigma 0.2 um,
    // vibration at the monitoring bin sigma 0.02 mm/s, given): the 90 % interval must
    // cover the true k in at least 80 % (24) of them. At a true 90 %, P(< 24 of 30) ~ 3 %.
    let f = fixture();
    let evidence = [
        (Quantity::MaxWearPinion, 0.2),
        (Quantity::VelocityRms, 0.02),
    ];
    let covered = (0..30u64)
        .filter(|seed| {
            let mut r = rng::stream(200 + seed, 0);
            let obs = Observations {
                series: evidence
                    .iter()
                    .map(|(q, sigma)| {
                        let noise = Normal::new(0.0, *sigma).unwrap();
                        Series {
                            quantity: *q,
                            cycles: OBS_CYCLES.to_vec(),
                            values: OBS_CYCLES
                                .iter()
                                .map(|c| f.truth.value(*q, *c).unwrap() + noise.sample(&mut r))
                                .collect(),
                            sigma: Some(vec![*sigma; OBS_CYCLES.len()]),
                        }
                    })
                    .collect(),
            };
            let set = CalibrationSettings {
                samples: 200,
                seed: *seed,
                grid_cells: 400,
                walkers: 32,
                steps: 2000,
            };
            let cal = calibrate(&f.prior, &obs, &f.surrogate, &set, &|| {}).unwrap();
            let p = &cal.summary[0];
            p.ci05 <= f.k_true && f.k_true <= p.ci95
        })
        .count();
    println!("coverage of the 90 % interval under the spectrum: {covered} / 30");
    assert!(covered >= 24, "{covered}");
}
