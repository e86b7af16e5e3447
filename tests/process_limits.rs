//! Streams and process limits (issue 22): standard output or error that cannot be written,
//! a thread count the system refuses, a file-size limit. Each ends with a documented exit
//! code and one message, never a panic (exit 101) or a silent kill.
#![cfg(target_os = "linux")]

mod common;

use common::stderr;
use std::os::unix::process::CommandExt;
use std::process::{Command, Stdio};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_gearwear"))
}

#[test]
fn a_full_or_closed_standard_stream_exits_3_once_said() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("out");
    let o = out.to_str().unwrap();
    // Standard output to /dev/full: the results are published, the failure said once on
    // standard error, exit 3.
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let r = bin()
        .args(["dynamics", "--out", o])
        .stdout(Stdio::from(full))
        .output()
        .unwrap();
    let e = stderr(&r);
    assert_eq!(r.status.code(), Some(3), "{e}");
    assert_eq!(
        e.matches("could not write to standard output").count(),
        1,
        "{e}"
    );
    assert!(!e.contains("panicked"), "{e}");
    assert!(out.join("summary.json").exists());
    // Standard error to /dev/full: said on standard output instead.
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let r = bin()
        .args(["dynamics", "--out", o])
        .stderr(Stdio::from(full))
        .output()
        .unwrap();
    assert_eq!(r.status.code(), Some(3));
    let so = String::from_utf8_lossy(&r.stdout);
    assert!(so.contains("could not write to standard error"), "{so}");
    // A closed pipe (the reader went away): exit 3, not 101.
    let mut child = bin()
        .args(["dynamics", "--out", o])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let r = child.wait_with_output().unwrap();
    let e = stderr(&r);
    assert_eq!(r.status.code(), Some(3), "{e}");
    assert!(e.contains("Broken pipe") && !e.contains("panicked"), "{e}");
}

#[test]
fn too_many_threads_asked_or_allowed_gives_fewer_threads() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("out");
    let r = bin()
        .args(["dynamics", "-q", "--out", out.to_str().unwrap()])
        .env("RAYON_NUM_THREADS", "100000")
        .output()
        .unwrap();
    let e = stderr(&r);
    assert!(r.status.success(), "{e}");
    assert!(
        e.contains("RAYON_NUM_THREADS=100000") && e.contains("using"),
        "{e}"
    );
    // A limit on processes (RLIMIT_NPROC) that leaves room for two threads. It binds only
    // an unprivileged user: as root, the child becomes `nobody` first.
    let shared = tempfile::tempdir().unwrap();
    std::fs::set_permissions(
        shared.path(),
        std::os::unix::fs::PermissionsExt::from_mode(0o777),
    )
    .unwrap();
    let out = shared.path().join("out");
    let mut cmd = bin();
    cmd.args(["dynamics", "-q", "--out", out.to_str().unwrap()])
        .env("RAYON_NUM_THREADS", "16");
    let root = unsafe { libc::geteuid() } == 0;
    unsafe {
        cmd.pre_exec(move || {
            if root && libc::setuid(65534) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            let lim = libc::rlimit {
                rlim_cur: 3,
                rlim_max: 3,
            };
            if libc::setrlimit(libc::RLIMIT_NPROC, &lim) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let r = cmd.output().unwrap();
    let e = stderr(&r);
    assert!(!e.contains("panicked"), "{e}");
    assert!(r.status.success(), "{e}");
    assert!(e.contains("refused 16 threads"), "{e}");
}

#[test]
fn a_file_size_limit_is_an_error_naming_the_file_not_a_silent_kill() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("out");
    let mut cmd = bin();
    cmd.args([
        "run",
        "-q",
        "--set",
        "wear.total_cycles=5e3",
        "--out",
        out.to_str().unwrap(),
    ]);
    // No SIGXFSZ disposition set here: gearwear must catch it itself.
    unsafe {
        cmd.pre_exec(|| {
            libc::signal(libc::SIGXFSZ, libc::SIG_DFL);
            let lim = libc::rlimit {
                rlim_cur: 32 * 1024,
                rlim_max: 32 * 1024,
            };
            if libc::setrlimit(libc::RLIMIT_FSIZE, &lim) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let r = cmd.output().unwrap();
    let e = stderr(&r);
    assert_eq!(r.status.code(), Some(2), "killed? {:?}: {e}", r.status);
    assert!(
        e.contains("File too large") && e.contains(out.to_str().unwrap()),
        "{e}"
    );
}
