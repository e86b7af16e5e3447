//! The model objects of a planetary case (`[planetary]`) for `gearwear stiffness`: the
//! set's geometry (`geometry::planetary`), the mean, smallest and largest stiffness of its
//! two meshes, the member speeds and frequencies at the case's input speed, the lumped
//! parameters (`[planetary.lumped]`'s given keys, the rest derived from the geometry by
//! `study::planetary_lumped`), and the time-invariant model's natural frequencies with
//! each mode's class (Lin & Parker 1999; docs/MODEL.md section 12).
//! The set's dynamic model is `study::planetary_dynamics`; the pair's `Model::from_case` refuses a set.

use super::model::ModelError;
use super::planetary_fault::mesh_fault;
use super::planetary_lumped::derived_lumped;
use crate::config::case::Case;
use crate::config::planetary::{LumpedPlanetarySection, PlanetarySection};
use crate::dynamics::planetary_lumped::{PlanetaryLumped, PlanetaryMode};
use crate::geometry::planetary::PlanetarySet;
use crate::io::Table;
use crate::stiffness::internal::InternalMeshStiffness;
use crate::stiffness::mesh::MeshStiffness;
use crate::stiffness::planetary_mesh::PlanetaryMeshes;
use crate::stiffness::potential_energy::ElasticPair;

/// Samples of the ring mesh's total stiffness over one mesh period for its extremes (the
/// spur study's table density): the extremes sit on plateaus of the pairs in contact.
const RING_SAMPLES: usize = 720;

/// A planetary case's stiffness model, built once.
#[derive(Debug, Clone)]
pub struct PlanetaryStudy {
    /// The `[planetary]` section.
    pub section: PlanetarySection,
    /// The set's geometry.
    pub set: PlanetarySet,
    /// The sun-planet mesh's stiffness (pinion = sun, gear = planet).
    pub sun_mesh: MeshStiffness,
    /// The ring-planet mesh's stiffness.
    pub ring_mesh: InternalMeshStiffness,
    /// Signed member speeds [sun, carrier, ring], Hz, at the case's input speed.
    pub speeds_hz: [f64; 3],
    /// Every mesh's stiffness over time with its phase (Parker & Lin 2004).
    pub meshes: PlanetaryMeshes,
    /// The lumped parameters used: `[planetary.lumped]`'s given keys, the others derived
    /// from the geometry (`study::planetary_lumped`).
    pub lumped: LumpedPlanetarySection,
    /// The lumped model's modes, ascending (always given since the lumped parameters can
    /// be derived).
    pub modes: Option<Vec<PlanetaryMode>>,
    /// Warnings of the geometry and the stiffness.
    pub warnings: Vec<String>,
}

