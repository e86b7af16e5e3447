//! The cost of `dataset`: its run-to-failure trajectories and its physical states (the
//! disk has its own budget, checked with the design).

use super::case_jobs::{estimate, Job};
use super::chains::run_to_failure_seconds;
use super::cost::{Estimate, Term, BASE_BYTES};
use super::evaluation::SLOWER_MACHINE_FACTOR;
use super::signals::{record_synthesis, BYTES_PER_SAMPLE_CHANNEL};
use crate::study::dataset::plan::{plan_of, Shard};
use crate::study::dataset::verify::{recomputed_count, MAX_RECOMPUTED_STATES};
use crate::study::dataset::DatasetDesign;
use crate::study::wear_check::MAX_RECOMPUTED;

/// CPU seconds per record sample of a dataset, besides its channels (tachometer, noise,
/// files; no figures nor analysis of `signals`), and per sample and channel, of a
/// physical state's first record, its periodic signals' synthesis apart
/// ([`record_synthesis`], counted with the state): measured 2026-11-30 (the built-in
/// case at 30 Hz and 25.6 kHz, 4 states of one record, 0.25 s against 8 s with 2
/// channels: 0.13 and 0.58 s of CPU, 0.57 us a sample; 0.25 s against 4 s with 20
/// channels: 0.24 and 1.17 s, 2.42 us) 0.36 us a sample and 0.10 us a sample and
/// channel, so 0.4 us and 0.1 us, times [`SLOWER_MACHINE_FACTOR`]: the first record
/// costs what a further one does (below) but its synthesis. (They were 0.5 us and 0.4
/// us, measured when the synthesis was not counted on its own and the channels did not
/// share the TSA's interpolation weights: with the synthesis counted besides, a design
/// of 40 states of one 1 s record was estimated at 4.0 times its CPU time and one of 4
/// records of 4 s with 20 channels at 6.3 times, issue 33. They were `signals`' 3 us
/// and 4 us before: a dataset's record costs less than a `signals` record.)
const SECONDS_PER_RECORD_SAMPLE: f64 = 0.4e-6 * SLOWER_MACHINE_FACTOR;
const SECONDS_PER_SAMPLE_CHANNEL: f64 = 0.1e-6 * SLOWER_MACHINE_FACTOR;
/// The same of each further record of a state (its noise realisations share the state's
/// rendered clean channels: only noise, analysis and files are made again), and of a
/// kept record read back and analysed by a resume's or a merge's check: measured
/// 2026-11-30 (built-in case, 1 s at 25.6 kHz, load 8) 13 ms a further record with 2
/// channels (4 and 40 states x 1 and 10 realisations: 0.17, 0.67, 1.26 and 5.82 s of
/// CPU) and 50 ms with 20 (4 states x 1 and 10: 0.42 and 2.22 s), so 0.35 us a sample
/// and 0.08 us a sample and channel; a kept record's check 12 ms with 2 channels (an
/// 800-record resume, docs/RELIABILITY.md); times [`SLOWER_MACHINE_FACTOR`].
const SECONDS_PER_FURTHER_RECORD_SAMPLE: f64 = 0.35e-6 * SLOWER_MACHINE_FACTOR;
const SECONDS_PER_FURTHER_SAMPLE_CHANNEL: f64 = 0.08e-6 * SLOWER_MACHINE_FACTOR;

/// CPU seconds of one record of `record`'s size: a state's first (`first`), or a
/// further realisation of it, or a kept record's check.
fn record_seconds(record: RecordSize, first: bool) -> f64 {
    let (base, channel) = if first {
        (SECONDS_PER_RECORD_SAMPLE, SECONDS_PER_SAMPLE_CHANNEL)
    } else {
        (
            SECONDS_PER_FURTHER_RECORD_SAMPLE,
            SECONDS_PER_FURTHER_SAMPLE_CHANNEL,
        )
    };
    record.samples * (base + record.channels * channel)
}

/// The size of the dataset's longest record: its samples (record length x sampling rate,
/// at the slowest speed for a length in revolutions) and its accelerometer channels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RecordSize {
    /// Samples of the longest record (one channel).
    pub samples: f64,
    /// Accelerometer channels of a record.
    pub channels: f64,
}

