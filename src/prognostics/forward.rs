//! One forward run: a dynamic wear study of a case, kept as its update records, and the
//! observable quantities it gives at any cycle count.
//!
//! Between updates (paper eq. 17) the wear grows linearly in cycles at the per-cycle
//! increment of the last update, so the maximum wear depth at n cycles after update j is
//! exactly max_i (h_ij + n inc_ij) (the maximum of straight lines, convex in n). The
//! response (vibration, DTE) is computed only at the updates; between two updates it is
//! interpolated linearly in cycles (the wear state moves linearly between them, and the
//! response of an intermediate state lies between theirs). A step (the response of the
//! last update held until the next) would make every observable jump where an update
//! falls, and the likelihood jagged in k; the linear reading keeps it continuous, so a
//! shift of the update points (another k, another block rounding) changes it little.
//!
//! A run that fails (today the integrator can fail at large wear) keeps the records it
//! reached and says why: it is valid up to its last record and unknown after it.
//!
//! **Condition indicators** ([`super::indicator`]). At each update of a wear run the wear
//! state is recorded through the case's `[signals]` chain with the built-in generic
//! housing (the record `gearwear signals` writes, measurement noise left out: noise
//! belongs to the likelihood's noise model) and the indicator is computed from that record
//! (`attach`). Between updates it is read as every response quantity is (linear in
//! cycles).

use super::indicator::{name, value};
use super::quantity::{indicators_of, Quantity};
use super::train_forward::TrainRun;
use crate::config::Case;
use crate::config::LoadSpectrumSection;
use crate::duty::contribution::combined_record;
use crate::duty::life::first_crossing;
use crate::duty::wear::{run_spectrum_wear, SpectrumRun};
use crate::duty::SpectrumModel;
use crate::signals::chain::NoiseSpec;
use crate::signals::setup::chain_of;
use crate::study::model::{Model, ModelError};
use crate::study::signal_record::record_case;
use crate::study::wear_loop::{run_wear, ProfileAndIncrement, UpdateRecord, WearMode, WearRun};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// The studies whose forward runs these are, as a refusal names them.
pub const PROGNOSTICS: &str = "`gearwear calibrate` and `gearwear predict`";

/// A dynamic wear study's records.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Trajectory {
    /// Wear coefficient of the run, m^2/N.
    pub coefficient_m2_per_n: f64,
    /// Cycle count the run was asked to reach.
    pub requested_cycles: f64,
    /// Every wear update of the run, in order of cycles.
    pub records: Vec<UpdateRecord>,
    /// Why the run stopped before `requested_cycles` (None: it reached them).
    pub failure: Option<String>,
    /// Condition indicators at the first updates, by name (`attach`).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub indicators: BTreeMap<String, Vec<f64>>,
    /// A gear train's later stages' records (stage 2 first), one per update as `records`
    /// (which are stage 1's); each record's cycles are its own pinion's revolutions.
    /// Empty for a single pair (and a one-stage train). `super::train_forward`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub later_stages: Vec<Vec<UpdateRecord>>,
    /// A train's pinion revolutions of each stage per input cycle (c_k,
    /// `TrainModel::cycle_factors`, stage order, c_1 = 1); empty for a single pair.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub cycle_factors: Vec<f64>,
}

/// Where a wear trajectory reaches a limit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Crossing {
    /// At this many cycles (continuous: the exact crossing within a block).
    Reached(f64),
    /// Not within the cycles the run covered.
    NotReached,
    /// The run failed before reaching the limit: unknown.
    Unknown,
}

/// Largest value of h_i + n inc_i over every profile (each tooth's when the mesh is
/// tooth-resolved: the deepest wear is on one tooth, as the wear study reports it), m.
fn max_after(profiles: &[ProfileAndIncrement], n: f64) -> f64 {
    profiles.iter().fold(0.0_f64, |m, (h, inc)| {
        h.iter().zip(*inc).fold(m, |m, (a, d)| m.max(a + n * d))
    })
}

