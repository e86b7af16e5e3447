//! The face load distribution of a case (`gearwear stiffness`, docs/MODEL.md 11.2): the
//! lead keys of `[modification]` and `operating.misalignment_um` as one gap across the
//! face (`stiffness::face_load::LeadGap`), checked against the pair, and the slice springs
//! solved under the case's static mesh force over a mesh period.
//!
//! `gearwear dynamics` on a helical pair takes the gap into its contact lines
//! (`study::helical_dynamics`); the other studies do not model a gap across the face yet:
//! `domain_problems` refuses the keys there ([`lead_refusal`]).

use super::helical::HelicalModel;
use super::model_error::ModelError;
use crate::config::case::{Case, MisalignmentPlane, ReliefShape};
use crate::dynamics::params::OperatingPoint;
use crate::geometry::GearPair;
use crate::stiffness::face_load::{FaceLoad, LeadGap};

/// Mesh positions over one mesh period at which the face load is solved.
pub const FACE_POSITIONS: usize = 72;

/// The warning for a misalignment in the normal plane (docs/MODEL.md 11.2).
pub const NORMAL_PLANE_WARNING: &str = "`operating.misalignment_plane` = \"normal\": a misalignment normal to the plane of action moves the flanks along each other, which opens no gap to first order (the flank normal at every point of contact lies in the plane of action); it is ignored (docs/MODEL.md 11.2)";

/// The lead keys and the misalignment a case gives, as `key = value` texts.
pub fn lead_keys(case: &Case) -> Vec<String> {
    let m = &case.modification;
    let o = &case.operating;
    let num = |k: &str, v: Option<f64>| v.map(|v| format!("`{k}` = {v}"));
    let mut keys: Vec<String> = [
        num("modification.crowning_um", m.crowning_um),
        num("modification.end_relief_um", m.end_relief_um),
        num("modification.end_relief_length_mm", m.end_relief_length_mm),
        num(
            "modification.helix_slope_deviation_um",
            m.helix_slope_deviation_um,
        ),
        num("operating.misalignment_um", o.misalignment_um),
    ]
    .into_iter()
    .flatten()
    .collect();
    if let Some(s) = m.end_relief_shape {
        let s = match s {
            ReliefShape::Linear => "linear",
            ReliefShape::Parabolic => "parabolic",
        };
        keys.push(format!("`modification.end_relief_shape` = \"{s}\""));
    }
    if let Some(p) = o.misalignment_plane {
        let p = match p {
            MisalignmentPlane::Action => "action",
            MisalignmentPlane::Normal => "normal",
        };
        keys.push(format!("`operating.misalignment_plane` = \"{p}\""));
    }
    keys
}

/// The refusal of the lead keys by a study that has no gap across the face, or `None`.
pub fn lead_refusal(case: &Case) -> Option<String> {
    let keys = lead_keys(case);
    (!keys.is_empty()).then(|| format!(
        "{}: taken only by `gearwear stiffness` on a single pair (the face load distribution and K_Hbeta, docs/MODEL.md 11.2) and by `gearwear dynamics`, `gearwear wear`, `gearwear run`, `gearwear sweep`, `gearwear dataset`, `gearwear calibrate` and `gearwear predict` on a helical pair (11.1-11.5, 11.9): the other studies have no gap across the face yet; remove them for this command",
        keys.join(", ")
    ))
}

