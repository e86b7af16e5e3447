//! `[planetary]`: a simple spur planetary set (sun, N planets on a carrier, ring), and
//! `[planetary.lumped]`, a set given by its lumped parameters (Lin & Parker 1999) so that
//! published lumped models can be rebuilt (docs/MODEL.md section 12).

use super::derivable::Derivable;
pub use super::planetary_fault::{FaultyGear, PlanetaryFault};
use serde::{Deserialize, Serialize};

/// A member of the set that can be an input, an output or fixed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Member {
    /// The sun gear (central external gear).
    Sun,
    /// The carrier (the arm that holds the planets' pins).
    Carrier,
    /// The ring gear (central internal gear).
    Ring,
}

impl Member {
    /// The case file's word for the member.
    pub fn name(self) -> &'static str {
        match self {
            Member::Sun => "sun",
            Member::Carrier => "carrier",
            Member::Ring => "ring",
        }
    }
}

/// `[planetary]`: the set's teeth, tooth form and power flow.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PlanetarySection {
    /// Number of planets N (1..=32).
    pub planets: i64,
    /// Planet positions on the carrier, deg, increasing within one revolution, the first
    /// at 0; absent: equally spaced (360 n / N).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub planet_angles_deg: Option<Vec<f64>>,
    /// Sun teeth z_s.
    pub teeth_sun: i64,
    /// Planet teeth z_p (all planets alike).
    pub teeth_planet: i64,
    /// Ring teeth z_r (counted positive).
    pub teeth_ring: i64,
    /// Module m, mm.
    pub module_mm: f64,
    /// Reference pressure angle alpha, deg.
    pub pressure_angle_deg: f64,
    /// Addendum coefficient h_a*, in modules.
    pub addendum_coefficient: f64,
    /// Addendum coefficient of the ring h_a2*, in modules. Shorter than the external
    /// gears' by default (0.8): a full-depth ring tip reaches below the involute that a
    /// rack generates on the planet (a rack's tip just reaches that point, and the ring's
    /// concave flank reaches deeper), which the geometry refuses as tip interference.
    pub addendum_coefficient_ring: f64,
    /// Dedendum coefficient h_f*, in modules.
    pub dedendum_coefficient: f64,
    /// Rack-cutter tip radius, in modules (the external gears' lowest involute point).
    pub tool_tip_radius_coefficient: f64,
    /// Face width b, mm.
    pub face_width_mm: f64,
    /// Profile shift coefficient of the sun x_s.
    pub profile_shift_sun: f64,
    /// Profile shift coefficient of the planets x_p.
    pub profile_shift_planet: f64,
    /// Profile shift coefficient of the ring x_r, ISO 21771's sign: positive thickens the
    /// ring's tooth at its reference circle and moves its tip circle inwards.
    pub profile_shift_ring: f64,
    /// The member the power comes in on.
    pub input: Member,
    /// The member the power leaves by.
    pub output: Member,
    /// The member held fixed.
    pub fixed: Member,
    /// Position error of each planet's pin on the carrier along the planet's tangential
    /// coordinate eta (positive in the sense the planet angles are counted), um, one value
    /// per planet; absent: none (docs/MODEL.md 12.8).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub planet_tangential_error_um: Option<Vec<f64>>,
    /// Position error of each planet's pin on the carrier along the planet's radial
    /// coordinate zeta (positive outwards, away from the sun), um, one value per planet;
    /// absent: none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub planet_radial_error_um: Option<Vec<f64>>,
    /// A floating sun: its lateral bearing stiffness is zero (the sun's x and y are held by
    /// its meshes alone), whatever `[planetary.lumped]` gives; false: the lumped section's.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub floating_sun: bool,
    /// The set's lumped parameters (masses, inertias, supports), each key optional: an
    /// absent table or key is derived from the geometry (docs/MODEL.md 12.4).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lumped: Option<LumpedPlanetarySection<Derivable>>,
    /// A tooth fault on one member (`[[planetary.fault]]`, at most one table; absent:
    /// none, and a set without one serialises as before; docs/MODEL.md 12.13).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub fault: Vec<PlanetaryFault>,
}

