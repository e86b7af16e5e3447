//! The surrogate forward model: a few true wear studies ("reference runs") that stand for
//! every wear coefficient.
//!
//! **Why it works.** Archard's wear per cycle is proportional to k (paper eq. 14) and the
//! response depends only on the wear state and the roughness law. So in the limit of small
//! blocks the whole coupled trajectory is a function of the exposure k N (N cycles): the
//! trajectory at k equals a run at k_j read at N k / k_j cycles. The block scheme keeps
//! this exactly when every block is cut by the wear threshold (a wear depth, so it cuts
//! at the same wear states for every k) but for the rounding of a block to whole cycles;
//! blocks limited by `wear.block_cycles` instead (small k) are finer, and differ.
//!
//! **The k axis.** Reference runs are made with the case's own block scheme at wear
//! coefficients k_0 = k_min, k_j = k_0 R^j (R = `K_NODE_RATIO`), up to the first one
//! whose blocks are all cut by the threshold (or that fails, or reaches k_max): every k
//! above it has the same blocks in exposure, so that run stands for all of them. Between
//! two reference runs the observables (read at the same exposure) are interpolated
//! linearly in ln k. The error left against true runs is measured in
//! docs/PROGNOSTICS.md and by `src/prognostics/tests_calibration.rs`.
//!
//! **A load spectrum.** Under a spectrum with fixed shares every bin's wear per cycle is
//! proportional to k, so the spectrum's wear per cycle sum_i s_i inc_i is too, and the
//! blocks are cut by the threshold on it: the invariance holds as it does for one
//! operating point, N counting the spectrum's cycles (each bin's s_i N). A test checks it.
//!
//! **A change of duty** ([`FutureDuty`], a future spectrum from N0 cycles on) breaks it:
//! the switch falls at the exposure k N0, which depends on k. So with a future duty every
//! node of k is its own run (nothing stands for the larger k), on a finer grid
//! (`future_node_ratio`), and the runs are read in two phases
//! (`prognostics::surrogate_duty`): before the switch at the same exposure from the node
//! at or above k (its switch comes later in exposure, so it is still in the first phase:
//! exact by the invariance), after it at the same exposure since the switch, weighted
//! linearly in k between the two nodes around it (they differ by their state at the
//! switch, W(k_j N0), about linear in k). Checked against true runs by a test and by
//! every `predict`.
//!
//! **Other parameters.** The roughness factor and the load torque have no such
//! invariance: one chain of reference runs per node of a regular grid over them, and
//! multilinear interpolation between nodes.

use super::forward::{
    run_duty_trajectory, run_failure, Crossing, FutureDuty, IndicatorError, Trajectory,
};
use super::prior::{apply, Prior, Theta};
use super::quantity::Quantity;
use crate::config::Case;
use crate::study::model::{Model, ModelError};
use crate::study::wear_loop::{run_wear, WearMode, WearRun};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// Ratio of neighbouring reference wear coefficients in the block-limited range.
pub(crate) const K_NODE_RATIO: f64 = 2.0;

/// Ratio of neighbouring k nodes under a change of duty: 2^(1/4), or coarser so that a
/// chain holds at most 17 runs (a prior-only prediction spans four decades).
pub(crate) fn future_node_ratio(k_lo: f64, k_hi: f64) -> f64 {
    2f64.powf(0.25).max((k_hi / k_lo).powf(1.0 / 16.0))
}

/// Most reference runs one chain over the prior of k can hold (k_hi / k_lo in steps of
/// [`K_NODE_RATIO`], both ends included): a progress bar's length, chains usually stop
/// earlier.
pub(crate) fn max_chain_runs(p: &super::prior::Prior) -> u64 {
    let k = &p.params[0];
    ((k.hi / k.lo).ln() / K_NODE_RATIO.ln()).ceil() as u64 + 1
}

/// As [`max_chain_runs`] under a change of duty: every node of the finer grid
/// ([`future_node_ratio`]) and k_hi.
pub(crate) fn future_chain_runs(p: &super::prior::Prior) -> u64 {
    let k = &p.params[0];
    if k.hi <= k.lo {
        return 1;
    }
    ((k.hi / k.lo).ln() / future_node_ratio(k.lo, k.hi).ln()).ceil() as u64 + 1
}

