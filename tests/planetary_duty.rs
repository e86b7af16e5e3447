//! `gearwear wear` on a planetary set (`[planetary]`) under a load spectrum
//! (`duty::planetary`, docs/MODEL.md 12.12), checked against independent facts: the
//! set's own constant-load study at the bin's operating point (the built binary), the
//! linearity of the update rule in the shares (merging two bins at one operating point
//! changes nothing), a resumed run against an uninterrupted one, the limiting member read
//! from the per-flank histories, and refusals with exit code 2.
//!
//! The case: the default set (24 / 30 / 84, four planets, sun in, ring fixed) to 2e4 input
//! cycles with a wear threshold of 0.1 µm, so that every run makes a handful of updates
//! whose blocks are cut by a member flank's threshold (about 1.5 s of CPU per bin, both
//! modes).

mod common;
use common::resume::{cut_log, cut_then_resumed_is_unchanged, edit_update, refused};
use common::{gearwear, read_csv, run_into, stderr};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// The short set, at 30 Hz and 60 N m on the sun, with `extra` appended.
fn case(dir: &Path, name: &str, operating: (f64, f64), extra: &str) -> String {
    let p = dir.join(name);
    std::fs::write(
        &p,
        format!(
            "[operating]\nload_torque_nm = {}\ninput_speed_hz = {}\n[planetary]\n[wear]\ntotal_cycles = 20000\nthreshold_um = 0.1\n{extra}",
            operating.0, operating.1
        ),
    )
    .unwrap();
    p.to_str().unwrap().to_owned()
}

/// A `[load_spectrum]` of bins (torque N m, speed Hz, share).
fn spectrum(bins: &[(f64, f64, f64)], more: &str) -> String {
    let b: Vec<String> = bins
        .iter()
        .map(|(t, f, s)| format!("{{torque_nm = {t}, input_speed_hz = {f}, share = {s}}}"))
        .collect();
    format!("[load_spectrum]\nbins = [{}]\n{more}", b.join(", "))
}

fn wear(dir: &Path, name: &str, config: &str) -> PathBuf {
    run_into(dir, name, &["wear", "--mode", "both"], Some(config), &[])
}

fn summary(dir: &Path) -> Value {
    serde_json::from_slice(&std::fs::read(dir.join("summary.json")).unwrap()).unwrap()
}

/// Every column of a CSV as numbers, with the header.
fn columns(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let (h, rows) = read_csv(path);
    let cols = (0..h.len())
        .map(|i| rows.iter().map(|r| r[i].parse().unwrap()).collect())
        .collect();
    (h, cols)
}

const MODES: [&str; 2] = ["dynamic", "quasi_static"];

#[test]
fn a_one_bin_spectrum_is_the_sets_own_study_at_that_bins_operating_point_byte_for_byte() {
    // The bin (80 N m, 20 Hz) is not the case's [operating] point (60 N m, 30 Hz): the
    // spectrum must apply the bin's torque and speed to the input member. s = 1 makes
    // every product of the spectrum's loop exact, so the tables are the bytes of the
    // set's own study run at 80 N m, 20 Hz.
    let d = tempfile::tempdir().unwrap();
    let one = spectrum(&[(80.0, 20.0, 1.0)], "");
    let a = wear(
        d.path(),
        "alone",
        &case(d.path(), "a.toml", (80.0, 20.0), ""),
    );
    let b = wear(
        d.path(),
        "duty",
        &case(d.path(), "b.toml", (60.0, 30.0), &one),
    );
    for mode in MODES {
        for f in ["wear_history", "mesh_history", "wear_profiles"] {
            let f = format!("{f}_{mode}.csv");
            let x = std::fs::read(a.join(&f)).unwrap();
            assert!(x == std::fs::read(b.join(&f)).unwrap(), "{f} differs");
        }
    }
    let (sa, sb) = (summary(&a), summary(&b));
    assert_eq!(sa["planetary_wear"], sb["planetary_wear"]);
    // All the wear is the one bin's.
    for mode in MODES {
        for f in sb["load_spectrum"][mode]["flanks"].as_array().unwrap() {
            assert_eq!(f["share_of_volume_by_bin"][0].as_f64(), Some(1.0), "{f}");
        }
    }
}

