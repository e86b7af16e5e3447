//! The two dataset jobs: [`DatasetJob`] (a design to a folder of records) and
//! [`DatasetMergeJob`] (shards joined), and where a design is read from.

use super::folder::{check_owner, copied_names, refused_names};
use super::merge::{check_trajectories, merge_datasets, shared_key};
use super::merge_verify::{verify_estimate, verify_inputs};
use super::plan::{check_dataset, dataset_key, trajectory_problems};
use super::request::{DatasetError, DatasetOutcome, DatasetRequest};
use super::run::{refuse_planted_names, run_dataset};
use super::verify::{verify_dataset, Verified};
use crate::app::observer::Observer;
use crate::app::{budget, publish, Job, JobError, Outcome};
use crate::io::input::{
    read_input, read_input_text, MAX_CASE_BYTES, MAX_DESIGN_BYTES, MAX_TRANSFER_PATH_BYTES,
};
use crate::io::OutputDir;
use crate::remedy::{Arg, Problem};
use crate::report::figure_output::FigureRequest;
use crate::report::Artifacts;
use crate::signals::path_file::parse_transfer_path;
use crate::signals::transfer::TransferPath;
use crate::study::budget::{estimate_dataset_resumed, estimate_folder_check, Budget};
use crate::study::dataset::plan::Shard;
use crate::study::dataset::{parse_design, DatasetDesign};
use std::path::{Path, PathBuf};

/// A study design and where it was read from (its folder resolves the design's relative
/// paths: the case file and the transfer-path file).
#[derive(Debug, Clone)]
pub struct DesignSource {
    /// The design's TOML text.
    pub text: String,
    /// The design's name in messages (its file name).
    pub name: String,
    /// The folder its relative paths are resolved against.
    pub folder: PathBuf,
    /// The base case given with the design rather than as a file (Python: a `Case`
    /// object as the design's `case`): its TOML text, read in place of the file the
    /// design's `case` key names.
    pub case_text: Option<String>,
}

impl DesignSource {
    /// The design in `path`.
    pub fn file(path: &Path) -> Result<Self, JobError> {
        let name = path.display().to_string();
        let text = read_input_text(path, "study design", MAX_DESIGN_BYTES)
            .map_err(|e| JobError::input(Problem::given(Arg::Design, &name, e.reason)))?;
        Ok(Self {
            text,
            name,
            folder: path
                .parent()
                .map_or_else(|| PathBuf::from("."), Path::to_path_buf),
            case_text: None,
        })
    }

    /// A design given as text (not read from a file) named `name` in messages, whose
    /// relative paths resolve against `folder`, with its base case as `case_text` if
    /// given so. The text is bounded as a design file is.
    pub fn inline(
        text: String,
        name: &str,
        folder: PathBuf,
        case_text: Option<String>,
    ) -> Result<Self, JobError> {
        let too_long = |what: &str, n: usize, max: u64| {
            JobError::input(Problem::given(
                Arg::Design,
                name,
                format!("{what} is {n} bytes, more than the {max} bytes it may be"),
            ))
        };
        if text.len() as u64 > MAX_DESIGN_BYTES {
            return Err(too_long("the design", text.len(), MAX_DESIGN_BYTES));
        }
        if let Some(c) = case_text
            .as_ref()
            .filter(|c| c.len() as u64 > MAX_CASE_BYTES)
        {
            return Err(too_long("its case", c.len(), MAX_CASE_BYTES));
        }
        Ok(Self {
            text,
            name: name.to_string(),
            folder,
            case_text,
        })
    }
}

/// See the module docs.
#[derive(Debug, Clone)]
pub struct DatasetJob {
    /// The study design and where it was read from.
    pub design: DesignSource,
    /// The part of the records to compute ([`Shard`]'s `index` of `count`; 1 of 1: all).
    pub shard: Shard,
    /// Output folder (the dataset, or one shard of it).
    pub out: PathBuf,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The run budget (`None`: no check).
    pub budget: Option<Budget>,
    /// The formats and size of the dataset's figure (`indicator_trends`), checked when the
    /// job starts; the records are the same whatever it is.
    pub figures: FigureRequest,
}