/// One chain of reference runs (increasing k) at fixed other parameters.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Chain {
    /// The parameters the chain holds fixed: roughness factor and torque (its k entry is not used).
    pub theta: Theta,
    /// Wear coefficient of each run, m^2/N, increasing.
    pub k: Vec<f64>,
    /// The reference runs, one per coefficient.
    pub runs: Vec<Trajectory>,
}

/// Reference runs and how to read them.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Surrogate {
    /// Interpolated parameters other than k (indices into [`Theta`]), node values.
    pub axes: Vec<(usize, Vec<f64>)>,
    /// One chain per node of the axes, row-major (first axis slowest).
    pub chains: Vec<Chain>,
    /// The change of duty the runs follow, if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub future: Option<FutureDuty>,
}

/// `n` evenly spaced values from lo to hi.
fn linspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo + (hi - lo) * i as f64 / (n - 1).max(1) as f64)
        .collect()
}

/// Whether every block of a run but its last was cut by the wear threshold (shorter
/// than `block_cycles`): then runs at larger k have the same blocks in exposure.
fn threshold_cut(t: &Trajectory, block_cycles: f64) -> bool {
    let c: Vec<f64> = t.records.iter().map(|r| r.wear.cycles).collect();
    c.len() > 2
        && c.windows(2)
            .rev()
            .skip(1)
            .all(|w| w[1] - w[0] < block_cycles)
}

/// Continue a run to `total` cycles (run_wear resumes from the records it is given); a run
/// under a spectrum is made again to `total`; a gear train's resumes as a pair's
/// (`super::train_forward`).
fn extend(case: &Case, t: &Trajectory, total: f64) -> Result<Trajectory, ModelError> {
    if !case.stage.is_empty() {
        let run = super::train_forward::extend_train(case, (&t.records, &t.later_stages), total)?;
        return Ok(Trajectory::of_train(run, t.coefficient_m2_per_n, total));
    }
    if case.load_spectrum.is_some() {
        return run_duty_trajectory(case, None, None, total);
    }
    let mut c = case.clone();
    c.wear.total_cycles = total;
    let model = Model::wear_study_from_case(&c, super::forward::PROGNOSTICS)?;
    let mut records = t.records.clone();
    let run = WearRun {
        records: t.records.clone(),
        ..WearRun::new(WearMode::Dynamic)
    };
    let result = run_wear(&model, run, &mut |r| {
        if let Some(x) = r.records.last() {
            records.push(x.clone());
        }
        Ok(())
    });
    records.dedup_by(|a, b| a.wear.cycles == b.wear.cycles);
    Ok(Trajectory {
        coefficient_m2_per_n: t.coefficient_m2_per_n,
        requested_cycles: total,
        records,
        failure: run_failure(result),
        indicators: Default::default(),
        later_stages: Vec::new(),
        cycle_factors: Vec::new(),
    })
}

/// The chain of reference runs at `theta` (its k ignored) for k in [k_lo, k_hi], each
/// covering `horizon` cycles at the largest k it stands for. Runs are made in parallel
/// batches; nodes past the first threshold-cut (or failed) run are discarded, so the
/// chain does not depend on the thread count.
fn chain(
    case: &Case,
    future: Option<&FutureDuty>,
    theta: Theta,
    k_lo: f64,
    k_hi: f64,
    horizon: f64,
    done: &(dyn Fn() + Sync),
) -> Result<Chain, ModelError> {
    let ratio = match future {
        None => K_NODE_RATIO,
        Some(_) => future_node_ratio(k_lo, k_hi),
    };
    let mut ks = vec![k_lo];
    while *ks.last().unwrap_or(&k_hi) * ratio < k_hi * (1.0 - 1e-12) {
        ks.push(ks[ks.len() - 1] * ratio);
    }
    if future.is_some() && k_hi > k_lo {
        // Every node its own run, the last at k_hi.
        ks.push(k_hi);
    }
    let block = case.wear.block_cycles;
    let batch = rayon::current_num_threads().max(1);
    let mut runs: Vec<Trajectory> = Vec::new();
    'outer: for start in (0..ks.len()).step_by(batch) {
        let end = (start + batch).min(ks.len());
        let made: Result<Vec<Trajectory>, ModelError> = (start..end)
            .into_par_iter()
            .map(|i| {
                let next = ks.get(i + 1).copied().unwrap_or(k_hi);
                let t = [ks[i], theta[1], theta[2]];
                let r = run_duty_trajectory(&apply(case, &t), future, None, horizon * next / ks[i]);
                done();
                r
            })
            .collect();
        for r in made? {
            let last = future.is_none() && (r.failure.is_some() || threshold_cut(&r, block));
            runs.push(r);
            if last {
                break 'outer;
            }
        }
    }
    // The last run stands for every k above it: extend it to cover k_hi.
    let j = runs.len() - 1;
    let need = horizon * k_hi / ks[j];
    if runs[j].failure.is_none() && runs[j].requested_cycles < need {
        let t = [ks[j], theta[1], theta[2]];
        runs[j] = extend(&apply(case, &t), &runs[j], need)?;
    }
    Ok(Chain {
        theta,
        k: ks[..runs.len()].to_vec(),
        runs,
    })
}

