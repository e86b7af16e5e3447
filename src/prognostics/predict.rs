//! Prediction: Monte Carlo forward runs over posterior (or prior) samples, to a horizon
//! of N cycles; fan charts of wear and vibration indicators, and the distribution of the
//! cycles at which the maximum pinion wear reaches a limit (remaining useful life).

use super::band::{cycles_grid, Band};
use super::forward::{run_duty_trajectory, Crossing, FutureDuty, Trajectory};
use super::prior::{apply, Prior, Theta};
use super::quantity::Quantity;
use super::stats::{quantile_sorted, std_dev};
use super::surrogate::Surrogate;
use crate::config::Case;
use crate::rng;
use crate::study::model::ModelError;
use serde::{Deserialize, Serialize};

/// Quantities of the fan charts: the wear and what the monitoring engineer will see.
pub(crate) const FAN_QUANTITIES: [Quantity; 6] = [
    Quantity::MaxWearPinion,
    Quantity::VelocityRms,
    Quantity::MeshHarmonic(1),
    Quantity::MeshHarmonic(2),
    Quantity::DtePeakToPeak,
    Quantity::DteHarmonic1,
];

/// The limit, horizon, sizes and seed of a life prediction.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PredictSettings {
    /// Wear limit on the maximum pinion wear depth, um.
    pub limit_um: f64,
    /// Horizon, cycles.
    pub cycles: f64,
    /// Points of the cycle grid the fans are given on.
    pub grid_points: usize,
    /// Seed of the random streams (each sample depends only on it and its index).
    pub seed: u64,
    /// Ensemble size.
    pub samples: usize,
    /// Meshes of the case (1 for a single pair; a gear train's stages): the fans hold
    /// every stage's quantities ([`fan_quantities`]) and the life is the first mesh's to
    /// reach the limit.
    #[serde(default = "one", skip_serializing_if = "is_one")]
    pub stages: usize,
}

/// The default of [`PredictSettings::stages`]: a single pair.
fn one() -> usize {
    1
}

/// Whether `n` is 1 (a single pair's settings are written as they were before trains).
fn is_one(n: &usize) -> bool {
    *n == 1
}

/// The fan quantities of a case of `stages` meshes: `FAN_QUANTITIES` (stage 1's),
/// then each later stage's (`Quantity::OnStage`), stage by stage.
pub fn fan_quantities(stages: usize) -> Vec<Quantity> {
    let mut v = FAN_QUANTITIES.to_vec();
    for s in 2..=stages {
        v.extend(FAN_QUANTITIES.iter().filter_map(|q| q.on_stage(s)));
    }
    v
}

/// Where the parameter samples come from.
#[derive(Debug, Clone)]
pub enum SampleSource {
    /// Draws from the prior.
    Prior(Prior),
    /// Posterior rows; `resample`: draw with replacement (else row i is sample i).
    Posterior {
        /// Posterior samples, one parameter set per row.
        rows: Vec<Theta>,
        /// Draw with replacement (else row i is sample i).
        resample: bool,
    },
}

impl SampleSource {
    /// Parameters of sample `index` (depends only on seed and index).
    pub fn draw(&self, index: usize, seed: u64) -> Theta {
        let mut r = rng::stream(seed, index as u64);
        match self {
            SampleSource::Prior(p) => p.draw(&mut r),
            SampleSource::Posterior { rows, resample } => {
                if *resample {
                    rows[((rng::uniform(&mut r) * rows.len() as f64) as usize).min(rows.len() - 1)]
                } else {
                    rows[index % rows.len()]
                }
            }
        }
    }
}

/// The forward model of a prediction.
pub enum Forward<'a> {
    /// The surrogate built from reference runs (fast).
    Surrogate(&'a Surrogate),
    /// One true wear study per sample (the case's block scheme), following a change of
    /// duty if one is given.
    Exact(&'a Case, Option<&'a FutureDuty>),
}

/// What one sample predicts.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SampleOutcome {
    /// Index of the sample in the ensemble.
    pub index: usize,
    /// Its parameters.
    pub theta: Theta,
    /// Cycles to the wear limit (NotReached: beyond the horizon; Unknown: the forward
    /// run failed before).
    pub life: Crossing,
    /// `values[f][g]`: `FAN_QUANTITIES[f]` at grid point g; None past a failure.
    pub values: Vec<Vec<Option<f64>>>,
    /// Why the run stopped before the horizon.
    pub failure: Option<String>,
    /// Cycles up to which the run is known (>= the horizon when it did not fail).
    pub valid_until: f64,
    /// On a gear train, the stage (1-based) whose maximum pinion wear reaches the limit
    /// first, when one does within the horizon; None for a single pair.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limiting_stage: Option<usize>,
}

