//! The shape of one gear's active flank besides the involute: profile modifications
//! (tip and root relief, a user deviation along the roll angle) and the profile slope and
//! form deviations of ISO 1328-1, each as a deviation normal to the profile, which at the
//! contact is along the line of action.
//!
//! Positions are the gear's own radius of curvature rho (m, the roll distance from its
//! base circle's tangency point); its active flank runs from the start of active profile
//! `sap` (where the mate's tip meets it) to its tip's contact point `tip`.
//!
//! - Relief (Tavakoli & Houser, J. Mech. Trans. Autom. Des. 108 (1986) 86; ISO 21771
//!   profile modifications): material removed (m) C (1 - u/L) for a linear relief and
//!   C (1 - u/L)^2 for a parabolic one, u < L the roll distance (m, along the line of
//!   action) from the tip's contact point (tip relief) or from the start of active profile
//!   (root relief), C the amount there and L the relief's length; nothing for u >= L.
//! - Profile slope deviation f_Halpha: linear over the active flank, from -f/2 at `sap` to
//!   +f/2 at `tip` (material added towards the tip when positive: the project's sign
//!   convention, not taken from the standard; zero mean). Slope and form are spread over
//!   the whole active flank, while ISO 1328-1 evaluates them over the profile evaluation
//!   range L_alpha, which stops short of the tip: measured over L_alpha, a drawn deviation
//!   would read slightly smaller than its value here.
//! - Profile form deviation f_falpha: a parabola f (1/3 - s^2), s = -1 at `sap` to 1 at
//!   `tip`: its peak-to-valley range is f, it has zero mean, and positive f bulges out in
//!   the middle (ISO 1328-1 defines the form deviation as the range of the residual about
//!   the mean line; a parabola is the lowest-order shape that has one).

use super::GearPair;

/// Which gear of the pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Side {
    Pinion,
    Gear,
}

/// The active flank of one gear: its start of active profile and tip contact, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ActiveFlank {
    pub sap_rho_m: f64,
    pub tip_rho_m: f64,
    /// Radius of curvature at the pitch point, m.
    pub pitch_rho_m: f64,
    pub base_radius_m: f64,
}

impl ActiveFlank {
    pub fn of(pair: &GearPair, side: Side) -> Self {
        let l = pair.loa_length_m;
        match side {
            Side::Pinion => Self {
                sap_rho_m: pair.rho_start_m,
                tip_rho_m: pair.rho_end_m,
                pitch_rho_m: pair.rho_pitch_m,
                base_radius_m: pair.pinion.base_radius_m,
            },
            Side::Gear => Self {
                sap_rho_m: l - pair.rho_end_m,
                tip_rho_m: l - pair.rho_start_m,
                pitch_rho_m: l - pair.rho_pitch_m,
                base_radius_m: pair.gear.base_radius_m,
            },
        }
    }

    /// Roll length of the addendum (pitch point to tip), m.
    pub(crate) fn addendum_roll_m(&self) -> f64 {
        self.tip_rho_m - self.pitch_rho_m
    }

    /// Roll length of the active dedendum (start of active profile to pitch point), m.
    pub(crate) fn dedendum_roll_m(&self) -> f64 {
        self.pitch_rho_m - self.sap_rho_m
    }
}

/// A relief: amount C (m) over length L (m) from an end of the flank.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Relief {
    pub amount_m: f64,
    pub length_m: f64,
    pub parabolic: bool,
}

impl Relief {
    /// Material removed at depth `u_m` into the relief from its end, m.
    fn at(&self, u_m: f64) -> f64 {
        if self.length_m <= 0.0 || u_m >= self.length_m {
            return 0.0;
        }
        let s = 1.0 - u_m.max(0.0) / self.length_m;
        self.amount_m * if self.parabolic { s * s } else { s }
    }
}

/// The flank's deviation from the involute common to every tooth of one gear: reliefs
/// and a user deviation along the roll angle (material removed positive, m).
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct FlankModification {
    pub tip: Option<Relief>,
    pub root: Option<Relief>,
    /// User deviation: own rho (m, ascending) and material removed (m); linear in
    /// between, constant beyond.
    pub user: Option<(Vec<f64>, Vec<f64>)>,
}

