//! The calibrate job: the posterior of the uncertain parameters (wear coefficient, and
//! optionally roughness factor and load torque) given observations of a running gearbox,
//! with the posterior samples, the model's band against the observations, the check of
//! the surrogate against true wear runs, and a report.

use super::inputs::TableSource;
use super::observer::{Observer, Task};
use super::train_prognostics::{check_train_prognostics, stages_of};
use super::{budget, build_wear_study_model, publish, settings, Job, JobError, Outcome};
use crate::config::Case;
use crate::prognostics::band::Band;
use crate::prognostics::calibrate::{calibrate, model_band, Calibration, CalibrationSettings};
use crate::prognostics::check::{
    check_calibration, theta_at_k_quantile, worst_ratio, CalibrationCheck,
};
use crate::prognostics::fit_check::{fit_check, FitCheck};
use crate::prognostics::likelihood::noise_scales;
use crate::prognostics::observations::parse_observations_of;
use crate::prognostics::prior::Prior;
use crate::prognostics::quantity::indicators_of;
use crate::prognostics::{Observations, Quantity, Surrogate};
use crate::remedy::Arg;
use crate::report::figure_output::FigureOutput;
use crate::report::figure_output::FigureRequest;
use crate::report::html::{render, Report};
use crate::report::prognostics::{calibration_section, posterior_figure, predictive_figure};
use crate::report::prognostics_tables::{
    bands_table, figure, fit_check_block, samples_table, thetas_json,
};
use crate::report::Artifacts;
use crate::store::RunMetadata;
use crate::study::budget::Budget;
use serde_json::json;
use std::path::PathBuf;

/// Cycle counts of the posterior band.
const BAND_POINTS: usize = 101;

/// The sampler's settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CalibrationOptions {
    /// Seed of every random draw.
    pub seed: u64,
    /// Posterior samples to write.
    pub samples: usize,
    /// Walkers of the ensemble sampler (three parameters).
    pub walkers: usize,
    /// Steps of the ensemble sampler (the first half is burn-in).
    pub steps: usize,
    /// True wear runs to check the surrogate against (at the posterior's 5/50/95 %).
    pub check_runs: usize,
}

impl Default for CalibrationOptions {
    fn default() -> Self {
        Self {
            seed: 1,
            samples: 2000,
            walkers: 32,
            steps: 2000,
            check_runs: 3,
        }
    }
}

/// See the module docs.
#[derive(Debug, Clone)]
pub struct CalibrateJob {
    /// The case calibrated (its `[calibration]` table gives the priors).
    pub case: Case,
    /// Observations: `cycles`, observed quantities (names of the updates table), optional
    /// `sigma_<name>` columns (docs/PROGNOSTICS.md).
    pub observations: TableSource,
    /// The sampler's settings (samples, walkers, steps, seed, check runs).
    pub options: CalibrationOptions,
    /// Output folder; `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The run budget (`None`: no check).
    pub budget: Option<Budget>,
    /// The formats and size of the figures, checked when the job starts.
    pub figures: FigureRequest,
}

impl CalibrateJob {
    /// The prior and the observations, checked.
    fn inputs(&self) -> Result<(Prior, Observations, String), JobError> {
        let prior = Prior::from_case(&self.case)?;
        if prior.free().is_empty() {
            return Err(JobError::input(
                "nothing to calibrate: every prior of [calibration] has equal bounds (give calibration.wear_coefficient_min_m2_per_n < ..._max_m2_per_n)",
            ));
        }
        let o = &self.options;
        settings::check_settings(crate::prognostics::limits::check_calibrate(
            o.samples,
            o.walkers,
            o.steps,
            o.check_runs,
            prior.free().len(),
        ))?;
        let (src, text) = self
            .observations
            .read(Arg::Observations, crate::io::input::MAX_OBSERVATIONS_BYTES)?;
        let obs = parse_observations_of(&text, &src, stages_of(&self.case))?;
        let observed: Vec<Quantity> = obs.series.iter().map(|s| s.quantity).collect();
        check_train_prognostics(&self.case, &observed, false)?;
        // The budget, now that the observations say how far the reference runs go.
        let e = crate::study::budget::estimate_calibration(
            &self.case,
            &prior,
            &crate::study::budget::CalibrationJob {
                values: obs.len(),
                quantities: obs.series.len(),
                max_cycles: obs.max_cycles(),
                samples: o.samples,
                walkers: o.walkers,
                steps: o.steps,
                check_runs: o.check_runs,
                check_depth_bound_m: crate::prognostics::check::observed_depth_bound_m(
                    &self.case,
                    &obs,
                    || {
                        let pair = crate::geometry::GearPair::from_case(&self.case.gear).ok()?;
                        Some(crate::study::budget::nominal_member_wear_per_cycle_m(
                            &self.case, &pair,
                        ))
                    },
                ),
            },
        );
        budget::check_estimate(&e, self.budget.as_ref())?;
        Ok((prior, obs, src))
    }
}

