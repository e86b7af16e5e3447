//! The load-spectrum job: a measured history of torque and speed (`duty::history`) ->
//! its load duration distribution, time at level (`duty::ldd`) -> the spectrum for a case,
//! with the time-at-level histogram (`report::ldd`). Needs no case: the history and the
//! counting options are the whole input.

use super::inputs::TableSource;
use super::observer::Observer;
use super::{budget, publish, Job, JobError, Outcome};
use crate::config::case::TorqueShaft;
use crate::config::spectrum_merge::{merge_small_bins, DEFAULT_MERGE_SHARE, MAX_MERGE_SHARE};
use crate::duty::history::{parse_history, DEFAULT_GAP_FACTOR};
use crate::duty::ldd::{
    load_duration_distribution, LddSettings, MAX_SPEED_CLASSES, MAX_TORQUE_CLASSES,
};
use crate::format::{shown, shown_percent};
use crate::io::input::MAX_HISTORY_BYTES;
use crate::remedy::{Arg, Problem};
use crate::report::figure_output::FigureRequest;
use crate::report::ldd::ldd_artifacts;
use crate::study::budget::{estimate_history, Budget};
use sha2::{Digest, Sha256};
use std::path::PathBuf;

/// See the module docs.
#[derive(Debug, Clone)]
pub struct LoadSpectrumJob {
    /// CSV of `time_s`, `torque_nm`, `input_speed_hz` (or `input_speed_rpm`).
    pub history: TableSource,
    /// The load-duration distribution's classes and counting rules (torque and speed
    /// classes, interpolation, the torque of each bin).
    pub settings: LddSettings,
    /// Shaft the history's torque was measured on (the spectrum's `torque_shaft`).
    pub torque_shaft: TorqueShaft,
    /// Longest interval accepted, as a multiple of the median interval (longer: a gap).
    pub gap_factor: f64,
    /// Bins under this share of the revolutions are merged into their nearest bin
    /// (`config::spectrum_merge`), in [0, 0.1]; 0 keeps every bin.
    pub merge_below_share: f64,
    /// Output folder; `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The run budget (`None`: no check).
    pub budget: Option<Budget>,
    /// The formats and size of the figures, checked when the job starts.
    pub figures: FigureRequest,
}

impl LoadSpectrumJob {
    /// A job with the default counting (10 torque x 5 speed classes, linear between
    /// samples, mean torque per cell) on the pinion's torque.
    pub fn new(history: TableSource) -> Self {
        Self {
            history,
            settings: LddSettings::default(),
            torque_shaft: TorqueShaft::Pinion,
            gap_factor: DEFAULT_GAP_FACTOR,
            merge_below_share: DEFAULT_MERGE_SHARE,
            out: None,
            replace: false,
            budget: Some(Budget::DEFAULT),
            figures: FigureRequest::default(),
        }
    }

    /// Every problem with the options, before the history is read.
    fn check(&self) -> Result<(), JobError> {
        let mut problems = Vec::new();
        let s = &self.settings;
        for (arg, n, max) in [
            (Arg::TorqueClasses, s.torque_classes, MAX_TORQUE_CLASSES),
            (Arg::SpeedClasses, s.speed_classes, MAX_SPEED_CLASSES),
        ] {
            if n == 0 || n > max {
                problems.push(Problem::given(
                    arg,
                    n.to_string(),
                    format!("expected a whole number in [1, {max}]"),
                ));
            }
        }
        // 1: no interval may exceed the median (a fixed-rate logger); 1e6: any record.
        if !(self.gap_factor >= 1.0 && self.gap_factor <= 1e6) {
            problems.push(Problem::given(
                Arg::GapFactor,
                self.gap_factor.to_string(),
                "expected a number in [1, 1000000] (the longest interval accepted, in median intervals)",
            ));
        }
        if !(0.0..=MAX_MERGE_SHARE).contains(&self.merge_below_share) {
            problems.push(Problem::given(
                Arg::MergeBelowShare,
                self.merge_below_share.to_string(),
                format!("expected a share of the revolutions in [0, {MAX_MERGE_SHARE}] (0 keeps every bin)"),
            ));
        }
        if problems.is_empty() {
            Ok(())
        } else {
            Err(JobError::Input(problems))
        }
    }
}

impl Job for LoadSpectrumJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "load-spectrum"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        self.check()?;
        let (source, text) = self.history.read(Arg::History, MAX_HISTORY_BYTES)?;
        budget::check_estimate(&estimate_history(text.len() as u64), self.budget.as_ref())?;
        let history = parse_history(text.as_bytes(), self.gap_factor).map_err(|e| {
            JobError::Input(
                e.problems
                    .into_iter()
                    .map(|p| Problem::given(Arg::History, &source, p))
                    .collect(),
            )
        })?;
        let ldd = load_duration_distribution(&history, self.settings);
        if ldd.reversed_torque_time_s > 0.0 {
            observer.warning(&format!(
                "{} h of the history ({} of its span) has a negative torque while the shaft turns (the coast flank loaded: braking or overrunning); it is counted as idle, because the model wears the drive flank only",
                shown(ldd.reversed_torque_time_s / 3600.0),
                shown_percent(ldd.reversed_torque_time_s / ldd.span_s)
            ));
        }
        let Some(mut spectrum) = ldd.spectrum(self.torque_shaft) else {
            return Err(JobError::input(Problem::given(
                Arg::History,
                &source,
                "no time under load (torque and speed both above zero): there is no spectrum to count",
            )));
        };
        let (bins, merged) = merge_small_bins(&spectrum.bins, self.merge_below_share);
        spectrum.bins = bins;
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        let mut a = ldd_artifacts(
            &source,
            history.time_s.len(),
            &ldd,
            &spectrum,
            &merged,
            self.torque_shaft,
        )
        .with_figure_output(figures);
        let hash = Sha256::digest(text.as_bytes());
        a.summary["metadata"] = serde_json::json!({
            "program": "gearwear",
            "version": env!("CARGO_PKG_VERSION"),
            "command": self.name(),
            "history_sha256": hash.iter().map(|b| format!("{b:02x}")).collect::<String>(),
        });
        publish::publish(out, a, None, observer)
    }
}