#[test]
fn two_bins_at_one_operating_point_are_one_bin_of_their_summed_share() {
    // The update rule is linear in the shares: the spectrum's rate is sum_i s_i inc_i and
    // the advance sum_i s_i n c inc_i (eq. 17), so bins A (0.3) and A (0.2) give
    // 0.3 inc_A + 0.2 inc_A = 0.5 inc_A, the rate and wear of one bin A (0.5): the same
    // blocks, the same flanks and the same responses, up to the rounding of the sums.
    // Beside them bin B (90 N m, 20 Hz, 0.5) keeps the spectrum a real one. Tolerance:
    // each update rounds its sums a few times (a few eps of the depth), and the responses
    // feed the wear back; 1e-9 of the peak depth leaves six orders for that amplification.
    let d = tempfile::tempdir().unwrap();
    let split = spectrum(
        &[(60.0, 30.0, 0.3), (90.0, 20.0, 0.5), (60.0, 30.0, 0.2)],
        "",
    );
    let merged = spectrum(&[(60.0, 30.0, 0.5), (90.0, 20.0, 0.5)], "");
    let a = wear(
        d.path(),
        "split",
        &case(d.path(), "a.toml", (60.0, 30.0), &split),
    );
    let b = wear(
        d.path(),
        "merged",
        &case(d.path(), "b.toml", (60.0, 30.0), &merged),
    );
    let mut worst: f64 = 0.0;
    for mode in MODES {
        let f = format!("wear_history_{mode}.csv");
        let ((ha, ca), (hb, cb)) = (columns(&a.join(&f)), columns(&b.join(&f)));
        assert_eq!(ha, hb);
        let at = |n: &str| ha.iter().position(|c| c == n).unwrap();
        assert_eq!(
            ca[at("input_cycles")],
            cb[at("input_cycles")],
            "{mode}: blocks"
        );
        assert_eq!(
            ca[at("block_limited_by_flank")],
            cb[at("block_limited_by_flank")]
        );
        let peak = ca[at("max_wear_sun_um")]
            .iter()
            .fold(0.0_f64, |x, y| x.max(*y));
        assert!(
            peak > 0.1,
            "{mode}: the sun wore {peak} µm: too little to compare"
        );
        for (k, name) in ha.iter().enumerate() {
            if name.starts_with("max_wear_") {
                for (x, y) in ca[k].iter().zip(&cb[k]) {
                    worst = worst.max((x - y).abs() / peak);
                }
            }
        }
        // Bins 1 and 3 of the split spectrum together added what bin 1 of the merged one
        // did, to every flank; bin B the same in both.
        let (sa, sb) = (summary(&a), summary(&b));
        let fa = sa["load_spectrum"][mode]["flanks"]
            .as_array()
            .unwrap()
            .clone();
        let fb = sb["load_spectrum"][mode]["flanks"]
            .as_array()
            .unwrap()
            .clone();
        for (x, y) in fa.iter().zip(&fb) {
            let s = |v: &Value, i: usize| v["share_of_volume_by_bin"][i].as_f64().unwrap();
            assert!(
                (s(x, 0) + s(x, 2) - s(y, 0)).abs() < 1e-9,
                "{mode}: {x} / {y}"
            );
            assert!((s(x, 1) - s(y, 1)).abs() < 1e-9, "{mode}: {x} / {y}");
        }
    }
    assert!(
        worst < 1e-9,
        "largest difference {worst:e} of the peak depth"
    );
    eprintln!("split against merged: {worst:e} of the peak depth");
}

