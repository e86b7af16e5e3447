//! The planar dynamic model of a helical pair (`gearwear dynamics` on a case with
//! `gear.helix_angle_deg` > 0; docs/MODEL.md section 11.1): the spur pair's 8-DOF model in
//! the transverse section, its time-varying mesh stiffness the slice model's
//! (`stiffness::helical`), one spring per tooth pair's contact line
//! (`SliceMeshStiffness::line_model`), the mesh force F along the transverse line of
//! action (its transverse part F_t = F; the axial part F tan(beta_b) loads the axial
//! bearings). Where the case gives axial bearings (`dynamics.bearing_axial_stiffness_*`),
//! pinion and gear carry axial degrees of freedom and the deflection takes their axial
//! motion (docs/MODEL.md 11.6, `axial_support`); otherwise the axial bearings are rigid.
//!
//! The lead keys (`[modification]`'s crowning, end relief and helix slope deviation,
//! `operating.misalignment_um`) give each line's slices their gaps across the face
//! (`stiffness::helical_lead`, `study::face_load_dynamic`).
//!
//! Per-tooth errors and faults (`[teeth]`, `[[fault]]`) make the mesh tooth-resolved: each
//! tooth's contact line on the line pair (`study::helical_teeth`, docs/MODEL.md 11.10).
//!
//! Refused (exit 2 naming the key): what needs a profile gap per slice or a second mesh (a
//! gear train, a planetary set, profile modifications, worn geometry; of the per-tooth
//! inputs what `study::helical_teeth` refuses),
//! Pedrero's load-sharing law (it is a spur pair's), and a total
//! contact ratio above `MAX_PAIRS` (the mesh follows at most that many contact lines).
//! The tip corners are not modelled: `contact.path` = "extended" (the default) runs the
//! nominal path with a warning.

use super::domain::{body_value_warnings, domain_problems};
use super::face_load::{face_load, lead_keys};
use super::helical::{
    axial_support, contact_ratio_problem, helical_contact, HelicalDynamics, HelicalModel,
    LeadDynamics,
};
use super::model::{pitch_line_velocity_warning, Model, ModelError};
use crate::config::case::{Case, ContactPathModel, LoadSharingModel, WornGeometry};
use crate::contact::friction::Friction;
use crate::contact::hertz::effective_modulus_of;
use crate::dynamics::params::DynamicParams;
use crate::dynamics::period_search::SteadyStateSettings;
use crate::geometry::ProfileGrid;
use crate::stiffness::helical_lead::LineGapTable;
use crate::stiffness::potential_energy::ElasticPair;
use crate::wear::RoughnessLaw;

pub use super::helical::EXTENDED_PATH_WARNING;

/// A key of a helical case that the planar dynamics cannot take, and why.
fn refusal(key: &str, value: &str, why: &str) -> String {
    format!("`{key}` = {value} is not available with a helical pair (`gear.helix_angle_deg` > 0) in `gearwear dynamics`, `gearwear wear`, `gearwear run`, `gearwear dataset`, `gearwear calibrate` and `gearwear predict`: {why}")
}

/// What a helical case asks that the planar model does not have (see the module docs).
fn refusals(case: &Case) -> Vec<String> {
    let mut r = Vec::new();
    let slices = "each slice would need its own gap; only new, unmodified teeth are modelled so far (docs/MODEL.md 11.1)";
    if !case.stage.is_empty() {
        r.push(refusal(
            "[[stage]]",
            "a gear train",
            "a train's helical stages are built as part of the train (`Model::dynamics_from_case`, docs/MODEL.md 4.3), not by the single pair's model",
        ));
    }
    if case.planetary.is_some() {
        r.push(refusal("[planetary]", "a planetary set", "not built"));
    }
    if case.modification.without_lead_keys() != Default::default() {
        r.push(refusal(
            "[modification]",
            "a profile modification",
            "each slice would need its own profile gap; of `[modification]` only the lead keys (crowning, end relief, helix slope deviation) are taken (docs/MODEL.md 11.1)",
        ));
    }
    r.extend(super::helical_teeth::teeth_problems(case));
    if case.wear.worn_geometry == WornGeometry::Worn {
        r.push(refusal("wear.worn_geometry", "\"worn\"", slices));
    }
    if case.contact.load_sharing == LoadSharingModel::Pedrero {
        r.push(refusal(
            "contact.load_sharing",
            "\"pedrero\"",
            "paper eq. (7) is a spur pair's law; give \"stiffness\" or \"auto\"",
        ));
    }
    r
}

/// The case without its lead keys (`study::face_load::lead_keys`): what the checks of the
/// planar model see.
pub(crate) fn without_lead_keys(case: &Case) -> Case {
    let mut c = case.clone();
    c.modification = c.modification.without_lead_keys();
    c.operating.misalignment_um = None;
    c.operating.misalignment_plane = None;
    c
}

