//! Surface kinematics at a tooth contact: rolling, sliding and the sliding distance a
//! flank point covers per passage through the Hertzian band.
//!
//! At the contact point both flanks move in the same direction perpendicular to the line
//! of action (LOA), at the speeds of paper eq. (5): `u_p = omega_p rho1`, `u_g = omega_g rho2`
//! (m/s), `rho1`, `rho2` the radii of curvature there (m), `omega` in rad/s. Positive means
//! the sense in which the driven mesh rolls (pinion turning forward).
//!
//! Allocation-free and cheap: used inside the dynamics right-hand side and by the wear model.

/// Surface speeds of the two flanks at one contact point, m/s.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SurfaceKinematics {
    /// `u_p = omega_p rho1`, m/s (paper eq. 5).
    pub pinion_velocity_m_per_s: f64,
    /// `u_g = omega_g rho2`, m/s (paper eq. 5).
    pub gear_velocity_m_per_s: f64,
}

/// Sliding distance per passage through the contact of a point on each flank, m.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SlidingDistances {
    /// Sliding distance of a point on the pinion flank, m.
    pub pinion_m: f64,
    /// Sliding distance of a point on the gear flank, m.
    pub gear_m: f64,
}

impl SurfaceKinematics {
    /// From the angular speeds (rad/s) and the radii of curvature at the contact (m).
    pub fn new(
        omega_pinion_rad_per_s: f64,
        omega_gear_rad_per_s: f64,
        rho1_m: f64,
        rho2_m: f64,
    ) -> Self {
        Self {
            pinion_velocity_m_per_s: omega_pinion_rad_per_s * rho1_m,
            gear_velocity_m_per_s: omega_gear_rad_per_s * rho2_m,
        }
    }

    /// Sliding velocity of the pinion surface relative to the gear surface,
    /// `u_s = u_p - u_g`, m/s (paper, text after eq. 5). Negative on the pinion's
    /// dedendum (approach), positive on its addendum (recess), zero at the pitch point.
    pub fn sliding_velocity_m_per_s(&self) -> f64 {
        self.pinion_velocity_m_per_s - self.gear_velocity_m_per_s
    }

    /// Entraining (rolling) velocity `V_e = (u_p + u_g) / 2`, m/s (Xu et al. 2007; paper eq. 9).
    pub fn entraining_velocity_m_per_s(&self) -> f64 {
        0.5 * (self.pinion_velocity_m_per_s + self.gear_velocity_m_per_s)
    }

    /// Slide-to-roll ratio `SR = 2 (u_p - u_g) / (u_p + u_g)` (paper eq. 9), dimensionless.
    /// Zero when there is no rolling (`u_p + u_g = 0`, e.g. at rest) instead of NaN or
    /// infinity: friction models then see no sliding.
    pub fn slide_to_roll_ratio(&self) -> f64 {
        let sum = self.pinion_velocity_m_per_s + self.gear_velocity_m_per_s;
        let sr = 2.0 * self.sliding_velocity_m_per_s() / sum;
        if sr.is_finite() {
            sr
        } else {
            0.0
        }
    }

