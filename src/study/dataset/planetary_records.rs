//! The records of one physical state of a planetary set (`super::planetary`): the ring
//! sensor's record at the state (what `gearwear signals` gives for the set, its channel
//! `ring_sensor_n` in N), a tachometer on the carrier, the measurement noise of each
//! realisation, the labels per member and the signal indicators.
//!
//! The tachometer: `signals.tachometer_pulses_per_revolution` pulses per revolution of
//! the carrier relative to the ring (the housing), pulse 0 rising at t = 0 where the ring
//! signal's planet 1 stands at its angle psi_1 (`study::planetary_signals`), 5 V for half
//! the pulse interval (`signals::tachometer`), band-limited below half the sampling rate.
//! Noise: `signals.snr_db` (white Gaussian noise at that signal-to-noise ratio over the
//! record, drawn as `signals::record::add_noise` draws a channel's); a noise density in accelerometer units has no
//! meaning for a force channel and is refused with the design. Indicators: the record's
//! RMS, crest factor and kurtosis (`signals::indicators::SignalIndicators`); the
//! time-synchronous averages of a pair's shafts are not made for a set (a planet's mesh
//! is heard through its window as it passes: no shaft of the set has a TSA standard).

use super::design::Condition;
use super::plan::{record_seed, Plan, StateIndex};
use super::planetary::{member_labels, mesh_sides_m, ring_record_at};
use super::records::{signal_file, RecordLabels};
use super::trajectory::Trajectory;
use crate::io::parquet::{parquet_bytes, read_f32_columns, Column, ColumnData};
use crate::io::Table;
use crate::signals::analysis::ChannelIndicators;
use crate::signals::indicators::SignalIndicators;
use crate::signals::noise::{sigma_for_snr, standard_normal};
use crate::signals::record::Record;
use crate::signals::tachometer::pulse_series;
use crate::study::planetary_signals::RingSensor;
use crate::study::planetary_wear::PlanetaryWearModel;
use crate::wear::WearState;
use serde_json::{json, Value};

/// The ring sensor's channel: its name in the labels' indicators, and its column.
pub const RING_CHANNEL: &str = "ring_sensor";
/// The ring sensor's column (as `gearwear signals` names it for a set).
pub const RING_COLUMN: &str = "ring_sensor_n";
/// The tachometer's column.
pub const TACHOMETER_COLUMN: &str = "tachometer_v";

/// Everything the records of one physical state of a set need.
pub struct PlanetaryInputs<'a> {
    /// The set at the state's speed and load.
    pub model: &'a PlanetaryWearModel,
    /// The ring sensor and the record's length and rate (`signals`' keys).
    pub sensor: RingSensor,
    /// Tachometer pulses per carrier revolution.
    pub pulses_per_revolution: usize,
    /// The measurement noise's signal-to-noise ratio, dB (`signals.snr_db`; none: no noise).
    pub snr_db: Option<f64>,
    /// The condition recorded.
    pub condition: &'a Condition,
    /// The condition's wear trajectory.
    pub trajectory: &'a Trajectory,
    /// Input cycles of the state.
    pub cycles: f64,
    /// The record's input-member speed, Hz, and load torque, N m (the design's).
    pub input_speed_hz: f64,
    /// The record's load torque on the input member, N m.
    pub load_torque_nm: f64,
    /// The design's failure limit, µm.
    pub wear_limit_um: f64,
    /// The design's seed.
    pub design_seed: u64,
}

/// Samples of a record of `sensor` (as `study::planetary_signals` counts them).
pub fn record_samples(sensor: &RingSensor) -> usize {
    (sensor.record_s * sensor.sampling_rate_hz).round().max(1.0) as usize
}

/// Carrier speed relative to the ring, Hz.
fn carrier_hz(model: &PlanetaryWearModel) -> f64 {
    let s = model.dynamics.study.speeds_hz;
    (s[1] - s[2]).abs()
}

