//! A helical stage of a gear train (docs/MODEL.md 4.3): the helical pair's own slice-method
//! mesh (`study::helical::HelicalModel`, `SliceMeshStiffness::line_model`, its contact
//! lines `study::helical::helical_contact`), the stage's axial bearings and the mesh's axial
//! gradient (`study::helical::axial_support`, docs/MODEL.md 11.6), built as the single
//! helical pair builds them (`Model::helical_from_case`), so that a one-stage helical train
//! is that pair.

use super::helical::{
    axial_support, contact_ratio_problem, helical_contact, HelicalDynamics, HelicalModel,
    EXTENDED_PATH_WARNING,
};
use crate::config::case::{Case, ContactPathModel, LoadSharingModel};
use crate::dynamics::contact_path::ContactPath;
use crate::dynamics::params::AxialSupport;
use crate::geometry::GearPair;
use crate::stiffness::mesh::MeshStiffness;

/// What a helical stage adds to a train's stage.
pub(crate) struct HelicalStageParts {
    /// The line pair (the transverse pair with its path start moved back by the stagger
    /// of a whole contact line: the pair the solver's mesh follows).
    pub line_pair: GearPair,
    /// The contact lines' stiffness table (the slice model's).
    pub mesh: MeshStiffness,
    /// Where the lines touch.
    pub contact: ContactPath,
    /// The helical pair and its slice model, for the outputs.
    pub helical: HelicalDynamics,
    /// The stage's axial bearings and the mesh's d delta / d z_p (None: rigid axial
    /// bearings, the planar model).
    pub axial: Option<AxialSupport>,
    /// Warnings of the slice model and the keys.
    pub warnings: Vec<String>,
}

/// The helical stage of the stage's single-pair case `sc` (`study::train::stage_case`:
/// its `[gear]`, `[dynamics]` and `stiffness.slices` the stage's). As the single helical
/// pair (the lead keys are refused before, by the stage's domain checks):
/// `sc`'s `contact.load_sharing` becomes "stiffness" (the lines share the load by
/// their compressions) and `contact.path` = "extended" the nominal path, with a warning.
pub(crate) fn helical_stage(sc: &mut Case) -> Result<HelicalStageParts, Vec<String>> {
    let hm = HelicalModel::from_case(sc).map_err(|e| e.0)?;
    let hp = hm.pair().clone();
    if let Some(p) = contact_ratio_problem(sc, &hp) {
        return Err(vec![p]);
    }
    let (line_pair, mesh, lead) = hm.slices.line_model();
    if sc.contact.load_sharing == LoadSharingModel::Pedrero {
        return Err(vec![
            "`contact.load_sharing` = \"pedrero\" on a helical stage: paper eq. (7) is a spur pair's law; give \"stiffness\" or \"auto\" (a helical stage's contact lines share the load by their compressions)".into(),
        ]);
    }
    let mut warnings = hm.warnings.clone();
    warnings.extend(super::domain::damping_alone_warnings(sc));
    sc.contact.load_sharing = LoadSharingModel::Stiffness;
    if sc.contact.path.is_extended() {
        warnings.push(EXTENDED_PATH_WARNING.into());
        sc.contact.path = ContactPathModel::Nominal;
    }
    let contact = helical_contact(&hp, &line_pair, lead);
    Ok(HelicalStageParts {
        axial: axial_support(sc, &hp),
        helical: HelicalDynamics {
            slices: hm.slices.slices(),
            slice_model: hm.slices.clone(),
            slice_mean_stiffness_n_per_m: hm.slices.mean_stiffness_n_per_m(),
            pair: hp,
            lead: None,
        },
        line_pair,
        mesh,
        contact,
        warnings,
    })
}
