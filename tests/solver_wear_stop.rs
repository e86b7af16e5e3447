//! A wear study never aborts for numerical reasons: when the worn teeth leave the model's
//! domain it stops, keeps its records, says why, and the CLI writes its outputs.

use gearwear::config::load_case;
use gearwear::study::wear_loop::{
    run_wear, StopKind, WearMode, WearRun, MAX_CONTACT_LOSS_FRACTION,
};
use gearwear::study::Model;
use std::process::Command;

/// The paper's case with 100 times the wear coefficient and a 5 um threshold: the pinion
/// wears 70 um deep (where the teeth fly apart for most of the period) in ~2e4 cycles
/// and ~20 updates instead of ~2e6 cycles and ~220 updates.
const FAST_WEAR: [&str; 3] = [
    "wear.coefficient_m2_per_n=2.5e-14",
    "wear.threshold_um=5",
    "wear.total_cycles=1e6",
];

#[test]
fn deep_wear_stops_the_run_with_its_records_and_the_reason() {
    let sets: Vec<String> = FAST_WEAR.iter().map(|s| s.to_string()).collect();
    let m = Model::from_case(&load_case("", &sets).unwrap()).unwrap();
    let mut seen_stop = false;
    let run = run_wear(&m, WearRun::new(WearMode::Dynamic), &mut |r| {
        seen_stop |= r.stopped.is_some();
        Ok(())
    })
    .expect("a stop is not an error");
    let stop = run.stopped.clone().expect("stopped early");
    assert_eq!(stop.kind, StopKind::ModelValidity, "{}", stop.reason);
    assert!(seen_stop, "the checkpoint after the stop must record it");
    // Every record kept is inside the model's domain, and the stop is after the last.
    let last = run.last().unwrap();
    assert!(run.records.len() > 5);
    assert!(stop.cycles > last.wear.cycles && stop.cycles < 1e6);
    let r = m
        .dynamic(
            &last.wear,
            &gearwear::dynamics::excitation::ExternalError::none(),
        )
        .unwrap();
    assert!(r.contact_loss_fraction() <= MAX_CONTACT_LOSS_FRACTION);
    // Resuming a stopped run does nothing more.
    let again = run_wear(&m, run.clone(), &mut |_| Ok(())).unwrap();
    assert_eq!(again, run);
    // A checkpoint written before the stop and warm-start fields existed still loads.
    let mut v = serde_json::to_value(&run).unwrap();
    v.as_object_mut().unwrap().remove("stopped");
    for rec in v["records"].as_array_mut().unwrap() {
        rec.as_object_mut().unwrap().remove("end_state");
    }
    let old: WearRun = serde_json::from_value(v).unwrap();
    assert!(old.stopped.is_none() && old.records[0].end_state.is_none());
}

#[test]
fn wear_command_writes_everything_up_to_the_stop_and_exits_zero() {
    // A stop because the teeth left the model's domain is a result: exit code 0, a
    // warning, summary.json names it, and every output exists.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("w");
    let mut args = vec!["wear", "--mode", "dynamic", "--out", out.to_str().unwrap()];
    for s in FAST_WEAR {
        args.extend(["--set", s]);
    }
    let o = Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args(&args)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(
        err.contains("stopped early") && err.contains("out of contact"),
        "{err}"
    );
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["stopped"]["dynamic"]["kind"], "model_validity");
    for f in [
        "updates_dynamic.csv",
        "wear_profiles_dynamic.csv",
        "fig11_force_and_wear_initial.png",
        "fig12_wear_rate_evolution.png",
        "fig13_max_accumulated_wear.png",
    ] {
        assert!(out.join(f).exists(), "{f} missing");
    }
}

/// (cycles, max_wear_pinion_um) of an updates CSV.
fn wear_column(path: &std::path::Path) -> Vec<(f64, f64)> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    let (c, w) = (col("cycles"), col("max_wear_pinion_um"));
    lines
        .map(|l| {
            let f: Vec<f64> = l
                .split(',')
                .map(|x| x.parse().unwrap_or(f64::NAN))
                .collect();
            (f[c], f[w])
        })
        .collect()
}

#[test]
fn the_ratio_of_a_stopped_run_says_at_which_cycle_count_it_is_taken() {
    // Both modes under the fast wear: the dynamic run stops (the teeth lose contact),
    // the quasi-static one goes on. The ratio line must name the last cycle count both
    // reached, and its ratio must be the two wear columns' ratio there (the quasi-static
    // one read between its updates by linear interpolation), from the written CSVs.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("w");
    let mut args = vec!["wear", "--out", out.to_str().unwrap()];
    for s in [
        "wear.coefficient_m2_per_n=2.5e-14",
        "wear.threshold_um=5",
        "wear.total_cycles=5e4",
    ] {
        args.extend(["--set", s]);
    }
    let o = Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args(&args)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let head = String::from_utf8_lossy(&o.stdout).to_string();
    let d = wear_column(&out.join("updates_dynamic.csv"));
    let q = wear_column(&out.join("updates_quasi_static.csv"));
    let (d_end, q_end) = (d.last().unwrap().0, q.last().unwrap().0);
    assert!(d_end < q_end && q_end == 5e4, "{d_end} {q_end}");
    let j = q.partition_point(|p| p.0 < d_end);
    let t = (d_end - q[j - 1].0) / (q[j].0 - q[j - 1].0);
    let q_at = q[j - 1].1 + t * (q[j].1 - q[j - 1].1);
    let ratio = d.last().unwrap().1 / q_at;
    let line = head
        .lines()
        .find(|l| l.starts_with("dynamic / quasi-static"))
        .unwrap_or_else(|| panic!("{head}"));
    assert!(
        line.contains(&format!("at {d_end} cycles")) && line.contains("dynamic run stopped early"),
        "{line}"
    );
    let shown: f64 = line.rsplit(": ").next().unwrap().parse().unwrap();
    // Printed to 4 significant digits (gearwear::format::SHOWN_DIGITS): within half a
    // unit of the fourth.
    let half_unit = 0.5 * 10f64.powi(ratio.abs().log10().floor() as i32 - 3);
    assert!((shown - ratio).abs() <= half_unit, "{line}: {ratio}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["ratio_at_cycles"].as_f64(), Some(d_end));
}
