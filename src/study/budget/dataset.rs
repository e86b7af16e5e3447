//! The cost of `dataset`: its run-to-failure trajectories and its physical states (the
//! disk has its own budget, checked with the design).

use super::case_jobs::{estimate, Job};
use super::cost::{Estimate, Term, BASE_BYTES};
use crate::study::dataset::plan::{plan_of, Shard};
use crate::study::dataset::DatasetDesign;

/// The cost of (a shard of) a dataset against the run budget, before anything is
/// computed (the disk has its own budget): each condition's run-to-failure trajectory
/// costs at most a dynamic wear study to `max_cycles` (it stops earlier at the wear
/// limit), each physical state of the shard one dynamic evaluation at its speed and load
/// (the costliest of the lowest and highest speed and load of its condition). Memory: the
/// costliest single study on each of `threads` threads.
pub fn estimate_dataset(d: &DatasetDesign, shard: Shard, threads: usize) -> Estimate {
    let states = plan_of(d).shard_states(shard).len() as f64;
    let ends = |v: &[f64]| {
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        [lo, hi]
    };
    let (mut trajectories_s, mut state_s, mut bytes) = (0.0, 0.0f64, 0.0f64);
    for c in &d.conditions {
        let mut case = c.case.clone();
        case.wear.total_cycles = d.max_cycles;
        let w = estimate(
            &case,
            Job::Wear {
                dynamic: true,
                quasi_static: false,
            },
        );
        trajectories_s += w.seconds();
        bytes = bytes.max(w.memory_bytes());
        for speed in ends(&d.speeds_hz) {
            for torque in ends(&d.torques_nm) {
                let mut case = c.case.clone();
                case.set_load_point(crate::config::case::LoadPoint {
                    input_speed_hz: speed,
                    load_torque_nm: torque,
                    ..case.load_point()
                });
                let e = estimate(&case, Job::Dynamics);
                state_s = state_s.max(e.seconds());
                bytes = bytes.max(e.memory_bytes());
            }
        }
    }
    Estimate::of_terms(vec![
        Term {
            what: "the conditions' run-to-failure trajectories",
            seconds: trajectories_s,
            bytes: 0.0,
            keys: &["run_to_failure.max_cycles", "the conditions' wear keys"],
        },
        Term {
            what: "the physical states' dynamic evaluations",
            seconds: states * state_s,
            bytes: threads.max(1) as f64 * (bytes - BASE_BYTES),
            keys: &[
                "the number of conditions, states, speeds and loads",
                "the conditions' numerics keys",
            ],
        },
    ])
}
