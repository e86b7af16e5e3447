//! The sweep job: the cross product of varied keys over a base case, one row per case, in
//! parallel; or one axis followed in order along its solution branches (continuation).
//! One path for both forms: in memory (nothing written), or to an output folder, where it
//! is resumable (finished cases are skipped) and shardable.
//!
//! Output folder layout (STEM = `sweep`, or `sweep_shard_I_of_N` for a shard):
//! `cases/<case_id>.json` (one per finished case, written first, atomically),
//! `STEM.csv` (this shard's rows by case id), `STEM.json` (what was run: axes, base case,
//! modes, failures; also the summary handed back), `STEM.png` (speed and continuation
//! sweeps). [`SweepMergeJob`] joins shard tables.

mod branches;
mod cases;
mod helical;
mod merge;
mod planetary;
mod records;

pub use merge::SweepMergeJob;

use super::budget::over_budget;
use super::observer::{Observer, Task};
use super::{publish, Job, JobError, Outcome};
use crate::config::Case;
use crate::duty::study::run_sweep_case;
use crate::io::output_dir::StateFolder;
use crate::remedy::{Arg, Problem, Words};
use crate::report::figure_output::{FigureOutput, FigureRequest};
use crate::report::modes::modes_json;
use crate::report::sweep_figure::{figures_for, SWEEP_FIGURE_PX};
use crate::report::Artifacts;
use crate::store::RunMetadata;
use crate::study::budget::{estimate_sweep, Budget, Job as Cost};
use crate::study::sweep::resonance::{speed_marks, SpeedMarks};
use crate::study::sweep::{
    CaseError, CaseRecord, Continuation, ContinuationPlan, Shard, SweepPlan, SweepRow, SweepRun,
    SweepTable,
};
use crate::study::Model;
use cases::{check_models, check_values, resolve, Planned};
use rayon::prelude::*;
use records::{check_case_files, finished, verify_finished, write_record};
use serde_json::json;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

/// See the module docs.
#[derive(Debug, Clone)]
pub struct SweepJob {
    /// The case every sweep case starts from.
    pub base: Case,
    /// The varied keys and their values.
    pub plan: SweepPlan,
    /// What each case runs.
    pub run: SweepRun,
    /// The part of the cases to run ([`Shard::ALL`]: every case).
    pub shard: Shard,
    /// Follow the single axis along solution branches instead.
    pub continuation: Option<Continuation>,
    /// Output folder; `None`: in memory, nothing written.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The budget of each case.
    pub budget: Option<Budget>,
    /// The formats and size of the figures, checked when the job starts.
    pub figures: FigureRequest,
}

/// What a sweep hands back: the outcome (the summary is `STEM.json`'s content) and the
/// table.
pub struct SweepOutput {
    /// What the job did (its summary is `sweep.json`'s content).
    pub outcome: Outcome,
    /// The sweep's table (one row per case).
    pub table: SweepTable,
}

impl AsRef<Outcome> for SweepOutput {
    fn as_ref(&self) -> &Outcome {
        &self.outcome
    }
}

/// What ran now: each case id with its warnings or its error.
type Outcomes = Vec<(usize, Result<Vec<String>, CaseError>)>;

/// The cases run now, the rows of the table, and the cases skipped as finished.
pub struct Ran {
    outcomes: Outcomes,
    rows: Vec<SweepRow>,
    skipped: usize,
}

/// The row of a case record.
fn row_of(r: &CaseRecord) -> Option<SweepRow> {
    Some(SweepRow {
        case_id: r.case_id,
        values: r.values.clone(),
        results: r.case_results()?,
        branch: r.continuation.as_ref().map(|c| c.branch),
    })
}

impl SweepJob {
    /// A wear sweep of a gear train under a `[load_spectrum]` is not built (each case would
    /// need the train's duty study): refused before any case runs.
    /// A wear sweep of a train with a tooth fault (`fault.stage`) is refused too
    /// (`study::train::refuse_fault`).
    fn refuse_train_spectrum(&self) -> Result<(), JobError> {
        if self.run == SweepRun::Wear {
            crate::study::train::refuse_fault(&self.base, "`gearwear sweep` of wear")?;
        }
        if self.base.stage.is_empty()
            || self.base.load_spectrum.is_none()
            || self.run != SweepRun::Wear
        {
            return Ok(());
        }
        Err(Problem::given(
            Arg::SweepRun,
            self.run.name(),
            Words::new().text(
                "this case is a gear train ([[stage]] tables) under a [load_spectrum]: its wear sweep is not built yet (a wear sweep of a train runs at one operating point; `gearwear wear` runs the train under its spectrum); remove the [load_spectrum] table to sweep the train's wear",
            ),
        )
        .into())
    }

