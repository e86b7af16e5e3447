//! `--figures svg --figure-size WxH` on every command that draws figures besides wear,
//! dynamics and stiffness (tests/figure_output.rs): sweep, sweep-merge, signals,
//! load-spectrum, calibrate, predict, predict-merge, dataset, dataset-merge, and run for
//! its report. Each is run twice on the same inputs, by default and SVG-only, and the two
//! folders are compared: every PNG of the default run is an SVG of the scaled size (read
//! from the files), no PNG is left, the manifest lists the SVGs, the data files are byte
//! for byte the same (a figure option must not change a number), and a report embeds the
//! SVGs.

mod common;

use common::figures::{manifest_paths, png_size, svg_size, tree};
use common::{ok, rejected, CHEAP};
use std::path::Path;

/// The size asked for, and the documented default one-panel size it scales from.
const SIZE: &str = "1200x500";
const ASKED: (f64, f64) = (1200.0, 500.0);
const DEFAULT: (f64, f64) = (900.0, 420.0);

/// The size a figure of default size `png` gets (README, `--figure-size`): each side
/// scaled by the asked one-panel size over 900 x 420, rounded to the pixel, at most
/// 8192 px.
fn scaled((w, h): (u32, u32)) -> (u32, u32) {
    let side = |v: u32, asked: f64, default: f64| {
        ((f64::from(v) * asked / default).round() as u32).min(8192)
    };
    (side(w, ASKED.0, DEFAULT.0), side(h, ASKED.1, DEFAULT.1))
}

/// Run `args` (a command and its inputs) into `root/png` by default and into `root/svg`
/// with `--figures svg --figure-size 1200x500`, then compare the two folders.
fn svg_run_matches_png_run(args: &[&str], root: &Path) {
    let (png, svg) = (root.join("png"), root.join("svg"));
    let mut a = args.to_vec();
    a.extend(["--out", png.to_str().unwrap()]);
    ok(&a);
    let mut b = args.to_vec();
    b.extend(["--figures", "svg", "--figure-size", SIZE]);
    b.extend(["--out", svg.to_str().unwrap()]);
    ok(&b);
    compare(&png, &svg, args[0]);
}

/// The default run's folder `png` against the SVG-only run's `svg`.
fn compare(png: &Path, svg: &Path, what: &str) {
    let (p, s) = (tree(png), tree(svg));
    let figures: Vec<&String> = p.keys().filter(|k| k.ends_with(".png")).collect();
    assert!(
        !figures.is_empty(),
        "{what}: the default run drew no figure"
    );
    assert!(
        s.keys().all(|k| !k.ends_with(".png")),
        "{what}: a PNG written with --figures svg: {:?}",
        s.keys()
    );
    let listed = manifest_paths(svg);
    for f in &figures {
        let name = format!("{}.svg", f.trim_end_matches(".png"));
        let file = s
            .get(&name)
            .unwrap_or_else(|| panic!("{what}: {name} missing"));
        assert_eq!(
            svg_size(file),
            scaled(png_size(&p[*f])),
            "{what}: {name} against {f}"
        );
        assert!(listed.contains(&name), "{what}: {name} not in the manifest");
    }
    let svgs = s.keys().filter(|k| k.ends_with(".svg")).count();
    assert_eq!(svgs, figures.len(), "{what}: one SVG per figure, no other");
    // Everything else: the same names, and the data files the same bytes.
    let rest = |t: &std::collections::BTreeMap<String, std::path::PathBuf>| -> Vec<String> {
        t.keys()
            .filter(|k| !k.ends_with(".png") && !k.ends_with(".svg"))
            .cloned()
            .collect()
    };
    assert_eq!(rest(&p), rest(&s), "{what}: other files differ");
    for k in rest(&p) {
        let manifest = k.ends_with("manifest.json");
        let data = [".csv", ".json", ".parquet", ".toml"]
            .iter()
            .any(|e| k.ends_with(e));
        if data && !manifest {
            assert!(
                std::fs::read(&p[&k]).unwrap() == std::fs::read(&s[&k]).unwrap(),
                "{what}: {k} differs with --figures svg"
            );
        }
    }
    if let (Some(a), Some(b)) = (p.get("report.html"), s.get("report.html")) {
        let (a, b) = (read(a), read(b));
        let count = |t: &str, kind: &str| t.matches(&format!("src=\"data:image/{kind};")).count();
        // The report of an SVG-only run shows each figure it showed before, as SVG.
        assert_eq!(count(&b, "png"), 0, "{what}: the report embeds a PNG");
        assert_eq!(count(&b, "svg+xml"), count(&a, "png"), "{what}: report");
        assert!(count(&a, "png") > 0);
    }
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap()
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_owned()
}

#[test]
fn the_run_report_embeds_svg_when_only_svg_is_asked() {
    let d = tempfile::tempdir().unwrap();
    let mut a = vec!["run", "--set", "wear.total_cycles=6000"];
    a.extend(CHEAP);
    svg_run_matches_png_run(&a, d.path());
}

#[test]
fn sweep_and_sweep_merge_write_svg_only() {
    let d = tempfile::tempdir().unwrap();
    let mut a = vec!["sweep"];
    a.extend(CHEAP);
    // A speed axis: the sweep draws its figure.
    a.extend(["--vary", "operating.input_speed_hz=25,30"]);
    svg_run_matches_png_run(&a, &d.path().join("sweep"));
    let input = d.path().join("sweep/png");
    svg_run_matches_png_run(
        &["sweep-merge", input.to_str().unwrap()],
        &d.path().join("merge"),
    );
}

