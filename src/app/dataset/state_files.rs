//! The records of one physical state computed into their files (signal, CSV, sidecar),
//! handed to the caller: written by a run (`super::run`), compared with the kept files
//! by a verification (`super::verify`).

use super::folder::Sidecar;
use super::request::DatasetRequest;
use crate::app::signals_planetary::ring_sensor_of;
use crate::checksum::sha256_hex;
use crate::signals::files::{record_parquet, record_table};
use crate::signals::setup::ChainSetup;
use crate::study::dataset::plan::{Plan, StateIndex};
use crate::study::dataset::planetary_records::{
    planetary_record_csv, planetary_record_parquet, planetary_state_records, PlanetaryInputs,
};
use crate::study::dataset::records::{state_records, StateInputs};
use crate::study::dataset::trajectory::Trajectory;
use crate::study::dataset::{Condition, StateChoice};
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::study::Model;
use std::collections::BTreeMap;

/// The files of one record as the job writes them: its signal file (Parquet), its CSV
/// when the design asks, and its sidecar.
pub(crate) struct RecordFiles {
    pub id: usize,
    pub signal_rel: String,
    pub signal: Vec<u8>,
    pub csv: Option<Vec<u8>>,
    pub sidecar: Vec<u8>,
}

/// Everything a physical state's records are computed from.
pub(crate) struct StateJob<'a> {
    pub req: &'a DatasetRequest<'a>,
    pub plan: &'a Plan,
    pub setups: &'a [ChainSetup],
    pub trajectories: &'a BTreeMap<usize, Trajectory>,
    pub key: &'a str,
}

/// Compute the records of physical state `p`, handing each record's files to `emit` as
/// they are made (written by a run, compared by a verification).
pub(crate) fn state_files(
    job: &StateJob,
    p: usize,
    emit: &mut dyn FnMut(RecordFiles) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let ix = job.plan.state_index(p);
    if job.req.design.conditions[ix.condition]
        .case
        .planetary
        .is_some()
    {
        return planetary_state_files(job, p, emit);
    }
    let model = state_model(job, ix)?;
    let d = job.req.design;
    let unit = job.setups[ix.condition].chain.acquisition.unit;
    let inputs = state_inputs(job, ix, &model)?;
    state_records(&inputs, job.plan, p, ix, &mut |labels, rec| {
        let id = labels.record_id;
        rec.check_finite(&format!("state {p}, record {id}"))
            .map_err(anyhow::Error::msg)?;
        let signal = record_parquet(&rec, unit, Some(&serde_json::to_value(&labels)?))?;
        let csv = if d.csv {
            Some(record_table(&rec, unit).to_csv()?)
        } else {
            None
        };
        let car = Sidecar {
            dataset_key: job.key.to_owned(),
            signal_sha256: sha256_hex(&signal),
            labels,
        };
        emit(RecordFiles {
            id,
            signal_rel: car.labels.file.clone(),
            sidecar: serde_json::to_vec_pretty(&car)?,
            signal,
            csv,
        })
    })
}

/// The model of a physical state's condition at its speed and load (one per condition,
/// speed and load: every state along the trajectory shares it): a helical pair's planar
/// model with its wear per slice (`Model::wear_study_from_case`, docs/MODEL.md 11.9).
pub(super) fn state_model(job: &StateJob, ix: StateIndex) -> anyhow::Result<Model> {
    Model::wear_study_from_case(&state_case(job, ix), DATASET).map_err(|e| anyhow::anyhow!("{e}"))
}

/// The study a dataset's refusals name.
pub(crate) const DATASET: &str = "`gearwear dataset`";

/// What the records of state `ix` are computed from, with its condition's `model`
/// ([`state_model`]). Fails when the job holds no trajectory of the condition.
pub(super) fn state_inputs<'a>(
    job: &'a StateJob,
    ix: StateIndex,
    model: &'a Model,
) -> anyhow::Result<StateInputs<'a>> {
    let d = job.req.design;
    let (cond, traj, cycles) = state_of(job, ix)?;
    Ok(StateInputs {
        model,
        setup: &job.setups[ix.condition],
        condition: cond,
        trajectory: traj,
        cycles,
        wear_limit_um: d.wear_limit_um,
        design_seed: d.seed,
    })
}