impl Job for CalibrateJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "calibrate"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        let (prior, obs, src) = self.inputs()?;
        let study = crate::prognostics::forward::PROGNOSTICS;
        let model = build_wear_study_model(&self.case, study, observer)?;
        let out = publish::open_if(self.out.as_deref(), None, self.name(), self.replace)?;
        let meta = RunMetadata::of_model(self.name(), &model);
        let o = &self.options;
        let case = &self.case;

        let nodes = case.calibration.surrogate_nodes.max(2) as usize;
        let n_ref = nodes.pow(prior.free().iter().filter(|i| **i != 0).count() as u32);
        observer.note(&format!(
            "calibrate: {n_ref} reference wear run(s) on {} threads",
            rayon::current_num_threads()
        ));
        let mut sur = counted(
            observer,
            Task::items("reference_runs", "reference runs", n_ref),
            |tick| Surrogate::build(case, &prior, obs.max_cycles(), nodes, tick),
        )?;
        let observed: Vec<Quantity> = obs.series.iter().map(|s| s.quantity).collect();
        if !indicators_of(&observed).is_empty() {
            counted(
                observer,
                Task::items(
                    "indicators",
                    "indicators of the reference runs",
                    sur.run_count(),
                ),
                |tick| sur.attach_indicators(case, &observed, tick),
            )
            .map_err(|e| JobError::Failed(anyhow::anyhow!("condition indicators: {e}")))?;
        }
        for (t, until, msg) in sur.failures() {
            observer.warning(&format!(
                "the reference run at k = {:.3e} m^2/N, roughness factor {}, load torque {} N m stopped at a wear exposure k N = {until:.3e} m^2/N ({msg}); parameters that need more count as failed samples",
                t[0], t[1], t[2]
            ));
        }
        let settings = CalibrationSettings {
            samples: o.samples,
            seed: o.seed,
            grid_cells: case.calibration.grid_points.max(16) as usize,
            walkers: o.walkers,
            steps: o.steps,
        };
        let steps = if prior.free().len() <= 2 { 8 } else { o.steps };
        let cal = counted(
            observer,
            Task::items("posterior", "posterior", steps),
            |tick| calibrate(&prior, &obs, &sur, &settings, tick),
        )
        .map_err(|e| JobError::Failed(anyhow::anyhow!(e)))?;
        if !cal.failed.is_empty() {
            let ks: Vec<f64> = cal.failed.iter().map(|t| t[0]).collect();
            observer.warning(&format!(
                "the forward model failed at {} parameter set(s) (k from {:.3e} to {:.3e} m^2/N); they carry no posterior mass and are listed in summary.json",
                cal.failed.len(),
                ks.iter().copied().fold(f64::INFINITY, f64::min),
                ks.iter().copied().fold(0.0, f64::max)
            ));
        }
        let art = self.artifacts(&obs, &src, &sur, &cal, (&meta, figures), observer)?;
        publish::publish(out, art, Some(&meta), observer)
    }
}

/// Run `work` as a counted task of `observer`, handing it the tick to call per unit.
pub fn counted<T>(
    observer: &dyn Observer,
    task: Task,
    work: impl FnOnce(&(dyn Fn() + Sync)) -> T,
) -> T {
    observer.start(&task);
    let n = std::sync::atomic::AtomicUsize::new(0);
    let tick = || {
        let done = n.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
        observer.advance(&task, done as f64, "");
    };
    let r = work(&tick);
    observer.finish(&task);
    r
}

/// The checks of a calibration: the model's band over the posterior against each
/// observed quantity, the noise scales, and the surrogate against true wear runs.
struct Checked {
    bands: Vec<(Quantity, Band)>,
    noise: Vec<(Quantity, bool, f64)>,
    check: Vec<CalibrationCheck>,
    worst: f64,
    fit: FitCheck,
}

