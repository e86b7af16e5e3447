//! ISO 6336-1 Method B tooth stiffness: single stiffness c' and mesh stiffness
//! c_gamma_alpha, an independent cross-check of the magnitude of the potential-energy
//! mesh stiffness.
//!
//! Source: ISO 6336-1:2006, clause 9 (Method B), unchanged in ISO 6336-1:2019:
//! - q' = C1 + C2/z_n1 + C3/z_n2 + C4 x1 + C5 x1/z_n1 + C6 x2 + C7 x2/z_n2 + C8 x1^2
//!   + C9 x2^2 (mm um/N), c'_th = 1/q' (theoretical single stiffness, N/(mm um));
//! - c' = c'_th C_M C_R C_B cos(beta), C_M = 0.8;
//! - c_gamma_alpha = c' (0.75 eps_alpha + 0.25), c_gamma_beta = 0.85 c_gamma_alpha.
//!
//! Checked against ISO/TR 6336-30:2017 Example 1 (`tests/iso6336_tr_example.rs`).
//! Stiffnesses are per unit face width in the standard's N/(mm um); multiply by the face
//! width with [`per_width_to_n_per_m`] for the N/m the dynamic model uses.
//! Internal gears (not needed here) take z_n2 -> infinity: the C3 and C7 terms vanish.

use crate::geometry::GearPair;

/// ISO 6336-1 Table (Method B) coefficients C1..C9 of q', mm um/N.
pub const Q_COEFFICIENTS: [f64; 9] = [
    0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182,
];

/// Correction factor C_M between measured and theoretical stiffness of solid discs.
pub const C_M: f64 = 0.8;

/// Line load below which ISO 6336-1 scales c' down, N/mm.
pub const LOW_LOAD_LIMIT_N_PER_MM: f64 = 100.0;

/// Inputs of Method B. Angles in rad; stiffness-related inputs dimensionless.
#[derive(Debug, Clone, PartialEq)]
pub struct Iso6336Input {
    /// Number of teeth of the pinion z_1.
    pub teeth_pinion: f64,
    /// Number of teeth of the gear z_2.
    pub teeth_gear: f64,
    /// Profile shift coefficient of the pinion x_1.
    pub profile_shift_pinion: f64,
    /// Profile shift coefficient of the gear x_2.
    pub profile_shift_gear: f64,
    /// Helix angle at the reference cylinder beta, rad (0 for spur gears).
    pub helix_angle_rad: f64,
    /// Normal pressure angle of the basic rack alpha_Pn, rad.
    pub normal_pressure_angle_rad: f64,
    /// Basic-rack dedendum h_fP / m_n of the pinion's rack.
    pub dedendum_coefficient_pinion: f64,
    /// Basic-rack dedendum h_fP / m_n of the gear's rack.
    pub dedendum_coefficient_gear: f64,
    /// Transverse contact ratio eps_alpha.
    pub transverse_contact_ratio: f64,
    /// Gear-blank factor C_R (1 for solid discs; see [`blank_factor`]).
    pub blank_factor: f64,
    /// Line load F_t K_A / b, N/mm; `None` skips the low-load correction.
    pub line_load_n_per_mm: Option<f64>,
}

/// Method B results, stiffnesses per unit face width in N/(mm um).
#[derive(Debug, Clone, PartialEq)]
pub struct Iso6336Stiffness {
    /// Virtual numbers of teeth z_n = z / (cos^2(beta_b) cos(beta)).
    pub virtual_teeth: [f64; 2],
    /// Theoretical single stiffness c'_th = 1/q', N/(mm um).
    pub theoretical_single_n_per_mm_um: f64,
    /// Basic rack factor C_B = (C_B1 + C_B2)/2.
    pub basic_rack_factor: f64,
    /// Low-load factor (F_t K_A / b / 100)^0.25 below 100 N/mm, else 1.
    pub low_load_factor: f64,
    /// Single stiffness c', N/(mm um).
    pub single_n_per_mm_um: f64,
    /// Mesh stiffness c_gamma_alpha, N/(mm um).
    pub mesh_alpha_n_per_mm_um: f64,
    /// Mesh stiffness c_gamma_beta = 0.85 c_gamma_alpha, N/(mm um).
    pub mesh_beta_n_per_mm_um: f64,
    /// Inputs outside the range the standard's fit was made for.
    pub warnings: Vec<String>,
}

