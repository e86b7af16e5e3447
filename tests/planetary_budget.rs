//! The run budget of a planetary set's wear study (`study::budget::planetary`): the
//! updates it counts before the run bound the updates the run makes (each run's own
//! history is the independent count), and a study over the budget is refused with exit 2
//! before its folder exists.

mod common;
use common::{gearwear, stderr};
use gearwear::config::load_case;
use gearwear::study::budget::planetary::planetary_wear_updates;
use gearwear::study::planetary_wear::PlanetaryWearModel;
use gearwear::study::planetary_wear_loop::{run_planetary_wear, PlanetaryWearRun};
use gearwear::study::wear_loop::WearMode;

fn counted_and_made(sets: &[&str], mode: WearMode) -> (f64, usize) {
    let mut all = vec!["wear.total_cycles=4e4".to_string()];
    all.extend(sets.iter().map(|s| s.to_string()));
    let case = load_case("[planetary]\n", &all).unwrap();
    let model = PlanetaryWearModel::from_case(&case).unwrap();
    let counted = planetary_wear_updates(&model, &case.wear);
    let run = run_planetary_wear(&model, &case.wear, PlanetaryWearRun::new(mode), &mut |_| {
        Ok(())
    })
    .unwrap();
    (counted, run.updates.len())
}

#[test]
fn the_counted_updates_bound_the_runs_updates() {
    // The block limit alone (m cycles), the threshold cutting every block (0.02 µm, with
    // the dynamic loads above the static ones), and a heavier load.
    for (sets, mode) in [
        (vec![], WearMode::Dynamic),
        (vec!["wear.threshold_um=0.02"], WearMode::QuasiStatic),
        (vec!["wear.threshold_um=0.02"], WearMode::Dynamic),
        (
            vec!["wear.threshold_um=0.02", "operating.load_torque_nm=200"],
            WearMode::QuasiStatic,
        ),
    ] {
        let (counted, made) = counted_and_made(&sets, mode);
        assert!(
            counted >= made as f64,
            "{sets:?} {mode:?}: counted {counted} updates, the run made {made}"
        );
        // Not a vacuous bound: the rate margin (2) times the running-in (the first
        // rate falls about twofold as the flanks run in; docs/RELIABILITY.md), plus a
        // block's rounding.
        assert!(
            counted <= 4.0 * made as f64 + 2.0,
            "{sets:?} {mode:?}: counted {counted} updates, the run made {made}"
        );
    }
}

#[test]
fn a_planetary_wear_study_over_the_budget_is_refused_before_its_folder() {
    let d = tempfile::tempdir().unwrap();
    let case = d.path().join("set.toml");
    std::fs::write(&case, "[planetary]\n").unwrap();
    let out = d.path().join("out");
    let o = gearwear(&[
        "wear",
        "--config",
        case.to_str().unwrap(),
        "--set",
        "wear.total_cycles=1e9",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("over its budget") && e.contains("planetary set's wear updates"),
        "{e}"
    );
    assert!(!out.exists(), "the refusal created {}", out.display());
}
