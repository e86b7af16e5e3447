//! The signals job: one record of the case as a sensor records it (the steady state, or
//! the transient of a ramp or a load fluctuation), its indicators and figures
//! (docs/SIGNALS.md).

use super::observer::Observer;
use super::{budget, build_dynamics_model, publish, Job, JobError, Outcome};
use crate::config::Case;
use crate::remedy::{Arg, Problem};
use crate::report::figure_output::FigureRequest;
use crate::report::signals::signals_artifacts;
use crate::signals::setup::chain_of;
use crate::signals::transfer::TransferPath;
use crate::store::transfer_path::read_transfer_path;
use crate::store::RunMetadata;
use crate::study::budget::{estimate_signals, Budget};
use crate::study::signal_record::record_case;
use crate::wear::WearState;
use std::path::PathBuf;

/// Where the transfer path comes from (absent: the built-in generic housing).
#[derive(Debug, Clone)]
pub enum TransferPathSource {
    /// An FRF table (`.csv`) or a modal description (`.toml`).
    File(PathBuf),
    /// A path built by the caller.
    Path(TransferPath),
}

/// The transfer path of `source`; a file's problems name it.
pub fn transfer_path_of(
    source: Option<&TransferPathSource>,
) -> Result<Option<TransferPath>, JobError> {
    match source {
        None => Ok(None),
        Some(TransferPathSource::Path(p)) => Ok(Some(p.clone())),
        Some(TransferPathSource::File(f)) => read_transfer_path(f).map(Some).map_err(|m| {
            JobError::Input(
                m.into_iter()
                    .map(|m| Problem::of(Arg::TransferPath, m))
                    .collect(),
            )
        }),
    }
}

/// What the signals study says of a gear train with a transient record (a ramp or a
/// load fluctuation): only the steady record runs on a train so far.
const TRAIN_TRANSIENT: &str = "this case is a gear train ([[stage]] tables) with a transient record (`signals.ramp_end_speed_hz` or `signals.torque_fluctuation_rms_nm` > 0): on a train, `gearwear signals` records the steady state only; remove those keys, or take a single pair ([gear], without [[stage]])";

/// Refuse a transient record of a gear train (before the budget check); a helical pair's
/// runs on its planar model (docs/MODEL.md 11.11).
fn refuse_train_transient(case: &Case) -> Result<(), JobError> {
    if !crate::study::transient_signals::is_transient(case) {
        return Ok(());
    }
    if !case.stage.is_empty() {
        return Err(JobError::input(Problem::new(TRAIN_TRANSIENT.to_owned())));
    }
    Ok(())
}

/// See the module docs.
#[derive(Debug, Clone)]
pub struct SignalsJob {
    /// The case whose signals are computed.
    pub case: Case,
    /// The transfer path from the mesh to the sensors (`None`: the generic housing path,
    /// `TransferPath::generic_housing`).
    pub transfer_path: Option<TransferPathSource>,
    /// Output folder; `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The run budget (`None`: no check).
    pub budget: Option<Budget>,
    /// The formats and size of the figures, checked when the job starts.
    pub figures: FigureRequest,
}

impl Job for SignalsJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "signals"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        if self.case.planetary.is_some() {
            return self.run_planetary(observer);
        }
        // The path first: its sensors are the record's channels, which the budget counts.
        let path = transfer_path_of(self.transfer_path.as_ref())?;
        let channels = path
            .as_ref()
            .map_or(crate::study::budget::signals::DEFAULT_CHANNELS, |p| {
                p.sensors.len()
            });
        refuse_train_transient(&self.case)?;
        // The estimate is the dynamics one (a train's counted by its cost factor,
        // `budget::train_factor`) with the record added.
        budget::check_estimate(
            &estimate_signals(&self.case, channels),
            self.budget.as_ref(),
        )?;
        let model = build_dynamics_model(&self.case, observer)?;
        // The chain is checked against the sensor stage's pair at its own pinion speed
        // (the stage's case; the single pair's case itself).
        let chain_case = model.train.as_ref().map_or(&self.case, |t| {
            &t.stages[self
                .case
                .signals
                .sensor_stage_index()
                .min(t.stages.len() - 1)]
            .case
        });
        let setup = chain_of(
            chain_case,
            path,
            chain_case.signals.max_input_speed_hz(chain_case),
        )?;
        for w in &setup.warnings {
            observer.warning(w);
        }
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        // New teeth: a helical pair's per slice, else the one profile the record has
        // always been made with.
        let new = match model.helical {
            Some(_) => model.new_wear_state(),
            None => WearState::new(model.grid.len()),
        };
        let rec = record_case(&model, &setup, &new).map_err(|e| JobError::Failed(e.into()))?;
        rec.record
            .check_finite("the signals record")
            .map_err(|e| JobError::Failed(anyhow::Error::msg(e)))?;
        let harmonics = self.case.signals.mesh_harmonics.max(1) as usize;
        // Judged by effect, as the model judges its teeth: zero errors, zero-depth
        // faults and zero reliefs leave the new, perfect teeth.
        let c = &self.case;
        let changed = c.teeth.changes_teeth()
            || c.modification.changes_teeth()
            || c.fault.iter().any(|f| f.changes_tooth());
        let label = if !changed {
            "new teeth"
        } else {
            "the case's tooth errors, modifications and faults"
        };
        let artifacts =
            signals_artifacts(&rec, &setup.chain, harmonics, label).with_figure_output(figures);
        let meta = RunMetadata::of_model(self.name(), &model);
        publish::publish(out, artifacts, Some(&meta), observer)
    }
}
