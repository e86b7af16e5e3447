//! Prognostics (issue 12) against independent facts: the k x N invariance of Archard
//! wear, the surrogate against true runs, recovery and coverage of a known wear
//! coefficient, the prior returned when the data say nothing, the deterministic limit,
//! the 1/sqrt(N) convergence of Monte Carlo percentiles, and thread-count independence.
//!
//! One set of forward runs (a reference run and a true run of the paper's case) serves
//! every test (`fixture`), so the file costs a few seconds.

use crate::config::Case;
use crate::prognostics::calibrate::{calibrate, Calibration, CalibrationSettings};
use crate::prognostics::check::theta_at_k_quantile;
use crate::prognostics::fit_check::{fit_check, normal_quantile, FitCheck};
use crate::prognostics::forward::{run_trajectory, Trajectory};
use crate::prognostics::likelihood::log_likelihood;
use crate::prognostics::likelihood::noise_scales;
use crate::prognostics::mcmc::{ensemble_sample, McmcSettings};
use crate::prognostics::observations::{Observations, Series};
use crate::prognostics::predict::{
    run_sample, Forward, LifeSummary, PredictSettings, SampleSource,
};
use crate::prognostics::prior::{Prior, Theta};
use crate::prognostics::stats::{
    autocorrelation_time, ks_critical_1pct, ks_statistic, mean, quantile, std_dev,
};
use crate::prognostics::{Quantity, Surrogate};
use crate::rng;
use rand_distr::{Distribution, Normal};
use std::sync::OnceLock;

/// The paper's case with the prior of k narrowed to [k0 / 10, 3 k0] (the default four
/// decades would carry the reference run past the integrator's present limit; the
/// solver work removes that).
struct Fixture {
    case: Case,
    prior: Prior,
    surrogate: Surrogate,
    /// A true wear study of the case (its own block scheme) at k0 to 4e4 cycles.
    truth: Trajectory,
    k0: f64,
}

/// Cycle counts of the synthetic observations.
const OBS_CYCLES: [f64; 10] = [4e3, 8e3, 12e3, 16e3, 20e3, 24e3, 28e3, 32e3, 36e3, 40e3];

fn fixture() -> &'static Fixture {
    static F: OnceLock<Fixture> = OnceLock::new();
    F.get_or_init(|| {
        let mut case = Case::default();
        // The paper's nominal path: its wear grows linearly in the cycles (the wear rate
        // moves 0.03 % over 4e4 cycles), the premise of the invariance and model-misfit
        // tests below. Under corner contact the tip corners' running-in wear makes the
        // rate fall ~30 % over the same cycles (docs/MODEL.md 4.2), which the block
        // scheme's discretisation and a square-root law then partly mimic.
        case.contact.path = crate::config::case::ContactPathModel::Nominal;
        let k0 = case.wear.coefficient_m2_per_n;
        case.calibration.wear_coefficient_min_m2_per_n = Some(k0 / 10.0);
        case.calibration.wear_coefficient_max_m2_per_n = Some(3.0 * k0);
        let prior = Prior::from_case(&case).unwrap();
        let surrogate = Surrogate::build(&case, &prior, 4e4, 2, &|| {}).unwrap();
        let truth = run_trajectory(&case, None, 4e4).unwrap();
        Fixture {
            case,
            prior,
            surrogate,
            truth,
            k0,
        }
    })
}

/// Observations of `quantities` from the true run at OBS_CYCLES plus Gaussian noise of
/// the given sigma (replicate `seed`); `known`: whether the sigma column is given.
fn synthetic(quantities: &[(Quantity, f64)], seed: u64, known: bool) -> Observations {
    let f = fixture();
    let mut r = rng::stream(seed, 0);
    Observations {
        series: quantities
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
                    sigma: known.then(|| vec![*sigma; OBS_CYCLES.len()]),
                }
            })
            .collect(),
    }
}

fn settings(seed: u64) -> CalibrationSettings {
    CalibrationSettings {
        samples: 2000,
        seed,
        grid_cells: 400,
        walkers: 32,
        steps: 2000,
    }
}

