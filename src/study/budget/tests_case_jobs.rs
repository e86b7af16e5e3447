//! Unit tests of `case_jobs`: the cost of the commands that run one case.

use super::*;
use crate::config::load_case;
use crate::study::budget::Budget;

fn case(sets: &[&str]) -> Case {
    crate::config::load::default_with(sets)
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
    // Run: 1 wear study of U updates (the first cold, U - 1 warm) plus 3 wear states
    // (cold), twice for the paper's case (its contact twin); ten bins (no longer the
    // paper's case): 10 studies and 3 wear states, and the life runs: 10 bins under the
    // spectrum and 10 alone, 10 um / 0.5 um + 1 updates each, the first cold.
    let u = one.wear_updates_dynamic;
    let ratio = dyn_s(&e) / dyn_s(&one);
    use super::super::steady_states::evaluations_seconds;
    let want = evaluations_seconds(
        &ten,
        10.0 + 3.0 + 20.0,
        10.0 * (u - 1.0) + 20.0 * 20.0,
        10.0 * u + 20.0 * 21.0,
    ) / evaluations_seconds(
        &Case::default(),
        2.0 * (1.0 + 3.0),
        2.0 * (u - 1.0),
        2.0 * u,
    );
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
        .unwrap_err()
        .to_string();
    assert!(msg.contains("load_spectrum.bins"), "{msg}");
}

#[test]
fn the_paper_case_s_run_counts_its_contact_twin() {
    // `gearwear run` of the paper's case runs the study a second time under the other
    // contact model; with Pedrero's law given (which the corner contact refuses) it
    // does not, and nothing else in the estimate depends on the sharing law: the
    // dynamic evaluations halve exactly.
    let seconds = |e: &Estimate| {
        e.terms
            .iter()
            .find(|t| t.what == "the dynamic evaluations")
            .unwrap()
            .seconds
    };
    let twin = estimate(&case(&[]), Job::Run);
    let alone = estimate(
        &case(&["contact.path=nominal", "contact.load_sharing=pedrero"]),
        Job::Run,
    );
    let ratio = seconds(&twin) / seconds(&alone);
    assert!((ratio - 2.0).abs() < 1e-12, "{ratio}");
    // `wear` runs no twin.
    let w = Job::Wear {
        dynamic: true,
        quasi_static: true,
    };
    let (a, b) = (
        estimate(&case(&[]), w),
        estimate(
            &case(&["contact.path=nominal", "contact.load_sharing=pedrero"]),
            w,
        ),
    );
    assert_eq!(seconds(&a), seconds(&b));
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
            .expect_err(&format!("{sets:?}"))
            .to_string();
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
