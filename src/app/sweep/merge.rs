//! The sweep-merge job: joins the tables of sweep shards (or of earlier merges) into one,
//! sorted by case id, refusing inputs of different sweeps.

use super::super::budget::over_budget;
use super::super::observer::Observer;
use super::super::{publish, Job, JobError, Outcome};
use super::SweepOutput;
use crate::remedy::{Arg, Problem};
use crate::report::figure_output::FigureRequest;
use crate::report::sweep_figure::{figures_for, SWEEP_FIGURE_PX};
use crate::report::Artifacts;
use crate::study::budget::Budget;
use crate::study::sweep::{Crossing, SweepTable};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// See the module docs.
#[derive(Debug, Clone)]
pub struct SweepMergeJob {
    /// Sweep output folders (their `sweep.csv` and `sweep_shard_*_of_*.csv`) or CSV files.
    pub inputs: Vec<PathBuf>,
    /// An output folder (gets `sweep.*`), or a `.csv` path (`FILE.*` beside it); `None`
    /// writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The budget of the merge (the tables read and joined).
    pub budget: Option<Budget>,
    /// The formats and size of the figure, checked when the job starts.
    pub figures: FigureRequest,
}

/// The sweep tables of a merge input: a CSV file, or a folder's `sweep.csv` and
/// `sweep_shard_*_of_*.csv`. Each comes with its `.json` description when present.
fn merge_inputs(input: &Path) -> Result<Vec<PathBuf>, JobError> {
    let shown = input.display().to_string();
    if !input.exists() {
        return Err(Problem::given(Arg::Inputs, shown, "does not exist").into());
    }
    if !input.is_dir() {
        // Read as a table only if it is a regular file (`io::read_input` says what it is).
        return Ok(vec![input.to_path_buf()]);
    }
    let mut found: Vec<PathBuf> = std::fs::read_dir(input)
        .map_err(|e| Problem::given(Arg::Inputs, &shown, format!("cannot read: {e}")))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            let n = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
            n == "sweep.csv" || (n.starts_with("sweep_shard_") && n.ends_with(".csv"))
        })
        .collect();
    found.sort();
    if found.is_empty() {
        return Err(Problem::given(
            Arg::Inputs,
            shown,
            "holds no sweep.csv or sweep_shard_*_of_*.csv",
        )
        .into());
    }
    Ok(found)
}

/// Whether a description is a sweep's or a merge's.
fn describes_a_sweep(m: &Value) -> bool {
    (m["command"] == "sweep" || m["command"] == "sweep-merge") && !m["vary"].is_null()
}

/// What makes tables parts of one sweep.
fn identity(m: &Value) -> Value {
    json!([
        m["vary"],
        m["run"],
        m["base"]["case_sha256"],
        m["total_cases"]
    ])
}

/// Tables and descriptions, each with its source.
type Read = (Vec<(String, SweepTable)>, Vec<(String, Value)>);

impl SweepMergeJob {
    /// Every table of the inputs with its source and its description.
    fn read(&self) -> Result<Read, JobError> {
        let mut tables = Vec::new();
        let mut metas = Vec::new();
        let mut bytes = 0u64;
        for input in &self.inputs {
            for csv in merge_inputs(input)? {
                // The budget, from the tables' sizes before each is read.
                bytes += std::fs::metadata(&csv).map_or(0, |m| m.len());
                if let Some(b) = &self.budget {
                    crate::study::budget::estimate_sweep_merge(bytes)
                        .check(b)
                        .map_err(|m| JobError::input(over_budget(m)))?;
                }
                let src = csv.display().to_string();
                // The table and its description, both required (`store::sweep_inputs`).
                let (t, m) = crate::store::sweep_inputs::merge_input(&csv)
                    .map_err(|e| Problem::of(Arg::Inputs, e))?;
                metas.push((src.clone(), m));
                tables.push((src, t));
            }
        }
        Ok((tables, metas))
    }

    /// The folder and file stem: `DIR` writes `DIR/sweep.*`, `FILE.csv` writes `FILE.*`.
    fn target(&self) -> Option<(PathBuf, String)> {
        let out = self.out.as_ref()?;
        Some(if out.extension().is_some_and(|e| e == "csv") {
            let dir = out
                .parent()
                .filter(|p| !p.as_os_str().is_empty())
                .unwrap_or(Path::new("."))
                .to_path_buf();
            let stem = out
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_else(|| "sweep".into());
            (dir, stem)
        } else {
            (out.clone(), "sweep".to_owned())
        })
    }
}

impl Job for SweepMergeJob {
    type Output = SweepOutput;

