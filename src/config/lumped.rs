//! `[dynamics]`: the lumped parameters of the tribo-dynamic model (paper Table 2, units
//! corrected as docs/MODEL.md says), and their resolution: masses and inertias of pinion
//! and gear may be left to the geometry (`"derived"`), which estimates them once, when the
//! model is built.

use super::derivable::Derivable;
use serde::{Deserialize, Serialize};

/// Lumped parameters of paper Table 2 (units corrected as docs/MODEL.md says).
///
/// `P` is the type of the four values the geometry can give (masses and inertias of
/// pinion and gear): [`Derivable`] in a case, `f64` once resolved
/// ([`DynamicsSection::resolve`]). Motor and brake inertias, which the geometry cannot
/// give, are always numbers.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    default,
    bound(
        serialize = "P: Serialize",
        deserialize = "P: Deserialize<'de>, DynamicsSection<P>: Default"
    )
)]
pub struct DynamicsSection<P = Derivable> {
    /// Pinion mass m_p, kg (paper Table 2: 0.7); `"derived"`: the blank's.
    pub mass_pinion_kg: P,
    /// Gear mass m_g, kg (paper: 1.822); `"derived"`: the blank's.
    pub mass_gear_kg: P,
    /// Pinion polar inertia J_p, kg m^2 (paper: 2.331e-4); `"derived"`: the blank's.
    pub inertia_pinion_kg_m2: P,
    /// Gear polar inertia J_g, kg m^2 (paper: 1.392e-3); `"derived"`: the blank's.
    pub inertia_gear_kg_m2: P,
    /// Density of the blanks for the derived values, kg/m^3 (steel: 7850).
    pub blank_density_kg_per_m3: f64,
    /// Motor inertia J_m, kg m^2 (paper: 2.1e-3).
    pub inertia_motor_kg_m2: f64,
    /// Brake inertia J_b, kg m^2 (paper: 1.05e-2).
    pub inertia_brake_kg_m2: f64,
    /// Pinion bearing stiffness in x and y, N/m (paper: 5e8).
    pub bearing_stiffness_pinion_n_per_m: f64,
    /// Gear bearing stiffness in x and y, N/m (paper: 5e8).
    pub bearing_stiffness_gear_n_per_m: f64,
    /// Pinion bearing damping in x and y, N s/m (paper: 4e5).
    pub bearing_damping_pinion_n_s_per_m: f64,
    /// Gear bearing damping in x and y, N s/m (paper: 4e5).
    pub bearing_damping_gear_n_s_per_m: f64,
    /// Motor-pinion coupling torsional stiffness k_mp, N m/rad (paper: 4e7).
    pub coupling_stiffness_motor_nm_per_rad: f64,
    /// Gear-brake coupling torsional stiffness k_bg, N m/rad (paper: 4e7).
    pub coupling_stiffness_brake_nm_per_rad: f64,
    /// Motor-pinion coupling torsional damping c_mp, N m s/rad (paper: 3e4).
    pub coupling_damping_motor_nm_s_per_rad: f64,
    /// Gear-brake coupling torsional damping c_bg, N m s/rad (paper: 3e4).
    pub coupling_damping_brake_nm_s_per_rad: f64,
    /// Mesh damping ratio zeta: c_m = 2 zeta sqrt(k_mean m_e). Not in the paper.
    pub mesh_damping_ratio: f64,
    /// Pinion axial bearing stiffness, N/m (a helical pair only; absent: rigid, no axial
    /// degree of freedom: the planar model, docs/MODEL.md 11.6).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_axial_stiffness_pinion_n_per_m: Option<f64>,
    /// Gear axial bearing stiffness, N/m (as the pinion's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_axial_stiffness_gear_n_per_m: Option<f64>,
    /// Pinion axial bearing damping, N s/m (absent: the pinion's radial bearing damping).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_axial_damping_pinion_n_s_per_m: Option<f64>,
    /// Gear axial bearing damping, N s/m (absent: the gear's radial bearing damping).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_axial_damping_gear_n_s_per_m: Option<f64>,
    /// Pinion tilting bearing stiffness, N m/rad, about each axis normal to the shaft (a
    /// helical pair only; absent: rigid, no tilting degrees of freedom, docs/MODEL.md 11.8).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_tilt_stiffness_pinion_nm_per_rad: Option<f64>,
    /// Gear tilting bearing stiffness, N m/rad (as the pinion's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_tilt_stiffness_gear_nm_per_rad: Option<f64>,
    /// Pinion tilting bearing damping, N m s/rad (absent: none).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_tilt_damping_pinion_nm_s_per_rad: Option<f64>,
    /// Gear tilting bearing damping, N m s/rad (absent: none).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_tilt_damping_gear_nm_s_per_rad: Option<f64>,
}

