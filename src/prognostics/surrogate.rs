//! The surrogate forward model: a few true wear studies ("reference runs") that stand for
//! every wear coefficient.
//!
//! **Why it works.** Archard's wear per cycle is proportional to k (paper eq. 14) and the
//! response depends only on the wear state and the roughness law. So in the limit of small
//! blocks the whole coupled trajectory is a function of the exposure k N (N cycles): the
//! trajectory at k equals the trajectory at k_ref read at N k / k_ref cycles. The block
//! scheme keeps this exactly when every block is cut by the wear threshold (the threshold
//! is a wear depth, so it cuts at the same wear states for every k); it breaks it only
//! through (a) the rounding of a block to whole cycles and (b) blocks limited by
//! `wear.block_cycles` instead (small k), which are finer than the threshold's.
//! The reference runs are therefore made with the threshold as the only cut (block =
//! whole run) at a k_ref 1000 times below the smallest k in use, so that a block holds
//! thousands of cycles and (a) vanishes; (b) is measured against true runs
//! (docs/PROGNOSTICS.md).
//!
//! The roughness factor and the load torque have no such invariance: one reference run
//! per node of a regular grid over them, and multilinear interpolation between nodes.

use super::forward::{run_trajectory, Crossing, Trajectory};
use super::prior::{apply, Prior, Theta};
use super::quantity::Quantity;
use crate::config::Case;
use crate::study::model::ModelError;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// Reference k relative to the smallest k in use (see the module notes).
pub const REFERENCE_K_FACTOR: f64 = 1e-3;

/// Largest reference cycle count: whole cycles stay exact in f64 far below 2^53 ~ 9e15.
const MAX_REFERENCE_CYCLES: f64 = 1e15;

/// Reference runs and how to read them.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Surrogate {
    /// k of every reference run, m^2/N.
    pub reference_k: f64,
    /// Interpolated parameters (indices into [`Theta`]) and their node values.
    pub axes: Vec<(usize, Vec<f64>)>,
    /// Reference runs, row-major over the axes (first axis slowest).
    pub nodes: Vec<Trajectory>,
    /// Parameters of each reference run.
    pub node_thetas: Vec<Theta>,
}

/// `n` evenly spaced values from lo to hi.
fn linspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo + (hi - lo) * i as f64 / (n - 1).max(1) as f64)
        .collect()
}

impl Surrogate {
    /// Run the reference runs for the parameter ranges of `prior` (its bounds; fixed
    /// parameters stay fixed) up to `max_cycles` cycles at the largest k.
    /// `nodes_per_axis` reference runs per free parameter other than k; `done` is called
    /// after each run (progress).
    pub fn build(
        case: &Case,
        prior: &Prior,
        max_cycles: f64,
        nodes_per_axis: usize,
        done: &(dyn Fn() + Sync),
    ) -> Result<Self, ModelError> {
        let k = &prior.params[0];
        let horizon = max_cycles.max(1.0);
        let reference_k = (k.lo * REFERENCE_K_FACTOR).max(k.hi * horizon / MAX_REFERENCE_CYCLES);
        let reference_cycles = (horizon * k.hi / reference_k).ceil();
        let axes: Vec<(usize, Vec<f64>)> = prior
            .free()
            .into_iter()
            .filter(|i| *i != 0)
            .map(|i| {
                let p = &prior.params[i];
                (i, linspace(p.lo, p.hi, nodes_per_axis.max(2)))
            })
            .collect();
        let count: usize = axes.iter().map(|a| a.1.len()).product();
        let node_thetas: Vec<Theta> = (0..count)
            .map(|id| {
                let mut t = [reference_k, prior.params[1].lo, prior.params[2].lo];
                let mut rest = id;
                for (i, values) in axes.iter().rev() {
                    t[*i] = values[rest % values.len()];
                    rest /= values.len();
                }
                t
            })
            .collect();
        let nodes: Result<Vec<Trajectory>, ModelError> = node_thetas
            .par_iter()
            .map(|t| {
                // The threshold is the only cut: block = the whole run.
                let r = run_trajectory(&apply(case, t), Some(reference_cycles), reference_cycles);
                done();
                r
            })
            .collect();
        Ok(Self {
            reference_k,
            axes,
            nodes: nodes?,
            node_thetas,
        })
    }

    /// Reference runs that failed, with their parameters and message.
    pub fn failures(&self) -> Vec<(Theta, f64, String)> {
        self.nodes
            .iter()
            .zip(&self.node_thetas)
            .filter_map(|(n, t)| {
                n.failure
                    .as_ref()
                    .map(|f| (*t, n.valid_until() * self.reference_k, f.clone()))
            })
            .collect()
    }

