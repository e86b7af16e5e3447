//! The wear study of a gear train (`[[stage]]`): the loop of `study::wear_loop` over
//! every mesh of the train (docs/MODEL.md, "Wear in a train").
//!
//! One response of the whole train feeds every mesh's Archard integral (paper eq.
//! 14-17): the dynamic response of the assembled train (each mesh excited by the others
//! through the shafts), or the quasi-static one (each mesh at its shaft's torque). The
//! study counts input cycles (revolutions of stage 1's pinion, the motor's shaft);
//! mesh k's pinion turns c_k times per input cycle (`TrainModel::cycle_factors`, from
//! the train's operating point, computed once), so a block of n input cycles adds
//! n c_k times mesh k's wear per pinion cycle to it. `wear.block_cycles` (m) and
//! `wear.total_cycles` are input cycles.
//!
//! The threshold rule of eq. 17 holds per mesh: the block is cut to the whole number of
//! input cycles after which no point of any mesh's profiles has gained more than
//! epsilon^m; the meshes share one update schedule (their dynamics are coupled), so the
//! mesh that wears fastest per input cycle sets it, and the update records which mesh
//! cut its block. A mesh whose teeth leave the model's domain (out of contact for more
//! than `MAX_CONTACT_LOSS_FRACTION` of its mesh period) stops the whole study, naming
//! the mesh; so does a response not found. A one-stage train is the single pair's loop,
//! number for number.
//!
//! A stage with a tooth fault (`fault.stage`, docs/MODEL.md 9.10) wears tooth by tooth,
//! as a single pair with a fault does: its wear state holds every tooth's profile, its
//! mesh in the train's response is built from them (`ToothInputs::mesh_for`), and the
//! response runs over the train's excitation period (the base periods after which the
//! faulty teeth meet again, `dynamics::grid::excitation_periods`), in which each tooth's
//! increments are taken from the engagements it meets (`wear::per_tooth`). The other
//! stages wear with every tooth alike, their path over the same period.

use super::model::Model;
use super::train::TrainModel;
use super::wear_loop::{
    fastest_block, mesh_record, solve_by, start_of, tooth_record, MeshWearParts, StopKind,
    UpdateRecord, WearMode, WearStop, MAX_CONTACT_LOSS_FRACTION,
};
use crate::dynamics::excitation::{ExternalError, PairGap};
use crate::dynamics::period_search::DynamicsError;
use crate::dynamics::quasi_static::solve_quasi_static;
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::steady::solve_steady_state_from;
use crate::dynamics::tooth_mesh::ToothMesh;
use crate::wear::WearState;

/// One update of a train: every mesh's record at one count of input cycles.
#[derive(Debug, Clone, PartialEq)]
pub struct TrainUpdate {
    /// Revolutions of the input (stage 1's pinion).
    pub input_cycles: f64,
    /// Each mesh's record (stage order); its `wear.cycles` are its own pinion's
    /// revolutions. Mesh 0's holds the train's periodic end state (the warm start).
    pub meshes: Vec<UpdateRecord>,
    /// The mesh (0-based) whose threshold cut the block that led here; None when the
    /// block was m cycles or what remained of the total.
    pub limited_by: Option<usize>,
}

/// A train's wear run: its mode and every update so far.
#[derive(Debug, Clone, PartialEq)]
pub struct TrainWearRun {
    /// The solver feeding the wear model.
    pub mode: WearMode,
    /// The updates so far, the first on new teeth.
    pub updates: Vec<TrainUpdate>,
    /// Set when the run stopped before the case's total cycles.
    pub stopped: Option<WearStop>,
}

impl TrainWearRun {
    /// A run in `mode` with no update yet (it starts from new teeth).
    pub fn new(mode: WearMode) -> Self {
        Self {
            mode,
            updates: Vec::new(),
            stopped: None,
        }
    }

    /// Mesh `m`'s records, one per update.
    pub fn mesh_records(&self, m: usize) -> Vec<UpdateRecord> {
        self.updates.iter().map(|u| u.meshes[m].clone()).collect()
    }

    /// The mesh (0-based) that limits the life: the deepest wear (either flank) at the
    /// last update, and that depth, m; None before any update.
    pub fn limiting_mesh(&self) -> Option<(usize, f64)> {
        let last = self.updates.last()?;
        limiting_of(last.meshes.iter().map(|r| &r.wear))
    }
}

/// The mesh (0-based) with the deepest wear (either flank) of the meshes' `wears` and
/// that depth, m (the last of equals); None for no mesh, and while no mesh has worn (new
/// teeth: every mesh's depth 0, none deeper than another).
pub fn limiting_of<'a>(wears: impl Iterator<Item = &'a WearState>) -> Option<(usize, f64)> {
    wears
        .map(|w| w.max_pinion_m().max(w.max_gear_m()))
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .filter(|(_, depth)| *depth > 0.0)
}