/// Inputs Method B cannot evaluate.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("ISO 6336 Method B: {}", .0.join("; "))]
pub struct Iso6336Error(pub Vec<String>);

/// Stiffness per unit face width c (N/(mm um)) times face width b (m), in N/m:
/// c b_mm = N/um, times 1e6 um/m.
pub fn per_width_to_n_per_m(c_n_per_mm_um: f64, face_width_m: f64) -> f64 {
    c_n_per_mm_um * (face_width_m * 1e3) * 1e6
}

/// Gear-blank factor C_R for a web of thickness b_s and a rim of thickness s_R
/// (ISO 6336-1:2006 Method B): C_R = 1 + ln(b_s/b) / (5 exp(s_R / (5 m_n))), with b_s/b
/// held to [0.2, 1.2] and s_R/m_n to >= 1 as the standard prescribes. Solid discs: 1.
pub fn blank_factor(web_over_face_width: f64, rim_over_module: f64) -> f64 {
    let bs_b = web_over_face_width.clamp(0.2, 1.2);
    let sr_m = rim_over_module.max(1.0);
    1.0 + bs_b.ln() / (5.0 * (sr_m / 5.0).exp())
}

/// Basic rack factor of one rack (ISO 6336-1): C_B = [1 + 0.5(1.2 - h_fP/m_n)]
/// [1 - 0.02(20 deg - alpha_Pn)], alpha_Pn in degrees in the second bracket.
pub fn rack_factor(dedendum_coefficient: f64, normal_pressure_angle_rad: f64) -> f64 {
    (1.0 + 0.5 * (1.2 - dedendum_coefficient))
        * (1.0 - 0.02 * (20.0 - normal_pressure_angle_rad.to_degrees()))
}

impl Iso6336Input {
    /// Method B inputs for a spur pair: beta = 0 (so z_n = z), alpha_Pn the pair's
    /// pressure angle, h_fP/m_n = (r - r_f)/m + x recovered from each gear's root radius,
    /// eps_alpha = [`GearPair::contact_ratio`].
    pub fn from_pair(pair: &GearPair, blank_factor: f64, line_load_n_per_mm: Option<f64>) -> Self {
        let dedendum = |g: &crate::geometry::Gear| {
            (g.pitch_radius_m - g.root_radius_m) / pair.module_m + g.profile_shift
        };
        Self {
            teeth_pinion: pair.pinion.teeth as f64,
            teeth_gear: pair.gear.teeth as f64,
            profile_shift_pinion: pair.pinion.profile_shift,
            profile_shift_gear: pair.gear.profile_shift,
            helix_angle_rad: 0.0,
            normal_pressure_angle_rad: pair.pressure_angle_rad,
            dedendum_coefficient_pinion: dedendum(&pair.pinion),
            dedendum_coefficient_gear: dedendum(&pair.gear),
            transverse_contact_ratio: pair.contact_ratio,
            blank_factor,
            line_load_n_per_mm,
        }
    }

