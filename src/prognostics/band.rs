//! Percentile bands over an ensemble: the fan charts and the posterior predictive band.

use super::stats::quantile_sorted;
use serde::{Deserialize, Serialize};

/// The percentiles of a band, in percent.
pub(crate) const PERCENTILES: [f64; 5] = [5.0, 25.0, 50.0, 75.0, 95.0];

/// Percentiles of one quantity against cycles over an ensemble.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Band {
    /// Pinion cycle counts of the grid the percentiles are given at.
    pub cycles: Vec<f64>,
    /// `percentiles[i][g]`: percentile `PERCENTILES[i]` at `cycles[g]`; NaN where undetermined.
    pub percentiles: Vec<Vec<f64>>,
    /// Ensemble members with a value at each cycle count.
    pub valid: Vec<usize>,
    /// Members in all.
    pub members: usize,
}

impl Band {
    /// Band of `values[m][g]` (member m, grid point g; None: no value, the run failed
    /// before). With `monotone` (a wear depth, which never decreases), a missing value
    /// lies between the member's last known value and +inf: each percentile is computed
    /// with both ends and kept where they agree, else undetermined (NaN). Otherwise
    /// missing members are left out.
    pub fn of(cycles: &[f64], values: &[Vec<Option<f64>>], monotone: bool) -> Self {
        let n = values.len();
        let mut percentiles = vec![vec![f64::NAN; cycles.len()]; PERCENTILES.len()];
        let mut valid = vec![0; cycles.len()];
        for g in 0..cycles.len() {
            let known: Vec<f64> = values
                .iter()
                .filter_map(|m| m.get(g).copied().flatten())
                .collect();
            valid[g] = known.len();
            let (mut lower, mut upper) = (known.clone(), known);
            if monotone {
                for m in values
                    .iter()
                    .filter(|m| m.get(g).copied().flatten().is_none())
                {
                    let last = m[..g.min(m.len())].iter().rev().find_map(|x| *x);
                    lower.push(last.unwrap_or(f64::NEG_INFINITY));
                }
                upper.resize(n, f64::INFINITY);
            }
            lower.sort_by(f64::total_cmp);
            upper.sort_by(f64::total_cmp);
            for (i, p) in PERCENTILES.iter().enumerate() {
                let a = quantile_sorted(&lower, p / 100.0);
                let b = quantile_sorted(&upper, p / 100.0);
                percentiles[i][g] = if a == b && a.is_finite() { a } else { f64::NAN };
            }
        }
        Self {
            cycles: cycles.to_vec(),
            percentiles,
            valid,
            members: n,
        }
    }

    /// Standard deviation over the members at grid point g (known values only).
    pub fn spread(values: &[Vec<Option<f64>>], g: usize) -> f64 {
        let v: Vec<f64> = values
            .iter()
            .filter_map(|m| m.get(g).copied().flatten())
            .collect();
        if v.len() < 2 {
            return f64::NAN;
        }
        super::stats::std_dev(&v)
    }
}

/// `points` cycle counts evenly spaced from 0 to `cycles`.
pub(crate) fn cycles_grid(cycles: f64, points: usize) -> Vec<f64> {
    let n = points.max(2);
    (0..n).map(|i| cycles * i as f64 / (n - 1) as f64).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_members_bound_the_percentiles_of_a_wear() {
        // At the second grid point, members 1..=4 and one whose run failed after a last
        // known value of 3.5: its value lies in [3.5, inf). The median of (1, 2, 3, 4, x)
        // is 3 for every x >= 3.5: determined. The 95 % point is not.
        let vals: Vec<Vec<Option<f64>>> = vec![
            vec![Some(0.0), Some(1.0)],
            vec![Some(0.0), Some(2.0)],
            vec![Some(0.0), Some(3.0)],
            vec![Some(0.0), Some(4.0)],
            vec![Some(3.5), None],
        ];
        let b = Band::of(&[0.0, 1.0], &vals, true);
        assert_eq!(b.percentiles[2][1], 3.0);
        assert!(b.percentiles[4][1].is_nan());
        // A failure at a small depth (0.5 instead of 3.5) leaves the median open too:
        // x in [0.5, inf) moves it between 2 and 3.
        let mut early = vals.clone();
        early[4][0] = Some(0.5);
        assert!(Band::of(&[0.0, 1.0], &early, true).percentiles[2][1].is_nan());
        // Left out (not monotone): the median of (1, 2, 3, 4) is 2.5.
        let b = Band::of(&[0.0, 1.0], &vals, false);
        assert_eq!((b.percentiles[2][1], b.valid[1]), (2.5, 4));
    }
}
