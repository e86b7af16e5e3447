//! Parquet files of named columns (records and dataset index tables, docs/SIGNALS.md).
//!
//! Why Parquet: a documented open columnar format that pandas (`pd.read_parquet`, with
//! pyarrow or fastparquet), MATLAB (`parquetread`, R2019a on), R (`arrow`) and Spark read
//! without gearwear; typed columns with exact binary floats (no text round trip); a
//! pure-Rust writer (the `parquet` crate without its Arrow layer and codecs). HDF5 would
//! need the C library at build time.
//!
//! Files are written for the widest compatibility and byte-for-byte reproducibility:
//! format version 1.0 pages, no compression, plain encoding (no dictionary) for numbers,
//! one row group, every column REQUIRED (no nulls), a fixed `created_by`. Units and other
//! metadata go into the file's key-value metadata (e.g. `gearwear.units`, a JSON object of
//! column name to unit), which `pyarrow.parquet.read_schema(path).metadata` shows.

use parquet::basic::{ConvertedType, Repetition, Type as PhysicalType};
use parquet::data_type::{ByteArray, ByteArrayType, DoubleType, FloatType, Int64Type};
use parquet::errors::ParquetError;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::{WriterProperties, WriterVersion};
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::types::Type;
use std::sync::Arc;

/// The values of one column.
#[derive(Debug, Clone, PartialEq)]
pub enum ColumnData {
    /// Double precision.
    F64(Vec<f64>),
    /// Single precision: recorded samples (24-bit converters resolve ~6e-8 of full
    /// scale, float32 6e-8 of each value).
    F32(Vec<f32>),
    /// 64-bit integers.
    I64(Vec<i64>),
    /// UTF-8 text.
    Text(Vec<String>),
}

impl ColumnData {
    /// Number of values.
    pub fn len(&self) -> usize {
        match self {
            ColumnData::F64(v) => v.len(),
            ColumnData::F32(v) => v.len(),
            ColumnData::I64(v) => v.len(),
            ColumnData::Text(v) => v.len(),
        }
    }

    /// Whether the column holds no values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// A named column.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// Column name (with its unit, e.g. `time_s`).
    pub name: String,
    /// The values.
    pub data: ColumnData,
}

impl Column {
    /// A column named `name` holding `data`.
    pub fn new(name: impl Into<String>, data: ColumnData) -> Self {
        Self {
            name: name.into(),
            data,
        }
    }
}

/// Writer identification stored in every file (fixed, so the bytes depend on the data only).
const CREATED_BY: &str = "gearwear (parquet-rs writer)";

