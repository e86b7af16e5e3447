//! The wear study of a planetary set (docs/MODEL.md 12.9): the loop of
//! `study::wear_loop` and `study::train_wear` over every mesh of the set
//! (`study::planetary_wear`).
//!
//! One steady response of the whole set (dynamic, or the quasi-static equilibrium at every
//! instant) feeds every mesh's Archard integral. The study counts input cycles
//! (revolutions of the input member); mesh j's pinion turns c_j times relative to the
//! carrier per input cycle (`PlanetaryWearModel::pinion_cycles_per_input`), so a block of
//! n input cycles adds n c_j times mesh j's wear per pinion cycle to it.
//! `wear.block_cycles` (m) and `wear.total_cycles` are input cycles.
//!
//! The threshold rule of eq. 17 holds per member flank: the block is cut to the whole
//! number of input cycles after which no point of any flank (the sun's, whose wear sums
//! its N meshes'; each planet's two; the ring's) has gained more than epsilon^m
//! (`wear_loop::block_length`), and the update records the flank that cut it. A mesh out
//! of contact for more than `wear_loop::MAX_CONTACT_LOSS_FRACTION` of the period, or a
//! response not found, stops the run (the records so far are kept).

use super::planetary_teeth::{faulty_teeth, teeth_increments, FaultyTeeth};
use super::planetary_wear::{member_flanks, new_teeth, wear_gaps, MemberFlank, PlanetaryWearModel};
use super::wear_loop::{
    fastest_block, StopKind, UpdateRecord, WearMode, WearStop, MAX_CONTACT_LOSS_FRACTION,
};
use crate::dynamics::summary::ResponseSummary;
use crate::wear::{WearIncrement, WearState};

/// One update of the set: every mesh's record at one count of input cycles.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanetaryUpdate {
    /// Revolutions of the input member.
    pub input_cycles: f64,
    /// Every mesh's record (sun meshes 1..N, then ring meshes), each as a single pair's
    /// update record ([`mesh_record`]): what a mesh's checkpoint log holds.
    pub meshes: Vec<UpdateRecord>,
    /// The member flank (index into [`PlanetaryUpdate::flanks`]) whose threshold cut the
    /// block that led here; None when it was m cycles or what remained of the total.
    pub limited_by: Option<usize>,
}

impl PlanetaryUpdate {
    /// Every member flank at this update (`planetary_wear::member_flanks`).
    pub fn flanks(&self, model: &PlanetaryWearModel) -> Vec<MemberFlank> {
        let wears: Vec<WearState> = self.meshes.iter().map(|m| m.wear.clone()).collect();
        let inc: Vec<WearIncrement> = self.meshes.iter().map(|m| m.increment()).collect();
        member_flanks(model, &wears, &inc)
    }
}

/// A planetary set's wear run: its mode and every update so far.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanetaryWearRun {
    /// Dynamic or quasi-static.
    pub mode: WearMode,
    /// Every update so far, the new set's first.
    pub updates: Vec<PlanetaryUpdate>,
    /// Set when the run stopped before the case's total cycles.
    pub stopped: Option<WearStop>,
}

impl PlanetaryWearRun {
    /// A run in `mode` with no update yet.
    pub fn new(mode: WearMode) -> Self {
        Self {
            mode,
            updates: Vec::new(),
            stopped: None,
        }
    }
}

impl PlanetaryWearRun {
    /// Every tooth of the faulty member's depth at the run's last update
    /// (`planetary_teeth::faulty_teeth`); None without a fault.
    pub fn faulty_teeth(&self, model: &PlanetaryWearModel) -> Option<FaultyTeeth> {
        let updates: Vec<(f64, &[UpdateRecord])> = self
            .updates
            .iter()
            .map(|u| (u.input_cycles, u.meshes.as_slice()))
            .collect();
        faulty_teeth(model, &updates)
    }
}

/// The update of `wears` at `input_cycles`: the set's response and every mesh's record;
/// Err(reason, kind) when the response is not found or a mesh leaves the model's domain.
pub fn update_of(
    model: &PlanetaryWearModel,
    mode: WearMode,
    (input_cycles, limited_by): (f64, Option<usize>),
    wears: Vec<WearState>,
) -> Result<PlanetaryUpdate, (String, StopKind)> {
    let gaps = wear_gaps(model, &wears);
    let h = model
        .force_history(mode == WearMode::Dynamic, &gaps)
        .map_err(|e| (e.to_string(), StopKind::Numerical))?;
    let samples = h.forces_n.len().max(1) as f64;
    // A force that is not finite would pass as contact and wear nothing (the Hertz
    // contact zeroes it): the response is refused instead.
    if h.forces_n.iter().flatten().any(|x| !x.is_finite()) {
        return Err((
            format!("at {input_cycles:.0} input cycles a mesh force of the set's response is not finite"),
            StopKind::Numerical,
        ));
    }
    let mut meshes = Vec::with_capacity(wears.len());
    for (j, wear) in wears.into_iter().enumerate() {
        let f: Vec<f64> = h.forces_n.iter().map(|s| s[j]).collect();
        let loss = f.iter().filter(|x| **x <= 0.0).count() as f64 / samples;
        if loss > MAX_CONTACT_LOSS_FRACTION {
            let (kind, p) = model.kind_of(j);
            return Err((
                format!(
                    "at {input_cycles:.0} input cycles planet {}'s {} mesh is out of contact for {:.0} % of the mesh period (more than {:.0} %): the wear model of a steady contact no longer applies",
                    p + 1,
                    ["sun", "ring"][kind],
                    100.0 * loss,
                    100.0 * MAX_CONTACT_LOSS_FRACTION
                ),
                StopKind::ModelValidity,
            ));
        }
        let mut increment = model.mesh_increment(j, &h, &gaps[j]);
        increment.teeth = teeth_increments(model, j, &h, &gaps[j]);
        meshes.push(mesh_record(wear, increment, &f));
    }
    Ok(PlanetaryUpdate {
        input_cycles,
        meshes,
        limited_by,
    })
}

