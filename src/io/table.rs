//! Column tables written as CSV (header with units, one row per sample).

/// Named numeric columns of equal length. Column names carry their unit, e.g.
/// `mesh_force_n`.
#[derive(Debug, Clone, Default)]
pub struct Table {
    /// Column names, each with its unit.
    pub names: Vec<String>,
    /// Columns of values, in the order of `names`.
    pub columns: Vec<Vec<f64>>,
}

impl Table {
    /// An empty table.
    pub fn new() -> Self {
        Self::default()
    }

    /// Add a column (builder style).
    pub fn col(mut self, name: &str, values: Vec<f64>) -> Self {
        self.names.push(name.to_owned());
        self.columns.push(values);
        self
    }

    /// Number of rows: the longest column's length.
    pub fn rows(&self) -> usize {
        self.columns.iter().map(Vec::len).max().unwrap_or(0)
    }

    /// CSV text. Non-finite values are written as empty cells, never as NaN.
    pub fn to_csv(&self) -> Result<Vec<u8>, csv::Error> {
        let mut w = csv::Writer::from_writer(Vec::new());
        w.write_record(&self.names)?;
        let mut row = Vec::with_capacity(self.names.len());
        for r in 0..self.rows() {
            row.clear();
            for c in &self.columns {
                row.push(match c.get(r) {
                    Some(v) if v.is_finite() => crate::format::format_number(*v),
                    _ => String::new(),
                });
            }
            w.write_record(&row)?;
        }
        w.into_inner().map_err(|e| csv::Error::from(e.into_error()))
    }

    /// The bytes of a Parquet file of these columns (doubles, exact; `io::parquet`), with
    /// the column names as written; for long tables, where CSV text would be large and
    /// slow to format. Columns must have equal lengths.
    pub fn to_parquet(&self) -> Result<Vec<u8>, parquet::errors::ParquetError> {
        let cols: Vec<super::parquet::Column> = self
            .names
            .iter()
            .zip(&self.columns)
            .map(|(n, c)| {
                super::parquet::Column::new(n.clone(), super::parquet::ColumnData::F64(c.clone()))
            })
            .collect();
        super::parquet::parquet_bytes(&cols, &[])
    }

    /// The columns of `other` added after these.
    pub fn append(mut self, other: Table) -> Self {
        self.names.extend(other.names);
        self.columns.extend(other.columns);
        self
    }

    /// Index of the column named `name`.
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }
}

/// The first name a CSV header repeats (compared after trimming), if any. A reader that
/// looks its columns up by name would otherwise take the first of the two silently.
pub fn repeated_column<'a>(names: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let mut seen = std::collections::HashSet::new();
    names.into_iter().map(str::trim).find(|n| !seen.insert(*n))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_round_trip_and_nan_cells() {
        let t = Table::new()
            .col("a_m", vec![1.0, 2.5])
            .col("b_n", vec![f64::NAN, -3.0]);
        let text = String::from_utf8(t.to_csv().unwrap()).unwrap();
        let mut r = csv::Reader::from_reader(text.as_bytes());
        let rows: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
        assert_eq!(rows[0].get(1), Some(""));
        assert_eq!(rows[1].get(0).unwrap().parse::<f64>().unwrap(), 2.5);
        assert!(!text.contains("NaN"));
    }
}
