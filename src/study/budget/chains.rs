//! The surrogate's reference runs counted the way `prognostics::surrogate::chain` makes
//! them, before any is made: the nodes of k, the runs computed (a parallel batch past the
//! last one kept included), each run's updates in each phase of its duty, and their CPU
//! time at the rates of run-to-failure evaluations
//! ([`run_to_failure_scale`]).
//!
//! - Without a change of duty: k_j = k_lo 2^j below k_hi, runs made in batches of the
//!   thread count, up to the batch holding the first run whose blocks are cut by the wear
//!   threshold; run j goes to H k_(j+1) / k_j cycles (k_hi after the last node), and the
//!   last kept run is extended to H k_hi / k_j (resumed; under a load spectrum made again).
//! - Under a change of duty (a future spectrum from N0 cycles): every node of the finer
//!   grid (ratio `max(2^(1/4), (k_hi / k_lo)^(1/16))`, `future_node_ratio`) and k_hi is
//!   its own run to H k_(j+1) / k_j; a run makes the blocks of its own duty to N0 and then
//!   starts again from the state at N0 under the future one (`forward::run_duty_trajectory`),
//!   so each phase has its own first update and blocks cut on its own wear per cycle (the
//!   doubling's count, before issue 33, missed the finer nodes and the second phase).
//!
//! Each phase makes one update and one more per block, each block `wear.block_cycles`
//! cut to the threshold over the largest wear rate at the block's start, which falls as
//! the pair runs in ([`super::running_in`]: the wear law's rate at the case's own load
//! sharing, relaxing as the worn gaps pass load to the other pair in double contact),
//! no more than its stop depth allows; every update evaluates every bin of the duty in
//! force, the first from rest, the warm ones dearer as the flanks wear deeper
//! ([`depth_factor`]; issue 33: at the rate of new flanks `predict` with a one-bin future
//! spectrum was counted under its CPU time). (Before, the initial rate was held for the
//! whole run: 2.4-3.5 times the updates made, issue 33.)

use super::evaluation::{
    axial_factor, dynamic_steps_per_period, nominal_wear_per_cycle_m, train_factor,
    DYNAMIC_WEAR_FACTOR, SECONDS_PER_TABLE_POINT, SLOWER_MACHINE_FACTOR,
};
use super::running_in::{Gaps, RunningIn};
use super::teeth::excitation_periods_of;
use crate::config::case::{Case, NumericsSection};
use crate::config::operating::LoadSpectrumSection;
use crate::geometry::GearPair;
use crate::study::wear_loop::block_length;

/// What the estimates need of the parameters' span (a calibration's prior, the span of a
/// prediction's samples): numbers, built by prognostics (`From<&Prior>`), so that the
/// cost model imports nothing above it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParameterSpan {
    /// Smallest and largest wear coefficient, m^2/N.
    pub wear_coefficient_min_m2_per_n: f64,
    /// Largest wear coefficient, m^2/N.
    pub wear_coefficient_max_m2_per_n: f64,
    /// Largest load torque, N m.
    pub load_torque_max_nm: f64,
    /// Parameters not fixed.
    pub free: usize,
    /// Parameters not fixed besides the wear coefficient: the surrogate's axes other than k.
    pub free_besides_wear_coefficient: usize,
}

