//! One record of a case (`gearwear signals`): the steady-state response of a wear state,
//! through the signal chain to a record, and its analysis.

use super::model::Model;
use crate::dynamics::excitation::ExternalError;
use crate::dynamics::period_search::DynamicsError;
use crate::dynamics::response::DynamicResponse;
use crate::dynamics::summary::ResponseSummary;
use crate::signals::analysis::{analyse, ChannelAnalysis};
use crate::signals::bearing::{bearing_forces, stage_bearing_forces, BearingForces};
use crate::signals::periodic::PeriodicSignal;
use crate::signals::record::{add_noise, Kinematics, PeriodicRecord, Record};
use crate::signals::setup::ChainSetup;
use crate::wear::WearState;

/// A record and what was computed from it.
#[derive(Debug, Clone)]
pub struct SignalRecord {
    /// Shaft speeds and teeth of the pair recorded.
    pub kinematics: Kinematics,
    /// The record as written: noise included.
    pub record: Record,
    /// The analysis of each channel.
    pub analysis: Vec<ChannelAnalysis>,
    /// Headline numbers of the steady state (at the starting speed of a transient).
    pub response: ResponseSummary,
    /// Nominal input speed at the start and end of the record, Hz (equal when steady).
    pub input_speed_hz: (f64, f64),
    /// Damped frequencies of the model's mesh poles, Hz (`docs/MODEL.md`, Modes).
    pub mesh_poles_hz: Vec<f64>,
    /// The bearing forces of a steady record as the Fourier series the chain took in
    /// (`PeriodicRecord::inputs`); None for a transient.
    pub bearing_forces: Option<Vec<PeriodicSignal>>,
    /// A gear train's stages' shaft speeds, teeth and mesh frequencies, stage order (the
    /// lines of every mesh in the record's spectrum); empty for a single pair.
    pub train_meshes: Vec<Kinematics>,
}

/// Shaft speeds and teeth of the model at its operating point: each shaft's speed is the
/// mesh frequency over its teeth (so 570 Hz over 19 teeth reads 30 Hz exactly, not back
/// from rad/s).
/// On a gear train, the shafts of the sensor stage (`signals.sensor_stage`): its mesh
/// frequency from the train's operating point (`TrainOperatingPoint`) over its teeth.
pub fn kinematics(model: &Model) -> Kinematics {
    if let Some(k) = train_meshes(model).get(sensor_stage(model)) {
        return *k;
    }
    let f_m = model.params.operating.mesh_frequency_hz;
    Kinematics {
        pinion_hz: f_m / model.pair.pinion.teeth as f64,
        gear_hz: f_m / model.pair.gear.teeth as f64,
        teeth_pinion: model.pair.pinion.teeth,
        teeth_gear: model.pair.gear.teeth,
    }
}

/// Each stage's kinematics of a train at its operating point (empty for a single pair),
/// in Hz from the tooth counts as the single pair's are: stage 1 meshes at the input
/// speed times its pinion's teeth, each shaft turns at its mesh frequency over its
/// teeth, and stage k + 1's pinion turns with stage k's gear (the speeds of
/// `TrainOperatingPoint`, without the round trip through rad/s, so that a one-stage
/// train reads the single pair's 570 Hz and 30 Hz exactly).
pub(crate) fn train_meshes(model: &Model) -> Vec<Kinematics> {
    let Some(train) = &model.train else {
        return Vec::new();
    };
    let mut shaft_hz = model.case.operating.input_speed_hz;
    train
        .stages
        .iter()
        .map(|s| {
            let (zp, zg) = (s.pair.pinion.teeth, s.pair.gear.teeth);
            let f_m = shaft_hz * zp as f64;
            let k = Kinematics {
                pinion_hz: f_m / zp as f64,
                gear_hz: f_m / zg as f64,
                teeth_pinion: zp,
                teeth_gear: zg,
            };
            shaft_hz = k.gear_hz;
            k
        })
        .collect()
}

