//! The run budget's memory for a gear train's recorded response, against the rows the
//! `dynamics` command really records. A train records whole base periods (the first
//! mesh's 31 periods of the 19/31 then 23/47 reducer hold the 4 evaluated ones), each
//! sampled on the grid of its most frequent mesh, not the sum of its meshes' periods;
//! counting 4 base periods of the summed meshes over-counted 15 x and refused the
//! reducer's wear with one cracked tooth (2.15 GB estimated against 0.76 GB of peak
//! resident memory measured with `/usr/bin/time`).

mod common;

use common::run_into;
use gearwear::config::load_case;
use gearwear::study::budget::{estimate, Job};

/// The reducer of `examples/two_stage_reducer.toml`'s shape (19/31 then 23/47, 60 N m).
const REDUCER: &str = "[operating]\ninput_speed_hz = 30\nload_torque_nm = 60\nload_torque_shaft = \"pinion\"\n\n[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n\n[[stage]]\nmodule_mm = 2.5\nteeth_pinion = 23\nteeth_gear = 47\nface_width_mm = 25\n";

/// A crack at the root of stage 1's pinion tooth 3 (the train's period grows to 19
/// base periods: every pinion tooth meets every intermediate-shaft turn).
const CRACK: &str = "\n[[fault]]\nstage = 1\ngear = \"pinion\"\ntooth = 3\nkind = \"crack\"\ncrack_depth_mm = 0.8\n";

/// Largest resident memory of any child this test process has waited for, bytes
/// (`getrusage(RUSAGE_CHILDREN)`'s `ru_maxrss`, in kB on Linux).
fn children_peak_bytes() -> f64 {
    // SAFETY: getrusage writes the struct it is given and nothing else.
    let mut u: libc::rusage = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { libc::getrusage(libc::RUSAGE_CHILDREN, &mut u) }, 0);
    u.ru_maxrss as f64 * 1024.0
}

#[test]
#[cfg(target_os = "linux")]
fn a_trains_memory_is_counted_within_a_few_times_its_measured_peak() {
    let d = tempfile::tempdir().unwrap();
    // Healthy first: the children's peak so far is then each run's own (the cracked
    // train holds 19 times the record).
    for (name, text, job) in [
        ("healthy", REDUCER.to_string(), "dynamics"),
        ("cracked", format!("{REDUCER}{CRACK}"), "dynamics"),
        ("cracked_wear", format!("{REDUCER}{CRACK}"), "wear"),
    ] {
        let config = d.path().join(format!("{name}.toml"));
        std::fs::write(&config, &text).unwrap();
        let mut command = vec![job];
        let mut sets = vec![];
        if job == "wear" {
            command.extend(["--mode", "dynamic"]);
            sets.push("wear.total_cycles=2e4");
        }
        run_into(
            d.path(),
            name,
            &command,
            Some(config.to_str().unwrap()),
            &sets,
        );
        let peak = children_peak_bytes();
        let case = load_case(
            &text,
            &sets.iter().map(|s| s.to_string()).collect::<Vec<_>>(),
        )
        .unwrap();
        let job = match job {
            "wear" => Job::Wear {
                dynamic: true,
                quasi_static: false,
            },
            _ => Job::Dynamics,
        };
        let counted = estimate(&case, job).memory_bytes();
        // Never under the measured peak (the budget is a bound); over by at most 5 x (the
        // count takes the error-controlled steps' bound, 700 samples per mesh period at
        // 200 grid nodes, where the record holds about the grid's nodes, and the tables'
        // copies at their largest).
        assert!(
            counted >= peak && counted <= 5.0 * peak,
            "{name}: peak {peak:.3e} B measured, the budget counts {counted:.3e} B"
        );
    }
}
