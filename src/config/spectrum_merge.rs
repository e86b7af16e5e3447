//! Dust bins: bins of a load spectrum that hold a negligible share of the load cycles,
//! merged into their nearest neighbour so that they cost no dynamic evaluation.
//!
//! A measured history counted into 10 x 5 classes leaves many cells with a few seconds
//! of transient (down to 1e-7 of the revolutions); each bin is a dynamic evaluation per
//! wear update, so these dust bins can double a study's cost for no change in its result.
//!
//! **Rule.** Bins whose share of the revolutions is below `min_share` are the dust; every
//! other bin is a target (when no bin reaches `min_share`, the one with the largest share
//! is the only target). Each dust bin joins the target nearest to it in the plane of
//! torque / T_max and speed / f_max (T_max, f_max: the spectrum's largest torque and
//! speed); of equally near targets, the one of higher torque (the conservative side),
//! then the first. A target and the dust it takes become one bin with
//! - the sum of their shares (revolutions are conserved, so the cycle count is exact);
//! - the revolution-weighted mean torque, T = sum(T_i n_i) / sum(n_i), which conserves
//!   the torque-revolution integral: Archard wear per cycle is linear in the load
//!   (p0 ~ W^1/2 times the band 2a ~ W^1/2, docs/MODEL.md section 10), so the
//!   quasi-static wear of the spectrum is unchanged by the merge;
//! - the speed that conserves the time, f = sum(n_i) / sum(n_i / f_i) (the time at bin i
//!   is n_i / f_i): the time-weighted mean speed, as the load duration distribution
//!   gives each cell.
//!
//! Only the dynamic part of the wear (how the dynamic factor differs between the dust's
//! operating points and its target's) changes, by at most the dust's share of the wear.

use super::operating::SpectrumBin;

/// Largest `min_share`: a tenth of the revolutions. Above it the merge would swallow
/// operating points that carry real wear.
pub const MAX_MERGE_SHARE: f64 = 0.1;

/// The default of `load-spectrum`: bins under 0.1 % of the revolutions are merged. A
/// bin's wear is at most its share of the spectrum's wear times the ratio of its wear rate
/// to the mean, so 0.1 % moves no result by more than its accuracy.
pub const DEFAULT_MERGE_SHARE: f64 = 1e-3;

/// What a merge did.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct Merged {
    /// Bins before the merge.
    pub bins_before: usize,
    /// Dust bins merged into a target.
    pub merged: usize,
    /// Sum of the merged bins' shares of the revolutions, in [0, 1].
    pub merged_share: f64,
}

/// `bins` with every bin below `min_share` of the revolutions merged into its nearest
/// target (module docs), the targets in their original order. `min_share` is in
/// [0, [`MAX_MERGE_SHARE`]] (checked by the caller); 0 returns the bins unchanged.
pub fn merge_small_bins(bins: &[SpectrumBin], min_share: f64) -> (Vec<SpectrumBin>, Merged) {
    let mut merged = Merged {
        bins_before: bins.len(),
        ..Merged::default()
    };
    let is_target: Vec<bool> = {
        let mut t: Vec<bool> = bins.iter().map(|b| b.share >= min_share).collect();
        if !t.contains(&true) {
            if let Some(i) = largest_share(bins) {
                t[i] = true;
            }
        }
        t
    };
    let t_max = bins.iter().fold(0.0_f64, |m, b| m.max(b.torque_nm));
    let f_max = bins.iter().fold(0.0_f64, |m, b| m.max(b.input_speed_hz));
    let scale = |x: f64, max: f64| if max > 0.0 { x / max } else { 0.0 };
    // Per target: sums of n, T n and n / f (revolutions, torque-revolutions, time).
    let mut sums: Vec<[f64; 3]> = bins
        .iter()
        .map(|b| [b.share, b.torque_nm * b.share, b.share / b.input_speed_hz])
        .collect();
    for (i, d) in bins.iter().enumerate().filter(|(i, _)| !is_target[*i]) {
        let distance = |j: usize| {
            let b = &bins[j];
            let dt = scale(b.torque_nm - d.torque_nm, t_max);
            let df = scale(b.input_speed_hz - d.input_speed_hz, f_max);
            dt.hypot(df)
        };
        let nearest = (0..bins.len()).filter(|j| is_target[*j]).min_by(|a, b| {
            distance(*a)
                .total_cmp(&distance(*b))
                .then(bins[*b].torque_nm.total_cmp(&bins[*a].torque_nm))
                .then(a.cmp(b))
        });
        let Some(j) = nearest else { continue };
        let s = sums[i];
        for (k, x) in s.iter().enumerate() {
            sums[j][k] += x;
        }
        merged.merged += 1;
        merged.merged_share += d.share;
    }
    let out = bins
        .iter()
        .enumerate()
        .filter(|(i, _)| is_target[*i])
        .map(|(i, b)| {
            if sums[i][0] == b.share {
                return *b;
            }
            let [n, tn, time] = sums[i];
            SpectrumBin {
                torque_nm: tn / n,
                input_speed_hz: n / time,
                share: n,
            }
        })
        .collect();
    (out, merged)
}