/// The sensor stage of a train, 0-based (`signals.sensor_stage`, validated against the
/// stages when the case is read; held to the last stage here all the same).
fn sensor_stage(model: &Model) -> usize {
    let n = model.train.as_ref().map_or(1, |t| t.stages.len());
    model.case.signals.sensor_stage_index().min(n.max(1) - 1)
}

/// The bearing forces the transfer path takes in: the single pair's, or the sensor
/// stage's of a train.
fn forces(model: &Model, r: &DynamicResponse) -> BearingForces {
    match &model.train {
        // Every stage's pinion and gear move laterally on their own bearings
        // (`assembly::train`), so the stage's forces exist.
        Some(t) => stage_bearing_forces(r, &t.assembly, sensor_stage(model))
            .expect("a train stage's gears have lateral coordinates and bearings"),
        None => bearing_forces(r, &model.params),
    }
}

/// The headline numbers of a steady state: the single pair's, or the sensor stage's
/// mesh of a train (`TrainModel::mesh_summary`).
fn summary(model: &Model, r: &DynamicResponse) -> ResponseSummary {
    match &model.train {
        Some(t) => t.mesh_summary(r, sensor_stage(model)),
        None => ResponseSummary::of(r),
    }
}

/// The noise-free periodic signals of a steady-state response.
pub fn periodic_record(model: &Model, setup: &ChainSetup, r: &DynamicResponse) -> PeriodicRecord {
    PeriodicRecord::new(&forces(model, r), &kinematics(model), &setup.chain)
}

/// Render, add noise and analyse a record of the periodic signals `p`.
pub fn record_from(
    model: &Model,
    setup: &ChainSetup,
    p: &PeriodicRecord,
    response: ResponseSummary,
) -> SignalRecord {
    let kin = kinematics(model);
    let chain = &setup.chain;
    let n = chain.samples(kin.shaft_hz(chain.tachometer.shaft));
    let mut record = p.render(chain, n);
    add_noise(&mut record, chain);
    record.round_to_stored();
    let analysis = analyse(&record, &kin, &chain.tachometer, setup.components);
    SignalRecord {
        input_speed_hz: (kin.pinion_hz, kin.pinion_hz),
        kinematics: kin,
        record,
        analysis,
        response,
        mesh_poles_hz: crate::study::ModalAnalysis::of(model).mesh_pole_frequencies_hz(),
        bearing_forces: Some(p.inputs.clone()),
        train_meshes: train_meshes(model),
    }
}

/// The record of the steady state of `wear` (with an external transmission error).
pub fn steady_record(
    model: &Model,
    setup: &ChainSetup,
    wear: &WearState,
    external: &ExternalError,
) -> Result<SignalRecord, DynamicsError> {
    let r = model.dynamic(wear, external)?;
    let p = periodic_record(model, setup, &r);
    Ok(record_from(model, setup, &p, summary(model, &r)))
}

/// The record of a case's `[signals]` section for `wear`: the steady state, or the
/// transient of a ramp or a load fluctuation (`study::transient_signals`).
pub fn record_case(
    model: &Model,
    setup: &ChainSetup,
    wear: &WearState,
) -> Result<SignalRecord, DynamicsError> {
    use super::transient_signals::{is_transient, transient_clean_record};
    if !is_transient(&model.case) {
        return steady_record(model, setup, wear, &ExternalError::none());
    }
    let (mut record, speeds) = transient_clean_record(model, setup, wear)?;
    let response = ResponseSummary::of(&model.dynamic(wear, &ExternalError::none())?);
    add_noise(&mut record, &setup.chain);
    record.round_to_stored();
    let kin = kinematics(model);
    let analysis = analyse(&record, &kin, &setup.chain.tachometer, setup.components);
    Ok(SignalRecord {
        input_speed_hz: (
            speeds.first().copied().unwrap_or(kin.pinion_hz),
            speeds.last().copied().unwrap_or(kin.pinion_hz),
        ),
        kinematics: kin,
        record,
        analysis,
        response,
        mesh_poles_hz: crate::study::ModalAnalysis::of(model).mesh_pole_frequencies_hz(),
        bearing_forces: None,
        train_meshes: train_meshes(model),
    })
}
