//! Reading the surrogate of a change of duty (`surrogate` module docs): the first phase
//! from the node at or above k at the same exposure, the second at the same exposure
//! since the switch, weighted linearly in k between the nodes around k.

use super::forward::{Crossing, FutureDuty};
use super::prior::Theta;
use super::quantity::Quantity;
use super::surrogate::{bisect_crossing, Surrogate};

/// One run read for a sample: chain, run, weight, and the run's cycles.
type Reading = (usize, usize, f64, f64);

impl Surrogate {
    /// The runs behind `theta` at `cycles` and where to read them.
    fn readings(&self, f: &FutureDuty, theta: &Theta, cycles: f64) -> Vec<Reading> {
        let k = theta[0];
        let n0 = f.from_cycles;
        let w = self.weights(theta);
        if cycles <= n0 {
            // Per chain of the other axes, the node at or above k alone.
            let mut out: Vec<Reading> = Vec::new();
            for (c, r, wt) in w {
                match out.iter_mut().find(|x| x.0 == c) {
                    Some(x) => {
                        x.2 += wt;
                        x.1 = x.1.max(r);
                    }
                    None => out.push((c, r, wt, 0.0)),
                }
            }
            for x in &mut out {
                x.3 = cycles * k / self.chains[x.0].k[x.1];
            }
            return out;
        }
        w.into_iter()
            .map(|(c, r, wt)| (c, r, wt, n0 + (cycles - n0) * k / self.chains[c].k[r]))
            .collect()
    }

    pub(super) fn value_after_change(
        &self,
        f: &FutureDuty,
        q: Quantity,
        theta: &Theta,
        cycles: f64,
    ) -> Option<f64> {
        self.readings(f, theta, cycles)
            .iter()
            .try_fold(0.0, |acc, (c, r, w, x)| {
                Some(acc + w * self.chains[*c].runs[*r].value(q, *x)?)
            })
    }

    pub(super) fn valid_until_after_change(&self, f: &FutureDuty, theta: &Theta) -> f64 {
        let k = theta[0];
        let n0 = f.from_cycles;
        self.weights(theta)
            .iter()
            .map(|(c, r, _)| {
                let v = self.chains[*c].runs[*r].valid_until();
                let kj = self.chains[*c].k[*r];
                if v >= n0 {
                    n0 + (v - n0) * kj / k
                } else {
                    v * kj / k
                }
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// First cycles where the surrogate's maximum pinion wear reaches the limit: bisection
    /// on the wear, non-decreasing in cycles within each phase (each run's is).
    pub(super) fn cycles_to_wear_after_change(&self, theta: &Theta, limit_um: f64) -> Crossing {
        let wear = |n: f64| self.value(Quantity::MaxWearPinion, theta, n);
        let end = self.valid_until(theta);
        let reached_by_end = matches!(wear(end), Some(v) if v >= limit_um);
        if !reached_by_end {
            let failed = self
                .weights(theta)
                .iter()
                .any(|(c, r, _)| self.chains[*c].runs[*r].failure.is_some());
            return if failed {
                Crossing::Unknown
            } else {
                Crossing::NotReached
            };
        }
        if matches!(wear(0.0), Some(v) if v >= limit_um) {
            return Crossing::Reached(0.0);
        }
        bisect_crossing(&wear, limit_um, 0.0, end)
    }
}
