//! The faulty member's teeth one by one over a planetary set's wear run (docs/MODEL.md
//! 12.16): every tooth's wear per pinion cycle on each mesh that meets it, from its own
//! contacts over the fault's period (`PlanetaryWearModel::tooth_increment`), kept in each
//! mesh's update record (`UpdateRecord::increment_teeth`, so a checkpoint holds it), and
//! every tooth's depth accumulated over the run's blocks from them, as the member's mean
//! profile is (paper eq. 17, `WearState::advance`: the rate of an update held over the
//! block after it).
//!
//! The mean over the teeth is the member's mean (`planetary_wear` takes each mesh's wear
//! as the mean of the fault period's mesh periods, the same samples grouped by period
//! instead of by tooth): the teeth's depths are a partition of the member's wear, not a
//! second model of it. They do not feed back: each pair's wear gap is the members' mean
//! profiles' (docs/MODEL.md 12.15), so a tooth that wears less than its neighbours is not
//! loaded more for it.

use super::planetary_wear::{ForceHistory, PlanetaryWearModel};
use super::wear_loop::UpdateRecord;
use crate::dynamics::excitation::PairGap;
use crate::dynamics::planetary_dynamic::MeshStiffnessSource;
use crate::stiffness::planetary_mesh::FaultMember;
use crate::wear::{ToothWear, WearIncrement};
use std::ops::Range;

/// One flank of the faulty member and the meshes that wear it.
#[derive(Debug, Clone, PartialEq)]
pub struct FaultyFlank {
    /// The flank as `planetary_wear::member_flanks` names it: "sun", "sun_side",
    /// "ring_side" or "ring".
    pub flank: &'static str,
    /// The meshes that wear it (module order).
    pub meshes: Range<usize>,
    /// Whether the member is those meshes' pinion (else their gear).
    pub pinion: bool,
    /// Those meshes' pinion cycles per input-member revolution.
    pub cycles_per_input: f64,
}

/// The faulty member of a set with a tooth fault: which, its faulty tooth, its teeth and
/// its flanks with the meshes that wear each; None without a fault.
pub fn faulty_member(
    model: &PlanetaryWearModel,
) -> Option<(FaultMember, usize, usize, Vec<FaultyFlank>)> {
    let MeshStiffnessSource::Tables(m) = &model.dynamics.model.source else {
        return None;
    };
    let f = m.fault()?;
    let n = model.planets();
    let [cs, cp] = model.pinion_cycles_per_input;
    let set = &model.dynamics.study.set;
    let flank = |flank, meshes, pinion, cycles_per_input| FaultyFlank {
        flank,
        meshes,
        pinion,
        cycles_per_input,
    };
    let (z, flanks) = match f.member {
        FaultMember::Sun => (set.teeth_sun(), vec![flank("sun", 0..n, true, cs)]),
        FaultMember::Planet(p) => (
            set.teeth_planet(),
            vec![
                flank("sun_side", p..p + 1, false, cs),
                flank("ring_side", n + p..n + p + 1, true, cp),
            ],
        ),
        FaultMember::Ring => (set.teeth_ring(), vec![flank("ring", n..2 * n, false, cp)]),
    };
    Some((f.member, f.tooth, z, flanks))
}

/// Every tooth of the faulty member's wear per pinion cycle on mesh `j` over the history
/// `h` (the mesh's gap `gap`), each from its own contacts
/// (`PlanetaryWearModel::teeth_increments`; zero for a
/// tooth that mesh never loads): a [`ToothWear`] with the member's side (`pinion_m` for
/// the mesh's pinion, `gear_m` for its gear) holding one profile per tooth and the other
/// side empty; None without a fault or for a mesh that never meets the member.
pub fn teeth_increments(
    model: &PlanetaryWearModel,
    j: usize,
    h: &ForceHistory,
    gap: &PairGap,
) -> Option<ToothWear> {
    let (_, _, z, flanks) = faulty_member(model)?;
    let f = flanks.iter().find(|f| f.meshes.contains(&j))?;
    let points = model.grids[model.kind_of(j).0].len();
    let teeth: Vec<Vec<f64>> = model
        .teeth_increments(j, h, gap)?
        .into_iter()
        .map(|i| match i {
            Some(i) if f.pinion => i.pinion_m,
            Some(i) => i.gear_m,
            None => vec![0.0; points],
        })
        .collect();
    debug_assert_eq!(teeth.len(), z);
    Some(if f.pinion {
        ToothWear {
            pinion_m: teeth,
            gear_m: Vec::new(),
        }
    } else {
        ToothWear {
            pinion_m: Vec::new(),
            gear_m: teeth,
        }
    })
}

