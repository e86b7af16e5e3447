//! The run budget: before any work starts, estimate a run's memory and time from its case
//! and refuse a run over budget (issue 13).
//!
//! # Formula
//!
//! With S = `numerics.steps_per_mesh_period`, P_e = `numerics.evaluated_mesh_periods`,
//! P_max = `numerics.max_mesh_periods`, N = `stiffness.table_points_per_mesh_period`,
//! G = `wear.points_per_profile`:
//!
//! - one dynamic evaluation integrates S_d (P_c + P_e) steps, with S_d = max(S,
//!   [`adaptive_steps_per_period`]) (the error control adds steps to the S grid nodes
//!   where the dynamics need them; the bound is measured, see the constant), P_c the
//!   periods until steady. P_c is not known before the run: the estimate takes
//!   P_c = min(P_max, [`PERIODS_TO_SETTLE_PER_DECADE`] x log10(1 / tolerance)) (the
//!   built-in case settles in 17-18 periods at 1e-6: 30 leaves margin), and separately
//!   requires that one evaluation that never settles, S (P_max + P_e) steps, fits the
//!   budget (where such a case ends, with an error);
//! - a quasi-static evaluation solves 2 S equilibria;
//! - a wear study makes U = 1 + ceil(C / n) updates (C = `wear.total_cycles`), the block n
//!   being `wear.block_cycles` cut to `wear.threshold_um` / (largest wear per cycle), at
//!   least one cycle (`study::wear_loop::block_length`). The largest wear per cycle is
//!   Archard's k p0 s at the nominal load shared by paper eq. (7), Hertz pressure p0 and
//!   sliding distance s at nominal speeds along the path of contact, times
//!   [`DYNAMIC_WEAR_FACTOR`] for the dynamic mode;
//! - time = 2 N t_table + E_d S (P_c + P_e) t_step + E_q S t_qs + checkpoint writing, with
//!   the rates of the reference machine (2-core AMD EPYC, docs/PERFORMANCE.md):
//!   t_step = 3 us per integrator step (12.5 ms for 4 200 steps), t_qs = 2.4 us,
//!   t_table = 2 us per table point; the checkpoint of each mode gains one record of
//!   (4 G + 4 S_d) numbers, 32 bytes each, per update (an append-only log; docs/RELIABILITY.md)
//!   written at 100 MB/s, plus 2 ms of fsync per update;
//! - a tooth-resolved case (per-tooth inputs) adds one term (`study::teeth_budget::budget_term`):
//!   its excitation repeats over P mesh periods (up to lcm(z1, z2)), so each dynamic
//!   evaluation integrates P - 1 more periods and a run-in, each quasi-static one P - 1
//!   more, a kept response records P periods with its contacts, and each wear record
//!   holds every tooth's profile;
//! - memory = 64 MB + kept responses x S_d P_e x [`BYTES_PER_SAMPLE`] (280 bytes a
//!   recorded sample, with vector growth, the output tables and their CSV text) + per mode U records of
//!   (4 G + 4 S_d) numbers at 8 bytes + for `wear` and `run` the outputs of every record's
//!   profiles, [`OUTPUT_BYTES_PER_PROFILE_POINT`] per grid point (and
//!   [`OUTPUT_SECONDS_PER_PROFILE_POINT`] of time).
//!
//! # Default budget
//!
//! [`Budget::DEFAULT`]: 2 GiB of memory and 600 s (10 minutes) of computing on one core of
//! the reference machine. `--budget-scale X` multiplies both; `--no-budget` drops the
//! check. A sweep checks each case against the budget (its number of cases is the user's
//! explicit choice; it is resumable and shardable).

use super::domain::nominal_contacts;
use super::sweep::plan::{AxisValue, SweepPlan};
use super::sweep::SweepRun;
use crate::config::case::Case;
use crate::config::load::case_with;
use crate::geometry::GearPair;

