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
use crate::study::budget::{estimate, Budget, Estimate, Job as Cost, Term, SECONDS_PER_STEP};
use crate::study::signal_record::record_case;
use crate::study::transient_signals::is_transient;
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

/// Bytes of memory per recorded second and sample rate: the record's channels, their
/// analysis, and for a transient the internal grid (8 samples a sample, four forces, their
/// spectra): measured about 1.5 kB per record sample for a transient, 0.2 kB steady.
const BYTES_PER_SAMPLE_STEADY: f64 = 400.0;
const BYTES_PER_SAMPLE_TRANSIENT: f64 = 3000.0;

/// Seconds per record sample of rendering, filtering, indicators and writing, on one
/// core: measured 2.7 us of user time a sample for a 20 s record at 100 kHz (2e6 samples,
/// 5.47 s), rounded up.
const SECONDS_PER_RECORD_SAMPLE: f64 = 3e-6;

/// The dynamics estimate with the record's memory added as its own term, so one estimate
/// (and one message, with every term) covers the whole job: before, the record was checked
/// apart and an estimate read from the budget's message missed it (a 10 s record at 1 MHz:
/// 0.07 GB reported against 3.7 GiB needed).
fn estimate_with_record(case: &Case) -> Estimate {
    let s = &case.signals;
    let seconds = match s.record_length_unit {
        crate::config::signals::LengthUnit::S => s.record_length,
        crate::config::signals::LengthUnit::Revolutions => {
            s.record_length / case.operating.input_speed_hz.max(1e-9)
        }
    };
    let per = if is_transient(case) {
        BYTES_PER_SAMPLE_TRANSIENT
    } else {
        BYTES_PER_SAMPLE_STEADY
    };
    // A transient record integrates every mesh period it spans at the grid's steps per
    // period (bounded above with the fastest speed of the record); a steady record
    // replays the steady state, whose cost is the dynamics estimate's.
    let samples = seconds * s.sampling_rate_hz;
    let transient_seconds = if is_transient(case) {
        let mesh_periods = case.gear.teeth_pinion as f64 * s.max_input_speed_hz(case) * seconds;
        mesh_periods * case.numerics.steps_per_mesh_period as f64 * SECONDS_PER_STEP
    } else {
        0.0
    };
    let mut e = estimate(case, Cost::Dynamics);
    e.terms.push(Term {
        what: "the record (channels, analysis, a transient's internal grid and integration)",
        seconds: transient_seconds + samples * SECONDS_PER_RECORD_SAMPLE,
        bytes: samples * per,
        keys: &[
            "signals.record_length",
            "signals.sampling_rate_hz",
            "signals.ramp_end_speed_hz",
            "numerics.steps_per_mesh_period",
        ],
    });
    e
}

impl Job for SignalsJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "signals"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        budget::check_estimate(&estimate_with_record(&self.case), self.budget.as_ref())?;
        let model = build_model(&self.case, observer)?;
        let path = transfer_path_of(self.transfer_path.as_ref())?;
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
