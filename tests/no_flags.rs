//! No library message names a command-line flag: Python users read the library's errors
//! too, and cannot pass flags. The command line words a message's arguments as flags
//! itself (`cli::flag`, through `gearwear::remedy`).
//!
//! Two checks: (1) every string literal of the library's sources outside `src/cli/`
//! (tests aside) is scanned for `--` followed by a letter; (2) the messages themselves are
//! built, from inputs that make each kind of error, and scanned in the library's own
//! words (`Display`), while the command line's wording of the same errors must name the
//! flag.

// The command line's spelling of each argument: its own table.
use gearwear::cli::flag;

use gearwear::app::{
    DynamicsJob, Job, JobError, PredictJob, PredictOptions, SweepJob, TransmissionErrorSource,
    WearJob,
};
use gearwear::config::{load_case, Case};
use gearwear::io::lock::OutputLock;
use gearwear::io::OutputError;
use gearwear::remedy::Arg;
use gearwear::study::budget::Budget;
use gearwear::study::sweep::{
    parse_vary, Continuation, ContinuationPlan, Shard, SweepPlan, SweepRun,
};
use gearwear::study::wear_loop::WearMode;
use std::path::{Path, PathBuf};

/// `--` then an ASCII letter: a flag.
fn flag_in(text: &str) -> Option<&str> {
    text.match_indices("--").find_map(|(i, _)| {
        text[i + 2..]
            .chars()
            .next()
            .filter(char::is_ascii_alphabetic)
            .map(|_| &text[i..(i + 20).min(text.len())])
    })
}

/// The string literals of Rust source `src` (ordinary, byte and raw strings), comments
/// and char literals skipped.
fn string_literals(src: &str) -> Vec<String> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                i += 2;
                while i + 1 < b.len() && !(b[i] == b'*' && b[i + 1] == b'/') {
                    i += 1;
                }
                i += 2;
            }
            b'\'' => {
                // A char literal ('x', '\n', '\u{..}') or a lifetime ('a): skip either.
                let rest = &src[i + 1..];
                let end = if rest.starts_with('\\') {
                    rest.find('\'').map(|j| j + 1)
                } else {
                    rest.char_indices()
                        .nth(1)
                        .filter(|(_, c)| *c == '\'')
                        .map(|(j, _)| j + 1)
                };
                i += 1 + end.unwrap_or(0);
            }
            b'r' if matches!(b.get(i + 1), Some(b'"' | b'#'))
                && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_')) =>
            {
                let hashes = b[i + 1..].iter().take_while(|c| **c == b'#').count();
                if b.get(i + 1 + hashes) != Some(&b'"') {
                    i += 1;
                    continue;
                }
                let start = i + 2 + hashes;
                let close = format!("\"{}", "#".repeat(hashes));
                let end = src[start..].find(&close).map_or(b.len(), |j| start + j);
                out.push(src[start..end].to_owned());
                i = end + close.len();
            }
            b'"' => {
                let start = i + 1;
                i += 1;
                while i < b.len() && b[i] != b'"' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
                out.push(src[start..i.min(b.len())].to_owned());
                i += 1;
            }
            _ => i += 1,
        }
    }
    out
}

/// Files that write the command line's own documentation rather than messages:
/// `config::docs` prints the case-file reference of `gearwear config --markdown`
/// (docs/CONFIG.md), which tells how the command line takes a case.
const CLI_DOCUMENTATION: [&str; 1] = ["src/config/docs.rs"];

/// The library's source files outside `src/cli/`, their unit tests cut off.
fn library_sources() -> Vec<(PathBuf, String)> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap().flatten() {
            let p = e.path();
            if p.is_dir() {
                if p.file_name().is_some_and(|n| n != "cli") {
                    walk(&p, out);
                }
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    let mut files = Vec::new();
    walk(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("src"),
        &mut files,
    );
    files.sort();
    files
        .into_iter()
        .filter(|p| {
            !p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with("tests_"))
                && !CLI_DOCUMENTATION.iter().any(|d| p.ends_with(d))
        })
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            let code = match text.find("#[cfg(test)]") {
                Some(i) => text[..i].to_owned(),
                None => text,
            };
            (p, code)
        })
        .collect()
}

#[test]
fn no_string_literal_of_the_library_names_a_flag() {
    // The scanner finds what it must (and skips comments and chars).
    let probe =
        "// \"--out\"\nlet c = '\"'; let s = \"choose --out\"; let r = r#\"--resume \"x\"\"#;";
    let lits = string_literals(probe);
    assert_eq!(lits, vec!["choose --out", "--resume \"x\""], "{lits:?}");
    let sources = library_sources();
    assert!(sources.len() > 100, "{} files", sources.len());
    let mut found = Vec::new();
    for (path, code) in &sources {
        for lit in string_literals(code) {
            if let Some(f) = flag_in(&lit) {
                found.push(format!("{}: {f:?} in {lit:?}", path.display()));
            }
        }
    }
    assert!(
        found.is_empty(),
        "library messages naming flags:\n{}",
        found.join("\n")
    );
}

/// A job's error in the library's words, and in the command line's.
fn words<J: Job>(job: J) -> (String, String) {
    match job.run(&()) {
        Err(e) => {
            let cli = e.render(flag::flag);
            (e.to_string(), cli)
        }
        Ok(_) => panic!("{} ran", job.name()),
    }
}

