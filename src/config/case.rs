//! The case file: every input of the model, as the user writes it in TOML.
//!
//! Field names carry their unit (`_mm`, `_hz`, `_nm`, ...). Geometry is given in the
//! millimetres engineers use; everything is converted to SI when the model objects are
//! built (`geometry::GearPair::from_case`, ...). The defaults are the paper's case
//! (Coatings 2022, 12, 1250, Tables 1-2 and section 4) with the readings documented in
//! `docs/MODEL.md`; each default that the paper does not give says so.
//!
//! Masses, rotary inertias and hub bores may be given as the string `"derived"`
//! ([`Derivable`]): the model then computes them from the geometry once, when it is built
//! (`study::Model::resolved_parameters`).

use super::planetary::PlanetarySection;
use serde::{Deserialize, Serialize};

pub use super::derivable::Derivable;
pub use super::gear::{GearSection, HelixHand};
pub use super::lumped::{BodyValues, DynamicsSection};
pub use super::operating::{
    LoadPoint, LoadSpectrumSection, MisalignmentPlane, OperatingSection, SpectrumBin,
    SpeedBoundary, TorqueShaft,
};
pub use super::output::OutputSection;
pub use super::signals::SignalsSection;
pub use super::teeth::{
    Fault, FaultKind, FaultTable, Member, ModificationSection, ReliefShape, TeethSection,
    ToothFault,
};
pub use super::train::StageSpec;

/// A whole case. `Default` is the paper's case.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct Case {
    /// The involute spur pair (paper Table 1).
    pub gear: GearSection,
    /// Elastic constants of pinion and gear.
    pub materials: MaterialsSection,
    /// The nominal operating point and how the speed is held.
    pub operating: OperatingSection,
    /// The lubricant (Xu's friction regression).
    pub lubricant: LubricantSection,
    /// Roughness of the flanks as they wear (paper 4.1).
    pub surface: SurfaceSection,
    /// Lumped parameters of the tribo-dynamic model (paper Table 2).
    pub dynamics: DynamicsSection,
    /// How the mesh stiffness is computed.
    pub stiffness: StiffnessSection,
    /// How the load is shared between pairs in contact.
    pub contact: ContactSection,
    /// The friction coefficient's model.
    pub friction: FrictionSection,
    /// Archard wear and the wear study's blocks.
    pub wear: WearSection,
    /// Integration, steady state and recording of the dynamic model.
    pub numerics: NumericsSection,
    /// Priors of the uncertain parameters for `gearwear calibrate` / `predict`.
    pub calibration: CalibrationSection,
    /// What a sensor records (`gearwear signals`, datasets); left out of a case's
    /// serialisation while it holds the defaults.
    #[serde(skip_serializing_if = "SignalsSection::is_default")]
    pub signals: SignalsSection,
    /// What the commands write of long runs (`config::output`); left out of a case's
    /// serialisation while it holds the defaults.
    #[serde(skip_serializing_if = "OutputSection::is_default")]
    pub output: OutputSection,
    /// The duty cycle (issue 20); absent: the single operating point of `operating`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_spectrum: Option<LoadSpectrumSection>,
    /// Manufacturing errors per tooth (absent: perfect teeth, the paper's).
    #[serde(skip_serializing_if = "TeethSection::is_empty")]
    pub teeth: TeethSection,
    /// Profile modifications of every tooth (absent: true involutes).
    #[serde(skip_serializing_if = "ModificationSection::is_empty")]
    pub modification: ModificationSection,
    /// Tooth faults (`[[fault]]` tables; none by default), resolved when the case is
    /// loaded.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub fault: Vec<ToothFault>,
    /// The stages of a gear train (`[[stage]]` tables; none: the single pair of
    /// `[gear]`), `config::train`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub stage: Vec<StageSpec>,
    /// A planetary set (`[planetary]`, `config::planetary`; absent: none). Only
    /// `gearwear stiffness` takes it so far; every study on the dynamic model refuses it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub planetary: Option<PlanetarySection>,
}

