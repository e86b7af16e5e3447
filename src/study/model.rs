//! The immutable model objects of one case, built once from a validated `Case`.

use super::domain::{
    axial_key_warnings, body_value_warnings, domain_problems, Resolved, ResolvedParameters,
};
pub use super::model_error::ModelError;
use super::teeth::ToothInputs;
use crate::config::case::{Case, LoadSharingModel};
use crate::contact::friction::Friction;
use crate::contact::hertz::effective_modulus_of;
use crate::dynamics::contact_path::ContactPath;
use crate::dynamics::excitation::{ExternalError, PairGap};
use crate::dynamics::model::{GearSystem, GearSystemParts, MAX_PAIRS};
use crate::dynamics::params::{DynamicParams, OperatingPoint};
use crate::dynamics::period_search::{DynamicsError, SteadyStateSettings};
use crate::dynamics::quasi_static::solve_quasi_static;
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::steady::solve_steady_state_from;
use crate::dynamics::tooth_mesh::ToothMesh;
use crate::geometry::{GearPair, ProfileGrid};
use crate::stiffness::mesh::{FilletSettings, MeshStiffness};
use crate::stiffness::potential_energy::ElasticPair;
use crate::wear::{RoughnessLaw, WearState};

/// New teeth and no external error, for the meshes of a train that a study leaves
/// unworn.
static NO_GAP: PairGap = PairGap::NONE;
static NO_ERROR: ExternalError = ExternalError::NONE;

/// Everything a solver needs, built once per case.
pub struct Model {
    /// The case as loaded.
    pub case: Case,
    /// The pair's geometry.
    pub pair: GearPair,
    /// Young's moduli and Poisson's ratios of the two gears.
    pub elastic: ElasticPair,
    /// The mesh stiffness, built once.
    pub mesh: MeshStiffness,
    /// Masses, inertias, stiffness, damping and operating point of the dynamic model.
    pub params: DynamicParams,
    /// The case's friction model.
    pub friction: Friction,
    /// Composite RMS roughness against the deepest pinion wear (paper section 4.1).
    pub roughness: RoughnessLaw,
    /// Points along the path of contact where wear is computed.
    pub grid: ProfileGrid,
    /// Numerical settings of a steady-state evaluation.
    pub settings: SteadyStateSettings,
    /// Effective (Hertz) modulus E* of the pair, Pa.
    pub effective_modulus_pa: f64,
    /// Where the pairs touch (`contact.path`; a train: its first stage's).
    pub contact: ContactPath,
    /// The teeth of a case with per-tooth inputs (errors, modifications, faults); None:
    /// every tooth the paper's.
    pub teeth: Option<ToothInputs>,
    /// Non-fatal findings (undercut, formulas outside their fitted range).
    pub warnings: Vec<String>,
    /// A gear train's stages and assembly (`[[stage]]`); None: the single pair. The
    /// fields above are then the first stage's (its pair, stiffness, grid, lumped
    /// parameters and operating point).
    pub train: Option<super::train::TrainModel>,
    /// A helical pair's planar model (`study::helical_dynamics`): `pair` and `mesh` are
    /// then its contact lines'; None for a spur pair.
    pub helical: Option<super::helical::HelicalDynamics>,
}

/// Pitch-line velocity above which a spur pair is implausible, m/s: ground, precision
/// spur gears run to about 40 m/s (ISO 6336's and AGMA's accuracy grades for high speed;
/// beyond it helical gears are used). A speed given in Hz where rpm was meant (900 Hz for
/// 900 rpm: 54 000 rpm) lands far above it.
pub const MAX_PITCH_LINE_VELOCITY_M_PER_S: f64 = 40.0;

/// A warning when the pinion's pitch-line velocity, v = Omega_p r_p (`op`: the case's
/// operating point on `pair`), is above [`MAX_PITCH_LINE_VELOCITY_M_PER_S`] (the case runs;
/// the speed may be meant).
pub fn pitch_line_velocity_warning(
    case: &Case,
    pair: &GearPair,
    op: &OperatingPoint,
) -> Option<String> {
    let f = case.operating.input_speed_hz;
    let v = op.pinion_speed_rad_s * pair.pinion.pitch_radius_m;
    (v > MAX_PITCH_LINE_VELOCITY_M_PER_S).then(|| {
        format!(
            "`operating.input_speed_hz` = {f} Hz ({:.0} rpm) gives a pitch-line velocity of {v:.1} m/s on this pair, above the {MAX_PITCH_LINE_VELOCITY_M_PER_S} m/s of any spur gear; if the speed was meant in rpm, give it as `operating.input_speed_rpm`",
            f * 60.0
        )
    })
}

