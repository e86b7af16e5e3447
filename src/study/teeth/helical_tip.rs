//! A broken tip on a helical tooth (docs/MODEL.md 11.12): the tip is gone down to the radius
//! r_a - h over the face slices the fault covers, so each covered slice of the tooth's
//! contact line stops touching where its own transverse position passes the cut (the spur
//! pair's broken tip, section 9.5, slice by slice), and the whole line stops touching once
//! none of its slices on the path is left uncut.
//!
//! Positions are the transverse path's pinion rho1 (m). A line's slice i (offset o_i from its
//! trailing end, on face slice j) touches while its position r = rho + o_i lies on the path
//! [A, E] and, if a cut covers it, on its tooth's side of the cut: r <= l for a pinion tooth
//! (its tip toward E), r >= l for a gear tooth (its tip toward A). So in the line pair's
//! trailing-end coordinate rho it touches on [lo_i - o_i, hi_i - o_i] (empty where the cut
//! lies off the path on the wrong side: the covered slice never touches), and the line on
//! the union of these. The tooth-resolved mesh ends a tooth's contact at one limit
//! (`ToothFlank::contact_limit_rho1_m`: a pinion tooth touches below it, a gear tooth
//! above), so the union must be one interval holding the healthy line's start (a pinion
//! tooth) or end (a gear tooth). It is when the cut leaves at least one slice spacing
//! L / N of the path uncut on the tooth's root side (the trailing slice in contact is then
//! always followed by an uncut one on the path); a tip broken closer to the start of
//! active profile over part of the face can end the line's contact and start it again
//! (its cut leading slices enter first), which that limit cannot hold: refused, naming
//! the key, the value and a sufficient range.

use crate::dynamics::tooth_mesh::ToothFlank;
use crate::geometry::flank_shape::Side;
use crate::geometry::GearPair;

/// Lengths compared on the path within this, m (rounding of sums of offsets).
const SAME_M: f64 = 1e-12;

/// A broken tip's cut on the transverse path: the pinion rho1 `limit_rho1_m` (m) beyond
/// which its tooth does not touch, toward the tooth's own tip (`side`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct TipCut {
    side: Side,
    limit_rho1_m: f64,
}

impl TipCut {
    /// The cut a fault's flank on the transverse pair carries (`study::teeth::apply_fault`
    /// sets its `contact_limit_rho1_m`), None for a crack or a spall.
    pub(super) fn of(flank: &ToothFlank, side: Side) -> Option<Self> {
        flank.contact_limit_rho1_m.map(|l| Self {
            side,
            limit_rho1_m: l,
        })
    }

    /// Whether a covered slice at pinion rho1 `r_m` lies beyond the cut (no contact).
    #[inline]
    pub(super) fn cuts(&self, r_m: f64) -> bool {
        match self.side {
            Side::Pinion => r_m > self.limit_rho1_m,
            Side::Gear => r_m < self.limit_rho1_m,
        }
    }
}

