//! One child process's CPU time and peak resident memory, measured by the kernel
//! (`wait4`: that child's own `rusage`, so that tests running at once in one binary do
//! not see each other's children, as `getrusage(RUSAGE_CHILDREN)` would).

use std::process::{Command, Stdio};

/// What a child used: CPU seconds (user + system, every thread) and its peak resident
/// memory, bytes (`ru_maxrss`, kB on Linux).
#[derive(Debug, Clone, Copy)]
pub struct Used {
    pub cpu_s: f64,
    pub peak_bytes: f64,
}

/// Runs `gearwear args` (stdout discarded, stderr kept for the failure message), waits
/// for it with `wait4` and returns what it used; panics when it fails.
#[cfg(target_os = "linux")]
// The child is reaped by `wait4` below, which clippy does not see.
#[allow(clippy::zombie_processes)]
pub fn run(args: &[&str]) -> Used {
    let err = tempfile::NamedTempFile::new().unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_gearwear"))
        .args(args)
        .stdout(Stdio::null())
        .stderr(err.reopen().unwrap())
        .spawn()
        .unwrap();
    let pid = child.id() as libc::pid_t;
    let mut status = 0;
    // SAFETY: wait4 writes the status and the struct it is given and nothing else; the
    // child is ours and not waited for elsewhere (`child` is dropped without a wait).
    let mut u: libc::rusage = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { libc::wait4(pid, &mut status, 0, &mut u) }, pid);
    assert!(
        libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0,
        "gearwear {args:?}: {}",
        std::fs::read_to_string(err.path()).unwrap_or_default()
    );
    let secs = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    Used {
        cpu_s: secs(u.ru_utime) + secs(u.ru_stime),
        peak_bytes: u.ru_maxrss as f64 * 1024.0,
    }
}

/// Prints an estimate (`bytes`, `secs`) beside what a run `used`, with the ratios, so
/// that a budget test's output can be read against the measured table of
/// docs/RELIABILITY.md.
#[allow(dead_code)]
pub fn print_counted(what: &str, bytes: f64, secs: f64, used: &Used) {
    eprintln!(
        "{what}: counted {:.3} GB, {secs:.2} s; used {:.3} GB, {:.2} s of CPU ({:.2} / {:.2})",
        bytes / 1e9,
        used.peak_bytes / 1e9,
        used.cpu_s,
        bytes / used.peak_bytes,
        secs / used.cpu_s
    );
}
