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
//! 0.5 um, below 5 um to 0.1 um); `round_iso` does so for reports, the random model
//! uses the unrounded values. The 2013 edition has classes 1 to 11 and says its formulas
//! are not to be extrapolated; class 12 is one more step of sqrt(2), an extrapolation of
//! the 2013 formulas (not the grade 12 of the 1995 edition, whose formulas differ).
//!
//! Random model (`draw_gear`; the standard gives tolerances, not a distribution, so
//! this is our choice): a tooth's position error is a once-per-revolution wave plus its
//! own residual, e_i = c cos(2 pi i / z) + s sin(2 pi i / z) + r_i, taken about the mean
//! (a common offset is a rigid rotation). The wave's components c, s are normal with
//! standard deviation F_pT / (6 sqrt 2), so its range 2 sqrt(c^2 + s^2) is F_pT / 3 in
//! RMS: the long wave is what makes the cumulative pitch deviation. The residuals r_i
//! are independent normal with standard deviation f_pT / (3 sqrt 2), so that a single
//! pitch deviation f_pt,i = e_i - e_(i-1) has standard deviation near f_pT / 3. (Drawing
//! the single pitch deviations independently instead makes the positions a random walk
//! whose range grows like sqrt(z) f_pT, faster than F_pT grows with d = m z: from about
//! 100 teeth few such gears would pass the class's cumulative pitch tolerance, none
//! from about 400.) Profile slope and form deviations are independent normal with
//! standard deviations f_HalphaT / 3 and f_falphaT / 3. A gear is kept when it passes the
//! class's inspection: every |f_pt,i| <= f_pT, the cumulative pitch deviation (range of
//! the positions) <= F_pT, and on every tooth |f_Halpha| <= f_HalphaT,
//! |f_falpha| <= f_falphaT and the total profile deviation F_alpha <= F_alphaT; otherwise
//! the seeded stream draws again (a manufactured gear of the class is one that was
//! accepted). A gear that no draw of `MAX_DRAWS` passes is an error, not kept.

use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};

/// The flank tolerances of one gear for one class, um (unrounded).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlankTolerances {
    /// Flank tolerance class (ISO 1328-1:2013 classes 1 to 11).
    pub class: i64,
    /// Single pitch tolerance f_pT, um.
    pub single_pitch_um: f64,
    /// Total cumulative pitch tolerance F_pT, um.
    pub cumulative_pitch_um: f64,
    /// Profile slope tolerance f_HalphaT, um.
    pub profile_slope_um: f64,
    /// Profile form tolerance f_falphaT, um.
    pub profile_form_um: f64,
    /// Total profile tolerance F_alphaT, um.
    pub profile_total_um: f64,
    /// Run-out tolerance F_rT, um.
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

/// What of class `class` for a gear of `teeth` teeth, reference diameter `d_mm` and
/// normal module `m_mm` lies outside the scope of ISO 1328-1:2013 (classes 1 to 11,
/// 5 <= z <= 1000, 5 mm <= d <= 15 000 mm, 0.5 mm <= m_n <= 70 mm; its formulas are
/// not to be extrapolated), or None inside it.
pub(crate) fn outside_scope(class: i64, teeth: usize, d_mm: f64, m_mm: f64) -> Option<String> {
    let mut out = Vec::new();
    if !(1..=11).contains(&class) {
        out.push(format!("class {class} (1 to 11)"));
    }
    if !(5..=1000).contains(&teeth) {
        out.push(format!("{teeth} teeth (5 to 1000)"));
    }
    if !(5.0..=15_000.0).contains(&d_mm) {
        out.push(format!("d = {d_mm} mm (5 to 15 000 mm)"));
    }
    if !(0.5..=70.0).contains(&m_mm) {
        out.push(format!("m_n = {m_mm} mm (0.5 to 70 mm)"));
    }
    (!out.is_empty()).then(|| out.join(", "))
}

/// A published value as ISO 1328-1:2013, 5.2.3 rounds it, um.
pub(crate) fn round_iso(v_um: f64) -> f64 {
    if v_um > 10.0 {
        v_um.round()
    } else if v_um >= 5.0 {
        (2.0 * v_um).round() / 2.0
    } else {
        (10.0 * v_um).round() / 10.0
    }
}

/// The errors drawn for one gear, um: tooth positions (about their mean), profile slope
/// and form deviations per tooth.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct DrawnGear {
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

