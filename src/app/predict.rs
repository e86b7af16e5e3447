//! The predict job: Monte Carlo prediction of wear, vibration indicators and remaining
//! life over posterior (or prior) samples, to a wear limit and a horizon; whole, or one
//! shard of it ([`crate::app::PredictMergeJob`] joins the shards).

use super::calibrate::counted;
use super::inputs::TableSource;
use super::observer::{Observer, Task};
use super::predict_future::FutureInput;
use super::train_prognostics::{check_train_prognostics, stages_of};
use super::{budget, build_wear_study_model, publish, settings, Job, JobError, Outcome};
use crate::config::Case;
use crate::io::Table;
use crate::prognostics::band::Band;
use crate::prognostics::check::{check_prediction, PredictionCheck};
use crate::prognostics::forward::{Crossing, FutureDuty};
use crate::prognostics::predict::{
    fans, run_sample, Forward, LifeSummary, PredictSettings, SampleOutcome, SampleSource,
};
use crate::prognostics::prior::{Prior, Theta};
use crate::prognostics::samples::read_samples;
use crate::prognostics::surrogate::{future_chain_runs, max_chain_runs};
use crate::prognostics::{Quantity, Surrogate};
use crate::remedy::Arg;
use crate::report::figure_output::{FigureOutput, FigureRequest};
use crate::report::html::{render, Report};
use crate::report::prognostics::{fan_figure, life_figure, prediction_section};
use crate::report::prognostics_tables::{bands_table, figure, thetas_json};
use crate::report::Artifacts;
use crate::store::RunMetadata;
use crate::study::budget::Budget;
use crate::study::sweep::Shard;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use sha2::{Digest, Sha256};
use std::path::PathBuf;

/// The forward model of each sample.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ForwardModel {
    /// Reference runs and the k x N invariance (fast).
    Surrogate,
    /// One true wear study per sample (slow; shard it).
    Exact,
}

/// What to predict and how.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PredictOptions {
    /// Wear limit on the maximum pinion wear depth, um.
    pub limit_um: f64,
    /// Horizon, pinion cycles.
    pub cycles: f64,
    /// Seed of every random draw.
    pub seed: u64,
    /// Ensemble size (`None`: every posterior row, or 2000 prior draws); with a posterior
    /// of another size its rows are drawn with replacement.
    pub samples: Option<usize>,
    /// Cycle counts of the fan charts, from 0 to the horizon.
    pub grid_points: usize,
    /// The forward model of each sample's wear: the surrogate or one true wear study per
    /// sample.
    pub forward: ForwardModel,
    /// True wear runs to check the surrogate against (at the 5/50/95 % of the life).
    pub check_runs: usize,
}

impl PredictOptions {
    /// The defaults for a limit and a horizon.
    pub fn new(limit_um: f64, cycles: f64) -> Self {
        Self {
            limit_um,
            cycles,
            seed: 1,
            samples: None,
            grid_points: 101,
            forward: ForwardModel::Surrogate,
            check_runs: 3,
        }
    }

    /// Every problem of the options: each within its range (`prognostics::limits`).
    fn check(&self) -> Result<(), JobError> {
        settings::check_settings(crate::prognostics::limits::check_predict(
            self.limit_um,
            self.cycles,
            self.samples,
            self.grid_points,
            self.check_runs,
        ))
    }
}

/// See the module docs.
#[derive(Debug, Clone)]
pub struct PredictJob {
    /// The case predicted (its prior, when no posterior is given).
    pub case: Case,
    /// Posterior samples (from a calibration); `None` samples the case's prior.
    pub posterior: Option<TableSource>,
    /// What to predict and how (limit, horizon, ensemble, forward model).
    pub options: PredictOptions,
    /// A change of duty: a future load spectrum from some cycle count on (default: none).
    pub future: FutureInput,
    /// One shard of the samples ([`Shard::ALL`]: all of them).
    pub shard: Shard,
    /// Output folder; `None` writes nothing.
    pub out: Option<PathBuf>,
    /// Replace another command's results in the output folder (else refused).
    pub replace: bool,
    /// The run budget (`None`: no check).
    pub budget: Option<Budget>,
    /// The formats and size of the figures (a shard draws none), checked when the job
    /// starts.
    pub figures: FigureRequest,
}

/// What makes shards parts of one prediction.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct Identity {
    pub settings: PredictSettings,
    pub forward: String,
    /// SHA-256 of the posterior samples' CSV text, or "prior".
    pub source: String,
    pub case_sha256: String,
    /// The future duty, resolved (its bins, not its file name).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub future: Option<FutureDuty>,
}