const EVIDENCE: [(Quantity, f64); 2] = [
    (Quantity::MaxWearPinion, 0.2),
    (Quantity::VelocityRms, 0.02),
];

#[test]
fn k_times_cycles_invariance_of_true_runs() {
    // Archard wear per cycle is proportional to k, and the response depends only on the
    // wear state: a true run at 2 k read at N/2 cycles must equal one at k read at N, up
    // to the rounding of each block to whole cycles (both runs are cut by the wear
    // threshold here, ~3400 and ~1700 cycles a block).
    let f = fixture();
    let mut c2 = f.case.clone();
    c2.wear.coefficient_m2_per_n = 2.0 * f.k0;
    let double = run_trajectory(&c2, None, 2e4).unwrap();
    let (mut wear_rel, mut vib_abs) = (0.0_f64, 0.0_f64);
    for c in OBS_CYCLES {
        let a = f.truth.value(Quantity::MaxWearPinion, c).unwrap();
        let b = double.value(Quantity::MaxWearPinion, c / 2.0).unwrap();
        wear_rel = wear_rel.max((a / b - 1.0).abs());
        let a = f.truth.value(Quantity::VelocityRms, c).unwrap();
        let b = double.value(Quantity::VelocityRms, c / 2.0).unwrap();
        vib_abs = vib_abs.max((a - b).abs());
    }
    println!("invariance, threshold-cut blocks: wear rel {wear_rel:.2e}, RMS velocity abs {vib_abs:.2e} mm/s");
    // Rounding loses < 1 cycle per block of ~1700: < 6e-4 relative in exposure.
    assert!(wear_rel < 1e-3, "{wear_rel}");
    // The velocity RMS falls ~0.08 mm/s per um of wear (~0.6 mm/s over the 40k cycles):
    // a 1e-3 relative exposure error moves it by < 1e-3 mm/s.
    assert!(vib_abs < 1e-3, "{vib_abs}");

    // Blocks limited by wear.block_cycles instead (k0/10: the threshold would allow
    // ~34000 cycles, the block holds 1e4): finer steps than the threshold's, so the
    // invariance holds only to the block scheme's own discretisation error.
    let mut c10 = f.case.clone();
    c10.wear.coefficient_m2_per_n = f.k0 / 10.0;
    let tenth = run_trajectory(&c10, None, 4e5).unwrap();
    let (mut wear_rel, mut vib_abs) = (0.0_f64, 0.0_f64);
    for c in OBS_CYCLES {
        let a = f.truth.value(Quantity::MaxWearPinion, c).unwrap();
        let b = tenth.value(Quantity::MaxWearPinion, 10.0 * c).unwrap();
        wear_rel = wear_rel.max((a / b - 1.0).abs());
        let a = f.truth.value(Quantity::VelocityRms, c).unwrap();
        let b = tenth.value(Quantity::VelocityRms, 10.0 * c).unwrap();
        vib_abs = vib_abs.max((a - b).abs());
    }
    println!("invariance, block-limited at k0/10: wear rel {wear_rel:.2e}, RMS velocity abs {vib_abs:.2e} mm/s");
    // Measured 5.9e-3 and 1.1e-3 mm/s (docs/PROGNOSTICS.md): the reason the surrogate
    // keeps reference runs along k in this range. Bound: 1 % / 0.01 mm/s.
    assert!(wear_rel < 1e-2 && vib_abs < 1e-2, "{wear_rel} {vib_abs}");
}

/// Posterior mean and sd of ln k from log-likelihoods at equally spaced ln k (uniform
/// prior in ln k): a plain quadrature, the same for both forward models compared.
fn moments(ln_k: &[f64], ll: &[f64]) -> (f64, f64) {
    let max = ll.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let w: Vec<f64> = ll.iter().map(|l| (l - max).exp()).collect();
    let sw: f64 = w.iter().sum();
    let m = ln_k.iter().zip(&w).map(|(x, w)| x * w).sum::<f64>() / sw;
    let v = ln_k
        .iter()
        .zip(&w)
        .map(|(x, w)| (x - m).powi(2) * w)
        .sum::<f64>()
        / sw;
    (m, v.sqrt())
}