impl Default for PlanetarySection {
    /// A four-planet standard set 24 / 30 / 84, module 2 mm: (z_s + z_r) / 4 = 27, and
    /// z_r = z_s + 2 z_p; sun in, carrier out, ring fixed (ratio 1 + 84/24 = 4.5).
    fn default() -> Self {
        Self {
            planets: 4,
            planet_angles_deg: None,
            teeth_sun: 24,
            teeth_planet: 30,
            teeth_ring: 84,
            module_mm: 2.0,
            pressure_angle_deg: 20.0,
            addendum_coefficient: 1.0,
            addendum_coefficient_ring: 0.8,
            dedendum_coefficient: 1.25,
            tool_tip_radius_coefficient: 0.38,
            face_width_mm: 20.0,
            profile_shift_sun: 0.0,
            profile_shift_planet: 0.0,
            profile_shift_ring: 0.0,
            input: Member::Sun,
            output: Member::Carrier,
            fixed: Member::Ring,
            planet_tangential_error_um: None,
            planet_radial_error_um: None,
            floating_sun: false,
            lumped: None,
            fault: Vec::new(),
        }
    }
}

/// `[planetary.lumped]`: the lumped parameters of Lin & Parker's (1999) model.
/// Inertias are given as such; the model divides them by the radius squared.
///
/// `P` is the type of every value: [`Derivable`] in a case, where an absent key or
/// `"derived"` is computed from the set's geometry and `[dynamics]` when the model is
/// built (`study::planetary_lumped`, docs/MODEL.md 12.4); `f64` once resolved (and in
/// a published table given in full).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    default,
    bound(
        serialize = "P: Serialize",
        deserialize = "P: Deserialize<'de>, LumpedPlanetarySection<P>: Default"
    )
)]
pub struct LumpedPlanetarySection<P = f64> {
    /// Sun mass, kg.
    pub mass_sun_kg: P,
    /// Planet mass (each), kg.
    pub mass_planet_kg: P,
    /// Ring mass, kg.
    pub mass_ring_kg: P,
    /// Carrier mass, kg.
    pub mass_carrier_kg: P,
    /// Sun polar moment of inertia, kg m^2.
    pub inertia_sun_kg_m2: P,
    /// Planet polar moment of inertia (each), kg m^2.
    pub inertia_planet_kg_m2: P,
    /// Ring polar moment of inertia, kg m^2.
    pub inertia_ring_kg_m2: P,
    /// Carrier polar moment of inertia, kg m^2.
    pub inertia_carrier_kg_m2: P,
    /// Sun base radius, mm.
    pub base_radius_sun_mm: P,
    /// Planet base radius, mm.
    pub base_radius_planet_mm: P,
    /// Ring base radius, mm.
    pub base_radius_ring_mm: P,
    /// Carrier radius (sun centre to planet pin), mm.
    pub carrier_radius_mm: P,
    /// Mean sun-planet mesh stiffness, N/m.
    pub mesh_stiffness_sun_planet_n_per_m: P,
    /// Mean ring-planet mesh stiffness, N/m.
    pub mesh_stiffness_ring_planet_n_per_m: P,
    /// Sun bearing stiffness (each lateral direction), N/m.
    pub bearing_stiffness_sun_n_per_m: P,
    /// Planet bearing stiffness (radial and tangential), N/m.
    pub bearing_stiffness_planet_n_per_m: P,
    /// Ring support stiffness (each lateral direction), N/m.
    pub bearing_stiffness_ring_n_per_m: P,
    /// Carrier bearing stiffness (each lateral direction), N/m.
    pub bearing_stiffness_carrier_n_per_m: P,
    /// Sun torsional support stiffness, N m/rad.
    pub torsional_stiffness_sun_nm_per_rad: P,
    /// Ring torsional support stiffness, N m/rad.
    pub torsional_stiffness_ring_nm_per_rad: P,
    /// Carrier torsional support stiffness, N m/rad.
    pub torsional_stiffness_carrier_nm_per_rad: P,
    /// Operating pressure angle of both meshes, deg.
    pub pressure_angle_deg: P,
}

