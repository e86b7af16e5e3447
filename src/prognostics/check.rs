//! The surrogate checked against true wear runs (the case's own block scheme) at a few
//! points of the posterior, as every `calibrate` and `predict` run reports it.

use super::band::{cycles_grid, Band};
use super::calibrate::Calibration;
use super::forward::{run_duty_trajectory, run_trajectory, Crossing};
use super::observations::Observations;
use super::predict::{fan_quantities, PredictSettings, SampleOutcome};
use super::prior::{apply, Theta, PARAMETERS};
use super::quantity::Quantity;
use super::surrogate::Surrogate;
use crate::config::Case;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// Posterior quantiles at which the checks are made, in order of use.
const CHECK_QUANTILES: [f64; 3] = [0.5, 0.05, 0.95];

/// One observed quantity: the largest error at the observed cycle counts, and its largest
/// ratio to the spread of the posterior predictive distribution of an observation there
/// (model spread over the posterior and noise scale, in quadrature).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct ObservableCheck {
    pub quantity: String,
    pub max_abs_error: f64,
    pub max_error_over_predictive_sd: f64,
}

/// A true run at one point of the posterior against the surrogate.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct CalibrationCheck {
    pub posterior_quantile_of_k: f64,
    /// [k m^2/N, roughness factor, load torque N m].
    pub theta: Theta,
    pub true_run_failure: Option<String>,
    pub quantities: Vec<ObservableCheck>,
}

/// Standard deviations of a measurement's noise above its value that the posterior's
/// 95 % of k is taken not to exceed at that measurement ([`observed_depth_bound_m`]).
const DEPTH_SIGMAS: f64 = 3.0;

/// The deepest wear, m, that the true runs of [`check_calibration`] (at the posterior's
/// 5, 50 and 95 % of k, to the last observation's cycles H) can reach as the wear
/// measurements with a given noise bound it. For each member (pinion, gear) the largest
/// (y_i + 3 sigma_i) H / c_i over its wear series whose `sigma_` column is given, for the
/// measurements at c_i > 0. Why: a posterior fits the wear it was given (Gaussian noise of
/// known sigma: a model value 3 sigma above a measurement costs 4.5 in log-likelihood at
/// that point alone), so the runs at its quantiles wear no deeper at c_i; and a run's
/// deepest wear is concave in its cycles (its rate falls as the pair runs in,
/// `study::budget::running_in`), so from c_i to H it grows at most by H / c_i. The wear
/// loop ends its blocks on the deeper member, so a member not measured is bounded by the
/// measured one times the ratio of their nominal wear per cycle (`member_rates`:
/// quasi-static Archard at the nominal load, the pinion's and the gear's, m per pinion
/// cycle). None (nothing bounds the posterior before it is computed: the run budget then
/// counts the runs at the prior's largest k) when no wear series has its noise given
/// (indicators alone, or a wear series whose noise is inferred: its scale free, a broad
/// posterior is possible), for a gear train or a planetary set (an unmeasured stage or
/// member may wear deeper), or when a nominal rate is not positive. Not a bound when the
/// observations contradict each other (another series pulls the posterior away from the
/// wear measured: the fit check reports it).
pub(crate) fn observed_depth_bound_m(
    case: &Case,
    obs: &Observations,
    member_rates: impl Fn() -> Option<(f64, f64)>,
) -> Option<f64> {
    if !case.stage.is_empty() || case.planetary.is_some() {
        return None;
    }
    let h = obs.max_cycles();
    let member = |q: Quantity| {
        obs.series
            .iter()
            .filter(|s| s.quantity == q)
            .filter_map(|s| {
                let sigma = s.sigma.as_ref()?;
                (0..s.values.len())
                    .filter(|&i| s.cycles[i] > 0.0)
                    .map(|i| {
                        (s.values[i] + DEPTH_SIGMAS * sigma[i]).max(0.0)
                            * (h / s.cycles[i]).max(1.0)
                    })
                    .reduce(f64::max)
            })
            .reduce(f64::max)
    };
    let (pinion, gear) = (
        member(Quantity::MaxWearPinion),
        member(Quantity::MaxWearGear),
    );
    if pinion.is_none() && gear.is_none() {
        return None;
    }
    let (rp, rg) = member_rates().filter(|(p, g)| *p > 0.0 && *g > 0.0)?;
    let pinion = pinion.or(gear.map(|g| g * rp / rg))?;
    let gear = gear.unwrap_or(pinion * rg / rp);
    Some(pinion.max(gear) * 1e-6).filter(|d| d.is_finite())
}

