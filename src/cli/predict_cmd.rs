//! `gearwear predict`: Monte Carlo prediction of wear, vibration indicators and remaining
//! life over posterior (or prior) samples; `gearwear predict-merge`: joins shards.
//! Thin: reads the inputs, calls `prognostics`, writes what it returns.

use super::args::{ForwardArg, PredictArgs, PredictMergeArgs};
use super::output::{build_model, open_out};
use super::progress::count_bar;
use super::CliError;
use crate::io::{OutputDir, RunMetadata, Table};
use crate::prognostics::check::{check_prediction, PredictionCheck};
use crate::prognostics::forward::Crossing;
use crate::prognostics::predict::{
    fans, run_sample, Forward, LifeSummary, PredictSettings, SampleOutcome, SampleSource,
};
use crate::prognostics::prior::{Prior, Theta};
use crate::prognostics::samples::read_samples;
use crate::prognostics::surrogate::max_chain_runs;
use crate::prognostics::{Quantity, Surrogate};
use crate::report::html::{render, Report};
use crate::report::prognostics::{fan_figure, life_figure, prediction_section};
use crate::report::prognostics_tables::{bands_table, figure, thetas_json};
use crate::report::Artifacts;
use crate::study::sweep::Shard;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use sha2::{Digest, Sha256};
use std::path::{Path, PathBuf};

/// What makes shards parts of one prediction.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Identity {
    settings: PredictSettings,
    forward: String,
    /// SHA-256 of the posterior file, or "prior".
    source: String,
    case_sha256: String,
}

/// What a shard writes.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct ShardFile {
    identity: Identity,
    shard: (usize, usize),
    /// `RunMetadata` of the run, as JSON.
    metadata: Value,
    checks: Vec<PredictionCheck>,
    reference_failures: Vec<(Theta, f64, String)>,
    outcomes: Vec<SampleOutcome>,
}

pub fn run(a: &PredictArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    let bad = crate::prognostics::limits::check_predict(
        a.limit_um,
        a.cycles,
        a.samples,
        a.grid_points,
        a.check_runs,
    );
    if !bad.is_empty() {
        return Err(CliError::Input(
            bad.iter().map(super::error::flag_problem).collect(),
        ));
    }
    let defaults = [
        case.wear.coefficient_m2_per_n,
        1.0,
        case.operating.load_torque_nm,
    ];
    let (source, span, source_id, n) = match &a.posterior {
        Some(p) => {
            let src = p.display().to_string();
            let text = crate::io::read_input_text(
                p,
                "posterior samples file",
                crate::io::input::MAX_POSTERIOR_BYTES,
            )
            .map_err(|e| CliError::input(format!("--posterior {e}")))?;
            let rows = read_samples(&text, &src, defaults).map_err(CliError::Input)?;
            let n = a.samples.unwrap_or(rows.len());
            let span = Prior::spanning(&rows);
            let id = format!("{:x}", Sha256::digest(text.as_bytes()));
            (
                SampleSource::Posterior {
                    resample: n != rows.len(),
                    rows,
                },
                span,
                id,
                n,
            )
        }
        None => {
            let prior = Prior::from_case(&case).map_err(CliError::Input)?;
            (
                SampleSource::Prior(prior.clone()),
                prior,
                "prior".to_string(),
                a.samples.unwrap_or(2000),
            )
        }
    };
    let shard = match &a.shard {
        Some(s) => Shard::parse(s).map_err(CliError::input)?,
        None => Shard::ALL,
    };
    super::output::check_budget(&crate::prognostics::budget::estimate_prediction(
        &case,
        &span,
        &crate::prognostics::budget::PredictionJob {
            samples_in_shard: n.div_ceil(shard.count.max(1)),
            grid_points: a.grid_points,
            cycles: a.cycles,
            exact: a.forward == ForwardArg::Exact,
            sharded: shard.count > 1,
            check_runs: if shard.index == 1 { a.check_runs } else { 0 },
            posterior_rows: match &source {
                SampleSource::Posterior { rows, .. } => rows.len(),
                SampleSource::Prior(_) => 0,
            },
        },
    ))?;
    build_model(&case)?;
    let stem =
        (shard.count > 1).then(|| format!("predict_shard_{}_of_{}", shard.index, shard.count));
    let mut out = super::output::open_set(&a.out, stem.as_deref(), "predict")?;
    let set = PredictSettings {
        limit_um: a.limit_um,
        cycles: a.cycles,
        grid_points: a.grid_points,
        seed: a.seed,
        samples: n,
    };
    let meta = RunMetadata::new("predict", &case);
    let identity = Identity {
        settings: set,
        forward: format!("{:?}", a.forward).to_lowercase(),
        source: source_id,
        case_sha256: meta.case_sha256.clone(),
    };
    let sur = match a.forward {
        ForwardArg::Surrogate => {
            let nodes = case.calibration.surrogate_nodes.max(2) as usize;
            let chains = nodes.pow(span.free().iter().filter(|i| **i != 0).count() as u32);
            let pb = count_bar(chains as u64 * max_chain_runs(&span), "reference runs");
            let s = Surrogate::build(&case, &span, a.cycles, nodes, &|| pb.inc(1))
                .map_err(|e| CliError::Input(e.0))?;
            pb.finish_and_clear();
            Some(s)
        }
        ForwardArg::Exact => None,
    };
    let fw = match &sur {
        Some(s) => Forward::Surrogate(s),
        None => Forward::Exact(&case),
    };
    let ids = shard.ids(n);
    eprintln!(
        "predict: {} of {n} samples (shard {}/{}) to {} cycles on {} threads",
        ids.len(),
        shard.index,
        shard.count,
        a.cycles,
        rayon::current_num_threads()
    );
    let pb = count_bar(ids.len() as u64, "samples");
    let outcomes: Result<Vec<SampleOutcome>, _> = ids
        .par_iter()
        .map(|&i| {
            let r = run_sample(&fw, source.draw(i, a.seed), i, &set);
            pb.inc(1);
            r
        })
        .collect();
    pb.finish_and_clear();
    let outcomes = outcomes.map_err(|e| CliError::Input(e.0))?;
    let checks = match (&sur, shard.index, a.check_runs) {
        (Some(s), 1, n) if n > 0 => check_prediction(&case, s, &outcomes, &set, n),
        _ => Vec::new(),
    };
    let file = ShardFile {
        identity,
        shard: (shard.index, shard.count),
        metadata: serde_json::to_value(&meta).map_err(anyhow::Error::from)?,
        checks,
        reference_failures: sur.as_ref().map_or_else(Vec::new, |s| s.failures()),
        outcomes,
    };
    if let Some(stem) = stem {
        let name = format!("{stem}.json");
        out.stage_json(
            &name,
            &serde_json::to_value(&file).map_err(anyhow::Error::from)?,
        )?;
        out.publish()?;
        eprintln!(
            "predict: shard written to {} (join the shards with `gearwear predict-merge`)",
            a.out.join(name).display()
        );
        return Ok(());
    }
    let art = prediction_artifacts(file, (0, Vec::new()))?;
    publish(out, art, "predict")
}