impl Default for LumpedPlanetarySection<Derivable> {
    /// Every key derived.
    fn default() -> Self {
        use Derivable::Derived;
        Self {
            mass_sun_kg: Derived,
            mass_planet_kg: Derived,
            mass_ring_kg: Derived,
            mass_carrier_kg: Derived,
            inertia_sun_kg_m2: Derived,
            inertia_planet_kg_m2: Derived,
            inertia_ring_kg_m2: Derived,
            inertia_carrier_kg_m2: Derived,
            base_radius_sun_mm: Derived,
            base_radius_planet_mm: Derived,
            base_radius_ring_mm: Derived,
            carrier_radius_mm: Derived,
            mesh_stiffness_sun_planet_n_per_m: Derived,
            mesh_stiffness_ring_planet_n_per_m: Derived,
            bearing_stiffness_sun_n_per_m: Derived,
            bearing_stiffness_planet_n_per_m: Derived,
            bearing_stiffness_ring_n_per_m: Derived,
            bearing_stiffness_carrier_n_per_m: Derived,
            torsional_stiffness_sun_nm_per_rad: Derived,
            torsional_stiffness_ring_nm_per_rad: Derived,
            torsional_stiffness_carrier_nm_per_rad: Derived,
            pressure_angle_deg: Derived,
        }
    }
}

impl From<LumpedPlanetarySection<f64>> for LumpedPlanetarySection<Derivable> {
    /// A table given in full (a published lumped model): every key given.
    fn from(l: LumpedPlanetarySection<f64>) -> Self {
        use Derivable::Given;
        Self {
            mass_sun_kg: Given(l.mass_sun_kg),
            mass_planet_kg: Given(l.mass_planet_kg),
            mass_ring_kg: Given(l.mass_ring_kg),
            mass_carrier_kg: Given(l.mass_carrier_kg),
            inertia_sun_kg_m2: Given(l.inertia_sun_kg_m2),
            inertia_planet_kg_m2: Given(l.inertia_planet_kg_m2),
            inertia_ring_kg_m2: Given(l.inertia_ring_kg_m2),
            inertia_carrier_kg_m2: Given(l.inertia_carrier_kg_m2),
            base_radius_sun_mm: Given(l.base_radius_sun_mm),
            base_radius_planet_mm: Given(l.base_radius_planet_mm),
            base_radius_ring_mm: Given(l.base_radius_ring_mm),
            carrier_radius_mm: Given(l.carrier_radius_mm),
            mesh_stiffness_sun_planet_n_per_m: Given(l.mesh_stiffness_sun_planet_n_per_m),
            mesh_stiffness_ring_planet_n_per_m: Given(l.mesh_stiffness_ring_planet_n_per_m),
            bearing_stiffness_sun_n_per_m: Given(l.bearing_stiffness_sun_n_per_m),
            bearing_stiffness_planet_n_per_m: Given(l.bearing_stiffness_planet_n_per_m),
            bearing_stiffness_ring_n_per_m: Given(l.bearing_stiffness_ring_n_per_m),
            bearing_stiffness_carrier_n_per_m: Given(l.bearing_stiffness_carrier_n_per_m),
            torsional_stiffness_sun_nm_per_rad: Given(l.torsional_stiffness_sun_nm_per_rad),
            torsional_stiffness_ring_nm_per_rad: Given(l.torsional_stiffness_ring_nm_per_rad),
            torsional_stiffness_carrier_nm_per_rad: Given(l.torsional_stiffness_carrier_nm_per_rad),
            pressure_angle_deg: Given(l.pressure_angle_deg),
        }
    }
}