/// The lead gaps of a helical case with at least two slices and a gap that is not zero
/// across the face (docs/MODEL.md 11.1): the static face load of `gearwear stiffness`
/// (`study::face_load::face_load`), whose checks refuse what leaves no slice, or a single
/// one, carrying load (exit 2 naming the keys); its warnings join `warnings`. None
/// without lead keys, with one slice (a single gap, shifted to 0) or a zero gap (a
/// misalignment in the normal plane): the unmodified model.
fn lead_gaps(
    hm: &HelicalModel,
    warnings: &mut Vec<String>,
) -> Result<Option<LeadDynamics>, ModelError> {
    if lead_keys(&hm.case).is_empty() {
        return Ok(None);
    }
    let static_load = face_load(hm)?;
    warnings.extend(static_load.warnings.iter().cloned());
    if hm.slices.slices() < 2 || static_load.gap.is_zero() {
        return Ok(None);
    }
    Ok(Some(LeadDynamics {
        slices: hm.slices.clone(),
        static_load: static_load.load,
        gap: static_load.gap,
    }))
}

impl Model {
    /// The model of the studies that take a helical pair through the spur pair's solver
    /// (`gearwear dynamics`, `signals`, `wear`, `sweep`): the planar model
    /// ([`Model::helical_from_case`]) where the case has a helix angle, else
    /// [`Model::from_case`] itself (so a spur case is built exactly as before); a gear
    /// train with its helical stages on their slice models (docs/MODEL.md 4.3).
    pub fn dynamics_from_case(case: &Case) -> Result<Model, ModelError> {
        if !case.stage.is_empty() {
            // A train, its helical stages on their slice models (docs/MODEL.md 4.3).
            Model::spur_or_train(case)
        } else if case.gear.helix_angle_deg == 0.0 {
            Model::from_case(case)
        } else {
            Model::helical_from_case(case)
        }
    }

    /// The model of the studies that wear a case along a whole trajectory beyond `gearwear
    /// wear` (`gearwear dataset`, `gearwear calibrate`, `gearwear predict`; `study` names
    /// the study in a refusal): a single helical pair's planar model with its wear per
    /// slice ([`Model::helical_from_case`], docs/MODEL.md 11.9), refusing what the wear
    /// studies refuse (`helical_teeth::refuse_for_wear`: the tilting keys, whose tilt the
    /// slices' wear would ignore, and per-tooth inputs, whose slices would have to wear
    /// tooth by tooth);
    /// anything else [`Model::from_case`] itself (a spur pair built exactly as before; a
    /// helical train keeps that constructor's refusal).
    pub fn wear_study_from_case(case: &Case, study: &str) -> Result<Model, ModelError> {
        if !case.stage.is_empty() || case.planetary.is_some() || case.gear.helix_angle_deg == 0.0 {
            return Model::from_case(case);
        }
        super::helical_teeth::refuse_for_wear(case, study)?;
        Model::helical_from_case(case)
    }

    /// [`Model::wear_study_from_case`] of `case` as `self` was built: the helical planar
    /// model when `self` is one (its case already holds the planar model's choices:
    /// stiffness load sharing, the nominal path), else [`Model::from_case`]. What a
    /// study's model becomes at another `wear.total_cycles` or block length.
    pub fn rebuilt_like(&self, case: &Case) -> Result<Model, ModelError> {
        match self.helical {
            Some(_) => Model::helical_from_case(case),
            None => Model::from_case(case),
        }
    }