/// Life within the horizon, or NotReached beyond it.
fn within(c: Crossing, horizon: f64) -> Crossing {
    match c {
        Crossing::Reached(x) if x > horizon => Crossing::NotReached,
        c => c,
    }
}

/// Predict one sample.
pub fn run_sample(
    fw: &Forward,
    theta: Theta,
    index: usize,
    set: &PredictSettings,
) -> Result<SampleOutcome, ModelError> {
    let grid = cycles_grid(set.cycles, set.grid_points);
    let fan = fan_quantities(set.stages);
    let train = set.stages > 1;
    let (life, values, failure, valid_until, limiting_stage) = match fw {
        Forward::Surrogate(s) => {
            let life = within(s.cycles_to_wear(&theta, set.limit_um), set.cycles);
            let limiting = match life {
                Crossing::Reached(x) if train => Some(s.deepest_stage(&theta, x)),
                _ => None,
            };
            let vals = fan
                .iter()
                .map(|q| grid.iter().map(|c| s.value(*q, &theta, *c)).collect())
                .collect();
            let until = s.valid_until(&theta);
            let failure = (until < set.cycles).then(|| {
                format!(
                    "the reference run behind this sample failed; the surrogate is known to {until:.0} cycles at this k"
                )
            });
            (life, vals, failure, until, limiting)
        }
        Forward::Exact(case, future) => {
            let t: Trajectory =
                run_duty_trajectory(&apply(case, &theta), *future, None, set.cycles)?;
            let life = within(t.cycles_to_wear(set.limit_um), set.cycles);
            let limiting = match life {
                Crossing::Reached(_) if train => t.limiting_stage(set.limit_um),
                _ => None,
            };
            let vals = fan
                .iter()
                .map(|q| grid.iter().map(|c| t.value(*q, *c)).collect())
                .collect();
            (life, vals, t.failure.clone(), t.valid_until(), limiting)
        }
    };
    Ok(SampleOutcome {
        index,
        theta,
        life,
        values,
        failure,
        valid_until,
        limiting_stage,
    })
}

/// The remaining-life distribution.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LifeSummary {
    /// Samples in the ensemble.
    pub samples: usize,
    /// Samples whose wear reaches the limit within the horizon.
    pub reached: usize,
    /// Samples whose wear stays below the limit over the horizon.
    pub beyond_horizon: usize,
    /// Samples whose forward run failed before the limit (life unknown).
    pub unknown: usize,
    /// Percentiles of the cycles to the limit; None: beyond the horizon, or not
    /// determined (an unknown life lies between its run's last known cycle count and
    /// +inf; a percentile is kept where both ends give the same value).
    pub p05: Option<f64>,
    /// Median of the cycles to the limit.
    pub median: Option<f64>,
    /// 95th percentile of the cycles to the limit.
    pub p95: Option<f64>,
    /// P(life > horizon) over the samples with a known life.
    pub prob_beyond_horizon: f64,
    /// Bounds on it when the unknown samples are counted as all below / all beyond.
    pub prob_beyond_horizon_bounds: (f64, f64),
    /// Standard deviation of the life over the samples that reach the limit.
    pub spread_reached: f64,
}

impl LifeSummary {
    /// The distribution of the outcomes `outcomes`.
    pub fn of(outcomes: &[SampleOutcome]) -> Self {
        let mut known: Vec<f64> = Vec::new();
        let (mut reached, mut beyond, mut unknown) = (0, 0, 0);
        for o in outcomes {
            match o.life {
                Crossing::Reached(c) => {
                    reached += 1;
                    known.push(c);
                }
                Crossing::NotReached => {
                    beyond += 1;
                    known.push(f64::INFINITY);
                }
                Crossing::Unknown => unknown += 1,
            }
        }
        let n = outcomes.len();
        let finite: Vec<f64> = known.iter().copied().filter(|x| x.is_finite()).collect();
        let mut lower = known.clone();
        lower.extend(
            outcomes
                .iter()
                .filter(|o| o.life == Crossing::Unknown)
                .map(|o| o.valid_until),
        );
        known.resize(n, f64::INFINITY);
        known.sort_by(f64::total_cmp);
        lower.sort_by(f64::total_cmp);
        let q = |p: f64| {
            let (a, b) = (quantile_sorted(&lower, p), quantile_sorted(&known, p));
            Some(b).filter(|x| x.is_finite() && *x == a)
        };
        let n_known = (reached + beyond) as f64;
        Self {
            samples: n,
            reached,
            beyond_horizon: beyond,
            unknown,
            p05: q(0.05),
            median: q(0.5),
            p95: q(0.95),
            prob_beyond_horizon: if n_known > 0.0 {
                beyond as f64 / n_known
            } else {
                f64::NAN
            },
            prob_beyond_horizon_bounds: (
                beyond as f64 / n.max(1) as f64,
                (beyond + unknown) as f64 / n.max(1) as f64,
            ),
            spread_reached: if finite.len() > 1 {
                std_dev(&finite)
            } else {
                f64::NAN
            },
        }
    }
}