#[test]
fn surrogate_error_is_below_a_tenth_of_the_posterior_spread() {
    // The posterior of ln k computed with true wear runs (one per quadrature point, the
    // case's own block scheme) and with the surrogate, on the same points and the same
    // observations: the means must agree to a tenth of the posterior sd.
    use rayon::prelude::*;
    let f = fixture();
    for (name, evidence) in [
        ("wear", vec![EVIDENCE[0]]),
        (
            "vibration",
            vec![
                (Quantity::VelocityRms, 0.02),
                (Quantity::MeshHarmonic(1), 0.02),
            ],
        ),
    ] {
        let obs = synthetic(&evidence, 1, true);
        let cal = calibrate(&f.prior, &obs, &f.surrogate, &settings(1), &|| {}).unwrap();
        let ks: Vec<f64> = cal.samples.iter().map(|t| t[0].ln()).collect();
        let (lo, hi) = (quantile(&ks, 0.0005), quantile(&ks, 0.9995));
        // 11 points over +-3.3 sd: the same quadrature for both models, so its own error
        // (small for a near-Gaussian posterior at 0.66 sd spacing) cancels in the comparison.
        let ln_k: Vec<f64> = (0..11).map(|i| lo + (hi - lo) * i as f64 / 10.0).collect();
        let truth: Vec<Trajectory> = ln_k
            .par_iter()
            .map(|x| {
                let mut c = f.case.clone();
                c.wear.coefficient_m2_per_n = x.exp();
                run_trajectory(&c, None, 4e4).unwrap()
            })
            .collect();
        let ll_true: Vec<f64> = truth
            .iter()
            .map(|t| log_likelihood(&obs, &|q, c| t.value(q, c)).unwrap())
            .collect();
        let ll_sur: Vec<f64> = ln_k
            .iter()
            .map(|x| {
                let th = [x.exp(), 1.0, 60.0];
                log_likelihood(&obs, &|q, c| f.surrogate.value(q, &th, c)).unwrap()
            })
            .collect();
        let (mt, st) = moments(&ln_k, &ll_true);
        let (ms, ss) = moments(&ln_k, &ll_sur);
        println!("{name}: posterior of ln k, true runs {mt:.5} +- {st:.5}, surrogate {ms:.5} +- {ss:.5}: error / spread {:.4}", (ms - mt).abs() / st);
        assert!((ms - mt).abs() < 0.1 * st, "{name}");
        // The sd agrees too (same tenth).
        assert!((ss - st).abs() < 0.1 * st, "{name}");
    }
}

#[test]
fn surrogate_between_reference_runs_in_the_block_limited_range() {
    // k between two reference runs of the chain, where the blocks are limited by
    // wear.block_cycles (the invariance does not hold exactly there): against a true run.
    let f = fixture();
    let chain = &f.surrogate.chains[0];
    assert!(chain.k.len() >= 2, "{:?}", chain.k);
    let k = (chain.k[0] * chain.k[1]).sqrt();
    let mut c = f.case.clone();
    c.wear.coefficient_m2_per_n = k;
    let horizon = 4e4; // the surrogate's horizon
    let truth = run_trajectory(&c, None, horizon).unwrap();
    let th = [k, 1.0, 60.0];
    let cycles: Vec<f64> = (1..=10).map(|i| horizon * i as f64 / 10.0).collect();
    let w = f
        .surrogate
        .max_error_against(&truth, &th, Quantity::MaxWearPinion, &cycles)
        .unwrap();
    let v = f
        .surrogate
        .max_error_against(&truth, &th, Quantity::VelocityRms, &cycles)
        .unwrap();
    let wear_end = truth.value(Quantity::MaxWearPinion, horizon).unwrap();
    println!("block-limited k = {k:.3e}: wear error {w:.2e} µm of {wear_end:.2} µm, RMS velocity error {v:.2e} mm/s");
    // Without the k axis the error was that of the invariance test (5.9e-3 relative);
    // interpolating in ln k between runs that bracket k must do far better: 1e-3.
    assert!(w < 1e-3 * wear_end, "{w}");
    assert!(v < 1e-3, "{v}");
}

