//! Bad gear trains in a case file: each refused with exit code 2 before any work, the
//! message naming the stage, the key and what is wrong (the built binary).

mod common;
use common::rejected;

/// `stages` after an `[operating]` section, written to a case file in `dir`.
fn case_file(dir: &tempfile::TempDir, stages: &str) -> String {
    let path = dir.path().join("train.toml");
    let text = format!("[operating]\ninput_speed_hz = 30\nload_torque_nm = 60\n\n{stages}");
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

fn refused(stages: &str, needles: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let file = case_file(&dir, stages);
    rejected(&["dynamics", "--config", &file], needles)
}

const SECOND: &str = "[[stage]]\nteeth_pinion = 23\nteeth_gear = 47\n";

#[test]
fn a_stage_joined_to_nothing_is_refused() {
    // No shaft between stage 1's gear and stage 2's pinion: stage 2 floats free.
    refused(
        &format!("[[stage]]\n{SECOND}"),
        &[
            "stage 1",
            "`stage.shaft_torsional_stiffness_nm_per_rad` is required",
            "connected to nothing",
        ],
    );
    // A shaft after the last stage joins nothing.
    refused(
        &format!(
            "[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n{SECOND}shaft_torsional_stiffness_nm_per_rad = 2e5\n"
        ),
        &["stage 2 is the last", "`stage.shaft_torsional_*`", "remove it"],
    );
}

#[test]
fn a_centre_distance_the_stage_cannot_meet_names_the_stage_and_its_key() {
    // Below the sum of stage 1's base radii (2 mm x (19 + 31) / 2 x cos 20 deg = 46.98 mm).
    refused(
        &format!("[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\ncentre_distance_mm = 20\n{SECOND}"),
        &["stage 1", "`stage.centre_distance_mm` = 20", "46.98"],
    );
    // So far apart that stage 2's teeth never touch.
    refused(
        &format!("[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n{SECOND}centre_distance_mm = 500\n"),
        &["stage 2", "`stage.centre_distance_mm` = 500", "do not touch"],
    );
}

#[test]
fn a_stage_key_out_of_range_or_unknown_is_refused() {
    refused(
        &format!("[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n{SECOND}bearing_stiffness_gear_n_per_m = 1e3\n"),
        &[
            "`stage.bearing_stiffness_gear_n_per_m` = 1000",
            "[10000, 1e12]",
            "(stage 2)",
        ],
    );
    // The first stage is stage 1, as in the other stage messages.
    let msg = refused(
        &format!("[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\nbearing_stiffness_gear_n_per_m = 1e3\n{SECOND}"),
        &["`stage.bearing_stiffness_gear_n_per_m` = 1000", "(stage 1)"],
    );
    assert!(!msg.contains("(stage 0)"), "{msg}");
    refused(
        &format!("[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n{SECOND}bogus = 1\n"),
        &["unknown key `stage.bogus`"],
    );
}

#[test]
fn a_train_too_large_for_the_budget_is_refused_before_it_runs() {
    refused(
        &format!("[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n{SECOND}\n[numerics]\nsteps_per_mesh_period = 20000\n"),
        &["over its budget (nothing was computed)", "numerics.steps_per_mesh_period"],
    );
}

#[test]
fn a_train_over_the_budget_is_refused_by_its_own_estimate() {
    // The same train with a grid far over any study's budget. `run`, `signals`,
    // `calibrate` and `predict` take a train: each is refused by the train's estimate (its
    // wear and dynamics estimates for `run`, the dynamics one with the train's cost factor
    // for `signals`, the train's forward runs for `calibrate` and `predict`), before any
    // work.
    let dir = tempfile::tempdir().unwrap();
    let file = case_file(
        &dir,
        &format!("[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n{SECOND}\n[numerics]\nsteps_per_mesh_period = 20000\n"),
    );
    let obs = dir.path().join("obs.csv");
    std::fs::write(
        &obs,
        "cycles,stage,max_wear_pinion_um\n1e4,2,0.5\n2e4,2,1\n",
    )
    .unwrap();
    let obs = obs.to_str().unwrap();
    for args in [
        vec!["run"],
        vec!["signals"],
        vec!["calibrate", "--observations", obs],
        vec!["predict", "--limit-um", "10", "--cycles", "1e5"],
    ] {
        let mut all = args.clone();
        all.extend(["--config", &file]);
        let err = rejected(&all, &["over its budget"]);
        assert!(
            !err.contains("this case is a gear train"),
            "{args:?}: {err}"
        );
    }
}

#[test]
fn a_sweep_that_changes_the_number_of_stages_is_refused() {
    // Sweeps take a train, of dynamics and of wear (tests/train_sweep.rs), and so do
    // datasets (tests/train_dataset.rs); a sweep's columns are those of one train.
    // A varied stage key without a table number makes each case of a single pair a
    // one-stage train: the number of stages changes, refused naming the key and case.
    rejected(
        &["sweep", "--vary", "stage.teeth_pinion=20,21"],
        &[
            "case 0 (stage.teeth_pinion=20)",
            "[stage.teeth_pinion]",
            "number of stages",
        ],
    );
}

#[test]
fn a_helical_angle_on_a_train_is_refused_by_the_studies_on_its_wear_loop() {
    // `[gear]` is stage 1 of a train: a helix angle there makes every stage that does not
    // give its own helical (docs/MODEL.md 4.3). `gearwear dynamics` and `stiffness` take it
    // (tests/helical_train.rs); the studies on the train's wear loop refuse it by the key
    // the stage takes, and must not send the user to the studies of a helical pair alone.
    let dir = tempfile::tempdir().unwrap();
    let file = case_file(
        &dir,
        &format!("[gear]\nhelix_angle_deg = 10\n\n[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n{SECOND}"),
    );
    for study in ["wear", "run"] {
        rejected(
            &[study, "--config", &file],
            &[
                "`gear.helix_angle_deg` = 10 (stage 1's, from `[gear]`)",
                "gear train",
                "spur stages only so far",
            ],
        );
    }
}

#[test]
fn severe_wear_geometry_on_a_train_is_refused_by_its_wear_studies() {
    // A train's stages wear on the involute geometry (wear opens gaps, docs/MODEL.md 5.1):
    // `wear.worn_geometry` = "worn" would be ignored, so the wear studies refuse it by key.
    let dir = tempfile::tempdir().unwrap();
    let file = case_file(
        &dir,
        &format!("[wear]\nworn_geometry = \"worn\"\n\n[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n{SECOND}"),
    );
    for study in ["wear", "run"] {
        rejected(
            &[study, "--config", &file],
            &["`wear.worn_geometry` = \"worn\"", "gear train", "involute"],
        );
    }
}

#[test]
fn a_numbered_override_equals_the_same_key_written_in_the_case_file() {
    use gearwear::config::load_case;
    // Second method: the key written in stage 2's table of the file.
    let base = "[operating]\ninput_speed_hz = 30\n\n[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n[[stage]]\nteeth_pinion = 23\nteeth_gear = 47\n";
    let written = base.replace("teeth_pinion = 23", "teeth_pinion = 25");
    let by_set = load_case(base, &["stage.2.teeth_pinion=25".into()]).unwrap();
    assert_eq!(by_set, load_case(&written, &[]).unwrap());
    assert_ne!(by_set, load_case(base, &[]).unwrap());
    // Stage 1's shaft, by number, likewise.
    let stiff = load_case(
        base,
        &["stage.1.shaft_torsional_stiffness_nm_per_rad=1e6".into()],
    )
    .unwrap();
    let written = base.replace("= 2e5", "= 1e6");
    assert_eq!(stiff, load_case(&written, &[]).unwrap());
    // A table the case lacks, a section that is not numbered: refused, naming the range.
    for (set, needle) in [
        ("stage.3.teeth_pinion=25", "the case has 2 (valid: 1 to 2"),
        ("stage.0.teeth_pinion=25", "the case has 2 (valid: 1 to 2"),
        ("gear.2.module_mm=3", "[gear] is not a numbered section"),
    ] {
        let e = load_case(base, &[set.into()]).unwrap_err().to_string();
        assert!(e.contains(needle), "{set}: {e}");
    }
}
