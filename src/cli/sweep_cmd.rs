//! `gearwear sweep`: the cross product of `--vary` axes, run in parallel, one row per
//! case; resumable (finished cases are skipped) and shardable. `gearwear sweep-merge`:
//! joins shard tables.
//!
//! Output directory layout (STEM = `sweep`, or `sweep_shard_I_of_N` with `--shard`):
//! `cases/<case_id>.json` (one per finished case, written first, atomically),
//! `STEM.csv` (this shard's rows by case id), `STEM.json` (what was run: axes, base case,
//! natural frequencies, failures), `STEM.png` (speed sweeps only).

use super::args::{CaseArgs, SweepArgs, SweepMergeArgs, SweepRunArg};
use super::output::say;
use super::CliError;
use crate::config::{load_case, schema, Case};
use crate::dynamics::excitation::{ExternalError, PairGap};
use crate::dynamics::modal::modes;
use crate::io::atomic::ensure_real_dir;
use crate::io::{write_atomic, OutputDir, RunMetadata};
use crate::report::artifacts::{stage_figures, Artifacts};
use crate::report::sweep::{speed_figure, SWEEP_FIGURE_PX};
use crate::study::sweep::{
    crossings, parse_vary, run_case, CaseError, CaseRecord, Crossing, Shard, SweepPlan, SweepRun,
    SweepTable, SPEED_KEY,
};
use crate::study::Model;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use serde_json::json;
use std::collections::BTreeMap;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Mesh harmonics whose crossings with the natural frequencies are marked.
const MARKED_HARMONICS: u32 = 3;

/// One case of this shard, resolved and validated.
struct Planned {
    id: usize,
    values: Vec<String>,
    case: Case,
    hash: String,
}

