//! A tooth thinned by wear in the potential energy integrals (severe wear, issue 18): the
//! flank that carries the load has lost w(rho) normal to the profile, so at height y the
//! section is t = 2h - w thick instead of 2h (area t b, second moment t^3 b / 12, moment
//! arm from the centreline as for the cracked tooth, `tooth_faults`). The wear depth is
//! normal to the involute, which at a point of roll angle u makes the angle u with the
//! section; taking the whole depth across the section overestimates the thinning by
//! 1/cos(u) - 1 (at most 6 % on the paper's pinion), well inside the other simplifications
//! of the beam model. Below the start of active profile nothing is worn.

use super::potential_energy::{GaussLegendre, ToothBeam};
use crate::geometry::flank_shape::interpolate_clamped;

/// Compliance (m/N) the wear `wear_m` at own radii of curvature `rho_m` (ascending, the
/// worn part of the flank) adds to `beam` loaded at own rho `load_rho_m`.
pub fn worn_compliance_m_per_n(
    beam: &ToothBeam,
    rho_m: &[f64],
    wear_m: &[f64],
    load_rho_m: f64,
) -> f64 {
    if wear_m.iter().all(|w| *w <= 0.0) || rho_m.is_empty() {
        return 0.0;
    }
    let (lo, hi) = (rho_m[0], rho_m[rho_m.len() - 1]);
    let rb = beam.base_radius_m;
    let b = beam.face_width_m;
    let worn = beam.compliance_with_section(load_rho_m, GaussLegendre::default_rule(), |h, y| {
        // The flank point at this height: radius r, radius of curvature sqrt(r^2 - rb^2).
        let r2 = h * h + y * y;
        let rho = (r2 - rb * rb).max(0.0).sqrt();
        let w = if r2 > rb * rb && rho >= lo && rho <= hi {
            interpolate_clamped(rho_m, wear_m, rho).max(0.0)
        } else {
            0.0
        };
        let t = (2.0 * h - w).max(1e-3 * h);
        (t * b, t * t * t * b / 12.0)
    });
    worn.total_m_per_n() - beam.compliance(load_rho_m).total_m_per_n()
}
