//! Resumes and merges at their limits (issue 33). A sidecar far beyond what a record's
//! labels can hold (a 600-700 MB sidecar, under the old 1 GiB read cap, aborted resume
//! and merge at 2.9 GB) is not read: a resume recomputes its record, a merge counts it
//! missing and names it, and neither process grows with the file. A merge that fails
//! half-way (here: the file-size limit hit while copying the first signal) leaves its
//! folder marked incomplete, and a second merge finishes it.

mod common;

use common::{gearwear, stderr};
use std::path::Path;

/// One condition, two states, two noise realisations: four records.
const DESIGN: &str =
    "seed = 3\n[run_to_failure]\nstates = 2\nmax_cycles = 1e4\nwear_limit_um = 10\n\
[operating]\ninput_speed_hz = [30]\n[records]\nnoise_realisations = 2\n";

/// The sidecar `rel` padded with blanks inside its JSON to 64 MiB (twice the cap): still
/// valid JSON, so only its size stands against it.
/// Written in pieces: the test process stays small, so that the child forked from it
/// (whose peak resident memory counts the pages it starts with) measures its own reads.
fn inflate(path: &Path) {
    use std::io::Write;
    let text = std::fs::read_to_string(path).unwrap();
    let (head, tail) = text.split_at(text.len() - 1);
    let mut f = std::io::BufWriter::new(std::fs::File::create(path).unwrap());
    f.write_all(head.as_bytes()).unwrap();
    let block = [b' '; 1 << 16];
    for _ in 0..(64 << 20) / block.len() {
        f.write_all(&block).unwrap();
    }
    f.write_all(tail.as_bytes()).unwrap();
    f.flush().unwrap();
}

fn p(dir: &Path, rel: &str) -> String {
    dir.join(rel).to_str().unwrap().to_owned()
}

#[test]
#[cfg(target_os = "linux")]
fn an_oversized_sidecar_is_recomputed_on_resume_and_left_out_of_a_merge() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    std::fs::write(dir.join("design.toml"), DESIGN).unwrap();
    let run = |out: &str, shard: Option<&str>| {
        let mut a = vec!["dataset", "-q", "--design"];
        let design = p(dir, "design.toml");
        let out = p(dir, out);
        a.push(&design);
        if let Some(s) = shard {
            a.extend(["--shard", s]);
        }
        a.extend(["--out", &out]);
        common::rusage::run(&a)
    };
    run("ds", None);
    let genuine = std::fs::read(dir.join("ds/records/0000001.json")).unwrap();
    inflate(&dir.join("ds/records/0000001.json"));
    // The resume reads at most the cap of the padded file: its peak stays near a small
    // run's (measured 21 MB), far below the 64 MiB a read of the file would take.
    let used = run("ds", None);
    assert!(
        used.peak_bytes < 60e6,
        "peak {} MB: the oversized sidecar was read",
        used.peak_bytes / 1e6
    );
    assert_eq!(
        std::fs::read(dir.join("ds/records/0000001.json")).unwrap(),
        genuine,
        "the record is recomputed as it was"
    );

    // A merge: the shard's oversized sidecar is a record left out, named (exit 1).
    run("s1", Some("1/2"));
    run("s2", Some("2/2"));
    let ids: Vec<String> = std::fs::read_dir(dir.join("s2/records"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    let victim = ids.iter().min().unwrap().clone();
    inflate(&dir.join("s2/records").join(&victim));
    let r = gearwear(&[
        "dataset-merge",
        "-q",
        &p(dir, "s1"),
        &p(dir, "s2"),
        "--out",
        &p(dir, "merged"),
    ]);
    let e = stderr(&r);
    assert_eq!(r.status.code(), Some(1), "{e}");
    assert!(
        e.contains(&format!("records/{victim} of")) && e.contains("left out"),
        "{e}"
    );
    assert!(!e.contains("panicked"), "{e}");
    // Everything else merged.
    let (_, rows) = common::read_csv(&dir.join("merged/index.csv"));
    assert_eq!(rows.len(), 3);
}

#[test]
#[cfg(target_os = "linux")]
fn a_merge_that_fails_half_way_leaves_its_folder_marked_incomplete() {
    use std::os::unix::process::CommandExt;
    let d = tempfile::tempdir().unwrap();
    let dir = d.path();
    std::fs::write(dir.join("design.toml"), DESIGN).unwrap();
    for (shard, out) in [("1/2", "s1"), ("2/2", "s2")] {
        let r = gearwear(&[
            "dataset",
            "-q",
            "--design",
            &p(dir, "design.toml"),
            "--shard",
            shard,
            "--out",
            &p(dir, out),
        ]);
        assert!(r.status.success(), "{}", stderr(&r));
    }
    let merge_args = [
        "dataset-merge".to_owned(),
        "-q".to_owned(),
        p(dir, "s1"),
        p(dir, "s2"),
        "--out".to_owned(),
        p(dir, "merged"),
    ];
    // A file-size limit of 64 kB: the marker and the small files fit, a record's signal
    // (about 300 kB) does not, so the merge stops inside its first copy.
    let mut cmd = std::process::Command::new(env!("CARGO_BIN_EXE_gearwear"));
    cmd.args(&merge_args);
    // SAFETY: only async-signal-safe calls (signal, setrlimit) run between fork and exec.
    unsafe {
        cmd.pre_exec(|| {
            libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
            let lim = libc::rlimit {
                rlim_cur: 64 << 10,
                rlim_max: 64 << 10,
            };
            if libc::setrlimit(libc::RLIMIT_FSIZE, &lim) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let r = cmd.output().unwrap();
    let e = String::from_utf8_lossy(&r.stderr);
    assert!(!r.status.success(), "the limited merge cannot succeed: {e}");
    assert!(!e.contains("panicked"), "{e}");
    let merged = dir.join("merged");
    assert!(
        merged.join("INCOMPLETE").exists(),
        "a merge that failed half-way leaves its folder marked: {e}"
    );
    assert!(!merged.join("index.csv").exists(), "no index is published");
    // The same merge without the limit finishes it: unmarked, every record indexed.
    let args: Vec<&str> = merge_args.iter().map(String::as_str).collect();
    let r = gearwear(&args);
    assert!(r.status.success(), "{}", stderr(&r));
    assert!(!merged.join("INCOMPLETE").exists());
    let (_, rows) = common::read_csv(&merged.join("index.csv"));
    assert_eq!(rows.len(), 4);
}