/// The case's lead gap, checked against the pair (its transverse section for a helical
/// pair), and the warnings. Errors name the key, its value and the valid range: a
/// crowning and end relief together deeper than the shallower tooth's whole depth
/// r_a - r_f, an end relief without its length (or the reverse), an end relief longer
/// than half the face.
pub fn lead_gap(case: &Case, pair: &GearPair) -> Result<(LeadGap, Vec<String>), ModelError> {
    let m = &case.modification;
    let o = &case.operating;
    let mut problems = Vec::new();
    let depth_um = |g: &crate::geometry::Gear| (g.tip_radius_m - g.root_radius_m) * 1e6;
    let depth = depth_um(&pair.pinion).min(depth_um(&pair.gear));
    let (c, e) = (m.crowning_um.unwrap_or(0.0), m.end_relief_um.unwrap_or(0.0));
    if c + e > depth {
        let key = match (m.crowning_um, m.end_relief_um) {
            (Some(c), Some(e)) => {
                format!("`modification.crowning_um` = {c} with `modification.end_relief_um` = {e}")
            }
            (Some(c), None) => format!("`modification.crowning_um` = {c}"),
            _ => format!("`modification.end_relief_um` = {e}"),
        };
        problems.push(format!(
            "{key} is more than the tooth depth allows: crowning and end relief together must lie in [0, {depth:.1}] µm on this pair (the shallower tooth's whole depth r_a - r_f)"
        ));
    }
    let half_mm = pair.face_width_m * 1e3 / 2.0;
    match (m.end_relief_um, m.end_relief_length_mm) {
        (Some(_), None) | (None, Some(_)) => problems.push(
            "`modification.end_relief_um` and `modification.end_relief_length_mm` go together: give both or neither".into(),
        ),
        (_, Some(l)) if l > half_mm => problems.push(format!(
            "`modification.end_relief_length_mm` = {l} is more than half the face: it must lie in (0, {half_mm}] mm on this pair (face width {} mm)",
            2.0 * half_mm
        )),
        _ => {}
    }
    if !problems.is_empty() {
        return Err(ModelError(problems));
    }
    let mut warnings = Vec::new();
    let misalignment_um = match o.misalignment_plane.unwrap_or_default() {
        MisalignmentPlane::Action => o.misalignment_um.unwrap_or(0.0),
        MisalignmentPlane::Normal => {
            if o.misalignment_um.is_some_and(|x| x != 0.0) {
                warnings.push(NORMAL_PLANE_WARNING.to_string());
            }
            0.0
        }
    };
    let gap = LeadGap {
        crowning_m: c * 1e-6,
        end_relief_m: e * 1e-6,
        end_relief_length_m: m.end_relief_length_mm.unwrap_or(0.0) * 1e-3,
        end_relief_parabolic: m.end_relief_shape == Some(ReliefShape::Parabolic),
        slope_m: (m.helix_slope_deviation_um.unwrap_or(0.0) + misalignment_um) * 1e-6,
    };
    Ok((gap, warnings))
}

/// A case's face load distribution with its gap and warnings.
#[derive(Debug, Clone)]
pub struct CaseFaceLoad {
    /// The solved distribution over a mesh period.
    pub load: FaceLoad,
    /// The gap it was solved with.
    pub gap: LeadGap,
    /// Warnings for the user.
    pub warnings: Vec<String>,
}

/// Solve the face load of `model`'s case at its static mesh force (module docs). A gap
/// that leaves the load on a single slice at some mesh position (N >= 2) is refused: the
/// contact pattern is narrower than the model resolves.
pub fn face_load(model: &HelicalModel) -> Result<CaseFaceLoad, ModelError> {
    let case = &model.case;
    let pair = &model.pair().transverse;
    let (gap, warnings) = lead_gap(case, pair)?;
    let force = OperatingPoint::of(&case.operating, pair).static_mesh_force_n;
    let load = FaceLoad::solve(&model.slices, &gap, force, FACE_POSITIONS)?;
    let n = model.slices.slices();
    if n >= 2 && load.fewest_loaded_slices() < 2 {
        // A linear gap T across the face leaves a triangle of width c = sqrt(2 F b / (k T))
        // (k the mesh stiffness; docs/MODEL.md 11.2); c >= 2 b / N for T <= F N^2 / (2 k).
        let t_max_um = force * (n * n) as f64 / (2.0 * model.slices.mean_stiffness_n_per_m()) * 1e6;
        return Err(ModelError(vec![format!(
            "{}: the gap across the face leaves the case's load ({force:.0} N) on a single slice of the face at some mesh position: the contact pattern is narrower than the {n} slices of {:.4} mm resolve; valid: a gap across the face of at most about {t_max_um:.0} µm at this load, or more slices (`stiffness.slices`)",
            lead_keys(case).join(", "),
            pair.face_width_m * 1e3 / n as f64
        )]));
    }
    Ok(CaseFaceLoad {
        load,
        gap,
        warnings,
    })
}
