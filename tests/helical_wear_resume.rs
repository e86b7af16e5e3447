//! `gearwear wear --resume` on a helical pair (docs/MODEL.md 11.3): a run whose logs were
//! cut (as a kill between two appends leaves them) resumes to the bytes of an
//! uninterrupted run, and a log whose per-slice wear was edited, its checksum recomputed,
//! is refused with exit 2 naming the line, the update and the face slice: every record's
//! slice wear must be its previous wear advanced over the recomputed block, not only the
//! records the resume recomputes.

mod common;
use common::resume::{cut_log, cut_then_resumed_is_unchanged, edit_update, refused, run};
use std::path::Path;

/// A small helical case (15 deg, 6 slices) with a wear threshold of 0.05 µm, so that its
/// run to 3e4 cycles has more updates than the resume recomputes (16): a record left out
/// of the recomputed sample is checked only by the chain.
fn args(mode: &str, out: &Path) -> Vec<String> {
    let mut a: Vec<String> = ["-q", "wear", "--mode", mode]
        .iter()
        .map(|s| s.to_string())
        .collect();
    for s in [
        "gear.helix_angle_deg=15",
        "stiffness.slices=6",
        "wear.total_cycles=3e4",
        "wear.threshold_um=0.05",
    ] {
        a.extend(["--set".to_string(), s.to_string()]);
    }
    a.extend(["--out".to_string(), out.to_str().unwrap().to_string()]);
    a
}

#[test]
fn a_cut_helical_run_resumes_to_the_bytes_of_an_uninterrupted_one() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    let cut = |out: &Path| {
        cut_log(&out.join("checkpoint_dynamic.jsonl"), 3, true);
        cut_log(&out.join("checkpoint_quasi_static.jsonl"), 5, false);
    };
    cut_then_resumed_is_unchanged(&args("both", &out), &out, &cut);
}

/// Add `by` (m) to the largest value of face slice `slice`'s pinion wear in update `at` of
/// the log `path`, the line's checksum recomputed (what a forger does); the mean profiles
/// are left as they were.
fn forge_slice(path: &Path, at: usize, slice: usize, by: f64) {
    edit_update(path, at, true, &|v| {
        let p = v
            .pointer_mut(&format!("/wear/slices/pinion_m/{slice}"))
            .expect("per-slice wear in the log")
            .as_array_mut()
            .unwrap();
        let k = (0..p.len())
            .max_by(|a, b| p[*a].as_f64().unwrap().total_cmp(&p[*b].as_f64().unwrap()))
            .unwrap();
        let y = p[k].as_f64().unwrap();
        assert!(y > 0.0, "slice {slice} of update {at} has not worn");
        p[k] = serde_json::json!(y + by);
    });
}

#[test]
fn a_forged_slice_value_is_refused_naming_the_line_and_the_slice() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("w");
    let a = args("quasi-static", &out);
    let o = run(&a);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let log = out.join("checkpoint_quasi_static.jsonl");
    let original = std::fs::read_to_string(&log).unwrap();
    let updates = original.lines().count() - 1;
    assert!(
        updates > 16 + 2,
        "{updates} updates: the resume would recompute them all"
    );
    // A middle update and the last one (always recomputed), each by 1 nm on slice 2
    // (a part in a thousand of the wear, far above any round-off: the chain is exact).
    for at in [updates / 2, updates - 1] {
        std::fs::write(&log, &original).unwrap();
        forge_slice(&log, at, 2, 1e-9);
        refused(
            &a,
            "a forged slice value",
            &[
                "checkpoint_quasi_static.jsonl",
                &format!("line {} (update {at})", at + 2),
                "face slice 2",
                "per-slice chain",
            ],
        );
    }
}
