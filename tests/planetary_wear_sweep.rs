//! `gearwear sweep --run wear` on a planetary set (`study::sweep::planetary_wear_row`,
//! docs/MODEL.md 12.17), checked against independent facts:
//! - every wear column of a row is `gearwear wear`'s summary.json of the row's case (run on
//!   its own, through the wear job and its report: another path through the application),
//!   and every mesh's force column the first row of its `mesh_history_dynamic.csv`; the
//!   same under a `[load_spectrum]`;
//! - identical, equally spaced planets in phase wear alike in every row;
//! - Archard's law takes the same volume from both flanks of a contact: the sun's volume
//!   column is the sum of the planets' sun-side ones, the ring's of their ring-side ones;
//! - the columns name every member flank;
//! - an interrupted sweep, resumed, writes the uninterrupted sweep's table byte for byte,
//!   and a finished record edited (with its checksum recomputed) is refused on resume.

mod common;
use common::{gearwear, read_csv, stderr};
use gearwear::study::sweep::CaseRecord;
use serde_json::Value;
use std::path::Path;

/// The default set (24 / 30 / 84, four planets in phase: z_s / N = 6) with a short wear
/// study of a few updates.
const SET: &str = "[planetary]\n[wear]\ntotal_cycles = 20000\nblock_cycles = 10000\n";

/// Two bins on the sun (torque N m, speed Hz, share), the monitoring bin the first.
const SPECTRUM: &str = "[load_spectrum]\nbins = [{torque_nm = 60, input_speed_hz = 30, share = 0.7}, {torque_nm = 90, input_speed_hz = 20, share = 0.3}]\n";

const MODES: [&str; 2] = ["dynamic", "quasi_static"];

fn write_case(dir: &Path, text: &str) -> String {
    let p = dir.join("case.toml");
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_owned()
}