/// CPU time of one dynamic evaluation from rest of a run-to-failure job (a dataset's
/// physical state, the first update of a wear run; the model built), on the built-in case
/// at its 30 Hz, s: measured 9.2 ms, counted 10 ms (2026-11-30, load 6: 40 physical
/// states of one 0.25 s record at 25.6 kHz against 1, 0.74 s of CPU more, 19.0 ms a
/// state, less its record's synthesis, 6.2 ms at the synthesis's measured rates
/// (`budget::signals::record_synthesis`), and its record, 3.6 ms at the dataset's
/// measured rates; the record's files stay in it). The steady-state search from rest
/// takes 2-5 shooting periods at 0.2-300 Hz (`periods_to_converge` of `gearwear
/// dynamics`), not the 30 that [`super::evaluation::PERIODS_TO_SETTLE_PER_DECADE`] bounds
/// for the other jobs. (It was 15 ms, measured on 2026-11-29 as a state's whole cost with
/// its synthesis and record, which the dataset's estimate counts besides: a design of 40
/// states of short records was estimated at 3.8 times its CPU time, issue 33.)
pub const SECONDS_PER_COLD_EVALUATION: f64 = 10e-3;
/// CPU time of one further wear update of a run (warm-started from the previous update's
/// periodic state, about one shooting period, and the wear increment), built-in case at
/// 30 Hz, s: measured 4 ms (trajectories of 17 against 7 and 2 updates, 2026-11-29).
pub const SECONDS_PER_WARM_UPDATE: f64 = 4e-3;
/// Mesh period of the built-in case at 30 Hz, where the two rates above were measured, s.
const MEASURED_MESH_PERIOD_S: f64 = 1.0 / 570.0;
/// Mesh period beyond which a period costs no more steps, s: the error control's steps
/// per period stop growing (489 at 263 ms, 455 at 105 ms).
const SLOWEST_MESH_PERIOD_S: f64 = 0.25;

/// How much dearer a run-to-failure evaluation of `case` is than the built-in case's at
/// 30 Hz (dimensionless): (T_m / T_30Hz)^(1/3) for its mesh period T_m in [T_30Hz, 0.25
/// s], the error control taking more steps in a longer period (each contact event rings
/// down within it), measured: a warm update costs 4, 7.5 and 16 ms at 30, 5 and 0.5 Hz
/// (ratios 1, 1.9 and 4.0 against 1, 1.8 and 3.9 by the power law), the steps of a search
/// from rest per period 171, 373, 455 and 489 at 30, 5, 0.5 and 0.2 Hz, and no fewer than
/// 167 at 50-300 Hz (so a shorter period is counted as 30 Hz's); times S_d over the
/// built-in S_d ([`dynamic_steps_per_period`]: finer grids and tolerances), the excitation
/// periods of a tooth-resolved case and [`train_factor`]. Bounds a case with modes like
/// the built-in one's; the general estimates ([`super::evaluation::SECONDS_PER_STEP`]) stay the bound for
/// any case.
pub fn run_to_failure_scale(case: &Case) -> f64 {
    let steps = dynamic_steps_per_period(&case.numerics)
        / dynamic_steps_per_period(&NumericsSection::default());
    let periods = excitation_periods_of(case).max(1) as f64;
    speed_scale(case) * steps.max(1.0) * periods * train_factor(case) * axial_factor(case)
}

/// The speed part of [`run_to_failure_scale`]: (T_m / T_30Hz)^(1/3) for the mesh period
/// T_m of the case's first pinion, clamped to [T_30Hz, 0.25 s] (also
/// `super::steady_states`, the wear study's periods).
pub(crate) fn speed_scale(case: &Case) -> f64 {
    let teeth = super::evaluation::input_pinion_teeth(case);
    let t_m = 1.0 / (teeth * case.operating.input_speed_hz);
    if t_m.is_finite() {
        (t_m.clamp(MEASURED_MESH_PERIOD_S, SLOWEST_MESH_PERIOD_S) / MEASURED_MESH_PERIOD_S).cbrt()
    } else {
        (SLOWEST_MESH_PERIOD_S / MEASURED_MESH_PERIOD_S).cbrt()
    }
}

/// Samples of the period a wear update spreads over the slices, on the built-in grid
/// (`numerics.steps_per_mesh_period` = 200) at 30 Hz, where
/// [`SECONDS_PER_RUN_SLICE_CONTACT`] was measured; [`run_to_failure_scale`] carries a
/// finer grid, a tighter tolerance and a slower mesh.
const SLICE_SAMPLES_AT_30_HZ: f64 = 200.0;
/// CPU seconds of one slice contact of a helical pair's wear update in a run-to-failure
/// job (`study::helical_wear`: the update's spread over the face slices beside its
/// dynamic evaluation, which the rates above count), s: measured 2026-11-30 on the 2-core
/// machine under load, `examples/helical_pair.toml` (400 slices, two transverse pairs:
/// 160 000 contacts an update) in a dataset of 2 states to 1e5 cycles (19 further
/// updates) against 1e3 (one): 1.30 s against 0.25 s of CPU (user and system), 55 ms an
/// update, 0.35 us a contact with the update's evaluation in it; times
/// [`SLOWER_MACHINE_FACTOR`]. (The wear study's
/// `super::helical::SECONDS_PER_SLICE_CONTACT` bounds the general, adaptive sample count
/// instead.)
pub const SECONDS_PER_RUN_SLICE_CONTACT: f64 = 0.35e-6 * SLOWER_MACHINE_FACTOR;

