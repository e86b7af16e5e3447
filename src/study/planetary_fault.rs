//! A planetary set's tooth fault (`[[planetary.fault]]`, docs/MODEL.md 12.13): the
//! compliance a crack or a spall on one sun or planet tooth adds to the pairs that hold
//! it, along each mesh's path of contact (`stiffness::planetary_mesh::MeshFault`), and
//! the fault's period checked against the limits before any run.
//!
//! The fault is the pair's (`config::teeth`): the same kinds, sizes and defaults, the same
//! checks against the tooth (`study::teeth::fault_problem`: a crack deeper than the root,
//! a spall off the active profile or deeper than the tooth holds) and the same compliance
//! (`study::teeth::apply_fault`, Chen & Shao 2011 for a crack, Saxena et al. 2016 for a
//! spall) on the sun-planet pair, the sun as its pinion and the planet as its gear. A
//! planet's crack also softens its ring mesh: the planet's tooth beam of that mesh with
//! the same crack (`stiffness::tooth_faults::crack_compliance_m_per_n`). A spall's gap and
//! lost contact width (a pair's full-width and partial spalls, `dynamics::tooth_mesh`) are
//! not taken: the set's meshes carry stiffness only (a stated limit).

use super::model::ModelError;
use super::teeth::{apply_fault, fault_problem};
use crate::config::case::{Fault, FaultTable, Member, ToothFault};
use crate::config::planetary::{FaultyGear, PlanetaryFault};
use crate::dynamics::tooth_mesh::ToothFlank;
use crate::geometry::flank_shape::{ActiveFlank, Side};
use crate::geometry::planetary::PlanetarySet;
use crate::stiffness::internal::InternalMeshStiffness;
use crate::stiffness::mesh::MeshStiffness;
use crate::stiffness::planetary_mesh::{FaultMember, MeshFault, FAULT_TABLE_POINTS};
use crate::stiffness::tooth_faults::{crack_compliance_m_per_n, Crack};

/// Most samples a faulty set's recorded period may hold: its mesh periods (up to
/// lcm(z_member, z_r) for the ring sensor's record) times the samples per mesh period.
/// 5e7 samples of a four-planet set's 42 states are 17 GB, beyond any budget; the limit
/// keeps the counts far inside `usize` and the message clear before the budget's.
pub const MAX_FAULT_PERIOD_SAMPLES: u64 = 50_000_000;

/// The fault's sizes as the pair's resolved fault on the member's side of the sun-planet
/// pair (the sun the pinion, a planet the gear): for the pair's checks and compliance.
fn as_pair_fault(f: &PlanetaryFault) -> Result<ToothFault, ModelError> {
    let side = match f.gear {
        FaultyGear::Sun => Member::Pinion,
        _ => Member::Gear,
    };
    let table = FaultTable {
        gear: side,
        tooth: 0,
        ..f.as_pair_table()
    };
    ToothFault::try_from(table).map_err(|e| ModelError(vec![e]))
}

