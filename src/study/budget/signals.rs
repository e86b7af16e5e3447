//! The cost of `signals`: the steady state (the dynamics estimate) and the record made of
//! it, or the transient a ramp or a load fluctuation integrates.

use super::case_jobs::{estimate, Job};
use super::cost::{Estimate, Term};
use super::evaluation::{SECONDS_PER_STEP, SLOWER_MACHINE_FACTOR};
use crate::config::Case;
use crate::study::transient_signals::is_transient;

/// Bytes of memory per recorded second and sample rate: the record's channels, their
/// analysis, and for a transient the internal grid (8 samples a sample, four forces, their
/// spectra): measured about 1.5 kB per record sample for a transient, 0.2 kB steady.
const BYTES_PER_SAMPLE_STEADY: f64 = 400.0;
const BYTES_PER_SAMPLE_TRANSIENT: f64 = 3000.0;

/// Seconds per record sample of rendering, filtering, indicators and writing, on one
/// core: measured 2.7 us of user time a sample for a 20 s record at 100 kHz (2e6 samples,
/// 5.47 s), rounded up.
const SECONDS_PER_RECORD_SAMPLE: f64 = 3e-6;

/// What each accelerometer channel adds per record sample (its rendering through the
/// transfer path, filter, indicators, TSA and files): measured 0.84-0.90 us of CPU time
/// and 48-54 bytes per sample and channel (a 1 s record at 25.6 kHz through a modal path
/// of 1 and of 100 sensors, `scripts/budget_table.sh`'s `path_N.toml`: 0.18 s / 23 MB
/// against 2.32-2.47 s / 145-159 MB, two runs at load 5, 2026-11-29). Time: 0.9 us times
/// [`SLOWER_MACHINE_FACTOR`]; memory does not depend on the machine: 64 bytes. (It was
/// 4 us, from a measurement of 3.3 us under another load and an older build: 5.5 times
/// the CPU time of 100 sensors, issue 33.)
pub const SECONDS_PER_SAMPLE_CHANNEL: f64 = 0.9e-6 * SLOWER_MACHINE_FACTOR;
pub const BYTES_PER_SAMPLE_CHANNEL: f64 = 64.0;

/// The sensors a record has without a transfer-path file (the generic housing's two).
pub const DEFAULT_CHANNELS: usize = 2;

/// The dynamics estimate with the record's memory added as its own term, so one estimate
/// (and one message, with every term) covers the whole job: before, the record was checked
/// apart and an estimate read from the budget's message missed it (a 10 s record at 1 MHz:
/// 0.07 GB reported against 3.7 GiB needed).
/// `channels`: the accelerometers of the transfer path (the sensors it names).
pub fn estimate_signals(case: &Case, channels: usize) -> Estimate {
    let s = &case.signals;
    let seconds = match s.record_length_unit {
        crate::config::signals::LengthUnit::S => s.record_length,
        crate::config::signals::LengthUnit::Revolutions => {
            s.record_length / case.operating.input_speed_hz.max(1e-9)
        }
    };
    let per = if is_transient(case) {
        BYTES_PER_SAMPLE_TRANSIENT
    } else {
        BYTES_PER_SAMPLE_STEADY
    };
    // A transient record integrates every mesh period it spans at the grid's steps per
    // period (bounded above with the fastest speed of the record); a steady record
    // replays the steady state, whose cost is the dynamics estimate's.
    let samples = seconds * s.sampling_rate_hz;
    let transient_seconds = if is_transient(case) {
        let mesh_periods = fastest_mesh_frequency_hz(case) * seconds;
        mesh_periods * case.numerics.steps_per_mesh_period as f64 * SECONDS_PER_STEP
    } else {
        0.0
    };
    let mut e = estimate(case, Job::Dynamics);
    e.terms.push(Term {
        what: "the record (channels, analysis, a transient's internal grid and integration)",
        seconds: transient_seconds
            + samples * (SECONDS_PER_RECORD_SAMPLE + channels as f64 * SECONDS_PER_SAMPLE_CHANNEL),
        bytes: samples * (per + channels as f64 * BYTES_PER_SAMPLE_CHANNEL),
        keys: &[
            "signals.record_length",
            "signals.sampling_rate_hz",
            "the transfer path's sensors",
            "signals.ramp_end_speed_hz",
            "numerics.steps_per_mesh_period",
        ],
    });
    e
}

/// The mesh frequency at the fastest input speed the case's record sees (a ramp's end or
/// the operating speed), Hz: the `OperatingPoint`'s of the case at that speed; 0 for a
/// pair the geometry refuses (building the model then names the problem).
fn fastest_mesh_frequency_hz(case: &Case) -> f64 {
    let mut fastest = case.clone();
    fastest.set_load_point(crate::config::case::LoadPoint {
        input_speed_hz: case.signals.max_input_speed_hz(case),
        ..case.load_point()
    });
    crate::geometry::GearPair::from_case(&case.gear).map_or(0.0, |pair| {
        crate::dynamics::params::OperatingPoint::of(&fastest.operating, &pair).mesh_frequency_hz
    })
}