/// The stage (1-based, of `stages`) whose maximum pinion wear `value` gives deepest (the
/// first of equals); 1 when none has a value.
pub(crate) fn deepest_stage(stages: usize, value: &dyn Fn(Quantity) -> Option<f64>) -> usize {
    (1..=stages)
        .filter_map(|s| Some((s, value(Quantity::MaxWearPinion.on_stage(s)?)?)))
        .fold((1, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a })
        .0
}

/// The first cycles in [lo, hi] where `wear` (non-decreasing, below `limit_um` at lo and
/// at or above it at hi) reaches `limit_um`, by bisection to 1e-12 relative; Unknown
/// where `wear` has no value.
pub(super) fn bisect_crossing(
    wear: &dyn Fn(f64) -> Option<f64>,
    limit_um: f64,
    mut lo: f64,
    mut hi: f64,
) -> Crossing {
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
    Crossing::Reached(hi)
}

impl Surrogate {
    /// Reference runs for the parameter ranges of `prior` (its bounds; fixed parameters
    /// stay fixed) up to `max_cycles` cycles at the largest k. `nodes_per_axis` chains per
    /// free parameter other than k; `done` is called after each run (progress).
    pub fn build(
        case: &Case,
        prior: &Prior,
        max_cycles: f64,
        nodes_per_axis: usize,
        done: &(dyn Fn() + Sync),
    ) -> Result<Self, ModelError> {
        Self::build_for_duty(case, None, prior, max_cycles, nodes_per_axis, done)
    }

    /// As [`Surrogate::build`], the runs following the change of duty `future`.
    pub fn build_for_duty(
        case: &Case,
        future: Option<&FutureDuty>,
        prior: &Prior,
        max_cycles: f64,
        nodes_per_axis: usize,
        done: &(dyn Fn() + Sync),
    ) -> Result<Self, ModelError> {
        let k = &prior.params[0];
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
        let thetas: Vec<Theta> = (0..count)
            .map(|id| {
                let mut t = [k.lo, prior.params[1].lo, prior.params[2].lo];
                let mut rest = id;
                for (i, values) in axes.iter().rev() {
                    t[*i] = values[rest % values.len()];
                    rest /= values.len();
                }
                t
            })
            .collect();
        let horizon = max_cycles.max(1.0);
        let chains: Result<Vec<Chain>, ModelError> = thetas
            .par_iter()
            .map(|t| chain(case, future, *t, k.lo, k.hi, horizon, done))
            .collect();
        Ok(Self {
            axes,
            chains: chains?,
            future: future.cloned(),
        })
    }

    /// Number of reference runs.
    pub fn runs(&self) -> usize {
        self.chains.iter().map(|c| c.runs.len()).sum()
    }

    /// Reference runs that failed: parameters, exposure k N reached (m^2/N), message.
    pub fn failures(&self) -> Vec<(Theta, f64, String)> {
        self.chains
            .iter()
            .flat_map(|c| {
                c.runs.iter().zip(&c.k).filter_map(|(r, k)| {
                    r.failure
                        .as_ref()
                        .map(|f| ([*k, c.theta[1], c.theta[2]], r.valid_until() * k, f.clone()))
                })
            })
            .collect()
    }

