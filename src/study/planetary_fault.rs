//! A planetary set's tooth fault (`[[planetary.fault]]`, docs/MODEL.md 12.13, 12.14): the
//! compliance a crack or a spall on one sun, planet or ring tooth adds to the pairs that
//! hold it, along each mesh's path of contact (`stiffness::planetary_mesh::MeshFault`), and
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
//! not taken: the set's meshes carry stiffness only (a stated limit). A ring tooth's fault
//! is the same crack or spall on the ring tooth's section (`stiffness::ring_tooth_faults`)
//! with the pair's checks carried over to it.

use super::model::ModelError;
use super::teeth::{apply_fault, fault_problem, lower_mm, upper_mm};
use crate::config::case::{Fault, FaultTable, Member, ToothFault};
use crate::config::planetary::{FaultyGear, PlanetaryFault};
use crate::dynamics::tooth_mesh::ToothFlank;
use crate::geometry::flank_shape::{ActiveFlank, Side};
use crate::geometry::planetary::PlanetarySet;
use crate::stiffness::internal::{InternalMeshStiffness, RingToothBeam};
use crate::stiffness::mesh::MeshStiffness;
use crate::stiffness::planetary_mesh::{FaultMember, MeshFault, FAULT_TABLE_POINTS};
use crate::stiffness::ring_tooth_faults::{
    ring_crack_compliance_m_per_n, ring_crack_max_depth_m, ring_spall_compliance_m_per_n,
    ring_spall_max_depth_m,
};
use crate::stiffness::tooth_faults::{crack_compliance_m_per_n, Crack, Spall};

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
    let pf = as_pair_fault(f)?;
    if f.gear == FaultyGear::Ring {
        return ring_mesh_fault(i, f, &pf.fault, set, ring_mesh);
    }
    let pair = &set.sun_planet;
    let flanks = [Side::Pinion, Side::Gear].map(|s| ActiveFlank::of(pair, s));
    if let Some(p) = fault_problem(i, &pf, pair, sun_mesh, &flanks) {
        let side = pf.gear.name();
        let p = p
            .replace("`fault.", "`planetary.fault.")
            .replace(
                &format!("fault {i}, {side} tooth 0"),
                &format!("planetary fault {}, {}", i + 1, f.who()),
            )
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
    let (sun_contact, ring_contact) =
        broken_tip_contacts(flank.contact_limit_rho1_m, side, member, &pf.fault, set);
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
        sun_contact_rho1_m: sun_contact,
        ring_contact_rho1_m: ring_contact,
    })
}

/// Where a broken tip (`fault`) lets the pairs holding its tooth touch, as the
/// [`MeshFault`]'s rho1 intervals of the sun and ring mesh: the pair's cut on the sun
/// mesh (`limit`, from `study::teeth::apply_fault`: the sun's tip side above it, the
/// planet's below it), and for a planet's tooth on its ring mesh too, where the planet's
/// own rho is the ring path's rho1 (docs/MODEL.md 12.13); None, None for another fault.
fn broken_tip_contacts(
    limit: Option<f64>,
    side: Side,
    member: FaultMember,
    fault: &Fault,
    set: &PlanetarySet,
) -> (Option<[f64; 2]>, Option<[f64; 2]>) {
    let sun = limit.map(|l| match side {
        Side::Pinion => [f64::NEG_INFINITY, l],
        Side::Gear => [l, f64::INFINITY],
    });
    let ring = match (member, fault) {
        (FaultMember::Planet(_), Fault::BrokenTip { removed_height_m }) => {
            let p = &set.ring_planet.planet;
            let r_cut = p.tip_radius_m - removed_height_m;
            let rho_cut = (r_cut.powi(2) - p.base_radius_m.powi(2)).max(0.0).sqrt();
            Some([f64::NEG_INFINITY, rho_cut])
        }
        _ => None,
    };
    (sun, ring)
}

/// The ring's own rho2 (m) of its active flank's tip end, pitch point and root end: the
/// ring path's start, pitch point and end (the ring's tip meets the planet first).
fn ring_flank(set: &PlanetarySet) -> [f64; 3] {
    let rp = &set.ring_planet;
    [rp.rho_start_m, rp.rho_pitch_m, rp.rho_end_m].map(|r| rp.rho_ring(r))
}

/// A spall on the ring's flank as its own rho2 (m): the centre `position_m` of roll from
/// the pitch point towards the ring's tip (smaller rho2), `length_m` long.
fn ring_spall(set: &PlanetarySet, position_m: f64, length_m: f64, depth_m: f64, w: f64) -> Spall {
    let centre = ring_flank(set)[1] - position_m;
    Spall {
        rho_lo_m: centre - 0.5 * length_m,
        rho_hi_m: centre + 0.5 * length_m,
        depth_m,
        width_fraction: w,
    }
}