/// The refusal of Pedrero's law with corner contact: eq. (7) shares the load between
/// pairs on the nominal path only.
pub const PEDRERO_WITH_CORNERS: &str = "`contact.load_sharing` = \"pedrero\" (paper eq. 7) shares the load between pairs on the nominal path of contact only, but `contact.path` = \"extended\" lets the tip corners touch beyond it: give `contact.path` = \"nominal\" for the paper's model, or `contact.load_sharing` = \"stiffness\" or \"auto\", which share the load by each pair's compression";

/// The warning of a case whose teeth differ under `contact.load_sharing` = "auto": its
/// pairs share the load by their compressions, identical teeth by Pedrero's law, so a
/// comparison of the two (a sweep across zero error, a baseline) mixes two laws; on the
/// paper's case the law alone moves the initial wear rate by about a fifth
/// (docs/MODEL.md, section 9). Given on the nominal path only: with corner contact
/// (`contact.path` = "extended") identical teeth share by compression too.
pub const AUTO_SHARING_WITH_RESOLVED_TEETH: &str = "the teeth differ or are modified, so the pairs share the load by their own compressions (`contact.load_sharing` = \"auto\"), while identical teeth use Pedrero's law (paper eq. 7); to compare such cases with identical teeth under one law, give `contact.load_sharing` = \"stiffness\"";

/// Warnings for the gears whose ISO 1328-1 tolerances (`teeth.accuracy_grade`) extrapolate
/// the 2013 formulas beyond the standard's scope (`geometry::iso1328::outside_scope`).
fn tolerance_extrapolation_warnings(case: &Case, pair: &GearPair) -> Vec<String> {
    let Some(class) = case.teeth.accuracy_grade else {
        return Vec::new();
    };
    let m_mm = pair.module_m * 1e3;
    [("pinion", &pair.pinion), ("gear", &pair.gear)]
        .into_iter()
        .filter_map(|(name, g)| {
            crate::geometry::iso1328::outside_scope(class, g.teeth, m_mm * g.teeth as f64, m_mm).map(|why| {
                format!(
                    "`teeth.accuracy_grade` = {class}: the {name}'s tolerances extrapolate the formulas of ISO 1328-1:2013 beyond its scope ({why})"
                )
            })
        })
        .collect()
}

/// The error of Pedrero's law asked for explicitly on teeth that differ: the law has no
/// place for one pair's gap or softer tooth. Names what makes the teeth differ.
fn pedrero_with_resolved_teeth(case: &Case) -> String {
    let mut why = Vec::new();
    if case.teeth != Default::default() {
        why.push("`[teeth]`");
    }
    if case.modification != Default::default() {
        why.push("`[modification]`");
    }
    if !case.fault.is_empty() {
        why.push("`[[fault]]`");
    }
    if case.wear.worn_geometry == crate::config::case::WornGeometry::Worn {
        why.push("`wear.worn_geometry` = \"worn\"");
    }
    format!(
        "`contact.load_sharing` = \"pedrero\" (paper eq. 7) is defined for identical, perfect teeth, but this case makes them differ ({}): give \"stiffness\" or \"auto\", which share the load by each pair's compression",
        why.join(", ")
    )
}

