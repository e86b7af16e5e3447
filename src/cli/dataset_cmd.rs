//! `gearwear dataset` and `gearwear dataset-merge`: parse, attach a progress bar, run the
//! job (`jobs::dataset`), print.

use super::output::say;
use super::progress::count_bar;
use super::signals_args::{DatasetArgs, DatasetMergeArgs};
use super::CliError;
use crate::io::OutputDir;
use crate::jobs::dataset::{
    check_dataset, merge_datasets, run_dataset, DatasetError, DatasetOutcome, DatasetRequest,
};
use crate::jobs::Progress;
use crate::signals::path_file::parse_transfer_path;
use crate::study::dataset::{parse_design, Shard};
use indicatif::ProgressBar;
use std::path::Path;

struct Bar(ProgressBar);

impl Progress for Bar {
    fn progress(&self, done: u64, total: u64) {
        self.0.set_length(total);
        self.0.set_position(done);
    }
    fn warning(&self, message: &str) {
        self.0.suspend(|| eprintln!("warning: {message}"));
    }
}

fn failed(e: DatasetError) -> CliError {
    match e {
        DatasetError::Input(p) => CliError::Input(p),
        DatasetError::Failed(e) => CliError::Failed(e),
    }
}

fn report(o: &DatasetOutcome, what: &str, out: &Path) -> Result<(), CliError> {
    say(&format!(
        "{what}: {} of {} records ({} computed, {} reused){}",
        o.shard_records,
        o.total_records,
        o.computed,
        o.reused,
        if o.missing.is_empty() {
            String::new()
        } else {
            format!("; {} records missing from the index", o.missing.len())
        }
    ));
    eprintln!("{what}: results -> {}", out.display());
    if o.failures.is_empty() {
        Ok(())
    } else {
        Err(CliError::Failed(anyhow::anyhow!(
            "{} physical states failed:\n  {}",
            o.failures.len(),
            o.failures.join("\n  ")
        )))
    }
}

pub fn run(a: &DatasetArgs) -> Result<(), CliError> {
    let name = a.design.display().to_string();
    let text = std::fs::read_to_string(&a.design)
        .map_err(|e| CliError::input(format!("--design {name}: cannot read it: {e}")))?;
    let base = a.design.parent().unwrap_or(Path::new("."));
    let read = |rel: &str| std::fs::read_to_string(base.join(rel)).map_err(|e| e.to_string());
    let design = parse_design(&text, &name, &read).map_err(CliError::Input)?;
    let (path, path_bytes) = match &design.transfer_path {
        Some(rel) => {
            let p = base.join(rel);
            let bytes = std::fs::read(&p).map_err(|e| {
                CliError::input(format!(
                    "{name}: `transfer_path` {}: cannot read it: {e}",
                    p.display()
                ))
            })?;
            let path =
                parse_transfer_path(&String::from_utf8_lossy(&bytes), &p.display().to_string())
                    .map_err(CliError::Input)?;
            (Some(path), bytes)
        }
        None => (None, Vec::new()),
    };
    let shard = match &a.shard {
        Some(s) => Shard::parse(s).map_err(CliError::input)?,
        None => Shard::ALL,
    };
    let req = DatasetRequest {
        design: &design,
        path,
        path_bytes,
        shard,
    };
    let checked = check_dataset(&req).map_err(failed)?;
    let set =
        (shard.count > 1).then(|| format!("dataset_shard_{}_of_{}", shard.index, shard.count));
    let out = OutputDir::open(&a.out, set.as_deref(), "dataset")?;
    let bar = Bar(count_bar(0, "records"));
    let o = run_dataset(&req, checked, &a.out, out, &bar).map_err(failed);
    bar.0.finish_and_clear();
    report(&o?, "dataset", &a.out)
}

pub fn merge(a: &DatasetMergeArgs) -> Result<(), CliError> {
    let out = OutputDir::open(&a.out, None, "dataset-merge")?;
    let inputs: Vec<&Path> = a.inputs.iter().map(|p| p.as_path()).collect();
    let o = merge_datasets(&inputs, &a.out, out).map_err(failed)?;
    report(&o, "dataset-merge", &a.out)
}
