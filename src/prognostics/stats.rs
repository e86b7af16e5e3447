//! Small statistics used by the samplers and the summaries: quantiles, the
//! Kolmogorov-Smirnov distance, the integrated autocorrelation time and split R-hat.
//! Written here because each is a few lines and no maintained crate bundles the
//! ensemble-MCMC versions (an autocorrelation averaged over walkers) we need.

/// Quantile p in [0, 1] of ascending `sorted` data, linear between order statistics
/// (Hyndman & Fan 1996, type 7). NaN for no data; +inf propagates.
pub(crate) fn quantile_sorted(sorted: &[f64], p: f64) -> f64 {
    let n = sorted.len();
    if n == 0 {
        return f64::NAN;
    }
    let h = (n - 1) as f64 * p.clamp(0.0, 1.0);
    let (i, f) = (h.floor() as usize, h - h.floor());
    if i + 1 >= n || f == 0.0 {
        return sorted[i.min(n - 1)];
    }
    sorted[i] + f * (sorted[i + 1] - sorted[i])
}

/// Quantile p of unsorted data (NaNs removed).
pub fn quantile(data: &[f64], p: f64) -> f64 {
    let mut v: Vec<f64> = data.iter().copied().filter(|x| !x.is_nan()).collect();
    v.sort_by(f64::total_cmp);
    quantile_sorted(&v, p)
}

/// Arithmetic mean of `x` (NaN for an empty slice).
pub fn mean(x: &[f64]) -> f64 {
    x.iter().sum::<f64>() / x.len() as f64
}

/// Sample standard deviation (n - 1).
pub fn std_dev(x: &[f64]) -> f64 {
    let m = mean(x);
    (x.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (x.len() as f64 - 1.0)).sqrt()
}

/// One-sample Kolmogorov-Smirnov statistic D = sup |F_n(x) - F(x)|.
#[cfg(test)]
pub fn ks_statistic(samples: &[f64], cdf: impl Fn(f64) -> f64) -> f64 {
    let mut v = samples.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len() as f64;
    v.iter().enumerate().fold(0.0_f64, |d, (i, x)| {
        let f = cdf(*x);
        d.max((f - i as f64 / n).abs())
            .max(((i + 1) as f64 / n - f).abs())
    })
}

/// Asymptotic critical value of D at level alpha = 0.01: 1.628 / sqrt(n) (Smirnov 1948;
/// the Kolmogorov distribution's 99 % point is 1.628).
#[cfg(test)]
pub fn ks_critical_1pct(n: usize) -> f64 {
    1.628 / (n as f64).sqrt()
}

/// Integrated autocorrelation time of an ensemble's chains (`chains[w][t]`), from the
/// walker-averaged autocorrelation function with Sokal's automatic window (the smallest
/// M with M >= 5 tau(M)), as Goodman & Weare (2010) and emcee do.
pub fn autocorrelation_time(chains: &[Vec<f64>]) -> f64 {
    let n = chains.iter().map(Vec::len).min().unwrap_or(0);
    if n < 4 {
        return f64::NAN;
    }
    let mut acf = vec![0.0; n];
    for c in chains {
        let m = mean(&c[..n]);
        let var: f64 = c[..n].iter().map(|x| (x - m).powi(2)).sum::<f64>() / n as f64;
        if var <= 0.0 {
            continue;
        }
        for (lag, a) in acf.iter_mut().enumerate().take(n / 2) {
            let s: f64 = (0..n - lag).map(|t| (c[t] - m) * (c[t + lag] - m)).sum();
            *a += s / (n as f64 * var);
        }
    }
    let norm = acf[0];
    if norm <= 0.0 {
        return f64::NAN;
    }
    let mut tau = 1.0;
    for (m, a) in acf.iter().enumerate().take(n / 2).skip(1) {
        tau += 2.0 * a / norm;
        if m as f64 >= 5.0 * tau {
            break;
        }
    }
    tau.max(1.0)
}

/// Split R-hat (Gelman et al., Bayesian Data Analysis, 3rd ed., eq. 11.4): each chain cut
/// in halves, then sqrt(var_plus / W) with W the mean within-chain variance and
/// var_plus = (n-1)/n W + B/n.
pub(crate) fn split_rhat(chains: &[Vec<f64>]) -> f64 {
    let half = chains.iter().map(Vec::len).min().unwrap_or(0) / 2;
    if half < 2 {
        return f64::NAN;
    }
    let parts: Vec<&[f64]> = chains
        .iter()
        .flat_map(|c| [&c[..half], &c[half..2 * half]])
        .collect();
    let n = half as f64;
    let means: Vec<f64> = parts.iter().map(|p| mean(p)).collect();
    let w = parts.iter().map(|p| std_dev(p).powi(2)).sum::<f64>() / parts.len() as f64;
    let b = n * std_dev(&means).powi(2);
    if w <= 0.0 {
        return f64::NAN;
    }
    (((n - 1.0) / n * w + b / n) / w).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantiles_match_the_type7_definition() {
        let v = [1.0, 2.0, 3.0, 4.0];
        // h = 3 p: p = 0.5 -> between 2 and 3; p = 0.9 -> 3.7 (3 + 0.7 x 1).
        assert_eq!(quantile_sorted(&v, 0.5), 2.5);
        assert!((quantile_sorted(&v, 0.9) - 3.7).abs() < 1e-12);
        assert_eq!(quantile(&[4.0, f64::NAN, 1.0], 0.0), 1.0);
        assert!(quantile(&[], 0.5).is_nan());
    }

    #[test]
    fn ks_of_a_perfect_grid_is_one_over_n() {
        // Points at i/n against the uniform CDF: the empirical CDF jumps 1/n at each.
        let x: Vec<f64> = (1..=10).map(|i| i as f64 / 10.0).collect();
        assert!((ks_statistic(&x, |v| v) - 0.1).abs() < 1e-12);
    }

    #[test]
    fn autocorrelation_of_an_ar1_chain() {
        // AR(1) x_t = rho x_{t-1} + e_t has tau = (1 + rho) / (1 - rho) = 3 for rho = 0.5.
        let mut r = crate::rng::stream(1, 0);
        let chains: Vec<Vec<f64>> = (0..8)
            .map(|_| {
                let mut x = 0.0;
                (0..4000)
                    .map(|_| {
                        // Uniform noise: any finite-variance innovation gives the same tau.
                        x = 0.5 * x + crate::rng::uniform(&mut r) - 0.5;
                        x
                    })
                    .collect()
            })
            .collect();
        let tau = autocorrelation_time(&chains);
        // 32000 draws: the estimate's relative error is ~ sqrt(2 M / N) ~ 5 %; 20 % margin.
        assert!((tau - 3.0).abs() < 0.6, "{tau}");
        // Chains of one stationary process: R-hat close to 1 (1.01 is the usual bar).
        assert!(split_rhat(&chains) < 1.01);
        // Chains shifted apart do not mix: R-hat far above 1.
        let shifted: Vec<Vec<f64>> = chains
            .iter()
            .enumerate()
            .map(|(i, c)| c.iter().map(|x| x + i as f64).collect())
            .collect();
        assert!(split_rhat(&shifted) > 2.0);
    }
}