impl PlanetaryStudy {
    /// Build the set and its meshes from a validated case. Materials: the sun takes
    /// `[materials]`' pinion constants, the planets and the ring the gear's. Both meshes
    /// leave out the fillet foundation (the ring's rim is rigid, docs/MODEL.md 12.2; the sun
    /// mesh alike so the two compare).
    pub fn from_case(case: &Case) -> Result<Self, ModelError> {
        let Some(section) = case.planetary.clone() else {
            return Err(ModelError(vec![
                "the case has no [planetary] section".into()
            ]));
        };
        if let Some(r) = super::face_load::lead_refusal(case) {
            return Err(ModelError(vec![r]));
        }
        super::helical_tilt::refuse_tilt(case, "a planetary set")?;
        if case.gear.helix_angle_deg != 0.0 {
            return Err(ModelError(vec![format!(
                "`gear.helix_angle_deg` = {} with [planetary]: a planetary set's meshes are spur so far (helical sets are not built), so it would give a spur result; set it to 0",
                case.gear.helix_angle_deg
            )]));
        }
        if let Some(f) = case.fault.first() {
            return Err(ModelError(vec![format!(
                "`fault.gear` = \"{}\" with [planetary]: a pair's `[[fault]]` does not apply to a planetary set; give its fault as a `[[planetary.fault]]` table (`gear` = \"sun\", \"planet\" or \"ring\")",
                f.gear.name()
            )]));
        }
        let steps = case.numerics.steps_per_mesh_period.max(8) as u64;
        super::planetary_fault::fault_period(&section, steps)?;
        let set = PlanetarySet::from_case(&section)?;
        let load = super::domain::planetary_domain_problems(case, &set);
        if !load.is_empty() {
            return Err(ModelError(load));
        }
        let elastic = ElasticPair::from_case(&case.materials);
        let n_table = case.stiffness.table_points_per_mesh_period.max(16) as usize;
        let sun_mesh = MeshStiffness::with_fillet(&set.sun_planet, &elastic, n_table, None)?;
        let planet_ring = ElasticPair {
            e_pinion_pa: elastic.e_gear_pa,
            nu_pinion: elastic.nu_gear,
            ..elastic
        };
        let ring_mesh = InternalMeshStiffness::new(&set.ring_planet, &planet_ring, false);
        let mut warnings = set.sun_planet.warnings.clone();
        // A set's meshes are spur: the axial bearing keys are ignored, as on a spur pair.
        warnings.extend(super::domain::axial_key_warnings(case));
        warnings.extend(sun_mesh.warnings().iter().cloned());
        let speeds_hz = set.member_speeds(case.operating.input_speed_hz);
        let mut meshes = PlanetaryMeshes::new(&set, &sun_mesh, &ring_mesh);
        if let Some((i, f)) = section
            .fault
            .iter()
            .enumerate()
            .find(|(_, f)| f.changes_tooth())
        {
            let fault = mesh_fault(i, f, &set, &sun_mesh, &ring_mesh)?;
            meshes = meshes.with_fault(&set, fault);
            if f.kind == crate::config::case::FaultKind::Spall
                && f.written("spall_width_fraction") >= 1.0
            {
                warnings.push(format!(
                    "`planetary.fault.spall_width_fraction` = 1 on {}: the set's meshes take the spall's stiffness (its pitted section) only; the gap a spall across the whole face opens (a pair's, docs/MODEL.md 9.5) is left out on a set",
                    f.who()
                ));
            }
        }
        let derived = derived_lumped(case, &set, meshes.mean_n_per_m());
        let lumped = match &section.lumped {
            Some(l) => l.resolve(&derived),
            None => derived,
        };
        let modes = Some(
            PlanetaryLumped::from_section(&lumped, set.planet_angles_rad.clone())
                .map_err(|p| ModelError(p.messages()))?
                .modes(),
        );
        Ok(Self {
            section,
            set,
            meshes,
            sun_mesh,
            ring_mesh,
            speeds_hz,
            lumped,
            modes,
            warnings,
        })
    }

    /// Every mesh's stiffness over one carrier revolution relative to the ring (z_r mesh
    /// cycles) at `per_cycle` samples per mesh cycle: columns `carrier_angle_deg` (the
    /// carrier's rotation relative to the ring), `mesh_cycles`, then
    /// `k_sun_planet_N_n_per_m` and `k_ring_planet_N_n_per_m` for each planet N.
    pub fn stiffness_table(&self, per_cycle: usize) -> Table {
        let zr = self.set.teeth_ring();
        let rows = zr * per_cycle;
        let cycles: Vec<f64> = (0..rows).map(|i| i as f64 / per_cycle as f64).collect();
        let mut t = Table::new()
            .col(
                "carrier_angle_deg",
                cycles.iter().map(|c| 360.0 * c / zr as f64).collect(),
            )
            .col("mesh_cycles", cycles.clone());
        for p in 0..self.set.planets() {
            let k = cycles
                .iter()
                .map(|c| self.meshes.sun_n_per_m(p, *c))
                .collect();
            t = t.col(&format!("k_sun_planet_{}_n_per_m", p + 1), k);
        }
        for p in 0..self.set.planets() {
            let k = cycles
                .iter()
                .map(|c| self.meshes.ring_n_per_m(p, *c))
                .collect();
            t = t.col(&format!("k_ring_planet_{}_n_per_m", p + 1), k);
        }
        t
    }

    /// Smallest and largest total stiffness of the ring mesh over a mesh period, N/m,
    /// sampled at `RING_SAMPLES` planet angles.
    pub fn ring_extremes_n_per_m(&self) -> (f64, f64) {
        let period = 2.0 * std::f64::consts::PI / self.set.teeth_planet() as f64;
        (0..RING_SAMPLES)
            .map(|i| {
                self.ring_mesh
                    .total_stiffness_n_per_m(period * i as f64 / RING_SAMPLES as f64)
            })
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), k| {
                (lo.min(k), hi.max(k))
            })
    }
}
