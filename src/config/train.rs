//! A gear train in the case file: one `[[stage]]` table per stage of a parallel-axis
//! reducer, in the order the power flows (docs/CONFIG.md, "Gear trains").
//!
//! A stage takes the pair's keys of `[gear]` and the pinion's and gear's keys of
//! `[dynamics]` (masses, inertias, bearings); a key it does not give is the section's.
//! Stage k's gear and stage k + 1's pinion sit on one shaft, whose torsional stiffness
//! and damping stage k gives (`shaft_torsional_*`). The motor drives stage 1's pinion
//! through `dynamics.coupling_*_motor_*`, the last stage's gear drives the load through
//! `dynamics.coupling_*_brake_*`; `[operating]` gives the input speed (stage 1's pinion)
//! and the load torque (on the input or the output shaft). A case without `[[stage]]`
//! is the single pair of `[gear]`, a one-stage train.

use super::derivable::Derivable;
use super::gear::{GearSection, HelixHand};
use super::lumped::DynamicsSection;
use super::teeth::{FaultKind, FaultTable};
use serde::{Deserialize, Serialize};

/// One `[[stage]]` table: every key optional (absent: `[gear]`'s or `[dynamics]`'s).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct StageSpec {
    /// Module m, mm (absent: `gear.module_mm`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub module_mm: Option<f64>,
    /// Teeth of the stage's pinion (the driving gear; absent: `gear.teeth_pinion`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub teeth_pinion: Option<i64>,
    /// Teeth of the stage's gear (absent: `gear.teeth_gear`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub teeth_gear: Option<i64>,
    /// Reference pressure angle, deg (absent: `gear.pressure_angle_deg`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure_angle_deg: Option<f64>,
    /// Addendum coefficient, in modules (absent: `gear.addendum_coefficient`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub addendum_coefficient: Option<f64>,
    /// Dedendum coefficient, in modules (absent: `gear.dedendum_coefficient`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dedendum_coefficient: Option<f64>,
    /// Profile shift coefficient of the stage's pinion (absent: `gear.profile_shift_pinion`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_shift_pinion: Option<f64>,
    /// Profile shift coefficient of the stage's gear (absent: `gear.profile_shift_gear`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile_shift_gear: Option<f64>,
    /// Face width, mm (absent: `gear.face_width_mm`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub face_width_mm: Option<f64>,
    /// Operating centre distance, mm (absent: `gear.centre_distance_mm`, or the one the profile shifts give).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub centre_distance_mm: Option<f64>,
    /// Pinion hub bore radius, mm, or `"derived"` (absent: `gear.hub_bore_radius_pinion_mm`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hub_bore_radius_pinion_mm: Option<Derivable>,
    /// Gear hub bore radius, mm, or `"derived"` (absent: `gear.hub_bore_radius_gear_mm`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hub_bore_radius_gear_mm: Option<Derivable>,
    /// Rack-cutter tip radius, in modules (absent: `gear.tool_tip_radius_coefficient`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tool_tip_radius_coefficient: Option<f64>,
    /// Pinion mass, kg, or `"derived"` from its blank (absent: `dynamics.mass_pinion_kg`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mass_pinion_kg: Option<Derivable>,
    /// Gear mass, kg, or `"derived"` (absent: `dynamics.mass_gear_kg`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mass_gear_kg: Option<Derivable>,
    /// Pinion polar inertia, kg m^2, or `"derived"` (absent: `dynamics.inertia_pinion_kg_m2`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inertia_pinion_kg_m2: Option<Derivable>,
    /// Gear polar inertia, kg m^2, or `"derived"` (absent: `dynamics.inertia_gear_kg_m2`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inertia_gear_kg_m2: Option<Derivable>,
    /// Pinion bearing stiffness in x and y, N/m (absent: `dynamics.bearing_stiffness_pinion_n_per_m`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_stiffness_pinion_n_per_m: Option<f64>,
    /// Gear bearing stiffness in x and y, N/m (absent: `dynamics.bearing_stiffness_gear_n_per_m`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_stiffness_gear_n_per_m: Option<f64>,
    /// Pinion bearing damping in x and y, N s/m (absent: `dynamics.bearing_damping_pinion_n_s_per_m`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_damping_pinion_n_s_per_m: Option<f64>,
    /// Gear bearing damping in x and y, N s/m (absent: `dynamics.bearing_damping_gear_n_s_per_m`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_damping_gear_n_s_per_m: Option<f64>,
    /// Mesh damping ratio zeta (absent: `dynamics.mesh_damping_ratio`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mesh_damping_ratio: Option<f64>,
    /// Torsional stiffness of the shaft from this stage's gear to the next stage's
    /// pinion, N m/rad (every stage but the last).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shaft_torsional_stiffness_nm_per_rad: Option<f64>,
    /// Its torsional damping, N m s/rad (absent: 0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shaft_torsional_damping_nm_s_per_rad: Option<f64>,
    /// Direction of the gear's centre seen from the pinion's, deg from +x (absent: 0,
    /// every centre on one line).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub centre_line_deg: Option<f64>,
    /// Helix angle of the stage's pair, deg (absent: `gear.helix_angle_deg`; 0: spur).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub helix_angle_deg: Option<f64>,
    /// Hand of the stage's pinion (absent: `gear.helix_hand_pinion`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub helix_hand_pinion: Option<HelixHand>,
    /// Slices across the stage's face (absent: `stiffness.slices`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slices: Option<i64>,
    /// Axial bearing stiffness of the stage's pinion, N/m (absent:
    /// `dynamics.bearing_axial_stiffness_pinion_n_per_m`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_axial_stiffness_pinion_n_per_m: Option<f64>,
    /// Axial bearing stiffness of the stage's gear, N/m (absent: `dynamics`').
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_axial_stiffness_gear_n_per_m: Option<f64>,
    /// Axial bearing damping of the stage's pinion, N s/m (absent: `dynamics`').
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_axial_damping_pinion_n_s_per_m: Option<f64>,
    /// Axial bearing damping of the stage's gear, N s/m (absent: `dynamics`').
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_axial_damping_gear_n_s_per_m: Option<f64>,
}