/// Shard files of a merge input: a file, or a directory's predict_shard_*_of_*.json.
fn shard_files(input: &Path) -> Result<Vec<PathBuf>, CliError> {
    if !input.is_dir() {
        return Ok(vec![input.to_path_buf()]); // read_input says what it is if not a file
    }
    let mut found: Vec<PathBuf> = std::fs::read_dir(input)
        .map_err(|e| CliError::input(format!("predict-merge: {}: {e}", input.display())))?
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
        return Err(CliError::input(format!(
            "predict-merge: {} holds no predict_shard_*_of_*.json",
            input.display()
        )));
    }
    Ok(found)
}

pub fn merge(a: &PredictMergeArgs) -> Result<(), CliError> {
    let mut files: Vec<(String, ShardFile)> = Vec::new();
    let mut bytes = 0u64;
    for input in &a.inputs {
        for p in shard_files(input)? {
            bytes += std::fs::metadata(&p).map_or(0, |m| m.len());
            let src = p.display().to_string();
            let text = crate::io::read_input_text(
                &p,
                "prediction shard",
                crate::io::input::MAX_PREDICT_SHARD_BYTES,
            )
            .map_err(|e| CliError::input(format!("predict-merge: {e}")))?;
            // The text itself must fit the budget before it is parsed.
            super::output::check_budget(&crate::prognostics::budget::estimate_merge(bytes, 0, 0))?;
            let f: ShardFile = serde_json::from_str(&text).map_err(|e| {
                CliError::input(format!("predict-merge: {src} is not a predict shard: {e}"))
            })?;
            files.push((src, f));
        }
    }
    let (src0, first) = files[0].clone();
    for (src, f) in &files {
        crate::prognostics::predict::check_shard(&f.identity.settings, f.shard, &f.outcomes)
            .map_err(|e| CliError::input(format!("predict-merge: {src}: {e}")))?;
        if f.identity != first.identity {
            return Err(CliError::input(format!(
                "predict-merge: {src} and {src0} come from different predictions (settings, forward model, samples or case differ)"
            )));
        }
    }
    super::output::check_budget(&crate::prognostics::budget::estimate_merge(
        bytes,
        first.identity.settings.samples,
        first.identity.settings.grid_points,
    ))?;
    let mut outcomes: Vec<SampleOutcome> =
        files.iter().flat_map(|f| f.1.outcomes.clone()).collect();
    outcomes.sort_by_key(|o| o.index);
    outcomes.dedup_by_key(|o| o.index);
    let have: std::collections::BTreeSet<usize> = outcomes.iter().map(|o| o.index).collect();
    // Counted, not listed: a shard may claim up to 1e7 samples.
    let n_missing = first.identity.settings.samples - have.len();
    let missing: Vec<usize> = (0..first.identity.settings.samples)
        .filter(|i| !have.contains(i))
        .take(100)
        .collect();
    if n_missing > 0 {
        eprintln!(
            "warning: {n_missing} of {} samples missing (first: {:?}); run their shards and merge again",
            first.identity.settings.samples,
            &missing[..missing.len().min(10)]
        );
    }
    let checks: Vec<PredictionCheck> = files.iter().flat_map(|f| f.1.checks.clone()).collect();
    let out = open_out(&a.out, "predict-merge")?;
    let art = prediction_artifacts(
        ShardFile {
            outcomes,
            checks,
            shard: (1, 1),
            ..first
        },
        (n_missing, missing),
    )?;
    publish(out, art, "predict-merge")
}

