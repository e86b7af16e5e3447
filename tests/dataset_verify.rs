//! Every record of a dataset verifiable (issue 33, "Verify by recomputation, never by
//! trusted fields"): forged sidecars, signals and trajectories whose checksums were
//! recomputed by the forger are refused on resume (exit 2, naming the file, no record
//! changed), `verify_folder` recomputes a sample of records from the design and finds
//! them, and the detection probability of the sample stated in docs/RELIABILITY.md is
//! checked against a direct enumeration.

mod common;

use common::{gearwear, ok, stderr};
use gearwear::app::budget::DEFAULT;
use gearwear::app::dataset::jobs::verify_folder;
use gearwear::app::dataset::DesignSource;
use gearwear::study::budget::Budget;
use gearwear::study::dataset::verify::{detection_probability, states_to_recompute};
use serde_json::Value;
use std::path::Path;

/// One condition, two states, one speed, two noise realisations: four records.
const DESIGN: &str =
    "seed = 3\n[run_to_failure]\nstates = 2\nmax_cycles = 1e4\nwear_limit_um = 10\n\
[operating]\ninput_speed_hz = [30]\n[records]\nnoise_realisations = 2\n";

fn run(dir: &Path) -> std::process::Output {
    let p = |s: &str| dir.join(s).to_str().unwrap().to_owned();
    gearwear(&[
        "dataset",
        "-q",
        "--design",
        &p("design.toml"),
        "--out",
        &p("ds"),
    ])
}

/// The dataset's own files (records, signals, state, index and metadata), by path.
fn dataset_files(ds: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    for sub in ["records", "signals", "state"] {
        let mut names: Vec<_> = std::fs::read_dir(ds.join(sub))
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        names.sort();
        for n in names {
            let rel = format!("{sub}/{n}");
            out.push((rel.clone(), std::fs::read(ds.join(&rel)).unwrap()));
        }
    }
    for f in ["index.csv", "metadata.json"] {
        out.push((f.into(), std::fs::read(ds.join(f)).unwrap()));
    }
    out
}

fn read_json(p: &Path) -> Value {
    serde_json::from_slice(&std::fs::read(p).unwrap()).unwrap()
}

fn write_json(p: &Path, v: &Value) {
    std::fs::write(p, serde_json::to_vec_pretty(v).unwrap()).unwrap();
}

fn sha256_hex(b: &[u8]) -> String {
    gearwear::checksum::sha256_hex(b)
}

/// The forgeries of a kept file, each a (file, edit) with the checksum the sidecar
/// carries recomputed where the edit touches a signal.
type Forgery = (&'static str, &'static str, fn(&Path));

/// Sets `labels.<key>` of the sidecar `rel` to `value` (nothing else changed).
fn edit_label(ds: &Path, rel: &str, key: &str, value: Value) {
    let p = ds.join(rel);
    let mut s = read_json(&p);
    assert!(s["labels"].get(key).is_some(), "{rel} has labels.{key}");
    assert_ne!(
        s["labels"][key], value,
        "{rel}: the forgery changes labels.{key}"
    );
    s["labels"][key] = value;
    write_json(&p, &s);
}

fn scale_wear(ds: &Path, f: f64) {
    let p = ds.join("state/trajectory_healthy.json");
    let mut t = read_json(&p);
    for r in t["trajectory"]["records"].as_array_mut().unwrap() {
        for k in ["pinion_m", "gear_m"] {
            for x in r["wear"][k].as_array_mut().unwrap() {
                *x = (x.as_f64().unwrap() * f).into();
            }
        }
    }
    write_json(&p, &t);
}

