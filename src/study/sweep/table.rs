//! The sweep table: one row per case (the labels of its varied values, `case_id`, its
//! results), its CSV form, and the merge of shard tables.
//!
//! A continuation sweep's rows also carry their branch: the CSV then has a `branch`
//! column (`up` or `down`) right after `case_id`. Ordinary sweeps have no such column, so
//! their tables are the same as before continuation existed.

use super::case_record::CaseRecord;
use super::case_run::{CaseResults, SweepRun};
use super::continuation::Branch;
use std::collections::BTreeMap;

/// Why a sweep table cannot be read or merged.
#[derive(Debug, thiserror::Error)]
pub enum SweepTableError {
    /// The text is not CSV.
    #[error(transparent)]
    Csv(#[from] csv::Error),
    /// The CSV is not a gearwear sweep table (the message names the row and column).
    #[error("{0}")]
    NotASweepTable(String),
    /// The tables are of different sweeps, or none were given.
    #[error("{0}")]
    MixedSweeps(String),
}

/// One case's row.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRow {
    /// The case's id.
    pub case_id: usize,
    /// Labels of the varied values (`study::sweep::plan::AxisValue::label`).
    pub values: Vec<String>,
    /// The case's results (after the varied values).
    pub results: CaseResults,
    /// The branch of a continuation point; `None` in an ordinary sweep.
    pub branch: Option<Branch>,
}

impl SweepRow {
    /// Same case id, values and numbers (NaN equal to NaN, bit for bit otherwise).
    fn same_as(&self, o: &SweepRow) -> bool {
        self.case_id == o.case_id
            && self.values == o.values
            && self.branch == o.branch
            && self.results.same_as(&o.results)
    }
}

/// Rows of one sweep (or shard), sorted by case id.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepTable {
    /// Varied keys: the columns before `case_id`.
    pub keys: Vec<String>,
    /// What each case ran, which sets the result columns after `case_id`.
    pub run: SweepRun,
    /// The number of meshes of a gear train (one column set each after the run's
    /// columns, `super::mesh_row`); 0 for a single pair.
    pub stages: usize,
    /// Whether the rows end with a helical pair's columns (`super::helical_row`).
    pub helical: bool,
    /// The number of planets of a planetary set (its meshes' and planets' columns after
    /// the run's, `super::planetary_row`); 0 for none.
    pub planets: usize,
    /// The rows, sorted by case id.
    pub rows: Vec<SweepRow>,
}

impl SweepTable {
    /// An empty table of a single pair's cases.
    pub fn new(keys: Vec<String>, run: SweepRun) -> Self {
        Self {
            keys,
            run,
            stages: 0,
            helical: false,
            planets: 0,
            rows: Vec::new(),
        }
    }

    /// The same table with a helical pair's columns when `helical`.
    pub fn with_helical(self, helical: bool) -> Self {
        Self { helical, ..self }
    }

    /// The same table with the columns of `stages` train meshes (0: a single pair).
    pub fn with_stages(self, stages: usize) -> Self {
        Self { stages, ..self }
    }

    /// The same table with the columns of a set of `planets` planets (0: none).
    pub fn with_planets(self, planets: usize) -> Self {
        Self { planets, ..self }
    }

    /// Table of case records (which must share keys, run, meshes, helical and planetary
    /// columns), sorted by case id; records of other columns than the first's are left
    /// out.
    pub fn from_records(
        keys: Vec<String>,
        run: SweepRun,
        stages: usize,
        records: &[CaseRecord],
    ) -> Self {
        let mut rows: Vec<SweepRow> = records
            .iter()
            .filter_map(|r| {
                let results = r.case_results().filter(|x| x.meshes.len() == stages)?;
                Some(SweepRow {
                    case_id: r.case_id,
                    values: r.values.clone(),
                    results,
                    branch: r.continuation.as_ref().map(|c| c.branch),
                })
            })
            .collect();
        rows.sort_by_key(|r| r.case_id);
        // The first row's helical and planetary columns; rows of other columns left out.
        let helical = rows.first().is_some_and(|r| r.results.helical.is_some());
        let planets_of = |r: &SweepRow| r.results.planetary.as_ref().map_or(0, |p| p.planets());
        let planets = rows.first().map_or(0, planets_of);
        rows.retain(|r| r.results.helical.is_some() == helical && planets_of(r) == planets);
        Self {
            keys,
            run,
            stages,
            helical,
            planets,
            rows,
        }
    }