/// Masses (kg) and polar inertias (kg m^2) of pinion and gear, as numbers: what the
/// geometry estimates, or what a case resolves to.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BodyValues {
    /// Pinion mass, kg.
    pub mass_pinion_kg: f64,
    /// Gear mass, kg.
    pub mass_gear_kg: f64,
    /// Pinion polar inertia, kg m^2.
    pub inertia_pinion_kg_m2: f64,
    /// Gear polar inertia, kg m^2.
    pub inertia_gear_kg_m2: f64,
}

impl BodyValues {
    /// (key, value) pairs in schema order, for messages.
    pub fn named(&self) -> [(&'static str, f64); 4] {
        [
            ("dynamics.mass_pinion_kg", self.mass_pinion_kg),
            ("dynamics.mass_gear_kg", self.mass_gear_kg),
            ("dynamics.inertia_pinion_kg_m2", self.inertia_pinion_kg_m2),
            ("dynamics.inertia_gear_kg_m2", self.inertia_gear_kg_m2),
        ]
    }
}

impl DynamicsSection {
    /// The given masses and inertias (`None` where derived), in [`BodyValues::named`] order.
    pub(crate) fn given_body_values(&self) -> [Option<f64>; 4] {
        [
            self.mass_pinion_kg.given(),
            self.mass_gear_kg.given(),
            self.inertia_pinion_kg_m2.given(),
            self.inertia_gear_kg_m2.given(),
        ]
    }

    /// The section with every `"derived"` value replaced by the geometry's `estimate`.
    pub fn resolve(&self, estimate: &BodyValues) -> DynamicsSection<f64> {
        DynamicsSection {
            mass_pinion_kg: self.mass_pinion_kg.or_derived(estimate.mass_pinion_kg),
            mass_gear_kg: self.mass_gear_kg.or_derived(estimate.mass_gear_kg),
            inertia_pinion_kg_m2: self
                .inertia_pinion_kg_m2
                .or_derived(estimate.inertia_pinion_kg_m2),
            inertia_gear_kg_m2: self
                .inertia_gear_kg_m2
                .or_derived(estimate.inertia_gear_kg_m2),
            blank_density_kg_per_m3: self.blank_density_kg_per_m3,
            inertia_motor_kg_m2: self.inertia_motor_kg_m2,
            inertia_brake_kg_m2: self.inertia_brake_kg_m2,
            bearing_stiffness_pinion_n_per_m: self.bearing_stiffness_pinion_n_per_m,
            bearing_stiffness_gear_n_per_m: self.bearing_stiffness_gear_n_per_m,
            bearing_damping_pinion_n_s_per_m: self.bearing_damping_pinion_n_s_per_m,
            bearing_damping_gear_n_s_per_m: self.bearing_damping_gear_n_s_per_m,
            coupling_stiffness_motor_nm_per_rad: self.coupling_stiffness_motor_nm_per_rad,
            coupling_stiffness_brake_nm_per_rad: self.coupling_stiffness_brake_nm_per_rad,
            coupling_damping_motor_nm_s_per_rad: self.coupling_damping_motor_nm_s_per_rad,
            coupling_damping_brake_nm_s_per_rad: self.coupling_damping_brake_nm_s_per_rad,
            mesh_damping_ratio: self.mesh_damping_ratio,
            bearing_axial_stiffness_pinion_n_per_m: self.bearing_axial_stiffness_pinion_n_per_m,
            bearing_axial_stiffness_gear_n_per_m: self.bearing_axial_stiffness_gear_n_per_m,
            bearing_axial_damping_pinion_n_s_per_m: self.bearing_axial_damping_pinion_n_s_per_m,
            bearing_axial_damping_gear_n_s_per_m: self.bearing_axial_damping_gear_n_s_per_m,
            bearing_tilt_stiffness_pinion_nm_per_rad: self.bearing_tilt_stiffness_pinion_nm_per_rad,
            bearing_tilt_stiffness_gear_nm_per_rad: self.bearing_tilt_stiffness_gear_nm_per_rad,
            bearing_tilt_damping_pinion_nm_s_per_rad: self.bearing_tilt_damping_pinion_nm_s_per_rad,
            bearing_tilt_damping_gear_nm_s_per_rad: self.bearing_tilt_damping_gear_nm_s_per_rad,
        }
    }
}

impl<P> DynamicsSection<P> {
    /// The axial bearings of pinion and gear (docs/MODEL.md 11.6): each body's stiffness
    /// (N/m) and damping (N s/m) where its `bearing_axial_stiffness_*` key is given (the
    /// damping's absent value is the body's radial bearing damping), None where the
    /// bearing is rigid.
    pub fn axial_bearings(&self) -> [Option<(f64, f64)>; 2] {
        [
            self.bearing_axial_stiffness_pinion_n_per_m.map(|k| {
                let c = self.bearing_axial_damping_pinion_n_s_per_m;
                (k, c.unwrap_or(self.bearing_damping_pinion_n_s_per_m))
            }),
            self.bearing_axial_stiffness_gear_n_per_m.map(|k| {
                let c = self.bearing_axial_damping_gear_n_s_per_m;
                (k, c.unwrap_or(self.bearing_damping_gear_n_s_per_m))
            }),
        ]
    }
}

impl<P> DynamicsSection<P> {
    /// The tilting bearings of pinion and gear (docs/MODEL.md 11.8): each body's stiffness
    /// (N m/rad) and damping (N m s/rad, absent: 0) about each of the two axes normal to
    /// its shaft where its `bearing_tilt_stiffness_*` key is given; None where the body's
    /// tilting is held rigidly.
    pub fn tilt_bearings(&self) -> [Option<(f64, f64)>; 2] {
        [
            self.bearing_tilt_stiffness_pinion_nm_per_rad.map(|k| {
                (
                    k,
                    self.bearing_tilt_damping_pinion_nm_s_per_rad.unwrap_or(0.0),
                )
            }),
            self.bearing_tilt_stiffness_gear_nm_per_rad.map(|k| {
                (
                    k,
                    self.bearing_tilt_damping_gear_nm_s_per_rad.unwrap_or(0.0),
                )
            }),
        ]
    }

