//! Every number and figure of the documentation that the program produces is the current
//! build's (issue 34). The numbers carry marks naming where they come from
//! (`tests/docs_numbers/mod.rs` describes them); this test runs every run the documents
//! name with the built binary and fails on a number or a figure that differs, naming the
//! file, the line, the expression and both values.
//!
//! To bring the documents up to date after a change that moves a number on purpose:
//!
//! ```sh
//! GEARWEAR_REGEN_DOCS=1 cargo test --release --test docs_generated
//! ```
//!
//! rewrites the marked numbers and copies the marked figures, then `git diff docs README.md`
//! shows what moved. Numbers without marks are not the program's (the paper's values,
//! published tables, the case's inputs), or are exempt for a reason that docs/ARCHITECTURE.md
//! ("Exempt numbers") states: machine-dependent, measured inside a test, only in a refusal,
//! in no output, too long a run.

mod docs_numbers;

use docs_numbers::{all_runs, check_text, execute, format, parse, Marks};
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// README.md and every Markdown file under docs/.
fn documents() -> Vec<PathBuf> {
    let mut files = vec![root().join("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(root().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    docs.sort();
    files.extend(docs);
    files
}

#[test]
fn generated_numbers_and_figures_are_the_builds() {
    let regen = std::env::var_os("GEARWEAR_REGEN_DOCS").is_some();
    let mut marks: BTreeMap<PathBuf, Marks> = BTreeMap::new();
    let mut texts = BTreeMap::new();
    for f in documents() {
        let text = std::fs::read_to_string(&f).unwrap();
        let m = parse(&text).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        texts.insert(f.clone(), text);
        marks.insert(f, m);
    }
    let mut runs = all_runs(&marks).unwrap();
    // The longest first, so that two cores finish together: scripts, wear studies and
    // datasets (many dynamic evaluations), then runs and sweeps, then single evaluations.
    runs.sort_by_key(|r| match r.args.first().map(String::as_str) {
        Some(a) if a.starts_with("scripts/") => 0,
        Some("wear" | "dataset") => 1,
        Some("run" | "sweep" | "signals") => 2,
        _ => 3,
    });
    let work = tempfile::tempdir().unwrap();
    let outputs = execute(
        Path::new(env!("CARGO_BIN_EXE_gearwear")),
        &runs,
        work.path(),
        &root(),
    )
    .unwrap();
    let mut problems = Vec::new();
    for (f, m) in &marks {
        let name = f.strip_prefix(root()).unwrap().display().to_string();
        let doc_dir = f.parent().unwrap();
        let (p, fixed) = check_text(&name, &texts[f], m, &outputs, doc_dir, &root());
        if regen && !p.is_empty() {
            std::fs::write(f, fixed).unwrap();
            for (_, source, image) in &m.images {
                let (run, file) = source.split_once(':').unwrap();
                std::fs::copy(outputs[run].join(file), doc_dir.join(image)).unwrap();
            }
            eprintln!("{name}: rewritten ({} change(s))", p.len());
        }
        problems.extend(p);
    }
    if !regen {
        assert!(
            problems.is_empty(),
            "{} generated number(s) or figure(s) differ from the build:\n{}\n\
             If the change is meant, regenerate: GEARWEAR_REGEN_DOCS=1 cargo test --release --test docs_generated",
            problems.len(),
            problems.join("\n")
        );
    }
}

// The machinery itself, on made-up documents and outputs.

fn fake_run(dir: &Path) -> HashMap<String, PathBuf> {
    std::fs::write(
        dir.join("summary.json"),
        r#"{"a": {"x.y": 14.55396, "n": 3512.4}, "r": 1.2164755, "list": [0.5, 2.0]}"#,
    )
    .unwrap();
    std::fs::write(dir.join("t.csv"), "t_s,force_n\n0,10\n1,30\n2,20\n").unwrap();
    std::fs::write(
        dir.join("branches.csv"),
        "branch,speed_hz,dte_um\nup,1,5\nup,2,6\nup,3,9\nup,4,10\ndown,4,10\ndown,3,9.5\ndown,2,6.5\ndown,1,5\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("meta.json"),
        r#"{"runs": [{"failure": 128709.2}, {"failure": 61951.7, "teeth_um": [10.0, 2.3, 6.9]}]}"#,
    )
    .unwrap();
    HashMap::from([("p".to_string(), dir.to_path_buf())])
}

#[test]
fn a_number_edited_by_hand_is_found_and_regenerated() {
    let dir = tempfile::tempdir().unwrap();
    let runs = fake_run(dir.path());
    let doc = "max DTE <!-- gw:p:/a/x.y|.2f -->14.55<!-- /gw --> um, cut at <!-- gw:p:/a/n|sep -->3 512<!-- /gw --> cycles.\n";
    let m = parse(doc).unwrap();
    let (p, _) = check_text("d.md", doc, &m, &runs, dir.path(), dir.path());
    assert!(p.is_empty(), "{p:?}");
    let edited = doc.replace("14.55", "14.56");
    let m = parse(&edited).unwrap();
    let (p, fixed) = check_text("d.md", &edited, &m, &runs, dir.path(), dir.path());
    assert_eq!(p.len(), 1, "{p:?}");
    assert!(
        p[0].starts_with("d.md:1: `p:/a/x.y` formatted `.2f` gives 14.55; the text says 14.56"),
        "{}",
        p[0]
    );
    assert_eq!(fixed, doc);
}

#[test]
fn expressions_read_json_and_csv_and_combine_them() {
    let dir = tempfile::tempdir().unwrap();
    let runs = fake_run(dir.path());
    let ev = |e: &str| docs_numbers::expr::evaluate(e, &runs).unwrap();
    assert_eq!(ev("p:/list/1"), 2.0);
    assert_eq!(ev("p:t.csv#force_n@max"), 30.0);
    assert_eq!(ev("p:t.csv#force_n@mean"), 20.0);
    assert_eq!(ev("p:t.csv#force_n@1"), 30.0);
    assert_eq!(ev("p:t.csv#force_n@range"), 20.0);
    assert_eq!(ev("(p:/r - 1) * 100"), (1.2164755 - 1.0) * 100.0);
    assert_eq!(ev("p:t.csv#force_n@max / p:/list/1"), 15.0);
    assert_eq!(ev("max(p:/list/0, -p:/list/1, 1)"), 1.0);
    assert!(docs_numbers::expr::evaluate("q:/a", &runs).is_err());
    assert!(docs_numbers::expr::evaluate("p:/nope", &runs).is_err());
    assert!(docs_numbers::expr::evaluate("p:t.csv#nope@max", &runs).is_err());
    assert_eq!(ev("sqrt(p:/list/1 * 8)"), 4.0);
    assert_eq!(ev("p:t.csv#force_n@count"), 3.0);
}

#[test]
fn operands_read_other_json_files_arrays_and_filtered_rows() {
    let dir = tempfile::tempdir().unwrap();
    let runs = fake_run(dir.path());
    let ev = |e: &str| docs_numbers::expr::evaluate(e, &runs);
    assert_eq!(ev("p:meta.json#/runs/1/failure"), Ok(61951.7));
    assert_eq!(ev("p:meta.json#/runs/1/teeth_um@min"), Ok(2.3));
    assert_eq!(ev("p:meta.json#/runs/1/teeth_um@max"), Ok(10.0));
    assert_eq!(ev("p:/list@mean"), Ok(1.25));
    // An array without @AGG, or @AGG on a number, names what is wrong.
    assert!(ev("p:meta.json#/runs/1/teeth_um").is_err());
    assert!(ev("p:/r@max").is_err());
    // Row filters: text, or the same number written differently.
    assert_eq!(ev("p:branches.csv?branch=down#dte_um@1"), Ok(9.5));
    assert_eq!(
        ev("p:branches.csv?branch=up&speed_hz=3.0#dte_um@first"),
        Ok(9.0)
    );
    assert_eq!(ev("p:branches.csv?branch=up#speed_hz@count"), Ok(4.0));
    assert!(ev("p:branches.csv?branch=sideways#dte_um@max").is_err());
    assert!(ev("p:meta.json?branch=up#/runs/0/failure").is_err());
}

#[test]
fn aggregates_interpolate_and_find_rows_by_another_column() {
    let dir = tempfile::tempdir().unwrap();
    let runs = fake_run(dir.path());
    let ev = |e: &str| docs_numbers::expr::evaluate(e, &runs);
    // Linear between the rows around the value, exact on a row, none outside the column.
    assert_eq!(ev("p:t.csv#t_s@at:force_n=25"), Ok(0.75));
    assert_eq!(ev("p:t.csv#t_s@at:force_n=30"), Ok(1.0));
    assert_eq!(ev("p:t.csv#force_n@at:t_s=1.5"), Ok(25.0));
    assert!(ev("p:t.csv#t_s@at:force_n=40").is_err());
    // The first crossing counts: force 25 is reached again between t = 1 and 2.
    assert_eq!(
        ev("p:branches.csv?branch=up#speed_hz@at:dte_um=7.5"),
        Ok(2.5)
    );
    assert_eq!(ev("p:t.csv#t_s@argmax:force_n"), Ok(1.0));
    assert_eq!(ev("p:t.csv#t_s@argmin:force_n"), Ok(0.0));
    // The largest step of dte between neighbouring rows: 6 -> 9 rising, 9.5 -> 6.5 falling.
    assert_eq!(
        ev("p:branches.csv?branch=up#speed_hz@before_jump:dte_um"),
        Ok(2.0)
    );
    assert_eq!(
        ev("p:branches.csv?branch=up#speed_hz@after_jump:dte_um"),
        Ok(3.0)
    );
    assert_eq!(
        ev("p:branches.csv?branch=down#speed_hz@before_jump:dte_um"),
        Ok(3.0)
    );
    assert_eq!(
        ev("p:branches.csv?branch=down#speed_hz@after_jump:dte_um"),
        Ok(2.0)
    );
    assert!(ev("p:t.csv#t_s@argmax:nope").is_err());
    // Trapezoids over t: (10 + 30) / 2 and (30 + 20) / 2 over 2 s.
    assert_eq!(ev("p:t.csv#force_n@mean_over:t_s"), Ok(22.5));
    assert!(ev("p:t.csv#force_n@mean_over:force_n").is_ok());
    assert!(ev("p:branches.csv?branch=up&speed_hz=1#dte_um@mean_over:speed_hz").is_err());
}

#[test]
fn a_column_pattern_reduces_every_matching_column_then_across_them() {
    let dir = tempfile::tempdir().unwrap();
    let runs = fake_run(dir.path());
    std::fs::write(
        dir.path().join("teeth.csv"),
        "rho_mm,tooth0_um,tooth1_um,tooth2_um,gear0_um\n1,2,7,4,9\n2,1,3,6,9\n",
    )
    .unwrap();
    let ev = |e: &str| docs_numbers::expr::evaluate(e, &runs);
    assert_eq!(ev("p:teeth.csv#tooth*_um@max@min"), Ok(2.0));
    assert_eq!(ev("p:teeth.csv#tooth*_um@max@max"), Ok(7.0));
    assert_eq!(ev("p:teeth.csv#tooth*_um@max@mean"), Ok(5.0));
    assert_eq!(ev("p:teeth.csv#tooth*_um@max@count"), Ok(3.0));
    assert_eq!(ev("p:teeth.csv#*_um@first@count"), Ok(4.0));
    assert!(ev("p:teeth.csv#tooth*_um@max").is_err());
    assert!(ev("p:teeth.csv#pinion*@max@max").is_err());
}

#[test]
fn a_code_block_marked_as_a_file_must_show_it() {
    let dir = tempfile::tempdir().unwrap();
    let runs = fake_run(dir.path());
    std::fs::write(dir.path().join("design.toml"), "seed = 7\nstates = 8\n").unwrap();
    let doc =
        "The design:\n<!-- gw-file design.toml -->\n```toml\nseed = 7\nstates = 8\n```\n\nafter\n";
    let m = parse(doc).unwrap();
    let (p, _) = check_text("d.md", doc, &m, &runs, dir.path(), dir.path());
    assert!(p.is_empty(), "{p:?}");
    let edited = doc.replace("states = 8", "states = 9");
    let m = parse(&edited).unwrap();
    let (p, fixed) = check_text("d.md", &edited, &m, &runs, dir.path(), dir.path());
    assert_eq!(p, ["d.md:2: the code block is not the file design.toml"]);
    assert_eq!(fixed, doc);
    assert!(parse("<!-- gw-file design.toml -->\nno block here\n").is_err());
}

#[test]
fn formats_round_as_stated() {
    assert_eq!(format(14.55396, ".2f").unwrap(), "14.55");
    assert_eq!(format(-0.12851, "pct.1").unwrap(), "-12.9");
    assert_eq!(format(0.2164, "pct.1").unwrap(), "+21.6");
    assert_eq!(format(3373.64, "4g").unwrap(), "3374");
    assert_eq!(format(3373.64, "2g").unwrap(), "3400");
    assert_eq!(format(0.056672, "3g").unwrap(), "0.0567");
    assert_eq!(format(9.996, "3g").unwrap(), "10.0");
    assert_eq!(format(400094413.1, "3e").unwrap(), "4.00e8");
    assert_eq!(format(3512.0, "sep").unwrap(), "3 512");
    assert_eq!(format(216012.6, "sep").unwrap(), "216 013");
    assert_eq!(format(-1234567.0, "sep").unwrap(), "-1 234 567");
    assert_eq!(format(522.4, "int").unwrap(), "522");
    assert!(format(f64::NAN, ".2f").is_err());
    assert!(format(1.0, "x").is_err());
}