#[test]
fn built_messages_name_no_flag_and_the_command_line_names_its_own() {
    let mut plain: Vec<String> = Arg::ALL.iter().map(|a| a.plain().to_owned()).collect();
    let mut cli: Vec<(String, &str)> = Vec::new();
    let d = tempfile::tempdir().unwrap();
    let case = Case::default();

    // Overrides and sweep axes.
    let e = load_case("", &["gear.module_mm=2\n[x]".into(), "gear=1".into()]).unwrap_err();
    plain.extend(e.messages());
    cli.extend(e.problems.iter().map(|w| (w.render(flag::flag), "--set")));
    for bad in [
        "speed",
        "a=1",
        "operating.input_speed_hz=",
        "operating.input_speed_hz=1:2",
        "operating.input_speed_hz=1,,2",
        "operating.input_speed_hz=1,1.0",
        "surface.roughness_table_rms_um=1,2",
        "operating.speed_hz=1",
    ] {
        let p = parse_vary(bad).unwrap_err();
        plain.push(p.to_string());
        cli.push((p.render(flag::flag), "--vary"));
    }
    let p = Shard::parse("3/2").unwrap_err();
    plain.push(p.to_string());
    cli.push((p.render(flag::flag), "--shard"));
    plain.push(SweepPlan::new(vec![]).unwrap_err().to_string());
    let two = SweepPlan::new(vec![
        parse_vary("operating.input_speed_hz=30,40").unwrap(),
        parse_vary("operating.load_torque_nm=30,40").unwrap(),
    ])
    .unwrap();
    let p = ContinuationPlan::new(&two, Continuation::Up).unwrap_err();
    plain.push(p.to_string());
    cli.push((p.render(flag::flag), "--vary"));

    // The output folder, its lock, checkpoints.
    for kind in [
        std::io::ErrorKind::PermissionDenied,
        std::io::ErrorKind::StorageFull,
        std::io::ErrorKind::NotADirectory,
    ] {
        let e = OutputError::io("write", d.path(), &std::io::Error::from(kind));
        plain.push(e.to_string());
        cli.push((e.render(flag::flag), "--out"));
    }
    let root = gearwear::io::dir::Dir::open_root(d.path()).unwrap();
    let _held = OutputLock::acquire(&root, ".lock", "wear").unwrap();
    let e = OutputLock::acquire(&root, ".lock", "run").unwrap_err();
    plain.push(e.to_string());
    cli.push((e.problem().render(flag::flag), "--out"));
    // A folder holding another command's results, refused unless replacing is allowed.
    let other = d.path().join("other");
    let mut set = gearwear::io::OutputDir::open(&other, None, "stiffness").unwrap();
    set.stage("a.txt", b"a").unwrap();
    set.publish().unwrap();
    let e = gearwear::io::OutputDir::open(&other, None, "wear").unwrap_err();
    plain.push(e.to_string());
    cli.push((e.problem().render(flag::flag), "--replace"));
    let e = gearwear::store::checkpoint::parse_checkpoint(
        b"x y\n",
        "checkpoint_dynamic.jsonl",
        WearMode::Dynamic,
        "abc",
    )
    .unwrap_err();
    plain.push(e.to_string());
    cli.push((e.problem().render(flag::flag), "--resume"));

    // Jobs refusing their input: the budget, a resume with nothing to resume, a sweep
    // option that does not fit, a transmission error, prediction options.
    let over = Case {
        wear: gearwear::config::case::WearSection {
            block_cycles: 1.0,
            ..Case::default().wear
        },
        ..Case::default()
    };
    let jobs: Vec<((String, String), &str)> = vec![
        (
            words(WearJob {
                case: over,
                modes: vec![WearMode::Dynamic],
                out: None,
                replace: false,
                resume: false,
                budget: Some(Budget::DEFAULT),
                figures: Default::default(),
            }),
            "--budget-scale",
        ),
        (
            words(WearJob {
                case: case.clone(),
                modes: vec![WearMode::Dynamic],
                out: Some(d.path().join("nothing")),
                replace: false,
                resume: true,
                budget: None,
                figures: Default::default(),
            }),
            "--resume",
        ),
        (
            words(SweepJob {
                base: case.clone(),
                plan: SweepPlan::new(vec![parse_vary("operating.input_speed_hz=30,40").unwrap()])
                    .unwrap(),
                run: SweepRun::Wear,
                shard: Shard::ALL,
                continuation: Some(Continuation::Up),
                out: None,
                replace: false,
                budget: None,
                figures: Default::default(),
            }),
            "--run",
        ),
        (
            words(DynamicsJob {
                case: case.clone(),
                transmission_error: Some(TransmissionErrorSource::Samples(vec![(0.0, 1.0)])),
                out: None,
                replace: false,
                budget: None,
                figures: Default::default(),
            }),
            "--transmission-error",
        ),
        (
            words(PredictJob {
                case: case.clone(),
                posterior: None,
                options: PredictOptions {
                    grid_points: 1,
                    ..PredictOptions::new(-1.0, 0.0)
                },
                future: Default::default(),
                shard: Shard::ALL,
                out: None,
                replace: false,
                budget: None,
                figures: Default::default(),
            }),
            "--limit-um",
        ),
    ];
    for ((p, c), f) in jobs {
        plain.push(p);
        cli.push((c, f));
    }
    let named: Vec<&String> = plain.iter().filter(|m| flag_in(m).is_some()).collect();
    assert!(
        named.is_empty(),
        "library messages naming flags: {named:#?}"
    );
    for (m, f) in &cli {
        assert!(m.contains(f), "the command line's wording lacks `{f}`: {m}");
    }
    // The job errors are input errors (exit 2), not failures.
    let e = SweepJob {
        base: case,
        plan: two,
        run: SweepRun::Dynamics,
        shard: Shard::ALL,
        continuation: Some(Continuation::Up),
        out: None,
        replace: false,
        budget: None,
        figures: Default::default(),
    }
    .run(&())
    .err()
    .unwrap();
    assert!(matches!(e, JobError::Input(_)), "{e}");
}