/// CPU seconds a helical pair's wear update adds in a run-to-failure job (a dataset's
/// trajectory, a prognostics run): its slice contacts
/// (`super::helical::slice_contacts_per_update` at `SLICE_SAMPLES_AT_30_HZ`) at
/// [`SECONDS_PER_RUN_SLICE_CONTACT`], times [`run_to_failure_scale`]; 0 for a spur pair
/// or a train.
pub fn helical_update_seconds(case: &Case) -> f64 {
    super::helical::slice_contacts_per_update(case, SLICE_SAMPLES_AT_30_HZ).map_or(0.0, |c| {
        c * SECONDS_PER_RUN_SLICE_CONTACT * run_to_failure_scale(case)
    })
}

/// CPU seconds of a run of `updates` wear updates of `case` in a run-to-failure job: the
/// mesh-stiffness table, one evaluation from rest and `updates` - 1 warm ones, at the
/// rates above times [`run_to_failure_scale`] and [`SLOWER_MACHINE_FACTOR`], and a
/// helical pair's slice contacts of every update ([`helical_update_seconds`]; a single
/// evaluation, e.g. a dataset's physical state, is counted as one update).
pub fn run_to_failure_seconds(case: &Case, updates: f64) -> f64 {
    let table = 2.0 * case.stiffness.table_points_per_mesh_period as f64 * SECONDS_PER_TABLE_POINT;
    let evals = SECONDS_PER_COLD_EVALUATION + (updates - 1.0).max(0.0) * SECONDS_PER_WARM_UPDATE;
    let helical = updates.max(1.0) * helical_update_seconds(case);
    table + evals * run_to_failure_scale(case) * SLOWER_MACHINE_FACTOR + helical
}

/// Mean mesh stiffness per face width of ISO 6336-1 (c'_gamma ~ 20 N/(mm um)), N/m^2:
/// only the scale of the elastic approach of the teeth.
const ISO_MESH_STIFFNESS_PER_WIDTH: f64 = 2e10;
/// Wear depth at which a run stops because the teeth lose contact, in elastic approaches
/// F / (c'_gamma b): measured 7.5-10.9 on spur pairs at 30 Hz and 16.9 on
/// `examples/helical_pair.toml` (60 N m); 50 leaves margin there (not at every speed: a
/// spur pair's dynamic run at 200 Hz went past 65, docs/RELIABILITY.md).
const STOP_DEPTH_IN_APPROACHES: f64 = 50.0;
/// The stop depth of such a pair is taken as at least this, m.
const MIN_STOP_DEPTH_M: f64 = 100e-6;

/// Elastic approach of the teeth under the case's nominal load, F / (c'_gamma b) with
/// c'_gamma = `ISO_MESH_STIFFNESS_PER_WIDTH` (2e10 N/m^2), m: the scale against which
/// wear depth is deep or shallow (contact lost, a warm update's cost, [`depth_factor`]);
/// infinite for a case whose pair cannot be built.
pub fn elastic_approach_m(case: &Case) -> f64 {
    let Ok(pair) = GearPair::from_case(&case.gear) else {
        return f64::INFINITY;
    };
    let rb = match case.operating.load_torque_shaft {
        crate::config::case::TorqueShaft::Pinion => pair.pinion.base_radius_m,
        crate::config::case::TorqueShaft::Gear => pair.gear.base_radius_m,
    };
    case.operating.load_torque_nm / rb / (ISO_MESH_STIFFNESS_PER_WIDTH * pair.face_width_m)
}