/// The line that says what a dataset run or merge wrote and where ("dataset: 4 records (2
/// computed, 2 reused), index and metadata -> data/"); a shard writes its description
/// instead of the index.
fn written(o: &DatasetOutcome, root: &Path, what: &str, shard: bool) -> String {
    let plural = if o.shard_records == 1 { "" } else { "s" };
    let records = if what == "dataset-merge" {
        format!("{} record{plural} joined", o.shard_records)
    } else {
        format!(
            "{} record{plural} ({} computed, {} reused)",
            o.shard_records, o.computed, o.reused
        )
    };
    let files = if shard {
        "the shard's description"
    } else {
        "index and metadata"
    };
    format!("{what}: {records}, {files} -> {}/", root.display())
}

fn outcome(o: &DatasetOutcome, root: &Path, what: &str) -> Outcome {
    let mut artifacts = Artifacts {
        summary: serde_json::json!({
            "records": o.total_records,
            "records_of_this_run": o.shard_records,
            "computed": o.computed,
            "reused": o.reused,
            "failures": o.failures,
            "missing": o.missing.listed,
            "missing_count": o.missing.count,
            "estimated_bytes": o.estimated_bytes,
        }),
        ..Default::default()
    };
    artifacts.headline = format!(
        "{what}: {} of {} records ({} computed, {} reused){}",
        o.shard_records,
        o.total_records,
        o.computed,
        o.reused,
        if o.missing.count == 0 {
            String::new()
        } else {
            format!("; {} records missing from the index", o.missing.count)
        }
    );
    Outcome {
        artifacts,
        published: Some(root.to_path_buf()),
        incomplete: (!o.failures.is_empty()).then(|| {
            format!(
                "{} {}:\n  {}",
                o.failures.len(),
                if what == "dataset-merge" {
                    "records left out"
                } else {
                    "physical states failed"
                },
                o.failures.join("\n  ")
            )
        }),
    }
}

impl Job for DatasetJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "dataset"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        let (design, path, path_bytes) = load_design(&self.design)?;
        let req = DatasetRequest {
            design: &design,
            path,
            path_bytes,
            shard: self.shard,
            figures,
            replace: self.replace,
        };
        let checked = check_dataset(&req)?;
        let threads = rayon::current_num_threads();
        // A resume checks each trajectory and finished state it finds instead of making
        // it (counted so).
        let kept: Vec<bool> = design
            .conditions
            .iter()
            .map(|c| {
                self.out
                    .join(super::folder::trajectory_rel(&c.name))
                    .is_file()
            })
            .collect();
        let key = dataset_key(&design, &req.path_bytes);
        let resumed = |kept_states| {
            estimate_dataset_resumed(
                &design,
                self.shard,
                threads,
                checked.record,
                (&kept, kept_states),
            )
        };
        // First from the sidecars' names alone, before any is read: every named state
        // taken as finished, the least work the resume can be (issue 33: every sidecar
        // was read before the budget was checked). Then the states whose sidecars are
        // this design's (each read once, at most `MAX_SIDECAR_BYTES`, only those the
        // names count).
        let named = kept_states_by_names(&self.out, &design, self.shard);
        budget::check_estimate(&resumed(named), self.budget.as_ref())?;
        let kept_states = kept_states(&self.out, &key, &design, self.shard);
        budget::check_estimate(&resumed(kept_states), self.budget.as_ref())?;
        // A trajectory longer than a folder keeps (after the run budget, which names the
        // cost first; without a budget this refuses it).
        let too_long = trajectory_problems(&design);
        if !too_long.is_empty() {
            return Err(DatasetError::Input(too_long).into());
        }
        // A folder belongs to one design: another design's run, shard or resume into it
        // is refused before it is opened (issue 33: it left false index rows).
        check_owner(
            &self.out,
            &dataset_key(&design, &req.path_bytes),
            self.replace,
        )
        .map_err(another_design)?;
        let set = (self.shard.count > 1)
            .then(|| format!("dataset_shard_{}_of_{}", self.shard.index, self.shard.count));
        // Links, FIFOs and foreign files at the names the run writes: refused before the
        // folder is opened (its lock and set record untouched).
        let prev = OutputDir::previous_state_of(&self.out, set.as_deref());
        refuse_planted_names(&req, &self.out, prev.as_ref())?;
        let out = publish::open(&self.out, set.as_deref(), self.name(), self.replace)?;
        let o = run_dataset(&req, checked, &self.out, out, observer)?;
        observer.note(&written(&o, &self.out, "dataset", self.shard.count > 1));
        Ok(outcome(&o, &self.out, "dataset"))
    }
}

