//! Tooth friction: the coefficient (Xu et al. 2007, a constant, or none) and the friction
//! force with a smoothed direction.
//!
//! Sign convention. Forces are positive along the pinion's surface velocity at the contact
//! (perpendicular to the line of action; the gear's surface moves the same way there). The
//! pinion surface slides at `u_s = u_p - u_g` relative to the gear surface, so friction on the
//! pinion is `f_p = -mu W tanh(u_s / v)` and on the gear `f_g = -f_p` (paper eq. 6; the paper:
//! "when u_s > 0, f_p is negative"). Their moments, in each gear's own sense of rotation, are
//! `rho1 f_p` and `rho2 f_g` (power = moment x omega = force x surface speed), and the power
//! of the pair is `f_p u_p + f_g u_g = f_p u_s = -mu W u_s tanh(u_s/v) <= 0`: friction only
//! dissipates. `tanh` with the smoothing speed `v` keeps the right-hand side continuous
//! through the pitch point, where the direction flips (docs/PAPER_NOTES.md, "Friction"). Allocation-free
//! and cheap: evaluated inside the dynamics right-hand side.

use super::hertz::HertzContact;
use super::kinematics::SurfaceKinematics;
use crate::config::case::{FrictionModel, FrictionSection, LengthUnit};

/// b1..b9 of Xu, Kahraman, Anderson & Maddock, J. Mech. Des. 129 (2007) 58 (the EHL-based
/// regression; paper eqs. 8-9 print them rounded to two decimals). The same nine values
/// appear in independent secondary implementations of Xu's formula.
pub const XU2007_B: [f64; 9] = [
    -8.916465, 1.03303, 1.036077, -0.354068, 2.812084, -0.100601, 0.752755, -0.390958, 0.620305,
];

/// Xu et al. (2007) friction coefficient, paper eqs. (8)-(9), in the regression's units:
/// `mu = e^f P_h^b2 |SR|^b3 V_e^b6 nu0^b7 R^b8`,
/// `f = b1 + b4 |SR| P_h log10(nu0) + b5 e^(-|SR| P_h log10(nu0)) + b9 e^S`,
/// with `P_h` the maximum Hertz pressure (GPa), `SR` the slide-to-roll ratio, `V_e` the
/// entraining velocity (m/s), `nu0` the inlet viscosity (cP, fitted for > 1), `R` the effective
/// radius (m as Xu; the caller scales it for the mm reading), `S` the composite RMS roughness (um).
///
/// Evaluated in logarithms: `SR = 0`, `P_h, V_e, nu0, R <= 0` or non-finite inputs give exactly
/// 0; never NaN. Not capped: it exceeds 1 (not physical) for S = 1.9-2.1 um with R in m on the
/// paper's pair and is +inf for S > ~7 um; callers report such values, not hide them.
pub fn xu2007_coefficient(p_h_gpa: f64, sr: f64, v_e: f64, nu0_cp: f64, r: f64, s_um: f64) -> f64 {
    XuConstants::new(nu0_cp, s_um).coefficient(p_h_gpa, sr, v_e, r)
}

/// The terms of [`xu2007_coefficient`] that depend only on the viscosity and the roughness
/// (constant over an evaluation), computed once; the coefficient from them is the same
/// bit for bit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct XuConstants {
    /// `nu0` positive and finite, `S` finite (else the coefficient is 0).
    valid: bool,
    log10_nu0: f64,
    ln_nu0: f64,
    exp_s: f64,
}

impl XuConstants {
    /// For the inlet viscosity `nu0_cp` (cP) and the composite RMS roughness `s_um` (um).
    pub fn new(nu0_cp: f64, s_um: f64) -> Self {
        Self {
            valid: nu0_cp > 0.0 && nu0_cp.is_finite() && s_um.is_finite(),
            log10_nu0: nu0_cp.log10(),
            ln_nu0: nu0_cp.ln(),
            exp_s: s_um.exp(),
        }
    }

