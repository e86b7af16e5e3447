//! The cost of the commands that run one case: `stiffness`, `dynamics`, `wear`, `run` and
//! one case of a sweep; and the most a wear checkpoint can hold.
//!
//! # Formula
//!
//! With S = `numerics.steps_per_mesh_period`, P_e = `numerics.evaluated_mesh_periods`,
//! P_max = `numerics.max_mesh_periods`, N = `stiffness.table_points_per_mesh_period`,
//! G = `wear.points_per_profile`:
//!
//! - one dynamic evaluation integrates at most S_d (P_c + P_e) steps, with S_d = max(S,
//!   [`adaptive_steps_per_period`](super::evaluation::adaptive_steps_per_period)) (the
//!   error control adds steps to the S grid nodes where the dynamics need them; the bound
//!   is measured, see the constant), P_c = min(P_max, [`PERIODS_TO_SETTLE_PER_DECADE`]
//!   x log10(1 / tolerance)) the periods until steady (a bound: 30 at 1e-6): the
//!   estimate's step counts, and one evaluation that never settles, S_d (P_max + P_e)
//!   steps, must fit the budget (where such a case ends, with an error). Their time is
//!   counted by [`super::steady_states`]: each wear study's first update, `dynamics` and the wear
//!   states of `run` a cold search (a few periods), every later update warm (one or two),
//!   each period at its measured CPU time at the case's speed and numerics;
//! - a quasi-static evaluation solves 2 S equilibria;
//! - a wear study makes U = 1 + ceil(C / n) updates (C = `wear.total_cycles`), the block n
//!   being `wear.block_cycles` cut to `wear.threshold_um` / (largest wear per cycle), at
//!   least one cycle (`study::wear_loop::block_length`). The largest wear per cycle is
//!   Archard's k p0 s at the nominal load shared by paper eq. (7), Hertz pressure p0 and
//!   sliding distance s at nominal speeds along the path of contact, times
//!   [`DYNAMIC_WEAR_FACTOR`] for the dynamic mode;
//! - time = 2 N t_table + the dynamic evaluations ([`super::steady_states`]) + E_q S
//!   t_qs + checkpoint writing, with the rates of the reference machine (2-core AMD EPYC,
//!   docs/PERFORMANCE.md): t_qs = 2.4 us,
//!   t_table = 2 us per table point; the checkpoint of each mode gains one record of
//!   (4 G + 4 S_d) numbers, 32 bytes each, per update (an append-only log;
//!   docs/RELIABILITY.md) written at 100 MB/s, plus 2 ms of fsync per update;
//! - a tooth-resolved case adds [`super::teeth::budget_term`]: its excitation repeats over
//!   P mesh periods (up to lcm(z1, z2)), integrated and recorded with its contacts by every
//!   evaluation, and each wear record holds every tooth's profile;
//! - memory = the baseline + kept responses x S_d P_e x [`BYTES_PER_SAMPLE`] (a train:
//!   whole base periods, `recorded_periods`) + U records of (4 G + 4 S_d) doubles a mode +
//!   the profiles' outputs ([`OUTPUT_BYTES_PER_PROFILE_POINT`] a grid point).
//!
//! Under a load spectrum each bin has its model (and table), every update evaluates every
//! bin, and the block is cut on the spectrum's wear per cycle.

use super::cost::{Estimate, Term};
use super::evaluation::{
    dynamic_steps_per_period, nominal_wear_per_cycle_m, recorded_periods, train_record_factor,
    wear_updates, DYNAMIC_WEAR_FACTOR, PERIODS_TO_SETTLE_PER_DECADE, SECONDS_PER_QUASI_STATIC_STEP,
    SECONDS_PER_TABLE_POINT,
};
use crate::config::case::Case;
use crate::config::paper_case::runs_contact_twin;
use crate::geometry::GearPair;
use crate::study::sweep::SweepRun;
use crate::study::wear_loop::WearMode;

/// Bytes of one recorded sample of a dynamic response, with growth, copies and the output
/// tables and their CSV text: measured 1500 for `gearwear dynamics` at 2e4 steps per
/// mesh period (280 of them the response itself); 2000 leaves margin.
pub const BYTES_PER_SAMPLE: f64 = 2000.0;
/// Memory of the outputs per profile grid point of each wear record (the wear profiles'
/// and Fig. 12's tables, their CSV text and the figure's curves): measured 106-109 bytes
/// (`wear.points_per_profile` = 1e5, 21 and 175 records); 160 leaves margin.
pub const OUTPUT_BYTES_PER_PROFILE_POINT: f64 = 160.0;
/// Time of the outputs per profile grid point of each wear record (four CSV cells and
/// the figure's data), s.
pub const OUTPUT_SECONDS_PER_PROFILE_POINT: f64 = 1e-6;
const CHECKPOINT_BYTES_PER_NUMBER: f64 = 32.0;
const DISK_BYTES_PER_S: f64 = 100e6;
const FSYNC_S: f64 = 2e-3;

