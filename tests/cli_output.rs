//! How the command line writes: results on standard output (not with --quiet), one
//! published set per folder with a manifest, output-folder problems named with exit 2.

use std::path::Path;
use std::process::{Command, Output};

fn gearwear(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args(args)
        .output()
        .expect("binary runs")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn p(path: &Path) -> &str {
    path.to_str().unwrap()
}

#[test]
fn results_go_to_stdout_and_quiet_drops_them() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("s");
    let o = gearwear(&["stiffness", "--out", p(&out)]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    // The headline states the contact ratio of the paper's pair (1.6022, docs/MODEL.md).
    assert!(
        text(&o.stdout).contains("contact ratio 1.602"),
        "{}",
        text(&o.stdout)
    );
    let q = gearwear(&["stiffness", "--quiet", "--out", p(&out)]);
    assert_eq!(q.status.code(), Some(0));
    assert!(q.stdout.is_empty(), "{}", text(&q.stdout));
}

#[test]
fn the_manifest_lists_every_output_with_its_checksum() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("s");
    assert!(gearwear(&["stiffness", "-q", "--out", p(&out)])
        .status
        .success());
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("manifest.json")).unwrap()).unwrap();
    let files = m["files"].as_array().unwrap();
    // Every file of the folder but the manifest itself and the folder's own hidden state
    // and lock (listed as `state_files` when a run keeps any), and nothing else.
    let mut on_disk: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n != "manifest.json" && !n.starts_with('.'))
        .collect();
    on_disk.sort();
    let mut listed: Vec<String> = files
        .iter()
        .map(|f| f["path"].as_str().unwrap().to_owned())
        .collect();
    listed.sort();
    assert_eq!(listed, on_disk, "{m}");
    assert!(listed.len() >= 3, "{m}");
    for f in files {
        let bytes = std::fs::read(out.join(f["path"].as_str().unwrap())).unwrap();
        assert_eq!(f["bytes"].as_u64().unwrap(), bytes.len() as u64);
        assert_eq!(
            f["sha256"].as_str().unwrap(),
            gearwear::io::output_dir::sha256_hex(&bytes)
        );
    }
}

#[test]
fn an_output_path_that_is_a_file_is_named_with_exit_2() {
    let d = tempfile::tempdir().unwrap();
    let file = d.path().join("taken");
    std::fs::write(&file, b"x").unwrap();
    let o = gearwear(&["stiffness", "--out", p(&file)]);
    assert_eq!(o.status.code(), Some(2));
    let e = text(&o.stderr);
    assert!(e.contains(p(&file)) && e.contains("not a folder"), "{e}");
}

#[test]
fn resume_without_a_checkpoint_is_an_error_that_says_so() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    let o = gearwear(&["wear", "--resume", "--out", p(&out)]);
    assert_eq!(o.status.code(), Some(2));
    let e = text(&o.stderr);
    assert!(e.contains("no checkpoint") && e.contains(p(&out)), "{e}");
    assert!(!out.exists(), "nothing is written for a rejected command");
}

#[test]
fn a_rerun_with_fewer_modes_leaves_no_files_of_the_earlier_run() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    let short = ["--set", "wear.total_cycles=2000", "-q", "--out", p(&out)];
    let run = |mode: &str| {
        let mut a = vec!["wear", "--mode", mode];
        a.extend(short);
        assert!(gearwear(&a).status.success());
    };
    run("both");
    assert!(out.join("updates_quasi_static.csv").exists());
    run("dynamic");
    for f in [
        "updates_quasi_static.csv",
        "wear_profiles_quasi_static.csv",
        "checkpoint_quasi_static.jsonl",
    ] {
        assert!(!out.join(f).exists(), "{f} of the earlier run left behind");
    }
    assert!(out.join("updates_dynamic.csv").exists());
}

#[test]
fn a_transmission_error_over_part_of_a_mesh_period_is_refused() {
    // 5 deg of the 18.95 deg mesh period of the paper's 19-tooth pinion.
    let d = tempfile::tempdir().unwrap();
    let te = d.path().join("te.csv");
    std::fs::write(&te, "pinion_angle_deg,error_um\n0,1\n2.5,2\n5,1\n").unwrap();
    let out = d.path().join("d");
    let o = gearwear(&["dynamics", "--transmission-error", p(&te), "--out", p(&out)]);
    assert_eq!(o.status.code(), Some(2));
    let e = text(&o.stderr);
    assert!(e.contains("te.csv") && e.contains("mesh period"), "{e}");
    assert!(!out.exists());
}
