//! What a duty cycle writes: the wear study under a spectrum (single-point outputs at the
//! monitoring bin, rankings, figures with their data) and the run's duty section.

use gearwear::config::load_case;
use gearwear::duty::contribution::ranking;
use gearwear::duty::study::run_duty_study;
use gearwear::duty::wear::{run_spectrum_modes, SpectrumRun};
use gearwear::duty::SpectrumModel;
use gearwear::io::OutputDir;
use gearwear::report::artifacts::publish_artifacts;
use gearwear::report::duty::{duty_section, duty_wear_artifacts};
use gearwear::study::wear_loop::WearMode;

const THREE: &str = "[load_spectrum]\nbins = [{torque_nm = 40, input_speed_hz = 20, share = 0.5}, {torque_nm = 60, input_speed_hz = 30, share = 0.3}, {torque_nm = 80, input_speed_hz = 70, share = 0.2}]\n";

#[test]
fn the_wear_outputs_under_a_spectrum_hold_what_each_bin_did() {
    let case = load_case(THREE, &[]).unwrap();
    let sm = SpectrumModel::from_case(&case).unwrap();
    let starts = [WearMode::Dynamic, WearMode::QuasiStatic]
        .map(|m| SpectrumRun::new(m, sm.shares.clone()))
        .to_vec();
    let runs = run_spectrum_modes(&sm, starts, &|_, _| Ok(())).unwrap();
    let refs: Vec<&SpectrumRun> = runs.iter().collect();
    let a = duty_wear_artifacts(&sm, &refs, None);
    let dir = tempfile::tempdir().unwrap();
    let out = OutputDir::open(&dir.path().join("w"), None, "wear").unwrap();
    let root = publish_artifacts(out, &a).unwrap();
    for f in [
        "summary.json",
        "updates_dynamic.csv",
        "duty/bins_dynamic.csv",
        "duty_spectrum.png",
        "duty_wear_by_bin_dynamic.png",
        "duty_dynamic_factor_quasi_static.png",
        "csv/duty_wear_by_bin_dynamic.csv",
    ] {
        assert!(root.join(f).exists(), "{f}");
    }
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(root.join("summary.json")).unwrap()).unwrap();
    let bins = s["load_spectrum"]["bins"].as_array().unwrap();
    assert_eq!(bins.len(), 3);
    // Mesh frequency z1 f: 19 x 70 Hz.
    assert!((bins[2]["mesh_frequency_hz"].as_f64().unwrap() - 1330.0).abs() < 1e-9);
    // The shares of wear sum to 1; the ranking is in decreasing order.
    let r = ranking(&runs[0]);
    let total: f64 = r.iter().map(|b| b.share_of_pinion_wear).sum();
    assert!((total - 1.0).abs() < 1e-12, "{total}");
    assert!(r
        .windows(2)
        .all(|w| w[0].share_of_pinion_wear >= w[1].share_of_pinion_wear));
    // The per-bin profiles of the CSV add up to the total profile.
    let csv = std::fs::read_to_string(root.join("csv/duty_wear_by_bin_dynamic.csv")).unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    for l in lines {
        let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
        let parts: f64 = (1..=3)
            .map(|i| v[col(&format!("wear_pinion_bin{i}_um"))])
            .sum();
        let total = v[col("wear_pinion_total_um")];
        assert!(
            (parts - total).abs() <= 1e-9 * total.max(1e-9),
            "{parts} {total}"
        );
    }
}

#[test]
fn the_run_study_adds_a_life_table_and_a_duty_section() {
    let mut case = load_case(THREE, &["wear.total_cycles=2e4".into()]).unwrap();
    case.load_spectrum.as_mut().unwrap().life_wear_limit_um = 3.0;
    let sm = SpectrumModel::from_case(&case).unwrap();
    let starts = [WearMode::Dynamic, WearMode::QuasiStatic]
        .map(|m| SpectrumRun::new(m, sm.shares.clone()))
        .to_vec();
    let study = run_duty_study(&sm, starts, &|_, _| Ok(())).unwrap();
    let life = study.life.as_ref().unwrap();
    assert_eq!(life.bins.len(), 3);
    let under = life.spectrum.cycles().unwrap();
    let lives: Vec<f64> = life.bins.iter().map(|b| b.life.cycles().unwrap()).collect();
    // The spectrum's life lies between its bins' shortest and longest.
    let (lo, hi) = lives
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(a, b), x| (a.min(*x), b.max(*x)));
    assert!(lo < under && under < hi, "{lives:?} {under}");
    let sec = duty_section(
        &sm,
        study.run(WearMode::Dynamic).unwrap(),
        Some(life),
        vec![],
    );
    assert_eq!(sec.tables.len(), 2);
    assert_eq!(sec.tables[1].rows.len(), 4);
}
