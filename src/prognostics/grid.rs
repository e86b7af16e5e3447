//! The exact posterior of one or two parameters on a grid.
//!
//! The prior is uniform in unit coordinates (log k for k), so the posterior mass of a
//! cell is proportional to the likelihood at its centre times its volume; within a cell
//! the density is taken constant. A posterior much narrower than the prior is resolved by
//! refining: the grid is laid again over the cells that hold all but 1e-9 of the mass (one
//! cell of margin each side), until that box stops shrinking. The mass left outside is
//! reported. Draws are exact from the piecewise-constant density: a cell by its mass, then
//! a uniform point inside it; they are independent, so the effective sample size is
//! their number.

use super::posterior_error::PosteriorError;
use super::prior::{Prior, Theta};
use crate::rng;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// Mass cut when the box is shrunk for the next level.
const TAIL_MASS: f64 = 1e-9;
/// Most refinement levels.
const MAX_LEVELS: usize = 8;

/// A normalised posterior on a regular grid in unit coordinates.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct GridPosterior {
    /// Free parameter indices (one or two).
    pub free: Vec<usize>,
    /// Unit-coordinate box of the final level, per axis.
    pub lo: Vec<f64>,
    pub hi: Vec<f64>,
    /// Cells per axis.
    pub cells: usize,
    /// Normalised mass per cell, row-major (first axis slowest).
    pub mass: Vec<f64>,
    /// Parameters of every grid point whose forward run failed (all levels).
    pub failed: Vec<Theta>,
    /// Prior mass of the failed cells on the first (whole-prior) level.
    pub prior_mass_failed: f64,
    /// Posterior mass found outside the final box on coarser levels (neglected).
    pub mass_outside: f64,
    pub levels: usize,
}

/// Cell centres of one level's grid: unit coordinates per point.
fn centres(lo: &[f64], hi: &[f64], cells: usize) -> Vec<Vec<f64>> {
    let d = lo.len();
    let total = cells.pow(d as u32);
    (0..total)
        .map(|id| {
            let mut u = vec![0.0; d];
            let mut rest = id;
            for a in (0..d).rev() {
                let i = rest % cells;
                rest /= cells;
                u[a] = lo[a] + (hi[a] - lo[a]) * (i as f64 + 0.5) / cells as f64;
            }
            u
        })
        .collect()
}

impl GridPosterior {
    /// Compute the posterior. `loglik` returns None for a failed forward run; `done` is
    /// called once per level (progress).
    pub(crate) fn compute(
        prior: &Prior,
        loglik: &(dyn Fn(&Theta) -> Option<f64> + Sync),
        cells: usize,
        done: &(dyn Fn() + Sync),
    ) -> Result<Self, PosteriorError> {
        let free = prior.free();
        let d = free.len();
        if !(1..=2).contains(&d) {
            return Err(PosteriorError::GridDimensions { free: d });
        }
        let (mut lo, mut hi) = (vec![0.0; d], vec![1.0; d]);
        let mut failed = Vec::new();
        let (mut prior_mass_failed, mut mass_outside) = (0.0, 0.0);
        let mut level = 0;
        loop {
            let pts = centres(&lo, &hi, cells);
            let thetas: Vec<Theta> = pts.iter().map(|u| prior.theta_at(u)).collect();
            let ll: Vec<Option<f64>> = thetas.par_iter().map(loglik).collect();
            done();
            let n_failed = ll.iter().filter(|x| x.is_none()).count();
            failed.extend(
                thetas
                    .iter()
                    .zip(&ll)
                    .filter(|(_, l)| l.is_none())
                    .map(|x| *x.0),
            );
            if level == 0 {
                prior_mass_failed = n_failed as f64 / ll.len() as f64;
            }
            let max = ll
                .iter()
                .flatten()
                .copied()
                .fold(f64::NEG_INFINITY, f64::max);
            if !max.is_finite() {
                let (failed, points) = (n_failed, ll.len());
                return Err(if failed == points {
                    PosteriorError::NoRunReached { failed, points }
                } else {
                    PosteriorError::ZeroLikelihood { failed, points }
                });
            }
            let w: Vec<f64> = ll
                .iter()
                .map(|l| l.map_or(0.0, |v| (v - max).exp()))
                .collect();
            let sum: f64 = w.iter().sum();
            let mass: Vec<f64> = w.iter().map(|x| x / sum).collect();
            let post = Self {
                free: free.clone(),
                lo: lo.clone(),
                hi: hi.clone(),
                cells,
                mass,
                failed: Vec::new(),
                prior_mass_failed,
                mass_outside,
                levels: level + 1,
            };
            // The box holding all but TAIL_MASS of every marginal, one cell of margin.
            let mut shrinks = false;
            let (mut nlo, mut nhi) = (lo.clone(), hi.clone());
            let mut outside = 0.0_f64;
            for a in 0..d {
                let m = post.marginal(a);
                let mut cum = 0.0;
                let first = m
                    .iter()
                    .position(|x| {
                        cum += x;
                        cum > TAIL_MASS / 2.0
                    })
                    .unwrap_or(0);
                let mut cum = 0.0;
                let last = cells
                    - 1
                    - m.iter()
                        .rev()
                        .position(|x| {
                            cum += x;
                            cum > TAIL_MASS / 2.0
                        })
                        .unwrap_or(0);
                let (i0, i1) = (first.saturating_sub(1), (last + 1).min(cells - 1));
                outside += m[..i0].iter().sum::<f64>() + m[i1 + 1..].iter().sum::<f64>();
                let width = (hi[a] - lo[a]) / cells as f64;
                nlo[a] = lo[a] + i0 as f64 * width;
                nhi[a] = lo[a] + (i1 + 1) as f64 * width;
                shrinks |= (nhi[a] - nlo[a]) < 0.5 * (hi[a] - lo[a]);
            }
            level += 1;
            if !shrinks || level >= MAX_LEVELS {
                return Ok(Self { failed, ..post });
            }
            mass_outside += outside;
            (lo, hi) = (nlo, nhi);
        }
    }