/// `[materials]`: elastic constants of pinion and gear.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct MaterialsSection {
    /// Pinion Young's modulus, GPa (paper: 205 GPa).
    pub youngs_modulus_pinion_gpa: f64,
    /// Pinion Poisson's ratio (paper: 0.3).
    pub poisson_ratio_pinion: f64,
    /// Gear Young's modulus, GPa (paper: 205 GPa).
    pub youngs_modulus_gear_gpa: f64,
    /// Gear Poisson's ratio (paper: 0.3).
    pub poisson_ratio_gear: f64,
}

impl Default for MaterialsSection {
    fn default() -> Self {
        Self {
            youngs_modulus_pinion_gpa: 205.0,
            poisson_ratio_pinion: 0.3,
            youngs_modulus_gear_gpa: 205.0,
            poisson_ratio_gear: 0.3,
        }
    }
}

/// `[lubricant]`: the oil, as Xu's friction regression sees it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LubricantSection {
    /// Inlet absolute viscosity nu_0, cP (mPa s). Not in the paper.
    pub viscosity_cp: f64,
}

impl Default for LubricantSection {
    fn default() -> Self {
        // ISO VG 100 mineral oil near 60 degC; the paper gives none.
        Self { viscosity_cp: 40.0 }
    }
}

/// Composite RMS roughness as a function of the maximum pinion wear depth (paper 4.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SurfaceSection {
    /// Maximum pinion wear depth at the table points, µm (ascending).
    pub roughness_table_wear_um: Vec<f64>,
    /// Composite RMS roughness S at those points, µm; linear in between, constant outside.
    pub roughness_table_rms_um: Vec<f64>,
}

impl Default for SurfaceSection {
    fn default() -> Self {
        // The paper's 2.1 / 1.9 / 1.5 um read as 0.21 / 0.19 / 0.15 um with R in metres
        // (docs/MODEL.md, friction): the reading under which the paper's "slight" decrease holds.
        Self {
            roughness_table_wear_um: vec![0.1, 0.5, 1.0],
            roughness_table_rms_um: vec![0.21, 0.19, 0.15],
        }
    }
}

/// `[stiffness]`: how the mesh stiffness is computed (potential energy method,
/// docs/MODEL.md section 2).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct StiffnessSection {
    /// Include the Sainsot et al. (2004) fillet-foundation compliance.
    pub fillet_foundation: bool,
    /// Where Sainsot's root half angle theta_f is taken.
    pub fillet_root_angle: FilletRootAngle,
    /// Use Sainsot's fit outside its published range (warning instead of error).
    pub allow_fillet_extrapolation: bool,
    /// Samples of the mesh-stiffness table over one mesh period.
    pub table_points_per_mesh_period: i64,
    /// Slices N across the face of a helical pair (docs/MODEL.md section 11); unused by a
    /// spur pair.
    #[serde(skip_serializing_if = "is_default_slices")]
    pub slices: i64,
}

/// Default slice count of a helical pair: the peak-to-peak mesh stiffness within 1 % of
/// its N -> infinity limit needs N of about 300 (docs/MODEL.md section 11).
pub const DEFAULT_SLICES: i64 = 400;

/// The default slice count: left out of a case's serialisation (spur cases unchanged).
fn is_default_slices(n: &i64) -> bool {
    *n == DEFAULT_SLICES
}

/// Where the fillet-foundation formula's root half angle theta_f (and its root
/// thickness S_f = 2 r_f theta_f) is taken (docs/MODEL.md, section 2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FilletRootAngle {
    /// Where the root fillet meets the root circle: the tooth's whole footing on the
    /// gear body (Sainsot, Velex & Duverger 2004; Chen & Shao 2011).
    FilletJunction,
    /// Where the flank's extension (the involute, or its radial continuation below the
    /// base circle) meets the root circle.
    FlankExtension,
}

impl Default for StiffnessSection {
    fn default() -> Self {
        Self {
            fillet_foundation: true,
            fillet_root_angle: FilletRootAngle::FilletJunction,
            allow_fillet_extrapolation: false,
            table_points_per_mesh_period: 400,
            slices: DEFAULT_SLICES,
        }
    }
}