/// What a shard writes (`predict_shard_I_of_N.json`), and what a whole prediction is
/// built from.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct ShardFile {
    pub identity: Identity,
    pub shard: (usize, usize),
    /// `RunMetadata` of the run, as JSON.
    pub metadata: Value,
    pub checks: Vec<PredictionCheck>,
    pub reference_failures: Vec<(Theta, f64, String)>,
    pub outcomes: Vec<SampleOutcome>,
}

impl PredictJob {
    /// Where the samples come from: (source, the span of the surrogate, the source's
    /// identity, the ensemble size).
    fn source(&self) -> Result<(SampleSource, Prior, String, usize), JobError> {
        let case = &self.case;
        let defaults = [
            case.wear.coefficient_m2_per_n,
            1.0,
            case.operating.load_torque_nm,
        ];
        Ok(match &self.posterior {
            Some(p) => {
                let (src, text) = p.read(Arg::Posterior, crate::io::input::MAX_POSTERIOR_BYTES)?;
                let rows = read_samples(&text, &src, defaults)?;
                let n = self.options.samples.unwrap_or(rows.len());
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
                let prior = Prior::from_case(case)?;
                (
                    SampleSource::Prior(prior.clone()),
                    prior,
                    "prior".to_string(),
                    self.options.samples.unwrap_or(2000),
                )
            }
        })
    }
}

impl Job for PredictJob {
    type Output = Outcome;

    fn name(&self) -> &'static str {
        "predict"
    }

    fn run(&self, observer: &dyn Observer) -> Result<Outcome, JobError> {
        let figures = self.figures.resolve().map_err(JobError::input)?;
        let o = &self.options;
        o.check()?;
        let future = self.future.resolve(o.cycles)?;
        let case = &self.case;
        check_train_prognostics(case, &[], future.is_some())?;
        let (source, span, source_id, n) = self.source()?;
        let shard = self.shard;
        // The budget, now that the samples' source and number are known.
        self.check_budget(&source, &span, n, future.as_ref())?;
        let study = crate::prognostics::forward::PROGNOSTICS;
        let model = build_wear_study_model(case, study, observer)?;
        // Every bin of the future duty within the model's domain (the Hertz pressure the
        // flanks can carry, ...) before the folder is opened: a refusal leaves nothing.
        if let Some(f) = &future {
            future_domain(case, &model, f)?;
        }
        let stem =
            (shard.count > 1).then(|| format!("predict_shard_{}_of_{}", shard.index, shard.count));
        let out = publish::open_if(
            self.out.as_deref(),
            stem.as_deref(),
            self.name(),
            self.replace,
        )?;
        let set = PredictSettings {
            limit_um: o.limit_um,
            cycles: o.cycles,
            grid_points: o.grid_points,
            seed: o.seed,
            samples: n,
            stages: stages_of(case),
        };
        let meta = RunMetadata::of_model(self.name(), &model);
        let identity = Identity {
            settings: set,
            forward: format!("{:?}", o.forward).to_lowercase(),
            source: source_id,
            case_sha256: meta.case_sha256.clone(),
            future: future.clone(),
        };
        let sur = match o.forward {
            ForwardModel::Surrogate => Some(self.surrogate(observer, &span, future.as_ref())?),
            ForwardModel::Exact => None,
        };
        let fw = match &sur {
            Some(s) => Forward::Surrogate(s),
            None => Forward::Exact(case, future.as_ref()),
        };
        let outcomes = self.run_samples(observer, &fw, &source, &set)?;
        let checks = match (&sur, shard.index, o.check_runs) {
            (Some(s), 1, n) if n > 0 => check_prediction(case, s, &outcomes, &set, n),
            _ => Vec::new(),
        };
        let file = ShardFile {
            identity,
            shard: (shard.index, shard.count),
            metadata: serde_json::to_value(&meta).map_err(|e| JobError::Failed(e.into()))?,
            checks,
            reference_failures: sur.as_ref().map_or_else(Vec::new, |s| s.failures()),
            outcomes,
        };
        if let Some(stem) = stem {
            let art = Artifacts {
                summary: serde_json::to_value(&file).map_err(|e| JobError::Failed(e.into()))?,
                summary_file: Some(format!("{stem}.json")),
                ..Default::default()
            };
            let outcome = publish::publish(out, art, None, observer)?;
            observer.note(&format!(
                "predict: shard {}/{} of the samples; join the shards to get the prediction",
                shard.index, shard.count
            ));
            return Ok(outcome);
        }
        publish::publish(
            out,
            prediction_artifacts(file, (0, Vec::new()), figures)?,
            None,
            observer,
        )
    }
}