    fn check(&self) -> Result<(), Iso6336Error> {
        let right = std::f64::consts::FRAC_PI_2;
        let alpha = self.normal_pressure_angle_rad;
        let finite = [
            self.dedendum_coefficient_pinion,
            self.dedendum_coefficient_gear,
            self.profile_shift_pinion,
            self.profile_shift_gear,
        ];
        // Every comparison with NaN is false, so each rule also rejects NaN.
        let teeth = self.teeth_pinion > 0.0 && self.teeth_gear > 0.0;
        let helix = self.helix_angle_rad.abs() < right;
        let pressure = alpha > 0.0 && alpha < right;
        let shape = finite.iter().all(|v| v.is_finite());
        let eps = self.transverse_contact_ratio > 0.0;
        let blank = self.blank_factor > 0.0;
        let load = self.line_load_n_per_mm.is_none_or(|w| w > 0.0);
        let rules = [
            (teeth, "teeth numbers must be positive (no internal gears)"),
            (helix, "helix angle must lie in (-90, 90) deg"),
            (pressure, "pressure angle must lie in (0, 90) deg"),
            (shape, "shifts and dedendum coefficients must be finite"),
            (eps, "transverse contact ratio must be positive"),
            (blank, "gear-blank factor C_R must be positive"),
            (load, "line load F_t K_A / b must be positive"),
        ];
        let e: Vec<String> = rules
            .iter()
            .filter(|(ok, _)| !ok)
            .map(|(_, m)| m.to_string())
            .collect();
        if e.is_empty() {
            Ok(())
        } else {
            Err(Iso6336Error(e))
        }
    }

    /// Evaluate Method B (ISO 6336-1:2006/2019 clause 9).
    pub fn evaluate(&self) -> Result<Iso6336Stiffness, Iso6336Error> {
        self.check()?;
        let mut warnings = Vec::new();
        let (x1, x2) = (self.profile_shift_pinion, self.profile_shift_gear);
        // Validity range of the q' fit (ISO 6336-1 Method B): x1 >= x2, -0.5 <= x1+x2 <= 2.
        if x1 < x2 || !(-0.5..=2.0).contains(&(x1 + x2)) {
            warnings.push(format!(
                "profile shifts x1 = {x1}, x2 = {x2} lie outside the q' fit's range (x1 >= x2, -0.5 <= x1 + x2 <= 2)"
            ));
        }
        // Virtual numbers of teeth (ISO 21771): z_n = z / (cos^2 beta_b cos beta),
        // sin beta_b = sin beta cos alpha_n.
        let beta = self.helix_angle_rad;
        let beta_b = (beta.sin() * self.normal_pressure_angle_rad.cos()).asin();
        let zn = |z: f64| z / (beta_b.cos().powi(2) * beta.cos());
        let (zn1, zn2) = (zn(self.teeth_pinion), zn(self.teeth_gear));

        let terms = [
            1.0,
            1.0 / zn1,
            1.0 / zn2,
            x1,
            x1 / zn1,
            x2,
            x2 / zn2,
            x1 * x1,
            x2 * x2,
        ];
        let q: f64 = Q_COEFFICIENTS.iter().zip(terms).map(|(c, t)| c * t).sum();
        if q.is_nan() || q <= 0.0 {
            return Err(Iso6336Error(vec![format!(
                "the flexibility q' = {q} mm µm/N is not positive for these teeth numbers and shifts"
            )]));
        }
        let c_th = 1.0 / q;

        // ISO 6336-1:2019 writes C_B = 0.5 (C_B1 + C_B2) for racks that differ; with one
        // rack it is the 2006 single-rack form.
        let alpha = self.normal_pressure_angle_rad;
        let c_b = 0.5
            * (rack_factor(self.dedendum_coefficient_pinion, alpha)
                + rack_factor(self.dedendum_coefficient_gear, alpha));

        // Low line loads: c' scaled by (F_t K_A / b / 100)^0.25 below 100 N/mm.
        let low_load_factor = match self.line_load_n_per_mm {
            Some(w) if w < LOW_LOAD_LIMIT_N_PER_MM => (w / LOW_LOAD_LIMIT_N_PER_MM).powf(0.25),
            _ => 1.0,
        };
        let single = c_th * C_M * self.blank_factor * c_b * beta.cos() * low_load_factor;

        let eps = self.transverse_contact_ratio;
        if eps < 1.2 && beta == 0.0 {
            // ISO 6336-1: for spur gears with eps_alpha < 1.2, c_gamma_alpha may be
            // reduced by up to 10 %; the full value is returned.
            warnings.push(format!(
                "eps_alpha = {eps:.4} < 1.2: ISO 6336-1 allows c_gamma_alpha to be reduced by up to 10 %"
            ));
        }
        let mesh_alpha = single * (0.75 * eps + 0.25);
        Ok(Iso6336Stiffness {
            virtual_teeth: [zn1, zn2],
            theoretical_single_n_per_mm_um: c_th,
            basic_rack_factor: c_b,
            low_load_factor,
            single_n_per_mm_um: single,
            mesh_alpha_n_per_mm_um: mesh_alpha,
            mesh_beta_n_per_mm_um: 0.85 * mesh_alpha,
            warnings,
        })
    }
}

