//! Accumulated wear of both profiles on the shared grid, and the gap it opens.

use crate::dynamics::excitation::PairGap;
use crate::geometry::GearPair;
use crate::geometry::ProfileGrid;
use crate::stiffness::mesh::MeshStiffness;
use serde::{Deserialize, Serialize};

use super::archard::WearIncrement;
use super::tooth_wear::{max_of, mean_profile, SliceWear, ToothWear};

/// Accumulated wear depth at each grid point (pinion point i and its conjugate gear
/// point i), m, after `cycles` pinion cycles.
///
/// With a tooth-resolved mesh every tooth has its own profile (`teeth`); `pinion_m` and
/// `gear_m` are then the mean over the teeth of each gear.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct WearState {
    /// Pinion load cycles accumulated so far.
    pub cycles: f64,
    /// Wear depth of the pinion flank at each grid point, m.
    pub pinion_m: Vec<f64>,
    /// Wear depth of the gear flank at each grid point, m.
    pub gear_m: Vec<f64>,
    /// Per-tooth profiles of a tooth-resolved mesh; `None` when all teeth wear alike.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub teeth: Option<ToothWear>,
    /// Per-slice profiles of a helical pair (docs/MODEL.md 11.3); `pinion_m` and `gear_m`
    /// are then the mean over the face slices. `None` for a spur pair.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub slices: Option<SliceWear>,
}

impl WearState {
    /// An unworn state (0 cycles, zero depth) on a grid of `points` points.
    pub fn new(points: usize) -> Self {
        Self {
            cycles: 0.0,
            pinion_m: vec![0.0; points],
            gear_m: vec![0.0; points],
            teeth: None,
            slices: None,
        }
    }

    /// No wear on any of the `slices` face slices of a helical pair (`points` grid points).
    pub fn per_slice(points: usize, slices: usize) -> Self {
        Self {
            slices: Some(SliceWear::new(points, slices, slices)),
            ..Self::new(points)
        }
    }

    /// No wear on every tooth of z1 pinion and z2 gear teeth (a tooth-resolved run).
    pub fn per_tooth(points: usize, z1: usize, z2: usize) -> Self {
        Self {
            teeth: Some(ToothWear::new(points, z1, z2)),
            ..Self::new(points)
        }
    }

    /// Paper eq. (17): hold the per-cycle increment for `cycles` cycles (every tooth its
    /// own when both state and increment are per tooth, every face slice its own when
    /// both are per slice).
    pub fn advance(&mut self, inc: &WearIncrement, cycles: f64) {
        let add = |h: &mut [f64], d: &[f64]| {
            for (h, d) in h.iter_mut().zip(d) {
                *h += cycles * d;
            }
        };
        // Each profile of a per-tooth or per-slice state advanced by its own increment;
        // the common profiles become their means.
        let each = |own: &mut ToothWear, by: &ToothWear| {
            for (h, d) in own.pinion_m.iter_mut().zip(&by.pinion_m) {
                add(h, d);
            }
            for (h, d) in own.gear_m.iter_mut().zip(&by.gear_m) {
                add(h, d);
            }
            (mean_profile(&own.pinion_m), mean_profile(&own.gear_m))
        };
        let means = match (&mut self.slices, &inc.slices, &mut self.teeth, &inc.teeth) {
            (Some(s), Some(i), _, _) => Some(each(s, i)),
            (_, _, Some(t), Some(i)) => Some(each(t, i)),
            _ => None,
        };
        match means {
            Some((p, g)) => (self.pinion_m, self.gear_m) = (p, g),
            None => {
                add(&mut self.pinion_m, &inc.pinion_m);
                add(&mut self.gear_m, &inc.gear_m);
            }
        }
        self.cycles += cycles;
    }

    /// Largest pinion wear depth, m (over every tooth when per tooth, every face slice
    /// when per slice).
    pub fn max_pinion_m(&self) -> f64 {
        match (&self.teeth, &self.slices) {
            (Some(t), _) => max_of(&t.pinion_m),
            (None, Some(s)) => max_of(&s.pinion_m),
            (None, None) => self.pinion_m.iter().fold(0.0_f64, |m, x| m.max(*x)),
        }
    }

    /// Largest gear wear depth, m (over every tooth when per tooth, every face slice
    /// when per slice).
    pub fn max_gear_m(&self) -> f64 {
        match (&self.teeth, &self.slices) {
            (Some(t), _) => max_of(&t.gear_m),
            (None, Some(s)) => max_of(&s.gear_m),
            (None, None) => self.gear_m.iter().fold(0.0_f64, |m, x| m.max(*x)),
        }
    }

    /// Gap a pair must close at each contact position: pinion wear plus the wear of the
    /// conjugate gear point (both measured along the profile normal = line of action).
    /// Each flank's profile is kept as well: a tip corner beyond the path of contact
    /// loads the two flanks at points that are not conjugate (the mate's flank where the
    /// corner touches it, the corner's own flank at its tip), each with its own wear
    /// (`dynamics::contact_path`; docs/MODEL.md 4.2), as the tooth-resolved mesh takes it.
    pub fn pair_gap(&self, grid: &ProfileGrid) -> PairGap {
        PairGap::from_flanks(
            grid.rho_pinion_m[0],
            grid.spacing_m,
            self.pinion_m.clone(),
            self.gear_m.clone(),
        )
    }

    /// The same wear shape scaled so that the maximum pinion depth is `target_m`.
    pub(crate) fn scaled_to_max_pinion(&self, target_m: f64) -> Self {
        let m = self.max_pinion_m();
        let f = if m > 0.0 { target_m / m } else { 0.0 };
        let scale = |v: &[f64]| v.iter().map(|x| x * f).collect::<Vec<_>>();
        Self {
            cycles: self.cycles * f,
            pinion_m: scale(&self.pinion_m),
            gear_m: scale(&self.gear_m),
            teeth: self.teeth.as_ref().map(|t| ToothWear {
                pinion_m: t.pinion_m.iter().map(|p| scale(p)).collect(),
                gear_m: t.gear_m.iter().map(|p| scale(p)).collect(),
            }),
            slices: self.slices.as_ref().map(|t| SliceWear {
                pinion_m: t.pinion_m.iter().map(|p| scale(p)).collect(),
                gear_m: t.gear_m.iter().map(|p| scale(p)).collect(),
            }),
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
