//! The sweep table: one row per case (varied values as text, `case_id`, result numbers),
//! its CSV form, and the merge of shard tables.
//!
//! A continuation sweep's rows also carry their branch: the CSV then has a `branch`
//! column (`up` or `down`) right after `case_id`. Ordinary sweeps have no such column, so
//! their tables are the same as before continuation existed.

use super::case_run::CaseRecord;
use super::continuation::Branch;
use std::collections::BTreeMap;

/// One case's row.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRow {
    pub case_id: usize,
    /// Varied values, as given to `--set`.
    pub values: Vec<String>,
    /// Result numbers; NaN where a number was not finite (an empty CSV cell).
    pub results: Vec<f64>,
    /// The branch of a continuation point; `None` in an ordinary sweep.
    pub branch: Option<Branch>,
}

impl SweepRow {
    /// Same case id, values and numbers (NaN equal to NaN, bit for bit otherwise).
    fn same_as(&self, o: &SweepRow) -> bool {
        self.case_id == o.case_id
            && self.values == o.values
            && self.branch == o.branch
            && self.results.len() == o.results.len()
            && self
                .results
                .iter()
                .zip(&o.results)
                .all(|(a, b)| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()))
    }
}

/// Rows of one sweep (or shard), sorted by case id.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SweepTable {
    /// Varied keys: the columns before `case_id`.
    pub keys: Vec<String>,
    /// Result columns: the columns after `case_id`.
    pub columns: Vec<String>,
    pub rows: Vec<SweepRow>,
}

impl SweepTable {
    /// Table of case records (which must share keys and columns), sorted by case id.
    pub fn from_records(keys: Vec<String>, columns: Vec<String>, records: &[CaseRecord]) -> Self {
        let mut rows: Vec<SweepRow> = records
            .iter()
            .map(|r| SweepRow {
                case_id: r.case_id,
                values: r.values.clone(),
                results: r.results.iter().map(|x| x.unwrap_or(f64::NAN)).collect(),
                branch: r.continuation.as_ref().map(|c| c.branch),
            })
            .collect();
        rows.sort_by_key(|r| r.case_id);
        Self {
            keys,
            columns,
            rows,
        }
    }

    /// Index of a result column.
    pub fn column(&self, name: &str) -> Option<usize> {
        self.columns.iter().position(|c| c == name)
    }

    /// Whether the rows carry branches (a continuation sweep).
    pub fn has_branches(&self) -> bool {
        self.rows.iter().any(|r| r.branch.is_some())
    }

    /// CSV: header `keys..., case_id, [branch,] columns...`; numbers as
    /// `crate::format` writes them (shortest round trip, plain where short), non-finite
    /// numbers as empty cells. The `branch` column is written only for a continuation sweep.
    pub fn to_csv(&self) -> Result<Vec<u8>, csv::Error> {
        let mut w = csv::Writer::from_writer(Vec::new());
        let branches = self.has_branches();
        let mut header = self.keys.clone();
        header.push("case_id".into());
        if branches {
            header.push("branch".into());
        }
        header.extend(self.columns.iter().cloned());
        w.write_record(&header)?;
        for r in &self.rows {
            let mut rec = r.values.clone();
            rec.push(r.case_id.to_string());
            if branches {
                rec.push(r.branch.map_or("", |b| b.name()).to_string());
            }
            rec.extend(r.results.iter().map(|v| {
                if v.is_finite() {
                    crate::format::format_number(*v)
                } else {
                    String::new()
                }
            }));
            w.write_record(&rec)?;
        }
        w.into_inner().map_err(|e| csv::Error::from(e.into_error()))
    }

    /// Read a table written by [`SweepTable::to_csv`].
    pub fn from_csv(text: &str) -> Result<Self, String> {
        let mut r = csv::Reader::from_reader(text.as_bytes());
        let header: Vec<String> = r
            .headers()
            .map_err(|e| e.to_string())?
            .iter()
            .map(str::to_owned)
            .collect();
        let Some(at) = header.iter().position(|h| h == "case_id") else {
            return Err("no `case_id` column: not a gearwear sweep table".into());
        };
        let branch_at =
            (header.get(at + 1).map(String::as_str) == Some("branch")).then_some(at + 1);
        let first_result = branch_at.map_or(at + 1, |b| b + 1);
        let mut t = SweepTable {
            keys: header[..at].to_vec(),
            columns: header[first_result..].to_vec(),
            rows: Vec::new(),
        };
        for (line, rec) in r.records().enumerate() {
            let rec = rec.map_err(|e| e.to_string())?;
            let row = line + 2;
            let cell = |i: usize| rec.get(i).unwrap_or("").trim();
            let case_id = cell(at)
                .parse()
                .map_err(|_| format!("row {row}: case_id `{}` is not a whole number", cell(at)))?;
            let branch = match branch_at.map(cell) {
                None | Some("") => None,
                Some(b) => Some(Branch::parse(b).ok_or_else(|| {
                    format!("row {row}: branch `{b}` is neither `up` nor `down`")
                })?),
            };
            let mut results = Vec::with_capacity(t.columns.len());
            for (i, name) in header.iter().enumerate().skip(first_result) {
                let s = cell(i);
                results.push(if s.is_empty() {
                    f64::NAN
                } else {
                    s.parse()
                        .map_err(|_| format!("row {row}, column {name}: `{s}` is not a number"))?
                });
            }
            t.rows.push(SweepRow {
                case_id,
                values: (0..at).map(|i| cell(i).to_owned()).collect(),
                results,
                branch,
            });
        }
        t.rows.sort_by_key(|r| r.case_id);
        Ok(t)
    }

