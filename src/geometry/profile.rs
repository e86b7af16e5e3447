//! Discretisation of the active profiles for the wear bookkeeping.
//!
//! Point i of the grid is one position on the path of contact, rho1_i uniform from
//! rho_A to rho_E. It names a pinion profile point (radius of curvature rho1_i) and the
//! gear profile point that meets it (rho2_i = N1N2 - rho1_i), so the two profiles share
//! one index and conjugate points never need interpolating.

use super::internal::InternalPair;
use super::pair::GearPair;

/// Points along the path of contact (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileGrid {
    /// Pinion radius of curvature at each point, m (ascending).
    pub rho_pinion_m: Vec<f64>,
    /// Gear radius of curvature at each point, m (descending).
    pub rho_gear_m: Vec<f64>,
    /// Pinion radius at each point, m.
    pub radius_pinion_m: Vec<f64>,
    /// Gear radius at each point, m.
    pub radius_gear_m: Vec<f64>,
    /// Spacing along the line of action, m.
    pub spacing_m: f64,
}

impl ProfileGrid {
    /// `n` points (n >= 2) from the start to the end of contact.
    pub fn new(pair: &GearPair, n: usize) -> Self {
        let n = n.max(2);
        let spacing = pair.path_length_m() / (n - 1) as f64;
        let rho1: Vec<f64> = (0..n)
            .map(|i| pair.rho_start_m + spacing * i as f64)
            .collect();
        let rho2: Vec<f64> = rho1.iter().map(|r| pair.rho_gear(*r)).collect();
        Self {
            radius_pinion_m: rho1.iter().map(|r| pair.pinion.radius_at_rho(*r)).collect(),
            radius_gear_m: rho2.iter().map(|r| pair.gear.radius_at_rho(*r)).collect(),
            rho_pinion_m: rho1,
            rho_gear_m: rho2,
            spacing_m: spacing,
        }
    }

    /// `n` points (n >= 2) on the path of contact of a planet (pinion) in a ring (gear),
    /// rho1 uniform from the ring's tip to the planet's tip; the ring's point conjugate to
    /// rho1 has radius of curvature rho2 = rho1 + N1N2 (`InternalPair::rho_ring`) and
    /// radius sqrt(rho2^2 + r_b2^2) (an involute's).
    pub fn internal(pair: &InternalPair, n: usize) -> Self {
        let n = n.max(2);
        let spacing = (pair.rho_end_m - pair.rho_start_m) / (n - 1) as f64;
        let rho1: Vec<f64> = (0..n)
            .map(|i| pair.rho_start_m + spacing * i as f64)
            .collect();
        let rho2: Vec<f64> = rho1.iter().map(|r| pair.rho_ring(*r)).collect();
        let rb2 = pair.ring.base_radius_m;
        Self {
            radius_pinion_m: rho1.iter().map(|r| pair.planet.radius_at_rho(*r)).collect(),
            radius_gear_m: rho2.iter().map(|r| r.hypot(rb2)).collect(),
            rho_pinion_m: rho1,
            rho_gear_m: rho2,
            spacing_m: spacing,
        }
    }

    /// Number of points on the grid.
    pub fn len(&self) -> usize {
        self.rho_pinion_m.len()
    }

    /// Whether the grid has no points (never, for a grid built by [`ProfileGrid::new`]).
    pub fn is_empty(&self) -> bool {
        self.rho_pinion_m.is_empty()
    }

    /// Linear interpolation of a per-point quantity at LOA position rho1 (clamped).
    pub fn interpolate(&self, values: &[f64], rho1_m: f64) -> f64 {
        let n = self.len();
        let u = ((rho1_m - self.rho_pinion_m[0]) / self.spacing_m).clamp(0.0, (n - 1) as f64);
        let i = (u.floor() as usize).min(n - 2);
        let t = u - i as f64;
        values[i] * (1.0 - t) + values[i + 1] * t
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::GearSection;

    #[test]
    fn ends_are_tip_and_start_of_active_profile() {
        let p = GearPair::from_case(&GearSection::default()).unwrap();
        let g = ProfileGrid::new(&p, 51);
        // Last pinion point is its tip; first gear point is the gear tip (exact geometry).
        assert!((g.radius_pinion_m[50] - p.pinion.tip_radius_m).abs() < 1e-12);
        assert!((g.radius_gear_m[0] - p.gear.tip_radius_m).abs() < 1e-12);
        // Conjugate points: rho1 + rho2 = N1N2 at every point.
        for i in 0..51 {
            assert!((g.rho_pinion_m[i] + g.rho_gear_m[i] - p.loa_length_m).abs() < 1e-15);
        }
    }

    #[test]
    fn interpolation_is_exact_for_linear_data() {
        let p = GearPair::from_case(&GearSection::default()).unwrap();
        let g = ProfileGrid::new(&p, 11);
        let v: Vec<f64> = g.rho_pinion_m.iter().map(|r| 3.0 * r + 1.0).collect();
        let r = 0.3 * p.rho_start_m + 0.7 * p.rho_end_m;
        assert!((g.interpolate(&v, r) - (3.0 * r + 1.0)).abs() < 1e-12);
    }
}
