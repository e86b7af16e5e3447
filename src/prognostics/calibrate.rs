//! Calibration: the posterior of the uncertain parameters given observations, by the
//! exact grid (one or two free parameters) or the ensemble sampler (three), on the
//! surrogate forward model.

use super::band::{cycles_grid, Band};
use super::grid::GridPosterior;
use super::likelihood::log_likelihood;
use super::mcmc::{ensemble_sample, McmcRun, McmcSettings};
use super::observations::Observations;
use super::posterior_error::PosteriorError;
use super::prior::{Parameter, Prior, Theta};
use super::stats::{autocorrelation_time, quantile, split_rhat};
use super::surrogate::Surrogate;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// The sizes and seed of a calibration.
#[derive(Debug, Clone, Copy)]
pub struct CalibrationSettings {
    /// Posterior samples to return.
    pub samples: usize,
    /// Seed of the random streams (the result depends only on it and the inputs).
    pub seed: u64,
    /// Grid cells per parameter.
    pub grid_cells: usize,
    /// Walkers of the ensemble sampler (MCMC only).
    pub walkers: usize,
    /// Steps per walker, burn-in included (MCMC only).
    pub steps: usize,
}

/// How the posterior is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Exact posterior on a (refined) grid.
    Grid,
    /// Affine-invariant ensemble MCMC (Goodman & Weare 2010).
    EnsembleMcmc,
}

/// Posterior summary of one parameter.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ParamSummary {
    /// The parameter summarised.
    pub parameter: Parameter,
    /// Posterior median, in the parameter's unit.
    pub median: f64,
    /// 90 % equal-tailed credible interval.
    pub ci05: f64,
    /// Upper end of the 90 % credible interval (95th percentile), in the parameter's unit.
    pub ci95: f64,
    /// Effective sample size of the returned samples.
    pub ess: f64,
    /// Split R-hat over walkers (MCMC only).
    pub rhat: Option<f64>,
}

/// Marginal posterior density of one parameter against its plotting coordinate
/// (log10 k for k, the value otherwise).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Density {
    /// The parameter.
    pub parameter: Parameter,
    /// Plotting coordinate of each density point (log10 k for k, the value otherwise).
    pub x: Vec<f64>,
    /// Posterior density at each point, per unit of the plotting coordinate.
    pub density: Vec<f64>,
    /// The prior's density in the same coordinate (uniform).
    pub prior_density: f64,
}

/// The result of calibrating the uncertain parameters against observations: posterior
/// samples and their summaries.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Calibration {
    /// The prior the posterior was computed from.
    pub prior: Prior,
    /// How it was computed.
    pub method: Method,
    /// Posterior samples of the parameters.
    pub samples: Vec<Theta>,
    /// Summary of each parameter, in the order of [`Theta`].
    pub summary: Vec<ParamSummary>,
    /// Marginal density of each parameter, in the order of [`Theta`].
    pub densities: Vec<Density>,
    /// Parameters at which the forward model failed (grid points or proposals).
    pub failed: Vec<Theta>,
    /// Grid: prior mass of the failed cells; posterior mass neglected outside the box.
    pub prior_mass_failed: Option<f64>,
    /// Grid: posterior mass estimated to lie outside the refined box (None for MCMC).
    pub mass_outside: Option<f64>,
    /// Grid: refinement levels used (None for MCMC).
    pub grid_levels: Option<usize>,
    /// MCMC: share of proposals accepted (None for the grid).
    pub acceptance: Option<f64>,
}

/// Width of one unit coordinate in the plotting coordinate.
fn unit_span(prior: &Prior, i: usize) -> f64 {
    let p = &prior.params[i];
    if p.log {
        (p.hi / p.lo).log10()
    } else {
        p.hi - p.lo
    }
}

/// Plotting coordinate of a unit coordinate.
fn plot_x(prior: &Prior, i: usize, u: f64) -> f64 {
    let p = &prior.params[i];
    if p.log {
        p.value_at_unit(u).log10()
    } else {
        p.value_at_unit(u)
    }
}

/// The posterior given the observations. `done` is called as work progresses.
pub fn calibrate(
    prior: &Prior,
    obs: &Observations,
    sur: &Surrogate,
    set: &CalibrationSettings,
    done: &(dyn Fn() + Sync),
) -> Result<Calibration, PosteriorError> {
    let free = prior.free();
    if free.is_empty() {
        return Err(PosteriorError::NothingToCalibrate);
    }
    let loglik = |t: &Theta| log_likelihood(obs, &|q, c| sur.value(q, t, c));
    let explain = |e| beyond_reach(e, obs, sur);
    if free.len() <= 2 {
        let g = GridPosterior::compute(prior, &loglik, set.grid_cells, done).map_err(explain)?;
        return Ok(from_grid(prior, &free, g, set));
    }
    let s = McmcSettings {
        walkers: set.walkers,
        steps: set.steps,
        burn_in: set.steps / 2,
        seed: set.seed,
    };
    let run = ensemble_sample(prior, &loglik, &s, done).map_err(explain)?;
    Ok(from_mcmc(prior, &free, run, set))
}

/// A calibration of `prior` by `method` with nothing filled in yet.
fn empty(prior: &Prior, method: Method) -> Calibration {
    Calibration {
        prior: prior.clone(),
        method,
        samples: Vec::new(),
        summary: Vec::new(),
        densities: Vec::new(),
        failed: Vec::new(),
        prior_mass_failed: None,
        mass_outside: None,
        grid_levels: None,
        acceptance: None,
    }
}