/// What a command computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Job {
    /// `gearwear stiffness`: the table (twice) and a quasi-static period (over the
    /// excitation period for a tooth-resolved case: the static TE of its teeth).
    Stiffness,
    /// `gearwear dynamics`: one steady-state evaluation.
    Dynamics,
    /// `gearwear wear`: the wear study in the modes named.
    Wear {
        /// With the dynamic solver.
        dynamic: bool,
        /// With the quasi-static solver.
        quasi_static: bool,
    },
    /// `gearwear run`: both wear studies and three wear-state evaluations.
    Run,
    /// One case of `gearwear sweep`.
    SweepCase(SweepRun),
}

/// Steps per mesh period and mesh periods of one evaluation of a case (module docs).
struct Periods {
    /// Steps of a quasi-static period (the grid, S) and of a dynamic one (S_d).
    s: f64,
    s_dyn: f64,
    /// Evaluated periods P_e, the most P_max, and those taken to settle P_c.
    p_e: f64,
    p_max: f64,
    p_c: f64,
}

impl Periods {
    fn of(case: &Case) -> Self {
        let nm = &case.numerics;
        let p_max = nm.max_mesh_periods as f64;
        let settle = PERIODS_TO_SETTLE_PER_DECADE * (1.0 / nm.steady_state_tolerance).log10();
        Self {
            s: nm.steps_per_mesh_period as f64,
            s_dyn: dynamic_steps_per_period(nm),
            p_e: nm.evaluated_mesh_periods as f64,
            p_max,
            p_c: p_max.min(settle.max(2.0)),
        }
    }
}

/// What a job evaluates besides its wear updates: the wear studies it runs (a mode per
/// bin of a load spectrum), the dynamic evaluations beyond them, and the responses kept
/// in memory at once.
struct Work {
    dynamic_modes: f64,
    quasi_modes: f64,
    extra_evals: f64,
    /// Of `extra_evals`, the cold ones (the job's own evaluations and each life run's
    /// first update); the rest are the life runs' warm updates.
    extra_cold: f64,
    kept: f64,
    /// Of `extra_evals`, the updates of the life table's runs under a spectrum, and
    /// whether they run the dynamic mode (`run`, or `wear` with it) or the quasi-static.
    life_updates: f64,
    life_dynamic: bool,
}

impl Work {
    fn of(case: &Case, job: Job, bins: f64) -> Self {
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
            // The paper's case runs its study again under the other contact model for the
            // comparison (`config::paper_case::runs_contact_twin`), after the first.
            Job::Run if runs_contact_twin(case) => (2.0, 2.0, 6.0, 5.0),
            // A helical pair's run adds the steady state of its new teeth to the three
            // wear states (`app::run_helical`), all four kept together in its report.
            Job::Run if case.gear.helix_angle_deg != 0.0 => (1.0, 1.0, 4.0, 6.0),
            Job::Run => (1.0, 1.0, 3.0, 5.0),
            Job::SweepCase(SweepRun::Wear) => (1.0, 1.0, 0.0, 2.0),
        };
        // The bins' responses of an update are in memory together.
        let kept = if dynamic_modes > 0.0 {
            kept * bins
        } else {
            kept
        };
        // `run` and `wear` under a spectrum add the life table: a run to the wear limit
        // under the spectrum (every bin) and one at each bin alone, blocks cut by the
        // threshold only. A train's lives are read from its run itself (`duty::train_life`).
        let (life_runs, life_updates) = match (&case.load_spectrum, job) {
            (Some(s), Job::Run | Job::Wear { .. }) if case.stage.is_empty() => {
                let per_run = (s.life_wear_limit_um / case.wear.threshold_um).ceil() + 1.0;
                (2.0 * bins, 2.0 * bins * per_run)
            }
            _ => (0.0, 0.0),
        };
        Self {
            dynamic_modes: dynamic_modes * bins,
            quasi_modes: quasi_modes * bins,
            extra_evals: extra_evals + life_updates,
            extra_cold: extra_evals + life_runs,
            kept,
            life_updates,
            life_dynamic: dynamic_modes > 0.0,
        }
    }
}

/// Largest wear per cycle at the nominal load, m (quasi-static; None without a pair):
/// under a load spectrum the bins' rates weighted by their shares, bounded by sum_i s_i
/// (each bin's largest).
fn nominal_wear_rate_m(case: &Case) -> Option<f64> {
    GearPair::from_case(&case.gear)
        .ok()
        .map(|pair| match &case.load_spectrum {
            Some(s) => s
                .bins
                .iter()
                .enumerate()
                .map(|(i, b)| b.share * nominal_wear_per_cycle_m(&case.at_bin(i), &pair))
                .sum(),
            None => nominal_wear_per_cycle_m(case, &pair),
        })
}

