//! The records of one physical state: its wear state from the trajectory, the steady
//! response at the state's operating point, the noise-free record once, then one noisy
//! record per realisation with its labels and indicators.

use super::design::Condition;
use super::plan::{record_seed, Plan, StateIndex};
use super::trajectory::Trajectory;
use crate::config::teeth::Member;
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::period_search::DynamicsError;
use crate::signals::analysis::{analyse, ChannelIndicators};
use crate::signals::files::stored_record;
use crate::signals::record::{add_noise, Record};
use crate::signals::setup::ChainSetup;
use crate::study::signal_record::{kinematics, periodic_record, train_meshes};
use crate::study::train_wear::{limiting_of, solve_train};
use crate::study::wear_loop::WearMode;
use crate::study::Model;
use crate::wear::WearState;
use serde::{Deserialize, Serialize};

/// The labels of a record: everything the study knows about it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RecordLabels {
    /// Record id (module docs of [`super::plan`]).
    pub record_id: usize,
    /// Signal file, relative to the dataset folder.
    pub file: String,
    /// The condition's name.
    pub condition: String,
    /// What the condition's case models (`design::fault_label`).
    pub fault: String,
    /// The design's grade of the fault (0 without one).
    pub severity: f64,
    /// The `[[fault]]` tables the record's case models, as the case gives them (kind,
    /// gear, tooth, sizes in the units their keys name); absent without a fault.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub faults: Vec<crate::config::teeth::FaultTable>,
    /// A planetary set's `[[planetary.fault]]` tables as the case gives them (member,
    /// planet, tooth, kind, sizes in the units their keys name; docs/MODEL.md 12.15);
    /// absent without one.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub planetary_faults: Vec<crate::config::planetary_fault::PlanetaryFault>,
    /// Index of the state along the condition's trajectory.
    pub trajectory_state: usize,
    /// Pinion load cycles of the state.
    pub cycles: f64,
    /// Deepest wear of the pinion profile at the state, µm.
    pub max_wear_pinion_um: f64,
    /// Deepest wear of the gear profile at the state, µm.
    pub max_wear_gear_um: f64,
    /// Maximum wear depth of each tooth, um (each tooth its own with a tooth-resolved
    /// mesh; all teeth alike in the identical-tooth model); empty for a train (its teeth
    /// are alike in each stage: each stage's in `stages`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub wear_pinion_tooth_um: Vec<f64>,
    /// Maximum wear depth of each gear tooth, µm (as the pinion's above).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub wear_gear_tooth_um: Vec<f64>,
    /// A gear train's stages at the state (stage order; empty for a single pair): each
    /// mesh's wear and cycles. For a train `cycles` are input cycles (stage 1's pinion)
    /// and `max_wear_pinion_um`, `max_wear_gear_um` the deepest of any stage.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stages: Vec<StageLabels>,
    /// A train's stage (1-based) whose mesh has the deepest wear at the state (either
    /// flank; the last of equals, as `gearwear wear` names the limiting mesh); absent
    /// while no mesh has worn (new teeth).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limiting_stage: Option<usize>,
    /// A planetary set's members at the state (`super::planetary`: the sun, planets 1..N,
    /// the ring; empty otherwise): each member's deepest wear and its teeth's load
    /// cycles. For a set `cycles` and `remaining_cycles` are input cycles (revolutions of
    /// the input member).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub members: Vec<super::planetary::MemberLabels>,
    /// A planetary set's deepest-worn member (`sun`, `planet<n>`, `ring`; the last of
    /// equals), the one that limits the set's life; absent while nothing has worn.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limiting_member: Option<String>,
    /// The design's failure limit on the deepest wear, µm.
    pub wear_limit_um: f64,
    /// Cycles from this state to failure (the deepest wear reaching the limit).
    pub remaining_cycles: f64,
    /// The failure was not reached within the trajectory: `remaining_cycles` is the
    /// cycles to the trajectory's end, a lower bound (right-censored).
    pub failure_censored: bool,
    /// Input (pinion) speed of the record, Hz.
    pub input_speed_hz: f64,
    /// Load torque of the record, N m.
    pub load_torque_nm: f64,
    /// Mesh frequency, Hz.
    pub mesh_hz: f64,
    /// Noise realisation r of the physical state (0-based).
    pub realisation: usize,
    /// Seed of the record's noise: a SplitMix64 hash of (design seed, record id), 53 bits.
    pub noise_seed: u64,
    /// Indicators of each channel of the record.
    pub indicators: Vec<ChannelIndicators>,
}

/// One stage of a gear train in a record's labels: its mesh's wear and cycles at the
/// state, its mesh frequency at the record's speed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StageLabels {
    /// The stage, 1-based (stage 1's pinion on the input shaft).
    pub stage: usize,
    /// Load cycles of the stage's pinion at the state (its own count: the input cycles
    /// times its revolutions per input revolution).
    pub pinion_cycles: f64,
    /// Deepest wear of the stage's pinion profile, µm.
    pub max_wear_pinion_um: f64,
    /// Deepest wear of the stage's gear profile, µm.
    pub max_wear_gear_um: f64,
    /// Deepest wear of the stage's mesh (either flank), µm.
    pub wear_max_um: f64,
    /// The stage's mesh frequency at the record's speed, Hz.
    pub mesh_hz: f64,
}