impl LumpedPlanetarySection<Derivable> {
    /// The section with every absent or `"derived"` key replaced by `derived`'s value:
    /// a given key always wins.
    pub fn resolve(&self, derived: &LumpedPlanetarySection<f64>) -> LumpedPlanetarySection<f64> {
        LumpedPlanetarySection {
            mass_sun_kg: self.mass_sun_kg.or_derived(derived.mass_sun_kg),
            mass_planet_kg: self.mass_planet_kg.or_derived(derived.mass_planet_kg),
            mass_ring_kg: self.mass_ring_kg.or_derived(derived.mass_ring_kg),
            mass_carrier_kg: self.mass_carrier_kg.or_derived(derived.mass_carrier_kg),
            inertia_sun_kg_m2: self.inertia_sun_kg_m2.or_derived(derived.inertia_sun_kg_m2),
            inertia_planet_kg_m2: self
                .inertia_planet_kg_m2
                .or_derived(derived.inertia_planet_kg_m2),
            inertia_ring_kg_m2: self
                .inertia_ring_kg_m2
                .or_derived(derived.inertia_ring_kg_m2),
            inertia_carrier_kg_m2: self
                .inertia_carrier_kg_m2
                .or_derived(derived.inertia_carrier_kg_m2),
            base_radius_sun_mm: self
                .base_radius_sun_mm
                .or_derived(derived.base_radius_sun_mm),
            base_radius_planet_mm: self
                .base_radius_planet_mm
                .or_derived(derived.base_radius_planet_mm),
            base_radius_ring_mm: self
                .base_radius_ring_mm
                .or_derived(derived.base_radius_ring_mm),
            carrier_radius_mm: self.carrier_radius_mm.or_derived(derived.carrier_radius_mm),
            mesh_stiffness_sun_planet_n_per_m: self
                .mesh_stiffness_sun_planet_n_per_m
                .or_derived(derived.mesh_stiffness_sun_planet_n_per_m),
            mesh_stiffness_ring_planet_n_per_m: self
                .mesh_stiffness_ring_planet_n_per_m
                .or_derived(derived.mesh_stiffness_ring_planet_n_per_m),
            bearing_stiffness_sun_n_per_m: self
                .bearing_stiffness_sun_n_per_m
                .or_derived(derived.bearing_stiffness_sun_n_per_m),
            bearing_stiffness_planet_n_per_m: self
                .bearing_stiffness_planet_n_per_m
                .or_derived(derived.bearing_stiffness_planet_n_per_m),
            bearing_stiffness_ring_n_per_m: self
                .bearing_stiffness_ring_n_per_m
                .or_derived(derived.bearing_stiffness_ring_n_per_m),
            bearing_stiffness_carrier_n_per_m: self
                .bearing_stiffness_carrier_n_per_m
                .or_derived(derived.bearing_stiffness_carrier_n_per_m),
            torsional_stiffness_sun_nm_per_rad: self
                .torsional_stiffness_sun_nm_per_rad
                .or_derived(derived.torsional_stiffness_sun_nm_per_rad),
            torsional_stiffness_ring_nm_per_rad: self
                .torsional_stiffness_ring_nm_per_rad
                .or_derived(derived.torsional_stiffness_ring_nm_per_rad),
            torsional_stiffness_carrier_nm_per_rad: self
                .torsional_stiffness_carrier_nm_per_rad
                .or_derived(derived.torsional_stiffness_carrier_nm_per_rad),
            pressure_angle_deg: self
                .pressure_angle_deg
                .or_derived(derived.pressure_angle_deg),
        }
    }
}

/// Largest planet pin position error, um: a millimetre, far beyond any carrier's
/// tolerance (position errors of pins are tens of micrometres; Bodas & Kahraman 2004
/// study up to ~100 um).
pub const MAX_PIN_ERROR_UM: f64 = 1000.0;

/// Largest number of planets a case may give: far above any built set (5 to 12 is usual),
/// and it bounds the lumped model's size (3 (N + 3) degrees of freedom).
pub const MAX_PLANETS: i64 = 32;

