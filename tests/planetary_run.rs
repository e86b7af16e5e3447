//! `gearwear run` on a planetary set (`examples/planetary_set.toml`): each study's files
//! are the bytes that study's own command writes (an independent path through the
//! application: the stiffness, dynamics, signals and wear jobs run on their own), the
//! run's summary copies their numbers, every number of the report's tables is the
//! studies' summary.json value to the report's four significant digits, the report loads
//! nothing from outside, and a run resumed from its finished checkpoints writes the same
//! bytes.

mod common;
use common::{assert_nested_study, gearwear, published, stderr};
use serde_json::Value;
use std::path::{Path, PathBuf};

const STUDIES: [&str; 4] = ["stiffness", "dynamics", "signals", "wear"];

fn config() -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/planetary_set.toml")
        .to_string_lossy()
        .into_owned()
}

/// `gearwear -q COMMAND` on the example to 4e4 input cycles (4 updates per mode: about
/// a second) into `out`, with `extra` arguments; must succeed.
fn run_ok(command: &str, out: &Path, extra: &[&str]) {
    let config = config();
    let mut a = vec![
        "-q",
        command,
        "--config",
        &config,
        "--set",
        "wear.total_cycles=4e4",
        "--out",
        out.to_str().unwrap(),
    ];
    a.extend(extra);
    let o = gearwear(&a);
    assert!(o.status.success(), "{a:?}: {}", stderr(&o));
}