/// Total profile deviation F_alpha of a tooth with slope and form deviations `slope_um`,
/// `form_um`, um: the range over the flank (s in [-1, 1]) of the deviation the model
/// gives it, (f_Halpha / 2) s + f_falpha (1/3 - s^2) (`geometry::flank_shape`): the ends
/// and, where it lies inside, the parabola's vertex s* = f_Halpha / (4 f_falpha).
pub fn total_profile_deviation(slope_um: f64, form_um: f64) -> f64 {
    let g = |s: f64| 0.5 * slope_um * s + form_um * (1.0 / 3.0 - s * s);
    // The vertex where it lies inside, else an end again (no allocation per tooth).
    let vertex = if form_um != 0.0 {
        slope_um / (4.0 * form_um)
    } else {
        1.0
    };
    let values = [g(-1.0), g(1.0), g(vertex.clamp(-1.0, 1.0))];
    let max = values.iter().fold(f64::NEG_INFINITY, |m, v| m.max(*v));
    let min = values.iter().fold(f64::INFINITY, |m, v| m.min(*v));
    max - min
}

/// Whether drawn errors pass the class's inspection (module docs).
pub(crate) fn passes_inspection(
    tol: &FlankTolerances,
    position_um: &[f64],
    slope_um: &[f64],
    form_um: &[f64],
) -> bool {
    single_pitch_deviations(position_um)
        .iter()
        .all(|f| f.abs() <= tol.single_pitch_um)
        && cumulative_pitch_deviation(position_um) <= tol.cumulative_pitch_um
        && slope_um.iter().zip(form_um).all(|(h, f)| {
            h.abs() <= tol.profile_slope_um
                && f.abs() <= tol.profile_form_um
                && total_profile_deviation(*h, *f) <= tol.profile_total_um
        })
}

/// Standard normal by Box-Muller from the stream.
fn normal(r: &mut ChaCha8Rng) -> f64 {
    let u1 = 1.0 - r.random::<f64>(); // (0, 1]: ln is finite
    let u2 = r.random::<f64>();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

/// Draws tried before a gear counts as undrawable. A draw passes with probability about
/// 0.997^z from the single pitch test alone (each |f_pt,i| within 3 standard
/// deviations), 0.07 at the 1000 teeth the schema allows, so 1e4 draws fail only with
/// probability 0.93^1e4, never in practice.
pub(crate) const MAX_DRAWS: usize = 10_000;

/// No draw passed the class's inspection (the teeth and class, for the message).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Undrawable {
    pub teeth: usize,
    pub class: i64,
}