#[test]
fn signals_write_svg_only() {
    let d = tempfile::tempdir().unwrap();
    let mut a = vec!["signals", "--set", "signals.record_length=0.5"];
    a.extend(CHEAP);
    svg_run_matches_png_run(&a, d.path());
}

#[test]
fn load_spectrum_writes_svg_only() {
    let d = tempfile::tempdir().unwrap();
    // Two torque levels at 1500 rpm, 0.5 s samples: a two-bin spectrum.
    let mut h = String::from("time_s,torque_nm,input_speed_rpm\n");
    for i in 0..=80 {
        let t = 0.5 * f64::from(i);
        h.push_str(&format!(
            "{t},{},1500\n",
            if t % 4.0 < 3.0 { 20 } else { 80 }
        ));
    }
    let h = write(d.path(), "history.csv", &h);
    svg_run_matches_png_run(&["load-spectrum", "--history", &h], d.path());
}

/// The cheap prognostics case of tests/prognostics_cli.rs (coarse numerics, a prior of k
/// over [k0/2, 2 k0]).
const CASE: &str = "[numerics]\nsteps_per_mesh_period = 60\nevaluated_mesh_periods = 2\n\
[wear]\npoints_per_profile = 31\n\
[calibration]\nwear_coefficient_min_m2_per_n = 1.25e-16\nwear_coefficient_max_m2_per_n = 5e-16\n";

#[test]
fn calibrate_predict_and_predict_merge_write_svg_only_and_reports_embed_it() {
    let d = tempfile::tempdir().unwrap();
    let case = write(d.path(), "case.toml", CASE);
    let obs = write(
        d.path(),
        "obs.csv",
        "cycles,max_wear_pinion_um,sigma_max_wear_pinion_um\n10000,1.5,0.2\n20000,3.0,0.2\n",
    );
    let cal = [
        "calibrate",
        "--config",
        &case,
        "--observations",
        &obs,
        "--samples",
        "100",
        "--check-runs",
        "1",
    ];
    svg_run_matches_png_run(&cal, &d.path().join("cal"));
    let post = d.path().join("cal/png/posterior_samples.csv");
    let pred = [
        "predict",
        "--config",
        &case,
        "--posterior",
        post.to_str().unwrap(),
        "--limit-um",
        "2.5",
        "--cycles",
        "4e4",
        "--samples",
        "40",
        "--grid-points",
        "11",
        "--check-runs",
        "0",
    ];
    svg_run_matches_png_run(&pred, &d.path().join("predict"));
    let shards = d.path().join("shards");
    for s in ["1/2", "2/2"] {
        let mut a = pred.to_vec();
        a.extend(["--shard", s, "--out", shards.to_str().unwrap()]);
        ok(&a);
    }
    svg_run_matches_png_run(
        &["predict-merge", shards.to_str().unwrap()],
        &d.path().join("merge"),
    );
}

/// One condition, two states of a short run to failure, one speed and realisation: the
/// smallest dataset with an indicator trend.
const DESIGN: &str = r#"
seed = 11
set = ["signals.snr_db=30", "signals.record_length=0.12", "numerics.steps_per_mesh_period=60",
       "stiffness.table_points_per_mesh_period=60", "wear.block_cycles=5e3"]
[run_to_failure]
states = 2
max_cycles = 1e4
wear_limit_um = 2
[operating]
input_speed_hz = [30]
[records]
noise_realisations = 1
[[condition]]
name = "healthy"
"#;

#[test]
fn dataset_and_dataset_merge_write_svg_only_with_the_same_records() {
    let d = tempfile::tempdir().unwrap();
    let design = write(d.path(), "design.toml", DESIGN);
    svg_run_matches_png_run(&["dataset", "--design", &design], &d.path().join("ds"));
    let shards = d.path().join("shards");
    for s in ["1/2", "2/2"] {
        ok(&[
            "dataset",
            "--design",
            &design,
            "--shard",
            s,
            "--out",
            shards.to_str().unwrap(),
        ]);
    }
    svg_run_matches_png_run(
        &["dataset-merge", shards.to_str().unwrap()],
        &d.path().join("merge"),
    );
}

#[test]
fn bad_figure_options_exit_2_on_every_command_before_anything_is_read_or_made() {
    let d = tempfile::tempdir().unwrap();
    let design = write(d.path(), "design.toml", DESIGN);
    // Inputs that do not exist: the figure options are checked first, so the message
    // names them, not the missing file.
    let missing = d.path().join("missing.csv");
    let m = missing.to_str().unwrap();
    let commands: Vec<Vec<&str>> = vec![
        vec!["sweep", "--vary", "operating.input_speed_hz=25,30"],
        vec!["sweep-merge", m],
        vec!["signals"],
        vec!["load-spectrum", "--history", m],
        vec!["calibrate", "--observations", m],
        vec![
            "predict",
            "--limit-um",
            "10",
            "--cycles",
            "1e5",
            "--posterior",
            m,
        ],
        vec!["predict-merge", m],
        vec!["dataset", "--design", &design],
        vec!["dataset-merge", m],
    ];
    for c in commands {
        let mut a = c.clone();
        a.extend(["--figures", "gif"]);
        rejected(&a, &["--figures", "gif", "png, svg or png,svg"]);
        let mut a = c.clone();
        a.push("--figure-size=10x800");
        rejected(
            &a,
            &[
                "--figure-size",
                "10x800",
                "width in [400, 8192]",
                "height in [200, 4096]",
            ],
        );
    }
}
