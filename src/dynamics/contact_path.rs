//! Where the teeth of a pair can touch: on the path of contact (the paper's model, its
//! involutes meeting on the line of action), or, beyond its ends, by a tip corner against
//! the mate's flank (corner contact, `geometry::corner`; docs/MODEL.md, section 4).
//!
//! A pair is followed over the reach: the path of contact, extended (`"extended"`) at
//! each end until its corner stands [`REACH_GAP_MODULES`] modules off the mate's flank. At
//! each position it is a [`PairPlace`]: on the path, both flanks are loaded at the
//! contact point rho1 and the geometric gap is zero; before the path's start the gear's
//! tip corner touches the pinion flank, past its end the pinion's tip corner the gear
//! flank, with the gap of the corner's geometry. The corner pair's spring is that of
//! its two teeth, the corner tooth loaded at its tip and the mate where the corner
//! touches it (`MeshStiffness::corner_pair_stiffness_n_per_m`), in series with the same
//! Hertz term as on the path; its force acts, like every pair's, along the line of action
//! (the tilt of the contact normal from it, which vanishes at the path's ends, is left
//! out: docs/MODEL.md). Wear gaps, reliefs, errors and faults enter where each flank is
//! loaded. At the path's ends the corner's gap is zero and its spring the pair's: the
//! load passes continuously from the corner to the path.

use super::excitation::PairGap;
use crate::config::case::ContactPathModel;
use crate::geometry::corner::{CornerGeometry, TipCorner};
use crate::geometry::pair::Reach;
use crate::geometry::GearPair;
use crate::stiffness::helical_lead::LineGapTable;
use crate::stiffness::mesh::MeshStiffness;
use std::sync::Arc;

/// Gap of a contact that cannot happen (a contact a broken tip has removed, a corner
/// that reaches no flank), m: far beyond any mesh deflection, so the pair never touches.
pub const REMOVED_GAP_M: f64 = 1e-3;

/// Gap at which a corner stops being followed beyond the path, in modules (0.1 m: 200 µm
/// on the paper's pair, 14 times its mesh deflection under the design load; a tooth bent
/// so far would have yielded). A mesh that deflects that much leaves the model.
pub const REACH_GAP_MODULES: f64 = 0.1;

/// Where and how a pair of teeth at the position rho1 of the reach touches.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairPlace {
    /// The pinion flank's load point: its radius of curvature, m.
    pub pinion_rho1_m: f64,
    /// The gear flank's load point, as the pinion rho1 of its conjugate point, m.
    pub gear_rho1_m: f64,
    /// d pinion_rho1 / d rho1 and d gear_rho1 / d rho1.
    pub pinion_rate: f64,
    /// d gear_rho1 / d rho1.
    pub gear_rate: f64,
    /// The corner's gap along the line of action (0 on the path), m, and d gap / d rho1.
    pub gap_m: f64,
    /// d gap / d rho1 (dimensionless).
    pub gap_slope: f64,
    /// A corner touches (false: the involutes on the path).
    pub corner: bool,
}

impl PairPlace {
    /// Both flanks at their common contact rho1 (on the path).
    pub fn on_path(rho1_m: f64) -> Self {
        Self {
            pinion_rho1_m: rho1_m,
            gear_rho1_m: rho1_m,
            pinion_rate: 1.0,
            gear_rate: 1.0,
            gap_m: 0.0,
            gap_slope: 0.0,
            corner: false,
        }
    }
}

/// A pair of identical teeth at one position: what the mesh force law takes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlainPair {
    /// Stiffness of the pair, N/m.
    pub stiffness_n_per_m: f64,
    /// Gap (corner geometry and wear), m, and d gap / d rho1.
    pub gap_m: f64,
    /// d gap / d rho1 (dimensionless).
    pub gap_slope: f64,
    /// Where its Hertz contact, friction and kinematics are taken: rho1 on the path, the
    /// path's end the corner continues beyond it (a sharp edge has no Hertz radius).
    pub contact_rho1_m: f64,
    /// A tip corner touches beyond the path (false: the involutes on the path).
    pub corner: bool,
    /// Share of the face width missing from the pair's contact (a helical pair's contact
    /// line partly off the path, [`ContactPath::helical_lines`]; 0 for a spur pair).
    pub width_loss: f64,
}

