//! `gearwear calibrate`: the posterior of the uncertain parameters given observations.
//! Thin: reads the inputs, calls `prognostics`, writes what it returns.

use super::args::CalibrateArgs;
use super::output::{build_model, finish, open_out};
use super::progress::count_bar;
use super::CliError;
use crate::io::RunMetadata;
use crate::prognostics::band::Band;
use crate::prognostics::calibrate::{calibrate, model_band, CalibrationSettings};
use crate::prognostics::check::{check_calibration, theta_at_k_quantile, worst_ratio};
use crate::prognostics::likelihood::noise_scales;
use crate::prognostics::prior::Prior;
use crate::prognostics::{parse_observations, Quantity, Surrogate};
use crate::report::html::{render, Report};
use crate::report::prognostics::{calibration_section, posterior_figure, predictive_figure};
use crate::report::prognostics_tables::{bands_table, figure, samples_table, thetas_json};
use crate::report::Artifacts;
use serde_json::json;

/// Cycle counts of the posterior band.
const BAND_POINTS: usize = 101;

pub fn run(a: &CalibrateArgs) -> Result<(), CliError> {
    let case = a.case.load()?;
    let prior = Prior::from_case(&case).map_err(CliError::Input)?;
    if prior.free().is_empty() {
        return Err(CliError::input(
            "nothing to calibrate: every prior of [calibration] has equal bounds (give calibration.wear_coefficient_min_m2_per_n < ..._max_m2_per_n)",
        ));
    }
    let bad = crate::prognostics::limits::check_calibrate(
        a.samples,
        a.walkers,
        a.steps,
        a.check_runs,
        prior.free().len(),
    );
    if !bad.is_empty() {
        return Err(CliError::Input(
            bad.iter().map(super::error::flag_problem).collect(),
        ));
    }
    let src = a.observations.display().to_string();
    let text = crate::io::read_input_text(
        &a.observations,
        "observations file",
        crate::io::input::MAX_OBSERVATIONS_BYTES,
    )
    .map_err(|e| CliError::input(format!("--observations {e}")))?;
    let obs = parse_observations(&text, &src).map_err(CliError::Input)?;
    super::output::check_budget(&crate::prognostics::budget::estimate_calibration(
        &case,
        &prior,
        &crate::prognostics::budget::CalibrationJob {
            values: obs.len(),
            quantities: obs.series.len(),
            max_cycles: obs.max_cycles(),
            samples: a.samples,
            walkers: a.walkers,
            steps: a.steps,
            check_runs: a.check_runs,
        },
    ))?;
    build_model(&case)?;
    let out = open_out(&a.out, "calibrate")?;
    let meta = RunMetadata::new("calibrate", &case);

    let nodes = case.calibration.surrogate_nodes.max(2) as usize;
    let n_ref = nodes.pow(prior.free().iter().filter(|i| **i != 0).count() as u32);
    eprintln!(
        "calibrate: {n_ref} reference wear run(s) on {} threads",
        rayon::current_num_threads()
    );
    let pb = count_bar(n_ref as u64, "reference runs");
    let sur = Surrogate::build(&case, &prior, obs.max_cycles(), nodes, &|| pb.inc(1))
        .map_err(|e| CliError::Input(e.0))?;
    pb.finish_and_clear();
    for (t, until, msg) in sur.failures() {
        eprintln!(
            "warning: the reference run at k = {:.3e} m^2/N, roughness factor {}, load torque {} N m stopped at a wear exposure k N = {until:.3e} m^2/N ({msg}); parameters that need more count as failed samples",
            t[0], t[1], t[2]
        );
    }
    let settings = CalibrationSettings {
        samples: a.samples,
        seed: a.seed,
        grid_cells: case.calibration.grid_points.max(16) as usize,
        walkers: a.walkers,
        steps: a.steps,
    };
    let pb = count_bar(
        if prior.free().len() <= 2 {
            8
        } else {
            a.steps as u64
        },
        "posterior",
    );
    let cal = calibrate(&prior, &obs, &sur, &settings, &|| pb.inc(1))
        .map_err(|e| CliError::Failed(anyhow::anyhow!(e)))?;
    pb.finish_and_clear();
    if !cal.failed.is_empty() {
        let ks: Vec<f64> = cal.failed.iter().map(|t| t[0]).collect();
        eprintln!(
            "warning: the forward model failed at {} parameter set(s) (k from {:.3e} to {:.3e} m^2/N); they carry no posterior mass and are listed in summary.json",
            cal.failed.len(),
            ks.iter().copied().fold(f64::INFINITY, f64::min),
            ks.iter().copied().fold(0.0, f64::max)
        );
    }

    let horizon = obs.max_cycles().max(1.0);
    let bands: Vec<(Quantity, Band)> = obs
        .series
        .iter()
        .map(|s| {
            (
                s.quantity,
                model_band(&sur, &cal.samples, s.quantity, horizon, BAND_POINTS).0,
            )
        })
        .collect();
    let median_theta = theta_at_k_quantile(&cal, 0.5);
    let noise = noise_scales(&obs, &|q, c| sur.value(q, &median_theta, c));
    if a.check_runs > 0 {
        eprintln!(
            "calibrate: checking the surrogate against {} true wear run(s)",
            a.check_runs.min(3)
        );
    }
    let check = check_calibration(&case, &sur, &cal, &obs, &noise, a.check_runs);
    let worst = worst_ratio(&check);
    if worst > 0.1 {
        eprintln!("warning: the surrogate's error reaches {worst:.3} of the posterior predictive spread (target < 0.1); see summary.json surrogate_check");
    }

    let mut art = Artifacts::default();
    art.table("posterior_samples.csv", samples_table(&cal.samples));
    art.table("posterior_band.csv", bands_table(&bands));
    let figs = vec![
        figure(&mut art, "posterior.png", &posterior_figure(&cal), "Marginal posterior density of each calibrated parameter (solid) and its prior (dashed).", Some("posterior_samples.csv"))?,
        figure(&mut art, "posterior_band.png", &predictive_figure(&obs, &bands), "Observations (points) against the model's band over the posterior samples: median, 50 % and 90 % bands of the noise-free model values.", Some("posterior_band.csv"))?,
    ];
    let summary = json!({
        "method": cal.method,
        "parameters": cal.summary.iter().map(|s| json!({
            "parameter": s.parameter.column(),
            "median": s.median,
            "ci90": [s.ci05, s.ci95],
            "ess": s.ess,
            "rhat": s.rhat,
        })).collect::<Vec<_>>(),
        "prior": cal.prior,
        "samples": cal.samples.len(),
        "seed": a.seed,
        "grid_levels": cal.grid_levels,
        "grid_posterior_mass_neglected": cal.mass_outside,
        "mcmc": {"walkers": a.walkers, "steps": a.steps, "burn_in": a.steps / 2, "acceptance": cal.acceptance},
        "observations": noise.iter().map(|(q, given, s)| json!({
            "quantity": q.name(),
            "values": obs.series.iter().find(|x| x.quantity == *q).map_or(0, |x| x.values.len()),
            "noise": if *given { "given (sigma column)" } else { "inferred (Jeffreys prior, marginalised)" },
            "noise_scale_at_posterior_median": s,
        })).collect::<Vec<_>>(),
        "forward_model": {
            "kind": "surrogate: reference runs read at the same exposure k N, interpolated in ln k (docs/PROGNOSTICS.md)",
            "reference_k_m2_per_n": sur.chains.iter().map(|c| c.k.clone()).collect::<Vec<_>>(),
            "reference_runs": sur.runs(),
            "reference_run_failures": sur.failures().iter().map(|(t, e, m)| json!({"theta": thetas_json(&[*t])[0], "exposure_reached_m2_per_n": e, "error": m})).collect::<Vec<_>>(),
        },
        "failed_samples": {
            "count": cal.failed.len(),
            "prior_mass_of_failed_grid_cells": cal.prior_mass_failed,
            "parameters": thetas_json(&cal.failed),
            "note": "parameters at which the forward model failed: zero posterior mass (the posterior is conditional on a successful run); listed up to 100",
        },
        "surrogate_check": check,
        "surrogate_check_max_error_over_predictive_sd": worst,
        "metadata": meta,
    });
    art.summary = summary;
    let notes = vec![format!(
        "Observations: {} values of {} quantities from {src}, up to {} cycles.",
        obs.len(),
        obs.series.len(),
        horizon
    )];
    let report = Report {
        title: "gearwear calibration".into(),
        sections: vec![calibration_section(&cal, notes, figs)],
        footer: format!(
            "gearwear {} | case sha256 {}",
            meta.version, meta.case_sha256
        ),
        ..Default::default()
    };
    art.documents
        .push(("report.html".into(), render(&report).into_bytes()));
    for s in cal
        .summary
        .iter()
        .filter(|s| s.rhat.is_some_and(|r| r > 1.05))
    {
        eprintln!(
            "warning: {}: split R-hat {:.3} > 1.05, the walkers have not mixed: rerun with more --steps",
            s.parameter.column(),
            s.rhat.unwrap_or(f64::NAN)
        );
    }
    art.headline = cal
        .summary
        .iter()
        .map(|s| {
            format!(
                "{}: median {:.4e}, 90 % interval [{:.4e}, {:.4e}]",
                s.parameter.column(),
                s.median,
                s.ci05,
                s.ci95
            )
        })
        .collect::<Vec<_>>()
        .join("\n");
    finish(out, art, &meta)
}