/// The cost of (a shard of) a dataset against the run budget, before anything is
/// computed (the disk has its own budget): each condition's run-to-failure trajectory
/// costs the updates of a dynamic wear study to `max_cycles` (it stops earlier at the
/// wear limit), one from rest and the others warm-started, without a wear study's
/// checkpoints and tables (`study::dataset::trajectory`); each physical state of the
/// shard one dynamic evaluation from rest at its speed and load (the costliest of the
/// lowest and highest speed and load of its condition), at the rates of run-to-failure
/// evaluations ([`run_to_failure_seconds`]: measured, times the slower-machine factor;
/// issue 33: the trajectory was a whole `wear` study and each state a `dynamics` run,
/// both under the slow-speed bounds of any case, 4-6 times the measured CPU); and each of
/// its records (noise, files) its samples x (a base + its channels) at the rates
/// measured for datasets. A resume does this work or checks what it keeps instead
/// ([`estimate_dataset_resumed`], `app::dataset::run`): each kept trajectory checked by
/// the wear law (before issue 33's count of it, counted nowhere); a sample of states
/// recomputed (counted as made); every other kept record's labels and signal read back
/// and analysed, a further record's cost (measured 12 ms against 13 ms,
/// docs/RELIABILITY.md). Memory: the costliest single study, or the longest record, on
/// each of `threads` threads. Counts are floats (never wrap: the record count of a design
/// is bounded when it is read).
pub fn estimate_dataset(
    d: &DatasetDesign,
    shard: Shard,
    threads: usize,
    record: RecordSize,
) -> Estimate {
    estimate_dataset_resumed(d, shard, threads, record, (&[], 0))
}

/// [`estimate_dataset`] of a run that finds the trajectories of the conditions
/// `kept[c]` in its folder (a resume; missing entries: none kept) and `kept_states` of
/// its shard's physical states with every record finished: each kept trajectory is
/// checked by the wear law instead of made, the first, the last and a sample of the
/// kept states (at most `MAX_RECOMPUTED_STATES`) recomputed, and every other kept
/// state's records read back and checked, at a further record's rate, instead of made
/// (`app::dataset::run`).
pub fn estimate_dataset_resumed(
    d: &DatasetDesign,
    shard: Shard,
    threads: usize,
    record: RecordSize,
    (kept, kept_states): (&[bool], usize),
) -> Estimate {
    let plan = plan_of(d);
    let shard_states = plan.shard_state_count(shard) as f64;
    let kept_states = (kept_states as f64).min(shard_states);
    let checked = (kept_states - MAX_RECOMPUTED_STATES as f64).max(0.0);
    // The states made (or recomputed), and the records of the others checked.
    let states = shard_states - checked;
    let realisations = plan.realisations as f64;
    let further = states * (realisations - 1.0).max(0.0);
    let records_s = states * record_seconds(record, true)
        + further * record_seconds(record, false)
        + checked * realisations * record_seconds(record, false);
    // A record held on each thread: its channels (clean and noisy, in the writer's
    // buffers), measured 98 bytes a sample in all with 2 channels on 2 threads (the peak
    // of 4 records of 8 s against 0.25 s at 25.6 kHz: 37.7 MB against 18.3 MB) and 65 more
    // per further channel (20 channels: 34 MB against 19 MB), within `signals`' 64 bytes a
    // sample and channel on each thread. (It also counted `signals`' 400 bytes a sample of
    // analysis a dataset does not make: 10 times the measured slope, issue 33.)
    let per_sample_b = record.channels * BYTES_PER_SAMPLE_CHANNEL;
    let c = design_costs(d, record);
    Estimate::of_terms(vec![
        Term {
            what: "the conditions' run-to-failure trajectories (or their checks on a resume)",
            seconds: c
                .trajectory_s
                .iter()
                .enumerate()
                .map(|(i, (made, check))| {
                    if kept.get(i) == Some(&true) {
                        *check
                    } else {
                        *made
                    }
                })
                .sum(),
            bytes: 0.0,
            keys: &["run_to_failure.max_cycles", "the conditions' wear keys"],
        },
        Term {
            what: "the physical states' dynamic evaluations",
            seconds: states * c.state_s,
            bytes: threads.max(1) as f64 * (c.bytes - BASE_BYTES),
            keys: &[
                "the number of conditions, states, speeds and loads",
                "the conditions' numerics keys",
            ],
        },
        Term {
            what: "the records (noise, analysis, files)",
            seconds: records_s,
            bytes: threads.max(1) as f64 * record.samples * per_sample_b,
            keys: &[
                "records.noise_realisations",
                "signals.record_length",
                "signals.sampling_rate_hz",
                "the transfer path's sensors",
            ],
        },
    ])
    .drawing(super::figures::dataset_figures())
}