/// Why a helical case cannot be modelled here: the model is planar (rotation and lateral
/// motion of spur pairs); a helical pair's axial force and tilting moments have no degrees
/// of freedom yet. Every study built on this constructor refuses it rather than give a
/// spur result; `dynamics`, `signals`, `wear`, `run` and `sweep` build the planar model
/// (`Model::dynamics_from_case`), datasets and prognostics the same with its wear per
/// slice (`Model::wear_study_from_case`).
fn helical_refusal(helix_angle_deg: f64) -> String {
    format!(
        "`gear.helix_angle_deg` = {helix_angle_deg} is a helical pair: this study is not yet built for it (helical dynamics has only its planar model, in `gearwear dynamics`, the steady record of `gearwear signals`, the wear per slice of `gearwear wear`, the whole study of `gearwear run`, the sweeps of dynamics and wear, the run-to-failure records of `gearwear dataset` and the forward runs of `gearwear calibrate` and `gearwear predict`, at one operating point or under a `[load_spectrum]` (`gearwear wear`, `gearwear run`, wear sweeps and prognostics), with axial motion where the axial bearing keys are given; tilting motion in the wear studies is not built), so it would give a spur result; `gearwear stiffness`, `gearwear dynamics`, `gearwear signals`, `gearwear wear`, `gearwear run`, `gearwear sweep`, `gearwear dataset`, `gearwear calibrate` and `gearwear predict` take helical pairs (set the angle to 0 for a spur pair)"
    )
}

/// The studies that take a train with helical stages (docs/MODEL.md 4.3).
pub const HELICAL_TRAIN_STUDIES: &str = "`gearwear stiffness`, `gearwear dynamics`, `gearwear signals` (its steady record) and `gearwear sweep` of dynamics";

/// The refusal of severe-wear geometry (`wear.worn_geometry` = "worn", docs/MODEL.md 9.7)
/// on a gear train's wear: every stage's mesh takes the involute geometry, the wear
/// opening gaps between the flanks (5.1), so the key would be ignored. None on a single
/// pair or with the involute geometry.
fn worn_train_refusal(case: &Case) -> Option<String> {
    (!case.stage.is_empty() && case.wear.worn_geometry == crate::config::case::WornGeometry::Worn)
        .then(|| {
            "`wear.worn_geometry` = \"worn\" on a gear train ([[stage]] tables): the studies of a train's wear (`gearwear wear`, `gearwear run`, `gearwear dataset`, `gearwear calibrate`, `gearwear predict`, a wear sweep, a load spectrum) take the involute geometry of every stage (wear opens gaps between the flanks, docs/MODEL.md 5.1), not the worn tooth's beams and base radii of a single pair; remove the key or give \"involute\"".to_string()
        })
}

/// Why a study on [`Model::from_case`] refuses a gear train with a helical stage: `wear`,
/// `run`, `dataset`, `calibrate`, `predict`, the wear sweeps and the load spectra of a
/// train have no wear per face slice (docs/MODEL.md 4.3), so they would give a spur
/// result. Names the first helical stage's key (`stage.helix_angle_deg`, or
/// `gear.helix_angle_deg` where the stage takes the case's) and its value; None for a
/// single pair or an all-spur train.
pub fn helical_train_refusal(case: &Case) -> Option<String> {
    let (k, spec) = case
        .stage
        .iter()
        .enumerate()
        .find(|(_, s)| s.helix_angle_deg.unwrap_or(case.gear.helix_angle_deg) != 0.0)?;
    let key = match spec.helix_angle_deg {
        Some(v) => format!("`stage.helix_angle_deg` = {v} (stage {})", k + 1),
        None => format!(
            "`gear.helix_angle_deg` = {} (stage {}'s, from `[gear]`)",
            case.gear.helix_angle_deg,
            k + 1
        ),
    };
    Some(format!(
        "{key} is a helical stage of a gear train ([[stage]] tables): `gearwear wear`, `gearwear run`, `gearwear dataset`, `gearwear calibrate`, `gearwear predict`, the wear sweeps and a `[load_spectrum]` take spur stages only so far (a train has no wear per face slice, docs/MODEL.md 4.3), so they would give a spur result; a train with helical stages runs in {HELICAL_TRAIN_STUDIES} (set the stage's helix angle to 0 for a spur stage)"
    ))
}