/// The arguments of a spectrum run of the short set into `out`.
fn args(config: &str, out: &Path) -> Vec<String> {
    let mut a: Vec<String> = ["-q", "wear", "--mode", "both", "--config", config, "--out"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    a.push(out.to_str().unwrap().into());
    a
}

#[test]
fn an_interrupted_spectrum_run_resumes_to_the_same_files_and_an_edit_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let two = spectrum(&[(60.0, 30.0, 0.6), (90.0, 20.0, 0.4)], "");
    let config = case(d.path(), "s.toml", (60.0, 30.0), &two);
    let out = d.path().join("w");
    let a = args(&config, &out);
    // Killed between the appends of an update: the dynamic run's bin 1 logs hold 4
    // updates, bin 2's sun meshes 4 and its ring meshes 3 (planet 1's torn mid-line); the
    // quasi-static logs 2 updates. The resumed run must write the same bytes (every
    // published table, the summary, the manifest and the logs).
    let cut = |out: &Path| {
        for p in 1..=4 {
            let log = |mode: &str, bin: usize, kind: &str| {
                out.join(format!(
                    "checkpoint_{mode}_bin{bin}_{kind}_planet_{p}.jsonl"
                ))
            };
            cut_log(&log("dynamic", 1, "sun"), 4, false);
            cut_log(&log("dynamic", 1, "ring"), 4, false);
            cut_log(&log("dynamic", 2, "sun"), 4, false);
            cut_log(&log("dynamic", 2, "ring"), 3, p == 1);
            for bin in 1..=2 {
                for kind in ["sun", "ring"] {
                    cut_log(&log("quasi_static", bin, kind), 2, false);
                }
            }
        }
    };
    cut_then_resumed_is_unchanged(&a, &out, &cut);
    // An edit under a rewritten checksum: bin 2's view of the ring at update 2 is not the
    // ring at update 1 advanced over the replayed block.
    let log = out.join("checkpoint_dynamic_bin2_ring_planet_3.jsonl");
    let original = std::fs::read_to_string(&log).unwrap();
    edit_update(&log, 2, true, &|v| {
        let g = v["wear"]["gear_m"].as_array_mut().unwrap();
        let k = g.len() / 2;
        g[k] = Value::from(g[k].as_f64().unwrap() * 1.5 + 1e-9);
    });
    refused(
        &a,
        "wear x 1.5",
        &[
            "update 2 (line 4), bin 2, mesh ring_planet_3",
            "advanced over the block",
        ],
    );
    std::fs::write(&log, &original).unwrap();
    // The last update's rate is chained to nothing: only recomputing every bin's response
    // catches it.
    let last = original.lines().count() - 2;
    edit_update(&log, last, true, &|v| {
        let g = v["increment_gear_m"].as_array_mut().unwrap();
        let k = g.len() / 2;
        g[k] = Value::from(g[k].as_f64().unwrap() * (1.0 + 1e-9));
    });
    refused(
        &a,
        "last rate x (1 + 1e-9)",
        &[
            &format!(
                "update {last} (line {}), bin 2, mesh ring_planet_3",
                last + 2
            ),
            "not what this case's model computes",
        ],
    );
}

