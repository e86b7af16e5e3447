//! `gearwear wear` and `gearwear run` on a gear train (`[[stage]]`) under a load spectrum
//! (`duty::train`): checked against the train's constant-load study run at each bin's
//! operating point (the built binary), the linear wear law of paper eq. 17, the ratios,
//! hours by hand, and bad input naming the bin and the stage.

mod common;
use common::{gearwear, published, read_csv, rejected, run_into, stderr};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Tooth numbers of the two stages (the paper's pair, then 23/47).
const Z: [(f64, f64); 2] = [(19.0, 31.0), (23.0, 47.0)];

/// The two-stage reducer of `examples/two_stage_reducer.toml` at 30 Hz and 60 N m on the
/// input shaft, with `extra` appended (a `[load_spectrum]`), written to `dir/name`.
fn case(dir: &Path, name: &str, extra: &str) -> String {
    let p = dir.join(name);
    std::fs::write(
        &p,
        format!(
            "[operating]\ninput_speed_hz = 30\nload_torque_nm = 60\nload_torque_shaft = \"pinion\"\n\n[[stage]]\nshaft_torsional_stiffness_nm_per_rad = 2e5\n\n[[stage]]\nmodule_mm = 2.5\nteeth_pinion = 23\nteeth_gear = 47\nface_width_mm = 25\n{extra}"
        ),
    )
    .unwrap();
    p.to_str().unwrap().to_owned()
}

fn wear(dir: &Path, name: &str, config: &str, mode: &str, sets: &[&str]) -> PathBuf {
    run_into(dir, name, &["wear", "--mode", mode], Some(config), sets)
}

fn summary(dir: &Path) -> Value {
    serde_json::from_slice(&std::fs::read(dir.join("summary.json")).unwrap()).unwrap()
}

/// A column of a CSV as numbers.
fn column(path: &Path, name: &str) -> Vec<f64> {
    let (h, rows) = read_csv(path);
    let i = h.iter().position(|c| c == name).unwrap();
    rows.iter().map(|r| r[i].parse().unwrap()).collect()
}

#[test]
fn a_one_bin_spectrum_at_the_operating_point_is_the_constant_load_train_byte_for_byte() {
    // s = 1 makes every product of the spectrum's loop exact: the same blocks, the same
    // responses, the same files (both modes, 2e4 input cycles, blocks cut by stage 1's
    // threshold).
    let d = tempfile::tempdir().unwrap();
    let one = "[load_spectrum]\nbins = [{ torque_nm = 60, input_speed_hz = 30, share = 1 }]\n";
    let total = "wear.total_cycles=2e4";
    let a = wear(
        d.path(),
        "const",
        &case(d.path(), "c.toml", ""),
        "both",
        &[total],
    );
    let b = wear(
        d.path(),
        "duty",
        &case(d.path(), "s.toml", one),
        "both",
        &[total],
    );
    for mode in ["dynamic", "quasi_static"] {
        let mut files = vec![format!("wear_history_{mode}.csv")];
        for k in 1..=2 {
            files.push(format!("updates_{mode}_stage{k}.csv"));
            files.push(format!("wear_profiles_{mode}_stage{k}.csv"));
        }
        for f in files {
            let x = std::fs::read(a.join(&f)).unwrap();
            assert!(x == std::fs::read(b.join(&f)).unwrap(), "{f} differs");
        }
    }
    let (sa, sb) = (summary(&a), summary(&b));
    for key in ["meshes", "limiting_mesh", "input_cycles"] {
        assert_eq!(sa[key], sb[key], "{key}");
    }
    // All the wear is the one bin's.
    let m = &sb["load_spectrum"]["quasi_static"]["meshes"];
    for k in 0..2 {
        assert_eq!(m[k]["share_of_pinion_wear_by_bin"][0].as_f64(), Some(1.0));
    }
}

/// The last update's pinion and gear wear profiles of stage `k` of `mode`, um.
fn last_profiles(dir: &Path, mode: &str, k: usize) -> (Vec<f64>, Vec<f64>) {
    let p = dir.join(format!("wear_profiles_{mode}_stage{k}.csv"));
    let u = column(&dir.join(format!("updates_{mode}_stage{k}.csv")), "cycles").len() - 1;
    (
        column(&p, &format!("wear_pinion_um_u{u}")),
        column(&p, &format!("wear_gear_um_u{u}")),
    )
}

#[test]
fn two_bins_wear_each_mesh_by_the_share_weighted_sum_of_the_bins_alone() {
    // One block of n input cycles from new teeth (threshold lifted, block = total): by
    // paper eq. 17 mesh k's wear is sum_i (s_i n c_k) inc_ik, and the train alone at bin
    // i's operating point wears n c_k inc_ik in the same block. So the spectrum's
    // profiles are s_1 W_1 + s_2 W_2 of the two constant-load runs, point by point.
    let d = tempfile::tempdir().unwrap();
    let spectrum = "[load_spectrum]\nbins = [\n  { torque_nm = 40, input_speed_hz = 20, share = 0.3 },\n  { torque_nm = 80, input_speed_hz = 30, share = 0.7 },\n]\n";
    let sets = [
        "wear.total_cycles=2e4",
        "wear.block_cycles=2e4",
        "wear.threshold_um=1e6",
    ];
    let mode = "quasi_static";
    let s = wear(
        d.path(),
        "duty",
        &case(d.path(), "s.toml", spectrum),
        "quasi-static",
        &sets,
    );
    let alone = |name: &str, t: &str, f: &str| {
        let mut all = sets.to_vec();
        let (t, f) = (
            format!("operating.load_torque_nm={t}"),
            format!("operating.input_speed_hz={f}"),
        );
        all.extend([t.as_str(), f.as_str()]);
        wear(
            d.path(),
            name,
            &case(d.path(), "c.toml", ""),
            "quasi-static",
            &all,
        )
    };
    let (w1, w2) = (alone("bin1", "40", "20"), alone("bin2", "80", "30"));
    for k in 1..=2 {
        let (sp, sg) = last_profiles(&s, mode, k);
        let (p1, g1) = last_profiles(&w1, mode, k);
        let (p2, g2) = last_profiles(&w2, mode, k);
        let peak = sp.iter().fold(0.0_f64, |m, x| m.max(*x));
        assert!(peak > 0.1, "stage {k} wears ({peak} um)");
        for (want, got) in [(&p1, &sp), (&g1, &sg)]
            .iter()
            .zip([&p2, &g2])
            .map(|((a, got), b)| {
                (
                    a.iter()
                        .zip(b)
                        .map(|(x, y)| 0.3 * x + 0.7 * y)
                        .collect::<Vec<_>>(),
                    got,
                )
            })
        {
            for (w, g) in want.iter().zip(got.iter()) {
                // A handful of roundings of doubles: 1e-12 of the peak depth.
                assert!((w - g).abs() <= 1e-12 * peak, "stage {k}: {g} vs {w}");
            }
        }
        // The stage's wear-by-bin figure: what bin i added is s_i W_i of the run at bin
        // i alone (the same identity, bin by bin), and the bins sum to the total.
        let fig = s.join(format!("csv/duty_wear_by_bin_{mode}_stage{k}.csv"));
        assert!(s
            .join(format!("duty_wear_by_bin_{mode}_stage{k}.png"))
            .exists());
        for (flank, alone1, alone2) in [("pinion", &p1, &p2), ("gear", &g1, &g2)] {
            let b1 = column(&fig, &format!("wear_{flank}_bin1_um"));
            let b2 = column(&fig, &format!("wear_{flank}_bin2_um"));
            let total = column(&fig, &format!("wear_{flank}_total_um"));
            for j in 0..total.len() {
                assert!(
                    (b1[j] - 0.3 * alone1[j]).abs() <= 1e-12 * peak,
                    "stage {k} {flank}"
                );
                assert!(
                    (b2[j] - 0.7 * alone2[j]).abs() <= 1e-12 * peak,
                    "stage {k} {flank}"
                );
                assert!(
                    (b1[j] + b2[j] - total[j]).abs() <= 1e-12 * peak,
                    "stage {k} {flank}"
                );
            }
        }
    }
    assert!(s.join("duty_spectrum.png").exists());
    // Hours by hand: n (s_1 / f_1 + s_2 / f_2) / 3600.
    let ls = &summary(&s)["load_spectrum"];
    let hours = 2e4 * (0.3 / 20.0 + 0.7 / 30.0) / 3600.0;
    let got = ls[mode]["hours"].as_f64().unwrap();
    assert!((got - hours).abs() <= 1e-12 * hours, "{got} h vs {hours} h");
    // The share of time by hand: (0.3 / 20) / (0.3 / 20 + 0.7 / 30) = 0.391304...
    let t1 = ls["bins"][0]["share_of_time"].as_f64().unwrap();
    assert!((t1 - 0.015 / (0.015 + 0.7 / 30.0)).abs() < 1e-12);
}

/// The operating point of stage `k` (0-based) at bin `i` in a summary's `load_spectrum`.
fn point(ls: &Value, i: usize, k: usize, key: &str) -> f64 {
    ls["bins"][i]["stages"][k][key].as_f64().unwrap()
}

fn close(got: f64, want: f64, what: &str) {
    // Base radii m z cos(alpha) / 2: their ratio is z_g / z_p up to a rounding or two.
    assert!(
        (got - want).abs() <= 1e-12 * want.abs(),
        "{what}: {got} vs {want}"
    );
}

#[test]
fn every_stage_takes_the_bin_torque_times_the_product_of_the_ratios() {
    let d = tempfile::tempdir().unwrap();
    let sets = ["wear.total_cycles=1000", "wear.block_cycles=1000"];
    // On the input shaft: stage 2's pinion carries T_in z_g1 / z_p1 and turns at
    // f_in z_p1 / z_g1.
    let input = "[load_spectrum]\nbins = [\n  { torque_nm = 40, input_speed_hz = 20, share = 0.5 },\n  { torque_nm = 70, input_speed_hz = 35, share = 0.5 },\n]\n";
    let a = wear(
        d.path(),
        "in",
        &case(d.path(), "in.toml", input),
        "quasi-static",
        &sets,
    );
    let ls = summary(&a)["load_spectrum"].clone();
    for (i, (t, f)) in [(40.0, 20.0), (70.0, 35.0)].into_iter().enumerate() {
        let r1 = Z[0].1 / Z[0].0;
        close(point(&ls, i, 0, "pinion_torque_nm"), t, "stage 1 pinion");
        close(
            point(&ls, i, 1, "pinion_torque_nm"),
            t * r1,
            "stage 2 pinion",
        );
        close(
            point(&ls, i, 1, "gear_torque_nm"),
            t * r1 * Z[1].1 / Z[1].0,
            "output",
        );
        close(point(&ls, i, 1, "pinion_speed_hz"), f / r1, "stage 2 speed");
        close(
            point(&ls, i, 1, "mesh_frequency_hz"),
            f / r1 * Z[1].0,
            "stage 2 mesh",
        );
    }
    // On the output shaft (the last stage's gear): the input carries T_out over both
    // ratios.
    let output = "[load_spectrum]\ntorque_shaft = \"gear\"\nbins = [\n  { torque_nm = 200, input_speed_hz = 30, share = 1 },\n]\n";
    let b = wear(
        d.path(),
        "out",
        &case(d.path(), "out.toml", output),
        "quasi-static",
        &sets,
    );
    let ls = summary(&b)["load_spectrum"].clone();
    let ratio = Z[0].1 / Z[0].0 * Z[1].1 / Z[1].0;
    assert_eq!(
        point(&ls, 0, 1, "gear_torque_nm"),
        200.0,
        "the output's torque as given"
    );
    close(point(&ls, 0, 0, "pinion_torque_nm"), 200.0 / ratio, "input");
    close(
        point(&ls, 0, 1, "pinion_torque_nm"),
        200.0 * Z[1].0 / Z[1].1,
        "stage 2 pinion",
    );
}

#[test]
fn a_bin_beyond_a_mesh_s_flanks_is_refused_naming_the_bin_and_the_stage() {
    // 6000 N m on the input: a Hertz pressure above 10 GPa on stage 1 (about 12 GPa)
    // but not on stage 2 (about 9 GPa, larger teeth); bin 1 is fine.
    let d = tempfile::tempdir().unwrap();
    let bad = "[load_spectrum]\nbins = [\n  { torque_nm = 60, input_speed_hz = 30, share = 0.5 },\n  { torque_nm = 6000, input_speed_hz = 30, share = 0.5 },\n]\n";
    let c = case(d.path(), "bad.toml", bad);
    // With the budget on, the bin's wear rate would price the run far over it (a load
    // the flanks cannot carry): the bin is named all the same, not a cost.
    // (The budget-on run keeps the case's 4e4 cycles: at 1000 the estimate would pass.)
    let short = ["--no-budget", "--set", "wear.total_cycles=1000"];
    for (cmd, how) in [
        ("wear", &short[..]),
        ("run", &short[..]),
        ("wear", &["-q"][..]),
    ] {
        let err = rejected(
            &[&[cmd, "--config", &c][..], how].concat(),
            &[
                "load_spectrum bin 2 (6000 N m, 30 Hz): stage 1:",
                "from the bin's `torque_nm` = 6000",
                "Hertz pressure",
            ],
        );
        assert!(!err.contains("bin 1"), "{err}");
        assert!(!err.contains("stage 2:"), "{err}");
        assert!(!err.contains("operating.load_torque_nm"), "{err}");
        assert!(!err.contains("budget"), "{err}");
    }
}

#[test]
fn a_run_cut_between_its_appends_resumes_to_the_bytes_of_an_uninterrupted_one() {
    let d = tempfile::tempdir().unwrap();
    let spectrum = "[load_spectrum]\nbins = [\n  { torque_nm = 40, input_speed_hz = 20, share = 0.5 },\n  { torque_nm = 60, input_speed_hz = 30, share = 0.5 },\n]\n";
    let c = case(d.path(), "s.toml", spectrum);
    let out = d.path().join("w");
    let o = out.to_str().unwrap();
    let args = [
        "-q",
        "wear",
        "--mode",
        "quasi-static",
        "--config",
        &c,
        "--set",
        "wear.total_cycles=2e4",
        "--out",
        o,
    ];
    let r = gearwear(&args);
    assert!(r.status.success(), "{}", stderr(&r));
    let full = published(&out);
    // A kill after update 2 of every log, in the middle of update 3's appends (bin 1's
    // logs hold it, bin 2's stage 2 half of it).
    for (file, keep, torn) in [
        ("checkpoint_quasi_static_bin1_stage1.jsonl", 3, false),
        ("checkpoint_quasi_static_bin1_stage2.jsonl", 3, false),
        ("checkpoint_quasi_static_bin2_stage1.jsonl", 2, false),
        ("checkpoint_quasi_static_bin2_stage2.jsonl", 2, true),
    ] {
        let p = out.join(file);
        let text = std::fs::read_to_string(&p).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines.len() > keep + 2, "{file}: {} lines", lines.len());
        let mut cut = lines[..keep + 1].join("\n") + "\n";
        if torn {
            cut.push_str(&lines[keep + 1][..lines[keep + 1].len() / 2]);
        }
        std::fs::write(&p, cut).unwrap();
    }
    let mut resume = args.to_vec();
    resume.push("--resume");
    let r = gearwear(&resume);
    assert!(r.status.success(), "{}", stderr(&r));
    let again = published(&out);
    assert_eq!(full.len(), again.len());
    for ((p, x), (q, y)) in full.iter().zip(&again) {
        assert!(p == q && x == y, "{p}: the resumed run's bytes differ");
    }
    // A log whose wear was edited, its checksum rewritten to pass, is refused by the
    // replay, naming the update, the bin and the stage.
    let p = out.join("checkpoint_quasi_static_bin2_stage1.jsonl");
    let text = std::fs::read_to_string(&p).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    let (_, json) = lines[3].split_once(' ').unwrap();
    let mut rec: Value = serde_json::from_str(json).unwrap();
    let x = rec.pointer_mut("/wear/pinion_m/10").unwrap();
    *x = Value::from(x.as_f64().unwrap() * 1.5 + 1e-9);
    let json = rec.to_string();
    lines[3] = format!(
        "{} {json}",
        gearwear::io::output_dir::sha256_hex(json.as_bytes())
    );
    std::fs::write(&p, lines.join("\n") + "\n").unwrap();
    let r = gearwear(&resume);
    let err = stderr(&r);
    assert_eq!(r.status.code(), Some(2), "{err}");
    assert!(err.contains("update 2 (line 4), bin 2, stage 1"), "{err}");
}