impl PredictJob {
    /// Refuse the job over its budget: its shard's `n`-sample ensemble drawn from `source`
    /// over `span`.
    fn check_budget(
        &self,
        source: &SampleSource,
        span: &Prior,
        n: usize,
        future: Option<&FutureDuty>,
    ) -> Result<(), JobError> {
        let (o, shard) = (&self.options, self.shard);
        let e = crate::study::budget::estimate_prediction(
            &self.case,
            span,
            &crate::study::budget::PredictionJob {
                samples_in_shard: n.div_ceil(shard.count.max(1)),
                grid_points: o.grid_points,
                cycles: o.cycles,
                exact: o.forward == ForwardModel::Exact,
                sharded: shard.count > 1,
                check_runs: if shard.index == 1 { o.check_runs } else { 0 },
                posterior_rows: match source {
                    SampleSource::Posterior { rows, .. } => rows.len(),
                    SampleSource::Prior(_) => 0,
                },
                future: future.map(|f| crate::study::budget::chains::FutureDutyJob {
                    spectrum: &f.spectrum,
                    from_cycles: f.from_cycles,
                }),
            },
        );
        budget::check_estimate(&e, self.budget.as_ref())
    }

    /// The surrogate over `span` to the horizon (under the `future` duty), its reference
    /// runs counted as they finish.
    fn surrogate(
        &self,
        observer: &dyn Observer,
        span: &Prior,
        future: Option<&FutureDuty>,
    ) -> Result<Surrogate, JobError> {
        let case = &self.case;
        let nodes = case.calibration.surrogate_nodes.max(2) as usize;
        let chains = nodes.pow(span.free().iter().filter(|i| **i != 0).count() as u32);
        let per_chain = match future {
            None => max_chain_runs(span),
            Some(_) => future_chain_runs(span),
        };
        Ok(counted(
            observer,
            Task::items(
                "reference_runs",
                "reference runs",
                chains * per_chain as usize,
            ),
            |tick| Surrogate::build_for_duty(case, future, span, self.options.cycles, nodes, tick),
        )?)
    }

    /// Every sample of this shard drawn from `source` and run through `fw`, in parallel,
    /// counted as they finish (stopped when the observer cancels).
    fn run_samples(
        &self,
        observer: &dyn Observer,
        fw: &Forward,
        source: &SampleSource,
        set: &PredictSettings,
    ) -> Result<Vec<SampleOutcome>, JobError> {
        let (o, shard) = (&self.options, self.shard);
        let n = set.samples;
        let ids = shard.ids(n);
        observer.note(&format!(
            "predict: {} of {n} samples (shard {}/{}) to {} cycles on {} threads",
            ids.len(),
            shard.index,
            shard.count,
            o.cycles,
            rayon::current_num_threads()
        ));
        counted(
            observer,
            Task::items("samples", "samples", ids.len()),
            |tick| {
                ids.par_iter()
                    .map(|&i| {
                        if observer.cancelled() {
                            return Err(JobError::Cancelled);
                        }
                        let r = run_sample(fw, source.draw(i, o.seed), i, set);
                        tick();
                        r.map_err(JobError::from)
                    })
                    .collect::<Result<Vec<SampleOutcome>, JobError>>()
            },
        )
    }
}

/// Each sample's limiting stage (NaN where none reached the limit).
fn limiting_column(o: &[SampleOutcome]) -> Vec<f64> {
    o.iter()
        .map(|s| s.limiting_stage.map_or(f64::NAN, |x| x as f64))
        .collect()
}

fn life_of(c: Crossing) -> Option<f64> {
    match c {
        Crossing::Reached(x) => Some(x),
        _ => None,
    }
}

/// Quantities whose band at the horizon goes into summary.json.
const FAN_AT_HORIZON: [Quantity; 4] = [
    Quantity::MaxWearPinion,
    Quantity::VelocityRms,
    Quantity::MeshHarmonic(1),
    Quantity::DtePeakToPeak,
];

/// The summary of a prediction (`summary.json`).
fn prediction_summary(
    f: &ShardFile,
    life: &LifeSummary,
    fans: &[(Quantity, Band)],
    failed: &[&SampleOutcome],
    missing: (usize, Vec<usize>),
) -> Value {
    let set = f.identity.settings;
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
    let at_horizon = |q: Quantity| {
        fans.iter().find(|b| b.0 == q).map(|(_, b)| {
            let g = b.cycles.len() - 1;
            json!({"p05": b.percentiles[0][g], "p25": b.percentiles[1][g], "median": b.percentiles[2][g], "p75": b.percentiles[3][g], "p95": b.percentiles[4][g], "samples_with_value": b.valid[g]})
        })
    };
    json!({
        "limit_um": set.limit_um,
        "horizon_cycles": set.cycles,
        "samples": set.samples,
        "seed": set.seed,
        "forward_model": f.identity.forward,
        "source": f.identity.source,
        "future_duty": f.identity.future.as_ref().map(|d| json!({
            "from_cycles": d.from_cycles,
            "load_spectrum": d.spectrum,
            "note": "from these pinion cycles (counted from new teeth) on, the gearbox runs under this load spectrum instead of the case's duty",
        })),
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
    })
}

