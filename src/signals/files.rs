//! A record as files: the columns of its signal file (Parquet) and of the PHM 2009-style
//! CSV, with their units.
//!
//! Columns, one row per sample: `<sensor>_<unit suffix>` for each accelerometer
//! (`input_m_per_s2`, `output_g`, ...; float32) and `tachometer_v` (float32); the CSV
//! adds `time_s` first. The Parquet file's key-value metadata holds `gearwear.units`
//! (column -> unit), `gearwear.sampling_rate_hz` and `gearwear.record` (the record's
//! labels as JSON, when given).

use super::chain::ChannelUnit;
use super::record::Record;
use crate::io::parquet::{parquet_bytes, read_f32_columns, Column, ColumnData};
use crate::io::Table;
use parquet::errors::ParquetError;
use serde_json::{json, Map, Value};

/// Column name of a sensor's channel.
pub(crate) fn channel_column(sensor: &str, unit: ChannelUnit) -> String {
    format!("{sensor}_{}", unit.suffix())
}

/// Name of the tachometer column.
pub(crate) const TACHOMETER_COLUMN: &str = "tachometer_v";

/// Column names and units of a record.
pub(crate) fn units(record: &Record, unit: ChannelUnit) -> Map<String, Value> {
    let mut m = Map::new();
    for (name, _) in &record.channels {
        m.insert(channel_column(name, unit), json!(unit.symbol()));
    }
    m.insert(TACHOMETER_COLUMN.into(), json!("V"));
    m
}

/// The Parquet bytes of a record; `labels` (a JSON object) go into its metadata.
pub(crate) fn record_parquet(
    record: &Record,
    unit: ChannelUnit,
    labels: Option<&Value>,
) -> Result<Vec<u8>, ParquetError> {
    let f32s = |v: &[f64]| ColumnData::F32(v.iter().map(|x| *x as f32).collect());
    let mut cols: Vec<Column> = record
        .channels
        .iter()
        .map(|(name, x)| Column::new(channel_column(name, unit), f32s(x)))
        .collect();
    cols.push(Column::new(TACHOMETER_COLUMN, f32s(&record.tachometer_v)));
    let mut meta = vec![
        (
            "gearwear.units".to_string(),
            Value::Object(units(record, unit)).to_string(),
        ),
        (
            "gearwear.sampling_rate_hz".to_string(),
            format!("{}", record.sampling_rate_hz),
        ),
    ];
    if let Some(l) = labels {
        meta.push(("gearwear.record".to_string(), l.to_string()));
    }
    parquet_bytes(&cols, &meta)
}

/// The record as a table for CSV (PHM 2009 style, with a time column). The values are
/// rounded to float32, as in the Parquet file, so both files hold the same numbers.
pub(crate) fn record_table(record: &Record, unit: ChannelUnit) -> Table {
    let f32s = |v: &[f64]| v.iter().map(|x| *x as f32 as f64).collect();
    let mut t = Table::new().col(
        "time_s",
        (0..record.len()).map(|n| record.time_s(n)).collect(),
    );
    for (name, x) in &record.channels {
        t = t.col(&channel_column(name, unit), f32s(x));
    }
    t.col(TACHOMETER_COLUMN, f32s(&record.tachometer_v))
}

/// The record held in the Parquet bytes `signal` of a record with the channels `sensors`
/// (in order) in `unit`, `samples` samples at `sampling_rate_hz`, as [`record_parquet`]
/// writes it: what its indicators are recomputed from (the file must have exactly those
/// columns and samples, `io::parquet::read_f32_columns`).
pub(crate) fn stored_record(
    signal: Vec<u8>,
    sensors: &[String],
    unit: ChannelUnit,
    samples: usize,
    sampling_rate_hz: f64,
) -> Result<Record, ParquetError> {
    let mut names: Vec<String> = sensors.iter().map(|s| channel_column(s, unit)).collect();
    names.push(TACHOMETER_COLUMN.to_owned());
    let mut columns = read_f32_columns(signal, &names, samples)?;
    let widen = |v: Vec<f32>| v.into_iter().map(f64::from).collect::<Vec<f64>>();
    let tachometer_v = widen(columns.pop().unwrap_or_default());
    Ok(Record {
        sampling_rate_hz,
        channels: sensors
            .iter()
            .cloned()
            .zip(columns.into_iter().map(widen))
            .collect(),
        tachometer_v,
    })
}
