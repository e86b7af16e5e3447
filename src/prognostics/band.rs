//! Percentile bands over an ensemble: the fan charts and the posterior predictive band.

use super::stats::quantile_sorted;
use serde::{Deserialize, Serialize};

/// The percentiles of a band, in percent.
pub const PERCENTILES: [f64; 5] = [5.0, 25.0, 50.0, 75.0, 95.0];

/// Percentiles of one quantity against cycles over an ensemble.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Band {
    pub cycles: Vec<f64>,
    /// percentiles[i][g]: percentile PERCENTILES[i] at cycles[g]; NaN where undetermined.
    pub percentiles: Vec<Vec<f64>>,
    /// Ensemble members with a value at each cycle count.
    pub valid: Vec<usize>,
    /// Members in all.
    pub members: usize,
}

impl Band {
    /// Band of `values[m][g]` (member m, grid point g; None: no value, the run failed
    /// before). With `unknown_is_above`, a missing value counts as larger than every
    /// known one (true of a wear depth, which never decreases, past a failure that
    /// happened at a larger depth): percentiles that fall among them are undetermined
    /// (NaN). Otherwise missing members are left out.
    pub fn of(cycles: &[f64], values: &[Vec<Option<f64>>], unknown_is_above: bool) -> Self {
        let n = values.len();
        let mut percentiles = vec![vec![f64::NAN; cycles.len()]; PERCENTILES.len()];
        let mut valid = vec![0; cycles.len()];
        for g in 0..cycles.len() {
            let mut v: Vec<f64> = values
                .iter()
                .filter_map(|m| m.get(g).copied().flatten())
                .collect();
            valid[g] = v.len();
            if unknown_is_above {
                v.resize(n, f64::INFINITY);
            }
            v.sort_by(f64::total_cmp);
            for (i, p) in PERCENTILES.iter().enumerate() {
                let q = quantile_sorted(&v, p / 100.0);
                percentiles[i][g] = if q.is_finite() { q } else { f64::NAN };
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
pub fn cycles_grid(cycles: f64, points: usize) -> Vec<f64> {
    let n = points.max(2);
    (0..n).map(|i| cycles * i as f64 / (n - 1) as f64).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_members_sit_above_for_wear() {
        // Members 1..=4 and one failed: as a wear, the failed one is above all; the
        // median of (1, 2, 3, 4, inf) is 3 and the 95 % point is undetermined.
        let vals: Vec<Vec<Option<f64>>> = vec![
            vec![Some(1.0)],
            vec![Some(2.0)],
            vec![Some(3.0)],
            vec![Some(4.0)],
            vec![None],
        ];
        let b = Band::of(&[0.0], &vals, true);
        assert_eq!(b.percentiles[2][0], 3.0);
        assert!(b.percentiles[4][0].is_nan());
        // Left out: the median of (1, 2, 3, 4) is 2.5.
        let b = Band::of(&[0.0], &vals, false);
        assert_eq!((b.percentiles[2][0], b.valid[0]), (2.5, 4));
    }
}