/// The problem of a ring tooth's fault `f` (index `i`) against the ring's tooth, if any:
/// a crack deeper than the root's thickness, a spall longer than or off the ring's active
/// profile or deeper than the tooth holds (the pair's checks, `study::teeth::
/// fault_problem`, on the ring tooth's section).
fn ring_fault_problem(
    i: usize,
    f: &PlanetaryFault,
    fault: &Fault,
    set: &PlanetarySet,
    beam: &RingToothBeam,
) -> Option<String> {
    let mm = 1e3;
    // Numbered as the case's checks number it (`config::planetary`: from 1).
    let who = format!("planetary fault {}, {}", i + 1, f.who());
    match *fault {
        Fault::Crack {
            depth_m, angle_rad, ..
        } => {
            let q_max = ring_crack_max_depth_m(beam, angle_rad);
            (depth_m >= q_max).then(|| format!(
                "`planetary.fault.crack_depth_mm` = {} ({who}) is deeper than the tooth: at {} deg its reach across the ring tooth's root must stay below the root's thickness {:.4} mm, valid [0, {}) mm",
                f.written("crack_depth_mm"),
                f.written("crack_angle_deg"),
                2.0 * beam.root_section().0 * mm,
                upper_mm(q_max * mm)
            ))
        }
        Fault::Spall {
            position_m,
            length_m,
            depth_m,
            width_fraction,
        } => {
            let [tip, pitch, root] = ring_flank(set);
            let s = ring_spall(set, position_m, length_m, depth_m, width_fraction);
            if length_m > root - tip {
                Some(format!(
                    "`planetary.fault.spall_length_mm` = {} ({who}) is longer than the ring's active profile: valid (0, {}] mm",
                    f.written("spall_length_mm"),
                    upper_mm((root - tip) * mm)
                ))
            } else if s.rho_lo_m < tip - 1e-12 || s.rho_hi_m > root + 1e-12 {
                Some(format!(
                    "`planetary.fault.spall_position_mm` = {} ({who}) puts the spall off the ring's active profile: with length {} mm its centre must lie within [{}, {}] mm of the pitch point (towards the ring's tip positive)",
                    f.written("spall_position_mm"),
                    f.written("spall_length_mm"),
                    lower_mm((pitch - root + 0.5 * length_m) * mm),
                    upper_mm((pitch - tip - 0.5 * length_m) * mm)
                ))
            } else {
                let d_max = ring_spall_max_depth_m(beam, &s);
                (depth_m > d_max).then(|| format!(
                    "`planetary.fault.spall_depth_um` = {} ({who}) is deeper than the tooth holds: a pit may take at most {:.0} % of the ring tooth's thickness at its edge nearer the tip ({:.4} mm), valid (0, {:.1}] µm",
                    f.written("spall_depth_um"),
                    Spall::MAX_THICKNESS_SHARE * 100.0,
                    d_max / Spall::MAX_THICKNESS_SHARE * mm,
                    (d_max * 1e7).floor() / 10.0
                ))
            }
        }
        Fault::BrokenTip { removed_height_m } => {
            // The ring tooth's height: tip (inner) to root (outer) circle.
            let ring = &set.ring_planet.ring;
            let height = ring.root_radius_m - ring.tip_radius_m;
            (removed_height_m > height).then(|| format!(
                "`planetary.fault.removed_height_mm` = {} ({who}) is more than the ring's tooth: valid (0, {}] mm (tip to root circle)",
                f.written("removed_height_mm"),
                upper_mm(height * mm)
            ))
        }
    }
}

