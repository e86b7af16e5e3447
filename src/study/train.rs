//! The model of a gear-train case (`[[stage]]` tables, `config::train`): each stage's
//! pair, mesh stiffness and wear grid, the assembly of the whole train and its operating
//! point, built once.

use super::helical::{helix_of, HelicalDynamics};
use super::model_error::ModelError;
use super::teeth::ToothInputs;
use crate::config::case::{Case, DynamicsSection, GearSection, SpeedBoundary, TorqueShaft};
use crate::config::train::StageSpec;
use crate::contact::friction::Friction;
use crate::dynamics::assembly::elements::{Drive, Elements};
use crate::dynamics::assembly::train::StageElements;
use crate::dynamics::assembly::{Assembly, Dof};
use crate::dynamics::contact_path::ContactPath;
use crate::dynamics::excitation::{ExternalError, PairGap};
use crate::dynamics::model::MAX_PAIRS;
use crate::dynamics::model::{GearSystem, MeshOperating, MeshParts};
use crate::dynamics::params::{AxialSupport, MeshPoint, TrainOperatingPoint};
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::summary::ResponseSummary;
use crate::dynamics::tooth_mesh::ToothMesh;
use crate::geometry::helical::HelicalPair;
use crate::geometry::{GearPair, ProfileGrid};
use crate::stiffness::mesh::{FilletSettings, MeshStiffness};
use crate::stiffness::potential_energy::ElasticPair;
use crate::wear::WearState;
use std::borrow::Cow;

/// One stage of a train.
pub struct Stage {
    /// The stage as a single-pair case: its `[gear]` and `[dynamics]` resolved from the
    /// stage's keys, its pinion's speed and torque as `[operating]` (on its pinion).
    pub case: Case,
    /// The stage's pair geometry.
    pub pair: GearPair,
    /// The stage's mesh stiffness.
    pub mesh: MeshStiffness,
    /// Points along the stage's path of contact where wear is computed.
    pub grid: ProfileGrid,
    /// The stage's masses and inertias (with `"derived"` resolved) and bearings.
    pub lumped: DynamicsSection<f64>,
    /// Where its pairs touch (`contact.path`; a helical stage: its contact lines).
    pub contact: ContactPath,
    /// A helical stage's pair and slice model (`stage.helix_angle_deg` > 0,
    /// `study::train_helical`); None: a spur stage. Its `pair` and `mesh` above are then
    /// the contact lines' (as `Model::helical_from_case` builds them).
    pub helical: Option<HelicalDynamics>,
    /// A helical stage's axial bearings and mesh axial gradient (docs/MODEL.md 4.3, 11.6);
    /// None: rigid axial bearings (and every spur stage).
    pub axial: Option<AxialSupport>,
    /// The stage's warnings (its geometry's, its stiffness's, its keys').
    pub warnings: Vec<String>,
    /// The stage's tooth-resolved mesh of new teeth when a `[[fault]]` table names the
    /// stage and changes its tooth (`fault.stage`, docs/MODEL.md 9.10); None: every
    /// tooth alike. `tooth_inputs.mesh_for` new teeth.
    pub teeth: Option<ToothMesh>,
    /// The faulty stage's teeth before wear (`study::teeth`), from which its
    /// tooth-resolved mesh of any per-tooth wear state is built (its wear study,
    /// `study::train_wear`); None exactly when `teeth` is.
    pub tooth_inputs: Option<ToothInputs>,
}

/// A train's model objects (see the module docs).
pub struct TrainModel {
    /// The stages, in order (stage 1's pinion on the input shaft).
    pub stages: Vec<Stage>,
    /// The assembled train: its elements, coordinates and constant matrices.
    pub assembly: Assembly,
    /// The train's operating point: every shaft's speed and torque, every mesh's frequency
    /// and force.
    pub operating: TrainOperatingPoint,
}

/// A message about stage `k` (0-based) of a case.
fn at_stage(k: usize, what: impl std::fmt::Display) -> String {
    format!("stage {}: {what}", k + 1)
}

