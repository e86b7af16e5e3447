//! Helpers of the tests that interrupt a wear run and resume it (`--resume`).

use std::path::Path;
use std::process::Output;

/// `gearwear` with the arguments `a`.
pub fn run(a: &[String]) -> Output {
    let refs: Vec<&str> = a.iter().map(String::as_str).collect();
    super::gearwear(&refs)
}

/// The arguments `a` with `--resume`.
pub fn resumed(a: &[String]) -> Vec<String> {
    let mut r = a.to_vec();
    r.push("--resume".into());
    r
}

/// Keep the header and `keep` updates of a log, and half of the next line when `torn`
/// (what a kill between or in the middle of appends leaves).
pub fn cut_log(path: &Path, keep: usize, torn: bool) {
    let text = std::fs::read_to_string(path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines.len() > keep + 1, "{path:?} has {} lines", lines.len());
    let mut out = lines[..keep + 1].join("\n") + "\n";
    if torn {
        let next = lines[keep + 1];
        out.push_str(&next[..next.len() / 2]);
    }
    std::fs::write(path, out).unwrap();
}

/// Edit update `at` (0-based, after the header line) of the log `path` with `f`, its line's
/// checksum recomputed when `rehash` (what a forger does), else kept (a plain edit).
pub fn edit_update(path: &Path, at: usize, rehash: bool, f: &dyn Fn(&mut serde_json::Value)) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut out = String::new();
    for (i, line) in text.lines().enumerate() {
        if i != at + 1 {
            out.push_str(line);
            out.push('\n');
            continue;
        }
        let (sum, json) = line.split_once(' ').unwrap();
        let mut v: serde_json::Value = serde_json::from_str(json).unwrap();
        f(&mut v);
        let j = serde_json::to_string(&v).unwrap();
        let s = if rehash { sha(&j) } else { sum.to_owned() };
        out.push_str(&format!("{s} {j}\n"));
    }
    std::fs::write(path, out).unwrap();
}

/// SHA-256 (hex) of `text`, as a checkpoint line's checksum.
pub fn sha(text: &str) -> String {
    gearwear::io::output_dir::sha256_hex(text.as_bytes())
}

/// Resume `a` and require exit 2 with every one of `needles` in the message, no panic.
pub fn refused(a: &[String], what: &str, needles: &[&str]) {
    let o = run(&resumed(a));
    let e = super::stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{what}: {e}");
    for n in needles {
        assert!(e.contains(n), "{what}: says `{n}`: {e}");
    }
    assert!(!e.contains("panicked"), "{what}: {e}");
}

/// Run `a` (a wear run into `out`, which must succeed), cut its logs with `cut`, resume
/// it, and require the folder's published files and logs to be the bytes of the
/// uninterrupted run, file by file.
pub fn cut_then_resumed_is_unchanged(a: &[String], out: &Path, cut: &dyn Fn(&Path)) {
    let o = run(a);
    assert!(o.status.success(), "{}", super::stderr(&o));
    let full = super::published(out);
    cut(out);
    let o = run(&resumed(a));
    assert!(o.status.success(), "{}", super::stderr(&o));
    let again = super::published(out);
    assert_eq!(
        full.iter().map(|f| &f.0).collect::<Vec<_>>(),
        again.iter().map(|f| &f.0).collect::<Vec<_>>()
    );
    for ((p, x), (_, y)) in full.iter().zip(&again) {
        assert!(x == y, "{p}: the resumed run's bytes differ");
    }
}

/// Run `args(full)` uninterrupted; run `args(cut)`, kill it once its log `log` (a
/// `.partial.jsonl` in `cut`) holds `updates` updates, resume it, and require the two
/// folders' published files and logs to be the same bytes.
pub fn killed_then_resumed_is_uninterrupted(
    args: &dyn Fn(&Path) -> Vec<String>,
    (full, cut): (&Path, &Path),
    log: &str,
    updates: usize,
) {
    let o = run(&args(full));
    assert!(o.status.success(), "{}", super::stderr(&o));
    let log = cut.join(log);
    let ready = || std::fs::read_to_string(&log).map_or(0, |t| t.lines().count()) > updates;
    super::kill_when(&args(cut), &ready);
    let o = run(&resumed(&args(cut)));
    assert!(o.status.success(), "{}", super::stderr(&o));
    assert!(
        super::published(full) == super::published(cut),
        "resumed outputs differ"
    );
}

/// The logs `logs` of the run `a` replaced by another case's (the same files in `other`):
/// refused by their header, naming the first log; then, with the headers forged to this
/// case's hash, refused by recomputing their first update (the records chain and replay
/// as a run, but not as this case's). The logs are left forged.
pub fn foreign_logs_refused(a: &[String], logs: &[std::path::PathBuf], other: &Path) {
    let hash = |t: &str| {
        let head: serde_json::Value =
            serde_json::from_str(t.lines().next().unwrap().split_once(' ').unwrap().1).unwrap();
        head["case_sha256"].as_str().unwrap().to_owned()
    };
    let theirs_of = |p: &Path| std::fs::read_to_string(other.join(p.file_name().unwrap())).unwrap();
    let ours = hash(&std::fs::read_to_string(&logs[0]).unwrap());
    let theirs = hash(&theirs_of(&logs[0]));
    assert_ne!(ours, theirs);
    for p in logs {
        std::fs::write(p, theirs_of(p)).unwrap();
    }
    let first = logs[0].file_name().unwrap().to_string_lossy().into_owned();
    refused(a, "another case", &[&first, "another case"]);
    for p in logs {
        let t = std::fs::read_to_string(p).unwrap();
        let (head, rest) = t.split_once('\n').unwrap();
        let json = head.split_once(' ').unwrap().1.replace(&theirs, &ours);
        std::fs::write(p, format!("{} {json}\n{rest}", sha(&json))).unwrap();
    }
    refused(
        a,
        "another case, forged header",
        &["update 0 (line 2)", "not what this case's model computes"],
    );
}

/// Resuming the finished run `a` in `out` (nothing left to compute) leaves its published
/// files and logs as they were.
pub fn resuming_a_finished_run_changes_nothing(a: &[String], out: &Path) {
    let before = super::published(out);
    let o = run(&resumed(a));
    assert!(o.status.success(), "{}", super::stderr(&o));
    assert!(super::published(out) == before);
}

/// Multiply the number at `key` (a JSON pointer) of a log record `v` by `f`; when `key`
/// names an array, its largest element (a point where the profile has worn). `at` names
/// the update in the message of an edit that would change nothing.
pub fn scale_at(v: &mut serde_json::Value, key: &str, at: usize, f: f64) {
    let at_key = match v.pointer(key).unwrap().as_array() {
        Some(a) => {
            let k = (0..a.len())
                .max_by(|p, q| a[*p].as_f64().unwrap().total_cmp(&a[*q].as_f64().unwrap()))
                .unwrap();
            format!("{key}/{k}")
        }
        None => key.to_owned(),
    };
    let x = v.pointer_mut(&at_key).unwrap();
    let y = x.as_f64().unwrap();
    assert!(
        y > 0.0,
        "{key} of update {at} is {y}: the edit would change nothing"
    );
    *x = serde_json::json!(y * f);
}