/// Why no parameter could be weighed, in the terms of the data: how far the reference
/// runs reach (cycles) against the last observation; `e` unchanged when they reach it.
fn beyond_reach(e: PosteriorError, obs: &Observations, sur: &Surrogate) -> PosteriorError {
    let reach = sur
        .chains
        .iter()
        .map(|c| sur.valid_until(&[c.k[0], c.theta[1], c.theta[2]]))
        .fold(0.0_f64, f64::max);
    let last = obs.max_cycles();
    if reach < last {
        PosteriorError::BeyondReach {
            cause: Box::new(e),
            reach_cycles: reach,
            last_cycles: last,
            first_failure: sur
                .failures()
                .first()
                .map_or("no failure recorded".into(), |f| f.2.clone()),
        }
    } else {
        e
    }
}

/// The calibration from the exact grid posterior `g` over the `free` parameters: samples
/// drawn from it, quantiles and densities read off the grid.
fn from_grid(
    prior: &Prior,
    free: &[usize],
    g: GridPosterior,
    set: &CalibrationSettings,
) -> Calibration {
    let mut out = empty(prior, Method::Grid);
    let draws = g.draw(set.samples, set.seed);
    out.samples = draws.iter().map(|u| prior.theta_at(u)).collect();
    for (a, &i) in free.iter().enumerate() {
        let q = |p| prior.params[i].value_at_unit(g.quantile_unit(a, p));
        out.summary.push(ParamSummary {
            parameter: prior.params[i].parameter,
            median: q(0.5),
            ci05: q(0.05),
            ci95: q(0.95),
            ess: set.samples as f64,
            rhat: None,
        });
        let (u, dens) = g.density_unit(a);
        let span = unit_span(prior, i);
        out.densities.push(Density {
            parameter: prior.params[i].parameter,
            x: u.iter().map(|v| plot_x(prior, i, *v)).collect(),
            density: dens.iter().map(|d| d / span).collect(),
            prior_density: 1.0 / span,
        });
    }
    out.prior_mass_failed = Some(g.prior_mass_failed);
    out.mass_outside = Some(g.mass_outside);
    out.grid_levels = Some(g.levels);
    out.failed = g.failed;
    out
}

/// The calibration from the ensemble sampler's `run` over the `free` parameters: the
/// chains thinned evenly to the requested count, quantiles, ESS and split R-hat from the
/// chains, densities as 40-bin histograms.
fn from_mcmc(
    prior: &Prior,
    free: &[usize],
    run: McmcRun,
    set: &CalibrationSettings,
) -> Calibration {
    let mut out = empty(prior, Method::EnsembleMcmc);
    out.acceptance = Some(run.acceptance);
    let flat = run.flat();
    // Evenly thinned to the requested count (deterministic).
    let n = set.samples.min(flat.len()).max(1);
    out.samples = (0..n)
        .map(|i| prior.theta_at(&flat[i * flat.len() / n]))
        .collect();
    for (a, &i) in free.iter().enumerate() {
        let c = run.coordinate(a);
        let all: Vec<f64> = flat.iter().map(|u| u[a]).collect();
        let tau = autocorrelation_time(&c);
        let q = |p| prior.params[i].value_at_unit(quantile(&all, p));
        out.summary.push(ParamSummary {
            parameter: prior.params[i].parameter,
            median: q(0.5),
            ci05: q(0.05),
            ci95: q(0.95),
            ess: (all.len() as f64 / tau).min(all.len() as f64),
            rhat: Some(split_rhat(&c)),
        });
        out.densities.push(histogram_density(prior, i, &all));
    }
    out.failed = run.failed;
    out
}

/// Histogram of 40 bins over the sampled range of unit coordinates `all` of parameter
/// `i`, as a density per unit of its plotting coordinate.
fn histogram_density(prior: &Prior, i: usize, all: &[f64]) -> Density {
    let (lo, hi) = (quantile(all, 0.0), quantile(all, 1.0));
    let bins = 40;
    let w = ((hi - lo) / bins as f64).max(1e-12);
    let mut h = vec![0.0; bins];
    for u in all {
        h[(((u - lo) / w) as usize).min(bins - 1)] += 1.0;
    }
    let span = unit_span(prior, i);
    Density {
        parameter: prior.params[i].parameter,
        x: (0..bins)
            .map(|b| plot_x(prior, i, lo + w * (b as f64 + 0.5)))
            .collect(),
        density: h
            .iter()
            .map(|c| c / (all.len() as f64 * w * span))
            .collect(),
        prior_density: 1.0 / span,
    }
}

/// The model's band over the posterior samples for quantity `q` on `points` cycle counts
/// from 0 to `max_cycles` (noise-free model values; the observations carry noise).
pub(crate) fn model_band(
    sur: &Surrogate,
    samples: &[Theta],
    q: super::quantity::Quantity,
    max_cycles: f64,
    points: usize,
) -> (Band, Vec<Vec<Option<f64>>>) {
    let grid = cycles_grid(max_cycles, points);
    let values: Vec<Vec<Option<f64>>> = samples
        .par_iter()
        .map(|t| grid.iter().map(|c| sur.value(q, t, *c)).collect())
        .collect();
    (Band::of(&grid, &values, q.is_wear()), values)
}