    /// The planar model of a helical case (module docs). `contact.load_sharing` = "auto"
    /// becomes "stiffness" (the lines share the load by their compressions).
    pub fn helical_from_case(case: &Case) -> Result<Model, ModelError> {
        let problems = refusals(case);
        if !problems.is_empty() {
            return Err(ModelError(problems));
        }
        let hm = HelicalModel::from_case(case)?;
        let hp = hm.pair().clone();
        if let Some(p) = contact_ratio_problem(case, &hp) {
            return Err(ModelError(vec![p]));
        }
        let transverse = hp.transverse.clone();
        let problems = domain_problems(&without_lead_keys(case), &transverse);
        if !problems.is_empty() {
            return Err(ModelError(problems));
        }
        let (line_pair, mesh, lead) = hm.slices.line_model();
        let mut warnings = hm.warnings.clone();
        warnings.extend(super::domain::damping_alone_warnings(case));
        let gaps = lead_gaps(&hm, &mut warnings)?;
        let mut params = DynamicParams::from_case(case, &transverse);
        params.axial = axial_support(case, &hp);
        let gap_m = gaps.as_ref().map(|g| &g.static_load);
        params.tilt = super::helical_tilt::tilt_support(case, &hm.slices, &params, gap_m)?;
        warnings.extend(body_value_warnings(
            case,
            &transverse.blank_estimates(case.dynamics.blank_density_kg_per_m3),
        ));
        warnings.extend(pitch_line_velocity_warning(
            case,
            &transverse,
            &params.operating,
        ));
        let mut case = case.clone();
        case.contact.load_sharing = LoadSharingModel::Stiffness;
        if case.contact.path.is_extended() {
            warnings.push(EXTENDED_PATH_WARNING.into());
            case.contact.path = ContactPathModel::Nominal;
        }
        let grid = ProfileGrid::new(&transverse, case.wear.points_per_profile.max(2) as usize);
        let speeds = [
            params.operating.pinion_speed_rad_s,
            params.operating.gear_speed_rad_s,
        ];
        let teeth = super::helical_teeth::tooth_inputs(&case, &hm.slices, &grid, speeds)?;
        let mut contact = helical_contact(&hp, &line_pair, lead);
        if let Some(g) = &gaps {
            let table = LineGapTable::new(&hm.slices, &g.static_load.gaps_m);
            contact = contact.with_lead_gaps(table);
        }
        Ok(Model {
            contact,
            grid,
            elastic: ElasticPair::from_case(&case.materials),
            friction: Friction::from_case(&case.friction),
            roughness: RoughnessLaw::from_case(&case.surface),
            settings: SteadyStateSettings::from_case(&case.numerics),
            effective_modulus_pa: effective_modulus_of(&case.materials),
            helical: Some(HelicalDynamics {
                slices: hm.slices.slices(),
                slice_model: hm.slices.clone(),
                slice_mean_stiffness_n_per_m: hm.slices.mean_stiffness_n_per_m(),
                pair: hp,
                lead: gaps,
            }),
            pair: line_pair,
            mesh,
            params,
            teeth,
            case,
            warnings,
            train: None,
        })
    }
}

/// Relative axial shift |z_p - z_g| above which [`axial_shift_warning`] speaks, as a share
/// of the face width: the model keeps the two faces aligned (docs/MODEL.md 11.6), which a
/// shift of a few percent of b leaves nearly true.
pub const AXIAL_SHIFT_WARNING_SHARE: f64 = 0.05;

/// A warning when the response `r` of a helical pair with axial degrees of freedom moves
/// the gears axially against each other by more than [`AXIAL_SHIFT_WARNING_SHARE`] of the
/// face width at any step (the faces' overlap, which the slices assume fixed, would move
/// by as much); None otherwise, and for a model without axial coordinates.
pub fn axial_shift_warning(
    model: &Model,
    r: &crate::dynamics::response::DynamicResponse,
) -> Option<String> {
    use crate::dynamics::assembly::elements::Elements;
    use crate::dynamics::assembly::single_pair::{GEAR, PINION};
    use crate::dynamics::assembly::{Assembly, Dof};
    model.helical.as_ref()?;
    let asm = Assembly::new(Elements::single_pair(&model.params, &model.pair)).ok()?;
    let at = |body| asm.index(body, Dof::Axial);
    let d = &r.signals.displacement;
    let z = |i: Option<usize>, k: usize| i.map_or(0.0, |i| d[k][i]);
    let (p, g) = (at(PINION), at(GEAR));
    if p.is_none() && g.is_none() {
        return None;
    }
    let shift_m = (0..d.len()).fold(0.0_f64, |m, k| m.max((z(p, k) - z(g, k)).abs()));
    let b_m = model.case.gear.face_width_mm * 1e-3;
    (shift_m > AXIAL_SHIFT_WARNING_SHARE * b_m).then(|| {
        format!(
            "the gears move axially against each other by up to {:.3} mm, {:.0} % of the {} mm face width (`dynamics.bearing_axial_stiffness_*`): the model keeps the faces aligned (docs/MODEL.md 11.6), so the result is unreliable beyond a few percent; stiffen the axial bearings",
            shift_m * 1e3,
            100.0 * shift_m / b_m,
            crate::format::shown(model.case.gear.face_width_mm)
        )
    })
}

/// [`axial_shift_warning`] of the steady state of `model`'s new teeth (no external error,
/// as `gearwear dynamics` solves it), for the studies that keep no response to check
/// (`gearwear wear`, `gearwear run` under a spectrum, the wear sweeps): the shift is
/// mostly the static F_a / k_a of the load, which the wear barely changes. None without
/// axial coordinates (nothing is solved then: a spur pair, or a helical pair on rigid
/// axial bearings) or when the steady state is not found (the study itself says why).
pub fn new_teeth_axial_shift_warning(model: &Model) -> Option<String> {
    model.helical.as_ref()?;
    model.params.axial.as_ref()?;
    let none = crate::dynamics::excitation::ExternalError::none();
    let r = model
        .dynamic(&crate::wear::WearState::new(model.grid.len()), &none)
        .ok()?;
    axial_shift_warning(model, &r)
}
