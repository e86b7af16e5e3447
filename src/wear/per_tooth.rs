//! Archard wear of every tooth from its own contact history over the excitation period
//! of a tooth-resolved mesh.
//!
//! The recorded response covers P mesh periods; each path sample carries its engagement,
//! its mesh cycle modulo P. Engagement e is one pass of a pair of teeth through the path
//! of contact; its samples sorted by rho1 give that pass's Archard increments exactly as
//! [`super::per_cycle_wear`] gives them for the one pass of identical teeth (the gear's
//! with the factor z1/z2 of eq. 17).
//!
//! Over the hunting period H = lcm(z1, z2, P) mesh cycles, pinion tooth a meets the gear in
//! cycles n = a, a + z1, ... (H / z1 of them, one per pinion revolution) and gear tooth b
//! in n = b, b + z2, ... (H / z2, z1/z2 per pinion revolution); cycle n is engagement
//! n mod P. A single pair's P divides lcm(z1, z2), so H is its hunting period; a stage of
//! a gear train repeats over the train's period, which may hold more of its mesh periods
//! than its own hunting period (docs/MODEL.md 9.10), and H then spans that period too, so
//! that each tooth's engagements are each counted equally often. Per pinion cycle
//! (revolution), tooth a wears by the mean of its
//! engagements' pinion increments, tooth b by the mean of its engagements' gear
//! increments (which carry z1/z2). The means run over the distinct engagements in
//! ascending order, each of which occurs equally often, so teeth that meet the same
//! engagements get bit-identical wear, and with P = 1 every tooth gets exactly the
//! increment of identical teeth.

use super::archard::{per_cycle_wear, WearIncrement};
use super::tooth_wear::{mean_profile, ToothWear};
use crate::dynamics::response::PathSample;
use crate::dynamics::tooth_mesh::lcm;
use crate::geometry::ProfileGrid;

/// The distinct engagements (ascending) of the tooth meeting in cycles n = tooth + j z
/// over the hunting period `hunting` of an excitation of `periods` mesh periods.
pub(crate) fn engagements_of(tooth: usize, z: usize, hunting: usize, periods: usize) -> Vec<usize> {
    let mut e: Vec<usize> = (tooth..hunting).step_by(z).map(|n| n % periods).collect();
    e.sort_unstable();
    e.dedup();
    e
}

/// Per-cycle wear of every tooth (module docs) from a response's path over `periods`
/// mesh periods of this mesh (samples tagged with their engagement, their mesh cycle
/// modulo `periods`), z1 pinion and z2 gear teeth, wear coefficient `k` (m^2/N). The
/// common profiles are the means over teeth.
pub fn per_tooth_wear(
    grid: &ProfileGrid,
    path: &[PathSample],
    periods: usize,
    z1: usize,
    z2: usize,
    k: f64,
) -> WearIncrement {
    let periods = periods.max(1);
    let mut by_engagement: Vec<Vec<PathSample>> = vec![Vec::new(); periods];
    for s in path {
        by_engagement[s.cycle.rem_euclid(periods as i64) as usize].push(*s);
    }
    let ratio = z1 as f64 / z2 as f64;
    let inc: Vec<WearIncrement> = by_engagement
        .iter_mut()
        .map(|samples| {
            samples.sort_by(|a, b| a.rho1_m.total_cmp(&b.rho1_m));
            per_cycle_wear(grid, samples, k, ratio)
        })
        .collect();
    // lcm(z1, z2) for a single pair (P divides it); with P, a train stage's.
    let hunting = lcm(lcm(z1, z2), periods);
    let mean = |engagements: &[usize], pick: &dyn Fn(&WearIncrement) -> &Vec<f64>| {
        let n = grid.len();
        let m = engagements.len().max(1) as f64;
        let mut sum = vec![0.0; n];
        for e in engagements {
            for (s, x) in sum.iter_mut().zip(pick(&inc[*e])) {
                *s += x;
            }
        }
        sum.iter().map(|s| s / m).collect::<Vec<f64>>()
    };
    let teeth = ToothWear {
        pinion_m: (0..z1)
            .map(|a| mean(&engagements_of(a, z1, hunting, periods), &|w| &w.pinion_m))
            .collect(),
        gear_m: (0..z2)
            .map(|b| mean(&engagements_of(b, z2, hunting, periods), &|w| &w.gear_m))
            .collect(),
    };
    WearIncrement {
        pinion_m: mean_profile(&teeth.pinion_m),
        gear_m: mean_profile(&teeth.gear_m),
        sliding_pinion_m: Vec::new(),
        sliding_gear_m: Vec::new(),
        teeth: Some(teeth),
        slices: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_tooth_meets_its_own_engagements() {
        // 19/31, only the pinion's teeth differ (P = 19): pinion tooth a meets only
        // engagement a; every gear tooth meets all 19 (the pair is coprime).
        assert_eq!(engagements_of(4, 19, 589, 19), vec![4]);
        assert_eq!(engagements_of(7, 31, 589, 19), (0..19).collect::<Vec<_>>());
        // Both differ (P = 589): tooth a meets 31 engagements, a + 19 j.
        let e = engagements_of(2, 19, 589, 589);
        assert_eq!(e.len(), 31);
        assert!(e.iter().all(|n| n % 19 == 2));
        // Identical teeth (P = 1): everyone meets engagement 0.
        assert_eq!(engagements_of(5, 31, 589, 1), vec![0]);
        // A hunting-free pair 20/40: gear tooth b meets pinion teeth b mod 20 only.
        assert_eq!(engagements_of(3, 40, 40, 40), vec![3]);
    }
}