impl CalibrateJob {
    /// The bands, the noise scales and the surrogate's check against true runs.
    fn check(
        &self,
        obs: &Observations,
        sur: &Surrogate,
        cal: &Calibration,
        observer: &dyn Observer,
    ) -> Checked {
        let o = &self.options;
        let horizon = obs.max_cycles().max(1.0);
        let bands: Vec<(Quantity, Band)> = obs
            .series
            .iter()
            .map(|s| {
                (
                    s.quantity,
                    model_band(sur, &cal.samples, s.quantity, horizon, BAND_POINTS).0,
                )
            })
            .collect();
        let median_theta = theta_at_k_quantile(cal, 0.5);
        let noise = noise_scales(obs, &|q, c| sur.value(q, &median_theta, c));
        let fit = fit_check(obs, &cal.samples, &|q, t, c| sur.value(q, t, c), &noise);
        if let Some(w) = &fit.warning {
            observer.warning(&format!("{w}; see summary.json fit_check"));
        }
        if o.check_runs > 0 {
            observer.note(&format!(
                "calibrate: checking the surrogate against {} true wear run(s)",
                o.check_runs.min(3)
            ));
        }
        let check = check_calibration(&self.case, sur, cal, obs, &noise, o.check_runs);
        let worst = worst_ratio(&check);
        if worst > 0.1 {
            observer.warning(&format!("the surrogate's error reaches {worst:.3} of the posterior predictive spread (target < 0.1); see summary.json surrogate_check"));
        }
        Checked {
            bands,
            noise,
            check,
            worst,
            fit,
        }
    }

    /// The summary of a calibration (`summary.json`).
    #[allow(clippy::too_many_arguments)]
    fn summary(
        &self,
        cal: &Calibration,
        obs: &Observations,
        sur: &Surrogate,
        noise: &[(Quantity, bool, f64)],
        check: &[CalibrationCheck],
        worst: f64,
        fit: &FitCheck,
        meta: &RunMetadata,
    ) -> serde_json::Value {
        let o = &self.options;
        json!({
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
            "seed": o.seed,
            "grid_levels": cal.grid_levels,
            "grid_posterior_mass_neglected": cal.mass_outside,
            "mcmc": {"walkers": o.walkers, "steps": o.steps, "burn_in": o.steps / 2, "acceptance": cal.acceptance},
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
            "fit_check": fit,
            "metadata": meta,
        })
    }

    /// The summary, tables, figures (in the formats and size of `figures`) and report of
    /// a calibration.
    fn artifacts(
        &self,
        obs: &Observations,
        src: &str,
        sur: &Surrogate,
        cal: &Calibration,
        (meta, figures): (&RunMetadata, FigureOutput),
        observer: &dyn Observer,
    ) -> Result<Artifacts, JobError> {
        let horizon = obs.max_cycles().max(1.0);
        let Checked {
            bands,
            noise,
            check,
            worst,
            fit,
        } = self.check(obs, sur, cal, observer);
        let mut art = Artifacts::default().with_figure_output(figures);
        art.table("posterior_samples.csv", samples_table(&cal.samples));
        art.table("posterior_band.csv", bands_table(&bands));
        let figs = vec![
            figure(&mut art, "posterior.png", &posterior_figure(cal), "Marginal posterior density of each calibrated parameter (solid) and its prior (dashed).", Some("posterior_samples.csv"))?,
            figure(&mut art, "posterior_band.png", &predictive_figure(obs, &bands), "Observations (points) against the model's band over the posterior samples: median, 50 % and 90 % bands of the noise-free model values.", Some("posterior_band.csv"))?,
        ];
        art.summary = self.summary(cal, obs, sur, &noise, &check, worst, &fit, meta);
        let (fit_text, fit_table) = fit_check_block(&fit);
        let notes = vec![
            format!(
                "Observations: {} values of {} quantities from {src}, up to {} cycles.",
                obs.len(),
                obs.series.len(),
                horizon
            ),
            fit_text,
        ];
        let mut section = calibration_section(cal, notes, figs);
        section.tables.push(fit_table);
        let report = Report {
            title: "gearwear calibration".into(),
            sections: vec![section],
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
            observer.warning(&format!(
                "{}: split R-hat {:.3} > 1.05, the walkers have not mixed: run more sampler steps",
                s.parameter.column(),
                s.rhat.unwrap_or(f64::NAN)
            ));
        }
        art.headline = cal
            .summary
            .iter()
            .map(|s| {
                format!(
                    "{}: median {}, 90 % interval [{}, {}]",
                    s.parameter.column(),
                    crate::format::shown(s.median),
                    crate::format::shown(s.ci05),
                    crate::format::shown(s.ci95)
                )
            })
            .collect::<Vec<_>>()
            .join("\n");
        Ok(art)
    }
}