const FORGERIES: [Forgery; 13] = [
    ("max wear x3", "records/0000001.json", |ds| {
        let p = ds.join("records/0000001.json");
        let mut s = read_json(&p);
        let w = s["labels"]["max_wear_pinion_um"].as_f64().unwrap();
        s["labels"]["max_wear_pinion_um"] = (3.0 * w + 1.0).into();
        write_json(&p, &s);
    }),
    ("remaining cycles", "records/0000002.json", |ds| {
        let p = ds.join("records/0000002.json");
        let mut s = read_json(&p);
        s["labels"]["remaining_cycles"] = 1.0.into();
        write_json(&p, &s);
    }),
    ("an indicator", "records/0000003.json", |ds| {
        let p = ds.join("records/0000003.json");
        let text = std::fs::read_to_string(&p).unwrap();
        // The first indicator value of the first channel, doubled.
        let mut s: Value = serde_json::from_str(&text).unwrap();
        let ind = &mut s["labels"]["indicators"][0];
        let key = ind
            .as_object()
            .unwrap()
            .iter()
            .find(|(_, v)| v.as_f64().is_some_and(|x| x != 0.0))
            .map(|(k, _)| k.clone())
            .unwrap();
        let x = ind[&key].as_f64().unwrap();
        ind[&key] = (2.0 * x).into();
        write_json(&p, &s);
    }),
    (
        "another record's signal, its checksum recomputed",
        "signals/0000000.parquet",
        |ds| {
            let other = std::fs::read(ds.join("signals/0000001.parquet")).unwrap();
            std::fs::write(ds.join("signals/0000000.parquet"), &other).unwrap();
            let p = ds.join("records/0000000.json");
            let mut s = read_json(&p);
            s["signal_sha256"] = sha256_hex(&other).into();
            write_json(&p, &s);
        },
    ),
    (
        "every wear value x3",
        "state/trajectory_healthy.json",
        |ds| scale_wear(ds, 3.0),
    ),
    ("negative wear", "state/trajectory_healthy.json", |ds| {
        scale_wear(ds, -1.0)
    }),
    ("cut to 3 updates", "state/trajectory_healthy.json", |ds| {
        let p = ds.join("state/trajectory_healthy.json");
        let mut t = read_json(&p);
        let recs = t["trajectory"]["records"].as_array_mut().unwrap();
        assert!(recs.len() > 3, "the trajectory has more than 3 updates");
        recs.truncate(3);
        let end = recs[2]["wear"]["cycles"].clone();
        t["trajectory"]["end_cycles"] = end;
        write_json(&p, &t);
    }),
    // Issue 33's other label edits: each a field of the record's identity or labels.
    ("severity", "records/0000001.json", |ds| {
        edit_label(ds, "records/0000001.json", "severity", 2.0.into())
    }),
    ("condition", "records/0000002.json", |ds| {
        edit_label(ds, "records/0000002.json", "condition", "crack".into())
    }),
    ("noise seed", "records/0000003.json", |ds| {
        let p = ds.join("records/0000003.json");
        let seed = read_json(&p)["labels"]["noise_seed"].as_u64().unwrap();
        edit_label(ds, "records/0000003.json", "noise_seed", (seed + 1).into())
    }),
    ("input speed", "records/0000000.json", |ds| {
        edit_label(ds, "records/0000000.json", "input_speed_hz", 31.0.into())
    }),
    // Positive wear whose updates are out of order (wear falling with cycles): two
    // updates' wear swapped.
    (
        "a non-monotone trajectory",
        "state/trajectory_healthy.json",
        |ds| {
            let p = ds.join("state/trajectory_healthy.json");
            let mut t = read_json(&p);
            let recs = t["trajectory"]["records"].as_array_mut().unwrap();
            let (a, b) = (recs[1]["wear"].clone(), recs[2]["wear"].clone());
            let cycles = |w: &Value| w["cycles"].clone();
            let (ca, cb) = (cycles(&a), cycles(&b));
            recs[1]["wear"] = b;
            recs[1]["wear"]["cycles"] = ca;
            recs[2]["wear"] = a;
            recs[2]["wear"]["cycles"] = cb;
            write_json(&p, &t);
        },
    ),
    ("failure cycles", "state/trajectory_healthy.json", |ds| {
        let p = ds.join("state/trajectory_healthy.json");
        let mut t = read_json(&p);
        t["trajectory"]["failure_cycles"] = 5000.0.into();
        write_json(&p, &t);
    }),
];