/// What a design's conditions cost, each once: their trajectories, the costliest
/// physical state (its dynamic evaluation from rest and its record's synthesis) and the
/// memory of the costliest single study.
struct DesignCosts {
    /// CPU seconds of each condition's run-to-failure trajectory: made, and checked by
    /// the wear law when kept (a check recomputes up to `MAX_RECOMPUTED` + 1 updates,
    /// each counted from rest, so it can cost more than a short trajectory made warm).
    trajectory_s: Vec<(f64, f64)>,
    /// CPU seconds of checking every condition's kept trajectory by the wear law: the
    /// updates `study::wear_check::verify_resumable` recomputes (at most
    /// `MAX_RECOMPUTED`) and the next update after the last, each an evaluation from its
    /// stored state, counted from rest.
    trajectory_checks_s: f64,
    /// CPU seconds of the costliest physical state.
    state_s: f64,
    /// Peak bytes of the costliest single study on one thread.
    bytes: f64,
}

/// [`DesignCosts`] of `d` with records of `record`'s size.
fn design_costs(d: &DatasetDesign, record: RecordSize) -> DesignCosts {
    let ends = |v: &[f64]| {
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        [lo, hi]
    };
    let mut c = DesignCosts {
        trajectory_s: Vec::new(),
        trajectory_checks_s: 0.0,
        state_s: 0.0,
        bytes: 0.0,
    };
    for cond in &d.conditions {
        if let Some((traj_s, one_s, b)) = planetary_costs(&cond.case, d) {
            // A set's kept trajectory is checked as its wear checkpoints are: a sample of
            // its updates recomputed, each about one update of the set.
            let check_s = (MAX_RECOMPUTED + 1) as f64 * one_s;
            c.trajectory_checks_s += check_s;
            c.trajectory_s.push((traj_s, check_s));
            c.state_s = c.state_s.max(one_s);
            c.bytes = c.bytes.max(b);
            continue;
        }
        let mut case = cond.case.clone();
        case.wear.total_cycles = d.max_cycles;
        let w = estimate(
            &case,
            Job::Wear {
                dynamic: true,
                quasi_static: false,
            },
        );
        let traj_s = run_to_failure_seconds(&case, w.wear_updates_dynamic);
        let check_s = (MAX_RECOMPUTED + 1) as f64 * run_to_failure_seconds(&case, 1.0);
        c.trajectory_checks_s += check_s;
        c.trajectory_s.push((traj_s, check_s));
        c.bytes = c.bytes.max(w.memory_bytes());
        for speed in ends(&d.speeds_hz) {
            for torque in ends(&d.torques_nm) {
                let mut case = cond.case.clone();
                case.set_load_point(crate::config::case::LoadPoint {
                    input_speed_hz: speed,
                    load_torque_nm: torque,
                    ..case.load_point()
                });
                let e = estimate(&case, Job::Dynamics);
                // Each state's periodic record is synthesised once (its realisations
                // only add noise): at low speed its harmonics dominate (0.6 s at 0.5 Hz).
                let (synth_s, synth_b) = record_synthesis(&case, record.channels as usize);
                c.state_s = c.state_s.max(run_to_failure_seconds(&case, 1.0) + synth_s);
                c.bytes = c.bytes.max(e.memory_bytes() + synth_b);
            }
        }
    }
    c
}

/// The records of a dataset folder a check verifies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KeptRecords {
    /// Records kept (sidecars under the dataset's key).
    pub records: f64,
    /// Physical states they belong to.
    pub states: f64,
}

/// The cost of verifying a dataset folder of design `d` holding `kept` records of
/// `record`'s size, as a merge verifies each input shard before it copies anything
/// (`app::dataset::merge_verify`): every kept trajectory checked by the wear law, the
/// first, last and a random sample of the physical states recomputed whole (at most
/// `MAX_RECOMPUTED_STATES`), and every other kept record's signal read back and analysed
/// on `threads` threads (at the rate of a state's further record, measured alike). (Before issue 33's budget for merges, a merge of 1e6 records was
/// hours of CPU counted nowhere.)
pub fn estimate_dataset_check(
    d: &DatasetDesign,
    kept: KeptRecords,
    threads: usize,
    record: RecordSize,
) -> Estimate {
    // A merge draws its sample among the states the shard holds: each a kept one.
    let recomputed = recomputed_count(kept.states as usize, MAX_RECOMPUTED_STATES) as f64;
    // The merged dataset's indicator trends are drawn after it.
    folder_check(d, kept, (recomputed, recomputed), threads, record)
        .drawing(super::figures::dataset_figures())
}

