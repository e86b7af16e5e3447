//! `gearwear sweep-merge`: joins the tables of sweep shards (or of earlier merges) into
//! one, sorted by case id, refusing inputs of different sweeps.

use super::args::SweepMergeArgs;
use super::output::say;
use super::CliError;
use crate::report::artifacts::{stage_figures, Artifacts};
use crate::report::sweep_figure::{figure_for, SWEEP_FIGURE_PX};
use crate::study::sweep::{Crossing, SweepTable};
use serde_json::json;
use std::path::{Path, PathBuf};

/// The sweep tables of a merge input: a CSV file, or a directory's `sweep.csv` and
/// `sweep_shard_*_of_*.csv`. Each comes with its `.json` description when present.
fn merge_inputs(input: &Path) -> Result<Vec<PathBuf>, CliError> {
    if !input.exists() {
        return Err(CliError::input(format!(
            "sweep-merge: {} does not exist",
            input.display()
        )));
    }
    if !input.is_dir() {
        return Ok(vec![input.to_path_buf()]); // read_input says what it is if not a file
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
    let mut bytes = 0u64;
    for input in &a.inputs {
        for csv in merge_inputs(input)? {
            bytes += std::fs::metadata(&csv).map_or(0, |m| m.len());
            super::output::check_budget(&crate::study::budget::estimate_sweep_merge(bytes))?;
            let src = csv.display().to_string();
            let (t, m) = crate::io::sweep_inputs::merge_input(&csv)
                .map_err(|e| CliError::input(format!("sweep-merge: {e}")))?;
            metas.push((src.clone(), m));
            tables.push((src, t));
        }
    }
    let merged =
        SweepTable::merge(&tables).map_err(|e| CliError::input(format!("sweep-merge: {e}")))?;
    // Descriptions present must agree on the sweep itself (axes, run, base case): shards
    // of different sweeps can have disjoint case ids and would otherwise merge silently.
    // A merge's description carries the same identity forward, so a merge of merges (or
    // of a merge and a shard) is checked like a merge of shards.
    let describes_a_sweep = |m: &serde_json::Value| {
        (m["command"] == "sweep" || m["command"] == "sweep-merge") && !m["vary"].is_null()
    };
    let identity = |m: &serde_json::Value| {
        json!([
            m["vary"],
            m["run"],
            m["base"]["case_sha256"],
            m["total_cases"]
        ])
    };
    if let Some((src0, m0)) = metas.iter().find(|(_, m)| describes_a_sweep(m)) {
        for (src, m) in metas.iter().filter(|(_, m)| describes_a_sweep(m)) {
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
    let mut out = super::output::open_set(&dir, Some(&stem), "sweep-merge")?;
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
    // Bounded by the plan's limit (a description is an input: it could claim any size).
    let total = total.filter(|n| *n <= crate::study::sweep::plan::MAX_CASES);
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
    let poles: Vec<f64> = metas
        .iter()
        .find_map(|(_, m)| m["modes"]["mesh_poles"].as_array().cloned())
        .unwrap_or_default()
        .iter()
        .filter_map(|p| p["damped_frequency_hz"].as_f64())
        .collect();
    if let Some(fig) = figure_for(&merged, marks.as_deref().unwrap_or(&[]), &poles) {
        let (w, h) = SWEEP_FIGURE_PX;
        art.figure_sized(format!("{stem}.png"), fig, w, h);
    }
    stage_figures(&mut out, &art.figures)?;
    let first = metas
        .iter()
        .find(|(_, m)| describes_a_sweep(m))
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
            "modes": first.as_ref().map(|m| m["modes"].clone()),
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
