//! Accumulated wear of both profiles on the shared grid, and the gap it opens.

use crate::dynamics::excitation::PairGap;
use crate::geometry::GearPair;
use crate::geometry::ProfileGrid;
use crate::stiffness::mesh::MeshStiffness;
use serde::{Deserialize, Serialize};

use super::archard::WearIncrement;

/// Accumulated wear depth at each grid point (pinion point i and its conjugate gear
/// point i), m, after `cycles` pinion cycles.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct WearState {
    pub cycles: f64,
    pub pinion_m: Vec<f64>,
    pub gear_m: Vec<f64>,
}

impl WearState {
    pub fn new(points: usize) -> Self {
        Self {
            cycles: 0.0,
            pinion_m: vec![0.0; points],
            gear_m: vec![0.0; points],
        }
    }

    /// Paper eq. (17): hold the per-cycle increment for `cycles` cycles.
    pub fn advance(&mut self, inc: &WearIncrement, cycles: f64) {
        for (h, d) in self.pinion_m.iter_mut().zip(&inc.pinion_m) {
            *h += cycles * d;
        }
        for (h, d) in self.gear_m.iter_mut().zip(&inc.gear_m) {
            *h += cycles * d;
        }
        self.cycles += cycles;
    }

    pub fn max_pinion_m(&self) -> f64 {
        self.pinion_m.iter().fold(0.0_f64, |m, x| m.max(*x))
    }

    pub fn max_gear_m(&self) -> f64 {
        self.gear_m.iter().fold(0.0_f64, |m, x| m.max(*x))
    }

    /// Gap a pair must close at each contact position: pinion wear plus the wear of the
    /// conjugate gear point (both measured along the profile normal = line of action).
    pub fn pair_gap(&self, grid: &ProfileGrid) -> PairGap {
        let g = self
            .pinion_m
            .iter()
            .zip(&self.gear_m)
            .map(|(a, b)| a + b)
            .collect();
        PairGap::new(grid.rho_pinion_m[0], grid.spacing_m, g)
    }

    /// The same wear shape scaled so that the maximum pinion depth is `target_m`.
    pub fn scaled_to_max_pinion(&self, target_m: f64) -> Self {
        let m = self.max_pinion_m();
        let f = if m > 0.0 { target_m / m } else { 0.0 };
        Self {
            cycles: self.cycles * f,
            pinion_m: self.pinion_m.iter().map(|x| x * f).collect(),
            gear_m: self.gear_m.iter().map(|x| x * f).collect(),
        }
    }
}

/// Geometric transmission error from wear over one mesh period, m: the gap of the pairs
/// in contact weighted by their stiffness, e(theta) = sum k_i g_i / sum k_i (the single
/// e_t of paper eq. 2 that gives the same force as the per-pair gaps when all touch).
/// Returned as (mesh phase rad, error m) at `n` phases.
pub fn wear_transmission_error(
    pair: &GearPair,
    mesh: &MeshStiffness,
    gap: &PairGap,
    n: usize,
) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let phase = pair.mesh_angle_rad() * i as f64 / n as f64;
            let (mut kg, mut k) = (0.0, 0.0);
            for (_, rho1) in pair.pairs_in_contact(phase) {
                let ki = mesh.pair_stiffness_n_per_m(rho1);
                kg += ki * gap.at(rho1).0;
                k += ki;
            }
            (phase, if k > 0.0 { kg / k } else { 0.0 })
        })
        .collect()
}
