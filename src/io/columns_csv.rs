//! Named, typed columns (`io::parquet::Column`) as CSV: the same table as a Parquet file,
//! for readers without a Parquet library (numbers as the shortest text that reads back
//! to the same double; float32 columns as their exact double value).

use super::parquet::{Column, ColumnData};
use crate::format::format_number;

/// CSV bytes of `columns` (equal lengths), header first.
pub fn columns_csv(columns: &[Column]) -> Result<Vec<u8>, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(columns.iter().map(|c| c.name.as_str()))?;
    let rows = columns.first().map_or(0, |c| c.data.len());
    let mut row = Vec::with_capacity(columns.len());
    for r in 0..rows {
        row.clear();
        for c in columns {
            row.push(match &c.data {
                ColumnData::F64(v) => format_number(v[r]),
                ColumnData::F32(v) => format_number(f64::from(v[r])),
                ColumnData::I64(v) => v[r].to_string(),
                ColumnData::Text(v) => v[r].clone(),
            });
        }
        w.write_record(&row)?;
    }
    w.into_inner().map_err(|e| csv::Error::from(e.into_error()))
}
