//! `gearwear sweep`: the cross product of `--vary` axes, run in parallel, one row per
//! case; resumable (finished cases are skipped) and shardable; or, with `--continuation`,
//! one axis followed in order along its solution branches (`sweep_continuation`).
//! `gearwear sweep-merge` (`sweep_merge_cmd`) joins shard tables.
//!
//! Output directory layout (STEM = `sweep`, or `sweep_shard_I_of_N` with `--shard`):
//! `cases/<case_id>.json` (one per finished case, written first, atomically),
//! `STEM.csv` (this shard's rows by case id), `STEM.json` (what was run: axes, base case,
//! modes, failures), `STEM.png` (speed and continuation sweeps).

use super::args::{CaseArgs, SweepArgs, SweepRunArg};
use super::output::say;
use super::progress::count_bar;
use super::sweep_continuation::{continuation_of, run_branches};
use super::sweep_records::{case_path, write_record, Outcomes, Planned};
use super::CliError;
use crate::config::{load_case, schema};
use crate::io::output_dir::StateFolder;
use crate::io::RunMetadata;
use crate::report::artifacts::{stage_figures, Artifacts};
use crate::report::modes::modes_json;
use crate::report::sweep_figure::{figure_for, SWEEP_FIGURE_PX};
use crate::study::sweep::resonance::speed_marks;
use crate::study::sweep::{
    parse_vary, run_case, CaseError, CaseRecord, Shard, SweepPlan, SweepRun, SweepTable,
};
use crate::study::Model;
use rayon::prelude::*;
use serde_json::json;
use std::collections::BTreeMap;
use std::path::Path;
use std::time::Instant;

