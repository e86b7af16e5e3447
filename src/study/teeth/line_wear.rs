//! What a helical pair's teeth keep for their wear tooth by tooth and slice by slice
//! (docs/MODEL.md 11.13): each tooth's transverse sections before wear (its errors'
//! removed material on the wear grid and its faults, with the face slices each covers),
//! and, at each sample of the line pair, the slices of the contact line on the path with
//! their healthy stiffnesses, so that a tooth's own wear per face slice becomes its
//! contact line's gap.
//!
//! **A tooth's worn line.** Tooth t's wear h_t,j on face slice j (normal to the flank, on
//! the transverse wear grid) enters its contact line at the line pair's sample rho as
//!   w_t(rho) = sum_i k_i h_t,j(i)(rho + o_i) / (cos(beta_b) sum_i k_i),
//! the stiffness-weighted mean of its slices' depths along the transverse line of action
//! (`study::helical::slice_gap_m` for one flank), with the healthy slice stiffnesses k_i:
//! the weights of the identical teeth's worn line (`HelicalDynamics::wear_gap`), so that
//! teeth worn alike give the pair that line's gap. The sum runs over the slices that touch:
//! a slice the tooth's broken tip cuts is left out, as its errors' line leaves it out
//! (`helical::line_flank`); where none touches, the line holds its nearest touching
//! sample's value. Where no slice of the line is on the path (it is about to enter or has
//! just left), the line takes its nearest slice's depth at the path's end, as
//! `HelicalDynamics::wear_gap` does.

use super::helical_tip::TipCut;
use crate::dynamics::tooth_mesh::ToothFlank;
use crate::geometry::ProfileGrid;

/// One fault of a tooth on the slice: its tables on the wear grid (compliance, the pit's
/// gap in `removed_m`), which face slices it covers, and a broken tip's cut
/// (docs/MODEL.md 11.12).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SliceFault {
    pub(super) flank: ToothFlank,
    pub(super) covers: Vec<bool>,
    pub(super) cut: Option<TipCut>,
}

impl SliceFault {
    /// Whether this fault's broken tip takes face slice `j` at pinion rho1 `r_m` out of
    /// contact.
    #[inline]
    pub(super) fn cuts(&self, j: usize, r_m: f64) -> bool {
        self.covers[j] && self.cut.is_some_and(|c| c.cuts(r_m))
    }
}

/// One tooth's transverse sections before wear: its errors' removed material on the wear
/// grid (m, empty where it is zero everywhere) and its faults.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ToothSlices {
    pub(super) removed_m: Vec<f64>,
    pub(super) faults: Vec<SliceFault>,
}

impl ToothSlices {
    /// Face slice `j` of this tooth at pinion rho1 `r_m`: its gap (the errors' removed
    /// material and a spall's pit, m) and its faults' compliance (m/N), or None where a
    /// broken tip takes it out of contact.
    #[inline]
    pub(crate) fn at(&self, grid: &ProfileGrid, j: usize, r_m: f64) -> Option<(f64, f64)> {
        if self.faults.iter().any(|x| x.cuts(j, r_m)) {
            return None;
        }
        let mut gap = if self.removed_m.is_empty() {
            0.0
        } else {
            grid.interpolate(&self.removed_m, r_m)
        };
        let mut c = 0.0;
        for x in self.faults.iter().filter(|x| x.covers[j]) {
            if let Some(t) = &x.flank.compliance_m_per_n {
                c += grid.interpolate(t, r_m);
            }
            gap += grid.interpolate(&x.flank.removed_m, r_m);
        }
        Some((gap, c))
    }
}

/// The line's slices at one sample of the line pair (module docs): those on the path
/// (face slice j, pinion rho1 of the slice m, healthy stiffness N/m), or, where none is,
/// the nearest slice at the path's end.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum LineCell {
    /// The slices on the path.
    On(Vec<(usize, f64, f64)>),
    /// No slice on the path: the nearest one's face slice and its position clamped to
    /// the path.
    Nearest(usize, f64),
}

impl LineCell {
    /// The line's gap from each slice's gap `g(j, rho1)` (None where the slice does not
    /// touch): the stiffness-weighted mean of the touching slices on the path, or the
    /// nearest slice's; None where no slice of the line touches.
    pub(crate) fn gap(&self, g: impl Fn(usize, f64) -> Option<f64>) -> Option<f64> {
        match self {
            LineCell::On(v) => {
                let (mut kg, mut k) = (0.0, 0.0);
                for &(j, x, ki) in v {
                    if let Some(gi) = g(j, x) {
                        kg += ki * gi;
                        k += ki;
                    }
                }
                (k > 0.0).then(|| kg / k)
            }
            LineCell::Nearest(j, x) => g(*j, *x),
        }
    }
}