impl Trajectory {
    /// Cycles up to which the run is known.
    pub(crate) fn valid_until(&self) -> f64 {
        match (&self.failure, self.records.last()) {
            (None, Some(_)) => self.requested_cycles,
            (Some(_), Some(r)) => r.wear.cycles,
            (_, None) => -1.0,
        }
    }

    /// Index of the last update at or before `cycles` (the run's own cycles: input
    /// cycles on a train); None beyond the valid range.
    fn update_at(&self, cycles: f64) -> Option<usize> {
        let tol = 1e-9 * self.valid_until().abs().max(1.0);
        if self.records.is_empty() || cycles > self.valid_until() + tol || cycles < 0.0 {
            return None;
        }
        let j = self.records.partition_point(|r| r.wear.cycles <= cycles);
        Some(j.max(1) - 1)
    }

    /// The trajectory of a gear train's run (`super::train_forward`) at wear coefficient
    /// `k` (m^2/N) asked to reach `requested` input cycles.
    pub(crate) fn of_train(run: TrainRun, k: f64, requested: f64) -> Self {
        Trajectory {
            coefficient_m2_per_n: k,
            requested_cycles: requested,
            records: run.records,
            failure: run.failure,
            indicators: BTreeMap::new(),
            later_stages: run.later_stages,
            cycle_factors: run.cycle_factors,
        }
    }

    /// Number of meshes the run holds (1 for a single pair).
    pub fn stage_count(&self) -> usize {
        1 + self.later_stages.len()
    }

    /// Stage `stage`'s (1-based) records and its pinion revolutions per input cycle;
    /// None for a stage the run does not hold.
    fn stage_records(&self, stage: usize) -> Option<(&[UpdateRecord], f64)> {
        match stage {
            1 => Some((&self.records, 1.0)),
            s => Some((
                self.later_stages.get(s.checked_sub(2)?)?,
                *self.cycle_factors.get(s - 1)?,
            )),
        }
    }

    /// Value of `q` at `cycles` (display units; on a train, input cycles and `q`'s
    /// stage), None beyond the valid range or for a stage the run does not hold.
    pub fn value(&self, q: Quantity, cycles: f64) -> Option<f64> {
        let j = self.update_at(cycles)?;
        let (records, c) = self.stage_records(q.stage())?;
        let r = &records[j];
        // Mesh k's pinion turns c_k times per input cycle: its own cycles since the
        // update (its record's cycles are its own, `train_wear::next_block`).
        let n = (cycles - self.records[j].wear.cycles).max(0.0) * c;
        Some(match q.base() {
            Quantity::MaxWearPinion => max_after(&r.pinion_profiles(), n) * 1e6,
            Quantity::MaxWearGear => max_after(&r.gear_profiles(), n) * 1e6,
            _ => match self.records.get(j + 1) {
                Some(next) if next.wear.cycles > self.records[j].wear.cycles => {
                    let t = ((cycles - self.records[j].wear.cycles).max(0.0)
                        / (next.wear.cycles - self.records[j].wear.cycles))
                        .min(1.0);
                    let (a, b) = (self.response(q, j)?, self.response(q, j + 1)?);
                    a + t * (b - a)
                }
                _ => self.response(q, j)?,
            },
        })
    }

    /// Value of a response quantity at update `j`; None for an indicator not attached
    /// there.
    fn response(&self, q: Quantity, j: usize) -> Option<f64> {
        match q {
            Quantity::Indicator(i) => self.indicators.get(name(i))?.get(j).copied(),
            _ => Some(q.of_summary(&self.stage_records(q.stage())?.0.get(j)?.summary)),
        }
    }

    /// Cycles at which the maximum pinion wear first reaches `limit_um`; on a train,
    /// the input cycles at which the first mesh's does (`limiting_stage`).
    pub fn cycles_to_wear(&self, limit_um: f64) -> Crossing {
        match self
            .stage_crossings(limit_um)
            .into_iter()
            .flatten()
            .reduce(f64::min)
        {
            Some(c) => Crossing::Reached(c),
            None if self.failure.is_some() => Crossing::Unknown,
            None => Crossing::NotReached,
        }
    }