/// The bytes of a Parquet file holding `columns` (equal lengths) and the key-value
/// `metadata`.
pub fn parquet_bytes(
    columns: &[Column],
    metadata: &[(String, String)],
) -> Result<Vec<u8>, ParquetError> {
    let rows = columns.first().map_or(0, |c| c.data.len());
    if let Some(c) = columns.iter().find(|c| c.data.len() != rows) {
        return Err(ParquetError::General(format!(
            "column `{}` has {} rows, the first column {rows}",
            c.name,
            c.data.len()
        )));
    }
    let fields = columns
        .iter()
        .map(|c| {
            let (physical, converted) = match c.data {
                ColumnData::F64(_) => (PhysicalType::DOUBLE, ConvertedType::NONE),
                ColumnData::F32(_) => (PhysicalType::FLOAT, ConvertedType::NONE),
                ColumnData::I64(_) => (PhysicalType::INT64, ConvertedType::NONE),
                ColumnData::Text(_) => (PhysicalType::BYTE_ARRAY, ConvertedType::UTF8),
            };
            Type::primitive_type_builder(&c.name, physical)
                .with_repetition(Repetition::REQUIRED)
                .with_converted_type(converted)
                .build()
                .map(Arc::new)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let schema = Arc::new(
        Type::group_type_builder("schema")
            .with_fields(fields)
            .build()?,
    );
    let kv = metadata
        .iter()
        .map(|(k, v)| KeyValue::new(k.clone(), v.clone()))
        .collect();
    let props = WriterProperties::builder()
        .set_writer_version(WriterVersion::PARQUET_1_0)
        .set_dictionary_enabled(false)
        .set_created_by(CREATED_BY.into())
        .set_key_value_metadata(Some(kv))
        .set_max_row_group_row_count(Some(rows.max(1)))
        .build();
    let mut buf = Vec::new();
    let mut w = SerializedFileWriter::new(&mut buf, schema, Arc::new(props))?;
    let mut rg = w.next_row_group()?;
    for c in columns {
        let Some(mut col) = rg.next_column()? else {
            break;
        };
        match &c.data {
            ColumnData::F64(v) => {
                col.typed::<DoubleType>().write_batch(v, None, None)?;
            }
            ColumnData::F32(v) => {
                col.typed::<FloatType>().write_batch(v, None, None)?;
            }
            ColumnData::I64(v) => {
                col.typed::<Int64Type>().write_batch(v, None, None)?;
            }
            ColumnData::Text(v) => {
                let b: Vec<ByteArray> = v.iter().map(|s| ByteArray::from(s.as_str())).collect();
                col.typed::<ByteArrayType>().write_batch(&b, None, None)?;
            }
        }
        col.close()?;
    }
    rg.close()?;
    w.close()?;
    Ok(buf)
}

/// The FLOAT columns `names` of the Parquet `bytes` of a file [`parquet_bytes`] wrote,
/// each of `rows` values, in the order of `names`. A file read back is checked before its
/// values are used: it must hold one row group of `rows` rows and exactly the columns
/// `names`, each FLOAT, else an error says what differs. The bytes may be anyone's (a
/// dataset folder is a user's), so a panic of the reader on a malformed file is caught
/// and returned as an error, not let through.
pub fn read_f32_columns(
    bytes: Vec<u8>,
    names: &[String],
    rows: usize,
) -> Result<Vec<Vec<f32>>, ParquetError> {
    std::panic::catch_unwind(move || f32_columns(bytes, names, rows))
        .unwrap_or_else(|_| Err(ParquetError::General("the file could not be read".into())))
}

/// [`read_f32_columns`] without the panic guard.
fn f32_columns(
    bytes: Vec<u8>,
    names: &[String],
    rows: usize,
) -> Result<Vec<Vec<f32>>, ParquetError> {
    use parquet::column::reader::ColumnReader;
    use parquet::file::reader::{FileReader, SerializedFileReader};
    let general = |m: String| ParquetError::General(m);
    let r = SerializedFileReader::new(bytes::Bytes::from(bytes))?;
    let meta = r.metadata();
    if meta.num_row_groups() != 1 || meta.row_group(0).num_rows() != rows as i64 {
        return Err(general(format!(
            "{} row groups of {} rows where one of {rows} was written",
            meta.num_row_groups(),
            meta.file_metadata().num_rows()
        )));
    }
    let schema = meta.file_metadata().schema_descr();
    let found: Vec<(String, PhysicalType)> = (0..schema.num_columns())
        .map(|i| {
            (
                schema.column(i).name().to_owned(),
                schema.column(i).physical_type(),
            )
        })
        .collect();
    let expected: Vec<(String, PhysicalType)> = names
        .iter()
        .map(|n| (n.clone(), PhysicalType::FLOAT))
        .collect();
    if found != expected {
        return Err(general(format!(
            "columns {:?} where {names:?} (float32) were written",
            found.iter().map(|(n, _)| n).collect::<Vec<_>>()
        )));
    }
    let group = r.get_row_group(0)?;
    (0..names.len())
        .map(|i| {
            let ColumnReader::FloatColumnReader(mut c) = group.get_column_reader(i)? else {
                return Err(general(format!("column `{}` is not float32", names[i])));
            };
            let mut values = Vec::with_capacity(rows);
            while values.len() < rows {
                let (records, _, _) =
                    c.read_records(rows - values.len(), None, None, &mut values)?;
                if records == 0 {
                    break;
                }
            }
            if values.len() != rows {
                return Err(general(format!(
                    "column `{}` holds {} values, not {rows}",
                    names[i],
                    values.len()
                )));
            }
            Ok(values)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use parquet::file::reader::{FileReader, SerializedFileReader};
    use parquet::record::Field;

    #[test]
    fn columns_round_trip_through_the_reference_reader() {
        let cols = vec![
            Column::new("time_s", ColumnData::F64(vec![0.0, 0.5, 1.0])),
            Column::new("input_g", ColumnData::F32(vec![1.5, -2.25, 3.0])),
            Column::new("record_id", ColumnData::I64(vec![7, 8, 9])),
            Column::new(
                "fault",
                ColumnData::Text(vec!["none".into(), "crack".into(), "".into()]),
            ),
        ];
        let meta = vec![(
            "gearwear.units".to_string(),
            "{\"input_g\":\"g\"}".to_string(),
        )];
        let bytes = parquet_bytes(&cols, &meta).unwrap();
        // Same input, same bytes.
        assert_eq!(bytes, parquet_bytes(&cols, &meta).unwrap());
        let mut f = tempfile::tempfile().unwrap();
        std::io::Write::write_all(&mut f, &bytes).unwrap();
        let r = SerializedFileReader::new(f).unwrap();
        let kv = r.metadata().file_metadata().key_value_metadata().unwrap();
        assert_eq!(kv[0].key, "gearwear.units");
        let rows: Vec<_> = r.get_row_iter(None).unwrap().map(|r| r.unwrap()).collect();
        assert_eq!(rows.len(), 3);
        let row1: Vec<_> = rows[1].get_column_iter().map(|(_, f)| f.clone()).collect();
        assert_eq!(row1[0], Field::Double(0.5));
        assert_eq!(row1[1], Field::Float(-2.25));
        assert_eq!(row1[2], Field::Long(8));
        assert_eq!(row1[3], Field::Str("crack".into()));
    }

    #[test]
    fn float_columns_read_back_as_written_and_other_files_are_refused() {
        let cols = vec![
            Column::new("a_g", ColumnData::F32(vec![1.5, -2.25, f32::MIN_POSITIVE])),
            Column::new("tachometer_v", ColumnData::F32(vec![0.0, 5.0, 5.0])),
        ];
        let bytes = parquet_bytes(&cols, &[]).unwrap();
        let names = |n: &[&str]| n.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        let read = read_f32_columns(bytes.clone(), &names(&["a_g", "tachometer_v"]), 3).unwrap();
        assert_eq!(read[0], vec![1.5, -2.25, f32::MIN_POSITIVE]);
        assert_eq!(read[1], vec![0.0, 5.0, 5.0]);
        // Another column name, count or length, a double column, or bytes that are no
        // Parquet file: an error, never values.
        assert!(read_f32_columns(bytes.clone(), &names(&["b_g", "tachometer_v"]), 3).is_err());
        assert!(read_f32_columns(bytes.clone(), &names(&["a_g"]), 3).is_err());
        assert!(read_f32_columns(bytes.clone(), &names(&["a_g", "tachometer_v"]), 4).is_err());
        let doubles =
            parquet_bytes(&[Column::new("a_g", ColumnData::F64(vec![1.0]))], &[]).unwrap();
        assert!(read_f32_columns(doubles, &names(&["a_g"]), 1).is_err());
        assert!(read_f32_columns(b"PAR1 not a file PAR1".to_vec(), &names(&["a_g"]), 1).is_err());
        let mut cut = bytes.clone();
        cut.truncate(bytes.len() / 2);
        assert!(read_f32_columns(cut, &names(&["a_g", "tachometer_v"]), 3).is_err());
    }

    #[test]
    fn columns_of_unequal_length_are_refused() {
        let cols = vec![
            Column::new("a", ColumnData::F64(vec![0.0, 1.0])),
            Column::new("b", ColumnData::F64(vec![0.0])),
        ];
        assert!(parquet_bytes(&cols, &[]).is_err());
    }
}