#[test]
fn forged_records_and_trajectories_are_refused_on_resume_and_found_by_verify() {
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("design.toml"), DESIGN).unwrap();
    let r = run(d.path());
    assert!(r.status.success(), "{}", stderr(&r));
    let ds = d.path().join("ds");
    assert!(
        !ds.join("INCOMPLETE").exists(),
        "a published dataset is not marked"
    );
    let design = DesignSource::file(&d.path().join("design.toml")).unwrap();

    // The genuine folder verifies: every state recomputed (2 <= the sample), no problem.
    let v = verify_folder(&design, &ds, 8, 1, DEFAULT.as_ref()).unwrap();
    assert_eq!(v.problems, Vec::<String>::new());
    assert_eq!(v.states_recomputed, vec![0, 1]);
    assert_eq!((v.records_present, v.trajectories_verified), (4, 1));
    let genuine = dataset_files(&ds);

    for (what, file, forge) in FORGERIES {
        forge(&ds);
        let forged = dataset_files(&ds);
        let v = verify_folder(&design, &ds, 8, 1, DEFAULT.as_ref()).unwrap();
        assert!(
            v.problems
                .iter()
                .any(|p| p.contains(&file[..file.len() - 8])),
            "{what}: verify names {file}: {:?}",
            v.problems
        );
        let r = run(d.path());
        let e = stderr(&r);
        assert_eq!(r.status.code(), Some(2), "{what}: {e}");
        assert!(!e.contains("panicked"), "{e}");
        assert!(e.contains("edited or is not this design's"), "{what}: {e}");
        assert_eq!(
            dataset_files(&ds),
            forged,
            "{what}: the resume changed no record"
        );
        assert!(
            ds.join("INCOMPLETE").exists(),
            "{what}: the folder stays marked"
        );
        // Undo the forgery: the resume then publishes the genuine dataset again.
        for (rel, bytes) in &genuine {
            std::fs::write(ds.join(rel), bytes).unwrap();
        }
        ok(&[
            "dataset",
            "-q",
            "--design",
            d.path().join("design.toml").to_str().unwrap(),
            "--out",
            ds.to_str().unwrap(),
        ]);
        assert!(!ds.join("INCOMPLETE").exists());
    }

    // A planted record beyond the design's ids: named by verify, never indexed.
    let planted = ds.join("records/0000099.json");
    let mut s = read_json(&ds.join("records/0000001.json"));
    s["labels"]["record_id"] = 99.into();
    s["labels"]["file"] = "signals/0000099.parquet".into();
    write_json(&planted, &s);
    std::fs::copy(
        ds.join("signals/0000001.parquet"),
        ds.join("signals/0000099.parquet"),
    )
    .unwrap();
    let v = verify_folder(&design, &ds, 8, 1, DEFAULT.as_ref()).unwrap();
    assert!(
        v.problems
            .iter()
            .any(|p| p.contains("0000099.json") && p.contains("beyond")),
        "{:?}",
        v.problems
    );

    // The check is counted against the run budget before any record is read (issue
    // 33: it was budgeted nowhere). Its count: the kept trajectory checked (9 updates
    // from rest, 0.27 s at the built-in case's rates) and both states recomputed, so a
    // budget of 1 ms cannot hold it, and one of 1e-9 the default (0.6 us) refuses it
    // naming time, while no budget lets it run. A budget that holds it changes nothing.
    let tiny = Budget::scaled(1e-9);
    let e = verify_folder(&design, &ds, 8, 1, Some(&tiny)).unwrap_err();
    let m = format!("{e:#}");
    assert!(m.contains("over its budget") && m.contains("time ~"), "{m}");
    assert!(verify_folder(&design, &ds, 8, 1, None).is_ok());
}

#[test]
fn records_planted_far_beyond_the_designs_ids_are_never_indexed() {
    // Issue 33: extra records with ids 99, 500 and 1e18 appeared in the index.
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("design.toml"), DESIGN).unwrap();
    let r = run(d.path());
    assert!(r.status.success(), "{}", stderr(&r));
    let ds = d.path().join("ds");
    for id in [99u64, 500, 1_000_000_000_000_000_000] {
        let mut s = read_json(&ds.join("records/0000001.json"));
        s["labels"]["record_id"] = id.into();
        s["labels"]["file"] = format!("signals/{id:07}.parquet").into();
        write_json(&ds.join(format!("records/{id:07}.json")), &s);
        std::fs::copy(
            ds.join("signals/0000001.parquet"),
            ds.join(format!("signals/{id:07}.parquet")),
        )
        .unwrap();
    }
    let r = run(d.path());
    assert!(r.status.success(), "{}", stderr(&r));
    let (h, rows) = common::read_csv(&ds.join("index.csv"));
    let id = h.iter().position(|c| c == "record_id").unwrap();
    let ids: Vec<&str> = rows.iter().map(|r| r[id].as_str()).collect();
    assert_eq!(
        ids,
        ["0", "1", "2", "3"],
        "only the design's records are indexed"
    );
}

