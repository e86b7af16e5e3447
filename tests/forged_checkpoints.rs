//! Forged checkpoints (issues 21 and 22): checkpoints of other cases under this case's
//! header, and same-case edits whose line checksums are recomputed, so that only the
//! recomputation of updates can catch them. Each must be refused with exit 2, naming the
//! file and the line, and leave the folder's published results as they were.

mod common;

use common::{gearwear, stderr};
use std::path::Path;

fn sha(text: &str) -> String {
    gearwear::io::output_dir::sha256_hex(text.as_bytes())
}

fn wear(out: &Path, sets: &[&str], extra: &[&str]) -> std::process::Output {
    let mut a = vec![
        "wear",
        "--mode",
        "dynamic",
        "-q",
        "--set",
        "wear.total_cycles=2e4",
        "--out",
        out.to_str().unwrap(),
    ];
    for s in sets {
        a.extend(["--set", s]);
    }
    a.extend(extra);
    gearwear(&a)
}

/// A checkpoint as lines of (checksum, JSON).
fn lines(path: &Path) -> Vec<(String, String)> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .map(|l| {
            let (s, j) = l.split_once(' ').unwrap();
            (s.to_owned(), j.to_owned())
        })
        .collect()
}

/// Lines back to text, every checksum recomputed (what a forger does).
fn forged(lines: &[(String, String)]) -> String {
    lines
        .iter()
        .map(|(_, j)| format!("{} {j}\n", sha(j)))
        .collect()
}

/// Edit record `i` (0-based, after the header) with `f`, checksums recomputed.
fn edit(base: &[(String, String)], i: usize, f: &dyn Fn(&mut serde_json::Value)) -> String {
    let mut l = base.to_vec();
    let mut v: serde_json::Value = serde_json::from_str(&l[i + 1].1).unwrap();
    f(&mut v);
    l[i + 1].1 = serde_json::to_string(&v).unwrap();
    forged(&l)
}

fn scale(v: &mut serde_json::Value, by: f64) {
    *v = serde_json::json!(v.as_f64().unwrap() * by);
}

