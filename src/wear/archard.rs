//! Archard wear per load cycle at every point of the active profiles.
//!
//! Archard (1953), paper eq. (14): dh = k p ds. Single-point observation (Flodin &
//! Andersson, Wear 207 (1997) 16): while a profile point passes through the Hertz band
//! of width 2a it slides over the mate by s_p = 2a |u_p - u_g| / u_p (pinion) and
//! s_g = 2a |u_p - u_g| / u_g (gear), with p the Hertz pressure at its contact (eq. 15,
//! standard form p0 = sqrt(w E*/(pi R)), docs/PAPER_NOTES.md). One pinion cycle (revolution) loads
//! each pinion tooth once and each gear tooth z1/z2 times on average, hence the factor
//! z1/z2 on the gear (eq. 17, docs/PAPER_NOTES.md: eq. 16 has a typo).

use super::tooth_wear::{SliceWear, ToothWear};
use crate::dynamics::response::{interpolate_path, PathSample};
use crate::geometry::ProfileGrid;

/// Wear depth added per pinion cycle at each grid point, m.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WearIncrement {
    /// Wear depth added to the pinion flank per pinion cycle at each grid point, m.
    pub pinion_m: Vec<f64>,
    /// Wear depth added to the gear flank per pinion cycle at each grid point, m.
    pub gear_m: Vec<f64>,
    /// Sliding distances per passage, m (for output and tests).
    pub sliding_pinion_m: Vec<f64>,
    /// Sliding distance of the gear flank per passage, m.
    pub sliding_gear_m: Vec<f64>,
    /// Per-tooth increments of a tooth-resolved mesh (`pinion_m`, `gear_m` then hold
    /// their means over the teeth).
    pub teeth: Option<ToothWear>,
    /// Per-slice increments of a helical pair (`pinion_m`, `gear_m` then hold their means
    /// over the face slices).
    pub slices: Option<SliceWear>,
}

impl WearIncrement {
    /// Largest increment on either profile, m per cycle (of any tooth when per tooth, of
    /// any face slice when per slice).
    pub fn max_m(&self) -> f64 {
        let common = self
            .pinion_m
            .iter()
            .chain(&self.gear_m)
            .fold(0.0_f64, |m, x| m.max(*x));
        let teeth = self
            .teeth
            .as_ref()
            .map_or(common, |t| t.max_m().max(common));
        self.slices.as_ref().map_or(teeth, |s| s.max_m().max(teeth))
    }
}

/// Archard increments per pinion cycle from the contact history along the path.
///
/// `path` is sorted by rho1 (a `DynamicResponse::path`), `coefficient_m2_per_n` is k,
/// `ratio_z1_z2` = z1/z2.
pub fn per_cycle_wear(
    grid: &ProfileGrid,
    path: &[PathSample],
    coefficient_m2_per_n: f64,
    ratio_z1_z2: f64,
) -> WearIncrement {
    let n = grid.len();
    let mut inc = WearIncrement {
        pinion_m: vec![0.0; n],
        gear_m: vec![0.0; n],
        sliding_pinion_m: vec![0.0; n],
        sliding_gear_m: vec![0.0; n],
        teeth: None,
        slices: None,
    };
    for i in 0..n {
        let s = interpolate_path(path, grid.rho_pinion_m[i]);
        let (up, ug) = (s.pinion_surface_speed_m_per_s, s.gear_surface_speed_m_per_s);
        if s.load_n <= 0.0 || up <= 0.0 || ug <= 0.0 {
            continue;
        }
        let slide = (up - ug).abs();
        let sp = 2.0 * s.half_width_m * slide / up;
        let sg = 2.0 * s.half_width_m * slide / ug;
        inc.sliding_pinion_m[i] = sp;
        inc.sliding_gear_m[i] = sg;
        inc.pinion_m[i] = coefficient_m2_per_n * s.pressure_pa * sp;
        inc.gear_m[i] = ratio_z1_z2 * coefficient_m2_per_n * s.pressure_pa * sg;
    }
    inc
}