fn life_of(c: Crossing) -> Option<f64> {
    match c {
        Crossing::Reached(x) => Some(x),
        _ => None,
    }
}

/// Stage and publish a prediction's outputs, print its headline.
fn publish(mut out: OutputDir, art: Artifacts, command: &str) -> Result<(), CliError> {
    crate::report::write_artifacts(&mut out, &art)?;
    let root = out.root().to_path_buf();
    out.publish()?;
    super::output::say(&art.headline);
    eprintln!("{command}: results -> {}", root.display());
    Ok(())
}

/// Every output of a prediction from its outcomes.
fn prediction_artifacts(f: ShardFile, missing: (usize, Vec<usize>)) -> Result<Artifacts, CliError> {
    let mut art = Artifacts::default();
    let set = f.identity.settings;
    let o = &f.outcomes;
    let life = LifeSummary::of(o);
    let fans = fans(o, &set);
    let lives: Vec<f64> = o.iter().filter_map(|s| life_of(s.life)).collect();
    let status = |c: Crossing| match c {
        Crossing::Reached(_) => 0.0,
        Crossing::NotReached => 1.0,
        Crossing::Unknown => 2.0,
    };
    let life_table = Table::new()
        .col("sample", o.iter().map(|s| s.index as f64).collect())
        .col(
            "wear_coefficient_m2_per_n",
            o.iter().map(|s| s.theta[0]).collect(),
        )
        .col("roughness_scale", o.iter().map(|s| s.theta[1]).collect())
        .col("load_torque_nm", o.iter().map(|s| s.theta[2]).collect())
        .col(
            "cycles_to_limit",
            o.iter()
                .map(|s| life_of(s.life).unwrap_or(f64::NAN))
                .collect(),
        )
        .col("life_status", o.iter().map(|s| status(s.life)).collect());
    art.table("life_samples.csv", life_table);
    art.table("fan_wear.csv", bands_table(&fans[..1]));
    art.table("fan_vibration.csv", bands_table(&fans[1..]));
    let figs = vec![
        figure(&mut art, "fan_wear.png", &fan_figure("Maximum pinion wear: median, 50 % and 90 % bands", &fans[..1], Some(set.limit_um)), "Fan chart of the maximum pinion wear depth over the ensemble, with the wear limit.", Some("fan_wear.csv"))?,
        figure(&mut art, "life.png", &life_figure(&lives, &life, set.cycles), "Distribution of the cycles at which the maximum pinion wear reaches the limit (samples that reach it within the horizon).", Some("life_samples.csv"))?,
        figure(&mut art, "fan_vibration.png", &fan_figure("Vibration and transmission-error indicators: median, 50 % and 90 % bands", &fans[1..], None), "Fan charts of the indicators a monitoring system sees: RMS and mesh harmonics of the pinion's y velocity, DTE peak-to-peak and first mesh harmonic.", Some("fan_vibration.csv"))?,
    ];
    // Surrogate error relative to the ensemble's spread of the life.
    let check_rows: Vec<Value> = f
        .checks
        .iter()
        .map(|c| {
            let err = c.life_error();
            json!({
                "theta": thetas_json(&[c.theta])[0],
                "life_surrogate": c.life_surrogate,
                "life_true": c.life_true,
                "life_abs_error": err,
                "life_error_over_spread": err.map(|e| e / life.spread_reached),
                "max_abs_error_over_fan_grid": c.max_abs_error.iter().map(|(q, e)| json!({"quantity": q, "error": e})).collect::<Vec<_>>(),
                "true_run_failure": c.true_run_failure,
            })
        })
        .collect();
    let failed: Vec<&SampleOutcome> = o.iter().filter(|s| s.failure.is_some()).collect();
    let at_horizon = |q: Quantity| {
        fans.iter().find(|b| b.0 == q).map(|(_, b)| {
            let g = b.cycles.len() - 1;
            json!({"p05": b.percentiles[0][g], "p25": b.percentiles[1][g], "median": b.percentiles[2][g], "p75": b.percentiles[3][g], "p95": b.percentiles[4][g], "samples_with_value": b.valid[g]})
        })
    };
    let summary = json!({
        "limit_um": set.limit_um,
        "horizon_cycles": set.cycles,
        "samples": set.samples,
        "seed": set.seed,
        "forward_model": f.identity.forward,
        "source": f.identity.source,
        "remaining_life_cycles": {
            "p05": life.p05, "median": life.median, "p95": life.p95,
            "prob_beyond_horizon": life.prob_beyond_horizon,
            "prob_beyond_horizon_bounds_with_failed_samples": life.prob_beyond_horizon_bounds,
            "reached": life.reached, "beyond_horizon": life.beyond_horizon, "unknown": life.unknown,
            "note": "cycles from 0 (new teeth) to the first cycle at which the maximum pinion wear reaches the limit; null percentiles lie beyond the horizon (or among samples whose forward run failed)",
        },
        "at_horizon": FAN_AT_HORIZON.iter().map(|q| json!({"quantity": q.name(), "band": at_horizon(*q)})).collect::<Vec<_>>(),
        "failed_samples": {
            "count": failed.len(),
            "parameters": thetas_json(&failed.iter().map(|s| s.theta).collect::<Vec<_>>()),
            "first_error": failed.first().and_then(|s| s.failure.clone()),
            "note": "samples whose forward run stopped before the horizon: their values after it are unknown (the wear fan counts them as above every known value), their life is unknown if the limit was not reached first",
        },
        "reference_run_failures": f.reference_failures.iter().map(|(t, e, m)| json!({"theta": thetas_json(&[*t])[0], "exposure_reached_m2_per_n": e, "error": m})).collect::<Vec<_>>(),
        "surrogate_check": check_rows,
        "missing_samples": {"count": missing.0, "first": missing.1},
        "metadata": f.metadata,
    });
    art.summary = summary;
    let mut notes = vec![format!(
        "{} samples, forward model: {}, seed {}.",
        set.samples, f.identity.forward, set.seed
    )];
    if !failed.is_empty() {
        notes.push(format!(
            "{} sample(s) had a forward run that stopped before the horizon (listed in summary.json).",
            failed.len()
        ));
    }
    let report = Report {
        title: "gearwear prediction".into(),
        sections: vec![prediction_section(
            &life,
            set.limit_um,
            set.cycles,
            notes,
            figs,
        )],
        footer: format!(
            "gearwear {} | case sha256 {}",
            f.metadata["version"].as_str().unwrap_or("?"),
            f.metadata["case_sha256"].as_str().unwrap_or("?")
        ),
        ..Default::default()
    };
    art.documents
        .push(("report.html".into(), render(&report).into_bytes()));
    let fmt =
        |c: Option<f64>| c.map_or_else(|| format!("> {:.3e}", set.cycles), |x| format!("{x:.4e}"));
    art.headline = format!(
        "cycles to {} um: median {}, 90 % [{}, {}], P(> {:.3e}) = {:.3}; {} failed sample(s)",
        set.limit_um,
        fmt(life.median),
        fmt(life.p05),
        fmt(life.p95),
        set.cycles,
        life.prob_beyond_horizon,
        failed.len(),
    );
    Ok(art)
}

/// Quantities whose band at the horizon goes into summary.json.
const FAN_AT_HORIZON: [Quantity; 4] = [
    Quantity::MaxWearPinion,
    Quantity::VelocityRms,
    Quantity::MeshHarmonic(1),
    Quantity::DtePeakToPeak,
];
