//! Observations of a running gearbox: `obs.csv` with a `cycles` column, one column per
//! observed quantity (named as in the updates CSV) and optional `sigma_<name>` columns
//! with the standard deviation of each measurement's noise (same unit).
//!
//! An empty cell means "not measured at this row" (a wear measurement is rarer than a
//! vibration reading).
//!
//! **A gear train** (`[[stage]]`): an optional `stage` column names the mesh a row's
//! values are of (1..N, stage 1 the input stage); without it, or in an empty cell, stage
//! 1, so a pair's files read unchanged. `cycles` are then input cycles (revolutions of
//! stage 1's pinion), whatever the stage (`super::train_forward`). A quantity observed on
//! stage k > 1 is its own series ([`Quantity::OnStage`]). Every problem is reported with its row (1-based data row, and the
//! file line) and column.

use super::quantity::Quantity;
use crate::remedy::Problems;

/// The measurements of one quantity.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The quantity measured.
    pub quantity: Quantity,
    /// Pinion cycles of each measurement.
    pub cycles: Vec<f64>,
    /// Measured values, display units (the quantity's name says which).
    pub values: Vec<f64>,
    /// Noise standard deviation of each measurement; `None`: unknown, inferred.
    pub sigma: Option<Vec<f64>>,
}

/// All observations of one file.
#[derive(Debug, Clone, PartialEq)]
pub struct Observations {
    /// One series per quantity measured.
    pub series: Vec<Series>,
}

impl Observations {
    /// Largest observed cycle count.
    pub fn max_cycles(&self) -> f64 {
        self.series
            .iter()
            .flat_map(|s| s.cycles.iter().copied())
            .fold(0.0, f64::max)
    }

    /// Number of measured values.
    pub fn len(&self) -> usize {
        self.series.iter().map(|s| s.values.len()).sum()
    }

    /// Whether there are no measured values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Most data rows: a reading every 1000 cycles for 1e8 cycles. The likelihood sums over
/// every row at every step of the sampler, so rows multiply the calibration's cost.
pub const MAX_ROWS: usize = 100_000;
/// Largest cycle count of an observation: the range of `wear.total_cycles`.
pub const MAX_CYCLES: f64 = 1e11;
/// Largest magnitude of an observed value in its display unit (um, mm/s): a metre of
/// wear or of transmission error, a kilometre per second; no gearbox comes near.
pub const MAX_VALUE: f64 = 1e6;
/// Range of a given noise standard deviation, display units: below 1e-9 the noise is
/// under the model's own floating-point resolution and any model error makes the
/// likelihood underflow to zero; above 1e6 it is not a measurement.
pub const SIGMA_RANGE: (f64, f64) = (1e-9, 1e6);

/// Fewest values of a quantity whose noise is inferred: with one value the marginal
/// likelihood 1/|residual| has no scale to learn from (docs/PROGNOSTICS.md).
pub(crate) const MIN_VALUES_UNKNOWN_SIGMA: usize = 2;

/// A cell shown in a message: cut, control characters escaped.
fn shown(cell: &str) -> String {
    crate::format::clip(&cell.escape_debug().to_string(), 40)
}

/// A finite number, or why not.
fn number(cell: &str) -> Result<f64, String> {
    match cell.trim().parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(x) => Err(format!("`{}` is not finite ({x})", shown(cell))),
        Err(_) => Err(format!("`{}` is not a number", shown(cell))),
    }
}

/// A number in `[lo, hi]`, or why not (`why` says what the range is).
fn in_range(cell: &str, lo: f64, hi: f64, why: &str) -> Result<f64, String> {
    let x = number(cell)?;
    if (lo..=hi).contains(&x) {
        Ok(x)
    } else {
        Err(format!("{x:e} is outside [{lo:e}, {hi:e}] ({why})"))
    }
}

/// The columns of the header: `cycles`, each observed quantity's, and each quantity's
/// `sigma_<name>` column when it has one.
struct Columns {
    cycles: usize,
    /// The `stage` column, if there is one.
    stage: Option<usize>,
    values: Vec<(Quantity, usize)>,
    sigma_of: Vec<Option<usize>>,
}