/// A ring tooth's fault `f` (index `i`, `fault` its resolved sizes) as the meshes'
/// [`MeshFault`]: the compliance it adds to the ring tooth (`stiffness::
/// ring_tooth_faults`) tabulated along the ring path (rho1 of the planet, own rho2 of the
/// ring = rho1 + N1N2); every planet's ring mesh meets it, no sun mesh.
fn ring_mesh_fault(
    i: usize,
    f: &PlanetaryFault,
    fault: &Fault,
    set: &PlanetarySet,
    ring_mesh: &InternalMeshStiffness,
) -> Result<MeshFault, ModelError> {
    let beam = ring_mesh.ring_beam();
    if let Some(p) = ring_fault_problem(i, f, fault, set, beam) {
        return Err(ModelError(vec![p]));
    }
    let rp = &set.ring_planet;
    let n = FAULT_TABLE_POINTS - 1;
    let own = (0..=n).map(|k| {
        rp.rho_ring(rp.rho_start_m + (rp.rho_end_m - rp.rho_start_m) * k as f64 / n as f64)
    });
    let table: Vec<f64> = match *fault {
        Fault::Crack {
            depth_m,
            angle_rad,
            width_fraction,
        } => {
            let crack = Crack {
                depth_m,
                angle_rad,
                width_fraction,
            };
            own.map(|rho2| ring_crack_compliance_m_per_n(beam, &crack, rho2))
                .collect()
        }
        Fault::Spall {
            position_m,
            length_m,
            depth_m,
            width_fraction,
        } => {
            let s = ring_spall(set, position_m, length_m, depth_m, width_fraction);
            let kh = ring_mesh.hertz_compliance_m_per_n();
            own.map(|rho2| ring_spall_compliance_m_per_n(beam, &s, kh, rho2))
                .collect()
        }
        // A broken tip adds no compliance; it cuts the contact (below).
        Fault::BrokenTip { .. } => vec![0.0; n + 1],
    };
    // A broken ring tip: the ring tooth now begins at r_a + h (its tip is its inner
    // circle), own rho2 = sqrt((r_a + h)^2 - r_b^2); it touches where rho2 is above that,
    // rho1 = rho2 - N1N2 on the ring path (docs/MODEL.md 12.14).
    let contact = match *fault {
        Fault::BrokenTip { removed_height_m } => {
            let ring = &set.ring_planet.ring;
            let r_cut = ring.tip_radius_m + removed_height_m;
            let rho2 = (r_cut.powi(2) - ring.base_radius_m.powi(2)).max(0.0).sqrt();
            Some([rho2 - set.ring_planet.loa_length_m, f64::INFINITY])
        }
        _ => None,
    };
    Ok(MeshFault {
        member: FaultMember::Ring,
        tooth: f.tooth.max(0) as usize,
        sun_m_per_n: None,
        ring_m_per_n: Some(table),
        sun_contact_rho1_m: None,
        ring_contact_rho1_m: contact,
    })
}

/// Mesh periods a faulty set's response repeats over (z_s for a sun tooth, z_p for a
/// planet's, z_r for a ring tooth's; 1 without a fault that changes its tooth): what its
/// dynamics records (`gearwear dynamics`, a sweep of dynamics); an input problem naming
/// the keys when its samples (`samples_per_period` each) pass
/// [`MAX_FAULT_PERIOD_SAMPLES`]. The ring sensor's longer record is checked by
/// [`fault_periods`] where a sensor hears it.
pub fn fault_period(
    section: &crate::config::planetary::PlanetarySection,
    samples_per_period: u64,
) -> Result<u64, ModelError> {
    let Some(f) = section.active_fault() else {
        return Ok(1);
    };
    let z = |v: i64| u64::try_from(v.max(1)).unwrap_or(1);
    let (key, p) = match f.gear {
        FaultyGear::Sun => ("planetary.teeth_sun", z(section.teeth_sun)),
        FaultyGear::Planet => ("planetary.teeth_planet", z(section.teeth_planet)),
        FaultyGear::Ring => ("planetary.teeth_ring", z(section.teeth_ring)),
    };
    match p.checked_mul(samples_per_period.max(1)) {
        Some(s) if s <= MAX_FAULT_PERIOD_SAMPLES => Ok(p),
        _ => Err(ModelError(vec![format!(
            "`planetary.fault.gear` = \"{}\" with `{key}` = {p} and `numerics.steps_per_mesh_period` = {samples_per_period}: the fault's response repeats over {p} mesh periods, beyond the limit of {MAX_FAULT_PERIOD_SAMPLES} samples: give fewer steps per mesh period or a member with fewer teeth",
            f.gear.name()
        )])),
    }
}

/// The fault's period ([`fault_period`]) and the ring sensor's record, lcm(that, z_r)
/// mesh periods (the planets' angles to the sensor repeat once per carrier revolution
/// relative to the ring, z_r mesh periods), in checked arithmetic; an input problem
/// naming the keys when either period's samples (`samples_per_period` each) pass
/// [`MAX_FAULT_PERIOD_SAMPLES`] (`gearwear signals` of a set checks it before it runs).
pub fn fault_periods(
    section: &crate::config::planetary::PlanetarySection,
    samples_per_period: u64,
) -> Result<(u64, u64), ModelError> {
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
        _ => Err(ModelError(vec![format!(
            "`planetary.fault.gear` = \"{}\" with {}`planetary.teeth_ring` = {zr} and `numerics.steps_per_mesh_period` = {samples_per_period}: the fault's response repeats over {p} mesh periods and the ring sensor's record over lcm({p}, {zr}) = {} mesh periods, {} samples, beyond the limit of {MAX_FAULT_PERIOD_SAMPLES}: give fewer steps per mesh period or a member with fewer teeth",
            f.gear.name(),
            match f.gear {
                FaultyGear::Ring => String::new(),
                g => format!("`planetary.teeth_{}` = {p}, ", g.name()),
            },
            record.map_or("more than 2^64".to_string(), |r| r.to_string()),
            samples.map_or("more than 2^64".to_string(), |s| s.to_string()),
        )])),
    }
}