/// The errors of a gear of `teeth` teeth drawn for tolerances `tol` from stream `stream`
/// of `seed` (see the module docs).
pub(crate) fn draw_gear(
    teeth: usize,
    tol: &FlankTolerances,
    seed: u64,
    stream: u64,
) -> Result<DrawnGear, Undrawable> {
    let mut r = ChaCha8Rng::seed_from_u64(seed);
    r.set_stream(stream);
    let z = teeth.max(1) as f64;
    let wave_sd = tol.cumulative_pitch_um / (6.0 * std::f64::consts::SQRT_2);
    let residual_sd = tol.single_pitch_um / (3.0 * std::f64::consts::SQRT_2);
    for rejected in 0..MAX_DRAWS {
        let (c, s) = (wave_sd * normal(&mut r), wave_sd * normal(&mut r));
        let mut pos: Vec<f64> = (0..teeth)
            .map(|i| {
                let angle = std::f64::consts::TAU * i as f64 / z;
                c * angle.cos() + s * angle.sin() + residual_sd * normal(&mut r)
            })
            .collect();
        let mean = pos.iter().sum::<f64>() / z;
        pos.iter_mut().for_each(|p| *p -= mean);
        let slope: Vec<f64> = (0..teeth)
            .map(|_| tol.profile_slope_um / 3.0 * normal(&mut r))
            .collect();
        let form: Vec<f64> = (0..teeth)
            .map(|_| tol.profile_form_um / 3.0 * normal(&mut r))
            .collect();
        if passes_inspection(tol, &pos, &slope, &form) {
            return Ok(DrawnGear {
                position_um: pos,
                slope_um: slope,
                form_um: form,
                rejected,
            });
        }
    }
    Err(Undrawable {
        teeth,
        class: tol.class,
    })
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
    fn the_standards_scope_is_named_where_the_formulas_are_extrapolated() {
        assert_eq!(outside_scope(5, 19, 38.0, 2.0), None);
        assert_eq!(outside_scope(11, 1000, 15_000.0, 15.0), None);
        let s = outside_scope(12, 19, 4.75, 0.25).unwrap();
        assert!(s.contains("class 12") && s.contains("d = 4.75 mm") && s.contains("m_n = 0.25 mm"));
        assert!(outside_scope(5, 4, 8.0, 2.0).unwrap().contains("4 teeth"));
    }

    #[test]
    fn total_profile_deviation_is_the_range_of_the_drawn_profile() {
        // By hand: a slope alone spans f (from -f/2 to f/2), a form alone f (1/3 to -2/3).
        assert!((total_profile_deviation(4.0, 0.0) - 4.0).abs() < 1e-12);
        assert!((total_profile_deviation(0.0, -3.0) - 3.0).abs() < 1e-12);
        // s + 2/3 - 2 s^2: vertex s = 1/4 at 0.791 67, ends -7/3 and -1/3: range 3.125.
        assert!((total_profile_deviation(2.0, 2.0) - 3.125).abs() < 1e-12);
        // A second method: the range of 1e5 samples of the curve, which can only fall
        // short of the true range, by at most the curve's slope (<= 0.5 |f_H| + 2 |f_f|)
        // times half the 2e-5 sample spacing.
        for (h, f) in [(4.838, 6.1), (-3.0, 1.0), (1.0, -0.2), (7.0, 0.5)] {
            let n = 100_000;
            let g: Vec<f64> = (0..=n)
                .map(|i| {
                    let s = -1.0 + 2.0 * i as f64 / n as f64;
                    0.5 * h * s + f * (1.0 / 3.0 - s * s)
                })
                .collect();
            let sampled = cumulative_pitch_deviation(&g);
            let exact = total_profile_deviation(h, f);
            let bound = (0.5 * f64::abs(h) + 2.0 * f64::abs(f)) * 1e-5;
            assert!(
                exact >= sampled - 1e-12 && exact - sampled <= bound,
                "{h} {f}"
            );
        }
    }

    #[test]
    fn gears_of_up_to_a_thousand_teeth_are_drawn_within_their_class() {
        // The schema takes up to 1000 teeth: every such gear must pass its class's
        // inspection (checked here by the inspection's own parts, not by the draw's
        // verdict), with single pitch deviations of the intended spread.
        for (z, class) in [(5, 5), (100, 2), (400, 5), (1000, 9)] {
            let tol = flank_tolerances(class, z as f64, 1.0);
            let g = draw_gear(z, &tol, 11, 0).expect("a gear of the class");
            let f = single_pitch_deviations(&g.position_um);
            assert!(f.iter().all(|f| f.abs() <= tol.single_pitch_um), "z = {z}");
            assert!(cumulative_pitch_deviation(&g.position_um) <= tol.cumulative_pitch_um);
            assert!(g
                .slope_um
                .iter()
                .zip(&g.form_um)
                .all(|(h, f)| total_profile_deviation(*h, *f) <= tol.profile_total_um));
            assert!(g.position_um.iter().sum::<f64>().abs() < 1e-9 * z as f64);
            if z == 1000 {
                // 1000 differences of residuals of sd f_pT / (3 sqrt 2): sd f_pT / 3,
                // slightly less after the 3-sd truncation of the inspection (0.329);
                // the sample sd of 1000 values is within 2.2 % (one sd) of it, so
                // [0.30, 0.36] f_pT leaves more than 4 sd either way.
                let sd = (f.iter().map(|x| x * x).sum::<f64>() / z as f64).sqrt();
                let ratio = sd / tol.single_pitch_um;
                assert!(ratio > 0.30 && ratio < 0.36, "{ratio}");
            }
        }
    }

    #[test]
    fn drawn_gears_pass_their_inspection_and_repeat_with_the_seed() {
        for class in [2, 5, 9] {
            let tol = flank_tolerances(class, 62.0, 2.0);
            let g = draw_gear(31, &tol, 7, 1).unwrap();
            assert_eq!(g, draw_gear(31, &tol, 7, 1).unwrap());
            assert_ne!(
                g.position_um,
                draw_gear(31, &tol, 8, 1).unwrap().position_um
            );
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