/// How the mesh force is split between two pairs in contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LoadSharingModel {
    /// Pedrero's law where it is defined (identical, perfect teeth of contact ratio
    /// between 1 and 2: the paper's case), otherwise by pair compression
    /// ([`LoadSharingModel::resolve`]).
    Auto,
    /// Paper eq. (7): Pedrero's piecewise-linear 1/3 - 2/3 law.
    Pedrero,
    /// Each pair's stiffness times its own deflection (gap from wear included).
    Stiffness,
}

impl LoadSharingModel {
    /// The law a mesh uses: `Auto` becomes Pedrero's (paper eq. 7) for identical,
    /// perfect teeth with 1 < contact ratio < 2, which is where the law is defined, and
    /// sharing by pair compression otherwise: for teeth that differ, Pedrero's law has no
    /// place for one pair's gap or softer tooth. An explicit choice stays as it is (the
    /// model refuses Pedrero's law where it is not defined).
    pub fn resolve(self, teeth_differ: bool, contact_ratio: f64) -> Self {
        match self {
            Self::Auto if teeth_differ || !(1.0..2.0).contains(&contact_ratio) => Self::Stiffness,
            Self::Auto => Self::Pedrero,
            law => law,
        }
    }
}

/// Where the teeth of a pair may touch (docs/MODEL.md, section 4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactPathModel {
    /// On the path of contact and, under load, by the tip corners before its start and
    /// after its end (corner contact, `geometry::corner`): the load passes gradually
    /// between pairs.
    Extended,
    /// Only on the nominal path of contact: perfect involutes meeting nowhere else (the
    /// paper's model).
    Nominal,
}

impl ContactPathModel {
    /// The model of a case that does not set `contact.path`: corner contact (issue 32;
    /// the paper's own model stays one key away).
    pub const DEFAULT: Self = Self::Extended;

    /// Corners touch beyond the path.
    pub fn is_extended(self) -> bool {
        self == Self::Extended
    }
}

/// `[contact]`: how the load is shared between pairs in contact.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ContactSection {
    /// The law the mesh force is split by between two pairs in contact.
    pub load_sharing: LoadSharingModel,
    /// Where the teeth of a pair may touch: the nominal path only, or beyond it by
    /// the tip corners.
    pub path: ContactPathModel,
}

impl Default for ContactSection {
    fn default() -> Self {
        Self {
            load_sharing: LoadSharingModel::Auto,
            path: ContactPathModel::DEFAULT,
        }
    }
}

/// The friction coefficient's model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FrictionModel {
    /// Xu, Kahraman, Anderson & Maddock (2007), paper eq. (8-9).
    Xu2007,
    /// A constant coefficient, `friction.constant_coefficient`.
    Constant,
    /// No friction.
    None,
}

/// Unit in which the radius of curvature enters Xu's regression (docs/MODEL.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LengthUnit {
    /// Metres (Xu et al.'s).
    M,
    /// Millimetres.
    Mm,
}

/// `[friction]`: the friction coefficient along the path of contact.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FrictionSection {
    /// The friction coefficient's model (paper eq. 8-9: Xu et al. 2007).
    pub model: FrictionModel,
    /// Used by `model = "constant"`.
    pub constant_coefficient: f64,
    /// Unit of the radius of curvature in Xu's regression (docs/MODEL.md).
    pub xu_radius_unit: LengthUnit,
    /// Sliding speed over which the friction direction turns (tanh smoothing), m/s.
    pub direction_smoothing_m_per_s: f64,
}

impl Default for FrictionSection {
    fn default() -> Self {
        Self {
            model: FrictionModel::Xu2007,
            constant_coefficient: 0.05,
            xu_radius_unit: LengthUnit::M,
            direction_smoothing_m_per_s: 0.01,
        }
    }
}

/// `[wear]`: Archard wear and the blocks of the wear study (paper eq. 17).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WearSection {
    /// Archard coefficient. The paper's 2.5e-12 read as cm^2/N (docs/MODEL.md).
    pub coefficient_m2_per_n: f64,
    /// Cycles m the per-cycle wear is held for, cycles (paper eq. 17).
    pub block_cycles: f64,
    /// Largest wear depth one block may add anywhere, um (paper's epsilon^m).
    pub threshold_um: f64,
    /// Pinion load cycles (revolutions) to simulate, cycles.
    pub total_cycles: f64,
    /// Points on each active profile.
    pub points_per_profile: i64,
    /// Which flank geometry the contact sees as wear proceeds (absent: the involute's,
    /// the paper's model).
    #[serde(skip_serializing_if = "WornGeometry::is_involute")]
    pub worn_geometry: WornGeometry,
}

