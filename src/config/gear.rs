//! `[gear]`: the involute spur pair of a case (paper Table 1), and of each stage of a
//! train (`config::train`, whose keys default to these).

use super::derivable::Derivable;
use serde::{Deserialize, Serialize};

/// Involute spur pair (paper Table 1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GearSection {
    /// Module m, mm (paper Table 1: 2 mm).
    pub module_mm: f64,
    /// Pinion teeth z1 (paper: 19).
    pub teeth_pinion: i64,
    /// Gear teeth z2 (paper: 31).
    pub teeth_gear: i64,
    /// Reference pressure angle alpha, deg (paper: 20).
    pub pressure_angle_deg: f64,
    /// Addendum coefficient h_a*, in modules (paper: 1).
    pub addendum_coefficient: f64,
    /// Dedendum coefficient h_f*, in modules (paper: 1.25).
    pub dedendum_coefficient: f64,
    /// Profile shift coefficient x1 of the pinion (paper: 0).
    pub profile_shift_pinion: f64,
    /// Profile shift coefficient x2 of the gear (paper: 0).
    pub profile_shift_gear: f64,
    /// Face width b, mm (paper: 20 mm).
    pub face_width_mm: f64,
    /// Operating centre distance, mm; absent means the one the profile shifts give.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub centre_distance_mm: Option<f64>,
    /// Pinion hub bore radius r_int, mm (the fillet foundation's ring); `"derived"`: r_f / 2
    /// (h_f = 2, mid-range of Sainsot's fit).
    pub hub_bore_radius_pinion_mm: Derivable,
    /// Gear hub bore radius r_int, mm; `"derived"`: r_f / 2.
    pub hub_bore_radius_gear_mm: Derivable,
    /// Rack-cutter tip radius, in modules (ISO 53 profile A: 0.38): the root fillet, the
    /// undercut check and Sainsot's theta_f.
    pub tool_tip_radius_coefficient: f64,
    /// Helix angle beta at the reference cylinder, deg; 0 (the default) is a spur pair. A
    /// helical case reads the keys above as the normal section (docs/MODEL.md section 11).
    #[serde(skip_serializing_if = "is_spur")]
    pub helix_angle_deg: f64,
    /// Hand of the pinion's helix (the gear takes the other); ignored at 0 deg.
    #[serde(skip_serializing_if = "HelixHand::is_right")]
    pub helix_hand_pinion: HelixHand,
}

/// A helix angle of 0: left out of a case's serialisation, so spur cases write what they
/// wrote before helical pairs existed.
fn is_spur(helix_angle_deg: &f64) -> bool {
    *helix_angle_deg == 0.0
}

/// Hand of a helix (`gear.helix_hand_pinion`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum HelixHand {
    /// Left-hand helix.
    Left,
    /// Right-hand helix (a right-handed screw); the default.
    #[default]
    Right,
}

impl HelixHand {
    /// The default hand: left out of a case's serialisation.
    fn is_right(&self) -> bool {
        *self == HelixHand::Right
    }
}

impl GearSection {
    /// Whether both gears have the same tooth form as `other`'s: numbers of teeth,
    /// reference profile and profile shifts (everything a tooth's shape, and Sainsot's
    /// root angle theta_f, depends on; not the size, width, bores or centre distance).
    pub(crate) fn same_tooth_form(&self, other: &GearSection) -> bool {
        self.teeth_pinion == other.teeth_pinion
            && self.teeth_gear == other.teeth_gear
            && self.pressure_angle_deg == other.pressure_angle_deg
            && self.addendum_coefficient == other.addendum_coefficient
            && self.dedendum_coefficient == other.dedendum_coefficient
            && self.profile_shift_pinion == other.profile_shift_pinion
            && self.profile_shift_gear == other.profile_shift_gear
            && self.tool_tip_radius_coefficient == other.tool_tip_radius_coefficient
    }

    /// Whether this is the same pair as `other` in every dimension that sets the blanks'
    /// size (tooth form, module, face width, centre distance); bores excluded.
    pub(crate) fn same_pair(&self, other: &GearSection) -> bool {
        self.same_tooth_form(other)
            && self.module_mm == other.module_mm
            && self.face_width_mm == other.face_width_mm
            && self.centre_distance_mm == other.centre_distance_mm
    }
}

impl Default for GearSection {
    fn default() -> Self {
        Self {
            module_mm: 2.0,
            teeth_pinion: 19,
            teeth_gear: 31,
            pressure_angle_deg: 20.0,
            addendum_coefficient: 1.0,
            dedendum_coefficient: 1.25,
            profile_shift_pinion: 0.0,
            profile_shift_gear: 0.0,
            face_width_mm: 20.0,
            centre_distance_mm: None,
            // Not in the paper: h_f = r_f / r_int ~ 2, mid-range of Sainsot's fit.
            hub_bore_radius_pinion_mm: Derivable::Given(8.0),
            hub_bore_radius_gear_mm: Derivable::Given(14.0),
            // ISO 53 profile A rack tip radius 0.38 m.
            tool_tip_radius_coefficient: 0.38,
            helix_angle_deg: 0.0,
            helix_hand_pinion: HelixHand::Right,
        }
    }
}