/// The parameters at posterior quantile p of k, the others at their medians.
pub(crate) fn theta_at_k_quantile(cal: &Calibration, p: f64) -> Theta {
    let mut t = cal.prior.params.map(|x| x.lo);
    for s in &cal.summary {
        let i = PARAMETERS
            .iter()
            .position(|x| *x == s.parameter)
            .unwrap_or(0);
        t[i] = match (i, p) {
            (0, p) if p < 0.5 => s.ci05,
            (0, p) if p > 0.5 => s.ci95,
            _ => s.median,
        };
    }
    t
}

/// Check a calibration at its posterior median, 5 % and 95 % of k (the first `n`).
/// `noise`: the noise scale per quantity (`likelihood::noise_scales`).
pub(crate) fn check_calibration(
    case: &Case,
    sur: &Surrogate,
    cal: &Calibration,
    obs: &Observations,
    noise: &[(Quantity, bool, f64)],
    n: usize,
) -> Vec<CalibrationCheck> {
    let ps: Vec<f64> = CHECK_QUANTILES.into_iter().take(n).collect();
    ps.par_iter()
        .filter_map(|p| {
            let theta = theta_at_k_quantile(cal, *p);
            let c = apply(case, &theta);
            let mut truth = run_trajectory(&c, None, obs.max_cycles()).ok()?;
            let observed: Vec<Quantity> = obs.series.iter().map(|s| s.quantity).collect();
            super::forward::attach(&mut truth, &c, &observed).ok()?;
            let quantities = obs
                .series
                .iter()
                .map(|s| {
                    let sigma = noise
                        .iter()
                        .find(|x| x.0 == s.quantity)
                        .map_or(0.0, |x| x.2);
                    let (mut err_max, mut ratio_max) = (0.0_f64, 0.0_f64);
                    for c in &s.cycles {
                        let members: Vec<Vec<Option<f64>>> = cal
                            .samples
                            .iter()
                            .map(|t| vec![sur.value(s.quantity, t, *c)])
                            .collect();
                        let sd = Band::spread(&members, 0).hypot(sigma);
                        let err = sur
                            .max_error_against(&truth, &theta, s.quantity, &[*c])
                            .unwrap_or(f64::NAN);
                        let ratio = if err == 0.0 { 0.0 } else { err / sd };
                        err_max = err_max.max(err);
                        if ratio.is_nan() || ratio > ratio_max {
                            ratio_max = ratio;
                        }
                    }
                    ObservableCheck {
                        quantity: s.quantity.name().into(),
                        max_abs_error: err_max,
                        max_error_over_predictive_sd: ratio_max,
                    }
                })
                .collect();
            Some(CalibrationCheck {
                posterior_quantile_of_k: *p,
                theta,
                true_run_failure: truth.failure,
                quantities,
            })
        })
        .collect()
}

/// Largest ratio of error to predictive spread over all checks.
pub(crate) fn worst_ratio(checks: &[CalibrationCheck]) -> f64 {
    checks
        .iter()
        .flat_map(|c| c.quantities.iter().map(|q| q.max_error_over_predictive_sd))
        .fold(0.0, f64::max)
}

/// A true run at one sample of a prediction against the surrogate.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct PredictionCheck {
    /// The parameters of the sample checked.
    pub theta: Theta,
    /// Cycles to the wear limit the surrogate predicts.
    pub life_surrogate: Crossing,
    /// Cycles to the wear limit of the true wear study.
    pub life_true: Crossing,
    /// Largest |surrogate - true| over the fan grid per fan quantity (None: no overlap).
    pub max_abs_error: Vec<(String, Option<f64>)>,
    /// Why the true run stopped early, if it did.
    pub true_run_failure: Option<String>,
}

impl PredictionCheck {
    /// |surrogate - true| of the cycles to the limit, when both reach it.
    pub(crate) fn life_error(&self) -> Option<f64> {
        match (self.life_surrogate, self.life_true) {
            (Crossing::Reached(a), Crossing::Reached(b)) => Some((a - b).abs()),
            _ => None,
        }
    }
}