impl FlankModification {
    /// Material removed at own rho `rho_m` of a flank `f`, m.
    pub(crate) fn removed_m(&self, f: &ActiveFlank, rho_m: f64) -> f64 {
        let mut h = 0.0;
        if let Some(r) = &self.tip {
            h += r.at(f.tip_rho_m - rho_m);
        }
        if let Some(r) = &self.root {
            h += r.at(rho_m - f.sap_rho_m);
        }
        if let Some((x, y)) = &self.user {
            h += interpolate_clamped(x, y, rho_m);
        }
        h
    }
}

/// Material added by profile slope and form deviations `slope_m`, `form_m` at own rho,
/// m (see the module docs).
pub(crate) fn slope_form_added_m(f: &ActiveFlank, rho_m: f64, slope_m: f64, form_m: f64) -> f64 {
    let span = f.tip_rho_m - f.sap_rho_m;
    if span <= 0.0 {
        return 0.0;
    }
    let s = (2.0 * (rho_m - f.sap_rho_m) / span - 1.0).clamp(-1.0, 1.0);
    0.5 * slope_m * s + form_m * (1.0 / 3.0 - s * s)
}

/// Piecewise-linear interpolation of (x ascending, y) at `x0`, constant beyond the ends.
pub(crate) fn interpolate_clamped(x: &[f64], y: &[f64], x0: f64) -> f64 {
    let n = x.len().min(y.len());
    match n {
        0 => 0.0,
        1 => y[0],
        _ => {
            if x0 <= x[0] {
                return y[0];
            }
            if x0 >= x[n - 1] {
                return y[n - 1];
            }
            let j = x[..n].partition_point(|v| *v <= x0).clamp(1, n - 1);
            let t = (x0 - x[j - 1]) / (x[j] - x[j - 1]);
            y[j - 1] + (y[j] - y[j - 1]) * t
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::case::GearSection;

    #[test]
    fn reliefs_and_deviations_by_hand() {
        let p = GearPair::from_case(&GearSection::default()).unwrap();
        let f = ActiveFlank::of(&p, Side::Gear);
        assert!((f.tip_rho_m - p.gear.tip_rho_m()).abs() < 1e-15);
        let m = FlankModification {
            tip: Some(Relief {
                amount_m: 10e-6,
                length_m: 1e-3,
                parabolic: false,
            }),
            root: Some(Relief {
                amount_m: 4e-6,
                length_m: 0.5e-3,
                parabolic: true,
            }),
            user: None,
        };
        // Linear tip relief: full at the tip, half 0.5 mm in, none at 1 mm.
        assert!((m.removed_m(&f, f.tip_rho_m) - 10e-6).abs() < 1e-18);
        assert!((m.removed_m(&f, f.tip_rho_m - 0.5e-3) - 5e-6).abs() < 1e-15);
        assert_eq!(m.removed_m(&f, f.tip_rho_m - 1.2e-3), 0.0);
        // Parabolic root relief: a quarter of the amount half way in.
        assert!((m.removed_m(&f, f.sap_rho_m + 0.25e-3) - 1e-6).abs() < 1e-15);
        // Slope: +-f/2 at the ends, 0 in the middle; form: range f, zero mean.
        let mid = 0.5 * (f.sap_rho_m + f.tip_rho_m);
        assert!((slope_form_added_m(&f, f.tip_rho_m, 6e-6, 0.0) - 3e-6).abs() < 1e-18);
        assert!(slope_form_added_m(&f, mid, 6e-6, 0.0).abs() < 1e-18);
        let ends = slope_form_added_m(&f, f.sap_rho_m, 0.0, 3e-6);
        let centre = slope_form_added_m(&f, mid, 0.0, 3e-6);
        assert!((centre - ends - 3e-6).abs() < 1e-18);
        assert!((interpolate_clamped(&[0.0, 1.0], &[2.0, 4.0], 0.25) - 2.5).abs() < 1e-15);
        assert_eq!(interpolate_clamped(&[0.0, 1.0], &[2.0, 4.0], 7.0), 4.0);
    }
}