/// The geometry of a worn flank the stiffness, the Hertz contact and the load sharing see
/// (docs/MODEL.md, section 9, "Severe wear").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum WornGeometry {
    /// The involute's (the paper's): wear only opens gaps.
    #[default]
    Involute,
    /// The worn profile's: thinner teeth, the worn flank's curvature, loads by compression.
    Worn,
}

impl WornGeometry {
    /// Whether this is the paper's involute geometry (the default, left out of a case's
    /// serialisation).
    pub(crate) fn is_involute(&self) -> bool {
        *self == WornGeometry::Involute
    }
}

impl Default for WearSection {
    fn default() -> Self {
        Self {
            coefficient_m2_per_n: 2.5e-16,
            block_cycles: 1e4,
            threshold_um: 0.5,
            total_cycles: 4e4,
            points_per_profile: 101,
            worn_geometry: WornGeometry::Involute,
        }
    }
}

/// `[numerics]`: integration, steady state and recording of the dynamic model.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct NumericsSection {
    /// Grid nodes per mesh period, aligned with the mesh events: the longest step and
    /// the fewest recorded samples per period.
    pub steps_per_mesh_period: i64,
    /// Local error per integration step relative to the state's scales.
    pub integration_tolerance: f64,
    /// Give up on steady state after this many mesh periods.
    pub max_mesh_periods: i64,
    /// Steady state: relative change of the state over one mesh period below this.
    pub steady_state_tolerance: f64,
    /// Mesh periods recorded once steady (signals, spectra).
    pub evaluated_mesh_periods: i64,
}

impl Default for NumericsSection {
    fn default() -> Self {
        Self {
            steps_per_mesh_period: 200,
            integration_tolerance: 1e-5,
            max_mesh_periods: 2000,
            steady_state_tolerance: 1e-6,
            evaluated_mesh_periods: 4,
        }
    }
}

/// Whether a key changes teeth one by one (`[teeth]`, `[modification]`, `[[fault]]`) or
/// their geometry as they wear (`wear.worn_geometry`): a key that can make the mesh
/// tooth-resolved.
pub(crate) fn is_per_tooth_key(key: &str) -> bool {
    ["teeth.", "modification.", "fault."]
        .iter()
        .any(|p| key.starts_with(p))
        || key == "wear.worn_geometry"
}

impl Case {
    /// Whether the case gives a per-tooth input (`[teeth]`, `[modification]`, `[[fault]]`,
    /// `wear.worn_geometry` = "worn") that changes a tooth. Inputs that leave every tooth
    /// perfect (zero errors and run-outs, zero-depth cracks, zero reliefs and profile
    /// deviations) do not count: such a case is the identical-teeth case, judged by the
    /// inputs' effect as `study::teeth` judges the built teeth.
    pub fn has_per_tooth_inputs(&self) -> bool {
        self.teeth.changes_teeth()
            || self.modification.changes_teeth()
            || self.fault.iter().any(ToothFault::changes_tooth)
            || self.wear.worn_geometry == WornGeometry::Worn
    }

    /// Cases compared with each other (the rows of a sweep, the conditions of a dataset)
    /// share one load-sharing law: where any of them gives per-tooth inputs
    /// (`any_per_tooth`), "auto" is made "stiffness" in each, so that a row of identical
    /// teeth is not solved under Pedrero's law while its neighbours with a tiny error are
    /// solved by compression (`LoadSharingModel::resolve`). The case says so itself, so a
    /// row rerun alone gives the same numbers.
    pub(crate) fn share_one_law(&mut self, any_per_tooth: bool) {
        if any_per_tooth && self.contact.load_sharing == LoadSharingModel::Auto {
            self.contact.load_sharing = LoadSharingModel::Stiffness;
        }
    }