/// Why a planetary case cannot be modelled here: the pair and train model is not the
/// set (`gearwear dynamics`, `signals`, `wear` and `run` take it by the planetary
/// studies before reaching here). Every study on this model refuses it.
fn planetary_refusal() -> String {
    "`[planetary]` is a planetary set: this study is not yet built for it, so it would give the result of the `[gear]` pair instead; only `gearwear stiffness` (its meshes' stiffness, phases, frequencies and the lumped model's natural frequencies), `gearwear dynamics`, `gearwear signals` (a sensor on the fixed ring), `gearwear wear` (every member's wear), `gearwear dataset` (run-to-failure records of the ring sensor), `gearwear run` (those studies with a report) and `gearwear sweep` of dynamics (each mesh's force and each planet's load sharing per case) and of wear (every member flank's wear per case, at one operating point or under a `[load_spectrum]`) take a planetary set so far".to_string()
}

/// The studies built on [`Model::from_case`] that wear a gear train beyond one operating
/// point, as a refusal names them.
const TRAIN_WEAR_STUDIES: &str = "this study of the train's wear (a dataset, a calibration, a prediction, a load spectrum or a wear sweep)";

impl Model {
    /// Build the model of a validated case: the geometry (with `"derived"` bores), the
    /// checks that need it (`study::domain`), the mesh stiffness and the lumped parameters
    /// (with `"derived"` masses and inertias, resolved here once).
    pub fn from_case(case: &Case) -> Result<Self, ModelError> {
        if let Some(p) = helical_train_refusal(case).or_else(|| worn_train_refusal(case)) {
            return Err(ModelError(vec![p]));
        }
        // The studies on this model wear the train beyond one operating point: a stage's
        // tooth fault is built into the wear of `gearwear wear` and `gearwear run` only
        // (`Model::train_wear_from_case`, docs/MODEL.md 9.10), refused whichever other
        // study asks (a wear sweep's cases included, whose base may have a fault of zero
        // size).
        super::train::refuse_fault(case, TRAIN_WEAR_STUDIES)?;
        Self::spur_or_train(case)
    }

    /// The model of the wear of a gear train at one operating point (`gearwear wear` and
    /// `gearwear run` without a `[load_spectrum]`): [`Model::from_case`] with a stage's
    /// tooth fault taken, that stage worn tooth by tooth (`study::train_wear`,
    /// docs/MODEL.md 9.10). A single pair: [`Model::from_case`] itself.
    pub fn train_wear_from_case(case: &Case) -> Result<Self, ModelError> {
        if case.stage.is_empty() {
            return Self::from_case(case);
        }
        if let Some(p) = helical_train_refusal(case).or_else(|| worn_train_refusal(case)) {
            return Err(ModelError(vec![p]));
        }
        Self::spur_or_train(case)
    }