/// Parse the observations CSV of a single pair (a `stage` column may only say 1).
/// `source` names the file in messages. Returns every problem found.
pub fn parse_observations(text: &str, source: &str) -> Result<Observations, Problems> {
    parse_observations_of(text, source, 1)
}

/// Parse the observations CSV of a case of `stages` meshes (1 for a single pair; a
/// `stage` column's values in 1..=stages). `source` names the file in messages. Returns
/// every problem found.
pub fn parse_observations_of(
    text: &str,
    source: &str,
    stages: usize,
) -> Result<Observations, Problems> {
    let mut rdr = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let header: Vec<String> = match rdr.headers() {
        Ok(h) => h.iter().map(str::to_owned).collect(),
        Err(e) => return Err(vec![format!("{source}: cannot read the header: {e}")].into()),
    };
    let cols = columns(&header, source)?;
    let mut series: Vec<Series> = cols
        .values
        .iter()
        .zip(&cols.sigma_of)
        .map(|((q, _), s)| Series {
            quantity: *q,
            cycles: Vec::new(),
            values: Vec::new(),
            sigma: s.map(|_| Vec::new()),
        })
        .collect();
    let mut problems = Vec::new();
    let rows = read_rows(
        &mut rdr,
        (&cols, stages),
        &mut series,
        &mut problems,
        source,
    );
    if rows == 0 {
        problems.push(format!("{source}: no data rows"));
    }
    if cols.stage.is_some() {
        // A column observed on later stages only has no stage-1 series.
        let staged: Vec<Quantity> = series
            .iter()
            .filter(|s| s.quantity.stage() > 1 && !s.values.is_empty())
            .map(|s| s.quantity.base())
            .collect();
        series.retain(|s| !(s.values.is_empty() && staged.contains(&s.quantity)));
        // Stage 1's series first, each stage's in the order of the columns.
        let order = |q: Quantity| {
            let col = cols.values.iter().position(|(c, _)| *c == q.base());
            (q.stage(), col)
        };
        series.sort_by_key(|s| order(s.quantity));
    }
    check_series(&series, rows, source, &mut problems);
    if problems.is_empty() {
        Ok(Observations { series })
    } else {
        Err(problems.into())
    }
}

/// The columns of `header`, or every problem with them (no `cycles` column, a column
/// twice, an unknown one, a sigma without its quantity, no quantity).
fn columns(header: &[String], source: &str) -> Result<Columns, Vec<String>> {
    let mut problems = Vec::new();
    let Some(cycles_col) = header.iter().position(|h| h == "cycles") else {
        return Err(vec![format!(
            "{source}: no `cycles` column (header: {})",
            header.join(",")
        )]);
    };
    // Quantity columns and their sigma columns.
    let mut value_cols: Vec<(Quantity, usize)> = Vec::new();
    let mut sigma_cols: Vec<(String, usize)> = Vec::new();
    let stage_col = header.iter().position(|h| h == "stage");
    for (j, h) in header.iter().enumerate() {
        if j == cycles_col || (Some(j) == stage_col && !header[..j].contains(h)) {
            continue;
        }
        if header[..j].contains(h) {
            problems.push(format!("{source}: column `{h}` appears twice"));
        } else if let Some(name) = h.strip_prefix("sigma_") {
            sigma_cols.push((name.to_owned(), j));
        } else if let Some(q) = Quantity::parse(h) {
            value_cols.push((q, j));
        } else {
            problems.push(format!(
                "{source}: unknown column `{h}`; valid quantities: {} (each optionally with a sigma_<name> column)",
                Quantity::valid_names()
            ));
        }
    }
    let mut sigma_of: Vec<Option<usize>> = vec![None; value_cols.len()];
    for (name, j) in &sigma_cols {
        match value_cols.iter().position(|(q, _)| q.name() == name) {
            Some(i) => sigma_of[i] = Some(*j),
            None => problems.push(format!(
                "{source}: column `sigma_{name}` has no matching quantity column `{name}`"
            )),
        }
    }
    if value_cols.is_empty() && problems.is_empty() {
        problems.push(format!(
            "{source}: no observed quantity; give one or more of: {}",
            Quantity::valid_names()
        ));
    }
    if !problems.is_empty() {
        return Err(problems);
    }
    Ok(Columns {
        cycles: cycles_col,
        stage: stage_col,
        values: value_cols,
        sigma_of,
    })
}