    /// Marginal mass per cell along axis `a`.
    pub(crate) fn marginal(&self, a: usize) -> Vec<f64> {
        let n = self.cells;
        let mut m = vec![0.0; n];
        for (id, x) in self.mass.iter().enumerate() {
            let i = if self.free.len() == 1 || a == 1 {
                id % n
            } else {
                id / n
            };
            m[i] += x;
        }
        m
    }

    /// Unit coordinate of quantile p of axis `a` (CDF linear within a cell).
    pub(crate) fn quantile_unit(&self, a: usize, p: f64) -> f64 {
        let m = self.marginal(a);
        let width = (self.hi[a] - self.lo[a]) / self.cells as f64;
        let mut cum = 0.0;
        for (i, x) in m.iter().enumerate() {
            if cum + x >= p && *x > 0.0 {
                return self.lo[a] + width * (i as f64 + (p - cum) / x);
            }
            cum += x;
        }
        self.hi[a]
    }

    /// Marginal density of axis `a` per unit coordinate at the cell centres.
    pub(crate) fn density_unit(&self, a: usize) -> (Vec<f64>, Vec<f64>) {
        let width = (self.hi[a] - self.lo[a]) / self.cells as f64;
        let m = self.marginal(a);
        let u = (0..self.cells)
            .map(|i| self.lo[a] + width * (i as f64 + 0.5))
            .collect();
        (u, m.iter().map(|x| x / width).collect())
    }

    /// Draw `n` independent samples (unit coordinates of the free parameters), sample i
    /// from random stream i of `seed`.
    pub fn draw(&self, n: usize, seed: u64) -> Vec<Vec<f64>> {
        let mut cdf = Vec::with_capacity(self.mass.len());
        let mut cum = 0.0;
        for x in &self.mass {
            cum += x;
            cdf.push(cum);
        }
        let d = self.free.len();
        (0..n)
            .into_par_iter()
            .map(|i| {
                let mut r = rng::stream(seed, i as u64);
                let v = rng::uniform(&mut r) * cum;
                let mut id = cdf.partition_point(|c| *c <= v).min(cdf.len() - 1);
                while self.mass[id] == 0.0 && id > 0 {
                    id -= 1; // v fell on a zero-mass cell's edge: take the one below
                }
                let mut u = vec![0.0; d];
                let mut rest = id;
                for a in (0..d).rev() {
                    let c = rest % self.cells;
                    rest /= self.cells;
                    let w = (self.hi[a] - self.lo[a]) / self.cells as f64;
                    u[a] = self.lo[a] + w * (c as f64 + rng::uniform(&mut r));
                }
                u
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::Case;

    #[test]
    fn gaussian_in_log_k_is_recovered_with_refinement() {
        // Likelihood Gaussian in u (log k) with centre 0.3 and sd 0.001: a posterior 1000
        // times narrower than the prior. Its median is 0.3 and its 95 % point is
        // 0.3 + 1.6449 sd (normal table).
        let prior = Prior::from_case(&Case::default()).unwrap();
        let ll = |t: &Theta| {
            let u = prior.params[0].unit_of(t[0]);
            Some(-0.5 * ((u - 0.3) / 1e-3).powi(2))
        };
        let g = GridPosterior::compute(&prior, &ll, 200, &|| {}).unwrap();
        assert!(g.levels > 1);
        // A cell is at most 1/200 of a box that spans >= ~12 sd: 0.06 sd; the error of a
        // quantile is a fraction of that. 1e-5 = 0.01 sd.
        assert!((g.quantile_unit(0, 0.5) - 0.3).abs() < 1e-5);
        assert!((g.quantile_unit(0, 0.95) - (0.3 + 1.6449e-3)).abs() < 1e-5);
        let s: Vec<f64> = g.draw(4000, 3).iter().map(|u| u[0]).collect();
        // Sample mean of 4000 draws: standard error sd/63 = 1.6e-5; allow 4 of them.
        assert!((crate::prognostics::stats::mean(&s) - 0.3).abs() < 6.4e-5);
    }
}