/// What the update after an update gives.
#[derive(Debug, Clone, PartialEq)]
pub enum TrainNext {
    /// A new update.
    Update(Box<TrainUpdate>),
    /// The run stops before this update (it is not recorded).
    Stop(WearStop),
    /// The total input cycles are reached.
    Finished,
}

/// The response of the train with each mesh worn as `wears` says (stage order), each
/// mesh's roughness that of its own wear, a faulty stage's mesh built from its teeth's
/// own wear (the gap of its mean profiles beside it, as the single pair's); retried as
/// `wear_loop::solve_by`.
pub fn solve_train(
    model: &Model,
    train: &TrainModel,
    mode: WearMode,
    wears: &[WearState],
    start: Option<&[f64]>,
) -> Result<DynamicResponse, DynamicsError> {
    let gaps: Vec<PairGap> = wears
        .iter()
        .zip(&train.stages)
        .map(|(w, s)| w.pair_gap(&s.grid))
        .collect();
    let rough: Vec<f64> = wears.iter().map(|w| model.roughness_for(w)).collect();
    let worn_teeth: Vec<Option<ToothMesh>> = wears
        .iter()
        .zip(&train.stages)
        .map(|(w, s)| s.tooth_inputs.as_ref().map(|t| t.mesh_for(w)))
        .collect();
    let teeth: Vec<Option<&ToothMesh>> = worn_teeth.iter().map(Option::as_ref).collect();
    let none = ExternalError::none();
    let gap_refs: Vec<&PairGap> = gaps.iter().collect();
    let ext = vec![&none; wears.len()];
    let sys = train.system_worn(
        &model.case,
        &model.friction,
        model.effective_modulus_pa,
        &gap_refs,
        &ext,
        (&rough, &teeth),
    );
    let steps = model.settings.steps_per_mesh_period;
    solve_by(
        &model.settings,
        mode,
        start,
        &|| solve_quasi_static(&sys, steps),
        &|s, settings| solve_steady_state_from(&sys, settings, s),
    )
}

/// The update of `wears` at `input_cycles` from the response `r`: each mesh's record (a
/// faulty stage's per tooth, over its mesh periods in the response's excitation period).
pub(crate) fn update_of(
    model: &Model,
    train: &TrainModel,
    mode: WearMode,
    (input_cycles, limited_by): (f64, Option<usize>),
    wears: Vec<WearState>,
    r: &DynamicResponse,
) -> TrainUpdate {
    let single = train.stages.len() == 1;
    let counts = train.mesh_counts();
    let meshes = wears
        .into_iter()
        .enumerate()
        .map(|(m, wear)| {
            let s = &train.stages[m];
            let parts = MeshWearParts {
                grid: &s.grid,
                teeth: [s.pair.pinion.teeth, s.pair.gear.teeth],
                coefficient_m2_per_n: model.case.wear.coefficient_m2_per_n,
            };
            // A one-stage train's summary is the single pair's (same numbers).
            let summary = if single {
                crate::dynamics::summary::ResponseSummary::of(r)
            } else {
                train.mesh_summary(r, m)
            };
            let roughness = model.roughness_for(&wear);
            if s.tooth_inputs.is_some() {
                let periods = counts[m] * r.excitation_periods.max(1);
                return tooth_record(&parts, (m, periods), mode, wear, roughness, summary, r);
            }
            mesh_record(&parts, m, mode, wear, roughness, summary, r)
        })
        .collect();
    TrainUpdate {
        input_cycles,
        meshes,
        limited_by,
    }
}

/// Every mesh's new teeth (stage order): where a run starts, at input cycle 0. A faulty
/// stage's state has a profile per tooth (`WearState::per_tooth`), the others one.
pub fn new_teeth(train: &TrainModel) -> Vec<WearState> {
    train
        .stages
        .iter()
        .map(|s| match s.tooth_inputs {
            Some(_) => WearState::per_tooth(s.grid.len(), s.pair.pinion.teeth, s.pair.gear.teeth),
            None => WearState::new(s.grid.len()),
        })
        .collect()
}

/// The block after an update: the input cycles it reaches, the mesh whose threshold cut
/// it, and every mesh's wear at its end.
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    /// Input cycles at the end of the block.
    pub input_cycles: f64,
    /// The mesh (0-based) whose threshold cut the block; None when it was m cycles or
    /// what remained of the total.
    pub limited_by: Option<usize>,
    /// Each mesh's wear at the end of the block (stage order).
    pub wears: Vec<WearState>,
}