/// Every output of a prediction from its outcomes (`missing`: how many sample indices no
/// shard had, and the first of them), its figures in the formats and size of `figures`.
pub(crate) fn prediction_artifacts(
    f: ShardFile,
    missing: (usize, Vec<usize>),
    figures: FigureOutput,
) -> Result<Artifacts, JobError> {
    let mut art = Artifacts::default().with_figure_output(figures);
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
    let life_table = match set.stages {
        1 => life_table,
        _ => life_table.col("limiting_stage", limiting_column(o)),
    };
    art.table("life_samples.csv", life_table);
    // The wear fans (every stage's on a train) and the response's.
    let (wear, response): (Vec<_>, Vec<_>) = fans.iter().cloned().partition(|f| f.0.is_wear());
    art.table("fan_wear.csv", bands_table(&wear));
    art.table("fan_vibration.csv", bands_table(&response));
    let figs = vec![
        figure(&mut art, "fan_wear.png", &fan_figure("Maximum pinion wear: median, 50 % and 90 % bands", &wear, Some(set.limit_um)), "Fan chart of the maximum pinion wear depth over the ensemble, with the wear limit.", Some("fan_wear.csv"))?,
        figure(&mut art, "life.png", &life_figure(&lives, &life, set.cycles), "Distribution of the cycles at which the maximum pinion wear reaches the limit (samples that reach it within the horizon).", Some("life_samples.csv"))?,
        figure(&mut art, "fan_vibration.png", &fan_figure("Vibration and transmission-error indicators: median, 50 % and 90 % bands", &response, None), "Fan charts of the indicators a monitoring system sees: RMS and mesh harmonics of the pinion's y velocity, DTE peak-to-peak and first mesh harmonic.", Some("fan_vibration.csv"))?,
    ];
    let failed: Vec<&SampleOutcome> = o.iter().filter(|s| s.failure.is_some()).collect();
    art.summary = prediction_summary(&f, &life, &fans, &failed, missing);
    let mut notes = vec![format!(
        "{} samples, forward model: {}, seed {}.",
        set.samples, f.identity.forward, set.seed
    )];
    if set.stages > 1 {
        super::predict_train::add_train_summary(&mut art.summary, o, &fans, set.stages);
        notes.push(super::predict_train::train_note(o, set.stages));
    }
    if let Some(d) = &f.identity.future {
        notes.push(format!(
            "Future duty: from {:.4e} cycles on, a load spectrum of {} bin(s) (listed in summary.json) instead of the case's duty.",
            d.from_cycles,
            d.spectrum.bins.len()
        ));
    }
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
    let shown = crate::format::shown;
    let fmt = |c: Option<f64>| c.map_or_else(|| format!("> {}", shown(set.cycles)), shown);
    art.headline = format!(
        "cycles to {} µm: median {}, 90 % [{}, {}], P(> {}) = {}; {} failed sample(s)",
        shown(set.limit_um),
        fmt(life.median),
        fmt(life.p05),
        fmt(life.p95),
        shown(set.cycles),
        shown(life.prob_beyond_horizon),
        failed.len(),
    );
    Ok(art)
}

/// The problems of the future duty `f`'s bins for `case` (each bin's case against the
/// model's domain, `study::domain`), named by bin: refused before any folder is opened.
fn future_domain(
    case: &crate::config::Case,
    model: &crate::study::Model,
    f: &crate::prognostics::forward::FutureDuty,
) -> Result<(), JobError> {
    let mut c = case.clone();
    c.load_spectrum = Some(f.spectrum.clone());
    // A helical pair's bins against its transverse section, its lead keys taken by its
    // planar model (as `Model::helical_from_case` checks its own operating point).
    let pair = model
        .helical
        .as_ref()
        .map_or(&model.pair, |h| &h.pair.transverse);
    if model.helical.is_some() {
        c = crate::study::helical_dynamics::without_lead_keys(&c);
    }
    let problems: Vec<crate::remedy::Problem> = (0..f.spectrum.bins.len())
        .flat_map(|i| {
            crate::study::domain::domain_problems(&c.at_bin(i), pair)
                .into_iter()
                .map(move |m| {
                    crate::remedy::Problem::of(
                        crate::remedy::Arg::FutureSpectrum,
                        format!("bin {}: {}", i + 1, crate::duty::model::in_bin_words(&m)),
                    )
                })
        })
        .collect();
    if problems.is_empty() {
        Ok(())
    } else {
        Err(JobError::Input(problems))
    }
}