    /// Reference runs and weights for `theta`: (chain, run, weight), weights > 0.
    pub(super) fn weights(&self, theta: &Theta) -> Vec<(usize, usize, f64)> {
        let mut st = vec![(0_usize, 1.0)];
        for (i, values) in &self.axes {
            let n = values.len();
            let x = theta[*i];
            let j = values.partition_point(|v| *v <= x).clamp(1, n - 1) - 1;
            let t = ((x - values[j]) / (values[j + 1] - values[j])).clamp(0.0, 1.0);
            st = st
                .into_iter()
                .flat_map(|(id, w)| [(id * n + j, w * (1.0 - t)), (id * n + j + 1, w * t)])
                .filter(|(_, w)| *w > 0.0)
                .collect();
        }
        let k = theta[0];
        st.into_iter()
            .flat_map(|(c, w)| {
                let ks = &self.chains[c].k;
                let n = ks.len();
                let j = ks.partition_point(|v| *v <= k);
                if j == 0 || j >= n {
                    return vec![(c, j.clamp(1, n) - 1, w)];
                }
                let t = match self.future {
                    // After a change of duty the runs differ by the state at their switch,
                    // W(k_j N0), about linear in k (module docs).
                    Some(_) => (k - ks[j - 1]) / (ks[j] - ks[j - 1]),
                    None => (k / ks[j - 1]).ln() / (ks[j] / ks[j - 1]).ln(),
                }
                .clamp(0.0, 1.0);
                vec![(c, j - 1, w * (1.0 - t)), (c, j, w * t)]
            })
            .filter(|x| x.2 > 0.0)
            .collect()
    }

    /// The run behind a weight and the factor from sample cycles to its cycles.
    fn run(&self, c: usize, r: usize, k: f64) -> (&Trajectory, f64) {
        (&self.chains[c].runs[r], k / self.chains[c].k[r])
    }

    /// Compute the condition indicators among `qs` at every update of every reference run
    /// (`super::indicator`), each run with its own parameters; `done` is called per run.
    pub fn attach_indicators(
        &mut self,
        case: &Case,
        qs: &[Quantity],
        done: &(dyn Fn() + Sync),
    ) -> Result<(), IndicatorError> {
        for chain in &mut self.chains {
            let c = apply(case, &chain.theta);
            for run in &mut chain.runs {
                let mut rc = c.clone();
                rc.wear.coefficient_m2_per_n = run.coefficient_m2_per_n;
                super::forward::attach(run, &rc, qs)?;
                done();
            }
        }
        Ok(())
    }

    /// Reference runs in all chains.
    pub(crate) fn run_count(&self) -> usize {
        self.chains.iter().map(|c| c.runs.len()).sum()
    }

    /// Value of `q` at `cycles` for parameters `theta`; None beyond the reference runs.
    pub fn value(&self, q: Quantity, theta: &Theta, cycles: f64) -> Option<f64> {
        if let Some(f) = &self.future {
            return self.value_after_change(f, q, theta, cycles);
        }
        self.weights(theta).iter().try_fold(0.0, |acc, (c, r, w)| {
            let (t, s) = self.run(*c, *r, theta[0]);
            Some(acc + w * t.value(q, cycles * s)?)
        })
    }

    /// Number of meshes the reference runs hold (1 for a single pair).
    pub fn stage_count(&self) -> usize {
        self.chains
            .iter()
            .find_map(|c| c.runs.first())
            .map_or(1, Trajectory::stage_count)
    }

    /// The deepest maximum pinion wear of any stage at `cycles` for `theta`, um (the
    /// pair's maximum pinion wear for a single pair); None beyond the reference runs.
    pub fn max_pinion_wear(&self, theta: &Theta, cycles: f64) -> Option<f64> {
        let stages = self.stage_count();
        if stages == 1 {
            return self.value(Quantity::MaxWearPinion, theta, cycles);
        }
        (1..=stages).try_fold(0.0_f64, |m, s| {
            let q = Quantity::MaxWearPinion.on_stage(s)?;
            Some(m.max(self.value(q, theta, cycles)?))
        })
    }