    /// [`xu2007_coefficient`] at `P_h` (GPa), `SR`, `V_e` (m/s) and `R` (regression unit).
    #[inline]
    pub fn coefficient(&self, p_h_gpa: f64, sr: f64, v_e: f64, r: f64) -> f64 {
        let (b, sr) = (&XU2007_B, sr.abs());
        let positive = |x: f64| x > 0.0 && x.is_finite();
        if !([p_h_gpa, sr, v_e, r].into_iter().all(positive) && self.valid) {
            return 0.0;
        }
        let x = sr * p_h_gpa * self.log10_nu0;
        let f = b[0] + b[3] * x + b[4] * (-x).exp() + b[8] * self.exp_s; // finite or +inf: b5, b9 > 0
        let powers = b[1] * p_h_gpa.ln() + b[2] * sr.ln() + b[5] * v_e.ln();
        (f + powers + b[6] * self.ln_nu0 + b[7] * r.ln()).exp()
    }
}

/// Which coefficient law, with its parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FrictionLaw {
    /// Xu et al. (2007) with the factor taking R from m to the unit it enters the
    /// regression in (1 for m, 1000 for mm; docs/PAPER_NOTES.md, "Friction").
    Xu2007(f64),
    /// A constant coefficient (direction still from the sliding velocity).
    Constant(f64),
    /// Frictionless contact (coefficient 0).
    None,
}

/// The case's friction model, ready for per-contact evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Friction {
    /// The coefficient law and its parameters.
    pub law: FrictionLaw,
    /// `v` in `tanh(u_s / v)`, m/s; not positive means a hard sign.
    pub direction_smoothing_m_per_s: f64,
}

impl Friction {
    /// From the case's `[friction]` section (ranges validated by `config::load`; a negative
    /// or NaN constant is still taken as 0 here so friction can never add energy).
    pub fn from_case(section: &FrictionSection) -> Self {
        let law = match section.model {
            FrictionModel::Xu2007 => FrictionLaw::Xu2007(match section.xu_radius_unit {
                LengthUnit::M => 1.0,
                LengthUnit::Mm => 1e3,
            }),
            FrictionModel::Constant => FrictionLaw::Constant(section.constant_coefficient.max(0.0)),
            FrictionModel::None => FrictionLaw::None,
        };
        Self {
            law,
            direction_smoothing_m_per_s: section.direction_smoothing_m_per_s,
        }
    }

    /// Friction coefficient at one contact (Hertz band `h`, surface speeds `k`), for the inlet
    /// viscosity in cP and the current composite RMS roughness in um (it changes with wear).
    pub fn coefficient(
        &self,
        h: &HertzContact,
        k: &SurfaceKinematics,
        viscosity_cp: f64,
        roughness_um: f64,
    ) -> f64 {
        self.coefficient_with(h, k, &XuConstants::new(viscosity_cp, roughness_um))
    }

    /// As [`Friction::coefficient`] with the viscosity and roughness terms computed once
    /// ([`XuConstants`]; the same value bit for bit).
    #[inline]
    pub fn coefficient_with(
        &self,
        h: &HertzContact,
        k: &SurfaceKinematics,
        xu: &XuConstants,
    ) -> f64 {
        match self.law {
            FrictionLaw::Xu2007(scale) => {
                let (p_h, r) = (h.max_pressure_pa * 1e-9, h.effective_radius_m * scale);
                let (sr, v_e) = (k.slide_to_roll_ratio(), k.entraining_velocity_m_per_s());
                xu.coefficient(p_h, sr, v_e, r)
            }
            FrictionLaw::Constant(mu) => mu,
            FrictionLaw::None => 0.0,
        }
    }

    /// Smoothed sign of the sliding velocity, `tanh(u_s / v)` in [-1, 1].
    pub fn direction(&self, sliding_velocity_m_per_s: f64) -> f64 {
        // Not positive (or NaN): a hard sign, as tanh over the smallest positive speed.
        let v = self.direction_smoothing_m_per_s.max(f64::MIN_POSITIVE);
        (sliding_velocity_m_per_s / v).tanh()
    }

    /// Friction force on the pinion, `f_p = -mu W tanh(u_s / v)`, N (module sign convention);
    /// the gear's is `-f_p`. A negative normal load (teeth apart) carries no friction.
    pub fn pinion_force_n(&self, mu: f64, normal_load_n: f64, sliding_m_per_s: f64) -> f64 {
        let w = normal_load_n.max(0.0);
        let d = self.direction(sliding_m_per_s);
        if mu == 0.0 || w == 0.0 || d == 0.0 {
            return 0.0; // avoids inf * 0 for an unbounded Xu coefficient
        }
        -mu * w * d
    }
}