/// Largest number of stages (each is a mesh: `dynamics::model::MAX_MESHES`).
pub const MAX_STAGES: usize = 16;

impl StageSpec {
    /// The stage's pair: `base` (the case's `[gear]`) with the stage's keys.
    pub fn gear_section(&self, base: &GearSection) -> GearSection {
        GearSection {
            module_mm: self.module_mm.unwrap_or(base.module_mm),
            teeth_pinion: self.teeth_pinion.unwrap_or(base.teeth_pinion),
            teeth_gear: self.teeth_gear.unwrap_or(base.teeth_gear),
            pressure_angle_deg: self.pressure_angle_deg.unwrap_or(base.pressure_angle_deg),
            addendum_coefficient: self
                .addendum_coefficient
                .unwrap_or(base.addendum_coefficient),
            dedendum_coefficient: self
                .dedendum_coefficient
                .unwrap_or(base.dedendum_coefficient),
            profile_shift_pinion: self
                .profile_shift_pinion
                .unwrap_or(base.profile_shift_pinion),
            profile_shift_gear: self.profile_shift_gear.unwrap_or(base.profile_shift_gear),
            face_width_mm: self.face_width_mm.unwrap_or(base.face_width_mm),
            centre_distance_mm: self.centre_distance_mm.or(base.centre_distance_mm),
            hub_bore_radius_pinion_mm: self
                .hub_bore_radius_pinion_mm
                .unwrap_or(base.hub_bore_radius_pinion_mm),
            hub_bore_radius_gear_mm: self
                .hub_bore_radius_gear_mm
                .unwrap_or(base.hub_bore_radius_gear_mm),
            tool_tip_radius_coefficient: self
                .tool_tip_radius_coefficient
                .unwrap_or(base.tool_tip_radius_coefficient),
            helix_angle_deg: self.helix_angle_deg.unwrap_or(base.helix_angle_deg),
            helix_hand_pinion: self.helix_hand_pinion.unwrap_or(base.helix_hand_pinion),
        }
    }

