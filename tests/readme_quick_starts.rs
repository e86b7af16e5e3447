//! README.md's quick starts, followed on the built binary: each block marked
//! `<!-- quick-start: NAME -->` is read from the README (so the test follows what the
//! README says, not a copy), its commands run in a fresh folder (paths under `examples/`
//! taken from the repository), and the files the README's text names exist and load.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The commands of each marked block: NAME -> lines of its ```sh block.
fn quick_starts() -> BTreeMap<String, Vec<String>> {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let mut out = BTreeMap::new();
    let mut lines = readme.lines();
    while let Some(l) = lines.next() {
        let Some(name) = l
            .trim()
            .strip_prefix("<!-- quick-start: ")
            .and_then(|r| r.strip_suffix(" -->"))
        else {
            continue;
        };
        assert_eq!(lines.next().map(str::trim), Some("```sh"), "{name}");
        let block: Vec<String> = lines
            .by_ref()
            .take_while(|l| l.trim() != "```")
            .map(|l| l.split(" #").next().unwrap_or(l).trim().to_owned())
            .filter(|l| !l.is_empty())
            .collect();
        out.insert(name.to_owned(), block);
    }
    out
}

/// Run the block's commands in `dir`; each must be `gearwear ...` and succeed.
fn follow(block: &[String], dir: &Path) {
    for line in block {
        let mut words = line.split_whitespace();
        assert_eq!(words.next(), Some("gearwear"), "{line}");
        let args: Vec<String> = words
            .map(|w| {
                if w.starts_with("examples/") {
                    root().join(w).to_string_lossy().into_owned()
                } else {
                    w.to_owned()
                }
            })
            .collect();
        let o = Command::new(env!("CARGO_BIN_EXE_gearwear"))
            .args(&args)
            .current_dir(dir)
            .output()
            .unwrap();
        assert!(
            o.status.success(),
            "{line}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
}

fn json(path: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The rows of a CSV file (header apart), each as long as the header.
fn csv_rows(path: &Path) -> Vec<csv::StringRecord> {
    let mut r = csv::Reader::from_path(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let width = r.headers().unwrap().len();
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    assert!(rows.iter().all(|x| x.len() == width), "{}", path.display());
    rows
}

/// A Parquet file's rows, read by the parquet crate (not by gearwear).
fn parquet_rows(path: &Path) -> i64 {
    use parquet::file::reader::{FileReader, SerializedFileReader};
    let f = std::fs::File::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    SerializedFileReader::new(f)
        .unwrap()
        .metadata()
        .file_metadata()
        .num_rows()
}

#[test]
fn the_readme_has_the_three_quick_starts() {
    let q = quick_starts();
    let names: Vec<&str> = q.keys().map(String::as_str).collect();
    assert_eq!(
        names,
        ["condition-monitoring", "drivetrain", "researcher"],
        "{q:?}"
    );
}

#[test]
fn researcher_quick_start() {
    let d = tempfile::tempdir().unwrap();
    follow(&quick_starts()["researcher"], d.path());
    for run in ["paper", "paper_flank"] {
        let s = json(&d.path().join(run).join("summary.json"));
        assert!(s["paper_comparison"].is_object(), "{run}");
        let html = std::fs::read_to_string(d.path().join(run).join("report.html")).unwrap();
        assert!(html.contains("</html>"), "{run}");
    }
}

#[test]
fn condition_monitoring_quick_start() {
    let d = tempfile::tempdir().unwrap();
    follow(&quick_starts()["condition-monitoring"], d.path());
    for rec in ["healthy", "class6"] {
        let dir = d.path().join(rec);
        let rows = csv_rows(&dir.join("record.csv")).len();
        assert!(rows > 0, "{rec}");
        assert_eq!(
            parquet_rows(&dir.join("record.parquet")),
            rows as i64,
            "{rec}"
        );
    }
    // The grade-6 pinion's record differs from the healthy one.
    // A missing field fails here, so two absent values cannot pass as "different".
    let rms = |rec: &str| {
        json(&d.path().join(rec).join("summary.json"))["indicators"][0]["rms"]
            .as_f64()
            .unwrap_or_else(|| panic!("{rec}: summary.json lacks indicators[0].rms"))
    };
    assert_ne!(rms("healthy"), rms("class6"));
    // The index: one row per record (2 conditions x 2 wear states), each record's file
    // present and readable, as the README's pandas lines read them.
    let ds = d.path().join("dataset");
    let index = csv_rows(&ds.join("index.csv"));
    assert_eq!(index.len(), 4);
    assert_eq!(parquet_rows(&ds.join("index.parquet")), 4);
    let head = csv::Reader::from_path(ds.join("index.csv"))
        .unwrap()
        .headers()
        .unwrap()
        .clone();
    let file = head.iter().position(|h| h == "file").unwrap();
    for row in &index {
        assert!(parquet_rows(&ds.join(&row[file])) > 0, "{}", &row[file]);
    }
}

#[test]
fn drivetrain_quick_start() {
    let d = tempfile::tempdir().unwrap();
    follow(&quick_starts()["drivetrain"], d.path());
    assert!(!csv_rows(&d.path().join("spectrum/spectrum.csv")).is_empty());
    let s = json(&d.path().join("duty/summary.json"));
    let life = &s["load_spectrum"]["life"];
    assert_eq!(life["limit_um"].as_f64(), Some(10.0), "{life}");
    assert!(life["spectrum"]["cycles"].as_f64().unwrap() > 0.0, "{life}");
}