/// The counts an estimate's terms follow from.
struct Counts {
    periods: Periods,
    work: Work,
    /// Bins of the load spectrum (1 without one).
    bins: f64,
    /// Updates of a dynamic and of a quasi-static wear study.
    u_d: f64,
    u_q: f64,
    /// Dynamic evaluations, and wear records over every mode.
    evals: f64,
    records: f64,
    /// Of `evals`, the cold ones (from the static equilibrium) and the warm ones
    /// ([`super::steady_states`]).
    cold: f64,
    warm: f64,
}

/// Estimate the cost of `job` on `case` (validated). Cheap: the geometry and a few dozen
/// Hertz contacts, no model (but a planetary set's wear sweep case: its set's model and
/// first quasi-static response, milliseconds, `planetary::sweep_wear_estimate`).
pub fn estimate(case: &Case, job: Job) -> Estimate {
    // A planetary set's wear sweep case runs the set's own wear study (its model is built
    // here: milliseconds, one quasi-static response for its first wear rate).
    if job == Job::SweepCase(SweepRun::Wear) {
        if let Some(e) = super::planetary::sweep_wear_estimate(case) {
            return e;
        }
    }
    let periods = Periods::of(case);
    let bins = case
        .load_spectrum
        .as_ref()
        .map_or(1.0, |s| s.bins.len() as f64);
    let rate = nominal_wear_rate_m(case);
    let r = rate.unwrap_or(0.0);
    let (u_d, u_q) = (
        wear_updates(case, DYNAMIC_WEAR_FACTOR * r),
        wear_updates(case, r),
    );
    let work = Work::of(case, job, bins);
    let evals = work.dynamic_modes * u_d + work.extra_evals;
    // Each wear study's first update is cold, the others warm; so are a life run's.
    let cold = work.dynamic_modes + work.extra_cold;
    let warm = work.dynamic_modes * (u_d - 1.0) + (work.extra_evals - work.extra_cold);
    let modes_updates = [(work.dynamic_modes, u_d), (work.quasi_modes, u_q)];
    let records: f64 = modes_updates.iter().map(|(m, u)| m * u).sum();
    let c = Counts {
        periods,
        work,
        bins,
        u_d,
        u_q,
        evals,
        records,
        cold,
        warm,
    };
    let mut terms = evaluation_terms(case, job, &c);
    terms.extend(record_terms(case, job, &c));
    terms.extend(model_terms(case, job, &c));
    let p = &c.periods;
    Estimate {
        steps_per_evaluation: p.s_dyn * (p.p_c + p.p_e),
        steps_to_give_up: if c.evals > 0.0 {
            p.s_dyn * (p.p_max + p.p_e)
        } else {
            0.0
        },
        recorded_samples: p.s_dyn * p.p_e,
        wear_per_cycle_m: rate,
        wear_updates_dynamic: c.u_d,
        wear_updates_quasi_static: c.u_q,
        terms,
        figures_drawn: figures_of(case, job),
    }
}

/// The PNG figures `job` draws on `case` ([`super::figures`]); none for a sweep's case
/// (the sweep's own figures are drawn once, after its cases: `super::sweep`).
fn figures_of(case: &Case, job: Job) -> Option<super::cost::FigureCount> {
    use super::figures as f;
    Some(match job {
        Job::Stiffness => f::stiffness_figures(case),
        Job::Dynamics => f::dynamics_figures(case),
        Job::Wear {
            dynamic,
            quasi_static,
        } => f::wear_figures(case, u32::from(dynamic) + u32::from(quasi_static)),
        Job::Run => f::run_figures(case),
        Job::SweepCase(_) => super::cost::FigureCount::default(),
    })
}

