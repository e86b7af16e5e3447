//! Hertz line contact of two parallel cylinders (Johnson, *Contact Mechanics*, 1985, ch. 4,
//! sec. 4.2): the tooth contact at one point of the path of contact, each flank replaced by
//! its radius of curvature there.
//!
//! Standard form used here (SI units):
//! - effective modulus `1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2` (Pa);
//! - effective radius `1/R = 1/rho1 + 1/rho2` (m);
//! - load per unit face width `w = W / b` (N/m);
//! - half-width `a = sqrt(4 w R / (pi E*))` (m);
//! - maximum pressure `p0 = sqrt(w E* / (pi R)) = 2 w / (pi a)` (Pa);
//! - pressure across the band `p(x) = p0 sqrt(1 - x^2/a^2)`, mean `w / (2a) = pi p0 / 4`.
//!
//! The paper's eq. (15), `P_h = sqrt(F kappa E / (2 b pi r_eq))`, is this `p0` for equal
//! materials with `E* = E / (2 (1 - nu^2))` except that it drops the `(1 - nu^2)`: it is
//! `sqrt(1 - nu^2)` (0.954 for nu = 0.3) times the standard value. We use the standard
//! form (docs/PAPER_NOTES.md, "Wear").
//!
//! Everything here is allocation-free and cheap: it runs inside the dynamics right-hand side.

use crate::config::case::MaterialsSection;
use std::f64::consts::PI;

/// Effective (contact) modulus `E*`, Pa: `1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2`
/// (Johnson 1985, ch. 4 notation). Moduli in Pa.
pub fn effective_modulus_pa(e1_pa: f64, nu1: f64, e2_pa: f64, nu2: f64) -> f64 {
    1.0 / ((1.0 - nu1 * nu1) / e1_pa + (1.0 - nu2 * nu2) / e2_pa)
}

/// `E*` of the case's pinion and gear materials (moduli given there in GPa), Pa.
pub fn effective_modulus_of(materials: &MaterialsSection) -> f64 {
    effective_modulus_pa(
        materials.youngs_modulus_pinion_gpa * 1e9,
        materials.poisson_ratio_pinion,
        materials.youngs_modulus_gear_gpa * 1e9,
        materials.poisson_ratio_gear,
    )
}

/// Effective radius of curvature `R = rho1 rho2 / (rho1 + rho2)`, m (two convex
/// involute flanks). Zero when either radius is not positive and finite: a contact at or
/// beyond a base circle has no Hertzian solution (the pressure would be infinite).
pub fn effective_radius_m(rho1_m: f64, rho2_m: f64) -> f64 {
    let valid = |r: f64| r > 0.0 && r.is_finite();
    if valid(rho1_m) && valid(rho2_m) {
        rho1_m * rho2_m / (rho1_m + rho2_m)
    } else {
        0.0
    }
}

/// The Hertzian band at one contact point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HertzContact {
    /// Half-width `a` of the contact band, m.
    pub half_width_m: f64,
    /// Maximum (centre) pressure `p0`, Pa.
    pub max_pressure_pa: f64,
    /// Effective radius of curvature `R`, m (kept even at zero load: friction uses it).
    pub effective_radius_m: f64,
}

impl HertzContact {
    /// Contact under a normal load `load_n` (N) spread over `face_width_m`, between flanks
    /// of radii of curvature `rho1_m` (pinion) and `rho2_m` (gear).
    pub fn new(
        load_n: f64,
        face_width_m: f64,
        rho1_m: f64,
        rho2_m: f64,
        materials: &MaterialsSection,
    ) -> Self {
        let e_star_pa = effective_modulus_of(materials);
        Self::with_modulus(load_n, face_width_m, rho1_m, rho2_m, e_star_pa)
    }

    /// As [`HertzContact::new`] with `E*` (Pa) computed once by the caller.
    /// Zero or negative load (teeth apart), zero width or invalid radii give zero pressure
    /// and width, never NaN.
    pub fn with_modulus(
        load_n: f64,
        face_width_m: f64,
        rho1_m: f64,
        rho2_m: f64,
        e_star_pa: f64,
    ) -> Self {
        Self::with_radius(
            load_n,
            face_width_m,
            effective_radius_m(rho1_m, rho2_m),
            e_star_pa,
        )
    }

