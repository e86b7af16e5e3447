//! Flank tolerances of ISO 1328-1:2013 (cylindrical gears, ISO system of flank tolerance
//! classification), the formulas of its clause 5, and the random teeth drawn for a class.
//!
//! For flank tolerance class A, reference diameter d and normal module m_n (both mm),
//! the tolerances in micrometres are the class-5 values times the step factor
//! sqrt(2)^(A - 5) (5.2.2):
//! - single pitch f_pT = (0.001 d + 0.4 m_n + 5) sqrt(2)^(A-5)                  (eq. 5)
//! - total cumulative pitch F_pT = (0.002 d + 0.55 sqrt(d) + 0.7 m_n + 12) ...   (eq. 6)
//! - profile slope f_HalphaT = (0.4 m_n + 0.001 d + 4) ...                         (eq. 7)
//! - profile form f_falphaT = (0.55 m_n + 5) ...                                   (eq. 8)
//! - total profile F_alphaT = sqrt(f_HalphaT^2 + f_falphaT^2)                      (eq. 9)
//! - radial run-out (informative annex) F_rT = 0.9 F_pT.
//!
//! The standard rounds published values (5.2.3: above 10 um to 1 um, 5 to 10 um to
//! 0.5 um, below 5 um to 0.1 um); [`round_iso`] does so for reports, the random model
//! uses the unrounded values. The 2013 edition has classes 1 to 11; class 12 (the 1995
//! edition's coarsest grade) is one more step of sqrt(2).
//!
//! Random model ([`draw_gear`]): the single pitch deviations f_pt,i are independent
//! normal with standard deviation f_pT / 3, made to close the circle (their mean is
//! removed: the pitches of a gear add up to a full turn); the tooth positions are their
//! running sums, taken about their mean (a common offset is a rigid rotation). Profile
//! slope and form deviations are independent normal with standard deviations f_HalphaT / 3
//! and f_falphaT / 3. A gear is kept when it passes the class's inspection: every
//! |f_pt,i| <= f_pT, the cumulative pitch deviation (range of the positions) <= F_pT,
//! every |f_Halpha| <= f_HalphaT and |f_falpha| <= f_falphaT; otherwise the seeded stream
//! draws again (a manufactured gear of the class is one that was accepted).

use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};

/// The flank tolerances of one gear for one class, um (unrounded).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlankTolerances {
    pub class: i64,
    pub single_pitch_um: f64,
    pub cumulative_pitch_um: f64,
    pub profile_slope_um: f64,
    pub profile_form_um: f64,
    pub profile_total_um: f64,
    pub runout_um: f64,
}

/// ISO 1328-1:2013 tolerances (clause 5, eq. 5-9; run-out from its annex) of class
/// `class` for reference diameter `d_mm` and normal module `m_mm`.
pub fn flank_tolerances(class: i64, d_mm: f64, m_mm: f64) -> FlankTolerances {
    let step = std::f64::consts::SQRT_2.powi(class as i32 - 5);
    let f_pt = (0.001 * d_mm + 0.4 * m_mm + 5.0) * step;
    let f_p = (0.002 * d_mm + 0.55 * d_mm.sqrt() + 0.7 * m_mm + 12.0) * step;
    let f_ha = (0.4 * m_mm + 0.001 * d_mm + 4.0) * step;
    let f_fa = (0.55 * m_mm + 5.0) * step;
    FlankTolerances {
        class,
        single_pitch_um: f_pt,
        cumulative_pitch_um: f_p,
        profile_slope_um: f_ha,
        profile_form_um: f_fa,
        profile_total_um: f_ha.hypot(f_fa),
        runout_um: 0.9 * f_p,
    }
}

/// A published value as ISO 1328-1:2013, 5.2.3 rounds it, um.
pub fn round_iso(v_um: f64) -> f64 {
    if v_um > 10.0 {
        v_um.round()
    } else if v_um >= 5.0 {
        (2.0 * v_um).round() / 2.0
    } else {
        (10.0 * v_um).round() / 10.0
    }
}

/// The errors drawn for one gear, um: tooth positions (running sums of the single pitch
/// deviations, about their mean), profile slope and form deviations per tooth.
#[derive(Debug, Clone, PartialEq)]
pub struct DrawnGear {
    pub position_um: Vec<f64>,
    pub slope_um: Vec<f64>,
    pub form_um: Vec<f64>,
    /// Draws rejected by the inspection before this one was kept.
    pub rejected: usize,
}

/// Single pitch deviations of tooth positions, um: f_pt,i = e_i - e_(i-1) (cyclic).
pub fn single_pitch_deviations(position_um: &[f64]) -> Vec<f64> {
    let n = position_um.len();
    (0..n)
        .map(|i| position_um[i] - position_um[(i + n - 1) % n])
        .collect()
}

/// Cumulative pitch deviation F_p of tooth positions: their range, um.
pub fn cumulative_pitch_deviation(position_um: &[f64]) -> f64 {
    let max = position_um.iter().fold(f64::NEG_INFINITY, |m, v| m.max(*v));
    let min = position_um.iter().fold(f64::INFINITY, |m, v| m.min(*v));
    if position_um.is_empty() {
        0.0
    } else {
        max - min
    }
}