impl PlanetarySection {
    /// Each key out of its range, as `planetary.KEY = VALUE is invalid: ...` messages:
    /// the checks that need no geometry (the geometry's own are in
    /// `geometry::planetary`).
    pub fn range_problems(&self) -> Vec<String> {
        let mut errs = Vec::new();
        if !(1..=MAX_PLANETS).contains(&self.planets) {
            errs.push(format!(
                "`planetary.planets` = {} is invalid: it must lie in 1..={MAX_PLANETS}",
                self.planets
            ));
        }
        for (key, z, min) in [
            ("teeth_sun", self.teeth_sun, 6),
            ("teeth_planet", self.teeth_planet, 6),
            ("teeth_ring", self.teeth_ring, 12),
        ] {
            if !(min..=10_000).contains(&z) {
                errs.push(format!(
                    "`planetary.{key}` = {z} is invalid: it must lie in {min}..=10000"
                ));
            }
        }
        for (key, v, lo, hi) in [
            ("module_mm", self.module_mm, 0.0, 100.0),
            ("face_width_mm", self.face_width_mm, 0.0, 2000.0),
            ("pressure_angle_deg", self.pressure_angle_deg, 10.0, 35.0),
            ("addendum_coefficient", self.addendum_coefficient, 0.0, 2.0),
            (
                "addendum_coefficient_ring",
                self.addendum_coefficient_ring,
                0.0,
                2.0,
            ),
            ("dedendum_coefficient", self.dedendum_coefficient, 0.0, 2.5),
        ] {
            if !(v.is_finite() && v > lo && v <= hi) {
                errs.push(format!(
                    "`planetary.{key}` = {v} is invalid: it must lie in ({lo}, {hi}]"
                ));
            }
        }
        let rho = self.tool_tip_radius_coefficient;
        if !(rho.is_finite() && (0.0..=0.6).contains(&rho)) {
            errs.push(format!(
                "`planetary.tool_tip_radius_coefficient` = {rho} is invalid: it must lie in [0, 0.6]"
            ));
        }
        for (key, x) in [
            ("profile_shift_sun", self.profile_shift_sun),
            ("profile_shift_planet", self.profile_shift_planet),
            ("profile_shift_ring", self.profile_shift_ring),
        ] {
            if !(x.is_finite() && x.abs() <= 1.5) {
                errs.push(format!(
                    "`planetary.{key}` = {x} is invalid: it must lie in [-1.5, 1.5]"
                ));
            }
        }
        errs.extend(self.power_flow_problems());
        errs.extend(self.pin_error_problems());
        errs.extend(self.fault_problems());
        errs
    }