/// Largest wear depth a wear run of `case` reaches before the teeth lose contact and it
/// stops (`wear_loop::MAX_CONTACT_LOSS_FRACTION`), m: `STOP_DEPTH_IN_APPROACHES` elastic
/// approaches under the nominal load ([`elastic_approach_m`]), at least
/// `MIN_STOP_DEPTH_M`. The surrogate's runs at the prior's largest k stop there long
/// before their horizon. (A static criterion on the worn profile, tried on 2026-11-30,
/// held at 30 Hz, 1.2-1.8 times the runs' depths, but not at other speeds: the dynamic
/// runs went to 205 um at 5 Hz and past 420 um at 60-200 Hz, where it counted 109 um; so
/// the bound stays this one.)
pub fn stop_depth_m(case: &Case) -> f64 {
    stop_depth_at_approach_m(elastic_approach_m(case))
}

/// [`stop_depth_m`] of a pair whose elastic approach is `approach_m`, m.
fn stop_depth_at_approach_m(approach_m: f64) -> f64 {
    (STOP_DEPTH_IN_APPROACHES * approach_m).max(MIN_STOP_DEPTH_M)
}

/// Depth, in elastic approaches, past which [`depth_factor`] grows no more (2.2 there).
const DEPTH_FACTOR_CAP_APPROACHES: f64 = 4.0;

/// How much dearer a warm update is on flanks worn `depth_m` deep than on new ones
/// (dimensionless): for x = d / a elastic approaches ([`elastic_approach_m`]),
/// min(1 + x / 2, 1.4 + x / 5), held at its value at 4 a (2.2). The worn teeth's impacts
/// take the error control more steps. Measured 2026-12-01 as the solver's right-hand side
/// evaluations of warm-started updates (deterministic, not a timing) on the built-in
/// pair, against the updates on flanks worn less than 5 um (where
/// [`SECONDS_PER_WARM_UPDATE`] was measured): at 60 N m and 30 Hz (a = 8.4 um) 1.0-1.05
/// to 0.65 a, then a step to 1.36 at 0.88 a, 1.32-1.40 at 1.1-2.8 a, 1.51 at 3.4 a, 1.80
/// at 7.6 a where contact is lost; at 40 N m and 20 Hz (a = 5.6 um) 1.13 at 1.7 a, 1.34
/// at 2.9 a, 2.02 at 5.4 a, 2.23 at 7.1 a (docs/RELIABILITY.md). An update's CPU time is
/// about proportional to them (1.1-1.2 us an evaluation on a busy machine; wear runs
/// timed earlier, 9.8 ms an update on average to 16 um and 13.6 ms to 78 um, stand
/// within the factor times [`SLOWER_MACHINE_FACTOR`], not within the factor alone). The growth depends on speed: at 100 Hz 2.2-2.9 from 4 a to 48 a (no
/// contact loss), at 5 Hz 1.5 at 2 a, 3.0 at 5.4 a and 5-6 from 10 a to contact loss at
/// 12-14 a; there the factor counts deep updates under their work, and the rates' factor
/// 2 ([`SLOWER_MACHINE_FACTOR`]) and the updates counted past the real stop
/// ([`stop_depth_m`]) are the margin. The cap is where the runs at 20-30 Hz stand (a
/// factor that followed 5 Hz would count these runs at 3-4 times their work).
/// `tests/budget_chains.rs` checks the factor against the solver's count at 20 and 30 Hz.
pub fn depth_factor(depth_m: f64, approach_m: f64) -> f64 {
    let x = (depth_m / approach_m).clamp(0.0, DEPTH_FACTOR_CAP_APPROACHES);
    if x.is_nan() {
        1.0
    } else {
        (1.0 + x / 2.0).min(1.4 + x / 5.0)
    }
}

/// Most blocks of one phase followed one by one: past them the rest are counted at the
/// last block's length (rates only fall, so blocks only grow: an upper bound).
const MAX_FOLLOWED_BLOCKS: usize = 2000;

/// What a run has reached when a phase ends: the deepest wear counted, m, and the
/// running-in's gaps.
#[derive(Debug, Clone, Default)]
struct Worn {
    depth_m: f64,
    gaps: Gaps,
}