    /// The case's load point: `[operating]`'s input speed, load torque and its shaft.
    pub fn load_point(&self) -> LoadPoint {
        let o = &self.operating;
        LoadPoint {
            input_speed_hz: o.input_speed_hz,
            load_torque_nm: o.load_torque_nm,
            load_torque_shaft: o.load_torque_shaft,
        }
    }

    /// Put the case at load point `p`: `[operating]`'s input speed, load torque and its
    /// shaft set to `p`'s. Everything else stays (how the speed is held, a load spectrum;
    /// [`Case::at_bin`] drops the spectrum). The one place a case's operating point is
    /// changed; the model derives its speeds, torques and mesh frequency from it
    /// (`dynamics::params::OperatingPoint`).
    pub fn set_load_point(&mut self, p: LoadPoint) {
        let o = &mut self.operating;
        o.input_speed_hz = p.input_speed_hz;
        o.load_torque_nm = p.load_torque_nm;
        o.load_torque_shaft = p.load_torque_shaft;
    }

    /// The case at bin `i` of its spectrum: the operating point set to the bin's torque
    /// (on the spectrum's shaft) and speed, without the spectrum. Everything else is the
    /// case's, so a bin equal to the operating point gives the case itself.
    pub fn at_bin(&self, i: usize) -> Case {
        let mut c = self.clone();
        if let Some(s) = self.load_spectrum.as_ref() {
            c.set_load_point(s.load_point(i, self.operating.load_torque_shaft));
        }
        c.load_spectrum = None;
        c
    }

    /// The case of every bin, or None without a spectrum.
    pub fn bin_cases(&self) -> Option<Vec<Case>> {
        let s = self.load_spectrum.as_ref()?;
        Some((0..s.bins.len()).map(|i| self.at_bin(i)).collect())
    }

    /// A starting point for a pair of one's own (`gearwear config --new-pair`): the
    /// built-in case with every value the geometry can give set to `"derived"` (hub bores,
    /// masses and inertias of pinion and gear), so that they follow the `[gear]` section
    /// the user edits.
    pub fn new_pair_template() -> Self {
        let mut c = Case::default();
        c.gear.hub_bore_radius_pinion_mm = Derivable::Derived;
        c.gear.hub_bore_radius_gear_mm = Derivable::Derived;
        c.dynamics.mass_pinion_kg = Derivable::Derived;
        c.dynamics.mass_gear_kg = Derivable::Derived;
        c.dynamics.inertia_pinion_kg_m2 = Derivable::Derived;
        c.dynamics.inertia_gear_kg_m2 = Derivable::Derived;
        c
    }
}

/// Priors of the uncertain parameters for `gearwear calibrate` / `predict` (issue 12).
/// A parameter whose bounds are equal is held fixed. Absent optional bounds are derived
/// from the case (see `prognostics::prior`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct CalibrationSection {
    /// Lower bound of the log-uniform prior of k, m^2/N; absent: the case's k / 100.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wear_coefficient_min_m2_per_n: Option<f64>,
    /// Upper bound of the log-uniform prior of k, m^2/N; absent: the case's k x 100.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wear_coefficient_max_m2_per_n: Option<f64>,
    /// Lower bound of the uniform prior of the factor on the roughness table (1 and 1:
    /// fixed).
    pub roughness_scale_min: f64,
    /// Upper bound of the uniform prior of the factor on the roughness table.
    pub roughness_scale_max: f64,
    /// Lower bound of the uniform prior of the load torque, N m; absent: the case's torque
    /// (fixed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_torque_min_nm: Option<f64>,
    /// Upper bound of the uniform prior of the load torque, N m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_torque_max_nm: Option<f64>,
    /// Cells per parameter of the exact grid posterior (one or two parameters).
    pub grid_points: i64,
    /// Reference runs per uncertain parameter other than k (surrogate nodes).
    pub surrogate_nodes: i64,
}

impl Default for CalibrationSection {
    fn default() -> Self {
        Self {
            wear_coefficient_min_m2_per_n: None,
            wear_coefficient_max_m2_per_n: None,
            roughness_scale_min: 1.0,
            roughness_scale_max: 1.0,
            load_torque_min_nm: None,
            load_torque_max_nm: None,
            grid_points: 400,
            surrogate_nodes: 5,
        }
    }
}