/// The set's mesh frequency z_r |f_c - f_r|, Hz.
pub fn set_mesh_hz(model: &PlanetaryWearModel) -> f64 {
    model.dynamics.study.set.teeth_ring() as f64 * carrier_hz(model)
}

/// Every mesh's wear state at the state's cycles.
fn state_wears(inp: &PlanetaryInputs) -> anyhow::Result<Vec<WearState>> {
    inp.trajectory.states_at(inp.cycles).ok_or_else(|| {
        anyhow::anyhow!(
            "state at {} input cycles lies beyond the trajectory's end ({} input cycles)",
            inp.cycles,
            inp.trajectory.end_cycles
        )
    })
}

/// The labels of every record of physical state `p` but their indicators (left empty):
/// what a resume and a merge compare every kept record's labels with.
pub fn planetary_expected_labels(
    inp: &PlanetaryInputs,
    plan: &Plan,
    p: usize,
    index: StateIndex,
) -> anyhow::Result<Vec<RecordLabels>> {
    let wears = state_wears(inp)?;
    Ok((0..plan.realisations)
        .map(|r| labels_of(inp, plan, (p, index), &wears, r))
        .collect())
}

/// The labels of record `realisation` of state `p` at the meshes' states `wears`.
fn labels_of(
    inp: &PlanetaryInputs,
    plan: &Plan,
    (p, index): (usize, StateIndex),
    wears: &[WearState],
    realisation: usize,
) -> RecordLabels {
    let (members, limiting) = member_labels(inp.model, wears, inp.cycles);
    let (pinion, gear) = mesh_sides_m(wears, inp.model.planets());
    let (remaining, censored) = inp.trajectory.remaining(inp.cycles);
    let id = plan.record_id(p, realisation);
    RecordLabels {
        record_id: id,
        file: signal_file(id),
        condition: inp.condition.name.clone(),
        fault: inp.condition.fault.clone(),
        severity: inp.condition.severity,
        faults: Vec::new(),
        planetary_faults: inp
            .condition
            .case
            .planetary
            .as_ref()
            .map_or_else(Vec::new, |s| s.fault.clone()),
        trajectory_state: index.state,
        cycles: inp.cycles,
        max_wear_pinion_um: pinion * 1e6,
        max_wear_gear_um: gear * 1e6,
        wear_pinion_tooth_um: Vec::new(),
        wear_gear_tooth_um: Vec::new(),
        stages: Vec::new(),
        limiting_stage: None,
        members,
        limiting_member: limiting,
        wear_limit_um: inp.wear_limit_um,
        remaining_cycles: remaining,
        failure_censored: censored,
        input_speed_hz: inp.input_speed_hz,
        load_torque_nm: inp.load_torque_nm,
        mesh_hz: set_mesh_hz(inp.model),
        realisation,
        noise_seed: record_seed(inp.design_seed, id),
        indicators: Vec::new(),
    }
}

/// Compute the records of physical state `p`, handing each (labels, record) to `emit`.
pub fn planetary_state_records(
    inp: &PlanetaryInputs,
    plan: &Plan,
    p: usize,
    index: StateIndex,
    emit: &mut dyn FnMut(RecordLabels, Record) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let wears = state_wears(inp)?;
    let ring = ring_record_at(inp.model, &wears, inp.sensor)
        .map_err(|e| anyhow::anyhow!("state {p} ({} input cycles): {e}", inp.cycles))?;
    let n = record_samples(&inp.sensor);
    let fs = inp.sensor.sampling_rate_hz;
    let tach = pulse_series(
        1.0 / carrier_hz(inp.model),
        inp.pulses_per_revolution.max(1),
        0.5 * fs,
    );
    let clean = Record {
        sampling_rate_hz: fs,
        channels: vec![(RING_CHANNEL.to_owned(), ring.values_n)],
        tachometer_v: tach.sample(0.0, fs, n),
    };
    for realisation in 0..plan.realisations {
        let mut labels = labels_of(inp, plan, (p, index), &wears, realisation);
        let mut rec = clean.clone();
        if let Some(snr) = inp.snr_db {
            // As `signals::record::add_noise` draws a channel's noise (stream 0: the one
            // channel), the record's own seed.
            for (c, (_, x)) in rec.channels.iter_mut().enumerate() {
                let sigma = sigma_for_snr(x, snr);
                let e = standard_normal(labels.noise_seed, c as u64, x.len());
                x.iter_mut().zip(&e).for_each(|(v, e)| *v += sigma * e);
            }
        }
        rec.round_to_stored();
        labels.indicators = indicators_of(&rec);
        emit(labels, rec)?;
    }
    Ok(())
}