    /// The continuation's order of points, after its checks: one axis, dynamics, no shard.
    fn continuation_plan(&self) -> Result<Option<ContinuationPlan>, JobError> {
        let Some(c) = self.continuation else {
            return Ok(None);
        };
        planetary::refuse_continuation(&self.base)?;
        if self.shard != Shard::ALL {
            return Err(Problem::given(
                Arg::Shard,
                format!("{}/{}", self.shard.index, self.shard.count),
                Words::new()
                    .text("a branch of a ")
                    .arg(Arg::Continuation)
                    .text(" runs in order, point after point, so it cannot be split into shards"),
            )
            .into());
        }
        if self.run != SweepRun::Dynamics {
            return Err(Problem::of(
                Arg::Continuation,
                Words::new()
                    .text("needs ")
                    .arg(Arg::SweepRun)
                    .text(" dynamics (the wear study is not warm-started along a branch)"),
            )
            .into());
        }
        Ok(Some(ContinuationPlan::new(&self.plan, c)?))
    }

    /// The sweep against the budget before any case is resolved
    /// (`study::budget::estimate_sweep`, from a few sampled values of each axis): its
    /// costliest case alone, and its shard's cases together.
    fn check_budget(&self) -> Result<(), JobError> {
        let Some(b) = &self.budget else {
            return Ok(());
        };
        let n = self.plan.len();
        let cases = n
            .saturating_sub(self.shard.index - 1)
            .div_ceil(self.shard.count.max(1));
        let threads = rayon::current_num_threads();
        let Some(e) = estimate_sweep(
            &self.base,
            &self.plan,
            (Cost::SweepCase(self.run), self.continuation.is_some()),
            cases,
            threads,
        ) else {
            return Ok(()); // cases that do not load are named by the checks that follow
        };
        e.worst_case.check(b).map_err(|m| {
            JobError::input(over_budget(format!(
                "the sweep's costliest case ({}): {m}",
                e.worst_overrides.join(", ")
            )))
        })?;
        e.total.check(b).map_err(|m| {
            JobError::input(
                Problem::new(format!("the sweep of {cases} case(s) as one run: {m}")).remedy(
                    crate::remedy::Remedy::new(
                        Words::new()
                            .text("split it into shards (")
                            .arg(Arg::Shard)
                            .text(": each shard is one run), ease those keys (lower a length, count or rate; raise a speed), or raise the budget knowingly with ")
                            .arg(Arg::BudgetScale)
                            .text(" X"),
                    ),
                ),
            )
        })
    }

    /// Run the continuation `c` branch by branch (`branches::run_branches`), each point's
    /// record into `folders` (the output folder and its cases folder) if given.
    fn run_continuation(
        &self,
        c: &ContinuationPlan,
        (planned, keys, columns): (&[Planned], &[String], &[String]),
        folders: Option<(&std::path::Path, &StateFolder)>,
        observer: &dyn Observer,
    ) -> Ran {
        observer.note(&format!(
            "sweep: continuation along {} ({} branch(es), {} points; points finished from the same start state are skipped)",
            keys.join(", "),
            c.branches.len(),
            c.len()
        ));
        let task = Task::items("sweep", "sweep cases", c.len());
        observer.start(&task);
        let count = std::sync::atomic::AtomicUsize::new(0);
        let on_point = || {
            let n = count.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            observer.advance(&task, n as f64, "");
        };
        let helical = helical::helical_table(&self.base, &self.plan);
        let r = branches::run_branches(
            (folders, helical, columns),
            c,
            planned,
            keys,
            &on_point,
            &|| !observer.cancelled(),
        );
        observer.finish(&task);
        r
    }