/// A stage's single-pair case: the case's sections with the stage's pair and bodies,
/// and `[operating]` at the stage's pinion (its speed, its torque on the pinion).
pub fn stage_case(case: &Case, spec: &StageSpec, point: Option<&MeshPoint>) -> Case {
    let mut c = case.clone();
    c.gear = spec.gear_section(&case.gear);
    c.dynamics = spec.dynamics_section(&case.dynamics);
    c.stiffness.slices = spec.slices(case.stiffness.slices);
    c.stage = Vec::new();
    if let Some(p) = point {
        c.operating.input_speed_hz = p.pinion_speed_rad_s / (2.0 * std::f64::consts::PI);
        c.operating.load_torque_nm = p.pinion_torque_nm;
        c.operating.load_torque_shaft = TorqueShaft::Pinion;
    }
    c
}

impl TrainModel {
    /// The train of `case` (which has stages), its materials `elastic`. Every problem
    /// names its stage.
    pub fn from_case(case: &Case, elastic: &ElasticPair) -> Result<Self, ModelError> {
        let mut problems = Vec::new();
        let mut pairs = Vec::new();
        for (k, spec) in case.stage.iter().enumerate() {
            match stage_pair(&spec.gear_section(&case.gear)) {
                Ok(p) => pairs.push(p),
                Err(e) => problems.extend(e.iter().map(|m| at_stage(k, spec.name_own_keys(m)))),
            }
        }
        if !problems.is_empty() {
            return Err(ModelError(problems));
        }
        let refs: Vec<&GearPair> = pairs.iter().collect();
        let operating = TrainOperatingPoint::of(&case.operating, &refs);
        let mut stages = Vec::new();
        for (k, (spec, pair)) in case.stage.iter().zip(pairs).enumerate() {
            match build_stage(case, (k, spec), pair, &operating.meshes[k], elastic) {
                Ok(s) => stages.push(s),
                Err(e) => problems.extend(e.iter().map(|m| at_stage(k, spec.name_own_keys(m)))),
            }
        }
        if !problems.is_empty() {
            return Err(ModelError(problems));
        }
        let elements = stage_elements(case, &stages);
        let (t_in, t_out) = operating.end_torques_nm();
        let drive = Drive {
            input: 0,
            output: 0,
            boundary: case.operating.speed_boundary,
            input_torque_nm: t_in,
            output_torque_nm: t_out,
            slip_damping_nm_s_per_rad: case.operating.motor_slip_damping_nm_s_per_rad,
        };
        let assembly = Assembly::new(Elements::train(&elements, drive))?;
        let model = Self {
            stages,
            assembly,
            operating,
        };
        let free = model.free_modes();
        if !free.is_empty() {
            return Err(ModelError(free));
        }
        Ok(model)
    }

    /// Rigid-body motions the springs do not hold, other than the drive's free rotation
    /// (motor slip): each named by the body that moves most in it. The stiffness at the
    /// mean mesh stiffnesses on the free coordinates has a null space of dimension 1
    /// with the motor slip boundary, 0 with an imposed speed.
    fn free_modes(&self) -> Vec<String> {
        let asm = &self.assembly;
        let k_mean: Vec<f64> = self
            .stages
            .iter()
            .map(|s| s.mesh.mean_stiffness_n_per_m())
            .collect();
        let k = asm.stiffness_with_meshes(&k_mean);
        let inv = asm.inverse_masses();
        let free: Vec<usize> = (0..asm.len()).filter(|i| inv[*i] > 0.0).collect();
        let n = free.len();
        // Mass-normalised, so that translations and rotations compare.
        let kt = nalgebra::DMatrix::from_fn(n, n, |a, b| {
            k[(free[a], free[b])] * (inv[free[a]] * inv[free[b]]).sqrt()
        });
        let eig = nalgebra::SymmetricEigen::new(kt);
        let scale = eig.eigenvalues.iter().fold(0.0_f64, |m, l| m.max(l.abs()));
        let expected = usize::from(asm.held().is_none());
        let mut zero: Vec<usize> = (0..n)
            .filter(|i| eig.eigenvalues[*i].abs() <= 1e-12 * scale)
            .collect();
        if zero.len() <= expected {
            return Vec::new();
        }
        zero.sort_by(|a, b| {
            eig.eigenvalues[*a]
                .abs()
                .total_cmp(&eig.eigenvalues[*b].abs())
        });
        zero.iter()
            .skip(expected)
            .map(|&i| {
                let v = eig.eigenvectors.column(i);
                let big = (0..n).max_by(|a, b| v[*a].abs().total_cmp(&v[*b].abs())).unwrap_or(0);
                let (body, dof) = asm.describe(free[big]);
                format!(
                    "{body} can move freely ({dof:?}): no bearing, shaft or mesh holds it; give it a bearing or a shaft"
                )
            })
            .collect()
    }

