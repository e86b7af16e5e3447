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
use crate::signals::record::{add_noise, Record};
use crate::signals::setup::ChainSetup;
use crate::study::signal_record::{kinematics, periodic_record};
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
    /// Index of the state along the condition's trajectory.
    pub trajectory_state: usize,
    /// Pinion load cycles of the state.
    pub cycles: f64,
    /// Deepest wear of the pinion profile at the state, µm.
    pub max_wear_pinion_um: f64,
    /// Deepest wear of the gear profile at the state, µm.
    pub max_wear_gear_um: f64,
    /// Maximum wear depth of each tooth, um (each tooth its own with a tooth-resolved
    /// mesh; all teeth alike in the identical-tooth model).
    pub wear_pinion_tooth_um: Vec<f64>,
    /// Maximum wear depth of each gear tooth, µm (as the pinion's above).
    pub wear_gear_tooth_um: Vec<f64>,
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
/// a tooth-resolved mesh, else the common profile's (all teeth alike).
pub fn tooth_max_um(wear: &WearState, member: Member, z: usize) -> Vec<f64> {
    let um = |p: &[f64]| p.iter().fold(0.0_f64, |m, x| m.max(*x)) * 1e6;
    match (&wear.teeth, member) {
        (Some(t), Member::Pinion) => t.pinion_m.iter().map(|p| um(p)).collect(),
        (Some(t), Member::Gear) => t.gear_m.iter().map(|p| um(p)).collect(),
        (None, Member::Pinion) => vec![um(&wear.pinion_m); z],
        (None, Member::Gear) => vec![um(&wear.gear_m); z],
    }
}

/// Signal file of record `id`.
pub fn signal_file(id: usize) -> String {
    format!("signals/{id:07}.parquet")
}

/// Compute the records of physical state `p`, handing each to `emit` as it is made.
pub fn state_records(
    inp: &StateInputs,
    plan: &Plan,
    p: usize,
    index: StateIndex,
    emit: &mut dyn FnMut(RecordLabels, Record) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let wear = inp.trajectory.state_at(inp.cycles).ok_or_else(|| {
        anyhow::anyhow!(
            "state at {} cycles lies beyond the trajectory's end ({} cycles)",
            inp.cycles,
            inp.trajectory.end_cycles
        )
    })?;
    let r = inp
        .model
        .dynamic(&wear, &ExternalError::none())
        .map_err(|e: DynamicsError| anyhow::anyhow!("state {p} ({} cycles): {e}", inp.cycles))?;
    let periodic = periodic_record(inp.model, inp.setup, &r);
    let kin = kinematics(inp.model);
    let mut chain = inp.setup.chain.clone();
    let clean = periodic.render(&chain, chain.samples(kin.shaft_hz(chain.tachometer.shaft)));
    let (remaining, censored) = inp.trajectory.remaining(inp.cycles);
    let case = &inp.model.case;
    let (z1, z2) = (inp.model.pair.pinion.teeth, inp.model.pair.gear.teeth);
    for realisation in 0..plan.realisations {
        let id = plan.record_id(p, realisation);
        let seed = record_seed(inp.design_seed, id);
        chain.acquisition.noise_seed = seed;
        let mut rec = clean.clone();
        add_noise(&mut rec, &chain);
        let analysis = analyse(&rec, &kin, &chain.tachometer, inp.setup.components);
        let labels = RecordLabels {
            record_id: id,
            file: signal_file(id),
            condition: inp.condition.name.clone(),
            fault: inp.condition.fault.clone(),
            severity: inp.condition.severity,
            faults: case.fault.iter().map(|f| f.table().clone()).collect(),
            trajectory_state: index.state,
            cycles: inp.cycles,
            max_wear_pinion_um: wear.max_pinion_m() * 1e6,
            max_wear_gear_um: wear.max_gear_m() * 1e6,
            wear_pinion_tooth_um: tooth_max_um(&wear, Member::Pinion, z1),
            wear_gear_tooth_um: tooth_max_um(&wear, Member::Gear, z2),
            wear_limit_um: inp.wear_limit_um,
            remaining_cycles: remaining,
            failure_censored: censored,
            input_speed_hz: case.operating.input_speed_hz,
            load_torque_nm: case.operating.load_torque_nm,
            mesh_hz: kin.mesh_hz(),
            realisation,
            noise_seed: seed,
            indicators: analysis.iter().map(|c| c.indicators()).collect(),
        };
        emit(labels, rec)?;
    }
    Ok(())
}