/// Check a prediction at the samples nearest the 50/5/95 % of the life (of k if no
/// sample reaches the limit), the first `n` of them.
pub(crate) fn check_prediction(
    case: &Case,
    sur: &Surrogate,
    outcomes: &[SampleOutcome],
    set: &PredictSettings,
    n: usize,
) -> Vec<PredictionCheck> {
    let mut by: Vec<(f64, Theta)> = outcomes
        .iter()
        .filter_map(|o| match o.life {
            Crossing::Reached(c) => Some((c, o.theta)),
            _ => None,
        })
        .collect();
    if by.is_empty() {
        by = outcomes.iter().map(|o| (o.theta[0], o.theta)).collect();
    }
    if by.is_empty() {
        return Vec::new();
    }
    by.sort_by(|a, b| a.0.total_cmp(&b.0));
    let picks: Vec<Theta> = CHECK_QUANTILES
        .iter()
        .take(n)
        .map(|p| by[((by.len() - 1) as f64 * p).round() as usize].1)
        .collect();
    let grid = cycles_grid(set.cycles, set.grid_points);
    let within = |c: Crossing| match c {
        Crossing::Reached(x) if x > set.cycles => Crossing::NotReached,
        c => c,
    };
    picks
        .par_iter()
        .filter_map(|theta| {
            let truth =
                run_duty_trajectory(&apply(case, theta), sur.future.as_ref(), None, set.cycles)
                    .ok()?;
            let max_abs_error = fan_quantities(set.stages)
                .iter()
                .map(|q| {
                    let e = grid
                        .iter()
                        .filter_map(|c| {
                            Some((sur.value(*q, theta, *c)? - truth.value(*q, *c)?).abs())
                        })
                        .reduce(f64::max);
                    (q.name().to_string(), e)
                })
                .collect();
            Some(PredictionCheck {
                theta: *theta,
                life_surrogate: within(sur.cycles_to_wear(theta, set.limit_um)),
                life_true: within(truth.cycles_to_wear(set.limit_um)),
                max_abs_error,
                true_run_failure: truth.failure,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::prognostics::observations::Series;

    fn series(quantity: Quantity, sigma: Option<Vec<f64>>) -> Series {
        Series {
            quantity,
            cycles: vec![0.0, 1e4, 2e4],
            values: vec![0.0, 2.0, 3.0],
            sigma,
        }
    }

    #[test]
    fn the_wear_measured_with_its_noise_bounds_the_check_runs() {
        // Wear to 4e4 cycles (the velocity's last reading) measured at 1e4 and 2e4 with
        // sigma 0.1 um: (2.3 um) x 4 and (3.3 um) x 2, the larger 9.2 um (the reading at
        // 0 cycles bounds nothing).
        let case = Case::default();
        let mut vib = series(Quantity::VelocityRms, None);
        vib.cycles[2] = 4e4;
        let wear = series(Quantity::MaxWearPinion, Some(vec![0.1; 3]));
        let obs = Observations {
            series: vec![vib.clone(), wear.clone()],
        };
        // The gear wears half as fast as the pinion per pinion cycle: the pinion's bound.
        let d = observed_depth_bound_m(&case, &obs, || Some((2.0, 1.0))).unwrap();
        assert!((d - 9.2e-6).abs() < 1e-15, "{d}");
        // The gear wearing 3 times as fast: the unmeasured gear bounds it (review finding:
        // the pinion's series alone undercounted the runs).
        let d = observed_depth_bound_m(&case, &obs, || Some((1.0, 3.0))).unwrap();
        assert!((d - 27.6e-6).abs() < 1e-14, "{d}");
        // Only the gear measured, the pinion 2 times as fast: 9.2 x 2.
        let gear_only = Observations {
            series: vec![
                vib.clone(),
                series(Quantity::MaxWearGear, Some(vec![0.1; 3])),
            ],
        };
        let d = observed_depth_bound_m(&case, &gear_only, || Some((2.0, 1.0))).unwrap();
        assert!((d - 18.4e-6).abs() < 1e-14, "{d}");
        // Indicators alone, or wear of inferred noise, or no rates: nothing bounds.
        let free = series(Quantity::MaxWearPinion, None);
        for s in [vec![vib.clone()], vec![vib.clone(), free]] {
            let o = Observations { series: s };
            assert_eq!(observed_depth_bound_m(&case, &o, || Some((1.0, 1.0))), None);
        }
        assert_eq!(observed_depth_bound_m(&case, &obs, || None), None);
        // A gear train: an unmeasured stage may wear deeper.
        let train = crate::config::load::load_case(
            include_str!("../../examples/two_stage_reducer.toml"),
            &[],
        )
        .unwrap();
        assert!(!train.stage.is_empty());
        assert_eq!(
            observed_depth_bound_m(&train, &obs, || Some((1.0, 1.0))),
            None
        );
    }
}