    /// Each stage's input cycles at which its maximum pinion wear first reaches
    /// `limit_um` (None: not within the run), stage order: stage k's crossing in its own
    /// cycles over c_k.
    pub fn stage_crossings(&self, limit_um: f64) -> Vec<Option<f64>> {
        (1..=self.stage_count())
            .map(|s| {
                let (records, c) = self.stage_records(s)?;
                first_crossing(records, self.valid_until() * c, limit_um * 1e-6).map(|x| x / c)
            })
            .collect()
    }

    /// The stage (1-based) whose maximum pinion wear reaches `limit_um` first, if one
    /// does within the run (the first of equal crossings).
    pub fn limiting_stage(&self, limit_um: f64) -> Option<usize> {
        self.stage_crossings(limit_um)
            .iter()
            .enumerate()
            .filter_map(|(s, c)| c.map(|c| (s + 1, c)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(s, _)| s)
    }
}

/// Why a wear run ended before its total cycles, if it did: an error, or an early stop
/// (the solver gave up, or the teeth left the model's domain; [`WearRun::stopped`]).
pub(crate) fn run_failure(result: anyhow::Result<WearRun>) -> Option<String> {
    match result {
        Err(e) => Some(format!("{e:#}")),
        Ok(run) => run.stopped.map(|s| s.reason),
    }
}

/// A change of duty: from `from_cycles` on, the gearbox runs under `spectrum` instead of
/// the case's own spectrum (or operating point), e.g. a heavier duty from next year.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FutureDuty {
    /// Pinion cycles from which the new duty applies.
    pub from_cycles: f64,
    /// The load spectrum of the new duty.
    pub spectrum: LoadSpectrumSection,
}

/// Run the dynamic wear study of `case` to `total_cycles`, with the case's block length
/// or `block_cycles` instead. A solver failure is kept in the trajectory, not returned.
/// Under a load spectrum the records are the spectrum's (`combined_record`: its wear
/// per cycle, the monitoring bin's response). A helical pair wears slice by slice on its
/// planar model (`Model::wear_study_from_case`, docs/MODEL.md 11.9), as `gearwear wear`
/// wears it.
pub fn run_trajectory(
    case: &Case,
    block_cycles: Option<f64>,
    total_cycles: f64,
) -> Result<Trajectory, ModelError> {
    run_duty_trajectory(case, None, block_cycles, total_cycles)
}

/// As [`run_trajectory`], the duty changing to `future` at its cycles: the run under the
/// case's duty to there, then, from the worn state it reached, under the future
/// spectrum (whose monitoring bin the response is read at from then on).
pub fn run_duty_trajectory(
    case: &Case,
    future: Option<&FutureDuty>,
    block_cycles: Option<f64>,
    total_cycles: f64,
) -> Result<Trajectory, ModelError> {
    let mut c = case.clone();
    c.wear.total_cycles = total_cycles;
    if let Some(b) = block_cycles {
        c.wear.block_cycles = b;
    }
    let traj = |records, failure| Trajectory {
        coefficient_m2_per_n: c.wear.coefficient_m2_per_n,
        requested_cycles: total_cycles,
        records,
        failure,
        indicators: BTreeMap::new(),
        later_stages: Vec::new(),
        cycle_factors: Vec::new(),
    };
    if !c.stage.is_empty() {
        if future.is_some() {
            return Err(ModelError(
                vec![super::train_forward::TRAIN_DUTY.to_owned()],
            ));
        }
        let run = super::train_forward::run_train(&c)?;
        return Ok(Trajectory::of_train(
            run,
            c.wear.coefficient_m2_per_n,
            total_cycles,
        ));
    }
    if future.is_none() && c.load_spectrum.is_none() {
        let model = Model::wear_study_from_case(&c, PROGNOSTICS)?;
        let mut records: Vec<UpdateRecord> = Vec::new();
        let result = run_wear(&model, WearRun::new(WearMode::Dynamic), &mut |run| {
            if let Some(r) = run.records.last() {
                records.push(r.clone());
            }
            Ok(())
        });
        return Ok(traj(records, run_failure(result)));
    }
    let switch = future.map_or(total_cycles, |f| f.from_cycles.clamp(0.0, total_cycles));
    let mut now = c.clone();
    now.wear.total_cycles = switch;
    let sm = SpectrumModel::dynamics_from_case(&now)?;
    let mut records = Vec::new();
    let first = SpectrumRun::new(WearMode::Dynamic, sm.shares.clone());
    let (run, failure) = spectrum_records(&sm, first, &mut records);
    let (Some(f), Some(run), None) = (future, run, &failure) else {
        return Ok(traj(records, failure));
    };
    if switch >= total_cycles {
        return Ok(traj(records, failure));
    }
    let mut then = c.clone();
    then.load_spectrum = Some(f.spectrum.clone());
    let sm = SpectrumModel::dynamics_from_case(&then)?;
    let state = run.last().map(|r| r.wear.clone()).unwrap_or_default();
    // The record at the switch holds the new duty's response and wear rate.
    records.pop();
    let failure = match SpectrumRun::starting_at(&sm, WearMode::Dynamic, state) {
        Ok(start) => spectrum_records(&sm, start, &mut records).1,
        Err(e) => Some(format!("{e:#}")),
    };
    Ok(traj(records, failure))
}

