//! The run budget's term for a record's figures at a requested size (`--figure-size`)
//! against what drawing them really costs: the peak resident memory and the CPU time of
//! `gearwear signals` at 4096 x 2048 px, less those of the same record at the default
//! size (the figures' share: the record, its analysis and the default-size figures are
//! counted and measured apart, `tests/budget.rs`). A long record under strong noise is
//! the costliest case: its spectrum's stems and its noisy traces reach across the plot
//! areas (issue 33: a 40 s record at 8192 x 4096 took 22.6 s and 1.74 GB against 8.2 s
//! and 1.10 GB counted, its figures by their pixels alone).

use std::process::Command;

use gearwear::config::load_case;
use gearwear::study::budget::{estimate_signals, FigureLoad};

/// The children's CPU seconds (user + system) so far and their largest resident memory,
/// bytes (`getrusage(RUSAGE_CHILDREN)`: the times of every child waited for, summed; the
/// peak the largest of any, `ru_maxrss` in kB on Linux).
#[cfg(target_os = "linux")]
fn children() -> (f64, f64) {
    // SAFETY: getrusage writes the struct it is given and nothing else.
    let mut u: libc::rusage = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { libc::getrusage(libc::RUSAGE_CHILDREN, &mut u) }, 0);
    let secs = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    (
        secs(u.ru_utime) + secs(u.ru_stime),
        u.ru_maxrss as f64 * 1024.0,
    )
}

/// A 20 s record (5.1e5 samples at the default 25.6 kHz) under noise 20 dB above the
/// signal: its spectrum's 2e5 bins and its noisy time trace and averages paint most of
/// their plot areas.
const SETS: [&str; 2] = ["signals.record_length=20", "signals.snr_db=-20"];

/// `signals` on the built-in case with [`SETS`] and `extra` arguments; the CPU seconds it
/// took and the children's peak memory after it.
#[cfg(target_os = "linux")]
fn run(extra: &[&str]) -> (f64, f64) {
    let d = tempfile::tempdir().unwrap();
    let (cpu0, _) = children();
    let mut c = Command::new(env!("CARGO_BIN_EXE_gearwear"));
    c.args(["signals", "-q", "--no-budget", "--out"])
        .arg(d.path().join("out"));
    for s in SETS {
        c.args(["--set", s]);
    }
    let o = c.args(extra).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (cpu1, peak) = children();
    (cpu1 - cpu0, peak)
}

#[test]
#[cfg(target_os = "linux")]
fn a_long_noisy_records_figures_are_counted_within_a_few_times_their_cost() {
    // The default size first: the children's peak is then its own (the larger size's
    // run follows and raises it).
    let (cpu_default, peak_default) = run(&[]);
    let (cpu_large, peak_large) = run(&["--figure-size", "4096x2048"]);
    let case = load_case("", &SETS.map(String::from)).unwrap();
    // Two channels: the generic housing's sensors.
    let e = estimate_signals(&case, 2);
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let load = FigureLoad::at_size((4096, 2048), (900, 420), 8192, threads);
    let term = load.term(e.figures_drawn).expect("figures at 4096 x 2048");
    let (cpu, bytes) = (cpu_large - cpu_default, peak_large - peak_default);
    eprintln!(
        "signals at 4096x2048: counted {:.2} s, {:.3} GB; drawing took {cpu:.2} s, {:.3} GB",
        term.seconds,
        term.bytes / 1e9,
        bytes / 1e9
    );
    // Never under what the figures cost (the budget is a bound); over by at most 5 x:
    // the painted pixels are counted as if every column of every dense series were
    // painted to the top, at the tallest figure's height (1.2-1.8 x the record figures'
    // own), the stems at the noisiest rate measured (1.4 x; docs/RELIABILITY.md), and
    // the time doubled for a slower machine; measured 2.9 x on 2026-12-01 at load ~2
    // (8.59 s counted, 2.98 s taken; 1.4 x before the doubling). A quiet machine's
    // shorter CPU time could put it near 4: the time's limit is 6.
    assert!(
        term.seconds >= cpu && term.seconds <= 6.0 * cpu,
        "figures took {cpu:.2} s of CPU at 4096 x 2048 beyond the default size; counted {:.2} s",
        term.seconds
    );
    assert!(
        term.bytes >= bytes && term.bytes <= 5.0 * bytes,
        "figures took {bytes:.3e} B at 4096 x 2048 beyond the default size; counted {:.3e} B",
        term.bytes
    );
    // And the whole run: the record's estimate and the term, against the run's own.
    assert!(e.seconds() + term.seconds >= cpu_large);
    assert!(e.memory_bytes() + term.bytes >= peak_large);
}
