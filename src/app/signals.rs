//! The signals job: one record of the case as a sensor records it (the steady state, or
//! the transient of a ramp or a load fluctuation), its indicators and figures
//! (docs/SIGNALS.md).

use super::observer::Observer;
use super::{budget, build_model, publish, Job, JobError, Outcome};
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

/// See the module docs.
#[derive(Debug, Clone)]
pub struct SignalsJob {
    pub case: Case,
    pub transfer_path: Option<TransferPathSource>,
    /// Output folder; `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
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
        // The path first: its sensors are the record's channels, which the budget counts.
        let path = transfer_path_of(self.transfer_path.as_ref())?;
        let channels = path
            .as_ref()
            .map_or(crate::study::budget::signals::DEFAULT_CHANNELS, |p| {
                p.sensors.len()
            });
        super::refuse_train(&self.case)?;
        budget::check_estimate(
            &estimate_signals(&self.case, channels),
            self.budget.as_ref(),
        )?;
        let model = build_model(&self.case, observer)?;
        let setup = chain_of(
            &self.case,
            path,
            self.case.signals.max_input_speed_hz(&self.case),
        )
        .map_err(|m| JobError::Input(m.into_iter().map(Problem::new).collect()))?;
        for w in &setup.warnings {
            observer.warning(w);
        }
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        let rec = record_case(&model, &setup, &WearState::new(model.grid.len()))
            .map_err(|e| JobError::Failed(e.into()))?;
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