    /// The tilting keys the case gives, (key, value), in schema order.
    pub fn tilt_keys(&self) -> Vec<(&'static str, f64)> {
        [
            (
                "dynamics.bearing_tilt_stiffness_pinion_nm_per_rad",
                self.bearing_tilt_stiffness_pinion_nm_per_rad,
            ),
            (
                "dynamics.bearing_tilt_stiffness_gear_nm_per_rad",
                self.bearing_tilt_stiffness_gear_nm_per_rad,
            ),
            (
                "dynamics.bearing_tilt_damping_pinion_nm_s_per_rad",
                self.bearing_tilt_damping_pinion_nm_s_per_rad,
            ),
            (
                "dynamics.bearing_tilt_damping_gear_nm_s_per_rad",
                self.bearing_tilt_damping_gear_nm_s_per_rad,
            ),
        ]
        .into_iter()
        .filter_map(|(k, v)| v.map(|v| (k, v)))
        .collect()
    }
}

impl DynamicsSection<f64> {
    /// The four values the geometry could give.
    pub(crate) fn body_values(&self) -> BodyValues {
        BodyValues {
            mass_pinion_kg: self.mass_pinion_kg,
            mass_gear_kg: self.mass_gear_kg,
            inertia_pinion_kg_m2: self.inertia_pinion_kg_m2,
            inertia_gear_kg_m2: self.inertia_gear_kg_m2,
        }
    }
}

impl Default for DynamicsSection {
    fn default() -> Self {
        Self {
            mass_pinion_kg: Derivable::Given(0.7),
            mass_gear_kg: Derivable::Given(1.822),
            inertia_pinion_kg_m2: Derivable::Given(2.331e-4),
            inertia_gear_kg_m2: Derivable::Given(1.392e-3),
            // Structural steel.
            blank_density_kg_per_m3: 7850.0,
            inertia_motor_kg_m2: 2.1e-3,
            inertia_brake_kg_m2: 1.05e-2,
            bearing_stiffness_pinion_n_per_m: 5e8,
            bearing_stiffness_gear_n_per_m: 5e8,
            bearing_damping_pinion_n_s_per_m: 4e5,
            bearing_damping_gear_n_s_per_m: 4e5,
            coupling_stiffness_motor_nm_per_rad: 4e7,
            coupling_stiffness_brake_nm_per_rad: 4e7,
            coupling_damping_motor_nm_s_per_rad: 3e4,
            coupling_damping_brake_nm_s_per_rad: 3e4,
            mesh_damping_ratio: 0.05,
            bearing_axial_stiffness_pinion_n_per_m: None,
            bearing_axial_stiffness_gear_n_per_m: None,
            bearing_axial_damping_pinion_n_s_per_m: None,
            bearing_axial_damping_gear_n_s_per_m: None,
            bearing_tilt_stiffness_pinion_nm_per_rad: None,
            bearing_tilt_stiffness_gear_nm_per_rad: None,
            bearing_tilt_damping_pinion_nm_s_per_rad: None,
            bearing_tilt_damping_gear_nm_s_per_rad: None,
        }
    }
}