/// [`estimate_dataset_check`] with a sample of `sample` physical states: the cost of
/// `app::dataset::jobs::verify_folder`, which draws its sample among all the design's
/// physical states (`study::dataset::verify::states_to_recompute`: every state of at most
/// `sample`, else the first, the last and `sample - 2` others, so two with a sample of 0
/// or 1) and recomputes those of conditions with a trajectory: counted all. (Before
/// issue 33's count of it, a folder's check was budgeted nowhere; until its review it
/// counted min(kept, sample) states, none with a sample of 0 where two are recomputed.)
pub fn estimate_folder_check(
    d: &DatasetDesign,
    kept: KeptRecords,
    sample: usize,
    threads: usize,
    record: RecordSize,
) -> Estimate {
    let physical = plan_of(d).physical_states();
    let recomputed = recomputed_count(physical, sample) as f64;
    // Those beyond the states missing from the folder are kept ones, at least.
    let missing = (physical as f64 - kept.states).max(0.0);
    let kept_recomputed = (recomputed - missing).clamp(0.0, kept.states);
    // A folder's check draws no figure.
    folder_check(d, kept, (recomputed, kept_recomputed), threads, record)
        .drawing(super::cost::FigureCount::default())
}

/// A folder's check with `recomputed` physical states recomputed whole, `kept_recomputed`
/// of them kept ones (their records not read back again; see [`estimate_dataset_check`]).
fn folder_check(
    d: &DatasetDesign,
    kept: KeptRecords,
    (recomputed, kept_recomputed): (f64, f64),
    threads: usize,
    record: RecordSize,
) -> Estimate {
    let plan = plan_of(d);
    let c = design_costs(d, record);
    let realisations = plan.realisations as f64;
    let per_state_s = c.state_s
        + record_seconds(record, true)
        + (realisations - 1.0).max(0.0) * record_seconds(record, false);
    let checked = (kept.records - kept_recomputed * realisations).max(0.0);
    let threads = threads.max(1) as f64;
    Estimate::of_terms(vec![
        Term {
            what: "the kept trajectories checked by the wear law",
            seconds: c.trajectory_checks_s,
            bytes: 0.0,
            keys: &["the conditions' wear keys"],
        },
        Term {
            what: "a sample of the physical states recomputed",
            seconds: recomputed * per_state_s,
            bytes: threads * (c.bytes - BASE_BYTES),
            keys: &["the conditions' numerics keys"],
        },
        Term {
            what: "every kept record's signal read back and analysed",
            seconds: checked * record_seconds(record, false),
            bytes: threads * record.samples * record.channels * BYTES_PER_SAMPLE_CHANNEL,
            keys: &[
                "the records the inputs hold",
                "signals.record_length",
                "signals.sampling_rate_hz",
                "the transfer path's sensors",
            ],
        },
    ])
}

/// A planetary condition's costs (`study::dataset::planetary`), None for a pair or a
/// train: its trajectory's CPU seconds (the set's own dynamic wear study to `max_cycles`,
/// `budget::planetary::estimate_planetary_wear`), one physical state's (one response of
/// the whole set: the study of a single update), and the study's memory. A set
/// whose wear model cannot be built is refused with the design before this counts it.
fn planetary_costs(case: &crate::config::Case, d: &DatasetDesign) -> Option<(f64, f64, f64)> {
    case.planetary.as_ref()?;
    let modes = [crate::study::wear_loop::WearMode::Dynamic];
    let mut c = case.clone();
    c.wear.total_cycles = d.max_cycles;
    let m = crate::study::planetary_wear::PlanetaryWearModel::from_case(&c).ok()?;
    let w = super::planetary::estimate_planetary_wear(&m, &c.wear, &modes);
    // One physical state: one response of the set, a study of 0 cycles (its first
    // update only; the measured rate per update does not depend on speed or load).
    c.wear.total_cycles = 0.0;
    let state_s = super::planetary::estimate_planetary_wear(&m, &c.wear, &modes).seconds();
    Some((w.seconds(), state_s, w.memory_bytes()))
}

/// Bytes of one number of a kept trajectory file (JSON): measured 22 with its separator
/// (an update of the built-in case: 1168 numbers in 25.9 kB); 24 leaves margin.
const TRAJECTORY_BYTES_PER_NUMBER: f64 = 24.0;