    /// The result columns.
    pub fn columns(&self) -> Vec<String> {
        let mut c = self.run.columns_for(self.stages);
        if self.helical {
            c.extend(super::helical_row::helical_columns(
                self.run == SweepRun::Wear,
            ));
        }
        if self.planets > 0 {
            c.extend(super::planetary_row::planetary_columns(
                self.planets,
                self.run == SweepRun::Wear,
            ));
        }
        c
    }

    /// Whether the rows have result column `name`.
    pub fn has_column(&self, name: &str) -> bool {
        self.columns().iter().any(|c| c == name)
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
        header.extend(self.columns());
        w.write_record(&header)?;
        for r in &self.rows {
            let mut rec = r.values.clone();
            rec.push(r.case_id.to_string());
            if branches {
                rec.push(r.branch.map_or("", |b| b.name()).to_string());
            }
            rec.extend(r.results.values().iter().map(|v| {
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
    pub fn from_csv(text: &str) -> Result<Self, SweepTableError> {
        let mut r = csv::Reader::from_reader(text.as_bytes());
        let header: Vec<String> = r.headers()?.iter().map(str::to_owned).collect();
        let Some(at) = header.iter().position(|h| h == "case_id") else {
            return Err(SweepTableError::NotASweepTable(
                "no `case_id` column: not a gearwear sweep table".into(),
            ));
        };
        let branch_at =
            (header.get(at + 1).map(String::as_str) == Some("branch")).then_some(at + 1);
        let first_result = branch_at.map_or(at + 1, |b| b + 1);
        let columns = header[first_result..].to_vec();
        let Some((run, stages, planets)) = SweepRun::shape_of(&columns) else {
            return Err(SweepTableError::NotASweepTable(format!(
                "result columns [{}] are those of no gearwear sweep (a dynamics sweep has [{}], a wear sweep adds [{}]; a gear train's then have [{}] per stage K)",
                columns.join(", "),
                SweepRun::Dynamics.columns().join(", "),
                SweepRun::Wear.columns()[SweepRun::Dynamics.columns().len()..].join(", "),
                super::mesh_row::MESH_COLUMNS.map(|c| format!("stageK_{c}")).join(", ")
            )));
        };
        let mut t = SweepTable::new(header[..at].to_vec(), run)
            .with_stages(stages)
            .with_helical(SweepRun::layout_of(&columns).is_some_and(|(_, _, h)| h))
            .with_planets(planets);
        for (line, rec) in r.records().enumerate() {
            let rec = rec?;
            let row = line + 2;
            let cell = |i: usize| rec.get(i).unwrap_or("").trim();
            let case_id = cell(at).parse().map_err(|_| {
                SweepTableError::NotASweepTable(format!(
                    "row {row}: case_id `{}` is not a whole number",
                    cell(at)
                ))
            })?;
            let branch = match branch_at.map(cell) {
                None | Some("") => None,
                Some(b) => Some(Branch::parse(b).ok_or_else(|| {
                    SweepTableError::NotASweepTable(format!(
                        "row {row}: branch `{b}` is neither `up` nor `down`"
                    ))
                })?),
            };
            let mut results = Vec::with_capacity(columns.len());
            for (i, name) in header.iter().enumerate().skip(first_result) {
                let s = cell(i);
                results.push(if s.is_empty() {
                    f64::NAN
                } else {
                    s.parse().map_err(|_| {
                        SweepTableError::NotASweepTable(format!(
                            "row {row}, column {name}: `{s}` is not a number"
                        ))
                    })?
                });
            }
            t.rows.push(SweepRow {
                case_id,
                values: (0..at).map(|i| cell(i).to_owned()).collect(),
                results: CaseResults::from_values_of(run, stages, planets, &results).ok_or_else(
                    || {
                        SweepTableError::NotASweepTable(format!(
                            "row {row}: not one number per column"
                        ))
                    },
                )?,
                branch,
            });
        }
        t.rows.sort_by_key(|r| r.case_id);
        Ok(t)
    }

    /// Join tables (each named by its source for messages) into one sorted by case id.
    /// A case present in several tables must have identical rows there. Tables with other
    /// varied keys (or in another order) or other result columns are another sweep: error.
    pub fn merge(tables: &[(String, SweepTable)]) -> Result<SweepTable, SweepTableError> {
        let Some((first_src, first)) = tables.first() else {
            return Err(SweepTableError::MixedSweeps("no tables to merge".into()));
        };
        let mut rows: BTreeMap<usize, (&str, &SweepRow)> = BTreeMap::new();
        for (src, t) in tables {
            if t.keys != first.keys {
                return Err(SweepTableError::MixedSweeps(format!(
                    "mixed sweeps: {src} varies [{}], {first_src} varies [{}]",
                    t.keys.join(", "),
                    first.keys.join(", ")
                )));
            }
            if t.run != first.run
                || t.stages != first.stages
                || t.helical != first.helical
                || t.planets != first.planets
            {
                return Err(SweepTableError::MixedSweeps(format!(
                    "mixed sweeps: {src} and {first_src} have different result columns ({})",
                    column_difference(t, first)
                )));
            }
            for r in &t.rows {
                match rows.get(&r.case_id) {
                    Some((other, o)) if !o.same_as(r) => {
                        return Err(SweepTableError::MixedSweeps(format!(
                            "case_id {} differs between {other} and {src} (values [{}] vs [{}]): not the same sweep, or results of different program versions",
                            r.case_id,
                            o.values.join(", "),
                            r.values.join(", ")
                        )));
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
            run: first.run,
            stages: first.stages,
            helical: first.helical,
            planets: first.planets,
            rows: rows.into_values().map(|(_, r)| r.clone()).collect(),
        })
    }
}

/// What differs between the result columns of two tables, for a message.
fn column_difference(a: &SweepTable, b: &SweepTable) -> String {
    if a.run != b.run {
        format!("a sweep of {} and one of {}", a.run.name(), b.run.name())
    } else if a.stages != b.stages {
        format!("gear trains of {} and {} stages", a.stages, b.stages)
    } else if a.helical != b.helical {
        "a helical pair's columns in one only".to_owned()
    } else {
        format!("planetary sets of {} and {} planets", a.planets, b.planets)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(ids: &[usize], bump: f64) -> SweepTable {
        let mut t = SweepTable::new(vec!["operating.input_speed_hz".into()], SweepRun::Dynamics);
        t.rows = ids
            .iter()
            .map(|&i| {
                let mut v = [1.5; 9];
                v[0] = 0.1 * i as f64 + bump;
                if i == 1 {
                    v[4] = f64::NAN;
                }
                SweepRow {
                    case_id: i,
                    values: vec![format!("{}", 20 + i)],
                    results: CaseResults::from_values(SweepRun::Dynamics, 0, &v).unwrap(),
                    branch: None,
                }
            })
            .collect();
        t
    }

    #[test]
    fn csv_round_trip_is_exact() {
        let t = table(&[0, 1, 2], 1.0 / 3.0);
        let back =
            SweepTable::from_csv(std::str::from_utf8(&t.to_csv().unwrap()).unwrap()).unwrap();
        assert_eq!(back.keys, t.keys);
        assert_eq!(back.run, t.run);
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
        assert_eq!(back.run, cont.run);
        for (a, b) in back.rows.iter().zip(&cont.rows) {
            assert!(a.same_as(b), "{a:?} != {b:?}");
        }
        let bad = text.replacen(",down,", ",sideways,", 1);
        assert!(SweepTable::from_csv(&bad)
            .unwrap_err()
            .to_string()
            .contains("sideways"));
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
        .unwrap_err()
        .to_string();
        assert!(e.contains("case_id 1"), "{e}");
        let mut other = table(&[5], 0.0);
        other.keys = vec!["operating.load_torque_nm".into()];
        let e = SweepTable::merge(&[("a".into(), table(&[1], 0.0)), ("b".into(), other)])
            .unwrap_err()
            .to_string();
        assert!(e.contains("mixed sweeps"), "{e}");
    }
}