/// The corners of a pair's teeth and their geometry.
#[derive(Debug, Clone, PartialEq)]
struct Corners {
    geometry: CornerGeometry,
    pinion_tip: TipCorner,
    gear_tip: TipCorner,
}

/// Where the pairs of one mesh touch (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactPath {
    reach: Reach,
    /// The path of contact, rho_A and rho_E, m.
    path: (f64, f64),
    loa_m: f64,
    corners: Option<Corners>,
    /// A helical pair's contact line: its extent L = b tan(beta_b) along the path, m
    /// (0: a spur pair; [`ContactPath::helical_lines`]).
    line_m: f64,
    /// The factor from a contact's transverse radii of curvature to those of the contact
    /// line's normal section, 1 / cos(beta_b) (Meusnier's theorem; ISO/TR 15144-1:2014
    /// takes the normal section's relative radius rho_t / cos(beta_b) for a helical
    /// pair's contact): 1 for a spur pair (docs/MODEL.md 11.1).
    normal_radius_factor: f64,
    /// The helical lines' force with lead gaps across the face ([`ContactPath::with_lead_gaps`];
    /// None: no gap across the face, each line a spring K(rho) (delta - e)).
    lead: Option<Arc<LineGapTable>>,
}

impl ContactPath {
    /// The contact of `pair` under `model`; the reach holds at most `max_pairs` pairs.
    pub fn new(pair: &GearPair, model: ContactPathModel, max_pairs: usize) -> Self {
        let path = (pair.rho_start_m, pair.rho_end_m);
        let nominal = Self {
            reach: pair.nominal_reach(),
            path,
            loa_m: pair.loa_length_m,
            corners: None,
            line_m: 0.0,
            normal_radius_factor: 1.0,
            lead: None,
        };
        if !model.is_extended() {
            return nominal;
        }
        let geometry = CornerGeometry::new(pair);
        let pinion_tip = TipCorner::sharp(pair.rho_end_m);
        let gear_tip = TipCorner::sharp(pair.loa_length_m - pair.rho_start_m);
        // A reach of (max_pairs - 1) base pitches holds at most max_pairs pairs.
        let spare = (max_pairs as f64 - 1.0) * pair.base_pitch_m - pair.path_length_m();
        let limit = REACH_GAP_MODULES * pair.module_m;
        let reach = geometry.reach(gear_tip, pinion_tip, path, limit, 0.5 * spare.max(0.0));
        Self {
            reach,
            corners: Some(Corners {
                geometry,
                pinion_tip,
                gear_tip,
            }),
            ..nominal
        }
    }

    /// The contact lines of a helical pair on the nominal path (`stiffness::helical`,
    /// `SliceMeshStiffness::line_model`): `line_pair` places each tooth pair by its line's
    /// trailing end rho in [A - L, E] (its reach), `path` is the transverse path [A, E], m,
    /// `line_m` = L = b tan(beta_b) > 0. A line's Hertz contact, friction and kinematics are
    /// taken at the middle of its part on the path, over that part's share of the face
    /// (docs/MODEL.md section 11.1); [`ContactPath::in_normal_section`] gives their radii.
    pub fn helical_lines(line_pair: &GearPair, path: (f64, f64), line_m: f64) -> Self {
        Self {
            reach: line_pair.nominal_reach(),
            path,
            loa_m: line_pair.loa_length_m,
            corners: None,
            line_m,
            normal_radius_factor: 1.0,
            lead: None,
        }
    }

    /// The same contacts between helical flanks of base helix angle beta_b,
    /// `cos_base_helix` = cos(beta_b): their Hertz radii are the transverse ones over
    /// cos(beta_b), those of the contact line's normal section (docs/MODEL.md 11.1, 11.3),
    /// whether the pair is followed by its contact lines or, with one slice, as one
    /// transverse pair.
    pub fn in_normal_section(self, cos_base_helix: f64) -> Self {
        Self {
            normal_radius_factor: 1.0 / cos_base_helix,
            ..self
        }
    }

