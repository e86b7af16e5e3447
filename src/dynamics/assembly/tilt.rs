//! The tilting terms of a helical mesh in the assembled coordinates (docs/MODEL.md 11.8):
//! how each body's tilts about the train's x and y axes enter the mesh deflection, and the
//! mesh's own tilting spring.
//!
//! Frame. d is the transverse line of action (the force on the pinion is -F d), z the
//! pinion's axis along its angular velocity (z = s z_plane, s the pinion's sense of
//! rotation in the plane) and n = d x z the normal of the plane of action, pointing from
//! the pinion's centre to the plane. A body's small tilt (theta_x, theta_y) about the
//! plane's x and y axes has the components a = theta . n and b = theta . d.

use super::elements::MeshLink;

/// n = d x z in the plane for the line of action `d` and the pinion's sense `spin`.
pub(crate) fn plane_normal(d: [f64; 2], spin: f64) -> [f64; 2] {
    [spin * d[1], -spin * d[0]]
}

/// d delta / d theta of the mesh `link` on the tilting coordinates (x, then y) of pinion
/// and gear, `tilts` their first (x) coordinates where the body tilts; m/rad. From the
/// deflection's tilting part (`MeshTilt`'s docs)
///   -mu a_p + (mu - s t L) a_g + s t (r_b1 b_p + r_b2 b_g),
/// with a = theta_x n_x + theta_y n_y and b = theta_x d_x + theta_y d_y.
pub(crate) fn tilt_gradient(
    link: &MeshLink,
    d: [f64; 2],
    spin: f64,
    tilts: [Option<usize>; 2],
) -> Vec<(usize, f64)> {
    let Some(t) = link.tilt else {
        return Vec::new();
    };
    let n = plane_normal(d, spin);
    let st = t.signed_tan_base_helix;
    let [rb1, rb2] = link.base_radius_m;
    // Coefficients of a and b for pinion and gear.
    let coef = [
        (-t.centre_lever_m, st * rb1),
        (t.centre_lever_m - st * t.line_of_action_length_m, st * rb2),
    ];
    let mut g = Vec::with_capacity(4);
    for (tilt, (ca, cb)) in tilts.into_iter().zip(coef) {
        if let Some(x) = tilt {
            g.push((x, ca * n[0] + cb * d[0]));
            g.push((x + 1, ca * n[1] + cb * d[1]));
        }
    }
    g
}

/// d tau / d theta, tau = a_g - a_p the relative tilt about n on which the mesh's
/// tilting spring acts, on the tilting coordinates of pinion and gear; rad/rad.
pub(crate) fn relative_tilt_gradient(
    d: [f64; 2],
    spin: f64,
    tilts: [Option<usize>; 2],
) -> Vec<(usize, f64)> {
    let n = plane_normal(d, spin);
    let mut h = Vec::with_capacity(4);
    for (tilt, sign) in tilts.into_iter().zip([-1.0, 1.0]) {
        if let Some(x) = tilt {
            h.push((x, sign * n[0]));
            h.push((x + 1, sign * n[1]));
        }
    }
    h
}