/// Index of the bin with the largest share (the first of equals).
fn largest_share(bins: &[SpectrumBin]) -> Option<usize> {
    (0..bins.len()).reduce(|a, b| if bins[b].share > bins[a].share { b } else { a })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bin(torque_nm: f64, input_speed_hz: f64, share: f64) -> SpectrumBin {
        SpectrumBin {
            torque_nm,
            input_speed_hz,
            share,
        }
    }

    /// A spectrum like a counted history's: three real bins and four of dust.
    fn spectrum() -> Vec<SpectrumBin> {
        vec![
            bin(100.0, 30.0, 0.6),
            bin(12.0, 2.0, 2e-7),
            bin(60.0, 25.0, 0.3),
            bin(95.0, 29.0, 4e-4),
            bin(58.0, 24.0, 6e-4),
            bin(20.0, 10.0, 0.0985),
            bin(21.0, 11.0, 5e-4 - 2e-7),
        ]
    }

    /// Revolutions, torque-revolutions and time summed over the bins: the three integrals
    /// the merge must keep (module docs), computed here from the bins directly.
    fn integrals(b: &[SpectrumBin]) -> [f64; 3] {
        b.iter().fold([0.0; 3], |s, b| {
            [
                s[0] + b.share,
                s[1] + b.torque_nm * b.share,
                s[2] + b.share / b.input_speed_hz,
            ]
        })
    }

    #[test]
    fn keeps_revolutions_torque_revolutions_and_time() {
        let before = spectrum();
        let (after, m) = merge_small_bins(&before, 1e-3);
        assert_eq!((m.bins_before, m.merged, after.len()), (7, 4, 3));
        // Merged shares: 2e-7 + 4e-4 + 6e-4 + (5e-4 - 2e-7), summed here by hand.
        assert!((m.merged_share - 1.5e-3).abs() < 1e-15);
        let (a, b) = (integrals(&before), integrals(&after));
        for k in 0..3 {
            // A few roundings of sums of order 1 (and ~60 for the torque integral).
            assert!(
                (a[k] - b[k]).abs() <= 1e-13 * a[k].abs(),
                "{k}: {a:?} {b:?}"
            );
        }
        assert!(after.iter().all(|b| b.share >= 1e-3));
    }

    #[test]
    fn dust_joins_its_nearest_target() {
        let (after, _) = merge_small_bins(&spectrum(), 1e-3);
        // (95, 29) joins (100, 30): torque (100*0.6 + 95*4e-4) / (0.6 + 4e-4).
        let t0 = (100.0 * 0.6 + 95.0 * 4e-4) / (0.6 + 4e-4);
        assert!((after[0].torque_nm - t0).abs() < 1e-12);
        // (58, 24) joins (60, 25); (12, 2) and (21, 11) join (20, 10).
        assert!((after[1].share - (0.3 + 6e-4)).abs() < 1e-15);
        assert!((after[2].share - (0.0985 + 5e-4)).abs() < 1e-15);
        // The time-conserving speed of (20, 10) with (12, 2) and (21, 11).
        let n = [0.0985, 2e-7, 5e-4 - 2e-7];
        let f = [10.0, 2.0, 11.0];
        let time: f64 = n.iter().zip(f).map(|(n, f)| n / f).sum();
        let speed = n.iter().sum::<f64>() / time;
        assert!((after[2].input_speed_hz - speed).abs() < 1e-12);
    }

    #[test]
    fn zero_share_is_identity_and_a_merge_is_idempotent() {
        let before = spectrum();
        let (same, m) = merge_small_bins(&before, 0.0);
        assert_eq!((same, m.merged), (before.clone(), 0));
        let (once, _) = merge_small_bins(&before, 1e-3);
        let (twice, m2) = merge_small_bins(&once, 1e-3);
        assert_eq!((twice, m2.merged), (once, 0));
    }

    #[test]
    fn with_no_bin_above_the_share_the_largest_takes_all() {
        let bins = vec![
            bin(10.0, 5.0, 0.25),
            bin(20.0, 5.0, 0.4),
            bin(30.0, 5.0, 0.35),
        ];
        let (after, m) = merge_small_bins(&bins, 0.1 * 5.0);
        assert_eq!((after.len(), m.merged), (1, 2));
        assert!((after[0].share - 1.0).abs() < 1e-15);
        assert!((after[0].torque_nm - (2.5 + 8.0 + 10.5)).abs() < 1e-12);
    }

    #[test]
    fn equally_near_targets_favour_the_higher_torque() {
        let bins = vec![
            bin(10.0, 5.0, 0.5),
            bin(30.0, 5.0, 0.4999),
            bin(20.0, 5.0, 1e-4),
        ];
        let (after, _) = merge_small_bins(&bins, 1e-3);
        assert_eq!(after[0], bins[0]);
        assert!((after[1].share - 0.5).abs() < 1e-15);
    }
}
