//! The cost of `signals`: the steady state (the dynamics estimate) and the record made of
//! it, or the transient a ramp or a load fluctuation integrates.

use super::case_jobs::{estimate, Job};
use super::cost::{Estimate, Term};
use super::evaluation::{SECONDS_PER_STEP, SLOWER_MACHINE_FACTOR};
use crate::config::Case;
use crate::study::transient_signals::is_transient;

/// Bytes of memory per record sample of a steady record: the channels, their analysis
/// (spectrum, averages, indicators) and files; measured about 0.15-0.2 kB (a 19 s record
/// at 25.6 kHz: 92 MB), counted 0.4 kB. A transient's record is counted by its internal
/// grid instead ([`transient_grid_bytes`]); its analysis, after the grid is freed, at this
/// rate.
const BYTES_PER_SAMPLE_STEADY: f64 = 400.0;

/// Bytes per cell of a transient's internal grid (`signals::transient_record`, n cells at
/// D f_s) at the record's peak, the tachometer's stage: the force sampler's four cell
/// integrals (4 x 8 B), the four forces' half spectra (n / 2 + 1 complex each: 4 x 8 B a
/// cell), the filter's response on the grid (4 B), the forward and inverse real-FFT
/// plans of length n (their n / 2-point complex FFTs' twiddles and the real FFTs': about
/// 24 B), and the tachometer's cells, their spectrum, the inverse transform's output and
/// its scratch (4 x 8 B); the channels and tachometer samples kept by then are under 3 B
/// a cell with two sensors (8 B a sample each, counted apart per channel): 127 B. The
/// allocator keeps what the forces' transforms freed (a force's cells, their means, its
/// spectrum and scratch: 4 x 8 B) in its heap while they are under its mmap threshold
/// (glibc raises it to a freed block's size, up to 32 MB: arrays of up to 4e6 cells),
/// counted again: 160 B. Measured 2026-11-30 (peak RSS of `gearwear signals`, a run-up
/// from 30 to 60 Hz at 25.6 kHz, 1, 2, 3, 5, 10 and 19 s: 41, 84, 95, 145, 273 and 503
/// MB): 125 B a cell between 5 and 19 s, 146 B at 2 s (the allocator's), so the count is
/// 1.15-1.45 times the peak with the process's base. It was 3000 B a record sample (375
/// a cell), three times the measured peak (issue 33: a 19 s run-up counted 1.52 GB
/// against 0.50 GB measured, and refused at 8192 x 4096 px where it peaks at 0.71 GB).
const BYTES_PER_TRANSIENT_CELL: f64 = 160.0;

/// Seconds per record sample of rendering, filtering, indicators and writing, on one
/// core: measured 2.7 us of user time a sample for a 20 s record at 100 kHz (2e6 samples,
/// 5.47 s), rounded up.
const SECONDS_PER_RECORD_SAMPLE: f64 = 3e-6;

/// What each accelerometer channel adds per record sample (its rendering through the
/// transfer path, filter, indicators, TSA and files). Measured again 2026-11-30 09:03
/// (load 5; a 1 s record at 25.6 kHz through a modal path of 1, 20 and 100 sensors,
/// `scripts/budget_table.sh`'s `path_N.toml`; CPU time, the lowest of four runs each:
/// 0.15, 0.44 and 0.99 s): 0.60 us a sample and sensor from 1 to 20 sensors, 0.27 us from
/// 20 to 100 (the cost per sensor falls with the count); counted 0.45 us, times
/// [`SLOWER_MACHINE_FACTOR`]: 1.5 to 3 times the measured channels' cost at every count
/// from 1 to 100. Memory does not depend on the machine: measured 50 bytes a sample and
/// sensor (20 against 100 sensors: 44 against 146 MB), counted 64. (It was 0.9 us, from
/// runs at load 5-8 that took 1.8-2.5 times as long, so 100 sensors were estimated at
/// 4.2 times their CPU time; 4 us before that, issue 33.)
pub const SECONDS_PER_SAMPLE_CHANNEL: f64 = 0.45e-6 * SLOWER_MACHINE_FACTOR;
pub(crate) const BYTES_PER_SAMPLE_CHANNEL: f64 = 64.0;