    /// Run the pending cases in parallel, writing their records into `cases` if given.
    fn run_parallel(
        &self,
        cases: Option<&StateFolder>,
        pending: &[&Planned],
        done: Vec<SweepRow>,
        keys: &[String],
        observer: &dyn Observer,
    ) -> Ran {
        let task = Task::items("sweep", "sweep cases", pending.len());
        observer.start(&task);
        let count = std::sync::atomic::AtomicUsize::new(0);
        let helical = helical::helical_table(&self.base, &self.plan);
        type Ran1 = (usize, Result<(Vec<String>, Option<SweepRow>), CaseError>);
        let ran: Vec<Ran1> = pending
            .par_iter()
            .map(|p| {
                if observer.cancelled() {
                    let e = CaseError::Solve(anyhow::anyhow!("stopped before it ran"));
                    return (p.id, Err(e));
                }
                let r = run_sweep_case(&p.case, self.run).and_then(|mut o| {
                    o.results = o.results.with_helical_columns(helical);
                    let row = match cases {
                        Some(c) => row_of(&write_record(c, p, keys, &o.results, None)?),
                        None => Some(SweepRow {
                            case_id: p.id,
                            values: p.labels.clone(),
                            results: o.results,
                            branch: None,
                        }),
                    };
                    Ok((o.warnings, row))
                });
                let n = count.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
                observer.advance(&task, n as f64, "");
                (p.id, r)
            })
            .collect();
        observer.finish(&task);
        let skipped = done.len();
        let mut rows = done;
        let mut outcomes = Vec::with_capacity(ran.len());
        for (id, r) in ran {
            outcomes.push((
                id,
                r.map(|(w, row)| {
                    rows.extend(row);
                    w
                }),
            ));
        }
        Ran {
            outcomes,
            rows,
            skipped,
        }
    }
}

/// The failed cases of `outcomes` as summary entries (id, values, branch, error); the
/// warnings of the others go to `observer` once each, with their number of cases.
fn failures(
    outcomes: Outcomes,
    planned: &[Planned],
    continuation: Option<&ContinuationPlan>,
    observer: &dyn Observer,
) -> Vec<serde_json::Value> {
    let labels_of: BTreeMap<usize, &Vec<String>> =
        planned.iter().map(|p| (p.id, &p.labels)).collect();
    let branch_of = |id: usize| {
        continuation.and_then(|c| {
            c.branches
                .iter()
                .find(|(_, p)| p.iter().any(|x| x.case_id == id))
                .map(|(b, _)| b.name())
        })
    };
    let mut warnings: BTreeMap<String, usize> = BTreeMap::new();
    let mut failed = Vec::new();
    for (id, r) in outcomes {
        match r {
            Ok(w) => w
                .into_iter()
                .for_each(|w| *warnings.entry(w).or_default() += 1),
            Err(e) => failed.push(json!({
                "case_id": id,
                "values": labels_of.get(&id),
                "branch": branch_of(id),
                "error": e.to_string(),
            })),
        }
    }
    for (w, n) in &warnings {
        observer.warning(&format!("{w} ({n} case(s))"));
    }
    failed
}

/// `stages` of a train's speed sweep summary: per mesh, its order (mesh frequency per
/// input rev/s) and the crossings of its harmonics with the train's mesh poles.
fn stages_json(stages: &[(f64, Vec<crate::study::sweep::Crossing>)]) -> serde_json::Value {
    stages
        .iter()
        .enumerate()
        .map(|(k, (order, c))| {
            json!({
                "stage": k + 1,
                "mesh_frequency_per_input_hz": order,
                "resonance_crossings": c,
            })
        })
        .collect()
}

impl Job for SweepJob {
    type Output = SweepOutput;