/// Integrator step on the reference machine, s.
pub const SECONDS_PER_STEP: f64 = 3e-6;
/// Quasi-static equilibria for one step of the grid (two per step), s.
pub const SECONDS_PER_QUASI_STATIC_STEP: f64 = 2.4e-6;
/// One point of the mesh-stiffness table, s.
pub const SECONDS_PER_TABLE_POINT: f64 = 2e-6;
/// Periods to settle per decade of `numerics.steady_state_tolerance`.
pub const PERIODS_TO_SETTLE_PER_DECADE: f64 = 5.0;
/// Recorded samples per mesh period of the dynamic solver at the default integration
/// tolerance 1e-5, bounding its step count from above: measured 662 at 0.5 Hz input
/// (the most: the slow mesh leaves the fast modes to the error control), 230 at 30 Hz,
/// 200 at 300 Hz (the grid nodes). At 1e-7, 1e-8 and 1e-9 the measured counts (2733,
/// 5761, 12412 at 0.5 Hz) stay below this bound's 3250, 7000 and 15080.
pub const ADAPTIVE_STEPS_AT_DEFAULT_TOLERANCE: f64 = 700.0;
/// Bytes of one recorded sample of a dynamic response, with growth, copies and the output
/// tables and their CSV text: measured 1500 for `gearwear dynamics` at 2e4 steps per
/// mesh period (280 of them the response itself); 2000 leaves margin.
pub const BYTES_PER_SAMPLE: f64 = 2000.0;
/// Bytes of one recorded sample of the response alone (280 bytes, doubled for vector
/// growth), without the output tables counted in [`BYTES_PER_SAMPLE`]: the periods a
/// tooth-resolved response records beyond `numerics.evaluated_mesh_periods`
/// (`study::teeth_budget`). Measured peaks of the paper's pair at
/// `teeth.accuracy_grade = 5` (589 periods): `dynamics` 258 MB, `run` 417 MB.
pub const RESPONSE_BYTES_PER_SAMPLE: f64 = 560.0;
/// Dynamic wear per cycle over the quasi-static estimate (dynamic factor margin).
pub const DYNAMIC_WEAR_FACTOR: f64 = 1.5;
/// Memory of the outputs per profile grid point of each wear record (the wear profiles'
/// and Fig. 12's tables, their CSV text and the figure's curves): measured 106-109 bytes
/// (`wear.points_per_profile` = 1e5, 21 and 175 records); 160 leaves margin.
pub const OUTPUT_BYTES_PER_PROFILE_POINT: f64 = 160.0;
/// Time of the outputs per profile grid point of each wear record (four CSV cells and
/// the figure's data), s.
pub const OUTPUT_SECONDS_PER_PROFILE_POINT: f64 = 1e-6;
const GIB: f64 = 1024.0 * 1024.0 * 1024.0;
const BASE_BYTES: f64 = 64e6;
const CHECKPOINT_BYTES_PER_NUMBER: f64 = 32.0;
const DISK_BYTES_PER_S: f64 = 100e6;
const FSYNC_S: f64 = 2e-3;

/// How much a run may use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Budget {
    pub memory_bytes: f64,
    pub seconds: f64,
}

impl Budget {
    /// 2 GiB and 10 minutes on one core of the reference machine.
    pub const DEFAULT: Budget = Budget {
        memory_bytes: 2.0 * GIB,
        seconds: 600.0,
    };

    /// The default budget times `factor` (> 0).
    pub fn scaled(factor: f64) -> Budget {
        Budget {
            memory_bytes: Self::DEFAULT.memory_bytes * factor,
            seconds: Self::DEFAULT.seconds * factor,
        }
    }
}

/// What a command computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Job {
    /// `gearwear stiffness`: the table (twice) and a quasi-static period (over the
    /// excitation period for a tooth-resolved case: the static TE of its teeth).
    Stiffness,
    /// `gearwear dynamics`: one steady-state evaluation.
    Dynamics,
    /// `gearwear wear`: the wear study in the modes named.
    Wear { dynamic: bool, quasi_static: bool },
    /// `gearwear run`: both wear studies and three wear-state evaluations.
    Run,
    /// One case of `gearwear sweep`.
    SweepCase(SweepRun),
}

/// One contribution to a run's cost, with the keys that drive it.
#[derive(Debug, Clone, PartialEq)]
pub struct Term {
    pub what: &'static str,
    pub seconds: f64,
    pub bytes: f64,
    pub keys: &'static [&'static str],
}

/// The estimated cost of a run. See the module docs for the formulas.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// Integrator steps of one evaluation that settles as expected: S (P_c + P_e).
    pub steps_per_evaluation: f64,
    /// Integrator steps of one evaluation that never settles: S (P_max + P_e).
    pub steps_to_give_up: f64,
    /// Samples one dynamic evaluation records: S_d P_e (a bound).
    pub recorded_samples: f64,
    /// Largest wear per cycle at the nominal load (quasi-static), m; None without a pair.
    pub wear_per_cycle_m: Option<f64>,
    /// Updates (records, the first included) of a dynamic and a quasi-static wear study.
    pub wear_updates_dynamic: f64,
    pub wear_updates_quasi_static: f64,
    pub terms: Vec<Term>,
}

