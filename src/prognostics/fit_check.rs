//! The fit check of a calibration: where each observation lies against the posterior
//! predictive distribution of an observation at its cycle count, and a warning when
//! more of them lie outside its central band than the band's coverage allows, or one
//! lies further out than Gaussian noise reaches.
//!
//! The posterior predictive distribution of observation i (quantity q, c_i cycles) is the
//! model's value over the posterior samples theta_s plus the noise model's Gaussian noise
//! (`likelihood`): the mixture p(y) = 1/S sum_s N(y; f_q(c_i; theta_s), sigma_i^2) (Gelman
//! et al., Bayesian Data Analysis, 3rd ed., section 6.3), sigma_i the observation's given
//! sigma, or the quantity's inferred noise scale (`likelihood::noise_scales`). Its central
//! `COVERAGE` band [l_i, u_i] is solved from the mixture's distribution function (no
//! random draws: the check is a function of the samples alone). An observation outside
//! lies `excess_i = (y_i - u_i) / sigma_i` (above) or `(l_i - y_i) / sigma_i` (below)
//! noise standard deviations beyond the band.
//!
//! Warning rule, both parts at false-alarm probability `FALSE_ALARM` for data the model
//! generated (the posterior's own spread widens the band and only lowers it, as does the
//! fit's pull of the predictions towards the data):
//! - **count**: of n observations, each is outside with probability 1 - COVERAGE, so the
//!   count outside is Binomial(n, 1 - COVERAGE); more than its upper FALSE_ALARM tail
//!   point (`max_outside`) warns;
//! - **distance**: one observation beyond the band by e noise sigmas, with the band's edge
//!   at least z = 1.96 sigma from the model value, has probability at most
//!   2 (1 - Phi(z + e)) per observation; over n of them (Bonferroni) that is below
//!   FALSE_ALARM for e > Phi^-1(1 - FALSE_ALARM / (2 n)) - z (`excess_limit`).
//!
//! With inferred noise the band is scaled by the residuals themselves: a misfit raises
//! the noise scale instead of leaving observations outside, so the check sees only its
//! shape (outliers among the residuals); the noise scale in the summary is then the sign.

use super::observations::Observations;
use super::prior::Theta;
use super::quantity::Quantity;
use rayon::prelude::*;
use serde::Serialize;

/// Central probability of the predictive band.
pub(crate) const COVERAGE: f64 = 0.95;
/// Probability that data the model generated raise the warning, per rule.
pub(crate) const FALSE_ALARM: f64 = 1e-3;
/// Beyond this many sigma from a mixture member its normal density and tail vanish in
/// double precision against the band's 2.5 % (Phi(-8.5) = 9.5e-18).
const TAIL_SIGMAS: f64 = 8.5;

/// Standard normal distribution function.
pub(crate) fn normal_cdf(z: f64) -> f64 {
    0.5 * libm::erfc(-z / std::f64::consts::SQRT_2)
}

/// Standard normal density.
fn normal_pdf(z: f64) -> f64 {
    (-0.5 * z * z).exp() / (2.0 * std::f64::consts::PI).sqrt()
}