fn ok(args: &[&str]) {
    let o = gearwear(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
}

/// `gearwear sweep --run wear` of `case` over `vary` into `out`: its header and rows.
fn sweep(case: &str, vary: &str, out: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let o = out.to_str().unwrap();
    ok(&[
        "-q", "sweep", "--config", case, "--run", "wear", "--vary", vary, "--out", o,
    ]);
    read_csv(&out.join("sweep.csv"))
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Equal to 1e-12 relative: both are the same loop's numbers, the CSV's and the JSON's
/// written to round trip exactly, so only a difference of program path (a different
/// model, block rule or reduction) could part them.
fn same(got: &str, want: f64, what: &str) {
    let g: f64 = got.parse().unwrap_or_else(|_| panic!("{what}: `{got}`"));
    assert!(
        (g - want).abs() <= 1e-12 * want.abs(),
        "{what}: sweep {g}, wear {want}"
    );
}

/// The sweep column stem of a flank of `gearwear wear`'s summary: `planet_2` /
/// `ring_side` is `planet2_ring_side`, the sun's and the ring's their member.
fn stem(member: &str, flank: &str) -> String {
    let m = member.replace("planet_", "planet");
    if member == flank {
        m
    } else {
        format!("{m}_{flank}")
    }
}

/// Check a sweep row against `gearwear wear` of the same case (`set`: the row's value as
/// a `--set`), returning the number of flank columns checked.
fn row_is_the_wear_study(
    case: &str,
    set: &str,
    head: &[String],
    row: &[String],
    dir: &Path,
) -> usize {
    let col = |name: &str| {
        let i = head
            .iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("no column {name} in {head:?}"));
        row[i].as_str()
    };
    let out = dir.join(set.replace(['=', '.'], "_"));
    ok(&[
        "-q",
        "wear",
        "--config",
        case,
        "--set",
        set,
        "--out",
        out.to_str().unwrap(),
    ]);
    let s: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let p = &s["planetary_wear"];
    let mut flanks = 0;
    for m in p["members"].as_array().unwrap() {
        let member = m["member"].as_str().unwrap();
        for mode in MODES {
            for (flank, v) in m["final"][mode]["flanks"].as_object().unwrap() {
                let name = format!("{}_wear_max_{mode}_um", stem(member, flank));
                same(col(&name), num(&v["max_wear_um"]), &name);
                let name = format!("{}_wear_volume_{mode}_mm3", stem(member, flank));
                same(col(&name), num(&v["volume_mm3"]), &name);
                flanks += 1;
            }
        }
    }
    for mode in MODES {
        same(
            col(&format!("wear_updates_{mode}")),
            num(&p["updates"][mode]),
            "updates",
        );
        same(
            col(&format!("wear_cycles_{mode}")),
            num(&p["input_cycles"][mode]),
            "cycles",
        );
        // The pair's wear columns are the first sun-planet mesh's members: the sun, and
        // planet 1's sun-side flank.
        same(
            col(&format!("wear_max_pinion_{mode}_um")),
            num(&p["members"][0]["final"][mode]["flanks"]["sun"]["max_wear_um"]),
            "pinion",
        );
        same(
            col(&format!("wear_max_gear_{mode}_um")),
            num(&p["members"][1]["final"][mode]["flanks"]["sun_side"]["max_wear_um"]),
            "gear",
        );
    }
    // Every mesh's mean force with the new set: the dynamic run's first update.
    let (mh, mrows) = read_csv(&out.join("mesh_history_dynamic.csv"));
    for (i, name) in mh.iter().enumerate() {
        if let Some(mesh) = name
            .strip_prefix("mean_force_")
            .and_then(|n| n.strip_suffix("_n"))
        {
            let c = format!("{}_mesh_force_mean_n", mesh.replace("planet_", "planet"));
            same(col(&c), mrows[0][i].parse().unwrap(), &c);
        }
    }
    flanks
}

#[test]
fn every_wear_column_of_a_planetary_row_is_the_wear_summary_of_its_case() {
    let d = tempfile::tempdir().unwrap();
    let case = write_case(d.path(), SET);
    let (h, rows) = sweep(&case, "operating.load_torque_nm=40,60", &d.path().join("s"));
    assert_eq!(rows.len(), 2);
    // The columns name every member flank, both modes: sun, each planet's two, ring.
    let mut stems = vec!["sun".to_string(), "ring".to_string()];
    for n in 1..=4 {
        stems.push(format!("planet{n}_sun_side"));
        stems.push(format!("planet{n}_ring_side"));
    }
    for s in &stems {
        for mode in MODES {
            let c = format!("{s}_wear_max_{mode}_um");
            assert!(h.contains(&c), "no column {c}");
        }
    }
    let col = |name: &str| h.iter().position(|c| c == name).unwrap();
    for (row, torque) in rows.iter().zip(["40", "60"]) {
        let set = format!("operating.load_torque_nm={torque}");
        // 10 flanks x 2 modes, each checked.
        assert_eq!(row_is_the_wear_study(&case, &set, &h, row, d.path()), 20);
        // Identical planets in phase: every planet's equations are planet 1's at every
        // instant, so their wear differs by round-off only (1e-12 relative, as
        // `gearwear wear`'s own test of the set), and every load share is 1.
        for mode in MODES {
            for side in ["sun_side", "ring_side"] {
                let at = |n: usize| -> f64 {
                    row[col(&format!("planet{n}_{side}_wear_max_{mode}_um"))]
                        .parse()
                        .unwrap()
                };
                assert!(at(1) > 0.0, "{mode} {side}: no wear");
                for n in 2..=4 {
                    assert!(
                        (at(n) / at(1) - 1.0).abs() <= 1e-12,
                        "{mode} planet {n} {side}: {} against {}",
                        at(n),
                        at(1)
                    );
                }
            }
        }
        for n in 1..=4 {
            let l: f64 = row[col(&format!("planet{n}_load_sharing_factor"))]
                .parse()
                .unwrap();
            assert!((l - 1.0).abs() <= 1e-12, "planet {n}: share {l}");
        }
    }
    // Archard's law takes the same volume from both flanks of a contact (each loses
    // k F times their sliding distance, however the depth is spread over each flank), so
    // the sun loses what the planets' sun-side flanks lose together, and the ring what
    // their ring-side flanks do. Each volume is summed on its own flank's grid: 1e-4
    // relative (measured 2.3e-5, the same at both torques: the two grids' integration).
    for row in &rows {
        for mode in MODES {
            let v = |stem: &str| -> f64 {
                row[col(&format!("{stem}_wear_volume_{mode}_mm3"))]
                    .parse()
                    .unwrap()
            };
            for (member, side) in [("sun", "sun_side"), ("ring", "ring_side")] {
                let planets: f64 = (1..=4).map(|n| v(&format!("planet{n}_{side}"))).sum();
                let own = v(member);
                assert!(own > 0.0, "{mode} {member}: no volume");
                assert!(
                    (own / planets - 1.0).abs() <= 1e-4,
                    "{mode}: the {member} lost {own} mm^3, the planets' {side} flanks {planets}"
                );
            }
        }
    }
    // The larger torque wears the sun more (a sanity check of the rows' order).
    let sun = |r: &Vec<String>| {
        r[col("sun_wear_max_quasi_static_um")]
            .parse::<f64>()
            .unwrap()
    };
    assert!(sun(&rows[1]) > sun(&rows[0]));
}

#[test]
fn a_spectrum_row_is_the_wear_summary_of_its_case_under_the_spectrum() {
    // The spectrum's scale as the axis: each row runs the set's loop over both bins
    // (`duty::planetary`), as `gearwear wear` runs the case under its spectrum.
    let d = tempfile::tempdir().unwrap();
    let case = write_case(d.path(), &format!("{SET}{SPECTRUM}"));
    let vary = "load_spectrum.torque_scale=1,1.2";
    let out = d.path().join("s");
    let (h, rows) = sweep(&case, vary, &out);
    assert_eq!(rows.len(), 2);
    for (row, scale) in rows.iter().zip(["1", "1.2"]) {
        let set = format!("load_spectrum.torque_scale={scale}");
        assert_eq!(row_is_the_wear_study(&case, &set, &h, row, d.path()), 20);
    }
    // Rerun: both records are finished, recomputed under the spectrum as the sweep ran
    // them (bit for bit, or refused) and kept.
    let table = std::fs::read(out.join("sweep.csv")).unwrap();
    let o = out.to_str().unwrap();
    let r = gearwear(&[
        "sweep", "--config", &case, "--run", "wear", "--vary", vary, "--out", o,
    ]);
    assert!(r.status.success(), "{}", stderr(&r));
    assert!(
        stderr(&r).contains("0 computed, 2 skipped"),
        "{}",
        stderr(&r)
    );
    assert!(std::fs::read(out.join("sweep.csv")).unwrap() == table);
}

#[test]
fn an_interrupted_set_wear_sweep_resumes_to_the_same_table() {
    let d = tempfile::tempdir().unwrap();
    let case = write_case(d.path(), SET);
    let vary = "operating.load_torque_nm=40,50,60";
    let whole = d.path().join("whole");
    sweep(&case, vary, &whole);
    let table = std::fs::read(whole.join("sweep.csv")).unwrap();
    // Interrupted after cases 0 and 2: only their records are on disk (the table is
    // written at the end). The rerun recomputes a sample of the finished records (all
    // of them here: bit for bit, or it refuses), runs case 1, and writes the same bytes.
    let cut = d.path().join("cut");
    sweep(&case, vary, &cut);
    std::fs::remove_file(cut.join("cases/1.json")).unwrap();
    std::fs::remove_file(cut.join("sweep.csv")).unwrap();
    let o = cut.to_str().unwrap();
    let r = gearwear(&[
        "sweep", "--config", &case, "--run", "wear", "--vary", vary, "--out", o,
    ]);
    assert!(r.status.success(), "{}", stderr(&r));
    assert!(
        stderr(&r).contains("1 computed, 2 skipped"),
        "{}",
        stderr(&r)
    );
    assert!(std::fs::read(cut.join("sweep.csv")).unwrap() == table);
    // A finished record edited, its checksum recomputed: the recomputation finds it.
    let path = cut.join("cases/2.json");
    let mut rec = CaseRecord::read(&path).unwrap().unwrap();
    let i = rec
        .columns
        .iter()
        .position(|c| c == "ring_wear_max_dynamic_um")
        .unwrap();
    rec.results[i] = rec.results[i].map(|x| x * 1.01);
    let rec = CaseRecord {
        checksum: None,
        ..rec
    }
    .sealed();
    std::fs::write(&path, serde_json::to_string_pretty(&rec).unwrap()).unwrap();
    let r = gearwear(&[
        "sweep", "--config", &case, "--run", "wear", "--vary", vary, "--out", o,
    ]);
    let err = stderr(&r);
    assert_eq!(r.status.code(), Some(2), "{err}");
    for needle in ["cases/2.json", "ring_wear_max_dynamic_um"] {
        assert!(err.contains(needle), "lacks `{needle}`: {err}");
    }
}
