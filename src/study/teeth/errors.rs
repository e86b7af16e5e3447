//! The errors each tooth of both gears is given: from the case, or drawn for the case's
//! ISO 1328-1 accuracy grade, else zero; and the tolerances of the class, for reports.

use super::sides::member_gear;
use crate::config::case::{Case, Member};
use crate::geometry::iso1328::{
    draw_gear, flank_tolerances, round_iso, FlankTolerances, MAX_DRAWS,
};
use crate::geometry::GearPair;
use serde::Serialize;

/// The errors each tooth of one gear was given (um; drawn or from the case).
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct GearErrors {
    /// Position (pitch) error of each tooth on the reference circle, um.
    pub position_um: Vec<f64>,
    /// Profile slope error f_Halpha of each tooth, µm.
    pub profile_slope_um: Vec<f64>,
    /// Profile form error f_falpha of each tooth, µm.
    pub profile_form_um: Vec<f64>,
    /// Radial run-out, um.
    pub runout_um: f64,
    /// ISO 1328-1 tolerances of the class drawn for, if any.
    pub tolerances: Option<FlankTolerancesReport>,
}

/// ISO 1328-1 tolerances of one gear, for reports (um, rounded as the standard publishes
/// them, 5.2.3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlankTolerancesReport {
    /// Flank tolerance class (ISO 1328-1:2013 classes 1 to 11).
    pub class: i64,
    /// Single pitch tolerance f_pT, µm.
    pub single_pitch_um: f64,
    /// Total cumulative pitch tolerance F_pT, µm.
    pub cumulative_pitch_um: f64,
    /// Profile slope tolerance f_HalphaT, µm.
    pub profile_slope_um: f64,
    /// Profile form tolerance f_falphaT, µm.
    pub profile_form_um: f64,
    /// Run-out tolerance F_rT, µm.
    pub runout_um: f64,
}

impl From<FlankTolerances> for FlankTolerancesReport {
    fn from(t: FlankTolerances) -> Self {
        Self {
            class: t.class,
            single_pitch_um: round_iso(t.single_pitch_um),
            cumulative_pitch_um: round_iso(t.cumulative_pitch_um),
            profile_slope_um: round_iso(t.profile_slope_um),
            profile_form_um: round_iso(t.profile_form_um),
            runout_um: round_iso(t.runout_um),
        }
    }
}

/// One value per tooth from an array of 1 or z values (absent: zeros).
fn per_tooth(v: &Option<Vec<f64>>, z: usize) -> Option<Vec<f64>> {
    v.as_ref().map(|v| {
        if v.len() == 1 {
            vec![v[0]; z]
        } else {
            v.clone()
        }
    })
}

/// No set of a gear's errors drawn for its accuracy grade (ISO 1328-1 class `class`)
/// from `teeth.error_seed` passed the class's inspection in [`MAX_DRAWS`] draws.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("`teeth.accuracy_grade` = {class}: no {member} of {teeth} teeth drawn from `teeth.error_seed` = {seed} passed the class's inspection in {MAX_DRAWS} draws; give its errors explicitly (`teeth.pitch_error_*_um`, `teeth.profile_*_um`)")]
pub(crate) struct ErrorsNotDrawn {
    /// The accuracy grade.
    pub class: i64,
    /// "pinion" or "gear".
    pub member: &'static str,
    /// Its number of teeth.
    pub teeth: usize,
    /// The seed the draws came from.
    pub seed: i64,
}

/// The errors of both gears: given, or drawn for the accuracy grade, else zero.
pub(crate) fn gear_errors(case: &Case, pair: &GearPair) -> Result<[GearErrors; 2], ErrorsNotDrawn> {
    let t = &case.teeth;
    let module_mm = pair.module_m * 1e3;
    let one = |member: Member| -> Result<GearErrors, ErrorsNotDrawn> {
        let g = member_gear(pair, member);
        let z = g.teeth;
        let (pitch, slope, form, runout) = match member {
            Member::Pinion => (
                &t.pitch_error_pinion_um,
                &t.profile_slope_pinion_um,
                &t.profile_form_pinion_um,
                t.runout_pinion_um,
            ),
            Member::Gear => (
                &t.pitch_error_gear_um,
                &t.profile_slope_gear_um,
                &t.profile_form_gear_um,
                t.runout_gear_um,
            ),
        };
        let tol = t
            .accuracy_grade
            .map(|a| flank_tolerances(a, module_mm * z as f64, module_mm));
        let drawn = match tol {
            Some(tol) => {
                let stream = match member {
                    Member::Pinion => 0,
                    Member::Gear => 1,
                };
                let seed = t.error_seed.unwrap_or(0);
                Some(
                    draw_gear(z, &tol, seed as u64, stream).map_err(|u| ErrorsNotDrawn {
                        class: u.class,
                        member: member.name(),
                        teeth: u.teeth,
                        seed,
                    })?,
                )
            }
            None => None,
        };
        let pick = |given: Option<Vec<f64>>, drawn: Option<Vec<f64>>| {
            given.or(drawn).unwrap_or_else(|| vec![0.0; z])
        };
        Ok(GearErrors {
            position_um: pick(pitch.clone(), drawn.as_ref().map(|d| d.position_um.clone())),
            profile_slope_um: pick(
                per_tooth(slope, z),
                drawn.as_ref().map(|d| d.slope_um.clone()),
            ),
            profile_form_um: pick(
                per_tooth(form, z),
                drawn.as_ref().map(|d| d.form_um.clone()),
            ),
            runout_um: runout.unwrap_or(0.0),
            tolerances: tol.map(Into::into),
        })
    };
    Ok([one(Member::Pinion)?, one(Member::Gear)?])
}