/// What a helical pair's teeth keep for their wear (module docs).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LineTeeth {
    /// Face slices N: tooth t's face slice j is profile t N + j of a wear state
    /// (`WearState::teeth`, docs/MODEL.md 11.13).
    pub(crate) slices: usize,
    /// cos(beta_b): a normal depth over it is its gap along the transverse line of action.
    pub(crate) cos_base_helix: f64,
    /// The transverse wear grid.
    pub(crate) grid: ProfileGrid,
    /// The line's slices at each sample of the line pair.
    pub(crate) cells: Vec<LineCell>,
    /// The line's slices: (face slice j, offset o_i from the trailing end, m).
    pub(crate) offsets: Vec<(usize, f64)>,
    /// The transverse path [A, E], pinion rho1, m.
    pub(crate) path: (f64, f64),
    /// Each pinion tooth's sections, tooth order.
    pub(crate) pinion: Vec<ToothSlices>,
    /// Each gear tooth's sections, tooth order.
    pub(crate) gear: Vec<ToothSlices>,
}

impl LineTeeth {
    /// Tooth `t`'s worn line (module docs) added to its flank's removed material `removed`
    /// (one value per sample of the line pair); `wear` holds every tooth's face slices'
    /// profiles, tooth t's at t N .. (t + 1) N, and `sections` is the tooth's before wear:
    /// a slice its broken tip cuts does not count, as in its errors' line
    /// (`helical::line_flank`). Where none of the line's slices touches, the line holds its
    /// nearest touching sample's value (the errors' line holds its own past its limit).
    pub(crate) fn add_wear(
        &self,
        removed: &mut [f64],
        wear: &[Vec<f64>],
        t: usize,
        sections: &ToothSlices,
    ) {
        let n = self.slices;
        let Some(own) = wear.get(t * n..(t + 1) * n) else {
            return;
        };
        let cos_bb = self.cos_base_helix;
        let touching = |j: usize, x: f64| sections.at(&self.grid, j, x).is_some();
        let mut line: Vec<Option<f64>> = (self.cells.iter())
            .map(|cell| {
                cell.gap(|j, x| touching(j, x).then(|| self.grid.interpolate(&own[j], x) / cos_bb))
            })
            .collect();
        // Held forward past a pinion tooth's cut, backward before a gear tooth's.
        let mut last = None;
        for v in line.iter_mut() {
            match v {
                Some(x) => last = Some(*x),
                None => *v = last,
            }
        }
        let mut next = None;
        for v in line.iter_mut().rev() {
            match v {
                Some(x) => next = Some(*x),
                None => *v = next,
            }
        }
        for (r, w) in removed.iter_mut().zip(&line) {
            *r += w.unwrap_or(0.0);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::flank_shape::Side;

    #[test]
    fn a_line_s_wear_weights_only_the_slices_its_broken_tip_leaves() {
        // A line of four face slices at pinion rho1 0.2, 0.4, 0.6, 0.8 (m, a unit grid
        // [0, 1]), healthy stiffnesses k = 1, 2, 7, 4, each slice worn uniformly by
        // d = 1, 2, 9, 4 um; the tooth's tip is broken past rho1 = 0.5 over slices 1 and 2,
        // so slice 2 (0.6) is cut and slices 0, 1, 3 touch. By hand the worn line is
        // (1 x 1 + 2 x 2 + 4 x 4) / (1 + 2 + 4) = 3 um over cos(beta_b) = 0.5, 6 um (over
        // all four slices it would be 84 / 14 = 6 um / 0.5 = 12 um). A second sample whose
        // one slice is cut holds the first's value (as the errors' line holds its own).
        let grid = ProfileGrid {
            rho_pinion_m: vec![0.0, 1.0],
            rho_gear_m: vec![1.0, 0.0],
            radius_pinion_m: vec![1.0, 1.0],
            radius_gear_m: vec![1.0, 1.0],
            spacing_m: 1.0,
        };
        let k = [1.0, 2.0, 7.0, 4.0];
        let d = [1e-6, 2e-6, 9e-6, 4e-6];
        let x = [0.2, 0.4, 0.6, 0.8];
        let flank = ToothFlank {
            contact_limit_rho1_m: Some(0.5),
            ..ToothFlank::perfect(2)
        };
        let fault = SliceFault {
            cut: TipCut::of(&flank, Side::Pinion),
            flank: ToothFlank::perfect(2),
            covers: vec![false, true, true, false],
        };
        let sections = ToothSlices {
            removed_m: Vec::new(),
            faults: vec![fault],
        };
        let line = LineTeeth {
            slices: 4,
            cos_base_helix: 0.5,
            grid: grid.clone(),
            cells: vec![
                LineCell::On((0..4).map(|j| (j, x[j], k[j])).collect()),
                LineCell::On(vec![(2, 0.9, 5.0)]),
            ],
            offsets: Vec::new(),
            path: (0.0, 1.0),
            pinion: Vec::new(),
            gear: Vec::new(),
        };
        let wear: Vec<Vec<f64>> = d.iter().map(|h| vec![*h, *h]).collect();
        let mut removed = vec![0.0; 2];
        line.add_wear(&mut removed, &wear, 0, &sections);
        let by_hand = (k[0] * d[0] + k[1] * d[1] + k[3] * d[3]) / (k[0] + k[1] + k[3]) / 0.5;
        // One rounding of a few sums: 1e-15 relative.
        assert!(
            (removed[0] - by_hand).abs() < 1e-15 * by_hand,
            "{removed:?} {by_hand}"
        );
        assert_eq!(removed[1], removed[0]);
    }
}
