//! Per-tooth errors and faults on a helical pair (docs/MODEL.md 11.10): what the planar
//! model (`study::helical_dynamics`) takes of `[teeth]` and `[[fault]]`, what it refuses,
//! and the refusal of the wear studies that do not wear such teeth tooth by tooth yet
//! (`gearwear wear` and `gearwear run` do, docs/MODEL.md 11.13).
//!
//! Taken by `gearwear dynamics` and `gearwear signals` (and the dynamics sweeps): pitch and
//! profile errors, run-out, cracks, spalls and broken tips across a span of the face
//! (`study::teeth::ToothInputs::helical`, docs/MODEL.md 11.12 for the tip). Refused, naming
//! the keys: the spur pair's `fault.*_width_fraction` (a helical fault's share of the face
//! is its span), and per-tooth inputs together with the lead keys or the tilting degrees of
//! freedom (their face loads assume every tooth alike).

use super::face_load::lead_keys;
use super::model_error::ModelError;
use super::teeth::ToothInputs;
use crate::config::case::Case;
use crate::geometry::ProfileGrid;
use crate::stiffness::helical::SliceMeshStiffness;

/// Whether a case gives its teeth per-tooth inputs (`[teeth]` or `[[fault]]`).
pub fn has_tooth_inputs(case: &Case) -> bool {
    case.teeth != Default::default() || !case.fault.is_empty()
}

/// What a helical case's per-tooth inputs ask that the planar model does not have (module
/// docs), each naming the key and what to give instead.
pub(crate) fn teeth_problems(case: &Case) -> Vec<String> {
    let mut p = Vec::new();
    for (i, f) in case.fault.iter().enumerate() {
        let which = format!("fault {i}, {} tooth {}", f.gear.name(), f.tooth);
        let t = f.table();
        for (key, v) in [
            ("crack_width_fraction", t.crack_width_fraction),
            ("spall_width_fraction", t.spall_width_fraction),
        ] {
            if let Some(v) = v {
                p.push(format!(
                    "`fault.{key}` = {v} ({which}) is a spur pair's share of the face; on a helical pair (`gear.helix_angle_deg` > 0) a fault covers the span [`fault.face_start_mm`, `fault.face_end_mm`] of the face (docs/MODEL.md 11.10): remove `fault.{key}` and give the span"
                ));
            }
        }
    }
    if !has_tooth_inputs(case) {
        return p;
    }
    let lead = lead_keys(case);
    if !lead.is_empty() {
        p.push(format!(
            "{} with per-tooth inputs (`[teeth]` or `[[fault]]`) on a helical pair: the lead gaps' face load assumes every tooth alike, so the two are not built together yet (docs/MODEL.md 11.10); remove one of them",
            lead.join(", ")
        ));
    }
    let tilt = case.dynamics.tilt_keys();
    if !tilt.is_empty() {
        let named: Vec<String> = tilt.iter().map(|(k, v)| format!("`{k}` = {v}")).collect();
        p.push(format!(
            "{} with per-tooth inputs (`[teeth]` or `[[fault]]`) on a helical pair: the tilting degrees of freedom take every tooth alike, so the two are not built together yet (docs/MODEL.md 11.10); remove one of them",
            named.join(", ")
        ));
    }
    p
}

/// The teeth of a helical case as contact lines (`ToothInputs::helical`), None without
/// per-tooth inputs or where none changes a tooth.
pub(crate) fn tooth_inputs(
    case: &Case,
    slices: &SliceMeshStiffness,
    grid: &ProfileGrid,
    shaft_speeds_rad_s: [f64; 2],
) -> Result<Option<ToothInputs>, ModelError> {
    if !has_tooth_inputs(case) {
        return Ok(None);
    }
    ToothInputs::helical(case, slices, grid, shaft_speeds_rad_s).map_err(ModelError)
}

/// `gearwear wear` in a refusal, and the study that wears a helical pair's teeth tooth by
/// tooth and slice by slice at one operating point (docs/MODEL.md 11.13).
pub const WEAR_STUDY: &str = "`gearwear wear`";

/// `gearwear run` in a refusal; it wears a helical pair's teeth as [`WEAR_STUDY`] does.
pub const RUN_STUDY: &str = "`gearwear run`";

/// The refusal of a helical case with per-tooth inputs by a wear study `study` that does
/// not wear its teeth tooth by tooth (a `[load_spectrum]`, a wear sweep, `gearwear
/// dataset`, `gearwear calibrate`, `gearwear predict`); None for a spur case, new identical
/// helical teeth, or [`WEAR_STUDY`] and [`RUN_STUDY`], which wear every tooth's face slices
/// from its own contact history (docs/MODEL.md 11.13).
pub fn wear_refusal(case: &Case, study: &str) -> Option<String> {
    let built = study == WEAR_STUDY || study == RUN_STUDY;
    (case.gear.helix_angle_deg != 0.0 && case.stage.is_empty() && has_tooth_inputs(case) && !built).then(|| {
        format!("`[teeth]` / `[[fault]]` on a helical pair (`gear.helix_angle_deg` > 0): {study} does not take per-tooth inputs on a helical pair yet (its teeth would wear slice by slice under each of its operating points or cases); `gearwear wear` and `gearwear run` at one operating point wear every tooth slice by slice (docs/MODEL.md 11.13), and `gearwear dynamics` and `gearwear signals` take them (docs/MODEL.md 11.10)")
    })
}

/// The refusals of a helical case by a wear study `study` (`wear`, `run`, a load
/// spectrum, a wear sweep): the tilting keys (`helical_tilt::tilt_refusal`), then the
/// per-tooth inputs ([`wear_refusal`]); None when it takes the case.
pub fn wear_refusals(case: &Case, study: &str) -> Option<String> {
    super::helical_tilt::tilt_refusal(case, study).or_else(|| wear_refusal(case, study))
}

/// [`wear_refusals`] as an error of the model.
pub(crate) fn refuse_for_wear(case: &Case, study: &str) -> Result<(), super::ModelError> {
    wear_refusals(case, study).map_or(Ok(()), |r| Err(super::ModelError(vec![r])))
}

/// As [`refuse_for_wear`] on a helical pair; a spur pair's tilting keys are ignored with
/// a warning (`helical_tilt::tilt_key_warnings`) and its teeth are its own model's.
pub(crate) fn refuse_for_wear_if_helical(
    case: &Case,
    study: &str,
) -> Result<(), super::ModelError> {
    if case.gear.helix_angle_deg == 0.0 {
        return Ok(());
    }
    refuse_for_wear(case, study)
}