/// Everything the records of one physical state need.
pub struct StateInputs<'a> {
    /// The condition's case at the state's speed and load.
    pub model: &'a Model,
    /// The signal chain (transfer path, sensors, acquisition).
    pub setup: &'a ChainSetup,
    /// The condition recorded.
    pub condition: &'a Condition,
    /// The condition's wear trajectory, whose state at `cycles` is recorded.
    pub trajectory: &'a Trajectory,
    /// Cycles of the state.
    pub cycles: f64,
    /// The design's failure limit on the deepest wear, µm.
    pub wear_limit_um: f64,
    /// The design's seed (each record's noise seed derives from it).
    pub design_seed: u64,
}

/// Deepest wear of each of the `z` teeth of `member`, um: each tooth's own profile with
/// a tooth-resolved mesh, else the state's deepest (all teeth alike: the common profile's
/// of a spur pair, the deepest face slice's of a helical pair, `WearState::max_pinion_m`).
pub fn tooth_max_um(wear: &WearState, member: Member, z: usize) -> Vec<f64> {
    let um = |p: &[f64]| p.iter().fold(0.0_f64, |m, x| m.max(*x)) * 1e6;
    match (&wear.teeth, member) {
        (Some(t), Member::Pinion) => t.pinion_m.iter().map(|p| um(p)).collect(),
        (Some(t), Member::Gear) => t.gear_m.iter().map(|p| um(p)).collect(),
        (None, Member::Pinion) => vec![wear.max_pinion_m() * 1e6; z],
        (None, Member::Gear) => vec![wear.max_gear_m() * 1e6; z],
    }
}

/// Signal file of record `id`.
pub fn signal_file(id: usize) -> String {
    format!("signals/{id:07}.parquet")
}

/// The meshes' wear states at the state's cycles (stage order; one for a single pair).
fn state_wears(inp: &StateInputs) -> anyhow::Result<Vec<WearState>> {
    inp.trajectory.states_at(inp.cycles).ok_or_else(|| {
        anyhow::anyhow!(
            "state at {} cycles lies beyond the trajectory's end ({} cycles)",
            inp.cycles,
            inp.trajectory.end_cycles
        )
    })
}

/// The labels of record `realisation` of physical state `p` without its indicators
/// (left empty): everything the design and the wear trajectory give it (`wear`, the
/// state's [`wear_labels`], computed once per state), the same for every realisation
/// but the id, file and noise seed.
fn labels_without_indicators(
    inp: &StateInputs,
    plan: &Plan,
    (p, index): (usize, StateIndex),
    wear: &WearLabels,
    realisation: usize,
) -> RecordLabels {
    let case = &inp.model.case;
    let (remaining, censored) = inp.trajectory.remaining(inp.cycles);
    let id = plan.record_id(p, realisation);
    RecordLabels {
        record_id: id,
        file: signal_file(id),
        condition: inp.condition.name.clone(),
        fault: inp.condition.fault.clone(),
        severity: inp.condition.severity,
        faults: case.fault.iter().map(|f| f.table().clone()).collect(),
        planetary_faults: Vec::new(),
        trajectory_state: index.state,
        cycles: inp.cycles,
        max_wear_pinion_um: wear.max_pinion_um,
        max_wear_gear_um: wear.max_gear_um,
        wear_pinion_tooth_um: wear.pinion_tooth_um.clone(),
        wear_gear_tooth_um: wear.gear_tooth_um.clone(),
        stages: wear.stages.clone(),
        limiting_stage: wear.limiting_stage,
        members: Vec::new(),
        limiting_member: None,
        wear_limit_um: inp.wear_limit_um,
        remaining_cycles: remaining,
        failure_censored: censored,
        input_speed_hz: case.operating.input_speed_hz,
        load_torque_nm: case.operating.load_torque_nm,
        mesh_hz: kinematics(inp.model).mesh_hz(),
        realisation,
        noise_seed: record_seed(inp.design_seed, id),
        indicators: Vec::new(),
    }
}

/// The labels of every record of physical state `p` but their indicators (left empty),
/// as [`state_records`] gives them, without solving the dynamics: what a resume and a
/// merge compare every kept record's labels with (docs/RELIABILITY.md, "Datasets").
pub fn expected_labels(
    inp: &StateInputs,
    plan: &Plan,
    p: usize,
    index: StateIndex,
) -> anyhow::Result<Vec<RecordLabels>> {
    let wear = wear_labels(inp.model, &state_wears(inp)?);
    Ok((0..plan.realisations)
        .map(|r| labels_without_indicators(inp, plan, (p, index), &wear, r))
        .collect())
}

