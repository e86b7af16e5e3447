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