/// Run `start` under `sm`, appending each new update to `records` as a single-point
/// record; the run and why it ended early, if it did.
fn spectrum_records(
    sm: &SpectrumModel,
    start: SpectrumRun,
    records: &mut Vec<UpdateRecord>,
) -> (Option<SpectrumRun>, Option<String>) {
    let mut keep = |run: &SpectrumRun| {
        if let Some(r) = run.records.last() {
            if records.last().map(|x| x.wear.cycles) != Some(r.wear.cycles) {
                records.push(combined_record(run, r, sm.monitoring));
            }
        }
    };
    // A run that starts from a given state has its first record already.
    keep(&start);
    let result = run_spectrum_wear(sm, start, &mut |run| {
        keep(run);
        Ok(())
    });
    match result {
        Err(e) => (None, Some(format!("{e:#}"))),
        Ok(run) => {
            let stop = run.stopped.as_ref().map(|s| s.reason.clone());
            (Some(run), stop)
        }
    }
}

/// Why the condition indicators of a run could not be computed (the case, not the run:
/// a record that fails only ends the indicator's values).
#[derive(Debug, thiserror::Error)]
pub enum IndicatorError {
    /// The case gives no dynamic model.
    #[error("{0}")]
    Model(ModelError),
    /// The case's signal chain cannot be recorded: one problem per entry.
    #[error("{}", .0.join("; "))]
    Chain(Vec<String>),
}