    /// The factor from a contact's transverse radii of curvature to the normal section's
    /// (1 / cos(beta_b) between helical flanks, 1 on a spur pair), dimensionless.
    #[inline]
    pub fn normal_radius_factor(&self) -> f64 {
        self.normal_radius_factor
    }

    /// The same helical lines with the lead gaps of `table` (docs/MODEL.md 11.1): each line
    /// carries the force of its slices, `LineGapTable::force`, instead of one spring.
    pub fn with_lead_gaps(self, table: LineGapTable) -> Self {
        Self {
            lead: Some(Arc::new(table)),
            ..self
        }
    }

    /// The lead gaps' line force, if the lines have gaps across the face.
    #[inline]
    pub fn lead_gaps(&self) -> Option<&LineGapTable> {
        self.lead.as_deref()
    }

    /// The part [lo, hi] of the helical line at trailing end `rho1_m` on the path, m.
    fn line_on_path(&self, rho1_m: f64) -> (f64, f64) {
        let (a, e) = self.path;
        (rho1_m.clamp(a, e), (rho1_m + self.line_m).clamp(a, e))
    }

    /// The stretch over which pairs are followed.
    pub fn reach(&self) -> Reach {
        self.reach
    }

    /// Whether corners touch beyond the path (`"extended"`).
    pub fn is_extended(&self) -> bool {
        self.corners.is_some()
    }

    /// The place of the pair at `rho1_m` whose pinion's involute ends at `pinion_tip`
    /// and gear's at `gear_tip` (each tooth's own corner: its tip, or the cut of a broken
    /// tip; None: the pair's full tip). On the nominal model every position is on the
    /// path (pairs are only followed along it). None where the teeth cannot touch: past a
    /// cut with the nominal model, or where no corner reaches the mate's flank.
    pub fn place(
        &self,
        rho1_m: f64,
        pinion_tip: Option<TipCorner>,
        gear_tip: Option<TipCorner>,
    ) -> Option<PairPlace> {
        let Some(c) = &self.corners else {
            let cut = pinion_tip.is_some_and(|t| rho1_m > t.involute_end_rho_m)
                || gear_tip.is_some_and(|t| rho1_m < self.loa_m - t.involute_end_rho_m);
            return (!cut).then(|| PairPlace::on_path(rho1_m));
        };
        let pt = pinion_tip.unwrap_or(c.pinion_tip);
        let gt = gear_tip.unwrap_or(c.gear_tip);
        let (start, end) = (self.loa_m - gt.involute_end_rho_m, pt.involute_end_rho_m);
        if rho1_m < start {
            let k = c.geometry.approach(gt, rho1_m)?;
            // The touched point must lie on the pinion's involute as it ends.
            (k.mate_rho_m <= end).then_some(PairPlace {
                pinion_rho1_m: k.mate_rho_m,
                gear_rho1_m: start,
                pinion_rate: k.mate_rho_slope,
                gear_rate: 0.0,
                gap_m: k.gap_m,
                gap_slope: k.gap_slope,
                corner: true,
            })
        } else if rho1_m > end {
            let k = c.geometry.recess(pt, rho1_m)?;
            let gear_rho1 = self.loa_m - k.mate_rho_m;
            (gear_rho1 >= start).then_some(PairPlace {
                pinion_rho1_m: end,
                gear_rho1_m: gear_rho1,
                pinion_rate: 0.0,
                gear_rate: -k.mate_rho_slope,
                gap_m: k.gap_m,
                gap_slope: k.gap_slope,
                corner: true,
            })
        } else {
            Some(PairPlace::on_path(rho1_m))
        }
    }

    /// Where a pair at `rho1_m` takes its Hertz contact, friction and kinematics: rho1
    /// itself on the nominal model and on the path, else the end of the path its corner
    /// continues.
    pub fn contact_rho1_m(&self, rho1_m: f64) -> f64 {
        match self.corners {
            None if self.line_m > 0.0 => {
                let (lo, hi) = self.line_on_path(rho1_m);
                0.5 * (lo + hi)
            }
            None => rho1_m,
            Some(_) => rho1_m.clamp(self.path.0, self.path.1),
        }
    }