impl Estimate {
    pub fn seconds(&self) -> f64 {
        self.terms.iter().map(|t| t.seconds).sum()
    }

    pub fn memory_bytes(&self) -> f64 {
        BASE_BYTES + self.terms.iter().map(|t| t.bytes).sum::<f64>()
    }

    /// Ok, or why the run is over `budget`, naming the keys that drive its cost.
    pub fn check(&self, budget: &Budget) -> Result<(), String> {
        let give_up = self.steps_to_give_up * SECONDS_PER_STEP;
        let (secs, bytes) = (self.seconds(), self.memory_bytes());
        let mut over = Vec::new();
        if bytes > budget.memory_bytes {
            let t = self.largest(|t| t.bytes);
            over.push(format!(
                "memory ~{:.3} GB, over the budget of {:.3} GB; most of it: {} ({:.3} GB), driven by {}",
                bytes / 1e9,
                budget.memory_bytes / 1e9,
                t.what,
                t.bytes / 1e9,
                keys(t.keys)
            ));
        }
        if secs > budget.seconds {
            let t = self.largest(|t| t.seconds);
            over.push(format!(
                "time ~{} on one core of the reference machine, over the budget of {}; most of it: {} ({}), driven by {}",
                duration(secs),
                duration(budget.seconds),
                t.what,
                duration(t.seconds),
                keys(t.keys)
            ));
        }
        if give_up > budget.seconds {
            over.push(format!(
                "one dynamic evaluation that finds no steady state integrates {:.3e} steps (~{}) before giving up, over the budget of {}; driven by `numerics.max_mesh_periods` x `numerics.steps_per_mesh_period`",
                self.steps_to_give_up,
                duration(give_up),
                duration(budget.seconds)
            ));
        }
        if over.is_empty() {
            Ok(())
        } else {
            // The remedy (lower those keys, or raise the budget) names arguments of the
            // front ends: the job layer adds it (`app::budget`).
            Err(format!(
                "the run is over its budget (nothing was computed): {}",
                over.join("; ")
            ))
        }
    }

    fn largest(&self, f: impl Fn(&Term) -> f64) -> &Term {
        self.terms
            .iter()
            .max_by(|a, b| f(a).total_cmp(&f(b)))
            .expect("an estimate has terms")
    }
}