    /// The stage (1-based) whose maximum pinion wear is deepest at `cycles` for `theta`
    /// (at the life, the stage that reached the limit first); 1 for a single pair.
    pub fn deepest_stage(&self, theta: &Theta, cycles: f64) -> usize {
        deepest_stage(self.stage_count(), &|q| self.value(q, theta, cycles))
    }

    /// Cycles up to which the surrogate is known for `theta`.
    pub(crate) fn valid_until(&self, theta: &Theta) -> f64 {
        if let Some(f) = &self.future {
            return self.valid_until_after_change(f, theta);
        }
        self.weights(theta)
            .iter()
            .map(|(c, r, _)| {
                let (t, s) = self.run(*c, *r, theta[0]);
                t.valid_until() / s
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// Cycles at which the maximum pinion wear reaches `limit_um`, for `theta`.
    pub fn cycles_to_wear(&self, theta: &Theta, limit_um: f64) -> Crossing {
        if self.future.is_some() {
            return self.cycles_to_wear_after_change(theta, limit_um);
        }
        let w = self.weights(theta);
        let mapped = |(c, r, _): &(usize, usize, f64)| {
            let (t, s) = self.run(*c, *r, theta[0]);
            match t.cycles_to_wear(limit_um) {
                Crossing::Reached(x) => Crossing::Reached(x / s),
                other => other,
            }
        };
        if let [one] = w[..] {
            return mapped(&one);
        }
        let crossings: Vec<Crossing> = w.iter().map(mapped).collect();
        let wear = |n: f64| self.max_pinion_wear(theta, n);
        let reached: Vec<f64> = crossings
            .iter()
            .filter_map(|c| match c {
                Crossing::Reached(x) => Some(*x),
                _ => None,
            })
            .collect();
        let first = reached.iter().copied().fold(f64::INFINITY, f64::min);
        let lo = if first.is_finite() { first } else { 0.0 };
        let hi = if reached.len() == crossings.len() {
            reached.iter().copied().fold(0.0, f64::max)
        } else {
            let end = self.valid_until(theta);
            match wear(end) {
                Some(v) if v >= limit_um => end,
                _ if crossings.contains(&Crossing::Unknown) => return Crossing::Unknown,
                _ => return Crossing::NotReached,
            }
        };
        // The weighted wear is non-decreasing in cycles (each run's is): bisection.
        bisect_crossing(&wear, limit_um, lo, hi)
    }

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

    fn empty_chain(k: Vec<f64>) -> Chain {
        Chain {
            theta: [0.0; 3],
            runs: vec![],
            k,
        }
    }

    #[test]
    fn multilinear_weights_sum_to_one() {
        let s = Surrogate {
            axes: vec![(1, vec![0.5, 1.0, 1.5]), (2, vec![40.0, 80.0])],
            chains: (0..6).map(|_| empty_chain(vec![1.0])).collect(),
            future: None,
        };
        let w = s.weights(&[1.0, 0.75, 50.0]);
        // Halfway between nodes 0 and 1 of the first axis, a quarter of the way along the
        // second: weights 0.5 x (0.75, 0.25) on chains (0,0), (0,1), (1,0), (1,1).
        let want = [(0, 0.375), (1, 0.125), (2, 0.375), (3, 0.125)];
        assert_eq!(w.len(), 4);
        for ((a, _, x), (b, y)) in w.iter().zip(want) {
            assert_eq!(*a, b);
            assert!((x - y).abs() < 1e-15);
        }
        // On a node: one weight.
        assert_eq!(s.weights(&[1.0, 1.5, 80.0]), vec![(5, 0, 1.0)]);
    }

    #[test]
    fn k_weights_are_linear_in_log_k() {
        let s = Surrogate {
            axes: vec![],
            chains: vec![empty_chain(vec![1.0, 2.0, 4.0])],
            future: None,
        };
        // sqrt(2) is halfway between 1 and 2 in ln k; above the last node: the last run.
        let w = s.weights(&[2f64.sqrt(), 1.0, 1.0]);
        assert!((w[0].2 - 0.5).abs() < 1e-12 && (w[1].2 - 0.5).abs() < 1e-12);
        assert_eq!(s.weights(&[10.0, 1.0, 1.0]), vec![(0, 2, 1.0)]);
        assert_eq!(s.weights(&[4.0, 1.0, 1.0]), vec![(0, 2, 1.0)]);
    }
}