/// The indicators of a set's record: its channel's signal indicators, no shaft TSA.
fn indicators_of(rec: &Record) -> Vec<ChannelIndicators> {
    rec.channels
        .iter()
        .map(|(name, x)| ChannelIndicators {
            channel: name.clone(),
            signal: SignalIndicators::of(x),
            pinion: None,
            gear: None,
        })
        .collect()
}

/// Column -> unit of a set's record.
fn units() -> Value {
    json!({RING_COLUMN: "N", TACHOMETER_COLUMN: "V"})
}

/// The Parquet bytes of a set's record (`ring_sensor_n` in N, `tachometer_v` in V,
/// float32), its labels in the key-value metadata as a pair's record has them.
pub fn planetary_record_parquet(rec: &Record, labels: &Value) -> anyhow::Result<Vec<u8>> {
    let f32s = |v: &[f64]| ColumnData::F32(v.iter().map(|x| *x as f32).collect());
    let ring = rec.channels.first().map_or(&[][..], |c| &c.1[..]);
    let cols = [
        Column::new(RING_COLUMN, f32s(ring)),
        Column::new(TACHOMETER_COLUMN, f32s(&rec.tachometer_v)),
    ];
    let meta = [
        ("gearwear.units".to_string(), units().to_string()),
        (
            "gearwear.sampling_rate_hz".to_string(),
            format!("{}", rec.sampling_rate_hz),
        ),
        ("gearwear.record".to_string(), labels.to_string()),
    ];
    Ok(parquet_bytes(&cols, &meta)?)
}

/// The same record as CSV (time_s first, values as stored in float32).
pub fn planetary_record_csv(rec: &Record) -> anyhow::Result<Vec<u8>> {
    let f32s = |v: &[f64]| v.iter().map(|x| *x as f32 as f64).collect();
    let ring = rec.channels.first().map_or(&[][..], |c| &c.1[..]);
    let t = Table::new()
        .col("time_s", (0..rec.len()).map(|n| rec.time_s(n)).collect())
        .col(RING_COLUMN, f32s(ring))
        .col(TACHOMETER_COLUMN, f32s(&rec.tachometer_v));
    Ok(t.to_csv()?)
}

/// The record stored in the Parquet bytes `signal` of `inp`'s state and its indicators,
/// recomputed from its samples as stored (its CSV twin is rendered from it); fails when the file does not hold the set's
/// columns and samples.
pub fn planetary_stored_indicators(
    inp: &PlanetaryInputs,
    signal: Vec<u8>,
) -> anyhow::Result<(Record, Vec<ChannelIndicators>)> {
    let names = [RING_COLUMN.to_owned(), TACHOMETER_COLUMN.to_owned()];
    let mut cols = read_f32_columns(signal, &names, record_samples(&inp.sensor))?;
    let widen = |v: Vec<f32>| v.into_iter().map(f64::from).collect::<Vec<f64>>();
    let tachometer_v = widen(cols.pop().unwrap_or_default());
    let rec = Record {
        sampling_rate_hz: inp.sensor.sampling_rate_hz,
        channels: vec![(
            RING_CHANNEL.to_owned(),
            widen(cols.pop().unwrap_or_default()),
        )],
        tachometer_v,
    };
    let indicators = indicators_of(&rec);
    Ok((rec, indicators))
}