/// The terms of the model's parts beyond the pair's evaluations: the stiffness outputs,
/// the teeth of a tooth-resolved case or train, a planetary set's faulty member and a
/// helical pair's slices and lines.
fn model_terms(case: &Case, job: Job, c: &Counts) -> Vec<Term> {
    let mut terms = Vec::new();
    let p = &c.periods;
    // `stiffness` of a tooth-resolved case adds the static TE of its teeth: one
    // quasi-static evaluation over the excitation period, kept for its table.
    let stiffness_te = if job == Job::Stiffness { 1.0 } else { 0.0 };
    if job == Job::Stiffness {
        terms.push(super::output::stiffness_output_term(
            case,
            super::teeth::faulty_train_stages(case),
        ));
    }
    if job == Job::Stiffness && !case.stage.is_empty() {
        terms.extend(super::teeth::train_stiffness_term(case, p.s));
    } else {
        terms.extend(super::teeth::budget_term(
            case,
            (c.evals, c.work.quasi_modes * c.u_q + stiffness_te),
            c.work.kept + stiffness_te,
            c.records,
            (p.s_dyn, p.s),
            super::steady_states::period_seconds(case),
        ));
    }
    terms.extend(super::planetary::fault_term(
        case,
        c.evals,
        c.work.kept,
        p.s_dyn,
    ));
    terms.extend(super::helical::tooth_lines_term(case));
    if matches!(
        job,
        Job::Wear { .. } | Job::Run | Job::SweepCase(SweepRun::Wear)
    ) {
        // A helical pair's life runs under a spectrum spread their slices too.
        let w = &c.work;
        let life = |dynamic: bool| {
            if w.life_dynamic == dynamic {
                w.life_updates
            } else {
                0.0
            }
        };
        terms.extend(super::helical::budget_term(
            case,
            matches!(job, Job::Wear { .. } | Job::Run),
            (
                w.dynamic_modes * c.u_d + life(true),
                w.quasi_modes * c.u_q + life(false),
            ),
            c.records,
            (p.s_dyn, p.s),
            super::steady_states::samples_per_period(case),
            (CHECKPOINT_BYTES_PER_NUMBER, DISK_BYTES_PER_S),
        ));
    }
    terms
}

/// The terms of the evaluations: the mesh-stiffness table, the dynamic evaluations, the
/// signals they record, the quasi-static evaluations.
fn evaluation_terms(case: &Case, job: Job, c: &Counts) -> Vec<Term> {
    let (p, w) = (&c.periods, &c.work);
    let table = case.stiffness.table_points_per_mesh_period as f64;
    let mut terms = vec![Term {
        what: "the mesh-stiffness table",
        seconds: 2.0 * table * SECONDS_PER_TABLE_POINT * c.bins,
        bytes: 16.0 * table,
        keys: &["stiffness.table_points_per_mesh_period"],
    }];
    if c.evals > 0.0 {
        terms.push(Term {
            what: "the dynamic evaluations",
            seconds: super::steady_states::evaluations_seconds(
                case,
                c.cold,
                c.warm,
                w.dynamic_modes * c.u_d + w.life_updates,
            ),
            bytes: 0.0,
            keys: if w.dynamic_modes > 0.0 {
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
    if w.kept > 0.0 {
        terms.push(Term {
            what: "the recorded signals",
            seconds: 0.0,
            // A train records whole base periods, each of max_k N_k mesh periods' samples
            // of its larger state (`train_record_factor`), not the sum of its meshes'.
            bytes: w.kept
                * p.s_dyn
                * recorded_periods(case, p.p_e)
                * BYTES_PER_SAMPLE
                * train_record_factor(case),
            keys: &[
                "numerics.evaluated_mesh_periods",
                "numerics.steps_per_mesh_period",
            ],
        });
    }
    // The stiffness command's table holds 720 equilibria, 360 steps' worth.
    let quasi_steps = w.quasi_modes * c.u_q * p.s + if job == Job::Stiffness { 360.0 } else { 0.0 };
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
    terms
}

/// The terms of the wear records: held in memory, and for `wear` and `run` their
/// profiles' tables and figures and the checkpoints written.
fn record_terms(case: &Case, job: Job, c: &Counts) -> Vec<Term> {
    let records = c.records;
    let grid = case.wear.points_per_profile as f64;
    let record_numbers = 4.0 * grid + 4.0 * c.periods.s_dyn;
    let mut terms = Vec::new();
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
    let checkpoints = matches!(job, Job::Wear { .. } | Job::Run);
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
    terms
}

/// Most bytes a checkpoint of `mode` can hold for `case`, so that a checkpoint file is
/// never read beyond what the run could have written: 16 times the estimated number of
/// updates (the estimate takes the nominal load; a run's actual updates stay well within
/// that margin) of (4 G + 4 S_d) numbers (a helical pair's wear maps add 4 N G, its
/// per-tooth maps 2 (z1 + z2) N G, `super::helical::wear_record_numbers`) at `CHECKPOINT_BYTES_PER_NUMBER` bytes, and at
/// least 64 MiB.
pub fn max_checkpoint_bytes(case: &Case, mode: WearMode) -> u64 {
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
    let s_dyn = dynamic_steps_per_period(&case.numerics);
    let numbers = 4.0 * case.wear.points_per_profile as f64
        + 4.0 * s_dyn
        + super::helical::wear_record_numbers(case);
    let bytes = 16.0 * updates * numbers * CHECKPOINT_BYTES_PER_NUMBER;
    bytes.clamp(64.0 * 1024.0 * 1024.0, 1e15) as u64
}

#[cfg(test)]
#[path = "tests_case_jobs.rs"]
mod tests;