/// Physical states of `shard` of design `d` whose every record `root` holds finished
/// under `key` (their sidecars; a resume checks them instead of making them). Only the
/// sidecars [`super::folder::sidecar_ids`] names within the design's records are read.
fn kept_states(root: &Path, key: &str, d: &DatasetDesign, shard: Shard) -> usize {
    let plan = crate::study::dataset::plan::plan_of(d);
    let ids = super::folder::sidecar_ids(root)
        .into_iter()
        .filter(|id| *id < plan.records())
        .filter(|id| super::folder::sidecar_at(root, *id).is_some_and(|s| s.dataset_key == key));
    states_of_shard(ids, d, shard)
}

/// [`kept_states`] by the sidecars' names alone (nothing read): at least as many.
fn kept_states_by_names(root: &Path, d: &DatasetDesign, shard: Shard) -> usize {
    let plan = crate::study::dataset::plan::plan_of(d);
    let ids = super::folder::sidecar_ids(root)
        .into_iter()
        .filter(|id| *id < plan.records());
    states_of_shard(ids, d, shard)
}

/// Physical states of `shard` of design `d` every record of which is among `ids`.
fn states_of_shard(ids: impl Iterator<Item = usize>, d: &DatasetDesign, shard: Shard) -> usize {
    let r = crate::study::dataset::plan::plan_of(d).realisations.max(1);
    let mut per_state = std::collections::BTreeMap::<usize, usize>::new();
    for id in ids {
        *per_state.entry(id / r).or_default() += 1;
    }
    per_state
        .iter()
        .filter(|(p, n)| **n >= r && **p % shard.count.max(1) == shard.index.saturating_sub(1))
        .count()
}

/// A design read as a dataset job reads it: the design parsed (its case files read
/// beside it), and its transfer path with the file's bytes (part of the dataset key).
pub fn load_design(
    d: &DesignSource,
) -> Result<(DatasetDesign, Option<TransferPath>, Vec<u8>), JobError> {
    let read = |rel: &str| match &d.case_text {
        Some(text) => Ok(text.clone()),
        None => read_input_text(&d.folder.join(rel), "case file", MAX_CASE_BYTES),
    };
    let design = parse_design(&d.text, &d.name, &read).map_err(|m| {
        JobError::Input(m.into_iter().map(|m| Problem::of(Arg::Design, m)).collect())
    })?;
    let (path, path_bytes) = match &design.transfer_path {
        Some(rel) => {
            let (path, bytes) = read_transfer_path(&d.folder.join(rel))?;
            (Some(path), bytes)
        }
        None => (None, Vec::new()),
    };
    Ok((design, path, path_bytes))
}

/// A transfer-path file read and parsed as a dataset job reads it, with its bytes (part
/// of the dataset key).
fn read_transfer_path(p: &Path) -> Result<(TransferPath, Vec<u8>), JobError> {
    let shown = p.display().to_string();
    let bytes = read_input(p, "transfer-path file", MAX_TRANSFER_PATH_BYTES)
        .map_err(|e| JobError::input(Problem::given(Arg::TransferPath, &shown, e.reason)))?;
    let path = parse_transfer_path(&String::from_utf8_lossy(&bytes), &shown).map_err(|m| {
        JobError::Input(
            m.into_iter()
                .map(|m| Problem::of(Arg::TransferPath, m))
                .collect(),
        )
    })?;
    Ok((path, bytes))
}

/// See the module docs.
#[derive(Debug, Clone)]
pub struct DatasetMergeJob {
    /// The dataset folders (shards) to join.
    pub inputs: Vec<PathBuf>,
    /// Output folder of the merged dataset.
    pub out: PathBuf,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The formats and size of the merged dataset's figure, checked when the job starts.
    pub figures: FigureRequest,
    /// The transfer-path file the shards' design was made with (its records are
    /// recomputed through it; the description keeps only its hash), as the design's
    /// `transfer_path` names it for `dataset`; `None` when the design uses none.
    pub transfer_path: Option<PathBuf>,
    /// The run budget the verification of the shards is checked against (`None`: no
    /// check).
    pub budget: Option<Budget>,
}