fn describe(keys: &[String], values: &[String]) -> String {
    keys.iter()
        .zip(values)
        .map(|(k, v)| format!("{k}={v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn read_config(c: &CaseArgs) -> Result<String, CliError> {
    c.text()
}

/// Parse the axes and check every value of every axis on the base case, so a bad value
/// is reported (key and value named) before anything runs.
fn plan_of(a: &SweepArgs, text: &str) -> Result<SweepPlan, CliError> {
    let mut problems = Vec::new();
    let mut axes = Vec::new();
    for v in &a.vary {
        match parse_vary(v) {
            Ok(x) => axes.push(x),
            Err(e) => problems.push(e),
        }
    }
    if !problems.is_empty() {
        return Err(CliError::Input(problems));
    }
    let plan = SweepPlan::new(axes).map_err(CliError::input)?;
    for axis in &plan.axes {
        let unknown_key = schema::spec(&axis.key).is_none();
        for v in &axis.values {
            let mut sets = a.case.set.clone();
            sets.push(format!("{}={v}", axis.key));
            if let Err(e) = load_case(text, &sets) {
                problems.extend(
                    e.problems
                        .iter()
                        .map(|p| format!("--vary {}: value `{v}`: {p}", axis.key)),
                );
                if unknown_key {
                    break; // the same message for every value
                }
            }
        }
    }
    if problems.is_empty() {
        Ok(plan)
    } else {
        Err(CliError::Input(problems))
    }
}

/// The record of a finished case, if `cases/<id>.json` holds this very case's result.
fn finished(dir: &Path, p: &Planned, run: SweepRun, keys: &[String]) -> Option<CaseRecord> {
    let r = CaseRecord::read(&case_path(dir, p.id)).ok()??;
    r.is_result_of(p.id, &p.hash, run, keys, &p.values)
        .then_some(r)
}

/// Every case file of the plan that exists must read back whole and unedited
/// (`CaseRecord::verify`); a record of another case (changed base case or values) is
/// fine: it is recomputed and replaced.
fn check_case_files(dir: &Path, planned: &[Planned]) -> Result<(), CliError> {
    let problems: Vec<String> = planned
        .iter()
        .filter_map(|p| CaseRecord::read(&case_path(dir, p.id)).err())
        .map(|e| format!("{e}; delete it to recompute that case"))
        .collect();
    if problems.is_empty() {
        Ok(())
    } else {
        Err(CliError::Input(problems))
    }
}

/// Recompute a random sample of the finished cases (`study::sweep::verify`): a record
/// edited with a recomputed checksum is refused, naming it.
fn verify_finished(
    dir: &Path,
    done: &[&Planned],
    run: SweepRun,
    keys: &[String],
) -> Result<(), CliError> {
    use crate::study::sweep::verify::{cases_to_recompute, verify_record};
    let problems: Vec<String> = cases_to_recompute(done.len())
        .into_par_iter()
        .filter_map(|i| {
            let p = done[i];
            let rec = finished(dir, p, run, keys)?;
            verify_record(&p.case, run, &rec).err().map(|e| {
                format!(
                    "{}: {e}; delete it to recompute that case",
                    case_path(dir, p.id).display()
                )
            })
        })
        .collect();
    if problems.is_empty() {
        Ok(())
    } else {
        Err(CliError::Input(problems))
    }
}

/// Run one case and write its record.
fn run_one(
    cases: &StateFolder,
    p: &Planned,
    run: SweepRun,
    keys: &[String],
) -> Result<Vec<String>, CaseError> {
    let o = run_case(&p.case, run)?;
    write_record(cases, p, run, keys, &o.results, None)?;
    Ok(o.warnings)
}

pub fn run(a: &SweepArgs) -> Result<(), CliError> {
    let started = Instant::now();
    let run_kind = match a.run {
        SweepRunArg::Dynamics => SweepRun::Dynamics,
        SweepRunArg::Wear => SweepRun::Wear,
    };
    let text = read_config(&a.case)?;
    let base = load_case(&text, &a.case.set)?;
    let plan = plan_of(a, &text)?;
    let shard = match &a.shard {
        Some(s) => Shard::parse(s).map_err(CliError::input)?,
        None => Shard::ALL,
    };
    let continuation = continuation_of(a, &plan)?;
    let keys = plan.keys();
    // Case ids with their plan index: a continuation point's id numbers it in run order.
    let ids: Vec<(usize, usize)> = match &continuation {
        None => shard.ids(plan.len()).into_iter().map(|i| (i, i)).collect(),
        Some(c) => c
            .branches
            .iter()
            .flat_map(|(_, p)| p.iter().map(|x| (x.case_id, x.value_index)))
            .collect(),
    };

    // Resolve and validate every case of the shard (and its model) before running any.
    let resolved: Vec<Result<Planned, String>> = ids
        .par_iter()
        .map(|&(id, index)| {
            let values = plan.values_of(index);
            let mut sets = a.case.set.clone();
            sets.extend(plan.overrides_of(index));
            let what = || format!("case {id} ({})", describe(&keys, &values));
            let case = load_case(&text, &sets)
                .map_err(|e| format!("{}: {}", what(), e.problems.join("; ")))?;
            let hash = RunMetadata::new("sweep", &case).case_sha256;
            Ok(Planned {
                id,
                values,
                case,
                hash,
            })
        })
        .collect();
    let (ok, bad): (Vec<_>, Vec<_>) = resolved.into_iter().partition(Result::is_ok);
    if !bad.is_empty() {
        return Err(CliError::Input(
            bad.into_iter().filter_map(Result::err).collect(),
        ));
    }
    let planned: Vec<Planned> = ok.into_iter().filter_map(Result::ok).collect();
    check_case_files(&a.out, &planned)?;
    let (done, pending): (Vec<&Planned>, Vec<&Planned>) = planned
        .iter()
        .partition(|p| finished(&a.out, p, run_kind, &keys).is_some());
    verify_finished(&a.out, &done, run_kind, &keys)?;
    let model_problems: Vec<String> = pending
        .par_iter()
        .filter_map(|p| {
            Model::from_case(&p.case)
                .err()
                .map(|e| format!("case {} ({}): {e}", p.id, describe(&keys, &p.values)))
        })
        .collect();
    if !model_problems.is_empty() {
        return Err(CliError::Input(model_problems));
    }
    let stem = shard.stem();
    let mut out = super::output::open_set(&a.out, Some(&stem), "sweep")?;
    let cases = out.state_folder("cases")?;

    let (outcomes, records, skipped) = if let Some(c) = &continuation {
        eprintln!(
            "sweep: continuation along {} ({} branch(es), {} points; points finished from the same start state are skipped)",
            keys.join(", "),
            c.branches.len(),
            c.len()
        );
        let pb = count_bar(c.len() as u64, "sweep cases");
        let r = run_branches(&a.out, &cases, c, &planned, &keys, &pb);
        pb.finish_and_clear();
        r
    } else {
        eprintln!(
            "sweep: {} cases in all, {} in shard {}/{}: {} already finished (skipped), {} to run on {} threads",
            plan.len(),
            planned.len(),
            shard.index,
            shard.count,
            done.len(),
            pending.len(),
            rayon::current_num_threads()
        );
        let pb = count_bar(pending.len() as u64, "sweep cases");
        let outcomes: Outcomes = pending
            .par_iter()
            .map(|p| {
                let r = run_one(&cases, p, run_kind, &keys);
                pb.inc(1);
                (p.id, r)
            })
            .collect();
        pb.finish_and_clear();
        // The table is rebuilt from the case files, so a rerun's table holds every case.
        let records: Vec<CaseRecord> = planned
            .iter()
            .filter_map(|p| finished(&a.out, p, run_kind, &keys))
            .collect();
        (outcomes, records, done.len())
    };
    let values_of: BTreeMap<usize, &Vec<String>> =
        planned.iter().map(|p| (p.id, &p.values)).collect();
    let branch_of = |id: usize| {
        continuation.as_ref().and_then(|c| {
            c.branches
                .iter()
                .find(|(_, p)| p.iter().any(|x| x.case_id == id))
                .map(|(b, _)| b.name())
        })
    };

    let mut warnings: BTreeMap<String, usize> = BTreeMap::new();
    let mut failed = Vec::new();
    let ran = outcomes.len();
    for (id, r) in outcomes {
        match r {
            Ok(w) => w
                .into_iter()
                .for_each(|w| *warnings.entry(w).or_default() += 1),
            Err(e) => failed.push(json!({
                "case_id": id,
                "values": values_of.get(&id),
                "branch": branch_of(id),
                "error": e.to_string(),
            })),
        }
    }
    for (w, n) in &warnings {
        eprintln!("warning ({n} case(s)): {w}");
    }

    let computed = ran - failed.len();
    for r in &records {
        out.keep_state(&format!("cases/{}.json", r.case_id));
    }
    let table = SweepTable::from_records(keys.clone(), run_kind.columns(), &records);
    let csv_path = a.out.join(format!("{stem}.csv"));
    out.stage(
        &format!("{stem}.csv"),
        &table.to_csv().map_err(anyhow::Error::from)?,
    )?;

    let speed = match Model::from_case(&base) {
        Ok(m) => speed_marks(&m, &plan),
        Err(e) => {
            eprintln!("warning: no resonance markers: the base case has no model: {e}");
            None
        }
    };
    let poles = speed
        .as_ref()
        .map_or_else(Vec::new, |m| m.modal.mesh_pole_frequencies_hz());
    let marks = speed.as_ref().map_or(&[][..], |m| &m.crossings[..]);
    let mut art = Artifacts::default();
    if let Some(fig) = figure_for(&table, marks, &poles) {
        let (w, h) = SWEEP_FIGURE_PX;
        art.figure_sized(format!("{stem}.png"), fig, w, h);
    }
    let wall_s = started.elapsed().as_secs_f64();
    let meta = json!({
        "command": "sweep",
        "run": run_kind,
        "vary": plan.axes.iter().map(|x| json!({"key": x.key, "values": x.values})).collect::<Vec<_>>(),
        "total_cases": plan.len(),
        "shard": {"index": shard.index, "count": shard.count, "scheme": "round-robin: case_id mod count = index - 1"},
        "cases_in_shard": planned.len(),
        "continuation": a.continuation.map(|c| format!("{c:?}").to_lowercase()),
        "failed": failed,
        "rows": table.rows.len(),
        "modes": speed.as_ref().map(|s| modes_json(&s.modal)),
        "resonance_crossings": speed.as_ref().map(|s| s.crossings.clone()),
        "base": RunMetadata::new("sweep", &base),
    });
    out.stage_json(&format!("{stem}.json"), &meta)?;
    stage_figures(&mut out, &art.figures)?;
    out.publish()?;
    say(&format!(
        "sweep: {} rows ({} computed, {} skipped, {} failed)",
        table.rows.len(),
        computed,
        skipped,
        failed.len()
    ));
    eprintln!(
        "sweep: {} rows -> {} ({} computed, {} skipped, {} failed; {:.1} s)",
        table.rows.len(),
        csv_path.display(),
        computed,
        skipped,
        failed.len(),
        wall_s
    );
    if failed.is_empty() {
        Ok(())
    } else {
        let list: Vec<String> = failed
            .iter()
            .map(|f| format!("case {}: {}", f["case_id"], f["error"]))
            .collect();
        let rerun = if continuation.is_some() {
            "each branch went on from the last point that succeeded; rerun to retry them"
        } else {
            "rerun to retry them; finished cases are skipped"
        };
        Err(CliError::Failed(anyhow::anyhow!(
            "{} of {} cases failed ({rerun}):\n  {}",
            failed.len(),
            planned.len(),
            list.join("\n  ")
        )))
    }
}