/// Updates of one phase of `total` cycles at wear coefficient `k` under `running`, from
/// `from`, and what the run reached: the loop's blocks (`study::wear_loop::block_length`:
/// `wear.block_cycles` cut to the threshold over the largest rate at the block's start,
/// [`RunningIn::rate_after`]), one update each after the first, until the cycles are run
/// or the deepest wear (each block adding its cycles times that rate, a bound) reaches
/// `stop_m` ([`stop_depth_m`]). Also the warm updates weighted by the cost of the depth
/// each is made at ([`depth_factor`] over `approach_m`).
fn updates_within(
    case: &Case,
    running: &RunningIn,
    (k, total): (f64, f64),
    from: &Worn,
    (stop_m, approach_m): (f64, f64),
) -> (Updates, Worn) {
    let w = &case.wear;
    let threshold = w.threshold_um * 1e-6;
    let (mut done, mut depth) = (0.0, from.depth_m);
    let mut u = Updates {
        count: 1.0,
        weighted_warm: 0.0,
    };
    for followed in 0.. {
        if !(done < total && depth < stop_m) {
            break;
        }
        let rate = k * running.rate_after(&from.gaps, k * done);
        let n = block_length(rate, w.block_cycles, threshold, total - done);
        if followed >= MAX_FOLLOWED_BLOCKS || n.is_nan() || n <= 0.0 {
            // The rest at the cost of the depth the rest reaches at the present rate
            // (rates only fall: an upper bound of both).
            let rest = ((total - done) / n.max(1.0)).ceil();
            let reached = depth + (total - done) * rate;
            depth = if reached.is_nan() { stop_m } else { reached };
            u.count += rest;
            u.weighted_warm += rest * depth_factor(depth.min(stop_m), approach_m);
            done = total;
            break;
        }
        done += n;
        depth += n * rate;
        u.count += 1.0;
        u.weighted_warm += depth_factor(depth.min(stop_m), approach_m);
    }
    let gaps = running.gaps_after(&from.gaps, k * done);
    (
        u,
        Worn {
            depth_m: depth.min(stop_m),
            gaps,
        },
    )
}

/// The updates of a phase: how many, and the warm ones (all but the first) each weighted
/// by its [`depth_factor`].
#[derive(Debug, Clone, Copy)]
struct Updates {
    count: f64,
    weighted_warm: f64,
}

/// A duty a run follows for a while: its initial wear per cycle per unit k (m per m^2/N,
/// with the dynamic margin) and its running-in, and the seconds of its first update
/// (every bin from rest, each bin's table) and of each further one (every bin warm).
#[derive(Debug, Clone)]
struct Duty {
    rate_per_k: f64,
    running: RunningIn,
    first_s: f64,
    /// Each further update's dynamic evaluations (dearer with depth, [`depth_factor`]), s.
    further_solver_s: f64,
    /// Each further update's helical slice contacts (not dearer with depth: the factor
    /// was measured on the solver's work), s.
    further_slices_s: f64,
    bins: f64,
    /// The smallest of its bins' elastic approaches, m ([`depth_factor`]); its stop depth
    /// ([`Duty::stop_m`]) follows from it.
    approach_m: f64,
}

