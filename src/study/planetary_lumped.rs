//! The lumped parameters of a planetary set derived from its geometry and `[dynamics]`
//! (docs/MODEL.md 12.4): the values an absent `[planetary.lumped]` key (or `"derived"`)
//! takes. A given key always wins (`LumpedPlanetarySection::resolve`).
//!
//! Bodies (density rho = `dynamics.blank_density_kg_per_m3`, face width b =
//! `planetary.face_width_mm`), each a hollow cylinder (Gere & Goodno, *Mechanics of
//! Materials*, appendix), as the single pair's blanks (docs/MODEL.md 7,
//! `geometry::blank`):
//!   m = rho pi b (r_o^2 - r_i^2),   J = m (r_o^2 + r_i^2) / 2   (kg, kg m^2).
//! - sun and planet: solid disks (r_i = 0) out to the reference (pitch) radius, the
//!   pair's rule for a toothed rim; a planet's bearing and a sun's shaft bore are counted
//!   as steel (a choice: the hub bores are unknown to a set).
//! - ring: an annulus from its root circle r_f out to a rim of thickness s_R = 3.5 m (the
//!   thinnest rim for which ISO 6336-3:2019's rim thickness factor of an internal gear is
//!   Y_B = 1, i.e. a rim stiff enough not to weaken the tooth root); its teeth inside r_f
//!   are left out. The rim thickness is a choice: housings often hold the ring by more.
//! - carrier: two side plates of thickness b / 2 each (together one face width), solid
//!   disks of radius r_c + r_p (carrier radius plus a planet's reference radius, so the
//!   plates cover the planets' pins and faces); pins and webs left out (a choice).
//!
//! Radii, mesh stiffness and pressure angle: the geometry's base radii, the carrier radius
//! (the sun-planet operating centre distance), the meshes' mean stiffness and the
//! sun-planet operating pressure angle (the modal table takes one angle; the dynamic model
//! takes each mesh's own).
//!
//! Supports, as the single pair's (`[dynamics]`): the sun's and the planets' lateral
//! bearings `dynamics.bearing_stiffness_pinion_n_per_m`, the ring's and the carrier's
//! `dynamics.bearing_stiffness_gear_n_per_m`. Torsional supports by the member's role:
//! the input's the motor coupling `dynamics.coupling_stiffness_motor_nm_per_rad` (k_mp;
//! `gearwear dynamics` leaves it out, a constant torque drives the input), the output's
//! the load coupling `dynamics.coupling_stiffness_brake_nm_per_rad` (k_bg), the fixed
//! member's stiff: [`FIXED_PER_COUPLING`] times k_bg (a choice: a housing far stiffer
//! than a shaft coupling, yet not so stiff that it dominates the modal table's conditioning).

use crate::config::case::Case;
use crate::config::planetary::{LumpedPlanetarySection, Member};
use crate::geometry::blank::disk_with_bore;
use crate::geometry::planetary::PlanetarySet;

/// The fixed member's torsional support over the load coupling k_bg: a hundredfold.
pub const FIXED_PER_COUPLING: f64 = 100.0;

/// Ring rim thickness s_R below the root circle, in modules (ISO 6336-3:2019: Y_B = 1 for
/// an internal gear with s_R >= 3.5 m_n).
pub const RING_RIM_MODULES: f64 = 3.5;

/// m -> mm.
const MM_PER_M: f64 = 1e3;

/// Every lumped value of the set derived from its geometry, `[dynamics]` and the meshes'
/// mean stiffness [sun-planet, ring-planet] (N/m).
pub fn derived_lumped(
    case: &Case,
    set: &PlanetarySet,
    mean_mesh_n_per_m: [f64; 2],
) -> LumpedPlanetarySection<f64> {
    let (module_m, b_m) = (set.sun_planet.module_m, set.sun_planet.face_width_m);
    let d = &case.dynamics;
    let rho = d.blank_density_kg_per_m3;
    let (sun, planet, ring) = (
        &set.sun_planet.pinion,
        &set.sun_planet.gear,
        &set.ring_planet.ring,
    );
    let (m_s, j_s) = disk_with_bore(sun.pitch_radius_m, 0.0, b_m, rho);
    let (m_p, j_p) = disk_with_bore(planet.pitch_radius_m, 0.0, b_m, rho);
    let rim_m = RING_RIM_MODULES * module_m;
    let (m_r, j_r) = disk_with_bore(ring.root_radius_m + rim_m, ring.root_radius_m, b_m, rho);
    let carrier_outer_m = set.carrier_radius_m + planet.pitch_radius_m;
    let (m_c, j_c) = disk_with_bore(carrier_outer_m, 0.0, b_m, rho);
    let torsional = |m: Member| {
        if m == set.fixed {
            FIXED_PER_COUPLING * d.coupling_stiffness_brake_nm_per_rad
        } else if m == set.output {
            d.coupling_stiffness_brake_nm_per_rad
        } else {
            d.coupling_stiffness_motor_nm_per_rad
        }
    };
    LumpedPlanetarySection {
        mass_sun_kg: m_s,
        mass_planet_kg: m_p,
        mass_ring_kg: m_r,
        mass_carrier_kg: m_c,
        inertia_sun_kg_m2: j_s,
        inertia_planet_kg_m2: j_p,
        inertia_ring_kg_m2: j_r,
        inertia_carrier_kg_m2: j_c,
        base_radius_sun_mm: sun.base_radius_m * MM_PER_M,
        base_radius_planet_mm: planet.base_radius_m * MM_PER_M,
        base_radius_ring_mm: ring.base_radius_m * MM_PER_M,
        carrier_radius_mm: set.carrier_radius_m * MM_PER_M,
        mesh_stiffness_sun_planet_n_per_m: mean_mesh_n_per_m[0],
        mesh_stiffness_ring_planet_n_per_m: mean_mesh_n_per_m[1],
        bearing_stiffness_sun_n_per_m: d.bearing_stiffness_pinion_n_per_m,
        bearing_stiffness_planet_n_per_m: d.bearing_stiffness_pinion_n_per_m,
        bearing_stiffness_ring_n_per_m: d.bearing_stiffness_gear_n_per_m,
        bearing_stiffness_carrier_n_per_m: d.bearing_stiffness_gear_n_per_m,
        torsional_stiffness_sun_nm_per_rad: torsional(Member::Sun),
        torsional_stiffness_ring_nm_per_rad: torsional(Member::Ring),
        torsional_stiffness_carrier_nm_per_rad: torsional(Member::Carrier),
        pressure_angle_deg: set.sun_planet.operating_pressure_angle_rad.to_degrees(),
    }
}