/// A mesh's record at an update, in the single pair's form (`wear_loop::UpdateRecord`, so
/// that its checkpoint log is an ordinary one: `store::part_logs`): its wear, its
/// increment per pinion cycle (with a tooth fault, on the faulty member's meshes, every
/// tooth's: `planetary_teeth::teeth_increments`), and of its response summary the mean, largest and
/// smallest force `forces_n` (N, over the period's samples) and their dynamic factor
/// (largest / mean; 0 for a mesh that carries nothing). The rest is left empty: the set's
/// model has no friction (roughness 0, no friction figures), no transmission error per
/// mesh, keeps no path loads (the figures read the wear profiles) and starts every
/// steady state afresh (no end state).
pub fn mesh_record(wear: WearState, increment: WearIncrement, forces_n: &[f64]) -> UpdateRecord {
    let samples = forces_n.len().max(1) as f64;
    let mean = forces_n.iter().sum::<f64>() / samples;
    let max = forces_n.iter().fold(0.0_f64, |a, b| a.max(*b));
    let min = forces_n.iter().fold(f64::INFINITY, |a, b| a.min(*b));
    UpdateRecord {
        wear,
        roughness_um: 0.0,
        summary: ResponseSummary {
            mesh_force_mean_n: mean,
            mesh_force_max_n: max,
            mesh_force_min_n: if min.is_finite() { min } else { 0.0 },
            dynamic_factor: if mean > 0.0 { max / mean } else { 0.0 },
            ..Default::default()
        },
        increment_pinion_m: increment.pinion_m,
        increment_gear_m: increment.gear_m,
        increment_teeth: increment.teeth,
        increment_slices: None,
        path_rho1_m: Vec::new(),
        path_load_n: Vec::new(),
        end_state: None,
    }
}

/// The block after `last` (paper eq. 17 per member flank, see the module docs): the input
/// cycles it reaches, the flank that cut it, and every mesh's wear at its end; None when
/// the total is reached.
pub fn next_block(
    model: &PlanetaryWearModel,
    wear: &crate::config::case::WearSection,
    last: &PlanetaryUpdate,
) -> Option<(f64, Option<usize>, Vec<WearState>)> {
    let remaining = wear.total_cycles - last.input_cycles;
    if remaining <= 0.5 {
        return None;
    }
    let (n, limited_by) = fastest_block(
        last.flanks(model)
            .iter()
            .map(|f| f.rate_m_per_input.iter().fold(0.0_f64, |a, b| a.max(*b))),
        wear,
        remaining,
    );
    let wears = last
        .meshes
        .iter()
        .enumerate()
        .map(|(j, r)| {
            let mut s = r.wear.clone();
            let c = model.pinion_cycles_per_input[model.kind_of(j).0];
            s.advance(&r.increment(), n * c);
            s
        })
        .collect();
    Some((last.input_cycles + n, limited_by, wears))
}

/// Run a planetary set's wear study in `mode` to the case's total input cycles;
/// `on_update` after every update (an error it returns stops the run). Only the first
/// response failing is an error; a later failure stops the run, keeping its updates.
pub fn run_planetary_wear(
    model: &PlanetaryWearModel,
    wear: &crate::config::case::WearSection,
    mut run: PlanetaryWearRun,
    on_update: &mut dyn FnMut(&PlanetaryWearRun) -> anyhow::Result<()>,
) -> anyhow::Result<PlanetaryWearRun> {
    if run.updates.is_empty() {
        let u = update_of(model, run.mode, (0.0, None), new_teeth(model))
            .map_err(|(e, _)| anyhow::anyhow!("the new set's response: {e}"))?;
        run.updates.push(u);
        on_update(&run)?;
    }
    while run.stopped.is_none() {
        let Some(last) = run.updates.last() else {
            break;
        };
        let Some((cycles, limited_by, wears)) = next_block(model, wear, last) else {
            break;
        };
        match update_of(model, run.mode, (cycles, limited_by), wears) {
            Ok(u) => run.updates.push(u),
            Err((reason, kind)) => {
                run.stopped = Some(WearStop {
                    cycles,
                    kind,
                    reason,
                })
            }
        }
        on_update(&run)?;
    }
    Ok(run)
}