    fn name(&self) -> &'static str {
        "sweep-merge"
    }

    fn run(&self, observer: &dyn Observer) -> Result<SweepOutput, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        let (tables, metas) = self.read()?;
        let merged = SweepTable::merge(&tables).map_err(|e| Problem::new(e.to_string()))?;
        // Descriptions present must agree on the sweep itself (axes, run, base case): shards
        // of different sweeps can have disjoint case ids and would otherwise merge silently.
        // A merge's description carries the same identity forward, so a merge of merges (or
        // of a merge and a shard) is checked like a merge of shards.
        if let Some((src0, m0)) = metas.iter().find(|(_, m)| describes_a_sweep(m)) {
            for (src, m) in metas.iter().filter(|(_, m)| describes_a_sweep(m)) {
                if identity(m) != identity(m0) {
                    return Err(Problem::new(format!(
                        "mixed sweeps: {src} and {src0} come from different sweeps (axes, run kind, base case or size differ)"
                    ))
                    .into());
                }
            }
        }
        let (dir, stem) = match self.target() {
            Some((d, s)) => (Some(d), s),
            None => (None, "sweep".to_owned()),
        };
        let out = publish::open_if(dir.as_deref(), Some(&stem), self.name(), self.replace)?;
        let total = metas
            .iter()
            .find_map(|(_, m)| m["total_cases"].as_u64())
            .map(|n| n as usize)
            // Bounded by the plan's limit (a description is an input: it could claim any size).
            .filter(|n| *n <= crate::study::sweep::plan::MAX_CASES);
        let have: std::collections::BTreeSet<usize> =
            merged.rows.iter().map(|r| r.case_id).collect();
        let missing: Vec<usize> =
            total.map_or_else(Vec::new, |n| (0..n).filter(|i| !have.contains(i)).collect());
        if !missing.is_empty() {
            observer.warning(&format!(
                "{} of {} cases missing from the merged table (first: {:?}); rerun their shards",
                missing.len(),
                total.unwrap_or(0),
                &missing[..missing.len().min(10)]
            ));
        }
        let mut art = Artifacts::default().with_figure_output(figures);
        add_merged_figures(&mut art, &metas, &merged, &stem);
        let first = metas
            .iter()
            .find(|(_, m)| describes_a_sweep(m))
            .map(|(_, m)| m.clone());
        art.summary = json!({
                "command": "sweep-merge",
                "inputs": tables.iter().map(|(s, _)| s.clone()).collect::<Vec<_>>(),
                "rows": merged.rows.len(),
                "total_cases": total,
                "missing_case_ids": missing,
                "vary": first.as_ref().map(|m| m["vary"].clone()),
                "run": first.as_ref().map(|m| m["run"].clone()),
                "resonance_crossings": first.as_ref().map(|m| m["resonance_crossings"].clone()),
                "modes": first.as_ref().map(|m| m["modes"].clone()),
                "base": first.as_ref().map(|m| m["base"].clone()),
        });
        if let (Some(st), Some(m)) = (
            first
                .as_ref()
                .map(|m| &m["stages"])
                .filter(|s| !s.is_null()),
            art.summary.as_object_mut(),
        ) {
            m.insert("stages".into(), st.clone());
        }
        art.summary_file = Some(format!("{stem}.json"));
        art.documents.push((
            format!("{stem}.csv"),
            merged.to_csv().map_err(|e| JobError::Failed(e.into()))?,
        ));
        art.headline = format!(
            "sweep-merge: {} rows from {} table(s)",
            merged.rows.len(),
            tables.len()
        );
        let outcome: Outcome = publish::publish(out, art, None, observer)?;
        if let Some(d) = &dir {
            observer.note(&format!(
                "sweep-merge: {} table(s), {} rows -> {}",
                tables.len(),
                merged.rows.len(),
                d.join(format!("{stem}.csv")).display()
            ));
        }
        Ok(SweepOutput {
            outcome,
            table: merged,
        })
    }
}

/// The merged table's figures, with the resonance crossings and mesh poles the inputs'
/// descriptions carry (a train's crossings per mesh from their `stages`).
fn add_merged_figures(
    art: &mut Artifacts,
    metas: &[(String, serde_json::Value)],
    merged: &SweepTable,
    stem: &str,
) {
    let marks: Option<Vec<Crossing>> = metas
        .iter()
        .find_map(|(_, m)| serde_json::from_value(m["resonance_crossings"].clone()).ok());
    let poles: Vec<f64> = metas
        .iter()
        .find_map(|(_, m)| m["modes"]["mesh_poles"].as_array().cloned())
        .unwrap_or_default()
        .iter()
        .filter_map(|p| p["damped_frequency_hz"].as_f64())
        .collect();
    let stage_marks: Vec<Vec<Crossing>> = metas
        .iter()
        .find_map(|(_, m)| m["stages"].as_array().cloned())
        .unwrap_or_default()
        .iter()
        .map(|s| serde_json::from_value(s["resonance_crossings"].clone()).unwrap_or_default())
        .collect();
    let marks = marks.as_deref().unwrap_or(&[]);
    for (suffix, fig) in figures_for(merged, marks, &stage_marks, &poles) {
        let (w, h) = SWEEP_FIGURE_PX;
        art.figure_sized(format!("{stem}{suffix}.png"), fig, w, h);
    }
}