fn json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn each_study_of_a_planetary_run_is_the_bytes_of_its_own_command() {
    let d = tempfile::tempdir().unwrap();
    let run = d.path().join("run");
    run_ok("run", &run, &[]);
    for study in STUDIES {
        let alone = d.path().join(study);
        run_ok(study, &alone, &[]);
        assert_nested_study(&run, &alone, study);
    }
    // The wear job's checkpoints are the run's too (same case, same updates).
    let logs: Vec<String> = std::fs::read_dir(d.path().join("wear"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with("checkpoint_"))
        .collect();
    assert_eq!(logs.len(), 2 * 8, "two modes x eight meshes");
    for f in &logs {
        assert!(
            std::fs::read(d.path().join("wear").join(f)).unwrap()
                == std::fs::read(run.join(f)).unwrap(),
            "{f}"
        );
    }
    check_summary(&run);
    check_report(&run);
    // Resumed from its own finished checkpoints: nothing changes.
    let before = published(&run);
    run_ok("run", &run, &["--resume"]);
    assert!(
        published(&run) == before,
        "a resumed finished run changed its files"
    );
}

/// The run's summary: its numbers are the studies' (exactly), and the ratio Willis'.
fn check_summary(run: &Path) {
    let s = json(&run.join("summary.json"));
    assert_eq!(s["metadata"]["command"], "run");
    let p = &s["planetary_run"];
    let st = json(&run.join("stiffness/summary.json"));
    let dy = json(&run.join("dynamics/summary.json"));
    let we = json(&run.join("wear/summary.json"));
    assert_eq!(p["modes"], st["planetary"]["modes"]);
    assert_eq!(p["kinematics"], st["planetary"]["kinematics"]);
    for k in [
        "meshes",
        "load_sharing_factor",
        "load_sharing_factor_static",
    ] {
        assert_eq!(p[k], dy["planetary_dynamics"][k], "{k}");
    }
    for k in ["members", "limiting_member", "input_cycles"] {
        assert_eq!(p[k], we["planetary_wear"][k], "{k}");
    }
    // Sun in, carrier out, ring fixed: 1 + z_r / z_s (Willis), to round-off.
    let ratio = p["kinematics"]["ratio_input_to_output"].as_f64().unwrap();
    assert!((ratio / (1.0 + 85.0 / 23.0) - 1.0).abs() < 1e-14, "{ratio}");
    assert_eq!(p["studies"]["signals"], "signals/summary.json");
}

/// The cells of the report's table whose caption holds `caption`, row by row.
fn table(html: &str, caption: &str) -> Vec<Vec<String>> {
    let at = html
        .find(&format!("{caption}</caption>"))
        .unwrap_or_else(|| panic!("no table `{caption}`"));
    let body = &html[at..at + html[at..].find("</table>").unwrap()];
    let body = &body[body.find("<tbody>").unwrap_or(0)..];
    body.split("<tr>")
        .skip(1)
        .map(|row| {
            row.split("<td")
                .skip(1)
                .map(|c| {
                    let c = &c[c.find('>').unwrap() + 1..];
                    c[..c.find("</td>").unwrap()].to_string()
                })
                .collect()
        })
        .collect()
}

/// A report cell shows `want` to four significant digits (`gearwear::format::shown`): the
/// rounding leaves at most half a unit of the fourth digit, 5e-4 of the value.
fn shows(cell: &str, want: f64, what: &str) {
    let got: f64 = cell
        .parse()
        .unwrap_or_else(|_| panic!("{what}: `{cell}` is not a number"));
    assert!(
        (got - want).abs() <= 5e-4 * want.abs(),
        "{what}: the report shows {got}, the study wrote {want}"
    );
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn check_report(run: &Path) {
    let html = std::fs::read_to_string(run.join("report.html")).unwrap();
    // Self-contained: nothing from outside (tests/report_html.rs's list), every image a
    // data URI, every link inside the page or to a file of the run.
    for bad in [
        "http://", "https://", "<script", "<link", "<iframe", "@import", "url(",
    ] {
        assert!(!html.contains(bad), "the report holds `{bad}`");
    }
    assert_eq!(
        html.matches("src=\"").count(),
        html.matches("src=\"data:").count()
    );
    for href in html.split("href=\"").skip(1) {
        let target = &href[..href.find('"').unwrap()];
        assert!(
            target.starts_with('#') || run.join(target).is_file(),
            "the report links {target}"
        );
    }
    // Two wear figures per mode and the ring sensor's sidebands.
    assert_eq!(html.matches("<img").count(), 2 * 2 + 1);
    let st = json(&run.join("stiffness/summary.json"));
    let modes = &st["planetary"]["modes"];
    let rows = table(
        &html,
        "Natural frequencies and mode classes (from the stiffness study).",
    );
    assert_eq!(rows.len(), modes["mode_classes"].as_array().unwrap().len());
    for (i, r) in rows.iter().enumerate() {
        shows(
            &r[1],
            num(&modes["undamped_natural_frequencies_hz"][i]),
            "frequency",
        );
        assert_eq!(r[2], modes["mode_classes"][i].as_str().unwrap());
        shows(&r[3], num(&modes["multiplicities"][i]), "multiplicity");
    }
    let d = &json(&run.join("dynamics/summary.json"))["planetary_dynamics"];
    let rows = table(&html, "(from the dynamics study).");
    assert_eq!(rows.len(), 4, "one row per planet");
    for (i, r) in rows.iter().enumerate() {
        for (c, key) in [
            (1, "planet_tangential_error_um"),
            (2, "planet_radial_error_um"),
            (3, "load_sharing_factor_static"),
            (4, "load_sharing_factor"),
            (5, "load_sharing_factor_ring"),
            (6, "load_sharing_factor_peak"),
        ] {
            shows(&r[c], num(&d[key][i]), key);
        }
        let mesh = |j: usize, k: &str| num(&d["meshes"][j][k]);
        shows(&r[7], mesh(i, "mean_force_n"), "sun mesh mean");
        shows(&r[8], mesh(i, "max_force_n"), "sun mesh max");
        shows(&r[9], mesh(4 + i, "mean_force_n"), "ring mesh mean");
        shows(&r[10], mesh(4 + i, "max_force_n"), "ring mesh max");
    }
    let w = &json(&run.join("wear/summary.json"))["planetary_wear"];
    let rows = table(&html, "(from the wear study; docs/MODEL.md 12.9).");
    let members = w["members"].as_array().unwrap();
    assert_eq!(rows.len(), members.len(), "sun, four planets, ring");
    for (r, m) in rows.iter().zip(members) {
        assert_eq!(r[0], m["member"].as_str().unwrap().replace('_', " "));
        for (k, mode) in ["dynamic", "quasi_static"].iter().enumerate() {
            let f = &m["final"][mode];
            shows(&r[2 + 2 * k], num(&f["max_wear_um"]), "max wear");
            shows(&r[3 + 2 * k], num(&f["volume_mm3"]), "volume");
        }
    }
    for mode in ["dynamic", "quasi_static"] {
        let limit = &w["limiting_member"][mode];
        let member = limit["member"].as_str().unwrap().replace('_', " ");
        assert!(
            html.contains(&format!("the {member} limits the life")),
            "{mode}: the limiting member"
        );
    }
    let g = &json(&run.join("signals/summary.json"))["planetary_signals"];
    let rows = table(&html, "(from the signals study).");
    let mut want = Vec::new();
    for h in g["mesh_harmonics"].as_array().unwrap() {
        want.push(h);
        want.extend(h["sidebands"].as_array().unwrap());
    }
    assert_eq!(rows.len(), want.len());
    for (r, e) in rows.iter().zip(want) {
        assert_eq!(r[0], e["order"].to_string());
        shows(&r[2], num(&e["frequency_hz"]), "frequency");
        shows(&r[3], num(&e["amplitude_n"]), "amplitude");
    }
}