    /// The stage's pinion and gear bodies and bearings: `base` (the case's
    /// `[dynamics]`) with the stage's keys.
    pub fn dynamics_section(&self, base: &DynamicsSection) -> DynamicsSection {
        DynamicsSection {
            mass_pinion_kg: self.mass_pinion_kg.unwrap_or(base.mass_pinion_kg),
            mass_gear_kg: self.mass_gear_kg.unwrap_or(base.mass_gear_kg),
            inertia_pinion_kg_m2: self
                .inertia_pinion_kg_m2
                .unwrap_or(base.inertia_pinion_kg_m2),
            inertia_gear_kg_m2: self.inertia_gear_kg_m2.unwrap_or(base.inertia_gear_kg_m2),
            bearing_stiffness_pinion_n_per_m: self
                .bearing_stiffness_pinion_n_per_m
                .unwrap_or(base.bearing_stiffness_pinion_n_per_m),
            bearing_stiffness_gear_n_per_m: self
                .bearing_stiffness_gear_n_per_m
                .unwrap_or(base.bearing_stiffness_gear_n_per_m),
            bearing_damping_pinion_n_s_per_m: self
                .bearing_damping_pinion_n_s_per_m
                .unwrap_or(base.bearing_damping_pinion_n_s_per_m),
            bearing_damping_gear_n_s_per_m: self
                .bearing_damping_gear_n_s_per_m
                .unwrap_or(base.bearing_damping_gear_n_s_per_m),
            mesh_damping_ratio: self.mesh_damping_ratio.unwrap_or(base.mesh_damping_ratio),
            bearing_axial_stiffness_pinion_n_per_m: self
                .bearing_axial_stiffness_pinion_n_per_m
                .or(base.bearing_axial_stiffness_pinion_n_per_m),
            bearing_axial_stiffness_gear_n_per_m: self
                .bearing_axial_stiffness_gear_n_per_m
                .or(base.bearing_axial_stiffness_gear_n_per_m),
            bearing_axial_damping_pinion_n_s_per_m: self
                .bearing_axial_damping_pinion_n_s_per_m
                .or(base.bearing_axial_damping_pinion_n_s_per_m),
            bearing_axial_damping_gear_n_s_per_m: self
                .bearing_axial_damping_gear_n_s_per_m
                .or(base.bearing_axial_damping_gear_n_s_per_m),
            ..base.clone()
        }
    }
}

impl StageSpec {
    /// The stage's slice count: `stage.slices`, else `stiffness.slices` (`base`).
    pub fn slices(&self, base: i64) -> i64 {
        self.slices.unwrap_or(base)
    }

    /// A message about the stage's single-pair case with each key the stage gives named as
    /// the stage's (`gear.module_mm` -> `stage.module_mm`): the key to change is the one
    /// the user wrote; keys the stage takes from `[gear]` or `[dynamics]` keep their names.
    pub fn name_own_keys(&self, message: &str) -> String {
        let Ok(toml::Value::Table(given)) = toml::Value::try_from(self) else {
            return message.to_string();
        };
        let mut out = message.to_string();
        for key in given.keys() {
            for section in ["gear", "dynamics", "stiffness"] {
                out = out.replace(&format!("`{section}.{key}`"), &format!("`stage.{key}`"));
            }
        }
        out
    }
}

