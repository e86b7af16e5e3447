//! The predict-merge job: joins the shards of a sharded prediction and builds its outputs
//! as an unsharded prediction would.

use super::observer::Observer;
use super::predict::{prediction_artifacts, ShardFile};
use super::{publish, Job, JobError, Outcome};
use crate::prognostics::check::PredictionCheck;
use crate::prognostics::predict::SampleOutcome;
use crate::remedy::{Arg, Problem};
use std::path::{Path, PathBuf};

/// See the module docs.
#[derive(Debug, Clone)]
pub struct PredictMergeJob {
    /// Shard files (`predict_shard_I_of_N.json`) or folders holding them.
    pub inputs: Vec<PathBuf>,
    /// Output folder; `None` writes nothing.
    pub out: Option<PathBuf>,
}

/// Shard files of a merge input: a file, or a folder's `predict_shard_*_of_*.json`.
fn shard_files(input: &Path) -> Result<Vec<PathBuf>, JobError> {
    if input.is_file() {
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
        let mut files: Vec<(String, ShardFile)> = Vec::new();
        for input in &self.inputs {
            for p in shard_files(input)? {
                let src = p.display().to_string();
                let text = std::fs::read_to_string(&p)
                    .map_err(|e| Problem::given(Arg::Inputs, &src, e.to_string()))?;
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
            if f.identity != first.identity {
                return Err(Problem::new(format!(
                    "{src} and {src0} come from different predictions (settings, forward model, samples, case or future duty differ)"
                ))
                .into());
            }
        }
        let mut outcomes: Vec<SampleOutcome> =
            files.iter().flat_map(|f| f.1.outcomes.clone()).collect();
        outcomes.sort_by_key(|o| o.index);
        outcomes.dedup_by_key(|o| o.index);
        let have: std::collections::BTreeSet<usize> = outcomes.iter().map(|o| o.index).collect();
        let missing: Vec<usize> = (0..first.identity.settings.samples)
            .filter(|i| !have.contains(i))
            .collect();
        if !missing.is_empty() {
            observer.warning(&format!(
                "{} of {} samples missing (first: {:?}); run their shards and merge again",
                missing.len(),
                first.identity.settings.samples,
                &missing[..missing.len().min(10)]
            ));
        }
        let checks: Vec<PredictionCheck> = files.iter().flat_map(|f| f.1.checks.clone()).collect();
        let out = publish::open_if(self.out.as_deref(), None, self.name())?;
        let art = prediction_artifacts(
            ShardFile {
                outcomes,
                checks,
                shard: (1, 1),
                ..first
            },
            missing,
        )?;
        publish::publish(out, art, None, observer)
    }
}