/// State `ix`'s condition, its verified wear trajectory and the cycles the state is
/// recorded at (evenly spaced along the trajectory, or as the design lists them). Fails
/// when the job holds no trajectory of the condition.
fn state_of<'a>(
    job: &'a StateJob,
    ix: StateIndex,
) -> anyhow::Result<(&'a Condition, &'a Trajectory, f64)> {
    let d = job.req.design;
    let cond = &d.conditions[ix.condition];
    let traj = job.trajectories.get(&ix.condition).ok_or_else(|| {
        anyhow::anyhow!("condition `{}` has no verified wear trajectory", cond.name)
    })?;
    let cycles = match &d.states {
        StateChoice::Count(n) => traj.even_states(*n)[ix.state],
        StateChoice::Cycles(c) => c[ix.state],
    };
    Ok((cond, traj, cycles))
}

/// The case of a physical state's condition at its speed and load.
fn state_case(job: &StateJob, ix: StateIndex) -> crate::config::Case {
    let d = job.req.design;
    let mut case = d.conditions[ix.condition].case.clone();
    case.set_load_point(crate::config::case::LoadPoint {
        input_speed_hz: d.speeds_hz[ix.speed],
        load_torque_nm: d.torques_nm[ix.load],
        ..case.load_point()
    });
    case
}

/// The wear model of a planetary condition's set at a physical state's speed and load
/// (one per condition, speed and load, as [`state_model`]).
pub(super) fn planetary_state_model(
    job: &StateJob,
    ix: StateIndex,
) -> anyhow::Result<PlanetaryWearModel> {
    PlanetaryWearModel::from_case(&state_case(job, ix)).map_err(|e| anyhow::anyhow!("{e}"))
}

/// What the records of a planetary state `ix` are computed from, with its set `model`
/// ([`planetary_state_model`]).
pub(super) fn planetary_inputs<'a>(
    job: &'a StateJob,
    ix: StateIndex,
    model: &'a PlanetaryWearModel,
) -> anyhow::Result<PlanetaryInputs<'a>> {
    let d = job.req.design;
    let (cond, traj, cycles) = state_of(job, ix)?;
    let case = state_case(job, ix);
    Ok(PlanetaryInputs {
        model,
        sensor: ring_sensor_of(&case, model.planets()),
        pulses_per_revolution: case.signals.tachometer_pulses_per_revolution.max(1) as usize,
        snr_db: case.signals.snr_db,
        condition: cond,
        trajectory: traj,
        cycles,
        input_speed_hz: d.speeds_hz[ix.speed],
        load_torque_nm: d.torques_nm[ix.load],
        wear_limit_um: d.wear_limit_um,
        design_seed: d.seed,
    })
}

/// [`state_files`] of a planetary condition's state (`study::dataset::planetary_records`).
fn planetary_state_files(
    job: &StateJob,
    p: usize,
    emit: &mut dyn FnMut(RecordFiles) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let ix = job.plan.state_index(p);
    let model = planetary_state_model(job, ix)?;
    let inputs = planetary_inputs(job, ix, &model)?;
    let csv = job.req.design.csv;
    planetary_state_records(&inputs, job.plan, p, ix, &mut |labels, rec| {
        rec.check_finite(&format!("state {p}, record {}", labels.record_id))
            .map_err(anyhow::Error::msg)?;
        let signal = planetary_record_parquet(&rec, &serde_json::to_value(&labels)?)?;
        let csv = if csv {
            Some(planetary_record_csv(&rec)?)
        } else {
            None
        };
        let car = Sidecar {
            dataset_key: job.key.to_owned(),
            signal_sha256: sha256_hex(&signal),
            labels,
        };
        emit(RecordFiles {
            id: car.labels.record_id,
            signal_rel: car.labels.file.clone(),
            sidecar: serde_json::to_vec_pretty(&car)?,
            signal,
            csv,
        })
    })
}