/// Read the data rows into `series`, each problem (with its row and line) into
/// `problems`; the number of rows read.
fn read_rows(
    rdr: &mut csv::Reader<&[u8]>,
    (cols, stages): (&Columns, usize),
    series: &mut Vec<Series>,
    problems: &mut Vec<String>,
    source: &str,
) -> usize {
    let mut previous: Option<f64> = None;
    let mut rows = 0;
    for (r, rec) in rdr.records().enumerate() {
        let at = format!("{source}: row {} (line {})", r + 1, r + 2);
        let rec = match rec {
            Ok(x) => x,
            Err(e) => {
                problems.push(format!("{at}: {e}"));
                continue;
            }
        };
        rows += 1;
        if rows > MAX_ROWS {
            problems.push(format!(
                "{source}: more than {MAX_ROWS} data rows (a reading every 1000 cycles for 1e8 cycles; each row is summed at every step of the sampler): thin the record"
            ));
            break;
        }
        // A quoted line break or another control character is never part of a number:
        // refused, not silently cut.
        if let Some(j) = rec.iter().position(|c| c.chars().any(char::is_control)) {
            problems.push(format!(
                "{at}: the cell in column {} holds a line break or another control character",
                j + 1
            ));
            continue;
        }
        let cell = |j: usize| rec.get(j).unwrap_or("").trim();
        let cycles = match row_cycles(cell(cols.cycles)) {
            Ok(c) => c,
            Err(e) => {
                problems.push(format!("{at}: {e}"));
                continue;
            }
        };
        if let Some(p) = previous.filter(|p| cycles < *p) {
            problems.push(format!(
                "{at}: `cycles` = {cycles} is below the previous row's {p}: rows must be in non-decreasing order of cycles"
            ));
        }
        previous = Some(cycles);
        let stage = match cols.stage.map(|j| row_stage(cell(j), stages)) {
            None => 1,
            Some(Ok(s)) => s,
            Some(Err(e)) => {
                problems.push(format!("{at}: {e}"));
                continue;
            }
        };
        for (i, (q, j)) in cols.values.iter().enumerate() {
            let raw = cell(*j);
            if raw.is_empty() {
                continue;
            }
            let Some(staged) = q.on_stage(stage) else {
                problems.push(format!(
                    "{at}: column `{}` is a condition indicator of the housing's record, not of one stage: observe it on stage 1 (`stage` = {stage} given)",
                    q.name()
                ));
                continue;
            };
            let k = match series.iter().position(|s| s.quantity == staged) {
                Some(k) => k,
                None => {
                    series.push(Series {
                        quantity: staged,
                        cycles: Vec::new(),
                        values: Vec::new(),
                        sigma: cols.sigma_of[i].map(|_| Vec::new()),
                    });
                    series.len() - 1
                }
            };
            match measurement(*q, raw, cols.sigma_of[i].map(cell)) {
                Ok((v, sigma)) => {
                    if let Some(s) = sigma {
                        series[k].sigma.get_or_insert_with(Vec::new).push(s);
                    }
                    series[k].cycles.push(cycles);
                    series[k].values.push(v);
                }
                Err(e) => problems.push(format!("{at}: {e}")),
            }
        }
    }
    rows
}