/// Problems of the stages as written (each names the stage, 1-based, and the key): the
/// shafts between stages, the stage count, and the single-pair sections a train does not
/// take yet.
pub fn stage_problems(stages: &[StageSpec], single_pair_inputs: &[&str]) -> Vec<String> {
    let mut out = Vec::new();
    if stages.len() > MAX_STAGES {
        out.push(format!(
            "the case has {} [[stage]] tables; a train has at most {MAX_STAGES} stages",
            stages.len()
        ));
    }
    let last = stages.len().saturating_sub(1);
    for (i, s) in stages.iter().enumerate() {
        let n = i + 1;
        if i < last && s.shaft_torsional_stiffness_nm_per_rad.is_none() {
            out.push(format!(
                "stage {n}: `stage.shaft_torsional_stiffness_nm_per_rad` is required: it is the shaft that carries stage {n}'s gear and stage {}'s pinion (without it stage {} is connected to nothing)",
                n + 1,
                n + 1
            ));
        }
        if i == last
            && (s.shaft_torsional_stiffness_nm_per_rad.is_some()
                || s.shaft_torsional_damping_nm_s_per_rad.is_some())
        {
            out.push(format!(
                "stage {n} is the last: its gear drives the load through `dynamics.coupling_stiffness_brake_nm_per_rad`; a `stage.shaft_torsional_*` key there joins it to no further stage: remove it"
            ));
        }
    }
    if !stages.is_empty() && !single_pair_inputs.is_empty() {
        out.push(format!(
            "{} describe the teeth of a single pair; a train of [[stage]] tables does not take them yet: remove them or the [[stage]] tables",
            single_pair_inputs.join(", ")
        ));
    }
    out
}

/// The problem of the `stage` key of `[[fault]]` table `i` (0-based, as the other fault
/// messages count) on a case of `stages` `[[stage]]` tables (0: a single pair): required
/// on a train, in 1..=stages; refused on a single pair (docs/MODEL.md 9.10).
pub(crate) fn fault_stage_problem(i: usize, stage: Option<i64>, stages: usize) -> Option<String> {
    match stage {
        None if stages > 0 => Some(format!(
            "`fault.stage` is required (fault {i}): the case is a gear train of {stages} [[stage]] tables, and each [[fault]] table names the stage whose pair holds its tooth, 1 to {stages}"
        )),
        Some(s) if stages == 0 => Some(format!(
            "`fault.stage` = {s} (fault {i}) is given on a single pair: the case has no [[stage]] tables, so the fault is on the [gear] pair; remove the key"
        )),
        Some(s) if s < 1 || s > stages as i64 => Some(format!(
            "`fault.stage` = {s} (fault {i}) is out of range: the train has stages 1 to {stages}"
        )),
        _ => None,
    }
}

/// The `[[fault]]` tables that put a tooth fault on a helical stage (its own
/// `helix_angle_deg`, or the case's it takes): not built (each face slice would need the
/// fault; docs/MODEL.md 9.10), refused when the case is read, before any budget. A crack
/// of zero depth changes no tooth and passes (as everywhere).
pub(crate) fn helical_stage_fault_problems(
    stages: &[StageSpec],
    gear: &GearSection,
    faults: &[FaultTable],
) -> Vec<String> {
    let mut out = Vec::new();
    for (i, f) in faults.iter().enumerate() {
        let Some(s) = f
            .stage
            .and_then(|s| stages.get(usize::try_from(s - 1).ok()?))
        else {
            continue;
        };
        let helix = s.helix_angle_deg.unwrap_or(gear.helix_angle_deg);
        let zero_crack = f.kind == FaultKind::Crack && f.crack_depth_mm == Some(0.0);
        if helix != 0.0 && !zero_crack {
            out.push(format!(
                "`fault.stage` = {} (fault {i}, {} {} tooth {}) names a helical stage (helix angle {helix} deg): a tooth fault on a helical stage is not built yet (each face slice would need it); give the fault to a spur stage, or `stage.helix_angle_deg` = 0",
                f.stage.unwrap_or(0),
                f.kind.name(),
                f.gear.name(),
                f.tooth
            ));
        }
    }
    out
}