#[test]
fn credible_intervals_cover_the_truth() {
    // 50 replicates of noise (different seeds) on the same true run, with the sigma given
    // and with it inferred: a calibrated 90 % interval covers the true k in ~90 % of them;
    // the issue asks at least 80 %. (For 50 replicates at a true 90 %, P(< 40) ~ 2 %.)
    let f = fixture();
    for known in [true, false] {
        let covered = (0..50)
            .filter(|seed| {
                let obs = synthetic(&EVIDENCE, 100 + seed, known);
                let mut s = settings(*seed);
                s.samples = 200;
                let cal = calibrate(&f.prior, &obs, &f.surrogate, &s, &|| {}).unwrap();
                let p = &cal.summary[0];
                p.ci05 <= f.k0 && f.k0 <= p.ci95
            })
            .count();
        println!(
            "coverage of the 90 % interval, sigma {}: {covered} / 50",
            if known { "given" } else { "inferred" }
        );
        assert!(covered >= 40, "{covered}");
    }
}

#[test]
fn without_information_the_posterior_is_the_prior() {
    // A wear measurement with sigma 1e9 um says nothing: the posterior samples of ln k
    // must follow the log-uniform prior (Kolmogorov-Smirnov at the 1 % level).
    let f = fixture();
    let obs = synthetic(&[(Quantity::MaxWearPinion, 1e9)], 5, true);
    let cal = calibrate(&f.prior, &obs, &f.surrogate, &settings(5), &|| {}).unwrap();
    let k: Vec<f64> = cal.samples.iter().map(|t| t[0]).collect();
    let d = ks_statistic(&k, |x| f.prior.params[0].cdf(x));
    assert!(d < ks_critical_1pct(k.len()), "D = {d}");

    // The ensemble sampler on three parameters with a flat likelihood: each marginal is
    // its uniform prior. The draws are correlated, so the test uses the effective
    // sample size.
    let mut case = Case::default();
    case.calibration.roughness_scale_min = 0.8;
    case.calibration.roughness_scale_max = 1.2;
    case.calibration.load_torque_min_nm = Some(50.0);
    case.calibration.load_torque_max_nm = Some(70.0);
    let prior = Prior::from_case(&case).unwrap();
    let s = McmcSettings {
        walkers: 32,
        steps: 1500,
        burn_in: 500,
        seed: 3,
    };
    let run = ensemble_sample(&prior, &|_| Some(0.0), &s, &|| {}).unwrap();
    for a in 0..3 {
        let c = run.coordinate(a);
        let flat: Vec<f64> = c.iter().flatten().copied().collect();
        let ess = flat.len() as f64 / autocorrelation_time(&c);
        let d = ks_statistic(&flat, |u| u.clamp(0.0, 1.0));
        assert!(
            d < ks_critical_1pct(ess as usize),
            "axis {a}: D = {d}, ESS = {ess}"
        );
    }
}

#[test]
fn point_mass_posterior_gives_the_deterministic_life() {
    // All samples at k0: every predicted life equals the cycle count at which one
    // deterministic wear study crosses the limit. That count is found independently by
    // running the study to ceil(life) and ceil(life) - 1 cycles (a run to T cycles is the
    // same run cut at T): the first is at or above the limit, the second below.
    let f = fixture();
    let limit = 3.0;
    let rows: Vec<Theta> = vec![[f.k0, 1.0, 60.0]; 4];
    let span = Prior::spanning(&rows);
    let set = PredictSettings {
        limit_um: limit,
        cycles: 5e4,
        grid_points: 11,
        seed: 1,
        samples: rows.len(),
        stages: 1,
    };
    let sur = Surrogate::build(&f.case, &span, set.cycles, 2, &|| {}).unwrap();
    let source = SampleSource::Posterior {
        rows: rows.clone(),
        resample: false,
    };
    for fw in [Forward::Surrogate(&sur), Forward::Exact(&f.case, None)] {
        let out: Vec<_> = (0..rows.len())
            .map(|i| run_sample(&fw, source.draw(i, 1), i, &set).unwrap())
            .collect();
        let life = LifeSummary::of(&out);
        let (lo, med, hi) = (life.p05.unwrap(), life.median.unwrap(), life.p95.unwrap());
        assert!(lo == med && med == hi, "{lo} {med} {hi}");
        let n = med.ceil();
        let wear_at = |total: f64| {
            let mut c = f.case.clone();
            c.wear.total_cycles = total;
            let t = run_trajectory(&c, None, total).unwrap();
            t.records.last().unwrap().wear.max_pinion_m() * 1e6
        };
        let (above, below) = (wear_at(n), wear_at(n - 1.0));
        assert!(
            above >= limit && below < limit,
            "life {med}: {below} at n-1, {above} at n"
        );
    }
}