    /// [`Model::from_case`] with a train's helical stages taken (`gearwear dynamics`,
    /// `signals`, `stiffness`, the dynamics sweeps: `Model::dynamics_from_case`).
    pub(crate) fn spur_or_train(case: &Case) -> Result<Self, ModelError> {
        if case.stage.is_empty() && case.gear.helix_angle_deg != 0.0 {
            return Err(ModelError(vec![helical_refusal(case.gear.helix_angle_deg)]));
        }
        if case.planetary.is_some() {
            return Err(ModelError(vec![planetary_refusal()]));
        }
        if case.contact.load_sharing == LoadSharingModel::Pedrero && case.contact.path.is_extended()
        {
            return Err(ModelError(vec![PEDRERO_WITH_CORNERS.into()]));
        }
        if !case.stage.is_empty() {
            return Self::train_from_case(case);
        }
        let pair = GearPair::from_case(&case.gear)?;
        let mut warnings = pair.warnings.clone();
        if case.contact.load_sharing == LoadSharingModel::Pedrero && pair.contact_ratio >= 2.0 {
            return Err(ModelError(vec![format!(
                "`contact.load_sharing` = \"pedrero\" (paper eq. 7) is defined for contact ratios between 1 and 2; this pair has {:.3}: use \"stiffness\"",
                pair.contact_ratio
            )]));
        }
        let problems = domain_problems(case, &pair);
        if !problems.is_empty() {
            return Err(ModelError(problems));
        }
        let elastic = ElasticPair::from_case(&case.materials);
        let n_table = case.stiffness.table_points_per_mesh_period.max(16) as usize;
        let mesh = MeshStiffness::with_fillet(
            &pair,
            &elastic,
            n_table,
            FilletSettings::for_pair(&case.stiffness, &case.gear),
        )?;
        warnings.extend(mesh.warnings().iter().cloned());
        let params = DynamicParams::from_case(case, &pair);
        warnings.extend(body_value_warnings(
            case,
            &pair.blank_estimates(case.dynamics.blank_density_kg_per_m3),
        ));
        warnings.extend(pitch_line_velocity_warning(case, &pair, &params.operating));
        warnings.extend(axial_key_warnings(case));
        warnings.extend(super::helical_tilt::tilt_key_warnings(case));
        let friction = Friction::from_case(&case.friction);
        let grid = ProfileGrid::new(&pair, case.wear.points_per_profile.max(2) as usize);
        let teeth = ToothInputs::from_case(
            case,
            &pair,
            &mesh,
            &grid,
            [
                params.operating.pinion_speed_rad_s,
                params.operating.gear_speed_rad_s,
            ],
            params.operating.static_mesh_force_n,
        )
        .map_err(ModelError)?;
        warnings.extend(tolerance_extrapolation_warnings(case, &pair));
        if teeth.is_some() {
            match case.contact.load_sharing {
                LoadSharingModel::Pedrero => {
                    return Err(ModelError(vec![pedrero_with_resolved_teeth(case)]))
                }
                // With corner contact identical teeth share by compression too: one law.
                LoadSharingModel::Auto if !case.contact.path.is_extended() => {
                    warnings.push(AUTO_SHARING_WITH_RESOLVED_TEETH.into())
                }
                LoadSharingModel::Auto => {}
                LoadSharingModel::Stiffness => {}
            }
        }
        Ok(Self {
            teeth,
            contact: ContactPath::new(&pair, case.contact.path, MAX_PAIRS),
            case: case.clone(),
            effective_modulus_pa: effective_modulus_of(&case.materials),
            elastic,
            mesh,
            params,
            friction,
            roughness: RoughnessLaw::from_case(&case.surface),
            grid,
            settings: SteadyStateSettings::from_case(&case.numerics),
            pair,
            warnings,
            train: None,
            helical: None,
        })
    }

    /// The model of a train case: its stages and assembly, and the first stage in the
    /// single pair's fields.
    fn train_from_case(case: &Case) -> Result<Self, ModelError> {
        super::helical_tilt::refuse_tilt(case, "a gear train (`[[stage]]`)")?;
        let elastic = ElasticPair::from_case(&case.materials);
        let train = super::train::TrainModel::from_case(case, &elastic)?;
        let first = &train.stages[0];
        let mut warnings = Vec::new();
        for (k, s) in train.stages.iter().enumerate() {
            let named = s.warnings.iter().map(|w| case.stage[k].name_own_keys(w));
            warnings.extend(named.map(|w| format!("stage {}: {w}", k + 1)));
        }
        if train.stages.iter().any(|s| s.teeth.is_some()) {
            // A faulty stage shares its load as a pair with resolved teeth does.
            match case.contact.load_sharing {
                LoadSharingModel::Pedrero => {
                    return Err(ModelError(vec![pedrero_with_resolved_teeth(case)]))
                }
                LoadSharingModel::Auto if !case.contact.path.is_extended() => {
                    warnings.push(AUTO_SHARING_WITH_RESOLVED_TEETH.into())
                }
                LoadSharingModel::Auto | LoadSharingModel::Stiffness => {}
            }
        }
        let p = &train.operating.meshes[0];
        let params = DynamicParams {
            lumped: first.lumped.clone(),
            speed_boundary: case.operating.speed_boundary,
            motor_slip_damping_nm_s_per_rad: case.operating.motor_slip_damping_nm_s_per_rad,
            operating: crate::dynamics::params::OperatingPoint {
                pinion_speed_rad_s: p.pinion_speed_rad_s,
                gear_speed_rad_s: p.gear_speed_rad_s,
                brake_torque_nm: p.gear_torque_nm,
                motor_torque_nm: p.pinion_torque_nm,
                mesh_frequency_hz: p.mesh_frequency_hz,
                static_mesh_force_n: p.static_mesh_force_n,
            },
            axial: None,
            tilt: None,
        };
        Ok(Self {
            contact: first.contact.clone(),
            pair: first.pair.clone(),
            mesh: first.mesh.clone(),
            grid: first.grid.clone(),
            params,
            elastic,
            friction: Friction::from_case(&case.friction),
            roughness: RoughnessLaw::from_case(&case.surface),
            settings: SteadyStateSettings::from_case(&case.numerics),
            effective_modulus_pa: effective_modulus_of(&case.materials),
            teeth: None,
            case: case.clone(),
            warnings,
            train: Some(train),
            helical: None,
        })
    }