impl Job for DatasetMergeJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "dataset-merge"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        if self.inputs.is_empty() {
            return Err(JobError::input(Problem::of(
                Arg::Inputs,
                "no dataset folders given",
            )));
        }
        let inputs: Vec<&Path> = self.inputs.iter().map(PathBuf::as_path).collect();
        let shared = shared_key(&inputs)?;
        let given = self
            .transfer_path
            .as_deref()
            .map(|p| read_transfer_path(p).map(|(t, b)| (p, t, b)))
            .transpose()?;
        let given = given.as_ref().map(|(p, t, b)| (*p, t, b.as_slice()));
        // The verification below reads and analyses every record of every shard: its
        // cost checked first (issue 33: a merge of 1e6 records was counted nowhere).
        let threads = rayon::current_num_threads();
        budget::check_estimate(
            &verify_estimate(&inputs, given, threads),
            self.budget.as_ref(),
        )?;
        check_trajectories(&inputs, &shared.0)?;
        // Every shard's description and a sample of its records recomputed bit for bit,
        // as a resume verifies what it reuses (issue 33: forged labels were merged).
        verify_inputs(&inputs, &shared.0, given)?;
        check_owner(&self.out, &shared.0, self.replace).map_err(another_design)?;
        // Links, FIFOs and foreign files at the names the merge copies to: refused before
        // the folder is opened, as a dataset run refuses them (issue 33).
        let prev = OutputDir::previous_state_of(&self.out, None);
        let names = inputs
            .iter()
            .flat_map(|d| copied_names(d, &self.out, &shared.0));
        let refused = refused_names(&self.out, names, prev.as_ref());
        if !refused.is_empty() {
            return Err(DatasetError::Input(refused).into());
        }
        let out = publish::open(&self.out, None, self.name(), self.replace)?;
        let o = merge_datasets(&inputs, &self.out, out, shared, figures)?;
        observer.note(&written(&o, &self.out, "dataset-merge", false));
        Ok(outcome(&o, &self.out, "dataset-merge"))
    }
}

/// The refusal of a folder that holds another design's dataset (`check_owner`'s message),
/// with its two ways out: another folder, or replacing the dataset.
fn another_design(problem: super::folder::FolderError) -> JobError {
    use crate::remedy::{Remedy, Words};
    JobError::input(
        Problem::of(Arg::Out, problem.to_string()).remedy(Remedy::new(
            Words::new()
                .text("choose another folder (")
                .arg(Arg::Out)
                .text("), or allow replacing its dataset (")
                .arg(Arg::Replace)
                .text(")"),
        )),
    )
}

/// [`verify_dataset`] of the design in `design` (read as a dataset job reads it) for the
/// folder `root`, within `budget` (the default: [`budget::DEFAULT`]; None: no check):
/// its cost counted before any record is read (`study::budget::estimate_folder_check`:
/// the kept trajectories checked, `sample` states recomputed, every other kept record
/// read back and analysed; issue 33: it was budgeted nowhere), refused as a job over
/// budget is.
pub fn verify_folder(
    design: &DesignSource,
    root: &Path,
    sample: usize,
    seed: u64,
    budget: Option<&Budget>,
) -> Result<Verified, JobError> {
    let (d, path, path_bytes) = load_design(design)?;
    let req = DatasetRequest {
        design: &d,
        path,
        path_bytes,
        shard: crate::study::dataset::plan::Shard { index: 1, count: 1 },
        figures: Default::default(),
        replace: false,
    };
    if budget.is_some() {
        // Counted from the sidecars' names, before any is read (issue 33: every
        // sidecar was parsed first): the records a check reads back at most.
        let checked = check_dataset(&req)?;
        let kept = super::folder::kept_by_names(root, &d);
        let threads = rayon::current_num_threads();
        let e = estimate_folder_check(&d, kept, sample, threads, checked.record);
        budget::check_estimate(&e, budget)?;
    }
    Ok(verify_dataset(&req, root, sample, seed)?)
}
