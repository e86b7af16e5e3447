//! What each bin of a spectrum did: the wear it added (per profile point and in total),
//! the bins ranked by their share of the wear, the dynamic factor of each bin as the
//! flanks wear, and the run as one sequence of updates for the single-point readers
//! (tables, figures, prognostics).

use super::wear::{SpectrumRecord, SpectrumRun};
use crate::study::wear_loop::{UpdateRecord, WearRun};
use serde::Serialize;

/// One update of `run` as a single-point update: the shared wear state, the spectrum's
/// per-cycle wear sum_i s_i inc_i (so wear between updates grows exactly as in the run),
/// and the response of bin `observed` (the monitoring bin: what a sensor records at its
/// reference condition).
pub(crate) fn combined_record(
    run: &SpectrumRun,
    r: &SpectrumRecord,
    observed: usize,
) -> UpdateRecord {
    let inc = r.increment(&run.shares);
    let b = &r.bins[observed.min(r.bins.len() - 1)];
    UpdateRecord {
        wear: r.wear.clone(),
        roughness_um: r.roughness_um,
        summary: b.summary,
        increment_pinion_m: inc.pinion_m,
        increment_gear_m: inc.gear_m,
        increment_teeth: inc.teeth,
        increment_slices: inc.slices,
        path_rho1_m: b.path_rho1_m.clone(),
        path_load_n: b.path_load_n.clone(),
        end_state: None,
    }
}

/// The run as single-point updates (`combined_record` of each).
pub fn combined_run(run: &SpectrumRun, observed: usize) -> WearRun {
    WearRun {
        mode: run.mode,
        records: run
            .records
            .iter()
            .map(|r| combined_record(run, r, observed))
            .collect(),
        stopped: run.stopped.clone(),
    }
}

/// The run as seen at bin `i`: the shared wear states with that bin's responses and its
/// per-cycle wear (per cycle of the bin).
pub fn bin_run(run: &SpectrumRun, i: usize) -> WearRun {
    WearRun {
        mode: run.mode,
        records: run.records.iter().map(|r| r.bins[i].clone()).collect(),
        stopped: run.stopped.clone(),
    }
}

/// Trapezoidal area under a depth profile on a uniform grid (units of depth x spacing;
/// the spacing cancels in shares).
pub(crate) fn area(h: &[f64]) -> f64 {
    match h.len() {
        0 => 0.0,
        1 => h[0],
        n => h.iter().sum::<f64>() - 0.5 * (h[0] + h[n - 1]),
    }
}

/// A share, 0 when there is nothing to share.
pub(crate) fn share(part: f64, whole: f64) -> f64 {
    if whole > 0.0 {
        part / whole
    } else {
        0.0
    }
}

/// What one bin contributed by the end of a run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BinWear {
    /// 1-based, as in the case.
    pub bin: usize,
    /// Share of the pinion load cycles the bin takes (its spectrum share s_i).
    pub share_of_cycles: f64,
    /// Share of the worn area of the pinion's profile (depth integrated along the path of
    /// contact), and of the gear's.
    pub share_of_pinion_wear: f64,
    /// Share of the worn area of the gear's profile the bin added.
    pub share_of_gear_wear: f64,
    /// Share of the wear at the point of the pinion's maximum wear depth.
    pub share_at_max_pinion_wear: f64,
    /// Largest depth this bin added on the pinion, um.
    pub max_pinion_added_um: f64,
    /// Wear share over cycle share: above 1, the bin wears more than its time suggests.
    pub wear_intensity: f64,
}

/// Each bin's contribution at the last record, ranked by share of the pinion's wear
/// (largest first; ties in bin order).
pub fn ranking(run: &SpectrumRun) -> Vec<BinWear> {
    let Some(last) = run.records.last() else {
        return Vec::new();
    };
    let total_p = area(&last.wear.pinion_m);
    let total_g = area(&last.wear.gear_m);
    let imax = last.wear.pinion_m.iter().enumerate().fold(0, |b, (i, x)| {
        if *x > last.wear.pinion_m[b] {
            i
        } else {
            b
        }
    });
    let at_max = last.wear.pinion_m.get(imax).copied().unwrap_or(0.0);
    let mut out: Vec<BinWear> = (0..last.by_bin_pinion_m.len())
        .map(|i| {
            let p = &last.by_bin_pinion_m[i];
            let s = share(area(p), total_p);
            BinWear {
                bin: i + 1,
                share_of_cycles: run.shares[i],
                share_of_pinion_wear: s,
                share_of_gear_wear: share(area(&last.by_bin_gear_m[i]), total_g),
                share_at_max_pinion_wear: share(p.get(imax).copied().unwrap_or(0.0), at_max),
                max_pinion_added_um: p.iter().fold(0.0_f64, |m, x| m.max(*x)) * 1e6,
                wear_intensity: share(s, run.shares[i]),
            }
        })
        .collect();
    out.sort_by(|a, b| {
        b.share_of_pinion_wear
            .total_cmp(&a.share_of_pinion_wear)
            .then(a.bin.cmp(&b.bin))
    });
    out
}

/// Dynamic factor (max / mean mesh force) of every bin at every update: one row per
/// update, one column per bin.
pub(crate) fn dynamic_factors(run: &SpectrumRun) -> Vec<Vec<f64>> {
    run.records
        .iter()
        .map(|r| r.bins.iter().map(|b| b.summary.dynamic_factor).collect())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn area_is_the_trapezoid_rule() {
        // Uniform depth 1 over 3 points (2 spacings): area 2; a triangle 0, 1, 0: area 1.
        assert_eq!(area(&[1.0, 1.0, 1.0]), 2.0);
        assert_eq!(area(&[0.0, 1.0, 0.0]), 1.0);
    }
}
