//! The noise model: how likely the observations are for given parameters.
//!
//! Each observed value y_i of quantity q at c_i cycles is the model's value f_q(c_i; theta)
//! plus independent Gaussian noise.
//! - With `sigma_<q>` given: log L_q = -1/2 sum_i ((y_i - f_i) / sigma_i)^2 (+ const).
//! - Without: the per-quantity sigma is unknown, with Jeffreys' prior p(sigma) ~ 1/sigma,
//!   and is integrated out: int sigma^(-n-1) exp(-S / (2 sigma^2)) d sigma ~ S^(-n/2), so
//!   log L_q = -(n/2) ln S with S = sum_i (y_i - f_i)^2 (a multivariate Student-t form;
//!   Gelman et al., Bayesian Data Analysis, 3rd ed., section 3.2). It needs n >= 2.
//!
//! Quantities add their log-likelihoods (independent noise).

use super::observations::Observations;
use super::quantity::Quantity;

/// log L of the observations given the model's values `f(q, cycles)`; None when the
/// forward model has no value (a failed run).
pub fn log_likelihood(obs: &Observations, f: &dyn Fn(Quantity, f64) -> Option<f64>) -> Option<f64> {
    let mut ll = 0.0;
    for s in &obs.series {
        let mut sum_sq = 0.0;
        for (i, (c, y)) in s.cycles.iter().zip(&s.values).enumerate() {
            let r = y - f(s.quantity, *c)?;
            sum_sq += match &s.sigma {
                Some(sig) => (r / sig[i]).powi(2),
                None => r * r,
            };
        }
        ll += match &s.sigma {
            Some(_) => -0.5 * sum_sq,
            // A perfect fit (S = 0) would be +inf: floor S at the smallest normal f64.
            None => -0.5 * s.values.len() as f64 * sum_sq.max(f64::MIN_POSITIVE).ln(),
        };
    }
    Some(ll)
}

/// Noise scale per quantity at the given model values: the given sigmas' RMS, or the
/// RMS residual sqrt(S / n) (the mode of the marginal posterior of sigma is
/// sqrt(S / (n + 1)); sqrt(S / n) is the usual estimate).
pub fn noise_scales(
    obs: &Observations,
    f: &dyn Fn(Quantity, f64) -> Option<f64>,
) -> Vec<(Quantity, bool, f64)> {
    obs.series
        .iter()
        .map(|s| {
            let n = s.values.len() as f64;
            match &s.sigma {
                Some(sig) => (
                    s.quantity,
                    true,
                    (sig.iter().map(|x| x * x).sum::<f64>() / n).sqrt(),
                ),
                None => {
                    let ss: f64 = s
                        .cycles
                        .iter()
                        .zip(&s.values)
                        .map(|(c, y)| f(s.quantity, *c).map_or(f64::NAN, |v| (y - v).powi(2)))
                        .sum();
                    (s.quantity, false, (ss / n).sqrt())
                }
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::prognostics::observations::Series;

    fn obs(sigma: Option<Vec<f64>>) -> Observations {
        Observations {
            series: vec![Series {
                quantity: Quantity::DteMax,
                cycles: vec![0.0, 1.0],
                values: vec![1.0, 3.0],
                sigma,
            }],
        }
    }

    #[test]
    fn gaussian_and_marginal_forms() {
        // Model value 2 everywhere: residuals -1, +1.
        let f = |_: Quantity, _: f64| Some(2.0);
        // Known sigma 0.5: -1/2 (4 + 4) = -4.
        let ll = log_likelihood(&obs(Some(vec![0.5, 0.5])), &f).unwrap();
        assert!((ll + 4.0).abs() < 1e-12);
        // Unknown sigma: -(2/2) ln 2.
        let ll = log_likelihood(&obs(None), &f).unwrap();
        assert!((ll + 2f64.ln()).abs() < 1e-12);
        // A failed forward run has no likelihood.
        assert_eq!(log_likelihood(&obs(None), &|_, _| None), None);
        let s = noise_scales(&obs(None), &f);
        assert!((s[0].2 - 1.0).abs() < 1e-12 && !s[0].1);
    }
}