    /// Single-point-observation sliding distances per passage through a band of
    /// half-width `a` (Flodin & Andersson, Wear 207 (1997) 16; docs/PAPER_NOTES.md, "Wear"):
    /// a flank point stays in the band for `2a / |u|` and slides `|u_p - u_g|` meanwhile, so
    /// `s_p = 2a |u_p - u_g| / |u_p|`, `s_g = 2a |u_p - u_g| / |u_g|` (m).
    ///
    /// A flank that does not move (`u = 0`, contact at its base circle) never passes
    /// through the band; its distance is returned as 0 rather than infinity.
    pub fn sliding_distances_m(&self, half_width_m: f64) -> SlidingDistances {
        let slide = 2.0 * half_width_m.max(0.0) * self.sliding_velocity_m_per_s().abs();
        let per = |u: f64| {
            let s = slide / u.abs();
            if s.is_finite() {
                s
            } else {
                0.0
            }
        };
        SlidingDistances {
            pinion_m: per(self.pinion_velocity_m_per_s),
            gear_m: per(self.gear_velocity_m_per_s),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::GearSection;
    use crate::geometry::pair::GearPair;
    use approx::assert_relative_eq;
    use std::f64::consts::PI;

    fn paper() -> GearPair {
        GearPair::from_case(&GearSection::default()).expect("paper pair is valid")
    }

    /// Pinion at 30 Hz; gear at the kinematic ratio omega_g = omega_p z1 / z2.
    fn speeds(p: &GearPair) -> (f64, f64) {
        let wp = 2.0 * PI * 30.0;
        (wp, wp / p.ratio())
    }

    /// At the pitch point rho1/rho2 = z1/z2 and omega_p/omega_g = z2/z1: pure rolling.
    #[test]
    fn no_sliding_at_pitch_point() {
        let p = paper();
        let (wp, wg) = speeds(&p);
        let k = SurfaceKinematics::new(wp, wg, p.rho_pitch_m, p.rho_gear(p.rho_pitch_m));
        // Relative to u ~ 1.2 m/s, rounding of rho_pitch and L gives ~1e-16 m/s.
        assert!(k.sliding_velocity_m_per_s().abs() < 1e-12);
        assert!(k.slide_to_roll_ratio().abs() < 1e-12);
        assert!(k.sliding_distances_m(90e-6).pinion_m < 1e-16);
        assert_relative_eq!(
            k.entraining_velocity_m_per_s(),
            wp * p.rho_pitch_m,
            max_relative = 1e-12
        );
    }

    /// Second method, rigid-body kinematics of involute gears (e.g. Litvin & Fuentes 2004,
    /// ch. 10): the sliding speed is (omega_p + omega_g) times the distance of the contact
    /// from the pitch point, negative in approach, positive in recess.
    #[test]
    fn sliding_equals_sum_of_speeds_times_distance_from_pitch() {
        let p = paper();
        let (wp, wg) = speeds(&p);
        for i in 0..=10 {
            let rho1 = p.rho_start_m + p.path_length_m() * i as f64 / 10.0;
            let k = SurfaceKinematics::new(wp, wg, rho1, p.rho_gear(rho1));
            let expected = (wp + wg) * (rho1 - p.rho_pitch_m);
            // Absolute 1e-12 m/s: cancellation of two ~1 m/s speeds.
            assert!((k.sliding_velocity_m_per_s() - expected).abs() < 1e-12);
        }
    }

    /// SR(d) = 2 d A / (2U + d D) with A = omega_p + omega_g, D = omega_p - omega_g,
    /// U = omega_p rho_pitch; so its even part over its odd part is exactly -d D / (2U):
    /// first order in d, i.e. SR is antisymmetric about the pitch point to first order.
    #[test]
    fn slide_to_roll_antisymmetric_to_first_order() {
        let p = paper();
        let (wp, wg) = speeds(&p);
        let sr = |d: f64| {
            let r1 = p.rho_pitch_m + d;
            SurfaceKinematics::new(wp, wg, r1, p.rho_gear(r1)).slide_to_roll_ratio()
        };
        for d in [1e-3, 1e-4, 1e-5] {
            let (even, odd) = (sr(d) + sr(-d), sr(d) - sr(-d));
            let expected = -d * (wp - wg) / (2.0 * wp * p.rho_pitch_m);
            // 1e-6 relative: even part is a cancellation of two O(d) numbers.
            assert_relative_eq!(even / odd, expected, max_relative = 1e-6);
        }
    }

    /// s_p/s_g = u_g/u_p; on the pinion dedendum (u_p < u_g) the pinion point slides
    /// farther than the gear point: the slow surface is the one that wears (Flodin &
    /// Andersson 1997). At the pitch point both are zero.
    #[test]
    fn sliding_distance_ratio_and_pinion_root() {
        let p = paper();
        let (wp, wg) = speeds(&p);
        let a = 85e-6;
        for rho1 in [
            p.rho_start_m,
            p.rho_pitch_m - 1e-3,
            p.rho_pitch_m + 1e-3,
            p.rho_end_m,
        ] {
            let k = SurfaceKinematics::new(wp, wg, rho1, p.rho_gear(rho1));
            let s = k.sliding_distances_m(a);
            let (up, ug) = (k.pinion_velocity_m_per_s, k.gear_velocity_m_per_s);
            assert_relative_eq!(s.pinion_m / s.gear_m, ug / up, max_relative = 1e-12);
            assert_eq!(s.pinion_m > s.gear_m, up < ug);
            // Time in the band times sliding speed.
            assert_relative_eq!(
                s.pinion_m,
                (2.0 * a / up) * (up - ug).abs(),
                max_relative = 1e-12
            );
        }
    }

    #[test]
    fn degenerate_speeds_give_zero_not_nan() {
        let rest = SurfaceKinematics::new(0.0, 0.0, 0.006, 0.011);
        assert_eq!(rest.slide_to_roll_ratio(), 0.0);
        let s = rest.sliding_distances_m(1e-4);
        assert_eq!((s.pinion_m, s.gear_m), (0.0, 0.0));
        // Contact at the pinion base circle: u_p = 0, the gear point still slides.
        let base = SurfaceKinematics::new(100.0, 60.0, 0.0, 0.017);
        let s = base.sliding_distances_m(1e-4);
        assert_eq!(s.pinion_m, 0.0);
        assert_relative_eq!(s.gear_m, 2e-4, max_relative = 1e-12);
        assert_relative_eq!(base.slide_to_roll_ratio(), -2.0, max_relative = 1e-12);
    }
}