    /// The dynamic system of the train for each stage's wear gap and external error and
    /// a roughness (um), every tooth alike. `friction`, `effective_modulus_pa`: the
    /// case's, shared by every mesh.
    #[allow(clippy::too_many_arguments)]
    pub fn system<'a>(
        &'a self,
        case: &Case,
        friction: &'a Friction,
        effective_modulus_pa: f64,
        gaps: &[&'a PairGap],
        externals: &[&'a ExternalError],
        roughness_um: f64,
    ) -> GearSystem<'a> {
        let rough = vec![roughness_um; self.stages.len()];
        let teeth = self.new_teeth_meshes();
        self.system_worn(
            case,
            friction,
            effective_modulus_pa,
            gaps,
            externals,
            (&rough, &teeth),
        )
    }

    /// Each stage's tooth-resolved mesh of new teeth (None: a stage whose teeth are
    /// alike), stage order.
    pub fn new_teeth_meshes(&self) -> Vec<Option<&ToothMesh>> {
        self.stages.iter().map(|s| s.teeth.as_ref()).collect()
    }

    /// As [`TrainModel::system`] with each mesh's own roughness (um, stage order: the
    /// roughness of its own wear, `wear.RoughnessLaw`) and tooth-resolved mesh (a faulty
    /// stage's with each tooth's own wear, `ToothInputs::mesh_for`; None for a stage
    /// whose teeth are alike), as the wear study of a train has.
    #[allow(clippy::too_many_arguments)]
    pub fn system_worn<'a>(
        &'a self,
        case: &Case,
        friction: &'a Friction,
        effective_modulus_pa: f64,
        gaps: &[&'a PairGap],
        externals: &[&'a ExternalError],
        (roughness_um, teeth): (&[f64], &[Option<&'a ToothMesh>]),
    ) -> GearSystem<'a> {
        let meshes = self
            .stages
            .iter()
            .zip(&self.operating.meshes)
            .enumerate()
            .map(|(k, (s, p))| {
                let parts = MeshParts {
                    pair: &s.pair,
                    mesh: &s.mesh,
                    friction,
                    viscosity_cp: case.lubricant.viscosity_cp,
                    gap: gaps[k],
                    external: externals[k],
                    // A helical stage's own ("stiffness", `study::train_helical`).
                    load_sharing: s.case.contact.load_sharing,
                    roughness_um: roughness_um[k],
                    effective_modulus_pa,
                    teeth: teeth[k],
                    contact: &s.contact,
                };
                let op = MeshOperating {
                    speeds_rad_s: [p.pinion_speed_rad_s, p.gear_speed_rad_s],
                    torques_nm: [p.pinion_torque_nm, p.gear_torque_nm],
                    static_force_n: p.static_mesh_force_n,
                    damping_ratio: s.lumped.mesh_damping_ratio,
                };
                (parts, op)
            })
            .collect();
        GearSystem::assembled(
            Cow::Borrowed(&self.assembly),
            meshes,
            self.operating.body_speeds_rad_s(),
        )
    }

    /// Revolutions of each stage's pinion per revolution of the input (stage 1's
    /// pinion): its speed over the input's (1 for stage 1, the product of the earlier
    /// stages' z_pinion / z_gear after it).
    pub fn cycle_factors(&self) -> Vec<f64> {
        let input = self.operating.meshes[0].pinion_speed_rad_s;
        self.operating
            .meshes
            .iter()
            .map(|p| p.pinion_speed_rad_s / input)
            .collect()
    }

    /// The summary of mesh `m` of a response of the train: its own mesh period's
    /// harmonics, its pinion's y velocity (`ResponseSummary::of_mesh`).
    pub fn mesh_summary(&self, r: &DynamicResponse, m: usize) -> ResponseSummary {
        let link = &self.assembly.elements.meshes[m];
        let pinion_y = self
            .assembly
            .index(link.pinion, Dof::Y)
            .unwrap_or(crate::dynamics::model::dof::YP);
        let period_s = 1.0 / self.operating.meshes[m].mesh_frequency_hz;
        ResponseSummary::of_mesh(r, m, period_s, pinion_y)
    }

    /// Mesh periods of each mesh in the train's base period (stage order; the single
    /// pair's 1), from the teeth (`dynamics::grid::chain_mesh_counts`): a tooth-resolved
    /// stage's response over E base periods spans E times its count of its own mesh
    /// periods, the period its engagements are counted in (`PathSample::cycle`). 1 for
    /// a mesh when a count overflows (never for the teeth the schema allows).
    pub fn mesh_counts(&self) -> Vec<usize> {
        let teeth: Vec<[usize; 2]> = self
            .stages
            .iter()
            .map(|s| [s.pair.pinion.teeth, s.pair.gear.teeth])
            .collect();
        crate::dynamics::grid::chain_mesh_counts(&teeth)
            .and_then(|c| c.into_iter().map(|n| usize::try_from(n).ok()).collect())
            .unwrap_or_else(|| vec![1; teeth.len()])
    }

    /// Whether the speed of the input is imposed (so the motor's coordinate is held).
    pub fn input_held(&self) -> bool {
        self.assembly.elements.drive.boundary == SpeedBoundary::MotorSpeedImposed
    }

    /// The rotation coordinate of body `b`.
    pub fn rotation(&self, b: usize) -> usize {
        self.assembly.index(b, Dof::Rotation).unwrap_or(0)
    }
}

/// The teeth of stage `k` (0-based; `sc` its single-pair case, holding the `[[fault]]`
/// tables that name the stage, `fault.stage`) and their tooth-resolved mesh of new teeth,
/// built by the pair's own machinery (`study::teeth::ToothInputs`: the same checks
/// against the tooth, the same compliances and gaps): None when no fault names the stage
/// or none changes its tooth (a crack of zero depth), so that stage stays the healthy one
/// bit for bit. Every stage of a train takes the involute geometry (wear opens gaps, as
/// a healthy stage's wear does): `wear.worn_geometry` is not applied to the faulty
/// stage's flanks. Errors: the pair's checks of the fault against the stage's tooth.
fn stage_teeth(
    sc: &Case,
    pair: &GearPair,
    mesh: &MeshStiffness,
    grid: &ProfileGrid,
    p: &MeshPoint,
) -> Result<Option<(ToothInputs, ToothMesh)>, Vec<String>> {
    if sc.fault.is_empty() {
        return Ok(None);
    }
    let mut fc = sc.clone();
    fc.wear.worn_geometry = crate::config::case::WornGeometry::Involute;
    let inputs = ToothInputs::from_case(
        &fc,
        pair,
        mesh,
        grid,
        [p.pinion_speed_rad_s, p.gear_speed_rad_s],
        p.static_mesh_force_n,
    )?;
    Ok(inputs.map(|t| {
        let new = t.mesh_for(&WearState::new(grid.len()));
        (t, new)
    }))
}

/// A train with a tooth fault (`fault.stage`) is refused by `study` (the command as the
/// message names it, e.g. "`gearwear dataset`"): the faulty stage wears tooth by tooth at
/// one operating point only (`gearwear wear` and `gearwear run`, `study::train_wear`,
/// docs/MODEL.md 9.10); the studies built on more than that (`dataset`, `calibrate`,
/// `predict`, a wear sweep, a load spectrum) are not built with a fault. Ok for a single
/// pair or a train whose faults change no tooth.
pub fn refuse_fault(case: &Case, study: &str) -> Result<(), ModelError> {
    let Some(f) = (!case.stage.is_empty())
        .then(|| case.fault.iter().find(|f| f.changes_tooth()))
        .flatten()
    else {
        return Ok(());
    };
    Err(ModelError(vec![format!(
        "`fault.stage` = {} ({} {} tooth {}): {study} on a gear train with a tooth fault is not built yet (the faulty stage's per-tooth wear is built at one operating point, in `gearwear wear` and `gearwear run` without a [load_spectrum]); `gearwear stiffness`, `gearwear dynamics`, `gearwear signals`, `gearwear sweep` of dynamics, `gearwear wear` and `gearwear run` take the fault; remove the [[fault]] table for {study} on the train",
        f.stage_index().map_or(0, |s| s + 1),
        f.kind().name(),
        f.gear.name(),
        f.tooth
    )]))
}

/// Each stage as the assembly needs it (shafts from the stages' keys; the motor's and
/// load's inertias and couplings from `[dynamics]`).
fn stage_elements(case: &Case, stages: &[Stage]) -> Vec<StageElements> {
    stages
        .iter()
        .zip(&case.stage)
        .map(|(s, spec)| StageElements {
            lumped: s.lumped.clone(),
            teeth: [s.pair.pinion.teeth, s.pair.gear.teeth],
            base_radius_m: [s.pair.pinion.base_radius_m, s.pair.gear.base_radius_m],
            pressure_angle_rad: s.pair.operating_pressure_angle_rad,
            centre_line_rad: spec.centre_line_deg.unwrap_or(0.0).to_radians(),
            shaft: spec
                .shaft_torsional_stiffness_nm_per_rad
                .map(|k| (k, spec.shaft_torsional_damping_nm_s_per_rad.unwrap_or(0.0))),
            axial: s.axial,
        })
        .collect()
}

/// A stage's transverse pair: the spur pair of its `[gear]` keys, or a helical stage's
/// transverse section (`HelicalPair`, its keys read as the normal section).
fn stage_pair(gear: &GearSection) -> Result<GearPair, Vec<String>> {
    if gear.helix_angle_deg == 0.0 {
        GearPair::from_case(gear).map_err(|e| e.0)
    } else {
        HelicalPair::from_case(gear, &helix_of(gear))
            .map(|h| h.transverse)
            .map_err(|e| e.0)
    }
}

/// One stage of the train of `case`: `spec` on its transverse pair `pair` at its mesh's
/// operating point `point`; a spur stage by the spur pair's mesh stiffness, a helical one
/// by its slice model (`study::train_helical`). Problems unnamed by stage.
fn build_stage(
    case: &Case,
    (k, spec): (usize, &StageSpec),
    pair: GearPair,
    point: &MeshPoint,
    elastic: &ElasticPair,
) -> Result<Stage, Vec<String>> {
    let mut sc = stage_case(case, spec, Some(point));
    // The stage's own faults (`fault.stage`): its single-pair case is its pair's.
    sc.fault.retain(|f| f.stage_index() == Some(k));
    let torque = format!(
        "its pinion's torque, {} N m from `operating.load_torque_nm` = {} through the ratios,",
        crate::format::shown(point.pinion_torque_nm),
        crate::format::shown(case.operating.load_torque_nm)
    );
    let problems = super::domain::domain_problems_naming(&sc, &pair, &torque);
    if !problems.is_empty() {
        return Err(problems);
    }
    let d = &sc.dynamics;
    let lumped = d.resolve(&pair.blank_estimates(d.blank_density_kg_per_m3));
    let grid = ProfileGrid::new(&pair, case.wear.points_per_profile.max(2) as usize);
    if sc.gear.helix_angle_deg != 0.0 {
        if let Some(f) = sc.fault.iter().find(|f| f.changes_tooth()) {
            return Err(vec![format!(
                "`fault.stage` = {} names a helical stage ({} {} tooth {}): a tooth fault on a helical stage is not built yet (its slices would each need the fault); give the fault to a spur stage, or `stage.helix_angle_deg` = 0",
                k + 1,
                f.kind().name(),
                f.gear.name(),
                f.tooth
            )]);
        }
        let h = super::train_helical::helical_stage(&mut sc)?;
        return Ok(Stage {
            case: sc,
            pair: h.line_pair,
            mesh: h.mesh,
            grid,
            lumped,
            contact: h.contact,
            helical: Some(h.helical),
            axial: h.axial,
            warnings: h.warnings,
            teeth: None,
            tooth_inputs: None,
        });
    }
    let n_table = case.stiffness.table_points_per_mesh_period.max(16) as usize;
    let mesh = MeshStiffness::with_fillet(
        &pair,
        elastic,
        n_table,
        FilletSettings::for_pair(&sc.stiffness, &sc.gear),
    )
    .map_err(|e| e.0)?;
    let contact = ContactPath::new(&pair, case.contact.path, MAX_PAIRS);
    let (tooth_inputs, teeth) = stage_teeth(&sc, &pair, &mesh, &grid, point)?.unzip();
    let mut warnings: Vec<String> = pair
        .warnings
        .iter()
        .chain(mesh.warnings())
        .cloned()
        .collect();
    warnings.extend(super::domain::axial_key_warnings(&sc));
    Ok(Stage {
        case: sc,
        pair,
        mesh,
        grid,
        lumped,
        contact,
        helical: None,
        axial: None,
        warnings,
        teeth,
        tooth_inputs,
    })
}