/// Phi^-1(p) for p in (0, 1), by bisection to 1e-12 (used once per check).
pub(crate) fn normal_quantile(p: f64) -> f64 {
    let (mut lo, mut hi) = (-40.0_f64, 40.0_f64);
    while hi - lo > 1e-12 {
        let mid = 0.5 * (lo + hi);
        if normal_cdf(mid) < p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Largest count of n observations outside the band that does not warn: the smallest k
/// with P(Binomial(n, 1 - COVERAGE) > k) < FALSE_ALARM (pmf by its recurrence in logs).
pub(crate) fn max_outside(n: usize) -> usize {
    let p = 1.0 - COVERAGE;
    let mut ln_pmf = Vec::with_capacity(n + 1);
    let mut l = n as f64 * (1.0 - p).ln();
    for j in 0..=n {
        ln_pmf.push(l);
        l += ((n - j) as f64 / (j + 1) as f64).ln() + (p / (1.0 - p)).ln();
    }
    let top = ln_pmf.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let pmf: Vec<f64> = ln_pmf.iter().map(|x| (x - top).exp()).collect();
    let total: f64 = pmf.iter().sum();
    let mut tail = 0.0; // P(X > k), built from the top down
    for k in (0..=n).rev() {
        if tail / total >= FALSE_ALARM {
            return k + 1;
        }
        tail += pmf[k];
    }
    0
}

/// Largest excess (noise sigmas beyond the band) of one of n observations that does not
/// warn (module docs, "distance").
pub(crate) fn excess_limit(n: usize) -> f64 {
    let z = normal_quantile(0.5 + 0.5 * COVERAGE);
    normal_quantile(1.0 - FALSE_ALARM / (2.0 * n.max(1) as f64)) - z
}

/// Quantile p of the mixture 1/S sum_s N(m_s, sigma^2), `sorted` the m_s ascending:
/// safeguarded Newton on the distribution function (bisection where a step leaves the
/// bracket), members beyond TAIL_SIGMAS counted as 0 or 1.
fn mixture_quantile(sorted: &[f64], sigma: f64, p: f64) -> f64 {
    let n = sorted.len() as f64;
    let cdf_pdf = |y: f64| {
        let a = sorted.partition_point(|m| *m < y - TAIL_SIGMAS * sigma);
        let b = sorted.partition_point(|m| *m <= y + TAIL_SIGMAS * sigma);
        let (mut f, mut g) = (a as f64, 0.0);
        for m in &sorted[a..b] {
            let z = (y - m) / sigma;
            f += normal_cdf(z);
            g += normal_pdf(z);
        }
        (f / n, g / (n * sigma))
    };
    let (mut lo, mut hi) = (
        sorted[0] - TAIL_SIGMAS * sigma,
        sorted[sorted.len() - 1] + TAIL_SIGMAS * sigma,
    );
    // Start from the normal with the mixture's mean and variance.
    let mean = sorted.iter().sum::<f64>() / n;
    let var = sorted.iter().map(|m| (m - mean).powi(2)).sum::<f64>() / n;
    let mut y = mean + normal_quantile(p) * (var + sigma * sigma).sqrt();
    for _ in 0..200 {
        let (f, g) = cdf_pdf(y);
        if (f - p).abs() < 1e-12 || hi - lo < 1e-9 * sigma {
            break;
        }
        if f < p {
            lo = lo.max(y);
        } else {
            hi = hi.min(y);
        }
        let newton = y - (f - p) / g;
        y = if g > 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
    }
    y
}

/// Where one observation lies against its band.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Placed {
    cycles: f64,
    value: f64,
    band: [f64; 2],
    sigma: f64,
    /// Noise sigmas beyond the band (0 inside).
    excess: f64,
}

fn place(cycles: f64, value: f64, members: &mut [f64], sigma: f64) -> Placed {
    members.sort_by(f64::total_cmp);
    // A perfect fit's inferred scale is 0: the band is then the members' own spread.
    let s = sigma.max(1e-12 * members.iter().fold(1e-300_f64, |a, m| a.max(m.abs())));
    let tail = 0.5 * (1.0 - COVERAGE);
    let band = [
        mixture_quantile(members, s, tail),
        mixture_quantile(members, s, 1.0 - tail),
    ];
    let excess = if value > band[1] {
        (value - band[1]) / s
    } else if value < band[0] {
        (band[0] - value) / s
    } else {
        0.0
    };
    Placed {
        cycles,
        value,
        band,
        sigma: s,
        excess,
    }
}

/// The observation of a quantity furthest outside its band.
#[derive(Debug, Clone, Serialize)]
pub struct Worst {
    /// Pinion cycles of the observation.
    pub cycles: f64,
    /// Observed value, display units.
    pub observed: f64,
    /// The central band there [lower, upper], display units.
    pub band: [f64; 2],
    /// Noise standard deviation used there, display units.
    pub sigma: f64,
    /// Distance beyond the band, noise sigmas and display units.
    pub excess_sigma: f64,
    /// Distance beyond the band, display units.
    pub excess: f64,
}

/// One observed quantity.
#[derive(Debug, Clone, Serialize)]
pub struct QuantityFit {
    /// Name of the quantity.
    pub quantity: String,
    /// "given" (sigma column) or "inferred".
    pub noise: &'static str,
    /// Observations of it.
    pub observations: usize,
    /// Observations outside its central band.
    pub outside: usize,
    /// The observation furthest outside (None: every one inside).
    pub worst: Option<Worst>,
    /// Observations without a model value at some posterior sample (left out).
    pub without_value: usize,
}

/// The fit check of a calibration (`summary.json` "fit_check").
#[derive(Debug, Clone, Serialize)]
pub struct FitCheck {
    /// Probability content of the central band the observations are held to (0.95).
    pub coverage: f64,
    /// Observations in all.
    pub observations: usize,
    /// Observations outside their central band.
    pub outside: usize,
    /// n (1 - coverage): what data the model generated would leave outside on average.
    pub expected_outside: f64,
    /// Rule: more than this many outside warns.
    pub max_outside_without_warning: usize,
    /// Largest distance beyond the band over all observations, noise sigmas.
    pub largest_excess_sigma: f64,
    /// Rule: further out than this warns.
    pub excess_limit_sigma: f64,
    /// Probability that each warning rule fires on data the model generated.
    pub false_alarm_probability_per_rule: f64,
    /// The check of each observed quantity.
    pub quantities: Vec<QuantityFit>,
    /// The warning (None: the data are consistent with the model).
    pub warning: Option<String>,
}

/// The fit check of observations against the posterior samples. `value(q, theta, c)` is
/// the forward model; `noise` the noise scale per quantity (`likelihood::noise_scales`).
pub fn fit_check(
    obs: &Observations,
    samples: &[Theta],
    value: &(dyn Fn(Quantity, &Theta, f64) -> Option<f64> + Sync),
    noise: &[(Quantity, bool, f64)],
) -> FitCheck {
    let mut quantities = Vec::new();
    for s in &obs.series {
        let inferred = noise
            .iter()
            .find(|x| x.0 == s.quantity)
            .map_or(0.0, |x| x.2);
        let placed: Vec<Option<Placed>> = (0..s.values.len())
            .into_par_iter()
            .map(|i| {
                let c = s.cycles[i];
                let mut members: Vec<f64> = samples
                    .iter()
                    .map(|t| value(s.quantity, t, c))
                    .collect::<Option<Vec<f64>>>()?;
                if members.is_empty() {
                    return None;
                }
                let sigma = s.sigma.as_ref().map_or(inferred, |v| v[i]);
                Some(place(c, s.values[i], &mut members, sigma))
            })
            .collect();
        let known: Vec<Placed> = placed.iter().flatten().copied().collect();
        let worst = known
            .iter()
            .filter(|p| p.excess > 0.0)
            .max_by(|a, b| a.excess.total_cmp(&b.excess))
            .map(|p| Worst {
                cycles: p.cycles,
                observed: p.value,
                band: p.band,
                sigma: p.sigma,
                excess_sigma: p.excess,
                excess: p.excess * p.sigma,
            });
        quantities.push(QuantityFit {
            quantity: s.quantity.name().into(),
            noise: if s.sigma.is_some() {
                "given"
            } else {
                "inferred"
            },
            observations: known.len(),
            outside: known.iter().filter(|p| p.excess > 0.0).count(),
            worst,
            without_value: placed.len() - known.len(),
        });
    }
    let n: usize = quantities.iter().map(|q| q.observations).sum();
    let outside: usize = quantities.iter().map(|q| q.outside).sum();
    let largest = quantities
        .iter()
        .filter_map(|q| q.worst.as_ref().map(|w| w.excess_sigma))
        .fold(0.0, f64::max);
    let mut check = FitCheck {
        coverage: COVERAGE,
        observations: n,
        outside,
        expected_outside: n as f64 * (1.0 - COVERAGE),
        max_outside_without_warning: max_outside(n),
        largest_excess_sigma: largest,
        excess_limit_sigma: excess_limit(n),
        false_alarm_probability_per_rule: FALSE_ALARM,
        quantities,
        warning: None,
    };
    check.warning = warning(&check);
    check
}

/// The warning of a fit check, naming how far the data lie from the model.
fn warning(c: &FitCheck) -> Option<String> {
    let too_many = c.outside > c.max_outside_without_warning;
    let too_far = c.largest_excess_sigma > c.excess_limit_sigma;
    if !too_many && !too_far {
        return None;
    }
    let worst = c
        .quantities
        .iter()
        .filter_map(|q| q.worst.as_ref().map(|w| (q, w)))
        .max_by(|a, b| a.1.excess_sigma.total_cmp(&b.1.excess_sigma))?;
    let (q, w) = worst;
    let side = if w.observed > w.band[1] {
        "above"
    } else {
        "below"
    };
    Some(format!(
        "the model does not fit the observations: {} of {} lie outside the central {:.0} % posterior predictive band ({:.1} expected; more than {} outside happens with probability < {} when the model holds), the furthest {:.1} noise sigma {side} it: {} = {:.4} at {:e} cycles against the band [{:.4}, {:.4}], {:.4} beyond it (sigma {:.4}, {}){}; the posterior assumes a model that does not describe these data: check the observations, their units and sigmas, and the case",
        c.outside,
        c.observations,
        100.0 * c.coverage,
        c.expected_outside,
        c.max_outside_without_warning,
        c.false_alarm_probability_per_rule,
        w.excess_sigma,
        q.quantity,
        w.observed,
        w.cycles,
        w.band[0],
        w.band[1],
        w.excess,
        w.sigma,
        q.noise,
        if too_far {
            format!(
                "; noise goes further than {:.2} sigma beyond it with probability < {}",
                c.excess_limit_sigma, c.false_alarm_probability_per_rule
            )
        } else {
            String::new()
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_functions_match_published_values() {
        // Abramowitz & Stegun table 26.1: Phi(1.96) = 0.9750021, Phi(-3) = 0.0013499.
        assert!((normal_cdf(1.96) - 0.975_002_1).abs() < 1e-7);
        assert!((normal_cdf(-3.0) - 0.001_349_9).abs() < 1e-7);
        assert!((normal_quantile(0.975) - 1.959_964).abs() < 1e-6);
    }

    #[test]
    fn binomial_limit_matches_direct_sums() {
        // n = 20, p = 0.05 (direct sums of the pmf, Python's math.comb): P(X > 4) =
        // 0.00257, P(X > 5) = 0.000329: the limit is 5.
        assert_eq!(max_outside(20), 5);
        // n = 1: P(X > 0) = 0.05, P(X > 1) = 0: the limit is 1 (one outside of one is
        // no sign by count).
        assert_eq!(max_outside(1), 1);
        // n = 1e5: 5214 by the same sum in logs (lgamma) in Python; the normal
        // approximation n p + 3.09 sqrt(n p q) gives 5213.
        assert_eq!(max_outside(100_000), 5214);
    }

    #[test]
    fn mixture_quantiles_of_one_member_are_the_normal_ones() {
        // One member: the band is m +- 1.96 sigma (to the normal quantile).
        let q = mixture_quantile(&[3.0], 0.5, 0.975);
        assert!((q - (3.0 + 0.5 * 1.959_964)).abs() < 1e-6, "{q}");
        // Two members far apart: the 2.5 % point is the lower one's 5 % point.
        let q = mixture_quantile(&[0.0, 100.0], 1.0, 0.025);
        assert!((q + 1.644_854).abs() < 1e-5, "{q}");
    }

    #[test]
    fn an_observation_outside_is_placed_by_its_excess() {
        let mut m = vec![0.0; 10];
        let p = place(1.0, 5.0, &mut m, 1.0);
        // Band [-1.96, 1.96]: 5 is 3.04 sigma above.
        assert!((p.excess - (5.0 - 1.959_964)).abs() < 1e-6);
        assert_eq!(place(1.0, 1.9, &mut m, 1.0).excess, 0.0);
    }
}