/// The stage of a row's `stage` cell (1..=`stages`; an empty cell is stage 1), or why
/// it is not one.
fn row_stage(cell: &str, stages: usize) -> Result<usize, String> {
    if cell.is_empty() {
        return Ok(1);
    }
    let range = if stages == 1 {
        "1: the case is a single pair, or a one-stage train".to_owned()
    } else {
        format!("1..{stages}: the case's stages")
    };
    match number(cell) {
        Ok(s) if s.fract() == 0.0 && s >= 1.0 && s <= stages as f64 => Ok(s as usize),
        Ok(s) => Err(format!(
            "column `stage` = {s} is outside {range} (a whole number naming the mesh)"
        )),
        Err(e) => Err(format!("column `stage`: {e}; the range is {range}")),
    }
}

/// The cycle count of a row's `cycles` cell, or why it is not one.
fn row_cycles(cell: &str) -> Result<f64, String> {
    match number(cell) {
        Ok(c) if c < 0.0 => Err(format!("`cycles` = {c} is negative")),
        Ok(c) if c > MAX_CYCLES => Err(format!(
            "`cycles` = {c:e} is beyond {MAX_CYCLES:e}, the range of wear.total_cycles"
        )),
        Ok(c) => Ok(c),
        Err(e) => Err(format!("`cycles`: {e}")),
    }
}

/// One measured value of `q` (the non-empty cell `raw`) and its noise's standard
/// deviation (the cell of its sigma column, if it has one), or why not.
fn measurement(q: Quantity, raw: &str, sigma: Option<&str>) -> Result<(f64, Option<f64>), String> {
    let v = in_range(
        raw,
        -MAX_VALUE,
        MAX_VALUE,
        "no gearbox's value in this unit",
    )
    .map_err(|e| format!("column `{}`: {e}", q.name()))?;
    let Some(cell) = sigma else {
        return Ok((v, None));
    };
    match number(cell) {
        Ok(s) if s <= 0.0 => Err(format!("`sigma_{}` = {s} must be > 0", q.name())),
        Ok(s) if !(SIGMA_RANGE.0..=SIGMA_RANGE.1).contains(&s) => Err(format!(
            "`sigma_{}` = {s:e} is outside [{:e}, {:e}] (below, any model error makes the likelihood underflow; above, it is not a measurement)",
            q.name(),
            SIGMA_RANGE.0,
            SIGMA_RANGE.1
        )),
        Ok(s) => Ok((v, Some(s))),
        Err(e) => Err(format!(
            "`sigma_{}`: {e} (a measured value needs its sigma)",
            q.name()
        )),
    }
}