    /// Nodes and multilinear weights for `theta` (weights > 0 only).
    fn weights(&self, theta: &Theta) -> Vec<(usize, f64)> {
        let mut out = vec![(0_usize, 1.0)];
        for (i, values) in &self.axes {
            let n = values.len();
            let x = theta[*i];
            let j = values.partition_point(|v| *v <= x).clamp(1, n - 1) - 1;
            let t = ((x - values[j]) / (values[j + 1] - values[j])).clamp(0.0, 1.0);
            out = out
                .into_iter()
                .flat_map(|(id, w)| [(id * n + j, w * (1.0 - t)), (id * n + j + 1, w * t)])
                .filter(|(_, w)| *w > 0.0)
                .collect();
        }
        out
    }

    /// Reference cycles standing for `cycles` cycles at wear coefficient k.
    fn to_reference(&self, k: f64, cycles: f64) -> f64 {
        cycles * k / self.reference_k
    }

    /// Value of `q` at `cycles` for parameters `theta`; None beyond the reference runs.
    pub fn value(&self, q: Quantity, theta: &Theta, cycles: f64) -> Option<f64> {
        let x = self.to_reference(theta[0], cycles);
        self.weights(theta).iter().try_fold(0.0, |acc, (n, w)| {
            Some(acc + w * self.nodes[*n].value(q, x)?)
        })
    }

    /// Cycles up to which the surrogate is known for `theta`.
    pub fn valid_until(&self, theta: &Theta) -> f64 {
        let x = self
            .weights(theta)
            .iter()
            .map(|(n, _)| self.nodes[*n].valid_until())
            .fold(f64::INFINITY, f64::min);
        x * self.reference_k / theta[0]
    }

    /// Cycles at which the maximum pinion wear reaches `limit_um`, for `theta`.
    pub fn cycles_to_wear(&self, theta: &Theta, limit_um: f64) -> Crossing {
        let w = self.weights(theta);
        let to_cycles = |x: f64| x * self.reference_k / theta[0];
        if let [(n, _)] = w[..] {
            return match self.nodes[n].cycles_to_wear(limit_um) {
                Crossing::Reached(x) => Crossing::Reached(to_cycles(x)),
                c => c,
            };
        }
        let crossings: Vec<Crossing> = w
            .iter()
            .map(|(n, _)| self.nodes[*n].cycles_to_wear(limit_um))
            .collect();
        let wear = |x: f64| -> Option<f64> {
            w.iter().try_fold(0.0, |acc, (n, wt)| {
                Some(acc + wt * self.nodes[*n].value(Quantity::MaxWearPinion, x)?)
            })
        };
        let reached: Vec<f64> = crossings
            .iter()
            .filter_map(|c| match c {
                Crossing::Reached(x) => Some(*x),
                _ => None,
            })
            .collect();
        let first = reached.iter().copied().fold(f64::INFINITY, f64::min);
        let mut lo = if first.is_finite() { first } else { 0.0 };
        let mut hi = if reached.len() == crossings.len() {
            reached.iter().copied().fold(0.0, f64::max)
        } else {
            let end = w
                .iter()
                .map(|(n, _)| self.nodes[*n].valid_until())
                .fold(f64::INFINITY, f64::min);
            match wear(end) {
                Some(v) if v >= limit_um => end,
                _ if crossings.contains(&Crossing::Unknown) => return Crossing::Unknown,
                _ => return Crossing::NotReached,
            }
        };
        // The weighted wear is non-decreasing in x (each node's is): bisection.
        for _ in 0..200 {
            if hi - lo <= 1e-12 * hi.max(1.0) {
                break;
            }
            let mid = 0.5 * (lo + hi);
            match wear(mid) {
                Some(v) if v >= limit_um => hi = mid,
                Some(_) => lo = mid,
                None => return Crossing::Unknown,
            }
        }
        Crossing::Reached(to_cycles(hi))
    }
}

impl Surrogate {
    /// Largest |surrogate - true run| of `q` over `cycles` for `theta` (the true run made
    /// at theta with the case's own block scheme); None if either has no value there.
    pub fn max_error_against(
        &self,
        truth: &Trajectory,
        theta: &Theta,
        q: Quantity,
        cycles: &[f64],
    ) -> Option<f64> {
        cycles.iter().try_fold(0.0_f64, |m, c| {
            Some(m.max((self.value(q, theta, *c)? - truth.value(q, *c)?).abs()))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn multilinear_weights_sum_to_one() {
        let s = Surrogate {
            reference_k: 1.0,
            axes: vec![(1, vec![0.5, 1.0, 1.5]), (2, vec![40.0, 80.0])],
            nodes: vec![],
            node_thetas: vec![],
        };
        let w = s.weights(&[1.0, 0.75, 50.0]);
        // Halfway between nodes 0 and 1 of the first axis, a quarter of the way along the
        // second: weights 0.5 x (0.75, 0.25) on ids (0,0), (0,1), (1,0), (1,1).
        let want = [(0, 0.375), (1, 0.125), (2, 0.375), (3, 0.125)];
        assert_eq!(w.len(), 4);
        for ((a, x), (b, y)) in w.iter().zip(want) {
            assert_eq!(*a, b);
            assert!((x - y).abs() < 1e-15);
        }
        // On a node: one weight.
        assert_eq!(s.weights(&[1.0, 1.5, 80.0]), vec![(5, 1.0)]);
    }
}