#[test]
fn the_limiting_member_is_the_flank_whose_history_reaches_the_limit_first() {
    // Read from wear_history_MODE.csv alone: for every member flank the first update at
    // which its largest depth reaches the limit. The flank reaching it at the earliest
    // update limits the life, and every flank's life lies within the block that ends at
    // its first such update (the depth grows linearly within a block, so the crossing is
    // after the update before and at or before that update). Hours: the cycles times
    // sum_i s_i / f_i by hand.
    let d = tempfile::tempdir().unwrap();
    let bins = [(60.0, 30.0, 0.6), (90.0, 20.0, 0.4)];
    let two = spectrum(&bins, "life_wear_limit_um = 0.05\n");
    let out = wear(d.path(), "w", &case(d.path(), "s.toml", (60.0, 30.0), &two));
    let s = summary(&out);
    let seconds_per_cycle: f64 = bins.iter().map(|(_, f, s)| s / f).sum();
    let limit = 0.05;
    for mode in MODES {
        let (h, c) = columns(&out.join(format!("wear_history_{mode}.csv")));
        let cycles = &c[h.iter().position(|x| x == "input_cycles").unwrap()];
        let u = &s["load_spectrum"][mode];
        let mut first: Option<(usize, String)> = None;
        let mut reached = 0;
        for f in u["flanks"].as_array().unwrap() {
            let (m, fl) = (f["member"].as_str().unwrap(), f["flank"].as_str().unwrap());
            let stem = if m == fl {
                m.to_string()
            } else {
                format!("{m}_{fl}")
            };
            let col = &c[h
                .iter()
                .position(|x| *x == format!("max_wear_{stem}_um"))
                .unwrap()];
            let row = col.iter().position(|x| *x >= limit);
            match (row, f["life"]["status"].as_str().unwrap()) {
                (Some(r), "reached") => {
                    reached += 1;
                    let n = f["life"]["cycles"].as_f64().unwrap();
                    assert!(
                        r > 0 && n > cycles[r - 1] && n <= cycles[r],
                        "{mode} {stem}: life {n} outside its block ({}, {}]",
                        cycles[r - 1],
                        cycles[r]
                    );
                    let hours = f["life_hours"].as_f64().unwrap();
                    assert!((hours / (n * seconds_per_cycle / 3600.0) - 1.0).abs() < 1e-12);
                    if first.as_ref().is_none_or(|(q, _)| r < *q) {
                        first = Some((r, m.to_string()));
                    }
                }
                (None, "beyond") => {}
                (row, status) => panic!("{mode} {stem}: history row {row:?}, life {status}"),
            }
        }
        assert!(
            reached >= 2,
            "{mode}: only {reached} flanks reach the limit: too few to rank"
        );
        let (_, member) = first.unwrap();
        assert_eq!(
            u["limiting_member"].as_str(),
            Some(member.as_str()),
            "{mode}"
        );
    }
}

#[test]
fn a_set_under_a_spectrum_refuses_bad_input_with_exit_2() {
    let d = tempfile::tempdir().unwrap();
    let cfg = |name: &str, extra: &str| case(d.path(), name, (60.0, 30.0), extra);
    let two = spectrum(&[(60.0, 30.0, 0.5), (90.0, 20.0, 0.5)], "");
    let refuse = |command: &str, config: &str, sets: &[&str], needles: &[&str]| {
        let out = d.path().join("out");
        let mut a = vec![
            command,
            "-q",
            "--config",
            config,
            "--out",
            out.to_str().unwrap(),
        ];
        for s in sets {
            a.extend(["--set", s]);
        }
        let o = gearwear(&a);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{a:?}: {e}");
        assert!(!e.contains("panicked"), "{e}");
        for n in needles {
            assert!(e.contains(n), "{a:?}: says `{n}`: {e}");
        }
        assert!(
            !out.exists(),
            "{a:?}: the refusal created {}",
            out.display()
        );
    };
    // The bins load the input member: torques on the gear shaft are refused, naming the
    // key, its value and the valid one.
    let gear = cfg(
        "g.toml",
        &spectrum(&[(60.0, 30.0, 1.0)], "torque_shaft = \"gear\"\n"),
    );
    refuse(
        "wear",
        &gear,
        &[],
        &["`load_spectrum.torque_shaft`", "\"gear\"", "\"pinion\""],
    );
    // A bin out of range: the bin, the key, the value and the range.
    let bad = cfg(
        "b.toml",
        &spectrum(&[(60.0, -30.0, 0.5), (90.0, 20.0, 0.5)], ""),
    );
    refuse("wear", &bad, &[], &["bin 1", "input_speed_hz", "-30"]);
    // Over the budget, every bin counted, before the folder is made.
    let c = cfg("s.toml", &two);
    refuse(
        "wear",
        &c,
        &["wear.total_cycles=1e9"],
        &["over its budget", "under the load spectrum"],
    );
    refuse(
        "run",
        &c,
        &["wear.total_cycles=1e9"],
        &["over its budget", "under the load spectrum"],
    );
    refuse(
        "run",
        &gear,
        &[],
        &["`load_spectrum.torque_shaft`", "\"gear\""],
    );
}