/// The sensors a record has without a transfer-path file (the generic housing's two).
pub const DEFAULT_CHANNELS: usize = 2;

/// The dynamics estimate with the record's memory added as its own term, so one estimate
/// (and one message, with every term) covers the whole job: before, the record was checked
/// apart and an estimate read from the budget's message missed it (a 10 s record at 1 MHz:
/// 0.07 GB reported against 3.7 GiB needed).
/// `channels`: the accelerometers of the transfer path (the sensors it names).
pub fn estimate_signals(case: &Case, channels: usize) -> Estimate {
    let s = &case.signals;
    // Revolutions of the tachometer's shaft, as the record counts them (a gear shaft
    // turns slower than the input: counted at the input speed, a 95-tooth gear's record
    // was counted 5 times too short).
    let seconds = s.record_seconds(case);
    // A transient's record: its internal grid at the record's peak, or its analysis after
    // the grid is freed, the larger; a steady record: its analysis.
    let samples = seconds * s.sampling_rate_hz;
    let record_bytes = if is_transient(case) {
        transient_grid_bytes(case).max(samples * BYTES_PER_SAMPLE_STEADY)
    } else {
        samples * BYTES_PER_SAMPLE_STEADY
    };
    // A transient record integrates every mesh period it spans at the grid's steps per
    // period (bounded above with the fastest speed of the record); a steady record
    // replays the steady state, whose cost is the dynamics estimate's.
    let transient_seconds = match (is_transient(case), s.ramp_end_speed_hz) {
        // A spur pair's load fluctuation, at its measured rates; a helical pair's, a
        // train's and a planetary set's at the error control's bound of steps.
        (true, None)
            if case.gear.helix_angle_deg == 0.0
                && case.stage.is_empty()
                && case.planetary.is_none() =>
        {
            steady_speed_transient_seconds(case)
        }
        (true, _) => transient_steps(case) * SECONDS_PER_STEP,
        (false, _) => 0.0,
    };
    let mut e = estimate(case, Job::Dynamics);
    if is_transient(case) {
        // The transient's model is built again at the fastest speed, a helical pair's
        // teeth as contact lines with it (`study::transient_signals`).
        e.terms.extend(super::helical::tooth_lines_term(case));
    }
    e.terms.extend(super::planetary::ring_record_term(case));
    // A planetary set's ring-sensor record is sampled in time from one carrier
    // revolution (`study::planetary_signals`), with no harmonic synthesis.
    if !is_transient(case) && case.planetary.is_none() {
        let (seconds, bytes) = record_synthesis(case, channels);
        e.terms.push(Term {
            what: "the record's harmonics (every harmonic of the response's and the tachometer's periods below the internal Nyquist frequency: more as the input speed falls)",
            seconds,
            bytes,
            keys: &[
                "operating.input_speed_hz",
                "signals.sampling_rate_hz",
                "signals.tachometer_pulses_per_revolution",
                "signals.anti_alias_attenuation_db",
            ],
        });
    }
    e.terms.push(Term {
        what: "the record (channels, analysis, a transient's internal grid and integration)",
        seconds: transient_seconds
            + samples * (SECONDS_PER_RECORD_SAMPLE + channels as f64 * SECONDS_PER_SAMPLE_CHANNEL),
        bytes: record_bytes + samples * channels as f64 * BYTES_PER_SAMPLE_CHANNEL,
        keys: &[
            "signals.record_length",
            "signals.sampling_rate_hz",
            "the transfer path's sensors",
            "signals.ramp_end_speed_hz",
            "numerics.steps_per_mesh_period",
        ],
    });
    e.drawing(
        super::figures::signals_figures(case)
            .plus(super::figures::record_figures_density(case, channels)),
    )
}

/// Seconds of one term c_m cos(m w) of the anti-alias filter's response at a harmonic
/// (`AntiAliasFilter::response`, one per tap pair): measured 12.5 ns of CPU (the
/// tachometer of a 0.05 Hz record, 2.05e6 harmonics x 234 terms in 6.0 s, 2026-11-29),
/// times [`SLOWER_MACHINE_FACTOR`].
const SECONDS_PER_RESPONSE_TERM: f64 = 12.5e-9 * SLOWER_MACHINE_FACTOR;