/// What is wrong with mesh `j`'s per-tooth increments `teeth` for `model` (see
/// [`teeth_increments`]: present exactly on the faulty member's meshes, one profile of the
/// grid's points per tooth on the member's side, finite and >= 0), if anything.
pub(crate) fn teeth_problem(
    model: &PlanetaryWearModel,
    j: usize,
    teeth: Option<&ToothWear>,
) -> Option<String> {
    let member = faulty_member(model);
    let flank = member
        .as_ref()
        .and_then(|(_, _, z, fl)| Some((*z, fl.iter().find(|f| f.meshes.contains(&j))?)));
    let (z, f, t) = match (flank, teeth) {
        (None, None) => return None,
        (None, Some(_)) => {
            return Some("holds per-tooth wear, but this mesh never meets a faulty tooth".into())
        }
        (Some(_), None) => {
            return Some("holds no per-tooth wear, but this mesh meets the faulty member".into())
        }
        (Some((z, f)), Some(t)) => (z, f, t),
    };
    let (own, other) = if f.pinion {
        (&t.pinion_m, &t.gear_m)
    } else {
        (&t.gear_m, &t.pinion_m)
    };
    let points = model.grids[model.kind_of(j).0].len();
    let sound = |p: &Vec<f64>| p.len() == points && p.iter().all(|x| x.is_finite() && *x >= 0.0);
    (own.len() != z || !other.is_empty() || !own.iter().all(sound)).then(|| {
        format!("its per-tooth wear is not {z} profiles of {points} points, finite and >= 0, on the faulty member's side")
    })
}

/// The wear per input-member revolution of tooth `tooth` of the faulty member from its
/// own contacts over the history `h` (the gaps `gaps`, module order), per flank as
/// `planetary_wear::member_flanks` names them: the sun's (its N sun meshes' pinion wear),
/// a planet's sun-side and ring-side flank, the ring's (its N ring meshes' gear wear),
/// each at its grid's points (docs/MODEL.md 12.15); None without a tooth fault.
pub fn tooth_rates(
    model: &PlanetaryWearModel,
    h: &ForceHistory,
    gaps: &[PairGap],
    tooth: usize,
) -> Option<Vec<(&'static str, Vec<f64>)>> {
    let (_, _, _, flanks) = faulty_member(model)?;
    flanks
        .iter()
        .map(|f| {
            let incs: Vec<WearIncrement> = f
                .meshes
                .clone()
                .map(|j| model.tooth_increment(j, h, &gaps[j], tooth))
                .collect::<Option<_>>()?;
            let side = |i: &WearIncrement| {
                if f.pinion {
                    i.pinion_m.clone()
                } else {
                    i.gear_m.clone()
                }
            };
            let v: Vec<Vec<f64>> = incs.iter().map(side).collect();
            Some((f.flank, summed(&v, f.cycles_per_input)))
        })
        .collect()
}

/// The point-by-point sum of equal-length profiles, times `c`.
fn summed(profiles: &[Vec<f64>], c: f64) -> Vec<f64> {
    let len = profiles.first().map_or(0, Vec::len);
    let mut s = vec![0.0; len];
    for p in profiles {
        for (a, b) in s.iter_mut().zip(p) {
            *a += b;
        }
    }
    s.into_iter().map(|x| x * c).collect()
}

/// Every tooth of the faulty member's wear at the end of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct FaultyTeeth {
    /// The member: "sun", "planet_N" (1-based) or "ring".
    pub member: String,
    /// The faulty tooth (0-based).
    pub tooth: usize,
    /// Per flank of the member (`FaultyFlank::flank`): every tooth's depth at the grid
    /// points, m (tooth, point).
    pub flanks: Vec<(&'static str, Vec<Vec<f64>>)>,
}

/// Every tooth of the faulty member's depth after the updates `updates` (each its input
/// cycles and every mesh's record, module order): sum over the blocks of each tooth's
/// rate at the block's start (the sum over the flank's meshes of its per-tooth increment
/// times their pinion cycles per input cycle) times the block's input cycles, as each
/// mesh's wear advances (paper eq. 17). None without a fault, or when a record before the
/// last lacks its per-tooth increments.
pub fn faulty_teeth(
    model: &PlanetaryWearModel,
    updates: &[(f64, &[UpdateRecord])],
) -> Option<FaultyTeeth> {
    let (member, tooth, z, flanks) = faulty_member(model)?;
    let member = match member {
        FaultMember::Sun => "sun".to_string(),
        FaultMember::Planet(p) => format!("planet_{}", p + 1),
        FaultMember::Ring => "ring".to_string(),
    };
    let mut out = Vec::new();
    for f in &flanks {
        let points = model.grids[model.kind_of(f.meshes.start).0].len();
        let mut depth = vec![vec![0.0; points]; z];
        for w in updates.windows(2) {
            let block = w[1].0 - w[0].0;
            for j in f.meshes.clone() {
                let teeth = w[0].1.get(j)?.increment_teeth.as_ref()?;
                let side = if f.pinion {
                    &teeth.pinion_m
                } else {
                    &teeth.gear_m
                };
                for (d, rate) in depth.iter_mut().zip(side) {
                    for (h, r) in d.iter_mut().zip(rate) {
                        *h += block * f.cycles_per_input * r;
                    }
                }
            }
        }
        out.push((f.flank, depth));
    }
    Some(FaultyTeeth {
        member,
        tooth,
        flanks: out,
    })
}
