//! The records of one physical state computed into their files (signal, CSV, sidecar),
//! handed to the caller: written by a run (`super::run`), compared with the kept files
//! by a verification (`super::verify`).

use super::folder::Sidecar;
use super::request::DatasetRequest;
use crate::checksum::sha256_hex;
use crate::signals::files::{record_parquet, record_table};
use crate::signals::setup::ChainSetup;
use crate::study::dataset::plan::Plan;
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
    let d = job.req.design;
    let ix = job.plan.state_index(p);
    let cond = &d.conditions[ix.condition];
    let traj = &job.trajectories[&ix.condition];
    let cycles = match &d.states {
        StateChoice::Count(n) => traj.even_states(*n)[ix.state],
        StateChoice::Cycles(c) => c[ix.state],
    };
    let mut case = cond.case.clone();
    case.set_load_point(crate::config::case::LoadPoint {
        input_speed_hz: d.speeds_hz[ix.speed],
        load_torque_nm: d.torques_nm[ix.load],
        ..case.load_point()
    });
    let model = Model::from_case(&case).map_err(|e| anyhow::anyhow!("{e}"))?;
    let setup = &job.setups[ix.condition];
    let unit = setup.chain.acquisition.unit;
    let inputs = StateInputs {
        model: &model,
        setup,
        condition: cond,
        trajectory: traj,
        cycles,
        wear_limit_um: d.wear_limit_um,
        design_seed: d.seed,
    };
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