/// Estimated bytes of the kept run-to-failure trajectory of a condition whose case is
/// `case`, run to `max_cycles` (`state/trajectory_<condition>.json`): the dynamic wear
/// study's nominal number of updates (it stops earlier at the wear limit; the threshold
/// may shorten its blocks, `app::dataset::plan` adds the margin) of 4 G + 2 S_d + 48
/// numbers each (wear and increment profiles; the load along the path of contact, about
/// two samples a step over the period, measured 241 and 365 at 60 and 200 grid steps;
/// the periodic state and the summary), plus 2 (z1 + z2) G per-tooth profiles when the
/// teeth differ; a train's N meshes N times that with each mesh's path over the train's
/// base period, plus its larger periodic state.
pub fn trajectory_bytes(case: &crate::config::Case, max_cycles: f64) -> f64 {
    let mut case = case.clone();
    case.wear.total_cycles = max_cycles;
    if case.planetary.is_some() {
        // A set keeps its 2 N meshes' records (`study::dataset::planetary`): each its
        // wear and increment on both flanks (4 G numbers) and its summary (about 40), no
        // path loads; and the update's input cycles.
        let Ok(m) = crate::study::planetary_wear::PlanetaryWearModel::from_case(&case) else {
            return 0.0;
        };
        let updates = super::planetary::planetary_wear_updates(&m, &case.wear);
        let grid = case.wear.points_per_profile.max(2) as f64;
        let meshes = 2.0 * m.planets() as f64;
        // With a tooth fault each mesh meeting the faulty member also keeps its z teeth's
        // rates (z G numbers: docs/MODEL.md 12.16).
        let teeth = super::planetary::tooth_rate_numbers(&m);
        return updates
            * (meshes * (4.0 * grid + 40.0) + teeth + 1.0)
            * TRAJECTORY_BYTES_PER_NUMBER;
    }
    let updates = estimate(
        &case,
        Job::Wear {
            dynamic: true,
            quasi_static: false,
        },
    )
    .wear_updates_dynamic;
    let grid = case.wear.points_per_profile as f64;
    let s_dyn = super::evaluation::dynamic_steps_per_period(&case.numerics);
    let teeth = if super::teeth::excitation_periods_of(&case) > 1 {
        2.0 * (case.gear.teeth_pinion + case.gear.teeth_gear).max(0) as f64 * grid
    } else {
        0.0
    };
    // A train keeps every mesh's records (`study::dataset::trajectory`), stage 1's with
    // the train's periodic state: 2 (4 + 12 N) numbers for N stages (`budget::train_factor`);
    // each mesh's load along its path is sampled over the train's base period, sum_k N_k
    // mesh periods (measured on the two-stage example, 31 + 23: 16733 samples against
    // 2 S_d 54 = 16740).
    let stages = case.stage.len();
    let per_update = if stages == 0 {
        4.0 * grid + 2.0 * s_dyn + 48.0 + teeth
    } else {
        let n = stages as f64;
        let periods = super::evaluation::base_mesh_periods(&case);
        n * (4.0 * grid + 2.0 * s_dyn * periods + 48.0) + 2.0 * (4.0 + 12.0 * n)
    };
    updates * per_update * TRAJECTORY_BYTES_PER_NUMBER
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::input::InputError;

    #[test]
    fn a_folder_check_counts_the_states_its_sample_recomputes() {
        // 4 physical states (4 cycle counts, one speed, one realisation), all kept.
        let no_file = |p: &str| -> Result<String, InputError> {
            Err(InputError {
                path: p.into(),
                reason: "none".into(),
            })
        };
        let text = "[run_to_failure]\ncycles = [0, 1e3, 2e3, 3e3]\nmax_cycles = 4e3\n";
        let d = crate::study::dataset::parse_design(text, "d.toml", &no_file).unwrap();
        let kept = KeptRecords {
            records: 4.0,
            states: 4.0,
        };
        let record = RecordSize {
            samples: 25_600.0,
            channels: 2.0,
        };
        let recomputed = |sample: usize| {
            let e = estimate_folder_check(&d, kept, sample, 1, record);
            (e.terms[1].seconds, e.terms[2].seconds)
        };
        // `verify_folder` recomputes the first and the last state with a sample of 0 or 1
        // (`states_to_recompute`), as with 2; all 4 with 8: twice the states of 2.
        let (two, checked_two) = recomputed(2);
        assert!(two > 0.0);
        assert_eq!(recomputed(0), (two, checked_two));
        assert_eq!(recomputed(1), (two, checked_two));
        let (all, checked_all) = recomputed(8);
        assert!((all / two - 2.0).abs() < 1e-12, "{all} {two}");
        // The recomputed states' records are not read back again: 2 of 4 with two
        // recomputed, none with all four.
        assert!(checked_two > 0.0 && checked_all == 0.0);
    }
}