/// The fault `f` (index `i`) of `set` as the meshes' [`MeshFault`], its sizes checked
/// against its tooth; problems name `planetary.fault.*` keys and the member.
pub fn mesh_fault(
    i: usize,
    f: &PlanetaryFault,
    set: &PlanetarySet,
    sun_mesh: &MeshStiffness,
    ring_mesh: &InternalMeshStiffness,
) -> Result<MeshFault, ModelError> {
    let pair = &set.sun_planet;
    let pf = as_pair_fault(f)?;
    let flanks = [Side::Pinion, Side::Gear].map(|s| ActiveFlank::of(pair, s));
    if let Some(p) = fault_problem(i, &pf, pair, sun_mesh, &flanks) {
        let side = pf.gear.name();
        let p = p
            .replace("`fault.", "`planetary.fault.")
            .replace(&format!("{side} tooth 0"), &f.who());
        return Err(ModelError(vec![p]));
    }
    let (member, side) = match (f.gear, f.planet) {
        (FaultyGear::Planet, Some(p)) => (FaultMember::Planet((p - 1) as usize), Side::Gear),
        _ => (FaultMember::Sun, Side::Pinion),
    };
    // The sun mesh: the pair's fault on its side, at the path's rho1 (own rho of the
    // sun = rho1, of the planet = its conjugate).
    let n = FAULT_TABLE_POINTS - 1;
    let path: Vec<f64> = (0..=n)
        .map(|k| pair.rho_start_m + (pair.rho_end_m - pair.rho_start_m) * k as f64 / n as f64)
        .collect();
    let own: Vec<f64> = match side {
        Side::Pinion => path.clone(),
        Side::Gear => path.iter().map(|r| pair.rho_gear(*r)).collect(),
    };
    let mut flank = ToothFlank {
        removed_m: vec![0.0; own.len()],
        ..Default::default()
    };
    apply_fault(&mut flank, &pf, pair, sun_mesh, side, &own);
    let sun = flank
        .compliance_m_per_n
        .unwrap_or_else(|| vec![0.0; own.len()]);
    // The ring mesh: a planet's crack on the planet's tooth beam of that mesh (own rho
    // of the planet = the ring path's rho1).
    let ring = match (member, pf.fault) {
        (
            FaultMember::Planet(_),
            Fault::Crack {
                depth_m,
                angle_rad,
                width_fraction,
            },
        ) => {
            let rp = &set.ring_planet;
            let crack = Crack {
                depth_m,
                angle_rad,
                width_fraction,
            };
            let tip = flanks[1].tip_rho_m;
            Some(
                (0..=n)
                    .map(|k| {
                        let rho =
                            rp.rho_start_m + (rp.rho_end_m - rp.rho_start_m) * k as f64 / n as f64;
                        crack_compliance_m_per_n(ring_mesh.planet_beam(), tip, &crack, rho)
                    })
                    .collect(),
            )
        }
        _ => None,
    };
    Ok(MeshFault {
        member,
        tooth: f.tooth.max(0) as usize,
        sun_m_per_n: Some(sun),
        ring_m_per_n: ring,
    })
}

/// Mesh periods a faulty set's response repeats over (z_s for a sun tooth, z_p for a
/// planet's; 1 without a fault that changes its tooth), and those of the ring sensor's
/// record, lcm(that, z_r) (the planets' angles to the sensor repeat once per carrier
/// revolution relative to the ring, z_r mesh periods), in checked arithmetic; an input
/// problem naming the keys when either period's samples (`samples_per_period` each)
/// pass [`MAX_FAULT_PERIOD_SAMPLES`].
pub fn fault_periods(
    section: &crate::config::planetary::PlanetarySection,
    samples_per_period: u64,
) -> Result<(u64, u64), String> {
    let Some(f) = section.active_fault() else {
        return Ok((1, 1));
    };
    let z = |v: i64| u64::try_from(v.max(1)).unwrap_or(1);
    let p = match f.gear {
        FaultyGear::Sun => z(section.teeth_sun),
        FaultyGear::Planet => z(section.teeth_planet),
        FaultyGear::Ring => z(section.teeth_ring),
    };
    let zr = z(section.teeth_ring);
    let gcd = |mut a: u64, mut b: u64| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let record = (p / gcd(p, zr)).checked_mul(zr);
    let samples = record.and_then(|r| r.checked_mul(samples_per_period.max(1)));
    match (record, samples) {
        (Some(r), Some(s)) if s <= MAX_FAULT_PERIOD_SAMPLES => Ok((p, r)),
        _ => Err(format!(
            "`planetary.fault.gear` = \"{}\" with `planetary.teeth_{}` = {p}, `planetary.teeth_ring` = {zr} and `numerics.steps_per_mesh_period` = {samples_per_period}: the fault's response repeats over {p} mesh periods and the ring sensor's record over lcm({p}, {zr}) = {} mesh periods, {} samples, beyond the limit of {MAX_FAULT_PERIOD_SAMPLES}: give fewer steps per mesh period or a member with fewer teeth",
            f.gear.name(),
            f.gear.name(),
            record.map_or("more than 2^64".to_string(), |r| r.to_string()),
            samples.map_or("more than 2^64".to_string(), |s| s.to_string()),
        )),
    }
}