impl Duty {
    /// The duty of `case` (its load spectrum, or its operating point) at the span's
    /// largest torque.
    fn of(case: &Case, span: &ParameterSpan) -> Duty {
        let mut c = case.clone();
        c.wear.coefficient_m2_per_n = 1.0;
        c.operating.load_torque_nm = c.operating.load_torque_nm.max(span.load_torque_max_nm);
        let points: Vec<(f64, Case)> = match &c.load_spectrum {
            Some(s) => (0..s.bins.len())
                .map(|i| (s.bins[i].share, c.at_bin(i)))
                .collect(),
            None => vec![(1.0, c.clone())],
        };
        let pair = GearPair::from_case(&c.gear).ok();
        let table = 2.0 * c.stiffness.table_points_per_mesh_period as f64 * SECONDS_PER_TABLE_POINT;
        let mut d = Duty {
            rate_per_k: 0.0,
            running: RunningIn::default(),
            first_s: 0.0,
            further_solver_s: 0.0,
            further_slices_s: 0.0,
            bins: points.len() as f64,
            approach_m: f64::INFINITY,
        };
        // A train's blocks follow its fastest mesh per input cycle.
        let train = super::train_prognostics::train_wear_per_input_cycle_m(&c);
        for (share, b) in &points {
            if let Some(r) = train {
                d.rate_per_k += share * DYNAMIC_WEAR_FACTOR * r;
            } else if let Some(p) = &pair {
                d.rate_per_k += share * DYNAMIC_WEAR_FACTOR * nominal_wear_per_cycle_m(b, p);
            }
            d.approach_m = d.approach_m.min(elastic_approach_m(b));
            let scale = run_to_failure_scale(b) * SLOWER_MACHINE_FACTOR;
            let helical = helical_update_seconds(b);
            d.first_s += table + SECONDS_PER_COLD_EVALUATION * scale + helical;
            d.further_solver_s += SECONDS_PER_WARM_UPDATE * scale;
            d.further_slices_s += helical;
        }
        // The running-in of a single spur pair (`super::running_in`); the initial rate
        // held otherwise.
        let spur = train.is_none() && c.gear.helix_angle_deg == 0.0 && c.planetary.is_none();
        d.running = pair
            .filter(|_| spur)
            .and_then(|p| RunningIn::of_bins(&p, &points, DYNAMIC_WEAR_FACTOR))
            .unwrap_or_else(|| RunningIn::constant(d.rate_per_k));
        d
    }

    /// Wear depth at which a run under this duty stops, m: the smallest of its bins'
    /// [`stop_depth_m`] (contact is lost first under the lightest load, whose elastic
    /// approach is the smallest).
    fn stop_m(&self) -> f64 {
        stop_depth_at_approach_m(self.approach_m)
    }

    /// Updates and seconds of `cycles` cycles of this duty at wear coefficient `k`,
    /// from what the run reached, `from`; and what it reaches.
    fn phase(&self, case: &Case, k: f64, cycles: f64, from: &Worn) -> (Count, Worn) {
        let bounds = (self.stop_m(), self.approach_m);
        let (u, worn) = updates_within(case, &self.running, (k, cycles), from, bounds);
        let warm = (u.count - 1.0).max(0.0);
        let c = Count {
            runs: 0.0,
            updates: u.count,
            seconds: self.first_s
                + u.weighted_warm * self.further_solver_s
                + warm * self.further_slices_s,
            largest_run: u.count * self.bins,
            warm_seconds: warm * (self.further_solver_s + self.further_slices_s),
        };
        (c, worn)
    }
}

/// What the reference runs (or true runs) count to.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Count {
    /// Runs made.
    pub runs: f64,
    /// Records kept, over every run (one an update; a run's first phase's last record
    /// is replaced by the second phase's first).
    pub updates: f64,
    /// CPU seconds of their evaluations.
    pub seconds: f64,
    /// The most bin records one run holds while it runs (its updates x its duty's bins).
    pub largest_run: f64,
    /// The warm-started updates (every update but each phase's first) at the rate of
    /// new flanks, [`SECONDS_PER_WARM_UPDATE`] (`seconds` holds them at the depth each is
    /// made at, [`depth_factor`]), s: a caller whose updates do more than the chains'
    /// adds to `seconds` in proportion to it.
    pub warm_seconds: f64,
}

impl Count {
    fn add(&mut self, o: Count) {
        self.runs += o.runs;
        self.updates += o.updates;
        self.seconds += o.seconds;
        self.warm_seconds += o.warm_seconds;
        self.largest_run = self.largest_run.max(o.largest_run);
    }
}

/// A change of duty as the estimate needs it: the future spectrum and N0.
#[derive(Debug, Clone, Copy)]
pub struct FutureDutyJob<'a> {
    /// The future load spectrum.
    pub spectrum: &'a LoadSpectrumSection,
    /// N0: the pinion cycles from new teeth at which the future spectrum takes over.
    pub from_cycles: f64,
}

/// The duties of a run of `case`: its own, and the future one with N0.
#[derive(Debug, Clone)]
pub struct Duties {
    own: Duty,
    future: Option<(Duty, f64)>,
}