/// Power of the friction pair `f_p u_p + f_g u_g = f_p u_s`, W (<= 0: dissipation).
pub fn friction_power_w(pinion_force_n: f64, sliding_velocity_m_per_s: f64) -> f64 {
    pinion_force_n * sliding_velocity_m_per_s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::{GearSection, MaterialsSection};
    use crate::geometry::pair::GearPair;
    use approx::assert_relative_eq;
    use proptest::prelude::*;

    const B: [f64; 9] = XU2007_B;
    fn mu(sr: f64, s_um: f64) -> f64 {
        xu2007_coefficient(1.2, sr, 1.2, 40.0, 0.004, s_um)
    }
    fn friction(model: FrictionModel, mm: bool) -> Friction {
        let xu_radius_unit = [LengthUnit::M, LengthUnit::Mm][mm as usize];
        Friction::from_case(&FrictionSection {
            model,
            xu_radius_unit,
            ..Default::default()
        })
    }

    /// Paper eq. (9) prints b1..b9 rounded to two decimals; hand evaluation at P_h = 1 GPa,
    /// SR = 1, V_e = 1 m/s, nu0 = 10 cP, R = 1, S = 0: f = b1 + b4 + b5/e + b9 = -7.615720,
    /// e^f = 4.92646e-4, 10^b7 = 5.65920, mu = 2.78798e-3 (6 digits: tolerance 1e-5).
    #[test]
    fn coefficients_and_hand_evaluated_point() {
        let printed = [-8.92, 1.03, 1.04, -0.35, 2.81, -0.10, 0.75, -0.39, 0.62];
        for (b, p) in B.iter().zip(printed) {
            assert!((b - p).abs() <= 0.005 + 1e-12);
        }
        let value = xu2007_coefficient(1.0, 1.0, 1.0, 10.0, 1.0, 0.0);
        assert_relative_eq!(value, 2.78798e-3, max_relative = 1e-5);
    }

    /// mu / |SR|^b3 -> e^(b1 + b5 + b9 e^S) P^b2 V^b6 nu^b7 R^b8 as SR -> 0: the other terms
    /// are O(x), x = |SR| P log10(nu0) ~ 2e-9 here, so 1e-6 is loose. SR = 0 gives exactly 0.
    #[test]
    fn vanishes_at_pure_rolling_and_is_even_in_sr() {
        let rest = 1.2f64.powf(B[1] + B[5]) * 40f64.powf(B[6]) * 0.004f64.powf(B[7]);
        let limit = (B[0] + B[4] + B[8] * 0.2f64.exp()).exp() * rest;
        let scaled = mu(1e-9, 0.2) / 1e-9f64.powf(B[2]);
        assert_relative_eq!(scaled, limit, max_relative = 1e-6);
        assert_eq!(mu(0.0, 0.2), 0.0);
        assert!(mu(1e-6, 0.2) < mu(1e-4, 0.2) && mu(1e-4, 0.2) < mu(1e-2, 0.2));
        for sr in [1e-6, 1e-3, 0.3, 1.4] {
            assert_eq!(mu(sr, 0.2), mu(-sr, 0.2));
        }
    }

    /// Exact identities of the formula: ln mu is linear in e^S with slope b9 > 0, so mu grows
    /// with roughness; reading R in mm multiplies mu by 1000^b8. Rounding only: 1e-12.
    #[test]
    fn roughness_and_radius_unit_identities() {
        let log_ratio = (mu(0.3, 0.15) / mu(0.3, 0.21)).ln();
        let expected = B[8] * (0.15f64.exp() - 0.21f64.exp());
        assert_relative_eq!(log_ratio, expected, max_relative = 1e-12);
        assert!(mu(0.3, 0.15) < mu(0.3, 0.19) && mu(0.3, 0.19) < mu(0.3, 0.21));
        let h = HertzContact::new(3361.0, 0.02, 0.0075, 0.0096, &MaterialsSection::default());
        let k = SurfaceKinematics::new(188.5, 115.5, 0.0075, 0.0096);
        let [m, mm] = [false, true]
            .map(|u| friction(FrictionModel::Xu2007, u).coefficient(&h, &k, 40.0, 0.2));
        assert_relative_eq!(mm / m, 1000f64.powf(B[7]), max_relative = 1e-12);
    }

    #[test]
    fn guarded_inputs_give_zero_or_inf_never_nan() {
        for (i, bad) in [(0, 0.0), (1, -1.0), (2, 0.0), (3, 0.0), (0, f64::NAN)] {
            let mut a = [1.0, 1.0, 40.0, 0.004]; // P_h, V_e, nu0, R
            a[i] = bad;
            assert_eq!(xu2007_coefficient(a[0], 0.3, a[1], a[2], a[3], 0.2), 0.0);
        }
        let huge = xu2007_coefficient(1.0, 1e-300, 1.0, 40.0, 0.004, 50.0);
        assert_eq!(huge, f64::INFINITY); // e^(0.62 e^50) overflows; not NaN
        let f = friction(FrictionModel::Xu2007, false);
        assert_eq!(f.pinion_force_n(f64::INFINITY, 3000.0, 0.0), 0.0);
        assert_eq!(f.pinion_force_n(0.05, -10.0, 1.0), 0.0);
    }

    proptest! {
        /// Friction only dissipates: f_p u_s <= 0 for every model, load, position and speed.
        #[test]
        fn friction_never_adds_energy(
            load in -100.0f64..2e4, rho1 in 0.0f64..0.02, rho2 in 0.0f64..0.03,
            wp in 0.0f64..1e3, wg in 0.0f64..1e3, nu in 1.0f64..500.0, s in 0.0f64..5.0,
            v in -0.01f64..0.1, mm: bool, model in prop::sample::select(vec![
                FrictionModel::Xu2007, FrictionModel::Constant, FrictionModel::None]),
        ) {
            let f = Friction { direction_smoothing_m_per_s: v, ..friction(model, mm) };
            let h = HertzContact::new(load, 0.02, rho1, rho2, &MaterialsSection::default());
            let k = SurfaceKinematics::new(wp, wg, rho1, rho2);
            let c = f.coefficient(&h, &k, nu, s);
            let fp = f.pinion_force_n(c, load, k.sliding_velocity_m_per_s());
            prop_assert!(c >= 0.0 && !fp.is_nan());
            prop_assert!(friction_power_w(fp, k.sliding_velocity_m_per_s()) <= 0.0);
        }
    }

    /// Paper case (docs/PAPER_NOTES.md): 30 Hz, 60 N m on the pinion (W = 60 / r_b1 = 3361 N, one pair),
    /// nu0 = 40 cP; printed for both R units and both roughness readings. Asserted only for
    /// the default reading (R in m, S/10): lubricated steel gear contacts run at mu = 0.01-0.1.
    #[test]
    fn paper_case_coefficients() {
        let p = GearPair::from_case(&GearSection::default()).unwrap();
        let mat = MaterialsSection::default();
        let (wp, load) = (60.0 * std::f64::consts::PI, 60.0 / p.pinion.base_radius_m);
        let (rs, rp, re) = (p.rho_start_m, p.rho_pitch_m, p.rho_end_m);
        for rho1 in [rs, rp - 1e-3, rp + 1e-3, re] {
            let h = HertzContact::new(load, p.face_width_m, rho1, p.rho_gear(rho1), &mat);
            let k = SurfaceKinematics::new(wp, wp / p.ratio(), rho1, p.rho_gear(rho1));
            let (sr, p0) = (k.slide_to_roll_ratio(), h.max_pressure_pa * 1e-9);
            for mm in [false, true] {
                let f = friction(FrictionModel::Xu2007, mm);
                let mus = [2.1, 1.9, 1.5, 0.21, 0.19, 0.15].map(|s| f.coefficient(&h, &k, 40.0, s));
                println!(
                    "rho1 {rho1:.5} m, R in mm {mm}: SR {sr:+.3}, p0 {p0:.3} GPa: mu {mus:.4?}"
                );
                assert!(mm || mus[3..].iter().all(|m| (0.01..=0.1).contains(m)));
            }
        }
    }
}