/// Check what a prediction shard claims (it is an input file): settings within their
/// ranges (`limits`), a shard `index` of `count` with 1 <= index <= count <= samples, at
/// most its share of the samples, each with an index below the ensemble size and one
/// value per fan quantity and grid point.
pub(crate) fn check_shard(
    set: &PredictSettings,
    (index, count): (usize, usize),
    outcomes: &[SampleOutcome],
) -> Result<(), String> {
    let bad = super::limits::check_predict(
        set.limit_um,
        set.cycles,
        Some(set.samples),
        set.grid_points,
        0,
    );
    if let Some(p) = bad.first() {
        return Err(p.message.clone());
    }
    if !(1..=crate::config::train::MAX_STAGES).contains(&set.stages) {
        return Err(format!(
            "`stages` = {} is outside 1..{}",
            set.stages,
            crate::config::train::MAX_STAGES
        ));
    }
    let fan = fan_quantities(set.stages).len();
    if !(1 <= index && index <= count && count <= set.samples) {
        return Err(format!(
            "shard {index} of {count} is not a shard of {} samples",
            set.samples
        ));
    }
    if outcomes.len() > set.samples.div_ceil(count) {
        return Err(format!(
            "holds {} samples, more than shard {index} of {count} of {} samples can",
            outcomes.len(),
            set.samples
        ));
    }
    for o in outcomes {
        if o.index >= set.samples
            || o.values.len() != fan
            || o.limiting_stage.is_some_and(|s| s == 0 || s > set.stages)
            || o.values.iter().any(|v| v.len() != set.grid_points)
        {
            return Err(format!(
                "sample {} does not fit the prediction ({} samples, {} fan quantities of {} points)",
                o.index,
                set.samples,
                fan,
                set.grid_points
            ));
        }
    }
    Ok(())
}

/// Fan charts of every fan quantity.
pub fn fans(outcomes: &[SampleOutcome], set: &PredictSettings) -> Vec<(Quantity, Band)> {
    let grid = cycles_grid(set.cycles, set.grid_points);
    fan_quantities(set.stages)
        .iter()
        .enumerate()
        .map(|(f, q)| {
            let v: Vec<Vec<Option<f64>>> = outcomes.iter().map(|o| o.values[f].clone()).collect();
            (*q, Band::of(&grid, &v, q.is_wear()))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome(life: Crossing, valid_until: f64) -> SampleOutcome {
        SampleOutcome {
            index: 0,
            theta: [1.0, 1.0, 1.0],
            life,
            values: vec![],
            failure: None,
            valid_until,
            limiting_stage: None,
        }
    }

    #[test]
    fn unknown_lives_bound_the_percentiles() {
        // Lives 1..=19 and one unknown whose run stopped at 25 cycles (its life is > 25):
        // the median (between the 10th and 11th of 20) is 10.5 whatever that life is;
        // the 95 % point (19.05th) depends on it: undetermined.
        let mut o: Vec<SampleOutcome> = (1..=19)
            .map(|i| outcome(Crossing::Reached(i as f64), 100.0))
            .collect();
        o.push(outcome(Crossing::Unknown, 25.0));
        let l = LifeSummary::of(&o);
        assert_eq!(l.median, Some(10.5));
        assert_eq!(l.p95, None);
        assert_eq!((l.reached, l.unknown), (19, 1));
        // The unknown run stopped at 5 cycles instead: its life in (5, inf) now moves
        // the median too.
        o[19].valid_until = 5.0;
        assert_eq!(LifeSummary::of(&o).median, None);
        // Beyond the horizon: counted in P(life > N).
        o[19].life = Crossing::NotReached;
        let l = LifeSummary::of(&o);
        assert_eq!((l.prob_beyond_horizon, l.median), (0.05, Some(10.5)));
    }
}