impl Duties {
    /// The duties of `case` over `span`, under `future` from its N0 on.
    pub fn of(case: &Case, span: &ParameterSpan, future: Option<FutureDutyJob>) -> Duties {
        Duties {
            own: Duty::of(case, span),
            future: future.map(|f| {
                let mut then = case.clone();
                then.load_spectrum = Some(f.spectrum.clone());
                (Duty::of(&then, span), f.from_cycles)
            }),
        }
    }

    /// One run at `k` to `to` cycles.
    pub fn run(&self, case: &Case, k: f64, to: f64) -> Count {
        let new = Worn {
            depth_m: 0.0,
            gaps: self.own.running.new_teeth(),
        };
        let mut c = match &self.future {
            Some((next, from)) if *from < to => {
                let (mut c, worn) = self.own.phase(case, k, *from, &new);
                // The record at the switch is made under both duties, kept once; the
                // second phase goes on from the depth and gaps the first reached (the
                // depth at most its stop depth, so the run's whole depth is bounded by
                // the stop depth; the gaps of the same positions of the same pair, when
                // both duties run in).
                let worn = Worn {
                    gaps: if next.running.new_teeth().len() == worn.gaps.len() {
                        worn.gaps
                    } else {
                        next.running.new_teeth()
                    },
                    ..worn
                };
                c.add(next.phase(case, k, to - from, &worn).0);
                c.updates -= 1.0;
                c
            }
            _ => self.own.phase(case, k, to, &new).0,
        };
        c.runs = 1.0;
        c
    }
}

/// The reference runs of one chain of the surrogate over the span's k to horizon `h`
/// cycles on `threads` threads (module docs).
pub fn chain_count(
    case: &Case,
    span: &ParameterSpan,
    future: Option<FutureDutyJob>,
    h: f64,
    threads: usize,
) -> Count {
    let (k_lo, k_hi) = (
        span.wear_coefficient_min_m2_per_n,
        span.wear_coefficient_max_m2_per_n,
    );
    let ratio = match future {
        None => 2.0,
        Some(_) => 2f64.powf(0.25).max((k_hi / k_lo).powf(1.0 / 16.0)),
    };
    let mut ks = vec![k_lo];
    while ks.len() < 400 && ks[ks.len() - 1] * ratio < k_hi * (1.0 - 1e-12) {
        ks.push(ks[ks.len() - 1] * ratio);
    }
    if future.is_some() && k_hi > k_lo {
        ks.push(k_hi);
    }
    let next = |j: usize| ks.get(j + 1).copied().unwrap_or(k_hi);
    let duties = Duties::of(case, span, future);
    let mut total = Count::default();
    if future.is_some() {
        for (j, k) in ks.iter().enumerate() {
            total.add(duties.run(case, *k, h * next(j) / k));
        }
        return total;
    }
    // The first run cut by the threshold ends the chain; its batch is made whole.
    let own = &duties.own;
    let threshold = case.wear.threshold_um * 1e-6;
    let cut = ks
        .iter()
        .position(|k| case.wear.block_cycles * own.rate_per_k * k > threshold)
        .unwrap_or(ks.len() - 1);
    let batch = threads.max(1);
    let made = ((cut / batch + 1) * batch).min(ks.len());
    for (j, k) in ks.iter().enumerate().take(made) {
        total.add(duties.run(case, *k, h * next(j) / k));
    }
    // The last kept run extended to cover k_hi: resumed (its further updates), or under
    // a spectrum made again whole.
    let (k, done) = (ks[cut], h * next(cut) / ks[cut]);
    let need = h * k_hi / k;
    if need > done {
        let whole = duties.run(case, k, need);
        if case.load_spectrum.is_some() {
            total.add(whole);
        } else {
            let before = duties.run(case, k, done);
            total.updates += whole.updates - before.updates;
            total.seconds += whole.seconds - before.seconds;
            total.warm_seconds += whole.warm_seconds - before.warm_seconds;
            total.largest_run = total.largest_run.max(whole.largest_run);
        }
    }
    total
}