    fn name(&self) -> &'static str {
        "sweep"
    }

    fn run(&self, observer: &dyn Observer) -> Result<SweepOutput, JobError> {
        let started = Instant::now();
        let figures = self.figures.resolve().map_err(JobError::input)?;
        // What a train cannot run, before the budget; then the budget, in milliseconds.
        self.refuse_train_spectrum()?;
        self.check_budget()?;
        check_values(&self.base, &self.plan)?;
        let continuation = self.continuation_plan()?;
        let plan = &self.plan;
        let keys = plan.keys();
        // Case ids with their plan index: a continuation point's id numbers it in run order.
        let ids: Vec<(usize, usize)> = match &continuation {
            None => self
                .shard
                .ids(plan.len())
                .into_iter()
                .map(|i| (i, i))
                .collect(),
            Some(c) => c
                .branches
                .iter()
                .flat_map(|(_, p)| p.iter().map(|x| (x.case_id, x.value_index)))
                .collect(),
        };
        let planned = resolve(&self.base, plan, &ids, self.run, self.budget.as_ref())?;
        let dir = self.out.as_deref();
        if let Some(d) = dir {
            check_case_files(d, &planned)?;
        }
        // A record is reused only with the table's columns (a plan that now has, or no
        // longer has, a helical pair's columns recomputes its spur cases).
        let columns = self.result_columns(plan);
        let done: Vec<CaseRecord> = match dir {
            Some(d) if continuation.is_none() => planned
                .iter()
                .filter_map(|p| finished(d, p, self.run, &keys))
                .filter(|r| r.columns == columns)
                .collect(),
            _ => Vec::new(),
        };
        let pending: Vec<&Planned> = planned
            .iter()
            .filter(|p| done.iter().all(|r| r.case_id != p.id))
            .collect();
        if let Some(d) = dir {
            let by_id: BTreeMap<usize, &Planned> = planned.iter().map(|p| (p.id, p)).collect();
            let pairs: Vec<(&Planned, &CaseRecord)> = done
                .iter()
                .filter_map(|r| by_id.get(&r.case_id).map(|p| (*p, r)))
                .collect();
            verify_finished(d, &pairs, self.run)?;
        }
        check_models(plan, &pending, self.run)?;
        let stem = self.shard.stem();
        let out = publish::open_if(dir, Some(&stem), self.name(), self.replace)?;
        let cases = out.as_ref().map(|o| o.state_folder("cases")).transpose()?;

        let ran = if let Some(c) = &continuation {
            let folders = dir.zip(cases.as_ref());
            self.run_continuation(c, (&planned, &keys, &columns), folders, observer)
        } else {
            observer.note(&format!(
                "sweep: {} cases in all, {} in shard {}/{}: {} already finished (skipped), {} to run on {} threads",
                plan.len(),
                planned.len(),
                self.shard.index,
                self.shard.count,
                done.len(),
                pending.len(),
                rayon::current_num_threads()
            ));
            let rows = done.iter().filter_map(row_of).collect();
            self.run_parallel(cases.as_ref(), &pending, rows, &keys, observer)
        };
        if observer.cancelled() {
            return Err(JobError::Cancelled);
        }
        self.finish(
            out,
            ran,
            &planned,
            continuation.as_ref(),
            (started, figures),
            observer,
        )
    }
}

impl SweepJob {
    /// The sweep's table with no row yet: its keys and result columns (the run's, each
    /// mesh's of a train, a helical pair's, a planetary set's).
    fn empty_table(&self, plan: &SweepPlan) -> SweepTable {
        SweepTable::new(plan.keys(), self.run)
            .with_stages(self.base.stage.len())
            .with_helical(helical::helical_table(&self.base, plan))
            .with_planets(planetary::planets_of(&self.base))
    }

    /// The result columns of the sweep's table ([`SweepJob::empty_table`]).
    fn result_columns(&self, plan: &SweepPlan) -> Vec<String> {
        self.empty_table(plan).columns()
    }

    /// The figure of the sweep (with the base case's resonance crossings on a speed
    /// axis), the marks, and the base case's metadata.
    fn figure(
        &self,
        table: &SweepTable,
        stem: &str,
        observer: &dyn Observer,
    ) -> (Artifacts, Option<SpeedMarks>, RunMetadata) {
        let plan = &self.plan;
        let base_model = Model::dynamics_from_case(&self.base);
        let speed: Option<SpeedMarks> = match &base_model {
            Ok(m) => speed_marks(m, plan),
            // A planetary set has no resonance markers yet (its modes are the stiffness
            // study's): no warning for it.
            Err(_) if self.base.planetary.is_some() => None,
            Err(e) => {
                observer.warning(&format!(
                    "no resonance markers: the base case has no model: {e}"
                ));
                None
            }
        };
        let poles = speed
            .as_ref()
            .map_or_else(Vec::new, |m| m.modal.mesh_pole_frequencies_hz());
        let marks = speed.as_ref().map_or(&[][..], |m| &m.crossings[..]);
        let stage_marks: Vec<Vec<_>> = speed
            .as_ref()
            .map_or_else(Vec::new, |m| m.stages.iter().map(|s| s.1.clone()).collect());
        let mut art = Artifacts::default();
        for (suffix, fig) in figures_for(table, marks, &stage_marks, &poles) {
            let (w, h) = SWEEP_FIGURE_PX;
            art.figure_sized(format!("{stem}{suffix}.png"), fig, w, h);
        }
        let base = match &base_model {
            Ok(m) => RunMetadata::of_model("sweep", m),
            Err(_) => RunMetadata::new("sweep", &self.base),
        };
        (art, speed, base)
    }