    /// Join tables (each named by its source for messages) into one sorted by case id.
    /// A case present in several tables must have identical rows there. Tables with other
    /// varied keys (or in another order) or other result columns are another sweep: error.
    pub fn merge(tables: &[(String, SweepTable)]) -> Result<SweepTable, String> {
        let Some((first_src, first)) = tables.first() else {
            return Err("sweep-merge: no tables to merge".into());
        };
        let mut rows: BTreeMap<usize, (&str, &SweepRow)> = BTreeMap::new();
        for (src, t) in tables {
            if t.keys != first.keys {
                return Err(format!(
                    "mixed sweeps: {src} varies [{}], {first_src} varies [{}]",
                    t.keys.join(", "),
                    first.keys.join(", ")
                ));
            }
            if t.columns != first.columns {
                return Err(format!(
                    "mixed sweeps: {src} and {first_src} have different result columns (a `--run dynamics` and a `--run wear` sweep?)"
                ));
            }
            for r in &t.rows {
                match rows.get(&r.case_id) {
                    Some((other, o)) if !o.same_as(r) => {
                        return Err(format!(
                            "case_id {} differs between {other} and {src} (values [{}] vs [{}]): not the same sweep, or results of different program versions",
                            r.case_id,
                            o.values.join(", "),
                            r.values.join(", ")
                        ));
                    }
                    Some(_) => {}
                    None => {
                        rows.insert(r.case_id, (src, r));
                    }
                }
            }
        }
        Ok(SweepTable {
            keys: first.keys.clone(),
            columns: first.columns.clone(),
            rows: rows.into_values().map(|(_, r)| r.clone()).collect(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(ids: &[usize], bump: f64) -> SweepTable {
        SweepTable {
            keys: vec!["operating.input_speed_hz".into()],
            columns: vec!["dte_max_um".into(), "dynamic_factor".into()],
            rows: ids
                .iter()
                .map(|&i| SweepRow {
                    case_id: i,
                    values: vec![format!("{}", 20 + i)],
                    results: vec![0.1 * i as f64 + bump, if i == 1 { f64::NAN } else { 1.5 }],
                    branch: None,
                })
                .collect(),
        }
    }

    #[test]
    fn csv_round_trip_is_exact() {
        let t = table(&[0, 1, 2], 1.0 / 3.0);
        let back =
            SweepTable::from_csv(std::str::from_utf8(&t.to_csv().unwrap()).unwrap()).unwrap();
        assert_eq!(back.keys, t.keys);
        assert_eq!(back.columns, t.columns);
        for (a, b) in back.rows.iter().zip(&t.rows) {
            assert!(a.same_as(b), "{a:?} != {b:?}");
        }
    }

    #[test]
    fn branch_column_only_for_continuation_and_round_trips() {
        let plain = table(&[0, 1], 0.0);
        let text = String::from_utf8(plain.to_csv().unwrap()).unwrap();
        assert!(!text.contains("branch"), "{text}");
        let mut cont = table(&[0, 1, 2], 0.25);
        for (r, b) in cont
            .rows
            .iter_mut()
            .zip([Branch::Up, Branch::Up, Branch::Down])
        {
            r.branch = Some(b);
        }
        let text = String::from_utf8(cont.to_csv().unwrap()).unwrap();
        assert!(text.starts_with("operating.input_speed_hz,case_id,branch,dte_max_um"));
        let back = SweepTable::from_csv(&text).unwrap();
        assert_eq!(back.columns, cont.columns);
        for (a, b) in back.rows.iter().zip(&cont.rows) {
            assert!(a.same_as(b), "{a:?} != {b:?}");
        }
        let bad = text.replacen(",down,", ",sideways,", 1);
        assert!(SweepTable::from_csv(&bad).unwrap_err().contains("sideways"));
    }

    #[test]
    fn merge_sorts_dedupes_and_rejects_conflicts() {
        let m = SweepTable::merge(&[
            ("b".into(), table(&[1, 3], 0.0)),
            ("a".into(), table(&[0, 2, 3], 0.0)),
        ])
        .unwrap();
        assert_eq!(
            m.rows.iter().map(|r| r.case_id).collect::<Vec<_>>(),
            vec![0, 1, 2, 3]
        );
        let e = SweepTable::merge(&[
            ("a".into(), table(&[1], 0.0)),
            ("b".into(), table(&[1], 1e-9)),
        ])
        .unwrap_err();
        assert!(e.contains("case_id 1"), "{e}");
        let mut other = table(&[5], 0.0);
        other.keys = vec!["operating.load_torque_nm".into()];
        let e =
            SweepTable::merge(&[("a".into(), table(&[1], 0.0)), ("b".into(), other)]).unwrap_err();
        assert!(e.contains("mixed sweeps"), "{e}");
    }
}
