//! ISO/TR 6336-30:2017, Example 1 (helical pair), against ISO 6336-1 Method B as
//! implemented in `gearwear::stiffness::iso6336`.
//!
//! Example data: m_n = 8 mm, z = 17/103, x = 0.145/0, beta = 15.8 deg, alpha_n = 20 deg,
//! b = 100 mm, a_w = 500 mm, basic rack ISO 53 profile D (h_aP = 1.0 m_n, h_fP = 1.4 m_n),
//! solid discs (C_R = 1), F_t = 127 352 N, K_A = 1. Published results (5 decimals):
//! c'_th = 17.85584, c' = 12.37047, c_gamma_alpha = 17.46485, c_gamma_beta = 14.84512
//! N/(mm um), z_n = 18.905 / 114.543. (Data and results as reproduced in the public
//! validation script of github.com/gfsReboucas/Drivetrain, `ISO_6336.m`, `example_01`.)
//!
//! The transverse contact ratio is not among the reproduced results; it is computed here
//! from the transverse geometry, independently of the library.

use gearwear::stiffness::iso6336::Iso6336Input;
use std::f64::consts::PI;

const MN_MM: f64 = 8.0;
const Z: [f64; 2] = [17.0, 103.0];
const X: [f64; 2] = [0.145, 0.0];
const BETA_DEG: f64 = 15.8;
const ALPHA_N_DEG: f64 = 20.0;
const FACE_WIDTH_MM: f64 = 100.0;
const CENTRE_DISTANCE_MM: f64 = 500.0;
const H_FP: f64 = 1.4;
const H_AP: f64 = 1.0;
const TANGENTIAL_LOAD_N: f64 = 127_352.0;

/// Published values are rounded to 5 decimals: the exact value lies within 5e-6 of them.
const HALF_UNIT_5_DECIMALS: f64 = 5e-6;

/// eps_alpha = [sqrt(d_a1^2 - d_b1^2) + sqrt(d_a2^2 - d_b2^2) - 2 a_w sin(alpha_wt)]
/// / (2 p_bt), p_bt = pi m_t cos(alpha_t) (ISO 21771), all in the transverse section.
fn transverse_contact_ratio(tip_diameters_mm: [f64; 2]) -> f64 {
    let beta = BETA_DEG.to_radians();
    let alpha_t = (ALPHA_N_DEG.to_radians().tan() / beta.cos()).atan();
    let m_t = MN_MM / beta.cos();
    let d = Z.map(|z| z * m_t);
    let d_b = d.map(|d| d * alpha_t.cos());
    let alpha_wt = ((d_b[0] + d_b[1]) / (2.0 * CENTRE_DISTANCE_MM)).acos();
    let g_alpha = 0.5
        * ((tip_diameters_mm[0].powi(2) - d_b[0].powi(2)).sqrt()
            + (tip_diameters_mm[1].powi(2) - d_b[1].powi(2)).sqrt())
        - CENTRE_DISTANCE_MM * alpha_wt.sin();
    g_alpha / (PI * m_t * alpha_t.cos())
}

/// d_a = d + 2 m_n (h_aP + x), mm (no tip alteration).
fn nominal_tip_diameters_mm() -> [f64; 2] {
    let m_t = MN_MM / BETA_DEG.to_radians().cos();
    [0, 1].map(|i| Z[i] * m_t + 2.0 * MN_MM * (H_AP + X[i]))
}

fn input(eps_alpha: f64) -> Iso6336Input {
    Iso6336Input {
        teeth_pinion: Z[0],
        teeth_gear: Z[1],
        profile_shift_pinion: X[0],
        profile_shift_gear: X[1],
        helix_angle_rad: BETA_DEG.to_radians(),
        normal_pressure_angle_rad: ALPHA_N_DEG.to_radians(),
        dedendum_coefficient_pinion: H_FP,
        dedendum_coefficient_gear: H_FP,
        transverse_contact_ratio: eps_alpha,
        blank_factor: 1.0,
        // 1273.5 N/mm: far above 100 N/mm, so no low-load correction applies.
        line_load_n_per_mm: Some(TANGENTIAL_LOAD_N / FACE_WIDTH_MM),
    }
}

#[test]
fn tr_6336_30_example_1_single_stiffness() {
    // c'_th and c' do not depend on eps_alpha.
    let s = input(1.5).evaluate().unwrap();
    // z_n published to 3 decimals.
    assert!(
        (s.virtual_teeth[0] - 18.905).abs() < 5e-4,
        "{:?}",
        s.virtual_teeth
    );
    assert!(
        (s.virtual_teeth[1] - 114.543).abs() < 5e-4,
        "{:?}",
        s.virtual_teeth
    );
    assert_eq!(s.low_load_factor, 1.0);
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    let c_th = s.theoretical_single_n_per_mm_um;
    let c1 = s.single_n_per_mm_um;
    assert!(
        (c_th - 17.85584).abs() < HALF_UNIT_5_DECIMALS,
        "c'_th = {c_th}"
    );
    assert!((c1 - 12.37047).abs() < HALF_UNIT_5_DECIMALS, "c' = {c1}");
}

#[test]
fn tr_6336_30_example_1_mesh_stiffness() {
    // Tip diameters as a drawing states them, to 0.01 mm: 159.66 / 872.35 mm (nominal
    // 159.6601 / 872.3548 mm). With these the published c_gamma_alpha and c_gamma_beta
    // are reproduced to every digit; the unrounded diameters give eps_alpha larger by
    // 2.5e-4, c_gamma_alpha larger by 2.3e-3 (checked below with its own tolerance).
    let nominal = nominal_tip_diameters_mm();
    assert!((nominal[0] - 159.66).abs() < 5e-3 && (nominal[1] - 872.35).abs() < 5e-3);
    let eps = transverse_contact_ratio([159.66, 872.35]);
    let s = input(eps).evaluate().unwrap();
    let (ca, cb) = (s.mesh_alpha_n_per_mm_um, s.mesh_beta_n_per_mm_um);
    assert!(
        (ca - 17.46485).abs() < HALF_UNIT_5_DECIMALS,
        "c_gamma_alpha = {ca}, eps = {eps}"
    );
    assert!(
        (cb - 14.84512).abs() < HALF_UNIT_5_DECIMALS,
        "c_gamma_beta = {cb}"
    );

    // Unrounded tips: d(eps)/d(d_a) = d_a / (2 p_bt sqrt(d_a^2 - d_b^2)) = 0.037 (pinion) and
    // 0.052 (gear) per mm here, so rounding to 0.01 mm (+-0.005 mm) moves eps by at most
    // 4.5e-4 and c_gamma_alpha by at most 0.75 c' 4.5e-4 = 4.2e-3.
    let eps_nominal = transverse_contact_ratio(nominal);
    let c_nom = input(eps_nominal)
        .evaluate()
        .unwrap()
        .mesh_alpha_n_per_mm_um;
    assert!(
        (c_nom - 17.46485).abs() < 4.2e-3,
        "c_gamma_alpha (unrounded tips) = {c_nom}"
    );
}

#[test]
fn tr_6336_30_example_1_in_newtons_per_metre() {
    // c' b = 12.37047 N/(mm um) x 100 mm = 1237.047 N/um = 1.237047e9 N/m.
    let s = input(1.5).evaluate().unwrap();
    let k = s.single_n_per_m(FACE_WIDTH_MM * 1e-3);
    assert!(
        (k - 1.237047e9).abs() < HALF_UNIT_5_DECIMALS * 100.0 * 1e6,
        "{k}"
    );
}