    /// The table, the summary, the figure (written as `figures` says) and the warnings of
    /// a sweep that ran (since `started`); published when the sweep has an output folder.
    fn finish(
        &self,
        mut out: Option<crate::io::OutputDir>,
        ran: Ran,
        planned: &[Planned],
        continuation: Option<&ContinuationPlan>,
        (started, figures): (Instant, FigureOutput),
        observer: &dyn Observer,
    ) -> Result<SweepOutput, JobError> {
        let plan = &self.plan;
        let computed_now = ran.outcomes.len();
        let failed = failures(ran.outcomes, planned, continuation, observer);
        let computed = computed_now - failed.len();
        let mut table = self.empty_table(plan);
        table.rows = ran.rows;
        table.rows.sort_by_key(|r| r.case_id);
        let stem = self.shard.stem();
        if let Some(o) = out.as_mut() {
            for r in &table.rows {
                o.keep_state(&format!("cases/{}.json", r.case_id));
            }
        }

        let (art, speed, base) = self.figure(&table, &stem, observer);
        let mut art = art.with_figure_output(figures);
        let wall_s = started.elapsed().as_secs_f64();
        art.summary = json!({
            "command": "sweep",
            "run": self.run,
            "vary": plan.axes.iter().map(|x| json!({"key": x.key, "values": x.labels()})).collect::<Vec<_>>(),
            "total_cases": plan.len(),
            "shard": {"index": self.shard.index, "count": self.shard.count, "scheme": "round-robin: case_id mod count = index - 1"},
            "cases_in_shard": planned.len(),
            "continuation": self.continuation.map(|c| format!("{c:?}").to_lowercase()),
            "failed": failed,
            "rows": table.rows.len(),
            "modes": speed.as_ref().map(|s| modes_json(&s.modal)),
            "resonance_crossings": speed.as_ref().map(|s| s.crossings.clone()),
            "base": base,
        });
        if let (Some(s), Some(m)) = (speed.as_ref(), art.summary.as_object_mut()) {
            if !s.stages.is_empty() {
                m.insert("stages".into(), stages_json(&s.stages));
            }
        }
        art.summary_file = Some(format!("{stem}.json"));
        art.documents.push((
            format!("{stem}.csv"),
            table.to_csv().map_err(|e| JobError::Failed(e.into()))?,
        ));
        let counts = format!(
            "{} computed, {} skipped, {} failed",
            computed,
            ran.skipped,
            failed.len()
        );
        art.headline = format!("sweep: {} rows ({counts})", table.rows.len());
        let rows = table.rows.len();
        let mut outcome = publish::publish(out, art, None, observer)?;
        // The counts and the time of this run are handed back and said, but kept out of
        // the published STEM.json, so that two runs of a sweep write the same bytes.
        if let Some(m) = outcome.artifacts.summary.as_object_mut() {
            m.insert("skipped_finished".into(), json!(ran.skipped));
            m.insert("computed".into(), json!(computed));
            m.insert("wall_time_s".into(), json!(wall_s));
        }
        let to = match &self.out {
            Some(d) => format!(" -> {}", d.join(format!("{stem}.csv")).display()),
            None => String::new(),
        };
        observer.note(&format!("sweep: {rows} rows{to} ({counts}; {wall_s:.1} s)"));
        if !failed.is_empty() {
            let list: Vec<String> = failed
                .iter()
                .map(|f| format!("case {}: {}", f["case_id"], f["error"]))
                .collect();
            let rerun = match (continuation.is_some(), self.out.is_some()) {
                (true, _) => {
                    " (each branch went on from the last point that succeeded; rerun to retry them)"
                }
                (false, true) => " (rerun to retry them; finished cases are skipped)",
                (false, false) => "",
            };
            outcome.incomplete = Some(format!(
                "{} of {} cases failed{rerun}:\n  {}",
                failed.len(),
                planned.len(),
                list.join("\n  ")
            ));
        }
        Ok(SweepOutput { outcome, table })
    }
}