#[test]
fn twenty_two_forged_checkpoints_are_refused_naming_the_line() {
    let d = tempfile::tempdir().unwrap();
    let a = d.path().join("a");
    assert!(wear(&a, &[], &[]).status.success());
    let ck = a.join("checkpoint_dynamic.jsonl");
    let base = lines(&ck);
    let n = base.len() - 1;
    assert!(n >= 4, "a run of a few updates ({n})");
    let published: Vec<(String, Vec<u8>)> = ["summary.json", "updates_dynamic.csv"]
        .iter()
        .map(|p| (p.to_string(), std::fs::read(a.join(p)).unwrap()))
        .collect();
    let mut forgeries: Vec<(String, String)> = Vec::new();
    // Checkpoints of five other operating points or parameters and another threshold:
    // their records under A's header (no forging needed), and their whole file with the
    // header rewritten to A's case.
    for set in [
        "operating.input_speed_hz=35",
        "operating.load_torque_nm=50",
        "wear.coefficient_m2_per_n=3e-16",
        "dynamics.mesh_damping_ratio=0.07",
        "friction.model=\"constant\"",
        "wear.threshold_um=0.4",
    ] {
        let b = d.path().join(format!("b{}", forgeries.len()));
        let r = wear(&b, &[set], &[]);
        assert!(r.status.success(), "{set}: {}", stderr(&r));
        let other = lines(&b.join("checkpoint_dynamic.jsonl"));
        let mut mixed = base[..1].to_vec();
        mixed.extend_from_slice(&other[1..]);
        let text: String = mixed.iter().map(|(s, j)| format!("{s} {j}\n")).collect();
        forgeries.push((format!("A's header, {set} records"), text));
        let mut whole = other.clone();
        whole[0] = base[0].clone();
        forgeries.push((format!("{set}, header forged to A's"), forged(&whole)));
    }
    // Same-case edits with recomputed checksums.
    let last = n - 1;
    type Edit = Box<dyn Fn(&mut serde_json::Value)>;
    let edits: Vec<(&str, usize, Edit)> = vec![
        (
            "last end state",
            last,
            Box::new(|v| scale(&mut v["end_state"][0], 1.0 + 1e-9)),
        ),
        (
            "last summary DTE",
            last,
            Box::new(|v| scale(&mut v["summary"]["dte_max_m"], 1.01)),
        ),
        (
            "last mesh force",
            last,
            Box::new(|v| scale(&mut v["summary"]["mesh_force_mean_n"], 1.001)),
        ),
        (
            "last path loads",
            last,
            Box::new(|v| scale(&mut v["path_load_n"][10], 0.9)),
        ),
        (
            "last increments",
            last,
            Box::new(|v| {
                for x in v["increment_pinion_m"].as_array_mut().unwrap() {
                    *x = serde_json::json!(x.as_f64().unwrap() * 0.5);
                }
            }),
        ),
        (
            "first summary",
            0,
            Box::new(|v| scale(&mut v["summary"]["dte_max_m"], 0.99)),
        ),
        (
            "middle summary",
            n / 2,
            Box::new(|v| scale(&mut v["summary"]["velocity_y_pinion_rms_m_per_s"], 1.05)),
        ),
        (
            "middle end state",
            n / 2,
            Box::new(|v| scale(&mut v["end_state"][3], 1.1)),
        ),
    ];
    for (what, i, f) in &edits {
        forgeries.push((what.to_string(), edit(&base, *i, f.as_ref())));
    }
    // A spliced tail: A's records, then the last record of the 35 Hz run.
    let other = lines(&d.path().join("b0").join("checkpoint_dynamic.jsonl"));
    let mut spliced = base[..n].to_vec();
    spliced.push(other[other.len() - 1].clone());
    forgeries.push(("spliced tail".into(), forged(&spliced)));
    // The last record dropped and the one before it copied in its place, cycles moved on.
    let mut copied = base[..n].to_vec();
    let mut v: serde_json::Value = serde_json::from_str(&base[n - 1].1).unwrap();
    let c = v["wear"]["cycles"].as_f64().unwrap();
    v["wear"]["cycles"] = serde_json::json!(c + 1.0);
    copied.push((String::new(), serde_json::to_string(&v).unwrap()));
    forgeries.push(("last record copied".into(), forged(&copied)));
    assert_eq!(forgeries.len(), 22);

    let original = std::fs::read(&ck).unwrap();
    for (what, text) in &forgeries {
        std::fs::write(&ck, text).unwrap();
        let r = wear(&a, &[], &["--resume"]);
        let e = stderr(&r);
        assert_eq!(r.status.code(), Some(2), "{what}: resumed: {e}");
        assert!(
            e.contains("checkpoint_dynamic.jsonl"),
            "{what}: names the file: {e}"
        );
        assert!(
            e.contains("line ") || e.contains("update "),
            "{what}: names the line: {e}"
        );
        assert!(!e.contains("panicked"), "{e}");
        for (p, bytes) in &published {
            assert_eq!(
                &std::fs::read(a.join(p)).unwrap(),
                bytes,
                "{what}: {p} changed"
            );
        }
    }
    // The true checkpoint still resumes.
    std::fs::write(&ck, &original).unwrap();
    let r = wear(&a, &[], &["--resume"]);
    assert!(r.status.success(), "{}", stderr(&r));
}

/// Under a load spectrum each bin has its own log: case A's headers kept, case B's records
/// (another wear coefficient) appended to every bin's log, each line's checksum valid.
#[test]
fn spectrum_bin_logs_of_another_case_are_refused() {
    let d = tempfile::tempdir().unwrap();
    let case = d.path().join("two.toml");
    std::fs::write(
        &case,
        "[load_spectrum]\nbins = [{torque_nm = 40, input_speed_hz = 20, share = 0.5}, {torque_nm = 60, input_speed_hz = 30, share = 0.5}]\n",
    )
    .unwrap();
    let config = ["--config", case.to_str().unwrap()];
    let (a, b) = (d.path().join("a"), d.path().join("b"));
    assert!(wear(&a, &[], &config).status.success());
    let other = wear(&b, &["wear.coefficient_m2_per_n=3e-16"], &config);
    assert!(other.status.success(), "{}", stderr(&other));
    let published = std::fs::read(a.join("updates_dynamic.csv")).unwrap();
    for bin in [1, 2] {
        let name = format!("checkpoint_dynamic_bin{bin}.jsonl");
        let (la, lb) = (lines(&a.join(&name)), lines(&b.join(&name)));
        let mut spliced = vec![la[0].clone()];
        spliced.extend(lb[1..].iter().cloned());
        let text: String = spliced.iter().map(|(s, j)| format!("{s} {j}\n")).collect();
        std::fs::write(a.join(&name), text).unwrap();
    }
    let o = wear(&a, &[], &[&config[..], &["--resume"]].concat());
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("cannot be resumed") && e.contains("line"), "{e}");
    assert_eq!(
        std::fs::read(a.join("updates_dynamic.csv")).unwrap(),
        published
    );
}