/// Standard normal by Box-Muller from the stream.
fn normal(r: &mut ChaCha8Rng) -> f64 {
    let u1 = 1.0 - r.random::<f64>(); // (0, 1]: ln is finite
    let u2 = r.random::<f64>();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

/// Largest number of draws before the last one is kept regardless (with z teeth the
/// chance of passing falls like 0.997^z; 1e4 draws cover any z the model takes).
const MAX_DRAWS: usize = 10_000;

/// The errors of a gear of `teeth` teeth drawn for tolerances `tol` from stream `stream`
/// of `seed` (see the module docs).
pub fn draw_gear(teeth: usize, tol: &FlankTolerances, seed: u64, stream: u64) -> DrawnGear {
    let mut r = ChaCha8Rng::seed_from_u64(seed);
    r.set_stream(stream);
    let mut rejected = 0;
    loop {
        let mut fpt: Vec<f64> = (0..teeth)
            .map(|_| tol.single_pitch_um / 3.0 * normal(&mut r))
            .collect();
        let mean = fpt.iter().sum::<f64>() / teeth.max(1) as f64;
        fpt.iter_mut().for_each(|f| *f -= mean);
        // e_0 = 0, e_i = e_(i-1) + f_pt,i; f_pt,0 = e_0 - e_(z-1) holds as the f sum to 0.
        let mut pos = Vec::with_capacity(teeth);
        let mut acc = 0.0;
        for (i, f) in fpt.iter().enumerate() {
            if i > 0 {
                acc += f;
            }
            pos.push(acc);
        }
        let pmean = pos.iter().sum::<f64>() / teeth.max(1) as f64;
        pos.iter_mut().for_each(|p| *p -= pmean);
        let slope: Vec<f64> = (0..teeth)
            .map(|_| tol.profile_slope_um / 3.0 * normal(&mut r))
            .collect();
        let form: Vec<f64> = (0..teeth)
            .map(|_| tol.profile_form_um / 3.0 * normal(&mut r))
            .collect();
        let ok = single_pitch_deviations(&pos)
            .iter()
            .all(|f| f.abs() <= tol.single_pitch_um)
            && cumulative_pitch_deviation(&pos) <= tol.cumulative_pitch_um
            && slope.iter().all(|f| f.abs() <= tol.profile_slope_um)
            && form.iter().all(|f| f.abs() <= tol.profile_form_um);
        if ok || rejected + 1 >= MAX_DRAWS {
            return DrawnGear {
                position_um: pos,
                slope_um: slope,
                form_um: form,
                rejected,
            };
        }
        rejected += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn class_5_values_follow_the_formulas_by_hand() {
        // d = 38 mm, m_n = 2 mm (the paper's pinion):
        // f_pT = 0.038 + 0.8 + 5 = 5.838; F_pT = 0.076 + 0.55 sqrt(38) + 1.4 + 12 = 16.866;
        // f_HaT = 0.8 + 0.038 + 4 = 4.838; f_faT = 1.1 + 5 = 6.1.
        let t = flank_tolerances(5, 38.0, 2.0);
        assert!((t.single_pitch_um - 5.838).abs() < 1e-12);
        assert!((t.cumulative_pitch_um - (13.476 + 0.55 * 38f64.sqrt())).abs() < 1e-12);
        assert!((t.profile_slope_um - 4.838).abs() < 1e-12);
        assert!((t.profile_form_um - 6.1).abs() < 1e-12);
        assert!((t.runout_um - 0.9 * t.cumulative_pitch_um).abs() < 1e-12);
        // One class coarser multiplies every tolerance by sqrt(2).
        let t6 = flank_tolerances(6, 38.0, 2.0);
        assert!((t6.single_pitch_um / t.single_pitch_um - 2f64.sqrt()).abs() < 1e-12);
        // Rounding of 5.2.3.
        assert_eq!(round_iso(16.866), 17.0);
        assert_eq!(round_iso(5.838), 6.0);
        assert_eq!(round_iso(4.838), 4.8);
    }

    #[test]
    fn drawn_gears_pass_their_inspection_and_repeat_with_the_seed() {
        for class in [2, 5, 9] {
            let tol = flank_tolerances(class, 62.0, 2.0);
            let g = draw_gear(31, &tol, 7, 1);
            assert_eq!(g, draw_gear(31, &tol, 7, 1));
            assert_ne!(g.position_um, draw_gear(31, &tol, 8, 1).position_um);
            assert!(single_pitch_deviations(&g.position_um)
                .iter()
                .all(|f| f.abs() <= tol.single_pitch_um));
            assert!(cumulative_pitch_deviation(&g.position_um) <= tol.cumulative_pitch_um);
            assert!(g.position_um.iter().sum::<f64>().abs() < 1e-9);
            // The spread is set by the class: sample std of f_pt near f_pT / 3 (31
            // values of a truncated normal: within a factor 2 either way).
            let f = single_pitch_deviations(&g.position_um);
            let sd = (f.iter().map(|x| x * x).sum::<f64>() / f.len() as f64).sqrt();
            assert!(sd > tol.single_pitch_um / 6.0 && sd < tol.single_pitch_um / 1.5);
        }
    }
}