    /// The values the case may leave to the geometry (hub bores, masses and inertias of
    /// pinion and gear) as the model uses them, with the geometry's estimates and
    /// Sainsot's h_f and theta_f: for summaries and reports.
    pub fn resolved_parameters(&self) -> ResolvedParameters {
        ResolvedParameters::new(
            &self.case,
            &self.pair,
            &self.params.lumped,
            self.mesh.fillets(),
        )
    }

    /// [`Model::resolved_parameters`] and the operating point: `metadata.resolved` of
    /// every summary.
    pub fn resolved(&self) -> Resolved {
        Resolved {
            parameters: self.resolved_parameters(),
            operating_point: self.params.operating,
        }
    }

    /// The dynamic system for a wear state (gap), external error and roughness (um),
    /// every tooth alike.
    pub fn system<'a>(
        &'a self,
        gap: &'a PairGap,
        external: &'a ExternalError,
        roughness_um: f64,
    ) -> GearSystem<'a> {
        self.system_for(gap, external, roughness_um, None)
    }

    /// As [`Model::system`] with a tooth-resolved mesh (with `contact.load_sharing` =
    /// "auto" its pairs' loads then follow their own compressions: Pedrero's law of eq. 7
    /// is for identical, perfect teeth; `LoadSharingModel::resolve`).
    pub fn system_for<'a>(
        &'a self,
        gap: &'a PairGap,
        external: &'a ExternalError,
        roughness_um: f64,
        teeth: Option<&'a ToothMesh>,
    ) -> GearSystem<'a> {
        if let Some(train) = &self.train {
            // The first stage's gap and error; the later stages' teeth new.
            let n = train.stages.len();
            let gaps: Vec<&PairGap> = (0..n).map(|k| if k == 0 { gap } else { &NO_GAP }).collect();
            let ext: Vec<&ExternalError> = (0..n)
                .map(|k| if k == 0 { external } else { &NO_ERROR })
                .collect();
            return train.system(
                &self.case,
                &self.friction,
                self.effective_modulus_pa,
                &gaps,
                &ext,
                roughness_um,
            );
        }
        self.pair_system(&self.contact, gap, external, roughness_um, teeth)
    }

    /// The single pair's system with its contact following `contact`.
    fn pair_system<'a>(
        &'a self,
        contact: &'a ContactPath,
        gap: &'a PairGap,
        external: &'a ExternalError,
        roughness_um: f64,
        teeth: Option<&'a ToothMesh>,
    ) -> GearSystem<'a> {
        GearSystem::new(GearSystemParts {
            pair: &self.pair,
            mesh: &self.mesh,
            params: &self.params,
            friction: &self.friction,
            viscosity_cp: self.case.lubricant.viscosity_cp,
            gap,
            external,
            load_sharing: self.case.contact.load_sharing,
            roughness_um,
            effective_modulus_pa: self.effective_modulus_pa,
            teeth,
            contact,
        })
    }

    /// The single pair's dynamic system with its contact following `contact` instead of
    /// the case's `contact.path` (new, identical teeth): the other contact model of the
    /// same pair, for figures that set the two beside each other.
    pub fn system_with_contact<'a>(
        &'a self,
        contact: &'a ContactPath,
        roughness_um: f64,
    ) -> GearSystem<'a> {
        self.pair_system(contact, &NO_GAP, &NO_ERROR, roughness_um, None)
    }

    /// The tooth-resolved mesh of a wear state (None when every tooth is the paper's).
    pub fn tooth_mesh(&self, wear: &WearState) -> Option<ToothMesh> {
        self.teeth.as_ref().map(|t| t.mesh_for(wear))
    }

    /// New teeth: a wear state with a profile per tooth when the teeth differ, per face
    /// slice for a helical pair.
    pub fn new_wear_state(&self) -> WearState {
        if let Some(h) = &self.helical {
            // Per-tooth inputs: every tooth's face slices, tooth t's slice j at t N + j
            // (docs/MODEL.md 11.13).
            return match &self.teeth {
                Some(_) => WearState::per_tooth(
                    self.grid.len(),
                    self.pair.pinion.teeth * h.slices,
                    self.pair.gear.teeth * h.slices,
                ),
                None => WearState::per_slice(self.grid.len(), h.slices),
            };
        }
        match &self.teeth {
            Some(_) => WearState::per_tooth(
                self.grid.len(),
                self.pair.pinion.teeth,
                self.pair.gear.teeth,
            ),
            None => WearState::new(self.grid.len()),
        }
    }

    /// Name and unit of each coordinate of the model's dynamic system
    /// (`Assembly::coordinate_names`).
    pub fn coordinate_names(&self) -> Vec<(String, &'static str)> {
        match &self.train {
            Some(t) => t.assembly.coordinate_names(),
            None => crate::dynamics::assembly::Assembly::new(
                crate::dynamics::assembly::elements::Elements::single_pair(
                    &self.params,
                    &self.pair,
                ),
            )
            .map(|a| a.coordinate_names())
            .unwrap_or_default(),
        }
    }

    /// Number of states of the model's dynamic system (twice its coordinates): the length
    /// of a periodic end state.
    pub fn state_len(&self) -> usize {
        match &self.train {
            Some(t) => 2 * t.assembly.len(),
            None => {
                let extra = self.params.axial_coordinates() + self.params.tilt_coordinates();
                crate::dynamics::model::NSTATE + 2 * extra
            }
        }
    }

    /// Roughness that goes with a wear state, um.
    pub fn roughness_for(&self, wear: &WearState) -> f64 {
        self.roughness.rms_um(wear.max_pinion_m())
    }

    /// Steady-state dynamic response of the worn pair.
    pub fn dynamic(
        &self,
        wear: &WearState,
        external: &ExternalError,
    ) -> Result<DynamicResponse, DynamicsError> {
        self.dynamic_from(wear, external, None)
    }

    /// As [`Model::dynamic`], warm-started from `start` (the `end_state` of an earlier
    /// response, e.g. the previous wear update or continuation point); `None` starts from
    /// the static equilibrium.
    pub fn dynamic_from(
        &self,
        wear: &WearState,
        external: &ExternalError,
        start: Option<&[f64]>,
    ) -> Result<DynamicResponse, DynamicsError> {
        self.dynamic_with(wear, external, start, &self.settings)
    }

    /// As [`Model::dynamic_from`] with other numerical settings (e.g. a retry with a
    /// tighter integration tolerance).
    pub fn dynamic_with(
        &self,
        wear: &WearState,
        external: &ExternalError,
        start: Option<&[f64]>,
        settings: &SteadyStateSettings,
    ) -> Result<DynamicResponse, DynamicsError> {
        let gap = self.wear_gap(wear);
        let teeth = self.tooth_mesh(wear);
        let sys = self.system_for(&gap, external, self.roughness_for(wear), teeth.as_ref());
        solve_steady_state_from(&sys, settings, start)
    }

    /// The gap a wear state opens in the model's mesh: the pair's (`WearState::pair_gap`),
    /// or a helical pair's contact lines' from its worn slices
    /// (`study::helical_wear`, docs/MODEL.md 11.3).
    pub fn wear_gap(&self, wear: &WearState) -> PairGap {
        match &self.helical {
            Some(h) => h.wear_gap(&self.grid, wear),
            None => wear.pair_gap(&self.grid),
        }
    }

    /// Quasi-static response of the worn pair.
    pub fn quasi_static(&self, wear: &WearState, external: &ExternalError) -> DynamicResponse {
        let gap = self.wear_gap(wear);
        let teeth = self.tooth_mesh(wear);
        let sys = self.system_for(&gap, external, self.roughness_for(wear), teeth.as_ref());
        solve_quasi_static(&sys, self.settings.steps_per_mesh_period)
    }
}