fn describe(keys: &[String], values: &[String]) -> String {
    keys.iter()
        .zip(values)
        .map(|(k, v)| format!("{k}={v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn read_config(c: &CaseArgs) -> Result<String, CliError> {
    match &c.config {
        Some(p) => std::fs::read_to_string(p)
            .map_err(|e| CliError::input(format!("--config {}: cannot read: {e}", p.display()))),
        None => Ok(String::new()),
    }
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

fn case_path(dir: &Path, id: usize) -> PathBuf {
    dir.join("cases").join(format!("{id}.json"))
}

/// The record of a finished case, if `cases/<id>.json` holds this very case's result.
fn finished(dir: &Path, p: &Planned, run: SweepRun, keys: &[String]) -> Option<CaseRecord> {
    let text = std::fs::read_to_string(case_path(dir, p.id)).ok()?;
    let r: CaseRecord = serde_json::from_str(&text).ok()?;
    r.is_result_of(p.id, &p.hash, run, keys, &p.values)
        .then_some(r)
}

fn progress_bar(n: usize) -> ProgressBar {
    let target = if std::io::stderr().is_terminal() {
        ProgressDrawTarget::stderr()
    } else {
        ProgressDrawTarget::hidden()
    };
    let pb = ProgressBar::with_draw_target(Some(n as u64), target);
    pb.set_style(
        ProgressStyle::with_template(
            "sweep [{bar:30}] {pos}/{len} cases (elapsed {elapsed}, eta {eta})",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    pb
}

/// Run one case and write its record; the record is the first and only file a case writes.
fn run_one(
    dir: &Path,
    p: &Planned,
    run: SweepRun,
    keys: &[String],
) -> Result<Vec<String>, CaseError> {
    let o = run_case(&p.case, run)?;
    let rec = CaseRecord {
        case_id: p.id,
        case_sha256: p.hash.clone(),
        run,
        keys: keys.to_vec(),
        values: p.values.clone(),
        columns: run.columns(),
        results: o
            .results
            .iter()
            .map(|x| x.is_finite().then_some(*x))
            .collect(),
    };
    let text = serde_json::to_string_pretty(&rec).map_err(|e| CaseError::Solve(e.into()))?;
    write_atomic(&case_path(dir, p.id), text.as_bytes()).map_err(|e| CaseError::Solve(e.into()))?;
    Ok(o.warnings)
}

/// Natural frequencies of the base case (modes of the model linearised at the mean mesh
/// stiffness, new teeth) and the crossings h z1 f_in = f_n inside the swept speed range.
fn speed_crossings(base: &Case, plan: &SweepPlan) -> Option<(Vec<f64>, Vec<Crossing>)> {
    let axis = plan.axes.iter().find(|x| x.key == SPEED_KEY)?;
    let speeds: Vec<f64> = axis.values.iter().filter_map(|v| v.parse().ok()).collect();
    let lo = speeds.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = speeds.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let model = match Model::from_case(base) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("warning: no resonance markers: the base case has no model: {e}");
            return None;
        }
    };
    let (gap, ext) = (PairGap::none(), ExternalError::none());
    let f_n = modes(&model.system(&gap, &ext, model.roughness.rms_um(0.0))).frequency_hz;
    let c = crossings(&f_n, model.pair.pinion.teeth, MARKED_HARMONICS, lo, hi);
    Some((f_n, c))
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
    let keys = plan.keys();
    let ids = shard.ids(plan.len());

    // Resolve and validate every case of the shard (and its model) before running any.
    let resolved: Vec<Result<Planned, String>> = ids
        .par_iter()
        .map(|&id| {
            let values = plan.values_of(id);
            let mut sets = a.case.set.clone();
            sets.extend(plan.overrides_of(id));
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
    let (done, pending): (Vec<&Planned>, Vec<&Planned>) = planned
        .iter()
        .partition(|p| finished(&a.out, p, run_kind, &keys).is_some());
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
    let mut out = OutputDir::open(&a.out, Some(&stem), "sweep")?;
    ensure_real_dir(&a.out, &a.out.join("cases"))?;

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
    let pb = progress_bar(pending.len());
    let outcomes: Vec<(usize, Result<Vec<String>, CaseError>)> = pending
        .par_iter()
        .map(|p| {
            let r = run_one(&a.out, p, run_kind, &keys);
            pb.inc(1);
            (p.id, r)
        })
        .collect();
    pb.finish_and_clear();

    let mut warnings: BTreeMap<String, usize> = BTreeMap::new();
    let mut failed = Vec::new();
    for (id, r) in outcomes {
        match r {
            Ok(w) => w
                .into_iter()
                .for_each(|w| *warnings.entry(w).or_default() += 1),
            Err(e) => failed
                .push(json!({"case_id": id, "values": plan.values_of(id), "error": e.to_string()})),
        }
    }
    for (w, n) in &warnings {
        eprintln!("warning ({n} case(s)): {w}");
    }

    // The table is rebuilt from the case files, so a rerun's table holds every case.
    let records: Vec<CaseRecord> = planned
        .iter()
        .filter_map(|p| finished(&a.out, p, run_kind, &keys))
        .collect();
    for p in &planned {
        if records.iter().any(|r| r.case_id == p.id) {
            out.keep_state(&format!("cases/{}.json", p.id));
        }
    }
    let table = SweepTable::from_records(keys.clone(), run_kind.columns(), &records);
    let csv_path = a.out.join(format!("{stem}.csv"));
    let mut art = Artifacts::default();
    out.stage(
        &format!("{stem}.csv"),
        &table.to_csv().map_err(anyhow::Error::from)?,
    )?;

    let speed = speed_crossings(&base, &plan);
    if let Some((_, marks)) = &speed {
        if let Some(fig) = speed_figure(&table, marks) {
            let (w, h) = SWEEP_FIGURE_PX;
            art.figure_sized(format!("{stem}.png"), fig, w, h);
        }
    }
    let wall_s = started.elapsed().as_secs_f64();
    let meta = json!({
        "command": "sweep",
        "run": run_kind,
        "vary": plan.axes.iter().map(|x| json!({"key": x.key, "values": x.values})).collect::<Vec<_>>(),
        "total_cases": plan.len(),
        "shard": {"index": shard.index, "count": shard.count, "scheme": "round-robin: case_id mod count = index - 1"},
        "cases_in_shard": planned.len(),
        "skipped_finished": done.len(),
        "computed": pending.len() - failed.len(),
        "failed": failed,
        "rows": table.rows.len(),
        "natural_frequencies_hz": speed.as_ref().map(|s| s.0.clone()),
        "resonance_crossings": speed.as_ref().map(|s| s.1.clone()),
        "wall_time_s": wall_s,
        "threads": rayon::current_num_threads(),
        "base": RunMetadata::new("sweep", &base),
    });
    out.stage_json(&format!("{stem}.json"), &meta)?;
    stage_figures(&mut out, &art.figures)?;
    out.publish()?;
    say(&format!(
        "sweep: {} rows ({} computed, {} skipped, {} failed)",
        table.rows.len(),
        pending.len() - failed.len(),
        done.len(),
        failed.len()
    ));
    eprintln!(
        "sweep: {} rows -> {} ({} computed, {} skipped, {} failed; {:.1} s)",
        table.rows.len(),
        csv_path.display(),
        pending.len() - failed.len(),
        done.len(),
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
        Err(CliError::Failed(anyhow::anyhow!(
            "{} of {} cases failed (rerun to retry them; finished cases are skipped):\n  {}",
            failed.len(),
            planned.len(),
            list.join("\n  ")
        )))
    }
}

/// The sweep tables of a merge input: a CSV file, or a directory's `sweep.csv` and
/// `sweep_shard_*_of_*.csv`. Each comes with its `.json` description when present.
fn merge_inputs(input: &Path) -> Result<Vec<PathBuf>, CliError> {
    if input.is_file() {
        return Ok(vec![input.to_path_buf()]);
    }
    if !input.is_dir() {
        return Err(CliError::input(format!(
            "sweep-merge: {} does not exist",
            input.display()
        )));
    }
    let mut found: Vec<PathBuf> = std::fs::read_dir(input)
        .map_err(|e| CliError::input(format!("sweep-merge: cannot read {}: {e}", input.display())))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            let n = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
            n == "sweep.csv" || (n.starts_with("sweep_shard_") && n.ends_with(".csv"))
        })
        .collect();
    found.sort();
    if found.is_empty() {
        return Err(CliError::input(format!(
            "sweep-merge: {} holds no sweep.csv or sweep_shard_*_of_*.csv",
            input.display()
        )));
    }
    Ok(found)
}

pub fn merge(a: &SweepMergeArgs) -> Result<(), CliError> {
    let mut tables = Vec::new();
    let mut metas: Vec<(String, serde_json::Value)> = Vec::new();
    for input in &a.inputs {
        for csv in merge_inputs(input)? {
            let src = csv.display().to_string();
            let text = std::fs::read_to_string(&csv)
                .map_err(|e| CliError::input(format!("sweep-merge: {src}: cannot read: {e}")))?;
            let t = SweepTable::from_csv(&text)
                .map_err(|e| CliError::input(format!("sweep-merge: {src}: {e}")))?;
            if let Some(m) = std::fs::read_to_string(csv.with_extension("json"))
                .ok()
                .and_then(|s| serde_json::from_str::<serde_json::Value>(&s).ok())
            {
                metas.push((src.clone(), m));
            }
            tables.push((src, t));
        }
    }
    let merged =
        SweepTable::merge(&tables).map_err(|e| CliError::input(format!("sweep-merge: {e}")))?;
    // Descriptions present must agree on the sweep itself (axes, run, base case): shards
    // of different sweeps can have disjoint case ids and would otherwise merge silently.
    let identity = |m: &serde_json::Value| {
        json!([
            m["vary"],
            m["run"],
            m["base"]["case_sha256"],
            m["total_cases"]
        ])
    };
    if let Some((src0, m0)) = metas.iter().find(|(_, m)| m["command"] == "sweep") {
        for (src, m) in metas.iter().filter(|(_, m)| m["command"] == "sweep") {
            if identity(m) != identity(m0) {
                return Err(CliError::input(format!(
                    "sweep-merge: mixed sweeps: {src} and {src0} come from different sweeps (axes, run kind, base case or size differ)"
                )));
            }
        }
    }
    // `--out DIR` writes DIR/sweep.*; `--out FILE.csv` writes FILE.* beside it.
    let (dir, stem) = if a.out.extension().is_some_and(|e| e == "csv") {
        let dir = a
            .out
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."))
            .to_path_buf();
        let stem = a
            .out
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "sweep".into());
        (dir, stem)
    } else {
        (a.out.clone(), "sweep".to_owned())
    };
    let mut out = OutputDir::open(&dir, Some(&stem), "sweep-merge")?;
    let csv_path = dir.join(format!("{stem}.csv"));
    out.stage(
        &format!("{stem}.csv"),
        &merged.to_csv().map_err(anyhow::Error::from)?,
    )?;

    let total = metas
        .iter()
        .find_map(|(_, m)| m["total_cases"].as_u64())
        .map(|n| n as usize);
    let have: std::collections::BTreeSet<usize> = merged.rows.iter().map(|r| r.case_id).collect();
    let missing: Vec<usize> =
        total.map_or_else(Vec::new, |n| (0..n).filter(|i| !have.contains(i)).collect());
    if !missing.is_empty() {
        eprintln!(
            "warning: {} of {} cases missing from the merged table (first: {:?}); rerun their shards",
            missing.len(),
            total.unwrap_or(0),
            &missing[..missing.len().min(10)]
        );
    }
    let marks: Option<Vec<Crossing>> = metas
        .iter()
        .find_map(|(_, m)| serde_json::from_value(m["resonance_crossings"].clone()).ok());
    let mut art = Artifacts::default();
    if let Some(fig) = speed_figure(&merged, marks.as_deref().unwrap_or(&[])) {
        let (w, h) = SWEEP_FIGURE_PX;
        art.figure_sized(format!("{stem}.png"), fig, w, h);
    }
    stage_figures(&mut out, &art.figures)?;
    let first = metas
        .iter()
        .find(|(_, m)| m["command"] == "sweep")
        .map(|(_, m)| m.clone());
    let meta = json!({
            "command": "sweep-merge",
            "inputs": tables.iter().map(|(s, _)| s.clone()).collect::<Vec<_>>(),
            "rows": merged.rows.len(),
            "total_cases": total,
            "missing_case_ids": missing,
            "vary": first.as_ref().map(|m| m["vary"].clone()),
            "run": first.as_ref().map(|m| m["run"].clone()),
            "resonance_crossings": first.as_ref().map(|m| m["resonance_crossings"].clone()),
            "base": first.as_ref().map(|m| m["base"].clone()),
    });
    out.stage_json(&format!("{stem}.json"), &meta)?;
    out.publish()?;
    say(&format!(
        "sweep-merge: {} rows from {} table(s)",
        merged.rows.len(),
        tables.len()
    ));
    eprintln!(
        "sweep-merge: {} table(s), {} rows -> {}",
        tables.len(),
        merged.rows.len(),
        csv_path.display()
    );
    Ok(())
}