#[test]
fn monte_carlo_percentiles_converge_at_one_over_root_n() {
    // The median life estimated from N prior samples, over 40 independent seeds: its
    // spread must fall as N^-1/2, i.e. by 4 from N = 100 to 1600. The spread of a
    // 40-seed standard deviation is ~11 % (1/sqrt(2 x 39)), the ratio's ~16 %; accept a
    // factor 1.6 (about 3 of those) either way.
    let f = fixture();
    let set = |n| PredictSettings {
        limit_um: 0.4,
        cycles: 4e4,
        grid_points: 2,
        seed: 0,
        samples: n,
        stages: 1,
    };
    let source = SampleSource::Prior(f.prior.clone());
    let fw = Forward::Surrogate(&f.surrogate);
    let spread = |n: usize| {
        let medians: Vec<f64> = (0..40_u64)
            .map(|seed| {
                let s = PredictSettings { seed, ..set(n) };
                let out: Vec<_> = (0..n)
                    .map(|i| run_sample(&fw, source.draw(i, seed), i, &s).unwrap())
                    .collect();
                let life = LifeSummary::of(&out);
                assert_eq!(
                    life.reached, n,
                    "every sample reaches 0.4 µm within 4e4 cycles"
                );
                life.median.unwrap()
            })
            .collect();
        std_dev(&medians)
    };
    let ratio = spread(100) / spread(1600);
    println!("spread of the median life, N = 100 over N = 1600: {ratio:.2} (1/sqrt(N): 4)");
    assert!((4.0 / 1.6..4.0 * 1.6).contains(&ratio), "{ratio}");
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let f = fixture();
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let sur = one.install(|| Surrogate::build(&f.case, &f.prior, 4e4, 2, &|| {}).unwrap());
    assert_eq!(sur.chains[0].k, f.surrogate.chains[0].k);
    assert_eq!(sur.chains[0].runs, f.surrogate.chains[0].runs);
    let obs = synthetic(&EVIDENCE, 9, false);
    let a = one.install(|| calibrate(&f.prior, &obs, &sur, &settings(2), &|| {}).unwrap());
    let b = calibrate(&f.prior, &obs, &f.surrogate, &settings(2), &|| {}).unwrap();
    assert_eq!(a.samples, b.samples);
    assert_eq!(
        mean(&a.samples.iter().map(|t| t[0]).collect::<Vec<_>>()),
        mean(&b.samples.iter().map(|t| t[0]).collect::<Vec<_>>())
    );
}

/// Gaussian noise without a random draw: the standard normal quantiles at (i + 0.5) / n
/// times sigma, taken in the order i = 3 j mod n (3 coprime to n = 10), so the residuals
/// do not trend with the cycle count. Their largest size, Phi^-1(0.95) = 1.645 sigma, is
/// inside the 95 % band's 1.96 sigma: the test data are fixed, and so is its outcome.
fn stratified(sigma: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|j| sigma * normal_quantile(((3 * j) % n) as f64 / n as f64 + 0.5 / n as f64))
        .collect()
}

/// Observations of `q` at OBS_CYCLES: `law(true value, cycles)` plus the stratified noise.
fn observed(q: Quantity, sigma: f64, known: bool, law: &dyn Fn(f64, f64) -> f64) -> Series {
    let f = fixture();
    let noise = stratified(sigma, OBS_CYCLES.len());
    Series {
        quantity: q,
        cycles: OBS_CYCLES.to_vec(),
        values: OBS_CYCLES
            .iter()
            .zip(&noise)
            .map(|(c, e)| law(f.truth.value(q, *c).unwrap(), *c) + e)
            .collect(),
        sigma: known.then(|| vec![sigma; OBS_CYCLES.len()]),
    }
}

