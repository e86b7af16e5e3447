//! Per-tooth inputs are judged by their effect: a `[[fault]]` crack of zero depth, zero
//! pitch errors, zero run-out, zero reliefs, a zero user profile deviation leave every
//! tooth perfect, so the case is the identical-teeth case: the same path through the
//! model, the same load-sharing law (paper eq. 7 under "auto"), and the same outputs,
//! byte for byte.

mod common;
use common::{ok, snapshot};
use gearwear::config::load_case;
use gearwear::study::Model;
use std::path::{Path, PathBuf};

/// Per-tooth inputs that change no tooth (TOML of a case file), by name.
const NO_EFFECT: [(&str, &str); 5] = [
    (
        "zero-depth crack",
        "[[fault]]\nkind = \"crack\"\ngear = \"pinion\"\ntooth = 4\ncrack_depth_mm = 0.0\n",
    ),
    (
        "zero pitch errors and run-out",
        "[teeth]\npitch_error_pinion_um = [0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]\nrunout_gear_um = 0.0\nrunout_gear_phase_deg = 30.0\nprofile_slope_pinion_um = [0.0]\n",
    ),
    (
        "zero tip and root relief",
        "[modification]\ntip_relief_um = 0.0\ntip_relief_length_mm = 1.0\nroot_relief_um = 0.0\nroot_relief_length_mm = 0.5\nshape = \"parabolic\"\n",
    ),
    (
        "zero user profile deviation",
        "[modification]\nprofile_roll_pinion_deg = [10.0, 30.0]\nprofile_deviation_pinion_um = [0.0, 0.0]\n",
    ),
    (
        "all of them",
        "[teeth]\npitch_error_gear_um = [0.0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]\n[modification]\ntip_relief_um = 0.0\ntip_relief_length_mm = 1.0\n[[fault]]\nkind = \"crack\"\ngear = \"gear\"\ntooth = 0\ncrack_depth_mm = 0.0\ncrack_angle_deg = 30.0\n",
    ),
];

#[test]
fn inputs_that_change_no_tooth_leave_the_identical_teeth_model() {
    for (name, toml) in NO_EFFECT {
        let case = load_case(toml, &[]).unwrap();
        assert!(!case.has_per_tooth_inputs(), "{name}");
        let model = Model::from_case(&case).unwrap();
        assert!(
            model.teeth.is_none(),
            "{name}: the model resolved the teeth"
        );
        assert!(
            model.warnings.iter().all(|w| !w.contains("load_sharing")),
            "{name}: {:?}",
            model.warnings
        );
    }
    // The same inputs with an effect do resolve the teeth (the judgement can fail).
    for toml in [
        "[[fault]]\nkind = \"crack\"\ngear = \"pinion\"\ntooth = 4\ncrack_depth_mm = 0.1\n",
        "[teeth]\nrunout_gear_um = 0.5\n",
        "[modification]\ntip_relief_um = 1.0\ntip_relief_length_mm = 1.0\n",
        "[modification]\nprofile_roll_pinion_deg = [10.0, 30.0]\nprofile_deviation_pinion_um = [0.0, 0.5]\n",
    ] {
        let case = load_case(toml, &[]).unwrap();
        assert!(case.has_per_tooth_inputs(), "{toml}");
        assert!(Model::from_case(&case).unwrap().teeth.is_some(), "{toml}");
    }
}

/// The summary without the `metadata` that echoes the inputs (the case as given, its
/// hash), which of course differ.
fn summary_without_inputs(path: &Path) -> serde_json::Value {
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v.as_object_mut().unwrap().remove("metadata");
    v
}

/// Every output of `command` for the case file `case` (None: the built-in case).
fn outputs(command: &str, case: Option<&Path>, out: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let o = out.to_str().unwrap();
    let mut args = vec![command, "--out", o, "-q"];
    if let Some(c) = case {
        args.extend(["--config", c.to_str().unwrap()]);
    }
    ok(&args);
    snapshot(out)
        .into_iter()
        .map(|(p, b)| (p.strip_prefix(out).unwrap().to_path_buf(), b))
        .collect()
}

#[test]
fn inputs_that_change_no_tooth_give_the_identical_teeth_outputs_byte_for_byte() {
    let dir = tempfile::tempdir().unwrap();
    for command in ["dynamics", "signals", "stiffness"] {
        let reference = outputs(command, None, &dir.path().join(command));
        for (i, (name, toml)) in NO_EFFECT.iter().enumerate() {
            let file = dir.path().join(format!("case{i}.toml"));
            std::fs::write(&file, toml).unwrap();
            let got = outputs(
                command,
                Some(&file),
                &dir.path().join(format!("{command}{i}")),
            );
            assert_eq!(
                got.iter().map(|(p, _)| p).collect::<Vec<_>>(),
                reference.iter().map(|(p, _)| p).collect::<Vec<_>>(),
                "{command}, {name}: other files"
            );
            for ((path, a), (_, b)) in got.iter().zip(&reference) {
                let file = path.to_string_lossy();
                if file == "manifest.json" || file.starts_with(".gearwear") {
                    // The manifest lists the files with their hashes (the summary's
                    // differ: inputs); the hidden state and lock files record the
                    // folder's inodes.
                    continue;
                }
                if file == "summary.json" {
                    assert_eq!(
                        summary_without_inputs(
                            &dir.path().join(format!("{command}{i}")).join(path)
                        ),
                        summary_without_inputs(&dir.path().join(command).join(path)),
                        "{command}, {name}: summary"
                    );
                    continue;
                }
                assert!(a == b, "{command}, {name}: {file} differs");
            }
        }
    }
}