    /// A pair of identical teeth at `rho1_m` with the wear `gap`: its stiffness (the
    /// path's table on the path, the corner's spring beyond it) and gap.
    pub fn plain_pair(&self, mesh: &MeshStiffness, gap: &PairGap, rho1_m: f64) -> PlainPair {
        match self.place(rho1_m, None, None) {
            Some(p) if !p.corner => {
                let (g, dg) = gap.at(rho1_m);
                if self.line_m > 0.0 {
                    return self.line_pair(mesh, gap, rho1_m);
                }
                PlainPair {
                    stiffness_n_per_m: mesh.pair_stiffness_n_per_m(rho1_m),
                    gap_m: g,
                    gap_slope: dg,
                    contact_rho1_m: rho1_m,
                    corner: false,
                    width_loss: 0.0,
                }
            }
            Some(p) => {
                let (g, dp, dg) = gap.at_flanks(p.pinion_rho1_m, p.gear_rho1_m);
                PlainPair {
                    stiffness_n_per_m: mesh
                        .corner_pair_stiffness_n_per_m(p.pinion_rho1_m, p.gear_rho1_m),
                    gap_m: p.gap_m + g,
                    gap_slope: p.gap_slope + dp * p.pinion_rate + dg * p.gear_rate,
                    contact_rho1_m: self.contact_rho1_m(rho1_m),
                    corner: true,
                    width_loss: 0.0,
                }
            }
            None => PlainPair {
                stiffness_n_per_m: 0.0,
                gap_m: REMOVED_GAP_M,
                gap_slope: 0.0,
                contact_rho1_m: self.contact_rho1_m(rho1_m),
                corner: true,
                width_loss: 0.0,
            },
        }
    }
}

impl ContactPath {
    /// [`ContactPath::plain_pair`] of a helical contact line at trailing end `rho1_m`: the
    /// line's stiffness K(rho) from `mesh` (the line pair's table), the line's gap from
    /// `gap`, a table over the trailing end's positions as K is (new teeth: 0; worn
    /// slices: `HelicalDynamics::wear_gap`, each slice at its own offset from the trailing
    /// end), and the share of the face its part off the path leaves out (kept below
    /// 1 - 1e-9 so a line just entering has a finite Hertz width).
    fn line_pair(&self, mesh: &MeshStiffness, gap: &PairGap, rho1_m: f64) -> PlainPair {
        let (lo, hi) = self.line_on_path(rho1_m);
        let mid = 0.5 * (lo + hi);
        let (g, dg) = gap.at(rho1_m);
        PlainPair {
            stiffness_n_per_m: mesh.pair_stiffness_n_per_m(rho1_m),
            gap_m: g,
            gap_slope: dg,
            contact_rho1_m: mid,
            corner: false,
            width_loss: self.line_width_loss(lo, hi),
        }
    }

    /// The share of the face a helical contact line at trailing end `rho1_m` leaves out of
    /// its Hertz contact, its part off the path ([`ContactPath::plain_pair`]); 0 for a spur
    /// pair's (or a one-slice) line. The tooth-resolved mesh of a helical pair
    /// (docs/MODEL.md 11.10) combines it with a tooth's own.
    #[inline]
    pub fn line_width_loss_at(&self, rho1_m: f64) -> f64 {
        if self.line_m > 0.0 && self.corners.is_none() {
            let (lo, hi) = self.line_on_path(rho1_m);
            self.line_width_loss(lo, hi)
        } else {
            0.0
        }
    }

    /// The share of the line off the path, its part on the path being [lo, hi] (kept below
    /// 1 - 1e-9 so a line just entering has a finite Hertz width).
    fn line_width_loss(&self, lo: f64, hi: f64) -> f64 {
        (1.0 - (hi - lo) / self.line_m).min(1.0 - 1e-9)
    }
}

#[cfg(test)]
#[path = "tests_contact_path.rs"]
mod tests;