/// Calibrate on `series` and check the fit, as `calibrate` does.
fn checked(series: Vec<Series>) -> (Calibration, FitCheck) {
    let f = fixture();
    let obs = Observations { series };
    let mut s = settings(11);
    s.samples = 500;
    let cal = calibrate(&f.prior, &obs, &f.surrogate, &s, &|| {}).unwrap();
    let med = theta_at_k_quantile(&cal, 0.5);
    let noise = noise_scales(&obs, &|q, c| f.surrogate.value(q, &med, c));
    let fit = fit_check(
        &obs,
        &cal.samples,
        &|q, t, c| f.surrogate.value(q, t, c),
        &noise,
    );
    (cal, fit)
}

#[test]
fn data_the_model_generated_pass_the_fit_check() {
    // Wear (sigma 0.2 um) and RMS velocity (0.02 mm/s) of the true run plus Gaussian
    // noise, the sigma given and inferred: no warning. With the given sigma every
    // residual is within 1.645 sigma of the truth, so an observation can leave the band
    // only by the fit's own shift, and a warning needs more than 4 of 20 outside or one
    // beyond 2.1 sigma (the rules at n = 20).
    for known in [true, false] {
        let series = EVIDENCE
            .iter()
            .map(|(q, s)| observed(*q, *s, known, &|v, _| v))
            .collect();
        let (_, fit) = checked(series);
        assert_eq!(fit.observations, 20);
        assert!(fit.warning.is_none(), "known {known}: {:?}", fit.warning);
        assert!(fit.outside <= 2, "known {known}: {}", fit.outside);
    }
}

#[test]
fn wear_offset_by_ten_sigma_warns_naming_how_far() {
    // The true wear plus 2 um (10 sigma). The model's wear starts at zero and grows
    // about linearly in the cycles, so the fit can only tilt it: least squares of
    // y = a c through the origin against an offset d over c_j = j c_1 (j = 1..10) moves
    // a c_1 by d sum(j) / sum(j^2) = d 55 / 385, leaving 0.857 d = 8.57 sigma at the
    // first observation; with its noise (-1.645 sigma) and less the band's 1.96 sigma
    // that is 4.97 sigma beyond it. Tolerance 1.5 sigma: the wear curve is not exactly
    // linear, the noise tilts the fit too, and the posterior's spread widens the band.
    let sigma = 0.2;
    let (_, fit) = checked(vec![observed(
        Quantity::MaxWearPinion,
        sigma,
        true,
        &|v, _| v + 10.0 * sigma,
    )]);
    let w = fit.warning.clone().expect("a warning");
    println!("{w}");
    let worst = fit.quantities[0].worst.clone().unwrap();
    assert!(
        (worst.excess_sigma - 4.97).abs() < 1.5,
        "{}",
        worst.excess_sigma
    );
    assert_eq!(worst.cycles, OBS_CYCLES[0]);
    assert!(
        w.contains(&format!("{:.1} noise sigma above", worst.excess_sigma)),
        "{w}"
    );
    assert!(w.contains("max_wear_pinion_um") && !w.contains("--"), "{w}");
}

#[test]
fn wear_of_another_law_warns() {
    // Wear growing as the square root of the cycles (running-in), equal to the true
    // wear at the last observation: at the first it is sqrt(10) = 3.2 times the linear
    // law's, a difference of ~1.3 um = 6.5 sigma that no wear coefficient removes.
    let last = OBS_CYCLES[OBS_CYCLES.len() - 1];
    let end = fixture()
        .truth
        .value(Quantity::MaxWearPinion, last)
        .unwrap();
    let (_, fit) = checked(vec![observed(
        Quantity::MaxWearPinion,
        0.2,
        true,
        &|_, c| end * (c / last).sqrt(),
    )]);
    assert!(fit.warning.is_some(), "{fit:?}");
    assert!(fit.largest_excess_sigma > fit.excess_limit_sigma, "{fit:?}");
}