/// Binomial coefficient, exact in u128 for the small sizes enumerated here.
fn choose(n: u128, k: u128) -> u128 {
    if k > n {
        return 0;
    }
    (0..k).fold(1, |acc, i| acc * (n - i) / (i + 1))
}

#[test]
fn the_detection_probability_is_the_enumerated_share_of_samples_that_find_a_forgery() {
    // Every sample the rule can draw (first, last, and k - 2 of the n - 2 others, all
    // subsets equally likely) enumerated as bit masks; forged states: m of the others.
    for n in 3..=14usize {
        for k in 2..=n {
            for m in 0..=(n - 2) {
                let others = n - 2;
                let forged = (1u32 << m) - 1; // the first m of the others
                let (mut found, mut all) = (0u64, 0u64);
                for mask in 0u32..(1 << others) {
                    if mask.count_ones() as usize != (k - 2).min(others) {
                        continue;
                    }
                    all += 1;
                    found += u64::from(mask & forged != 0);
                }
                let p = if n <= k {
                    f64::from(u8::from(m > 0))
                } else {
                    found as f64 / all as f64
                };
                let q = detection_probability(n, m, k);
                // Both are ratios of integers below 2^14, computed in f64: 1e-12.
                assert!((p - q).abs() < 1e-12, "n {n} k {k} m {m}: {p} vs {q}");
                // The closed form of the docs: 1 - C(n-2-m, k-2) / C(n-2, k-2).
                if n > k {
                    let c = 1.0
                        - choose((others - m) as u128, (k - 2) as u128) as f64
                            / choose(others as u128, (k - 2) as u128) as f64;
                    assert!((c - q).abs() < 1e-12, "n {n} k {k} m {m}");
                }
            }
        }
    }
    // One forged state among the others is found with probability (k - 2) / (n - 2).
    assert!((detection_probability(1002, 1, 8) - 6.0 / 1000.0).abs() < 1e-15);
}

#[test]
fn the_sampler_draws_the_first_the_last_and_uniform_others() {
    // n = 10, k = 4: 2 of the 8 others. Forged {3, 6}: missed with probability
    // C(6, 2) / C(8, 2) = 15 / 28. Over 20,000 seeds the share found is within 5 standard
    // errors (0.0035 each) of 13 / 28.
    let (n, k, seeds) = (10, 4, 20_000u64);
    let mut found = 0u64;
    for seed in 0..seeds {
        let s = states_to_recompute(n, k, seed);
        assert_eq!(s.len(), k);
        assert!(s.contains(&0) && s.contains(&(n - 1)));
        found += u64::from(s.contains(&3) || s.contains(&6));
    }
    let share = found as f64 / seeds as f64;
    let p = 13.0 / 28.0;
    let se = (p * (1.0 - p) / seeds as f64).sqrt();
    assert!((share - p).abs() < 5.0 * se, "{share} vs {p}");
    assert_eq!(states_to_recompute(5, 8, 1), vec![0, 1, 2, 3, 4]);
}

fn p(dir: &Path, s: &str) -> String {
    dir.join(s).to_str().unwrap().to_owned()
}

