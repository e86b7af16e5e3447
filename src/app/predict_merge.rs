//! The predict-merge job: joins the shards of a sharded prediction and builds its outputs
//! as an unsharded prediction would.

use super::observer::Observer;
use super::predict::{prediction_artifacts, ShardFile};
use super::{budget, publish, Job, JobError, Outcome};
use crate::prognostics::check::PredictionCheck;
use crate::prognostics::predict::SampleOutcome;
use crate::remedy::{Arg, Problem};
use crate::report::figure_output::FigureRequest;
use crate::study::budget::estimate_merge;
use crate::study::budget::Budget;
use std::path::{Path, PathBuf};

/// See the module docs.
#[derive(Debug, Clone)]
pub struct PredictMergeJob {
    /// Shard files (`predict_shard_I_of_N.json`) or folders holding them.
    pub inputs: Vec<PathBuf>,
    /// Output folder; `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The budget of the merge (the shards read and joined).
    pub budget: Option<Budget>,
    /// The formats and size of the figures, checked when the job starts.
    pub figures: FigureRequest,
}

/// Shard files of a merge input: a file, or a folder's `predict_shard_*_of_*.json`.
fn shard_files(input: &Path) -> Result<Vec<PathBuf>, JobError> {
    if !input.is_dir() {
        // Read only if it is a regular file (`io::read_input` says what it is).
        return Ok(vec![input.to_path_buf()]);
    }
    let shown = input.display().to_string();
    let mut found: Vec<PathBuf> = std::fs::read_dir(input)
        .map_err(|e| Problem::given(Arg::Inputs, &shown, e.to_string()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            let n = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
            n.starts_with("predict_shard_")
                && n.ends_with(".json")
                && !n.ends_with(".manifest.json")
        })
        .collect();
    found.sort();
    if found.is_empty() {
        return Err(
            Problem::given(Arg::Inputs, shown, "holds no predict_shard_*_of_*.json").into(),
        );
    }
    Ok(found)
}

impl Job for PredictMergeJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "predict-merge"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        let mut files: Vec<(String, ShardFile)> = Vec::new();
        let mut bytes = 0u64;
        let limit = self.budget.as_ref();
        for input in &self.inputs {
            for p in shard_files(input)? {
                bytes += std::fs::metadata(&p).map_or(0, |m| m.len());
                let src = p.display().to_string();
                let text = crate::io::read_input_text(
                    &p,
                    "prediction shard",
                    crate::io::input::MAX_PREDICT_SHARD_BYTES,
                )
                .map_err(|e| Problem::of(Arg::Inputs, e.to_string()))?;
                // The text itself must fit the budget before it is parsed.
                budget::check_estimate(&estimate_merge(bytes, 0, 0), limit)?;
                let f: ShardFile = serde_json::from_str(&text).map_err(|e| {
                    Problem::given(Arg::Inputs, &src, format!("not a prediction shard: {e}"))
                })?;
                files.push((src, f));
            }
        }
        let Some((src0, first)) = files.first().cloned() else {
            return Err(Problem::of(Arg::Inputs, "no shard files given").into());
        };
        for (src, f) in &files {
            crate::prognostics::predict::check_shard(&f.identity.settings, f.shard, &f.outcomes)
                .map_err(|e| Problem::given(Arg::Inputs, src, e))?;
            if f.identity != first.identity {
                return Err(Problem::new(format!(
                    "{src} and {src0} come from different predictions (settings, forward model, samples, case or future duty differ)"
                ))
                .into());
            }
        }
        budget::check_estimate(
            &estimate_merge(
                bytes,
                first.identity.settings.samples,
                first.identity.settings.grid_points,
            ),
            limit,
        )?;
        let mut outcomes: Vec<SampleOutcome> =
            files.iter().flat_map(|f| f.1.outcomes.clone()).collect();
        outcomes.sort_by_key(|o| o.index);
        outcomes.dedup_by_key(|o| o.index);
        let have: std::collections::BTreeSet<usize> = outcomes.iter().map(|o| o.index).collect();
        // Counted, not listed: a shard may claim up to 1e7 samples.
        let n_missing = first.identity.settings.samples.saturating_sub(have.len());
        let missing: Vec<usize> = (0..first.identity.settings.samples)
            .filter(|i| !have.contains(i))
            .take(100)
            .collect();
        if n_missing > 0 {
            observer.warning(&format!(
                "{n_missing} of {} samples missing (first: {:?}); run their shards and merge again",
                first.identity.settings.samples,
                &missing[..missing.len().min(10)]
            ));
        }
        let checks: Vec<PredictionCheck> = files.iter().flat_map(|f| f.1.checks.clone()).collect();
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        let art = prediction_artifacts(
            ShardFile {
                outcomes,
                checks,
                shard: (1, 1),
                ..first
            },
            (n_missing, missing),
            figures,
        )?;
        publish::publish(out, art, None, observer)
    }
}
