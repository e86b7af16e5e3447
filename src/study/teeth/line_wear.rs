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
//! teeth worn alike give the pair that line's gap. Where no slice of the line is on the
//! path (it is about to enter or has just left), the line takes its nearest slice's depth
//! at the path's end, as `HelicalDynamics::wear_gap` does.

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
    /// The line's gap from each slice's gap `g(j, rho1)`: the stiffness-weighted mean of
    /// the slices on the path, or the nearest slice's.
    pub(crate) fn gap(&self, g: impl Fn(usize, f64) -> f64) -> f64 {
        match self {
            LineCell::On(v) => {
                let (mut kg, mut k) = (0.0, 0.0);
                for &(j, x, ki) in v {
                    kg += ki * g(j, x);
                    k += ki;
                }
                if k > 0.0 {
                    kg / k
                } else {
                    0.0
                }
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
    /// profiles, tooth t's at t N .. (t + 1) N.
    pub(crate) fn add_wear(&self, removed: &mut [f64], wear: &[Vec<f64>], t: usize) {
        let n = self.slices;
        let Some(own) = wear.get(t * n..(t + 1) * n) else {
            return;
        };
        let cos_bb = self.cos_base_helix;
        for (r, cell) in removed.iter_mut().zip(&self.cells) {
            *r += cell.gap(|j, x| self.grid.interpolate(&own[j], x) / cos_bb);
        }
    }
}