#[test]
fn merges_of_damaged_or_foreign_shards_are_refused_or_name_the_records_left_out() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    std::fs::write(dir.join("a.toml"), DESIGN).unwrap();
    std::fs::write(dir.join("b.toml"), DESIGN.replace("seed = 3", "seed = 4")).unwrap();
    for (design, shard, out) in [
        ("a.toml", "1/2", "s1"),
        ("a.toml", "2/2", "s2"),
        ("b.toml", "2/2", "s3"),
    ] {
        ok(&[
            "dataset",
            "-q",
            "--design",
            &p(dir, design),
            "--shard",
            shard,
            "--out",
            &p(dir, out),
        ]);
    }
    let merge = |inputs: &[&str]| {
        let mut a = vec!["dataset-merge".to_owned(), "-q".to_owned()];
        a.extend(inputs.iter().map(|i| p(dir, i)));
        a.extend(["--out".to_owned(), p(dir, "merged")]);
        gearwear(&a.iter().map(String::as_str).collect::<Vec<_>>())
    };
    let refused = |inputs: &[&str], needle: &str| {
        let before = common::snapshot(dir);
        let r = merge(inputs);
        let e = stderr(&r);
        assert_eq!(r.status.code(), Some(2), "{inputs:?}: {e}");
        assert!(e.contains(needle), "{inputs:?}: {e}");
        assert!(
            !dir.join("merged").exists(),
            "{inputs:?}: the target is untouched"
        );
        assert_eq!(common::snapshot(dir), before);
    };
    // Shards of two designs.
    refused(&["s1", "s3"], "a shard of another dataset");

    let desc = dir.join("s2/state/dataset.json");
    let genuine = std::fs::read(&desc).unwrap();
    // The design inside the description edited, its key kept: not its own key.
    let mut v = read_json(&desc);
    v["design"] = v["design"]
        .as_str()
        .unwrap()
        .replace("noise_realisations = 2", "noise_realisations = 3")
        .into();
    write_json(&desc, &v);
    refused(&["s1", "s2"], "does not give its own dataset key");
    // ... and with the key recomputed by the forger: another dataset than s1's.
    v["dataset_key"] = gearwear::app::dataset::plan::key_of_description(&v)
        .unwrap()
        .into();
    write_json(&desc, &v);
    refused(&["s1", "s2"], "a shard of another dataset");
    // The description's other fields edited (the metadata is written from it): it differs
    // from the first input's under the same key.
    std::fs::write(&desc, &genuine).unwrap();
    let mut v = read_json(&desc);
    v["seed"] = 99.into();
    write_json(&desc, &v);
    refused(&["s1", "s2"], "differs from the first input's");
    std::fs::write(&desc, &genuine).unwrap();

    // A forged trajectory: refused, naming it.
    let traj = dir.join("s2/state/trajectory_healthy.json");
    let genuine_t = std::fs::read(&traj).unwrap();
    scale_wear(&dir.join("s2"), 3.0);
    refused(&["s1", "s2"], "trajectory_healthy.json");
    std::fs::write(&traj, &genuine_t).unwrap();

    // A record whose signal file is gone: merged without it, named, counted missing.
    std::fs::remove_file(dir.join("s2/signals/0000003.parquet")).unwrap();
    let r = merge(&["s1", "s2"]);
    let e = stderr(&r);
    assert_eq!(r.status.code(), Some(1), "{e}");
    assert!(e.contains("record 3 of") && e.contains("left out"), "{e}");
    let m = read_json(&dir.join("merged/metadata.json"));
    assert_eq!(m["records_missing"], serde_json::json!([3]));
    assert_eq!(m["records_present"], 3);
    assert!(!dir.join("merged/INCOMPLETE").exists());
}

#[test]
fn a_killed_dataset_run_leaves_its_folder_marked_incomplete_until_a_resume_publishes() {
    let d = tempfile::tempdir().unwrap();
    let design = DESIGN.replace("states = 2", "states = 40");
    std::fs::write(d.path().join("design.toml"), design).unwrap();
    let ds = d.path().join("ds");
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args([
            "dataset",
            "-q",
            "--design",
            &p(d.path(), "design.toml"),
            "--out",
            &p(d.path(), "ds"),
        ])
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    // Killed once it has written its first record (polled; the run takes seconds).
    let started = std::time::Instant::now();
    while std::fs::read_dir(ds.join("records")).map_or(0, Iterator::count) == 0 {
        assert!(started.elapsed().as_secs() < 120, "no record written");
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(
        ds.join("INCOMPLETE").exists(),
        "a killed run leaves the folder marked"
    );
    let r = run(d.path());
    assert!(r.status.success(), "{}", stderr(&r));
    assert!(!ds.join("INCOMPLETE").exists(), "published: the mark goes");
    assert_eq!(read_json(&ds.join("metadata.json"))["records_present"], 80);
}
