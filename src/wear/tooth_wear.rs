//! Wear of every tooth of a tooth-resolved mesh on the shared grid, and the sums over
//! teeth that the wear state and the increments both take.

use serde::{Deserialize, Serialize};

/// Wear of every tooth on the shared grid (tooth t's profile at `pinion_m[t]`), m.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ToothWear {
    /// Wear depth of each pinion tooth at each grid point, m (tooth, point).
    pub pinion_m: Vec<Vec<f64>>,
    /// Wear depth of each gear tooth at each grid point, m (tooth, point).
    pub gear_m: Vec<Vec<f64>>,
}

impl ToothWear {
    /// No wear on z1 pinion and z2 gear teeth of `points` grid points.
    pub fn new(points: usize, z1: usize, z2: usize) -> Self {
        Self {
            pinion_m: vec![vec![0.0; points]; z1],
            gear_m: vec![vec![0.0; points]; z2],
        }
    }

    /// Largest depth on any tooth of either gear, m.
    pub fn max_m(&self) -> f64 {
        max_of(&self.pinion_m).max(max_of(&self.gear_m))
    }
}

/// Wear of every face slice of a helical pair (docs/MODEL.md 11.3) on the shared grid:
/// the shape of [`ToothWear`] with the index the face slice j (at y_j = (j + 1/2) b / N
/// from the face end y = 0, `SliceMeshStiffness::positions_m`) instead of the tooth, m
/// (slice, point).
pub type SliceWear = ToothWear;

/// Largest entry of every profile, m (0 for none).
pub(crate) fn max_of(profiles: &[Vec<f64>]) -> f64 {
    profiles.iter().flatten().fold(0.0_f64, |m, x| m.max(*x))
}

/// The deepest point of tooth `tooth`'s profile and the deepest of every other tooth's
/// (`profiles[t]` tooth t's depth along the flank, m): how a faulty tooth's wear is
/// reported beside its gear's other teeth (a gear train's faulty stage, a planetary
/// set's faulty member); None when there is no such tooth.
pub(crate) fn deepest_own_and_others(profiles: &[Vec<f64>], tooth: usize) -> Option<(f64, f64)> {
    let deepest = |p: &[f64]| p.iter().fold(0.0_f64, |a, b| a.max(*b));
    let own = deepest(profiles.get(tooth)?);
    let others = profiles
        .iter()
        .enumerate()
        .filter(|(t, _)| *t != tooth)
        .map(|(_, p)| deepest(p))
        .fold(0.0_f64, f64::max);
    Some((own, others))
}

/// Mean profile of several teeth.
pub(crate) fn mean_profile(profiles: &[Vec<f64>]) -> Vec<f64> {
    let n = profiles.first().map_or(0, Vec::len);
    let z = profiles.len().max(1) as f64;
    (0..n)
        .map(|i| profiles.iter().map(|p| p[i]).sum::<f64>() / z)
        .collect()
}