/// Compute the records of physical state `p`, handing each to `emit` as it is made.
pub fn state_records(
    inp: &StateInputs,
    plan: &Plan,
    p: usize,
    index: StateIndex,
    emit: &mut dyn FnMut(RecordLabels, Record) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let wears = state_wears(inp)?;
    let r = match &inp.model.train {
        Some(t) => solve_train(inp.model, t, WearMode::Dynamic, &wears, None),
        None => inp.model.dynamic(&wears[0], &ExternalError::none()),
    }
    .map_err(|e: DynamicsError| anyhow::anyhow!("state {p} ({} cycles): {e}", inp.cycles))?;
    let periodic = periodic_record(inp.model, inp.setup, &r);
    let mut chain = inp.setup.chain.clone();
    let clean = periodic.render(&chain, record_samples(inp));
    let wear = wear_labels(inp.model, &wears);
    for realisation in 0..plan.realisations {
        let mut labels = labels_without_indicators(inp, plan, (p, index), &wear, realisation);
        chain.acquisition.noise_seed = labels.noise_seed;
        let mut rec = clean.clone();
        add_noise(&mut rec, &chain);
        rec.round_to_stored();
        labels.indicators = indicators_of(inp, &rec);
        emit(labels, rec)?;
    }
    Ok(())
}

/// Samples per channel of a record of `inp`'s state (the chain's record length at the
/// tachometer shaft's speed).
fn record_samples(inp: &StateInputs) -> usize {
    let chain = &inp.setup.chain;
    chain.samples(kinematics(inp.model).shaft_hz(chain.tachometer.shaft))
}

/// The indicators of `rec`, a record of `inp`'s state, as its labels give them.
fn indicators_of(inp: &StateInputs, rec: &Record) -> Vec<ChannelIndicators> {
    let (kin, chain) = (kinematics(inp.model), &inp.setup.chain);
    analyse(rec, &kin, &chain.tachometer, inp.setup.components)
        .iter()
        .map(|c| c.indicators())
        .collect()
}

/// The record stored in the Parquet bytes `signal` (a signal file of `inp`'s state,
/// `signals::files::record_parquet`) and its indicators recomputed from the stored
/// samples: the indicators its labels must hold, since a record's indicators are computed
/// from its samples as stored (`Record::round_to_stored`), and the samples its CSV twin
/// must hold. Fails when the file does not hold the design's channels and samples.
pub fn stored_indicators(
    inp: &StateInputs,
    signal: Vec<u8>,
) -> anyhow::Result<(Record, Vec<ChannelIndicators>)> {
    let acq = &inp.setup.chain.acquisition;
    let rec = stored_record(
        signal,
        &inp.setup.chain.path.sensors,
        acq.unit,
        record_samples(inp),
        acq.sampling_rate_hz,
    )?;
    let indicators = indicators_of(inp, &rec);
    Ok((rec, indicators))
}

/// The wear labels of a state (every record of it alike).
struct WearLabels {
    max_pinion_um: f64,
    max_gear_um: f64,
    pinion_tooth_um: Vec<f64>,
    gear_tooth_um: Vec<f64>,
    stages: Vec<StageLabels>,
    limiting_stage: Option<usize>,
}

/// The wear labels of the meshes' states `wears` (stage order; one for a single pair):
/// a single pair's deepest wear per flank and per tooth; a train's per stage, the
/// deepest of any stage per flank, and the limiting stage
/// (`train_wear::limiting_of`).
fn wear_labels(model: &Model, wears: &[WearState]) -> WearLabels {
    let Some(train) = &model.train else {
        let (z1, z2) = (model.pair.pinion.teeth, model.pair.gear.teeth);
        return WearLabels {
            max_pinion_um: wears[0].max_pinion_m() * 1e6,
            max_gear_um: wears[0].max_gear_m() * 1e6,
            pinion_tooth_um: tooth_max_um(&wears[0], Member::Pinion, z1),
            gear_tooth_um: tooth_max_um(&wears[0], Member::Gear, z2),
            stages: Vec::new(),
            limiting_stage: None,
        };
    };
    let kin = train_meshes(model);
    let stages: Vec<StageLabels> = wears
        .iter()
        .zip(&kin)
        .take(train.stages.len())
        .enumerate()
        .map(|(k, (w, kn))| StageLabels {
            stage: k + 1,
            pinion_cycles: w.cycles,
            max_wear_pinion_um: w.max_pinion_m() * 1e6,
            max_wear_gear_um: w.max_gear_m() * 1e6,
            wear_max_um: w.max_pinion_m().max(w.max_gear_m()) * 1e6,
            mesh_hz: kn.mesh_hz(),
        })
        .collect();
    let deepest = |f: &dyn Fn(&StageLabels) -> f64| stages.iter().map(f).fold(0.0, f64::max);
    WearLabels {
        max_pinion_um: deepest(&|s| s.max_wear_pinion_um),
        max_gear_um: deepest(&|s| s.max_wear_gear_um),
        pinion_tooth_um: Vec::new(),
        gear_tooth_um: Vec::new(),
        limiting_stage: limiting_of(wears.iter()).map(|(m, _)| m + 1),
        stages,
    }
}