    /// As [`HertzContact::with_modulus`] with the effective radius `radius` (m) given:
    /// flanks that are no longer involutes (worn), whose curvature is not 1/rho.
    pub fn with_radius(load_n: f64, face_width_m: f64, radius: f64, e_star_pa: f64) -> Self {
        let w = load_n / face_width_m; // N/m
        let e_star = e_star_pa;
        if !(w > 0.0 && w.is_finite() && radius > 0.0 && e_star > 0.0 && e_star.is_finite()) {
            return Self {
                effective_radius_m: radius,
                ..Self::default()
            };
        }
        Self {
            half_width_m: (4.0 * w * radius / (PI * e_star)).sqrt(),
            max_pressure_pa: (w * e_star / (PI * radius)).sqrt(),
            effective_radius_m: radius,
        }
    }

    /// Mean pressure over the band, `pi p0 / 4` (= `w / (2a)` by equilibrium), Pa.
    pub fn mean_pressure_pa(&self) -> f64 {
        PI * self.max_pressure_pa / 4.0
    }

    /// Semi-elliptical pressure `p0 sqrt(1 - x^2/a^2)` at `x_m` from the band centre, Pa;
    /// zero outside the band.
    pub fn pressure_at_pa(&self, x_m: f64) -> f64 {
        if self.half_width_m <= 0.0 || x_m.abs() >= self.half_width_m {
            return 0.0;
        }
        let t = x_m / self.half_width_m;
        self.max_pressure_pa * (1.0 - t * t).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn steel() -> MaterialsSection {
        MaterialsSection {
            youngs_modulus_pinion_gpa: 210.0,
            poisson_ratio_pinion: 0.3,
            youngs_modulus_gear_gpa: 210.0,
            poisson_ratio_gear: 0.3,
        }
    }

    /// Hand computation: two steel cylinders r1 = r2 = 20 mm (R = 10 mm), E = 210 GPa,
    /// nu = 0.3, F = 10 kN on L = 20 mm (w = 5e5 N/m).
    /// E* = 210e9 / (2 * 0.91) = 115.38 GPa; a^2 = 4 * 5e5 * 0.01 / (pi * 115.38e9)
    /// = 5.5174e-8 m^2, a = 234.89 um; p0 = 2 w / (pi a) = 1e6 / 7.3793e-4 = 1.3551 GPa.
    /// Tolerance 1e-4: the hand values carry 5 significant digits.
    #[test]
    fn hand_computed_steel_rollers() {
        let c = HertzContact::new(10e3, 0.02, 0.02, 0.02, &steel());
        assert_relative_eq!(c.effective_radius_m, 0.01, max_relative = 1e-12);
        assert_relative_eq!(
            effective_modulus_of(&steel()),
            115.38e9,
            max_relative = 1e-4
        );
        assert_relative_eq!(c.half_width_m, 234.89e-6, max_relative = 1e-4);
        assert_relative_eq!(c.max_pressure_pa, 1.3551e9, max_relative = 1e-4);
    }

    /// Second published form: Carvill, *Mechanical Engineer's Data Handbook* (1993), p. 52,
    /// two rollers: full width w_c = sqrt(16 F ((1-nu1^2)/E1 + (1-nu2^2)/E2) / (pi L (1/r1 + 1/r2))),
    /// sigma_c = 4 F / (pi w_c L). Different materials and radii; rounding-level agreement.
    #[test]
    fn agrees_with_handbook_roller_formula() {
        let m = MaterialsSection {
            youngs_modulus_pinion_gpa: 205.0,
            poisson_ratio_pinion: 0.3,
            youngs_modulus_gear_gpa: 110.0,
            poisson_ratio_gear: 0.34,
        };
        let (f, l, r1, r2) = (3361.0, 0.02, 0.0075, 0.0096);
        let compliance = (1.0 - 0.09) / 205e9 + (1.0 - 0.34 * 0.34) / 110e9;
        let wc = (16.0 * f * compliance / (PI * l * (1.0 / r1 + 1.0 / r2))).sqrt();
        let c = HertzContact::new(f, l, r1, r2, &m);
        assert_relative_eq!(2.0 * c.half_width_m, wc, max_relative = 1e-12);
        assert_relative_eq!(
            c.max_pressure_pa,
            4.0 * f / (PI * wc * l),
            max_relative = 1e-12
        );
    }

    /// p0 = 2w/(pi a), and the semi-elliptical distribution carries the load: integrating
    /// p(x) over the band (midpoint rule, 20000 cells; error ~ n^-1.5 from the square-root
    /// edges, < 1e-5) gives w, so the mean w/(2a) is pi p0 / 4.
    #[test]
    fn pressure_identities_and_equilibrium() {
        let (load, b) = (3361.0, 0.02);
        let c = HertzContact::new(load, b, 0.0065, 0.0106, &steel());
        let w = load / b;
        assert_relative_eq!(
            c.max_pressure_pa,
            2.0 * w / (PI * c.half_width_m),
            max_relative = 1e-12
        );
        assert_relative_eq!(
            w / (2.0 * c.half_width_m),
            c.mean_pressure_pa(),
            max_relative = 1e-12
        );
        let n = 20_000;
        let dx = 2.0 * c.half_width_m / n as f64;
        let total: f64 = (0..n)
            .map(|i| c.pressure_at_pa(-c.half_width_m + (i as f64 + 0.5) * dx) * dx)
            .sum();
        assert_relative_eq!(total, w, max_relative = 1e-5);
    }

    /// p0 and a both grow as sqrt(w): four times the load doubles them (exact scaling).
    #[test]
    fn square_root_load_scaling() {
        let c1 = HertzContact::new(1000.0, 0.02, 0.006, 0.011, &steel());
        let c4 = HertzContact::new(4000.0, 0.02, 0.006, 0.011, &steel());
        assert_relative_eq!(
            c4.max_pressure_pa / c1.max_pressure_pa,
            2.0,
            max_relative = 1e-12
        );
        assert_relative_eq!(c4.half_width_m / c1.half_width_m, 2.0, max_relative = 1e-12);
    }

    /// The paper's eq. (15) is the standard p0 times sqrt(1 - nu^2) (equal materials).
    #[test]
    fn paper_eq15_differs_by_sqrt_one_minus_nu_squared() {
        let (f, b, r1, r2, e) = (3361.0, 0.02, 0.0065, 0.0106, 210e9);
        let c = HertzContact::new(f, b, r1, r2, &steel());
        let eq15 = (f * e / (2.0 * b * PI * c.effective_radius_m)).sqrt();
        assert_relative_eq!(
            eq15 / c.max_pressure_pa,
            (1.0f64 - 0.09).sqrt(),
            max_relative = 1e-12
        );
    }

    #[test]
    fn no_load_or_degenerate_geometry_gives_zero_not_nan() {
        for (load, b, r1, r2) in [
            (0.0, 0.02, 0.006, 0.011),
            (-50.0, 0.02, 0.006, 0.011),
            (100.0, 0.0, 0.006, 0.011),
            (100.0, 0.02, 0.0, 0.011),
            (100.0, 0.02, -0.001, 0.011),
            (f64::NAN, 0.02, 0.006, 0.011),
        ] {
            let c = HertzContact::new(load, b, r1, r2, &steel());
            assert_eq!(c.max_pressure_pa, 0.0);
            assert_eq!(c.half_width_m, 0.0);
            assert_eq!(c.pressure_at_pa(0.0), 0.0);
            assert!(!c.effective_radius_m.is_nan());
        }
        // Zero load keeps the geometric radius (friction still needs R).
        let c = HertzContact::new(0.0, 0.02, 0.006, 0.012, &steel());
        assert_relative_eq!(c.effective_radius_m, 0.004, max_relative = 1e-12);
    }
}