/// Seconds per harmonic of the response's period besides the filter (the four bearing
/// forces' coefficients from their Hermite interpolants, the transfer path): measured
/// about 4 us (1.3 s for 1.08e5 harmonics with two sensors, less the filter's 0.6 s),
/// times [`SLOWER_MACHINE_FACTOR`].
const SECONDS_PER_RESPONSE_HARMONIC: f64 = 4e-6 * SLOWER_MACHINE_FACTOR;

/// Peak bytes per harmonic: of the response's period (four inputs' coefficients and
/// their cells' moments, each sensor's spectrum), measured about 256, counted 320; of the
/// tachometer's (its pulses' spectrum, filtered and rendered), measured 136 (0.05 and
/// 0.1 Hz records: 293 and 153 MB for 2.05e6 and 1.02e6 harmonics), counted 160.
const BYTES_PER_RESPONSE_HARMONIC: f64 = 320.0;
const BYTES_PER_TACHOMETER_HARMONIC: f64 = 160.0;

/// The cost (seconds on one core, peak bytes) of synthesising a steady record's periodic
/// signals (`signals::record::PeriodicRecord::new`): every harmonic k / T below the
/// internal Nyquist frequency D f_s / 2 of the response's period T (the excitation
/// period) and of the tachometer's pulse period, each through the filter's response (a
/// cosine sum over half its taps). Both counts grow as the speed falls (1 / f): a 0.05 Hz
/// record at 25.6 kHz has 2e6 tachometer harmonics. `channels`: the sensors.
pub fn record_synthesis(case: &Case, channels: usize) -> (f64, f64) {
    let s = &case.signals;
    let terms = crate::signals::antialias::AntiAliasFilter::design(
        s.sampling_rate_hz,
        s.anti_alias_attenuation_db,
    )
    .taps
    .len() as f64
        / 2.0;
    let Some(RecordHarmonics {
        response,
        tachometer,
    }) = record_harmonics(case)
    else {
        return (f64::INFINITY, f64::INFINITY);
    };
    let seconds = response
        * (channels as f64 * terms * SECONDS_PER_RESPONSE_TERM + SECONDS_PER_RESPONSE_HARMONIC)
        + tachometer * terms * SECONDS_PER_RESPONSE_TERM;
    let bytes = response * BYTES_PER_RESPONSE_HARMONIC + tachometer * BYTES_PER_TACHOMETER_HARMONIC;
    (seconds, bytes)
}

/// The harmonics a steady record synthesises, counted from the case alone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RecordHarmonics {
    /// Harmonics of the response's period below the internal Nyquist frequency.
    pub response: f64,
    /// Harmonics of the tachometer's pulse period below it.
    pub tachometer: f64,
}

/// [`RecordHarmonics`] of a steady record of `case`: D f_s / 2 times each period (None
/// when the periods cannot be counted, see `record_periods`).
pub fn record_harmonics(case: &Case) -> Option<RecordHarmonics> {
    let s = &case.signals;
    let top = 0.5 * crate::signals::antialias::OVERSAMPLING as f64 * s.sampling_rate_hz;
    let (period_s, shaft_hz) = record_periods(case)?;
    Some(RecordHarmonics {
        response: top * period_s,
        tachometer: top / (shaft_hz * s.tachometer_pulses_per_revolution.max(1) as f64),
    })
}