impl Iso6336Stiffness {
    /// Single stiffness c' b of a face width b (m), N/m.
    pub fn single_n_per_m(&self, face_width_m: f64) -> f64 {
        per_width_to_n_per_m(self.single_n_per_mm_um, face_width_m)
    }

    /// Mesh stiffness c_gamma_alpha b of a face width b (m), N/m.
    pub fn mesh_alpha_n_per_m(&self, face_width_m: f64) -> f64 {
        per_width_to_n_per_m(self.mesh_alpha_n_per_mm_um, face_width_m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::GearSection;

    fn spur(z1: f64, z2: f64) -> Iso6336Input {
        Iso6336Input {
            teeth_pinion: z1,
            teeth_gear: z2,
            profile_shift_pinion: 0.0,
            profile_shift_gear: 0.0,
            helix_angle_rad: 0.0,
            normal_pressure_angle_rad: 20f64.to_radians(),
            dedendum_coefficient_pinion: 1.2,
            dedendum_coefficient_gear: 1.2,
            transverse_contact_ratio: 1.6,
            blank_factor: 1.0,
            line_load_n_per_mm: None,
        }
    }

    #[test]
    fn rack_limit_and_helix() {
        // z -> infinity, x = 0: only C1 is left (1e12 teeth leave < 1e-10 of the rest);
        // the helix then only enters through cos(beta), and z_n grows with beta.
        let mut i = spur(1e12, 1e12);
        let s = i.evaluate().unwrap();
        assert!((s.theoretical_single_n_per_mm_um - 1.0 / 0.04723).abs() < 1e-8);
        i.helix_angle_rad = 30f64.to_radians();
        let h = i.evaluate().unwrap();
        let ratio = h.single_n_per_mm_um / s.single_n_per_mm_um;
        assert!((ratio - 30f64.to_radians().cos()).abs() < 1e-9);
        assert!(h.virtual_teeth[0] > 1e12);
        assert_eq!(
            spur(19.0, 31.0).evaluate().unwrap().virtual_teeth,
            [19.0, 31.0]
        );
    }

    #[test]
    fn rack_factor_reference_values() {
        // h_fP = 1.2 m_n at 20 deg is the standard's reference (C_B = 1); ISO 6336-1 quotes
        // 0.975 for 1.25 m_n; 1.4 m_n (ISO 53 profile D) gives 0.9; 25 deg: 1 + 0.02 x 5.
        let a20 = 20f64.to_radians();
        assert!((rack_factor(1.2, a20) - 1.0).abs() < 1e-15);
        assert!((rack_factor(1.25, a20) - 0.975).abs() < 1e-15);
        assert!((rack_factor(1.4, a20) - 0.9).abs() < 1e-15);
        assert!((rack_factor(1.2, 25f64.to_radians()) - 1.1).abs() < 1e-12);
        let mut i = spur(20.0, 40.0);
        i.dedendum_coefficient_gear = 1.4; // two racks average (ISO 6336-1:2019)
        assert!((i.evaluate().unwrap().basic_rack_factor - 0.95).abs() < 1e-15);
    }

    #[test]
    fn low_load_mesh_blank_and_units() {
        let at = |w: Option<f64>, eps: f64| {
            let mut i = spur(19.0, 31.0);
            (i.line_load_n_per_mm, i.transverse_contact_ratio) = (w, eps);
            i.evaluate().unwrap()
        };
        let base = at(None, 1.6);
        assert_eq!(at(Some(100.0), 1.6).low_load_factor, 1.0); // continuous at the limit
        let low = at(Some(6.25), 1.6); // 6.25 / 100 = 0.5^4
        assert!((low.single_n_per_mm_um - 0.5 * base.single_n_per_mm_um).abs() < 1e-12);
        // eps_alpha = 1: one pair always carries, c_gamma_alpha = c'.
        let one = at(None, 1.0);
        assert!((one.mesh_alpha_n_per_mm_um - one.single_n_per_mm_um).abs() < 1e-12);
        assert!(one.warnings.iter().any(|w| w.contains("10 %")));
        assert!((base.mesh_beta_n_per_mm_um / base.mesh_alpha_n_per_mm_um - 0.85).abs() < 1e-15);
        assert_eq!(blank_factor(1.0, 3.0), 1.0); // web as wide as the face
        assert_eq!(blank_factor(0.05, 3.0), blank_factor(0.2, 3.0));
        assert_eq!(blank_factor(0.5, 0.3), blank_factor(0.5, 1.0));
        // 1 N/(mm um) over 20 mm = 20 N/um = 2e7 N/m.
        assert!((per_width_to_n_per_m(1.0, 0.020) - 2e7).abs() < 1e-6);
    }

    #[test]
    fn invalid_inputs_are_errors_not_panics() {
        let with = |f: fn(&mut Iso6336Input)| {
            let mut i = spur(19.0, 31.0);
            f(&mut i);
            i.evaluate()
        };
        assert!(with(|i| i.teeth_pinion = 0.0).is_err());
        assert!(with(|i| i.transverse_contact_ratio = f64::NAN).is_err());
        assert!(with(|i| i.line_load_n_per_mm = Some(-3.0)).is_err());
        let shifted = with(|i| i.profile_shift_gear = 0.5).unwrap();
        assert!(shifted.warnings.iter().any(|w| w.contains("x1 >= x2")));
    }

    #[test]
    fn paper_pair_from_case() {
        let pair = GearPair::from_case(&GearSection::default()).unwrap();
        // 60 N m on the pinion, F_t at the 19 mm reference radius, b = 20 mm: 158 N/mm.
        let load = 60.0 / pair.pinion.pitch_radius_m / (pair.face_width_m * 1e3);
        let inp = Iso6336Input::from_pair(&pair, 1.0, Some(load));
        assert!((inp.dedendum_coefficient_pinion - 1.25).abs() < 1e-12);
        assert!((inp.dedendum_coefficient_gear - 1.25).abs() < 1e-12);
        let s = inp.evaluate().unwrap();
        assert_eq!(s.low_load_factor, 1.0);
        // Hand evaluation: q' = C1 + C2/19 + C3/31, C_B = 0.975 (h_fP = 1.25 m_n).
        let single = 0.8 * 0.975 / (0.04723 + 0.15551 / 19.0 + 0.25791 / 31.0);
        assert!((s.single_n_per_mm_um - single).abs() < 1e-12);
        // docs/PAPER_NOTES.md eps_alpha = 1.6022 to 4 decimals (+-5e-5): c_gamma_alpha to 0.75 c' 5e-5.
        let mesh_notes = single * (0.75 * 1.6022 + 0.25);
        assert!((s.mesh_alpha_n_per_mm_um - mesh_notes).abs() < 0.75 * single * 5e-5);
        eprintln!(
            "paper pair: c'_th = {:.4}, c' = {:.4}, c_gamma_alpha = {:.4} N/(mm µm); b = 20 mm: c' b = {:.4e}, c_gamma_alpha b = {:.4e} N/m; line load {load:.1} N/mm",
            s.theoretical_single_n_per_mm_um,
            s.single_n_per_mm_um,
            s.mesh_alpha_n_per_mm_um,
            s.single_n_per_m(pair.face_width_m),
            s.mesh_alpha_n_per_m(pair.face_width_m)
        );
    }
}