/// Every series has a value, and enough of them to infer its noise when no sigma is
/// given (problems into `problems`).
fn check_series(series: &[Series], rows: usize, source: &str, problems: &mut Vec<String>) {
    for s in series {
        let n = s.values.len();
        if n == 0 && rows > 0 {
            problems.push(format!(
                "{source}: column `{}` has no value (every cell is empty)",
                s.quantity.name()
            ));
            continue;
        }
        if s.sigma.is_none() && n < MIN_VALUES_UNKNOWN_SIGMA && rows > 0 {
            problems.push(format!(
                "{source}: column `{}` has {n} value(s); inferring its noise needs at least {MIN_VALUES_UNKNOWN_SIGMA}, or give a `sigma_{}` column",
                s.quantity.name(),
                s.quantity.name()
            ));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> String {
        parse_observations(text, "obs.csv").unwrap_err().to_string()
    }

    #[test]
    fn reads_values_sigmas_and_missing_cells() {
        let o = parse_observations(
            "cycles,max_wear_pinion_um,sigma_max_wear_pinion_um,velocity_y_pinion_rms_mm_per_s\n\
             0,,,1.6\n1e4,1.5,0.1,1.5\n2e4,3.0,0.2,1.4\n",
            "obs.csv",
        )
        .unwrap();
        assert_eq!(o.series.len(), 2);
        assert_eq!(o.series[0].cycles, vec![1e4, 2e4]);
        assert_eq!(o.series[0].sigma, Some(vec![0.1, 0.2]));
        assert_eq!(o.series[1].values, vec![1.6, 1.5, 1.4]);
        assert_eq!(o.len(), 5);
        assert_eq!(o.max_cycles(), 2e4);
    }

    /// Issue 22's wrong diagnoses: values no forward run can meet are refused up front,
    /// naming them, and a file with no value at all is an error (issue 21: so is a quoted
    /// line break inside a cell).
    #[test]
    fn values_beyond_any_run_and_empty_or_broken_cells_are_refused_up_front() {
        for (text, needle) in [
            ("cycles,dte_max_um\n0,17\n1e300,17\n", "1e300"),
            ("cycles,dte_max_um\n0,17\n1e9,17\n1e12,17\n", "1e12"),
            ("cycles,dte_max_um\n0,17\n1e4,1e308\n", "dte_max_um"),
            (
                "cycles,dte_max_um,sigma_dte_max_um\n0,17,1e-300\n1e4,17,0.1\n",
                "sigma_dte_max_um",
            ),
            ("cycles,dte_max_um\n0,\n1e4,\n", "every cell is empty"),
            ("cycles,dte_max_um\n0,17\n1e4,\"1\n7\"\n", "line break"),
        ] {
            let e = err(text);
            assert!(e.contains(needle), "{text:?}: {e}");
        }
    }

    #[test]
    fn a_stage_column_splits_each_quantity_by_mesh() {
        // Stage 2's wear is its own series; stage 1's (and an empty cell's) the plain
        // quantity; a column observed on stage 2 only has no stage-1 series.
        let o = parse_observations_of(
            "cycles,stage,max_wear_pinion_um,dte_max_um\n0,1,0,17\n1e4,2,0.5,\n2e4,,1.5,17.2\n3e4,2,0.9,\n",
            "obs.csv",
            2,
        )
        .unwrap();
        let names: Vec<&str> = o.series.iter().map(|s| s.quantity.name()).collect();
        assert_eq!(
            names,
            [
                "max_wear_pinion_um",
                "dte_max_um",
                "max_wear_pinion_um_stage2"
            ]
        );
        assert_eq!(o.series[0].cycles, vec![0.0, 2e4]);
        assert_eq!(o.series[2].values, vec![0.5, 0.9]);
        let o = parse_observations_of(
            "cycles,stage,max_wear_pinion_um\n1e4,2,0.5\n3e4,2,0.9\n",
            "obs.csv",
            2,
        )
        .unwrap();
        assert_eq!(o.series.len(), 1);
        assert_eq!(o.series[0].quantity.stage(), 2);
        let e = parse_observations_of("cycles,stage,dte_max_um\n0,1,17\n1,4,17\n", "o", 3)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("row 2") && e.contains("`stage` = 4") && e.contains("1..3"),
            "{e}"
        );
    }

    #[test]
    fn errors_name_row_and_column() {
        let e = err("cycles,dte_max_um\n0,17\n-5,17\n");
        assert!(
            e.contains("row 2 (line 3)") && e.contains("negative"),
            "{e}"
        );
        let e = err("cycles,dte_max_um\n10,17\n5,17\n");
        assert!(e.contains("row 2") && e.contains("non-decreasing"), "{e}");
        let e = err("cycles,dte_max_um\n0,17\n5,nan\n");
        assert!(e.contains("row 2") && e.contains("dte_max_um") && e.contains("not finite"));
        let e = err("cycles,vibration\n0,1\n");
        assert!(e.contains("unknown column `vibration`"), "{e}");
        let e = err("cycles,sigma_dte_max_um\n0,1\n");
        assert!(e.contains("sigma_dte_max_um"), "{e}");
        let e = err("cycles,dte_max_um,sigma_dte_max_um\n0,17,0\n");
        assert!(e.contains("must be > 0"), "{e}");
        let e = err("cycles,dte_max_um\n0,17\n");
        assert!(e.contains("at least 2"), "{e}");
        assert!(err("x\n1\n").contains("no `cycles` column"));
        assert!(err("cycles,dte_max_um\n").contains("no data rows"));
    }
}