fn keys(k: &[&str]) -> String {
    k.iter()
        .map(|k| format!("`{k}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// "12 s", "3.4 min", "5.1 h", "7.1 days", "2.0e3 days".
fn duration(s: f64) -> String {
    if s < 120.0 {
        format!("{s:.3} s")
    } else if s < 7200.0 {
        format!("{:.1} min", s / 60.0)
    } else if s < 172_800.0 {
        format!("{:.1} h", s / 3600.0)
    } else if s < 8.64e7 {
        format!("{:.1} days", s / 86_400.0)
    } else {
        format!("{:.1e} days", s / 86_400.0)
    }
}

/// Largest Archard wear per pinion cycle on either profile at the nominal load and speeds,
/// m (quasi-static; see the module docs).
pub fn nominal_wear_per_cycle_m(case: &Case, pair: &GearPair) -> f64 {
    let ratio = pair.pinion.teeth as f64 / pair.gear.teeth as f64;
    let k = case.wear.coefficient_m2_per_n;
    nominal_contacts(case, pair, 64)
        .iter()
        .map(|c| {
            let (up, ug) = (
                c.kinematics.pinion_velocity_m_per_s,
                c.kinematics.gear_velocity_m_per_s,
            );
            if !(up > 0.0 && ug > 0.0) {
                return 0.0;
            }
            let slide = 2.0 * c.hertz.half_width_m * (up - ug).abs();
            let p0 = c.hertz.max_pressure_pa;
            (k * p0 * slide / up).max(ratio * k * p0 * slide / ug)
        })
        .fold(0.0, f64::max)
}

/// Updates (records) of a wear study whose largest wear per cycle is `rate_m`.
pub fn wear_updates(case: &Case, rate_m: f64) -> f64 {
    let w = &case.wear;
    let threshold = w.threshold_um * 1e-6;
    let mut block = w.block_cycles;
    if rate_m > 0.0 && block * rate_m > threshold {
        block = (threshold / rate_m).floor().max(1.0);
    }
    1.0 + (w.total_cycles / block).ceil()
}

/// Most bytes a checkpoint of `mode` can hold for `case`, so that a checkpoint file is
/// never read beyond what the run could have written: 16 times the estimated number of
/// updates (the estimate takes the nominal load; a run's actual updates stay well within
/// that margin) of (4 G + 4 S_d) numbers at [`CHECKPOINT_BYTES_PER_NUMBER`] bytes, and at
/// least 64 MiB.
pub fn max_checkpoint_bytes(case: &Case, mode: crate::study::wear_loop::WearMode) -> u64 {
    use crate::study::wear_loop::WearMode;
    let dynamic = mode == WearMode::Dynamic;
    let e = estimate(
        case,
        Job::Wear {
            dynamic,
            quasi_static: !dynamic,
        },
    );
    let updates = if dynamic {
        e.wear_updates_dynamic
    } else {
        e.wear_updates_quasi_static
    };
    let s_dyn = (case.numerics.steps_per_mesh_period as f64).max(adaptive_steps_per_period(
        case.numerics.integration_tolerance,
    ));
    let numbers = 4.0 * case.wear.points_per_profile as f64 + 4.0 * s_dyn;
    let bytes = 16.0 * updates * numbers * CHECKPOINT_BYTES_PER_NUMBER;
    bytes.clamp(64.0 * 1024.0 * 1024.0, 1e15) as u64
}

/// How much more a dynamic evaluation of a gear train costs than one of a single pair
/// (1 for a case without `[[stage]]`): its base period (`dynamics::grid::base_period`)
/// holds sum_k N_k mesh periods of its meshes, each with its events and steps, and each
/// step costs about (states / 16) times the single pair's (a right-hand side per mesh,
/// linear algebra on the larger state). A train whose base period cannot be counted is
/// infinitely dear (refused).
pub fn train_factor(case: &Case) -> f64 {
    if case.stage.is_empty() {
        return 1.0;
    }
    let teeth: Vec<[usize; 2]> = case
        .stage
        .iter()
        .map(|s| {
            let g = s.gear_section(&case.gear);
            [g.teeth_pinion.max(1) as usize, g.teeth_gear.max(1) as usize]
        })
        .collect();
    let states = 4.0 + 12.0 * teeth.len() as f64;
    match crate::dynamics::grid::chain_mesh_counts(&teeth) {
        Some(counts) => counts.iter().map(|c| *c as f64).sum::<f64>() * (states / 16.0).max(1.0),
        None => f64::INFINITY,
    }
}

/// Steps per mesh period the error control of the dynamic solver takes, at most, at the
/// local error tolerance `tol` (dimensionless): [`ADAPTIVE_STEPS_AT_DEFAULT_TOLERANCE`]
/// x (1e-5 / tol)^(1/3), the step of a third-order method scaling as tol^(1/3).
pub fn adaptive_steps_per_period(tol: f64) -> f64 {
    ADAPTIVE_STEPS_AT_DEFAULT_TOLERANCE * (1e-5 / tol).cbrt()
}

/// Estimate the cost of `job` on `case` (validated). Cheap: the geometry and a few dozen
/// Hertz contacts, no model.
pub fn estimate(case: &Case, job: Job) -> Estimate {
    let nm = &case.numerics;
    let s = nm.steps_per_mesh_period as f64;
    // Dynamic evaluations: the error control may add steps to the grid nodes.
    let s_dyn = s.max(adaptive_steps_per_period(nm.integration_tolerance));
    let p_e = nm.evaluated_mesh_periods as f64;
    let p_max = nm.max_mesh_periods as f64;
    let p_c = p_max
        .min((PERIODS_TO_SETTLE_PER_DECADE * (1.0 / nm.steady_state_tolerance).log10()).max(2.0));
    let table = case.stiffness.table_points_per_mesh_period as f64;
    let grid = case.wear.points_per_profile as f64;
    // Under a load spectrum each bin has its model (and table), every update evaluates
    // every bin, and the block is cut on the spectrum's wear per cycle, bounded by
    // sum_i s_i (each bin's largest).
    let bins = case
        .load_spectrum
        .as_ref()
        .map_or(1.0, |s| s.bins.len() as f64);
    let rate = GearPair::from_case(&case.gear)
        .ok()
        .map(|pair| match &case.load_spectrum {
            Some(s) => s
                .bins
                .iter()
                .enumerate()
                .map(|(i, b)| b.share * nominal_wear_per_cycle_m(&case.at_bin(i), &pair))
                .sum(),
            None => nominal_wear_per_cycle_m(case, &pair),
        });
    let r = rate.unwrap_or(0.0);
    let (u_d, u_q) = (
        wear_updates(case, DYNAMIC_WEAR_FACTOR * r),
        wear_updates(case, r),
    );
    let (dynamic_modes, quasi_modes, extra_evals, kept) = match job {
        Job::Stiffness => (0.0, 0.0, 0.0, 0.0),
        Job::Dynamics | Job::SweepCase(SweepRun::Dynamics) => (0.0, 0.0, 1.0, 1.0),
        Job::Wear {
            dynamic,
            quasi_static,
        } => (
            f64::from(u8::from(dynamic)),
            f64::from(u8::from(quasi_static)),
            0.0,
            2.0,
        ),
        Job::Run => (1.0, 1.0, 3.0, 5.0),
        Job::SweepCase(SweepRun::Wear) => (1.0, 1.0, 0.0, 2.0),
    };
    // The bins' responses of an update are in memory together.
    let kept = if dynamic_modes > 0.0 {
        kept * bins
    } else {
        kept
    };
    let (dynamic_modes, quasi_modes) = (dynamic_modes * bins, quasi_modes * bins);
    // `run` under a spectrum adds the life table: a run to the wear limit under the
    // spectrum (every bin) and one at each bin alone, blocks cut by the threshold only.
    let extra_evals = match (&case.load_spectrum, job) {
        (Some(s), Job::Run) => {
            let per_run = (s.life_wear_limit_um / case.wear.threshold_um).ceil() + 1.0;
            extra_evals + 2.0 * bins * per_run
        }
        _ => extra_evals,
    };
    let checkpoints = matches!(job, Job::Wear { .. } | Job::Run);
    let record_numbers = 4.0 * grid + 4.0 * s_dyn;
    let mut terms = vec![Term {
        what: "the mesh-stiffness table",
        seconds: 2.0 * table * SECONDS_PER_TABLE_POINT * bins,
        bytes: 16.0 * table,
        keys: &["stiffness.table_points_per_mesh_period"],
    }];
    let evals = dynamic_modes * u_d + extra_evals;
    if evals > 0.0 {
        terms.push(Term {
            what: "the dynamic evaluations",
            seconds: evals * s_dyn * (p_c + p_e) * SECONDS_PER_STEP * train_factor(case),
            bytes: 0.0,
            keys: if dynamic_modes > 0.0 {
                &[
                    "numerics.steps_per_mesh_period",
                    "wear.total_cycles",
                    "wear.block_cycles",
                    "wear.threshold_um",
                    "wear.coefficient_m2_per_n",
                    "load_spectrum.bins",
                ]
            } else {
                &[
                    "numerics.steps_per_mesh_period",
                    "numerics.steady_state_tolerance",
                ]
            },
        });
    }
    if kept > 0.0 {
        terms.push(Term {
            what: "the recorded signals",
            seconds: 0.0,
            bytes: kept * s_dyn * p_e * BYTES_PER_SAMPLE * train_factor(case),
            keys: &[
                "numerics.evaluated_mesh_periods",
                "numerics.steps_per_mesh_period",
            ],
        });
    }
    // The stiffness command's table holds 720 equilibria, 360 steps' worth.
    let quasi_steps = quasi_modes * u_q * s + if job == Job::Stiffness { 360.0 } else { 0.0 };
    if quasi_steps > 0.0 {
        terms.push(Term {
            what: "the quasi-static evaluations",
            seconds: quasi_steps * SECONDS_PER_QUASI_STATIC_STEP,
            bytes: 0.0,
            keys: &[
                "wear.total_cycles",
                "wear.block_cycles",
                "wear.threshold_um",
                "wear.coefficient_m2_per_n",
            ],
        });
    }
    let modes_updates = [(dynamic_modes, u_d), (quasi_modes, u_q)];
    let records: f64 = modes_updates.iter().map(|(m, u)| m * u).sum();
    if records > 0.0 {
        terms.push(Term {
            what: "the wear records",
            seconds: 0.0,
            bytes: records * record_numbers * 8.0,
            keys: &[
                "wear.points_per_profile",
                "numerics.steps_per_mesh_period",
                "wear.total_cycles",
                "wear.block_cycles",
                "wear.threshold_um",
                "wear.coefficient_m2_per_n",
            ],
        });
    }
    if checkpoints && records > 0.0 {
        // `wear` and `run` write the profiles of every record (and Python's wear and run
        // build the same tables).
        let points = records * grid;
        terms.push(Term {
            what: "the wear profiles' tables and figures",
            seconds: points * OUTPUT_SECONDS_PER_PROFILE_POINT,
            bytes: points * OUTPUT_BYTES_PER_PROFILE_POINT,
            keys: &[
                "wear.points_per_profile",
                "wear.threshold_um",
                "wear.block_cycles",
                "wear.total_cycles",
            ],
        });
        let written = records * record_numbers * CHECKPOINT_BYTES_PER_NUMBER;
        terms.push(Term {
            what: "writing the checkpoints",
            seconds: written / DISK_BYTES_PER_S + records * FSYNC_S,
            bytes: 0.0,
            keys: &[
                "wear.total_cycles",
                "wear.block_cycles",
                "wear.threshold_um",
                "wear.coefficient_m2_per_n",
                "wear.points_per_profile",
            ],
        });
    }
    // `stiffness` of a tooth-resolved case adds the static TE of its teeth: one
    // quasi-static evaluation over the excitation period, kept for its table.
    let stiffness_te = if job == Job::Stiffness { 1.0 } else { 0.0 };
    terms.extend(super::teeth_budget::budget_term(
        case,
        evals,
        quasi_modes * u_q + stiffness_te,
        kept + stiffness_te,
        records,
        s_dyn,
        s,
    ));
    Estimate {
        steps_per_evaluation: s_dyn * (p_c + p_e),
        steps_to_give_up: if evals > 0.0 {
            s_dyn * (p_max + p_e)
        } else {
            0.0
        },
        recorded_samples: s_dyn * p_e,
        wear_per_cycle_m: rate,
        wear_updates_dynamic: u_d,
        wear_updates_quasi_static: u_q,
        terms,
    }
}

/// Values of an axis at which a sweep's cost is sampled: the first and last, the
/// numerically smallest and largest, and up to [`SAMPLED_VALUES`] spread between, so that
/// estimating a sweep costs milliseconds however many values an axis has.
pub const SAMPLED_VALUES: usize = 8;

fn sampled_indices(values: &[AxisValue]) -> Vec<usize> {
    let n = values.len();
    if n == 0 {
        return Vec::new();
    }
    let mut idx: std::collections::BTreeSet<usize> = (0..SAMPLED_VALUES.min(n))
        .map(|i| i * (n - 1) / (SAMPLED_VALUES - 1).max(1))
        .collect();
    idx.insert(n - 1);
    let num = |v: &AxisValue| {
        v.value
            .as_float()
            .or_else(|| v.value.as_integer().map(|i| i as f64))
    };
    let numbered: Vec<(usize, f64)> = (0..n)
        .filter_map(|i| num(&values[i]).map(|x| (i, x)))
        .collect();
    if let Some(lo) = numbered.iter().min_by(|a, b| a.1.total_cmp(&b.1)) {
        idx.insert(lo.0);
    }
    if let Some(hi) = numbered.iter().max_by(|a, b| a.1.total_cmp(&b.1)) {
        idx.insert(hi.0);
    }
    idx.into_iter().collect()
}

/// The estimated cost of `sweep-merge` of tables of `bytes` in all: the text, the rows
/// parsed (their values as text and numbers) and the merged table's CSV, about four times
/// the text.
pub fn estimate_sweep_merge(bytes: u64) -> Estimate {
    Estimate {
        steps_per_evaluation: 0.0,
        steps_to_give_up: 0.0,
        recorded_samples: 0.0,
        wear_per_cycle_m: None,
        wear_updates_dynamic: 0.0,
        wear_updates_quasi_static: 0.0,
        terms: vec![Term {
            what: "the tables read and merged",
            seconds: bytes as f64 * 2e-8,
            bytes: 4.0 * bytes as f64,
            keys: &["the size of the tables merged"],
        }],
    }
}

/// The estimated cost of `load-spectrum` on a history of `bytes` of text: read, parsed
/// into its columns and counted in one pass, about three times the text in memory, and
/// 2e-8 s a byte (a 1e6-sample history, about 30 MB of text, counts in 0.39 s:
/// docs/PERFORMANCE.md, duty-cycle benchmark).
pub fn estimate_history(bytes: u64) -> Estimate {
    Estimate {
        steps_per_evaluation: 0.0,
        steps_to_give_up: 0.0,
        recorded_samples: 0.0,
        wear_per_cycle_m: None,
        wear_updates_dynamic: 0.0,
        wear_updates_quasi_static: 0.0,
        terms: vec![Term {
            what: "the history read and counted",
            seconds: bytes as f64 * 2e-8,
            bytes: 3.0 * bytes as f64,
            keys: &["the size of the history"],
        }],
    }
}

/// Memory a sweep holds per case besides the cases in flight: the resolved case, its
/// record and its row, bytes.
pub const BYTES_PER_SWEEP_CASE: f64 = 16e3;

/// What a sweep's estimate found.
#[derive(Debug, Clone)]
pub struct SweepEstimate {
    /// The sweep as one job: every case of the shard, one after the other (time), and the
    /// cases in flight on `threads` threads plus the records (memory).
    pub total: Estimate,
    /// One case with every axis at its costliest sampled value, and its overrides.
    pub worst_case: Estimate,
    pub worst_overrides: Vec<String>,
}

/// Estimate a sweep of `cases` cases (those of its shard) over `axes` (key, values) on
/// `threads` threads without resolving every case: `load(overrides)` gives the case of a
/// set of overrides (None when it does not load: the sweep reports those itself). The
/// cost per case is sampled at a few values of each axis (the others at the base case);
/// the total is the base cost times, per axis, the mean ratio of its sampled values to the
/// base (exact when the cost does not depend on a varied key, and when it is a product of
/// per-axis factors); the worst case puts every axis at its costliest sampled value.
pub fn estimate_sweep(
    base: &Case,
    plan: &SweepPlan,
    job: Job,
    cases: usize,
    threads: usize,
) -> Option<SweepEstimate> {
    let load = |settings: &[(&str, toml::Value)]| case_with(base, settings).ok();
    let base_e = estimate(&load(&[])?, job);
    let (base_s, base_b) = (base_e.seconds().max(1e-9), base_e.memory_bytes());
    let mut ratio = 1.0;
    let mut worst: Vec<(&str, toml::Value)> = Vec::new();
    let mut worst_overrides = Vec::new();
    for axis in &plan.axes {
        let mut sum = 0.0;
        let mut n = 0.0;
        let mut costliest: Option<(f64, usize)> = None;
        for i in sampled_indices(&axis.values) {
            let Some(c) = load(&[(axis.key, axis.values[i].value.clone())]) else {
                continue;
            };
            let e = estimate(&c, job);
            let cost = e.seconds() / base_s + e.memory_bytes() / base_b;
            sum += e.seconds() / base_s;
            n += 1.0;
            if costliest.as_ref().is_none_or(|(c0, _)| cost > *c0) {
                costliest = Some((cost, i));
            }
        }
        if n > 0.0 {
            ratio *= sum / n;
        }
        if let Some((_, i)) = costliest {
            worst.push((axis.key, axis.values[i].value.clone()));
            worst_overrides.push(format!("{}={}", axis.key, axis.values[i].label));
        }
    }
    let worst_case = estimate(&load(&worst).or_else(|| load(&[]))?, job);
    let cases_f = cases as f64;
    let in_flight = (threads.max(1) as f64).min(cases_f);
    let total = Estimate {
        terms: vec![
            Term {
                what: "the sweep's cases, one after the other",
                seconds: cases_f * base_s * ratio,
                bytes: 0.0,
                keys: &["the number of cases of the shard", "the varied keys"],
            },
            Term {
                what: "the cases in flight, and every case's record",
                seconds: 0.0,
                bytes: in_flight * (worst_case.memory_bytes() - BASE_BYTES)
                    + cases_f * BYTES_PER_SWEEP_CASE,
                keys: &["the number of cases of the shard", "the varied keys"],
            },
        ],
        steps_to_give_up: worst_case.steps_to_give_up,
        ..worst_case.clone()
    };
    Some(SweepEstimate {
        total,
        worst_case,
        worst_overrides,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::load_case;

    fn case(sets: &[&str]) -> Case {
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        load_case("", &sets).unwrap()
    }

    #[test]
    fn built_in_runs_fit_the_default_budget() {
        let c = Case::default();
        for job in [
            Job::Stiffness,
            Job::Dynamics,
            Job::Run,
            Job::Wear {
                dynamic: true,
                quasi_static: true,
            },
            Job::SweepCase(SweepRun::Wear),
        ] {
            let e = estimate(&c, job);
            e.check(&Budget::DEFAULT).unwrap();
            // The built-in run takes ~0.3 s (docs/PERFORMANCE.md): the estimate is an
            // upper bound of the right order.
            assert!(e.seconds() < 20.0, "{job:?}: {}", e.seconds());
        }
    }

    #[test]
    fn every_bin_of_a_spectrum_is_counted() {
        // Ten bins at the operating point (shares 0.1): the same wear rate and updates,
        // ten times the evaluations.
        let one = estimate(&Case::default(), Job::Run);
        let bins = ["{torque_nm = 60, input_speed_hz = 30, share = 0.1}"; 10].join(", ");
        let ten = load_case(&format!("[load_spectrum]\nbins = [{bins}]\n"), &[]).unwrap();
        let e = estimate(&ten, Job::Run);
        assert!((e.wear_per_cycle_m.unwrap() / one.wear_per_cycle_m.unwrap() - 1.0).abs() < 1e-12);
        assert_eq!(e.wear_updates_dynamic, one.wear_updates_dynamic);
        let dyn_s = |e: &Estimate| {
            e.terms
                .iter()
                .find(|t| t.what == "the dynamic evaluations")
                .unwrap()
                .seconds
        };
        // Run: 1 wear study of U updates plus 3 wear states; ten bins: 10 U + 3, and the
        // life runs: 10 bins under the spectrum and 10 alone, 10 um / 0.5 um + 1 updates.
        let u = one.wear_updates_dynamic;
        let ratio = dyn_s(&e) / dyn_s(&one);
        let want = (10.0 * u + 3.0 + 20.0 * 21.0) / (u + 3.0);
        assert!((ratio - want).abs() < 1e-12, "{ratio} {want}");
        // A long spectrum over the budget names the bins.
        let many = vec!["{torque_nm = 60, input_speed_hz = 30, share = 0.0001}"; 10_000].join(", ");
        let big = load_case(
            &format!("[load_spectrum]\nbins = [{many}]\n"),
            &["wear.total_cycles=1e6".into()],
        )
        .unwrap();
        let msg = estimate(&big, Job::Run)
            .check(&Budget::DEFAULT)
            .unwrap_err();
        assert!(msg.contains("load_spectrum.bins"), "{msg}");
    }

    #[test]
    fn issue_13_values_are_refused_naming_their_keys() {
        for (sets, job, key) in [
            (
                vec!["numerics.steps_per_mesh_period=1e6"],
                Job::Dynamics,
                "numerics.steps_per_mesh_period",
            ),
            (
                vec!["numerics.evaluated_mesh_periods=1e5"],
                Job::Dynamics,
                "numerics.evaluated_mesh_periods",
            ),
            (
                vec!["wear.total_cycles=1e11"],
                Job::Run,
                "wear.total_cycles",
            ),
            (vec!["wear.block_cycles=1"], Job::Run, "wear.block_cycles"),
            (
                vec!["wear.threshold_um=1e-3", "wear.total_cycles=1e6"],
                Job::Run,
                "wear.threshold_um",
            ),
            (
                vec!["wear.coefficient_m2_per_n=1e-11"],
                Job::Run,
                "wear.coefficient_m2_per_n",
            ),
            (
                vec![
                    "numerics.max_mesh_periods=1e6",
                    "numerics.steady_state_tolerance=1e-12",
                ],
                Job::Dynamics,
                "numerics.max_mesh_periods",
            ),
            (
                vec!["wear.points_per_profile=1e5", "wear.block_cycles=20"],
                Job::Wear {
                    dynamic: false,
                    quasi_static: true,
                },
                "wear.points_per_profile",
            ),
        ] {
            let e = estimate(&case(&sets), job)
                .check(&Budget::DEFAULT)
                .expect_err(&format!("{sets:?}"));
            assert!(
                e.contains(key) && e.contains("over its budget"),
                "{sets:?}: {e}"
            );
        }
        // A budget raised knowingly lets a refused run through.
        let big = estimate(&case(&["wear.block_cycles=100"]), Job::Run);
        assert!(big.check(&Budget::scaled(1e-3)).is_err());
        assert!(big.check(&Budget::DEFAULT).is_ok());
    }
}