/// The block after `last` (paper eq. 17 per mesh, see the module docs): n input cycles,
/// m cut to the fastest mesh's threshold and to the total; mesh k's wear advanced by
/// n c_k of its pinion cycles at the rate `last` holds. None when the total is reached.
/// The one step of the loop that [`next_train_update`] and the replay of a checkpoint
/// (`study::train_wear_check`) share.
pub fn next_block(model: &Model, train: &TrainModel, last: &TrainUpdate) -> Option<Block> {
    let w = &model.case.wear;
    let remaining = w.total_cycles - last.input_cycles;
    if remaining <= 0.5 {
        return None;
    }
    let c = train.cycle_factors();
    // Each mesh's largest wear per input cycle; the fastest sets the block.
    let (n, limited_by) = fastest_block(
        last.meshes
            .iter()
            .zip(&c)
            .map(|(r, ck)| r.increment().max_m() * ck),
        w,
        remaining,
    );
    let wears: Vec<WearState> = last
        .meshes
        .iter()
        .zip(&c)
        .map(|(r, ck)| {
            let mut s = r.wear.clone();
            s.advance(&r.increment(), n * ck);
            s
        })
        .collect();
    let input_cycles = last.input_cycles + n;
    Some(Block {
        input_cycles,
        limited_by,
        wears,
    })
}

/// The update after `last` (`None`: new teeth at cycle 0), the train's step of
/// `wear_loop::next_update`. Only the first update's failure is an error.
pub fn next_train_update(
    model: &Model,
    train: &TrainModel,
    mode: WearMode,
    last: Option<&TrainUpdate>,
) -> Result<TrainNext, DynamicsError> {
    let Some(last) = last else {
        let wears = new_teeth(train);
        let r = solve_train(model, train, mode, &wears, None)?;
        let u = update_of(model, train, mode, (0.0, None), wears, &r);
        return Ok(TrainNext::Update(Box::new(u)));
    };
    let Some(block) = next_block(model, train, last) else {
        return Ok(TrainNext::Finished);
    };
    let start = start_of(&last.meshes[0]);
    Ok(respond_to_block(
        model,
        train,
        mode,
        block,
        start.as_deref(),
    ))
}

/// The train's response to the wear at the end of `block` (warm-started from `start`)
/// and the update it gives, or the stop: a mesh out of contact for more than
/// `MAX_CONTACT_LOSS_FRACTION` of its mesh period, or no steady state found.
pub fn respond_to_block(
    model: &Model,
    train: &TrainModel,
    mode: WearMode,
    block: Block,
    start: Option<&[f64]>,
) -> TrainNext {
    let Block {
        input_cycles,
        limited_by,
        wears,
    } = block;
    match solve_train(model, train, mode, &wears, start) {
        Ok(r) => match (0..wears.len()).find(|m| r.contact_loss_fraction_of(*m) > MAX_CONTACT_LOSS_FRACTION) {
            Some(m) => TrainNext::Stop(WearStop {
                cycles: input_cycles,
                kind: StopKind::ModelValidity,
                reason: format!(
                    "at {input_cycles:.0} input cycles (stage {}: maximum pinion wear {:.2} µm) the teeth of stage {} are out of contact for {:.0} % of its mesh period (more than {:.0} %): the wear model of a steady contact no longer applies",
                    m + 1,
                    wears[m].max_pinion_m() * 1e6,
                    m + 1,
                    100.0 * r.contact_loss_fraction_of(m),
                    100.0 * MAX_CONTACT_LOSS_FRACTION
                ),
            }),
            None => TrainNext::Update(Box::new(update_of(
                model,
                train,
                mode,
                (input_cycles, limited_by),
                wears,
                &r,
            ))),
        },
        Err(e) => TrainNext::Stop(WearStop {
            cycles: input_cycles,
            kind: StopKind::Numerical,
            reason: format!(
                "at {input_cycles:.0} input cycles no steady state of the train was found, even from the static equilibrium with a 10x tighter numerics.integration_tolerance and 2x the numerics.steps_per_mesh_period: {e}"
            ),
        }),
    }
}

/// Run (or continue) a train's wear study to the case's total input cycles;
/// `on_update` after every update (progress; an error it returns stops the run).
pub fn run_train_wear(
    model: &Model,
    train: &TrainModel,
    mut run: TrainWearRun,
    on_update: &mut dyn FnMut(&TrainWearRun) -> anyhow::Result<()>,
) -> anyhow::Result<TrainWearRun> {
    loop {
        let next = match run.updates.last() {
            None => next_train_update(model, train, run.mode, None)?,
            Some(_) if run.stopped.is_some() => break,
            Some(u) => next_train_update(model, train, run.mode, Some(u))?,
        };
        match next {
            TrainNext::Finished => break,
            TrainNext::Stop(s) => run.stopped = Some(s),
            TrainNext::Update(u) => run.updates.push(*u),
        }
        on_update(&run)?;
    }
    Ok(run)
}
