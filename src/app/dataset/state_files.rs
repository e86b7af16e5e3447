//! The records of one physical state computed into their files (signal, CSV, sidecar),
//! handed to the caller: written by a run (`super::run`), compared with the kept files
//! by a verification (`super::verify`).

use super::folder::Sidecar;
use super::request::DatasetRequest;
use crate::checksum::sha256_hex;
use crate::signals::files::{record_parquet, record_table};
use crate::signals::setup::ChainSetup;
use crate::study::dataset::plan::{Plan, StateIndex};
use crate::study::dataset::records::{state_records, StateInputs};
use crate::study::dataset::trajectory::Trajectory;
use crate::study::dataset::StateChoice;
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
    let model = state_model(job, ix)?;
    let d = job.req.design;
    let unit = job.setups[ix.condition].chain.acquisition.unit;
    let inputs = state_inputs(job, ix, &model)?;
    state_records(&inputs, job.plan, p, ix, &mut |labels, rec| {
        let id = labels.record_id;
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
/// speed and load: every state along the trajectory shares it).
pub(super) fn state_model(job: &StateJob, ix: StateIndex) -> anyhow::Result<Model> {
    let d = job.req.design;
    let mut case = d.conditions[ix.condition].case.clone();
    case.set_load_point(crate::config::case::LoadPoint {
        input_speed_hz: d.speeds_hz[ix.speed],
        load_torque_nm: d.torques_nm[ix.load],
        ..case.load_point()
    });
    Model::from_case(&case).map_err(|e| anyhow::anyhow!("{e}"))
}

/// What the records of state `ix` are computed from, with its condition's `model`
/// ([`state_model`]). Fails when the job holds no trajectory of the condition.
pub(super) fn state_inputs<'a>(
    job: &'a StateJob,
    ix: StateIndex,
    model: &'a Model,
) -> anyhow::Result<StateInputs<'a>> {
    let d = job.req.design;
    let cond = &d.conditions[ix.condition];
    let traj = job.trajectories.get(&ix.condition).ok_or_else(|| {
        anyhow::anyhow!("condition `{}` has no verified wear trajectory", cond.name)
    })?;
    let cycles = match &d.states {
        StateChoice::Count(n) => traj.even_states(*n)[ix.state],
        StateChoice::Cycles(c) => c[ix.state],
    };
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