#[test]
fn run_under_a_spectrum_nests_the_wear_study_and_studies_the_monitoring_bin() {
    // Second path through the application: `gearwear wear` on the same case writes the
    // run's wear/ folder byte for byte, and `gearwear dynamics`, `stiffness` and
    // `signals` on the set at the monitoring bin's operating point (bin 2, the larger
    // share: 90 N m, 20 Hz) its dynamics/, stiffness/ and signals/ folders. The report's duty section names
    // the limiting member of wear/summary.json and every bin.
    use common::assert_nested_study;
    let d = tempfile::tempdir().unwrap();
    let two = spectrum(&[(60.0, 30.0, 0.4), (90.0, 20.0, 0.6)], "");
    let config = case(d.path(), "s.toml", (60.0, 30.0), &two);
    let at_bin = case(d.path(), "b.toml", (90.0, 20.0), "");
    let r = run_into(d.path(), "run", &["run"], Some(&config), &[]);
    let w = wear(d.path(), "wear", &config);
    assert_nested_study(&r, &w, "wear");
    for study in ["dynamics", "stiffness", "signals"] {
        let alone = run_into(d.path(), study, &[study], Some(&at_bin), &[]);
        // Every file the same bytes; summary.json the same but for its `metadata`, which
        // names the case the run was given (with its spectrum), not the bin's.
        let files = common::manifest_files(&alone);
        assert!(files.contains(&"summary.json".to_string()), "{study}");
        for f in files {
            let (x, y) = (alone.join(&f), r.join(study).join(&f));
            if f == "summary.json" {
                let (mut x, mut y) = (summary(&alone), summary(&r.join(study)));
                x["metadata"] = Value::Null;
                y["metadata"] = Value::Null;
                assert_eq!(x, y, "{study}/summary.json");
            } else {
                assert!(
                    std::fs::read(x).unwrap() == std::fs::read(y).unwrap(),
                    "{study}/{f}"
                );
            }
        }
    }
    let s = summary(&r);
    assert_eq!(s["load_spectrum"], summary(&w)["load_spectrum"]);
    let html = std::fs::read_to_string(r.join("report.html")).unwrap();
    let at = html
        .find("Duty cycle: the set") // the apostrophe is escaped in HTML
        .expect("the duty section");
    let section = &html[at..];
    for mode in MODES {
        let m = s["load_spectrum"][mode]["limiting_member"]
            .as_str()
            .unwrap()
            .replace('_', " ");
        assert!(section.contains(&m), "{mode}: {m}");
    }
    assert!(
        section.contains("90") && section.contains("60"),
        "the bins' torques"
    );
    // Resuming the finished run writes the same bytes.
    let before = common::published(&r);
    let a = [
        "-q",
        "run",
        "--config",
        &config,
        "--out",
        r.to_str().unwrap(),
        "--resume",
    ];
    let o = gearwear(&a);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        common::published(&r) == before,
        "the resumed run's files differ"
    );
}

#[test]
fn the_budget_counts_at_least_the_updates_a_spectrum_run_makes() {
    use gearwear::config::load_case;
    use gearwear::duty::planetary::PlanetarySpectrum;
    use gearwear::study::budget::planetary::planetary_spectrum_wear_updates;
    let d = tempfile::tempdir().unwrap();
    let two = spectrum(&[(60.0, 30.0, 0.6), (90.0, 20.0, 0.4)], "");
    let config = case(d.path(), "s.toml", (60.0, 30.0), &two);
    let text = std::fs::read_to_string(&config).unwrap();
    let ps = PlanetarySpectrum::from_case(&load_case(&text, &[]).unwrap()).unwrap();
    let counted = planetary_spectrum_wear_updates(&ps.models, &ps.shares, &ps.case.wear);
    let out = wear(d.path(), "w", &config);
    for mode in MODES {
        let (_, rows) = read_csv(&out.join(format!("wear_history_{mode}.csv")));
        assert!(
            counted >= rows.len() as f64,
            "{mode}: counted {counted} updates, the run made {}",
            rows.len()
        );
    }
}