/// The response's period (s) a steady record repeats and the tachometer shaft's speed
/// (Hz), from the case alone: the single pair's excitation period
/// ([`super::teeth::excitation_periods_of`] mesh periods); a train's base period
/// (`dynamics::grid::chain_mesh_counts`) times its fault's base periods
/// ([`super::teeth::excitation_periods_of`]) and the sensor stage's shaft. None when a count
/// overflows or the teeth are not positive (building the model then names the problem).
fn record_periods(case: &Case) -> Option<(f64, f64)> {
    let f_in = case.operating.input_speed_hz;
    let gear_shaft = case.signals.tachometer_shaft == crate::config::signals::Shaft::Gear;
    if case.stage.is_empty() {
        let g = &case.gear;
        if g.teeth_pinion < 1 || g.teeth_gear < 1 {
            return None;
        }
        let f_mesh = f_in * g.teeth_pinion as f64;
        let period = super::teeth::excitation_periods_of(case) as f64 / f_mesh;
        let shaft = if gear_shaft {
            f_mesh / g.teeth_gear as f64
        } else {
            f_in
        };
        return Some((period, shaft));
    }
    let mut teeth = Vec::with_capacity(case.stage.len());
    for st in &case.stage {
        let g = st.gear_section(&case.gear);
        if g.teeth_pinion < 1 || g.teeth_gear < 1 {
            return None;
        }
        teeth.push([g.teeth_pinion as usize, g.teeth_gear as usize]);
    }
    let counts = crate::dynamics::grid::chain_mesh_counts(&teeth)?;
    // A faulty stage repeats over several base periods (docs/MODEL.md 9.10).
    let faults = super::teeth::excitation_periods_of(case) as f64;
    let period = faults * counts[0] as f64 / (f_in * teeth[0][0] as f64);
    let stage = case.signals.sensor_stage_index().min(teeth.len() - 1);
    let mut pinion = f_in;
    for t in &teeth[..stage] {
        pinion *= t[0] as f64 / t[1] as f64;
    }
    let t = teeth[stage];
    let shaft = if gear_shaft {
        pinion * t[0] as f64 / t[1] as f64
    } else {
        pinion
    };
    Some((period, shaft))
}

/// Peak bytes of a transient record's internal grid (`signals::transient_record`): its
/// n cells at D f_s, n = `fast_len`(lead-in + the record and its tail + lead-in's length
/// of padding), at `BYTES_PER_TRANSIENT_CELL`. In f64: a length past 2^50 cells (refused
/// by the budget long before) is counted at 2 n, the next power of two's bound.
pub fn transient_grid_bytes(case: &Case) -> f64 {
    use crate::signals::transient_record::{fast_len, LEAD_S, TAIL_S};
    let s = &case.signals;
    let rate = crate::signals::antialias::OVERSAMPLING as f64 * s.sampling_rate_hz;
    let lead = (LEAD_S * rate).round();
    let cells = lead + ((s.record_seconds(case) + TAIL_S) * rate).ceil() + (LEAD_S * rate).floor();
    let n = if cells.is_finite() && cells < 2f64.powi(50) {
        fast_len(cells as usize) as f64
    } else {
        2.0 * cells
    };
    n * BYTES_PER_TRANSIENT_CELL
}

/// CPU seconds of a steady-speed transient (a load fluctuation, no ramp) per mesh period
/// it integrates, on the built-in case at 30 Hz at its transient tolerance, with its
/// force sampling: measured 2026-12-01 on the 2-core machine at load 2 (user + system of
/// `gearwear signals`, torque fluctuation of 10 N m at 25.6 kHz, records of 1, 2, 5 and
/// 10 s: 1.53, 2.48, 6.7 and 9.9 s, 0.93 s a record second beyond a fixed 0.6 s; less the
/// record's samples as [`SECONDS_PER_RECORD_SAMPLE`] and the channels count them, 0.81 s
/// over 570 mesh periods), 1.42 ms; counted 1.5 ms times [`SLOWER_MACHINE_FACTOR`]. (It
/// was the run-up's bound, the error control's steps at the slowest mesh, 1197 a period
/// at 3 us: 2.1 s a record second, and no fixed part: issue 33, a 2 s record 1.41 and a
/// 5 s one 3.1 times its CPU time.)
const SECONDS_PER_STEADY_TRANSIENT_PERIOD: f64 = 1.5e-3 * SLOWER_MACHINE_FACTOR;

/// CPU seconds a steady-speed transient costs whatever its length: the steady state at
/// the starting speed from rest, the model built again at the fastest speed, the grid's
/// transforms planned, the signals' figures: measured 2026-12-01 0.2 s (a 0.25 s record,
/// 0.43 s, less its 0.25 s at 0.93 s a second) to 0.6 s (the intercept of the 1 to 10 s
/// records, load 2); counted 0.5 s times [`SLOWER_MACHINE_FACTOR`].
const STEADY_TRANSIENT_FIXED_SECONDS: f64 = 0.5 * SLOWER_MACHINE_FACTOR;