/// Compute the indicators `qs` asks for at every update of `t` (those not there yet), for
/// the run's `case` (at its monitoring bin under a load spectrum). The values stop at the
/// first update whose record fails (the trajectory then reads the indicator as unknown
/// from there on).
pub(crate) fn attach(
    t: &mut Trajectory,
    case: &Case,
    qs: &[Quantity],
) -> Result<(), IndicatorError> {
    let wanted: Vec<u16> = indicators_of(qs)
        .into_iter()
        .filter(|i| !t.indicators.contains_key(name(*i)))
        .collect();
    if wanted.is_empty() || t.records.is_empty() {
        return Ok(());
    }
    // Under a load spectrum the sensor records at the monitoring bin, as the response
    // quantities are read there ([`run_trajectory`]).
    let case = &match &case.load_spectrum {
        Some(s) => case.at_bin(s.monitoring_index()),
        None => case.clone(),
    };
    let model = Model::wear_study_from_case(case, PROGNOSTICS).map_err(IndicatorError::Model)?;
    let mut setup = chain_of(case, None, case.signals.max_input_speed_hz(case))
        .map_err(|p| IndicatorError::Chain(p.messages()))?;
    setup.chain.acquisition.noise = NoiseSpec::None;
    let rows: Vec<Option<Vec<f64>>> = t
        .records
        .par_iter()
        .map(|r| {
            let rec = record_case(&model, &setup, &r.wear).ok()?;
            wanted.iter().map(|i| value(&rec.analysis, *i)).collect()
        })
        .collect();
    let known = rows.iter().take_while(|r| r.is_some()).count();
    for (k, i) in wanted.iter().enumerate() {
        let v = rows[..known].iter().flatten().map(|r| r[k]).collect();
        t.indicators.insert(name(*i).to_owned(), v);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wear::WearState;

    /// Two updates of a two-point profile: point 0 wears 1 nm/cycle, point 1 2 nm/cycle
    /// for 100 cycles, then both 1 nm/cycle.
    fn toy() -> Trajectory {
        let rec = |cycles: f64, h: [f64; 2], inc: [f64; 2], v: f64| UpdateRecord {
            wear: WearState {
                cycles,
                pinion_m: h.to_vec(),
                gear_m: vec![0.0; 2],
                teeth: None,
                slices: None,
            },
            roughness_um: 0.2,
            summary: crate::dynamics::summary::ResponseSummary {
                velocity_y_pinion_rms_m_per_s: v,
                ..Default::default()
            },
            increment_pinion_m: inc.to_vec(),
            increment_gear_m: vec![0.0; 2],
            increment_teeth: None,
            increment_slices: None,
            path_rho1_m: vec![],
            path_load_n: vec![],
            end_state: None,
        };
        Trajectory {
            coefficient_m2_per_n: 1e-16,
            requested_cycles: 300.0,
            records: vec![
                rec(0.0, [0.0, 0.0], [1e-9, 2e-9], 1e-3),
                rec(100.0, [1e-7, 2e-7], [1e-9, 1e-9], 2e-3),
            ],
            failure: None,
            indicators: BTreeMap::new(),
            later_stages: Vec::new(),
            cycle_factors: Vec::new(),
        }
    }

    #[test]
    fn values_between_updates() {
        let t = toy();
        // 50 cycles at 2 nm/cycle: 0.1 um; 200 cycles: 0.2 um + 100 x 1 nm = 0.3 um.
        let w = |c| t.value(Quantity::MaxWearPinion, c).unwrap();
        assert!((w(50.0) - 0.1).abs() < 1e-12 && (w(200.0) - 0.3).abs() < 1e-12);
        // Response: linear between updates (1 mm/s at 0, 2 mm/s at 100 cycles), then that
        // of the last update.
        let v = |c| t.value(Quantity::VelocityRms, c).unwrap();
        assert!((v(25.0) - 1.25).abs() < 1e-12);
        assert_eq!((v(100.0), v(300.0)), (2.0, 2.0));
        assert_eq!(t.value(Quantity::VelocityRms, 301.0), None);
    }

    #[test]
    fn crossing_is_exact_within_a_block() {
        let t = toy();
        // 0.15 um at 2 nm/cycle: 75 cycles; 0.25 um: 100 + 0.05 um / 1 nm = 150 cycles.
        // 1e-9 cycles: far above the rounding of (L - h) / inc, far below one cycle.
        let at = |l| match t.cycles_to_wear(l) {
            Crossing::Reached(c) => c,
            c => panic!("{c:?}"),
        };
        assert!((at(0.15) - 75.0).abs() < 1e-9);
        assert!((at(0.25) - 150.0).abs() < 1e-9);
        // 0.2 + 200 x 1 nm = 0.4 um at the end: 0.5 um is not reached.
        assert_eq!(t.cycles_to_wear(0.5), Crossing::NotReached);
        let mut f = toy();
        f.failure = Some("integrator failed".into());
        assert_eq!(f.cycles_to_wear(0.5), Crossing::Unknown);
        assert_eq!(f.value(Quantity::VelocityRms, 150.0), None);
    }
}