    /// The `[[planetary.fault]]` tables' problems that the case alone shows: more than one
    /// table, a kind or member not built on a set yet, a planet or tooth index outside the
    /// set, the keys against the kind (the pair's `FaultKind::keys`).
    fn fault_problems(&self) -> Vec<String> {
        let mut errs = Vec::new();
        if self.fault.len() > 1 {
            errs.push(format!(
                "`[[planetary.fault]]` has {} tables: a planetary set takes one tooth fault so far (give one table)",
                self.fault.len()
            ));
        }
        for (i, f) in self.fault.iter().enumerate() {
            let z = match f.gear {
                FaultyGear::Sun => self.teeth_sun,
                FaultyGear::Planet => self.teeth_planet,
                FaultyGear::Ring => self.teeth_ring,
            };
            if f.tooth < 0 || f.tooth >= z {
                errs.push(format!(
                    "`planetary.fault.tooth` = {} (fault {i}, {}) is invalid: the {} has teeth 0 to {}",
                    f.tooth,
                    f.gear.name(),
                    f.gear.name(),
                    z - 1
                ));
            }
            match (f.gear, f.planet) {
                (FaultyGear::Planet, None) => errs.push(format!(
                    "`planetary.fault.planet` is required for a fault on a planet (fault {i}): give the planet, 1..={}",
                    self.planets
                )),
                (FaultyGear::Planet, Some(p)) if !(1..=self.planets).contains(&p) => {
                    errs.push(format!(
                        "`planetary.fault.planet` = {p} (fault {i}) is invalid: the set's planets are 1..={} (`planetary.planets` = {})",
                        self.planets, self.planets
                    ))
                }
                (FaultyGear::Sun | FaultyGear::Ring, Some(p)) => errs.push(format!(
                    "`planetary.fault.planet` = {p} (fault {i}) applies to `gear = \"planet\"` only, not to the {}: remove it",
                    f.gear.name()
                )),
                _ => {}
            }
            let own = f.kind.keys();
            for (key, given) in f.as_pair_table().given() {
                match own.iter().find(|(k, _)| *k == key) {
                    None if given => errs.push(format!(
                        "`planetary.fault.{key}` (fault {i}) does not apply to kind \"{}\"; its keys: {}",
                        f.kind.name(),
                        own.iter().map(|(k, _)| *k).collect::<Vec<_>>().join(", ")
                    )),
                    Some((_, true)) if !given => errs.push(format!(
                        "`planetary.fault.{key}` is required for a fault of kind \"{}\" (fault {i}, {})",
                        f.kind.name(),
                        f.who()
                    )),
                    _ => {}
                }
            }
        }
        errs
    }

    /// The set's tooth fault that changes its tooth, if any (a crack of zero depth is the
    /// healthy set).
    pub fn active_fault(&self) -> Option<&PlanetaryFault> {
        super::planetary_fault::active(&self.fault)
    }

    /// The planet pin position errors: one value per planet, each finite and within
    /// [`MAX_PIN_ERROR_UM`].
    fn pin_error_problems(&self) -> Vec<String> {
        let mut errs = Vec::new();
        for (key, v) in [
            (
                "planet_tangential_error_um",
                &self.planet_tangential_error_um,
            ),
            ("planet_radial_error_um", &self.planet_radial_error_um),
        ] {
            let Some(v) = v else { continue };
            if v.len() as i64 != self.planets {
                errs.push(format!(
                    "`planetary.{key}` has {} values: it must have one per planet, `planetary.planets` = {}",
                    v.len(),
                    self.planets
                ));
            }
            for (i, e) in v.iter().enumerate() {
                if !(e.is_finite() && e.abs() <= MAX_PIN_ERROR_UM) {
                    errs.push(format!(
                        "`planetary.{key}` value {} (planet {}) = {e} is invalid: it must lie in [-{MAX_PIN_ERROR_UM}, {MAX_PIN_ERROR_UM}]",
                        i + 1,
                        i + 1
                    ));
                }
            }
        }
        errs
    }

    /// Each planet's pin position error (tangential, radial), m: zeros where absent.
    pub fn pin_errors_m(&self) -> Vec<(f64, f64)> {
        let n = self.planets.max(0) as usize;
        let at = |v: &Option<Vec<f64>>, i: usize| {
            v.as_ref().and_then(|v| v.get(i)).copied().unwrap_or(0.0) * 1e-6
        };
        (0..n)
            .map(|i| {
                (
                    at(&self.planet_tangential_error_um, i),
                    at(&self.planet_radial_error_um, i),
                )
            })
            .collect()
    }

    /// Input, output and fixed must be three different members.
    fn power_flow_problems(&self) -> Vec<String> {
        let mut errs = Vec::new();
        for (a, b, va, vb) in [
            ("input", "fixed", self.input, self.fixed),
            ("output", "fixed", self.output, self.fixed),
            ("input", "output", self.input, self.output),
        ] {
            if va == vb {
                errs.push(format!(
                    "`planetary.{a}` = \"{}\" is invalid: the {} cannot be both the {a} and the {b} (a simple planetary set has one input, one output and one fixed member, each of \"sun\", \"carrier\", \"ring\")",
                    va.name(),
                    va.name()
                ));
            }
        }
        errs
    }
}