/// CPU seconds of a steady-speed transient of `case` (a load fluctuation at the case's
/// speed): [`STEADY_TRANSIENT_FIXED_SECONDS`] and every mesh period of the record and its
/// tail at [`SECONDS_PER_STEADY_TRANSIENT_PERIOD`], times the ratio of the case's steps
/// per period to the built-in case's (`transient_steps` of one second at each: a finer
/// grid or tolerance) and the slower mesh's factor (`super::chains::speed_scale`: the
/// error control's steps per period grow as the mesh slows).
pub(crate) fn steady_speed_transient_seconds(case: &Case) -> f64 {
    let periods = mesh_frequency_hz(case, case.operating.input_speed_hz)
        * (case.signals.record_seconds(case) + crate::signals::transient_record::TAIL_S);
    let per_period = |c: &Case| {
        let tol = c.numerics.integration_tolerance
            * crate::study::transient_signals::TRANSIENT_TOLERANCE_FACTOR;
        super::evaluation::adaptive_steps_per_period(tol)
            .max(c.numerics.steps_per_mesh_period as f64)
    };
    let steps = per_period(case) / per_period(&Case::default());
    STEADY_TRANSIENT_FIXED_SECONDS
        + periods
            * SECONDS_PER_STEADY_TRANSIENT_PERIOD
            * steps.max(1.0)
            * super::chains::speed_scale(case)
}

/// Accepted integrator steps of a transient record of `case` (a ramp or a load
/// fluctuation; `study::transient_signals`), bounded above: every mesh period the record
/// spans and its tail (`signals::transient_record::TAIL_S`), at the error control's bound
/// at the transient's tolerance (`adaptive_steps_per_period`(tol x
/// `TRANSIENT_TOLERANCE_FACTOR`)) or the grid's `numerics.steps_per_mesh_period`, the
/// larger. The error control, not the grid, sets the steps of a transient: counting the
/// grid alone (200 a period) put a run-up's integration at about half of its measured
/// time, for the spur pair as for a helical one (docs/MODEL.md 11.11;
/// tests/helical_transient.rs counts them). The mesh periods are the drive's: the speed
/// runs linearly from the start to the end of the ramp (`transient_signals::drive_of`)
/// and the mesh frequency is proportional to it, so the record spans (f_0 + f_1) / 2 x L
/// periods (f the mesh frequencies at the ramp's ends, L the record's seconds) and the
/// tail f_1 x `TAIL_S`. (They were counted at the fastest speed throughout: a run-up
/// from 30 to 60 Hz 4/3 of its periods, its 19 s record 80 s against 22.5 s of CPU,
/// issue 33.)
pub fn transient_steps(case: &Case) -> f64 {
    use crate::study::transient_signals::TRANSIENT_TOLERANCE_FACTOR;
    let s = &case.signals;
    let tol = case.numerics.integration_tolerance * TRANSIENT_TOLERANCE_FACTOR;
    let per_period = super::evaluation::adaptive_steps_per_period(tol)
        .max(case.numerics.steps_per_mesh_period as f64);
    let start = mesh_frequency_hz(case, case.operating.input_speed_hz);
    let end = s
        .ramp_end_speed_hz
        .map_or(start, |f| mesh_frequency_hz(case, f));
    let periods = 0.5 * (start + end) * s.record_seconds(case)
        + end * crate::signals::transient_record::TAIL_S;
    periods * per_period
}

/// The mesh frequency of `case` at the input speed `input_speed_hz`, Hz: the
/// `OperatingPoint`'s of the case at that speed; 0 for a pair the geometry refuses
/// (building the model then names the problem).
fn mesh_frequency_hz(case: &Case, input_speed_hz: f64) -> f64 {
    let mut at = case.clone();
    at.set_load_point(crate::config::case::LoadPoint {
        input_speed_hz,
        ..case.load_point()
    });
    crate::geometry::GearPair::from_case(&case.gear).map_or(0.0, |pair| {
        crate::dynamics::params::OperatingPoint::of(&at.operating, &pair).mesh_frequency_hz
    })
}