/// Where a tooth's contact line touches (module docs): `offsets` its slices' (face slice
/// j, offset o_i, m), `path` the transverse path [A, E], `cuts` each broken tip's face
/// slices covered and cut, `side` the tooth's gear. Ok(None): no slice is cut; Ok(Some(l)):
/// the limit in the line pair's trailing-end rho (m) of the module docs, below the line
/// pair's start `rho_start_m` for a pinion tooth that never touches (above `path.1` for
/// a gear's); Err(()): the line's contact would end and start again.
pub(super) fn line_limit(
    offsets: &[(usize, f64)],
    path: (f64, f64),
    rho_start_m: f64,
    cuts: &[(&[bool], TipCut)],
    side: Side,
) -> Result<Option<f64>, ()> {
    if cuts.is_empty() || offsets.is_empty() {
        return Ok(None);
    }
    let (a, e) = path;
    let mut live: Vec<(f64, f64)> = offsets
        .iter()
        .filter_map(|&(j, o)| {
            let (mut lo, mut hi) = (a, e);
            for (_, cut) in cuts.iter().filter(|(c, _)| c[j]) {
                match cut.side {
                    Side::Pinion => hi = hi.min(cut.limit_rho1_m),
                    Side::Gear => lo = lo.max(cut.limit_rho1_m),
                }
            }
            (lo <= hi).then_some((lo - o, hi - o))
        })
        .collect();
    let o_min = offsets.iter().map(|x| x.1).fold(f64::INFINITY, f64::min);
    let o_max = offsets
        .iter()
        .map(|x| x.1)
        .fold(f64::NEG_INFINITY, f64::max);
    let healthy = (a - o_max, e - o_min);
    live.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut merged: Vec<(f64, f64)> = Vec::new();
    for (lo, hi) in live {
        match merged.last_mut() {
            Some(m) if lo <= m.1 + SAME_M => m.1 = m.1.max(hi),
            _ => merged.push((lo, hi)),
        }
    }
    let Some(&(lo, hi)) = merged.first() else {
        // No slice ever touches: the limit beyond the whole line pair.
        return Ok(Some(match side {
            Side::Pinion => rho_start_m - 1.0,
            Side::Gear => e + 1.0,
        }));
    };
    if merged.len() > 1 {
        return Err(());
    }
    match side {
        Side::Pinion if lo > healthy.0 + SAME_M => Err(()),
        Side::Pinion => Ok((hi < healthy.1 - SAME_M).then_some(hi)),
        Side::Gear if hi < healthy.1 - SAME_M => Err(()),
        Side::Gear => Ok((lo > healthy.0 + SAME_M).then_some(lo)),
    }
}

/// The largest removed height (m) that leaves one slice spacing `spacing_m` (L / N) of the
/// path [A, E] uncut on the tooth's root side (module docs), a sufficient bound for a line
/// that touches over one stretch: for the pinion r_a1 - sqrt(r_b1^2 + (A + L/N)^2), for the
/// gear, whose own radius of curvature at A's mate E is loa - E, r_a2 - sqrt(r_b2^2 +
/// (loa - E + L/N)^2) (the involute's r^2 = r_b^2 + rho^2); 0 when the path is shorter.
pub(super) fn max_removed_height_m(pair: &GearPair, side: Side, spacing_m: f64) -> f64 {
    let (g, rho) = match side {
        Side::Pinion => (&pair.pinion, pair.rho_start_m + spacing_m),
        Side::Gear => (&pair.gear, pair.loa_length_m - pair.rho_end_m + spacing_m),
    };
    (g.tip_radius_m - (g.base_radius_m.powi(2) + rho.powi(2)).sqrt()).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cut(side: Side, l: f64) -> TipCut {
        TipCut {
            side,
            limit_rho1_m: l,
        }
    }

    #[test]
    fn a_whole_face_cut_ends_the_line_when_its_trailing_slice_passes_it() {
        // Four slices at offsets 0.5, 1.5, 2.5, 3.5 on a path [10, 20], line pair from 6.
        let offsets: Vec<(usize, f64)> = (0..4).map(|j| (j, j as f64 + 0.5)).collect();
        let limit = |covers: [bool; 4], side: Side, l: f64| {
            line_limit(
                &offsets,
                (10.0, 20.0),
                6.0,
                &[(&covers, cut(side, l))],
                side,
            )
        };
        let all = [true; 4];
        // The pinion's cut at 15 leaves the line touching until its trailing slice (0.5)
        // passes 15, i.e. rho = 14.5; the gear's from when its leading slice (3.5)
        // reaches 15.
        assert_eq!(limit(all, Side::Pinion, 15.0), Ok(Some(14.5)));
        assert_eq!(limit(all, Side::Gear, 15.0), Ok(Some(11.5)));
        // Half the face, the trailing slices: the leading ones touch until they leave at
        // E (rho = 20 - 2.5 = 17.5), after the cut ones stopped (15 - 0.5).
        let half = [true, true, false, false];
        assert_eq!(limit(half, Side::Pinion, 15.0), Ok(Some(17.5)));
        // Cut below A on the leading half: the line's first slices to enter never touch,
        // so it would start touching late: refused.
        let lead = [false, false, true, true];
        assert_eq!(limit(lead, Side::Pinion, 9.0), Err(()));
        // Below A over the whole face: never touches (the limit below the line pair).
        assert_eq!(limit(all, Side::Pinion, 9.0), Ok(Some(5.0)));
    }
}
