//! A measured load-time history: time, torque and input speed, as a data logger on a
//! drivetrain records them.
//!
//! CSV with a header naming each column with its unit: `time_s` (s), `torque_nm` (N m, on
//! the shaft the spectrum names) and `input_speed_hz` (Hz) or `input_speed_rpm`
//! (rpm = 60 Hz). Other columns are ignored (loggers record more channels). Checked
//! before anything is counted, every problem naming the row (1-based data row and file
//! line), the column and the valid range:
//! - a value that is not a finite number (NaN, inf, empty): a gap in the record;
//! - a value outside its column's range ([`TIME_LIMIT_S`], [`TORQUE_LIMIT_NM`],
//!   [`SPEED_LIMIT_HZ`]): beyond any drivetrain, and where the sums the load spectrum is
//!   counted from (durations, torque times time) would overflow to inf;
//! - time not strictly increasing (a logger restart, a file joined out of order);
//! - an interval longer than the gap limit (by default [`DEFAULT_GAP_FACTOR`] times the
//!   median interval): missing data, whose time at level nobody knows.

use crate::config::operating::SpeedUnit;

/// A gap: an interval this many times the median interval (a logger at a fixed rate
/// never exceeds 1; variable-rate logging on change stays within a few).
pub const DEFAULT_GAP_FACTOR: f64 = 10.0;

/// Largest |time| of a sample, s (about 31 700 years): a record's intervals and
/// durations stay far from overflow.
pub const TIME_LIMIT_S: f64 = 1e12;
/// Largest |torque| of a sample, N m: the top of `operating.load_torque_nm`'s range (a
/// 10 MW drive at 10 rpm carries about 9.5e6 N m on its slow shaft).
pub const TORQUE_LIMIT_NM: f64 = 1e7;
/// Largest |input speed| of a sample, Hz: the top of `operating.input_speed_hz`'s range
/// (60 000 rpm).
pub const SPEED_LIMIT_HZ: f64 = 1000.0;

/// Most problems listed before the rest of the file is left unchecked.
const MAX_PROBLEMS: usize = 20;

/// Time, torque and speed at each sample.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct History {
    /// Time of each sample from the start of the record, s.
    pub time_s: Vec<f64>,
    /// Torque at each sample, N m, on the shaft the load spectrum names.
    pub torque_nm: Vec<f64>,
    /// Input (pinion) shaft speed at each sample, Hz (read as Hz or rpm).
    pub input_speed_hz: Vec<f64>,
}

/// Problems with a history (an input error; each line names row and column).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", .problems.join("; "))]
pub struct HistoryError {
    /// One line per problem, each naming its row and column.
    pub problems: Vec<String>,
}

impl HistoryError {
    fn one(p: impl Into<String>) -> Self {
        Self {
            problems: vec![p.into()],
        }
    }
}

/// Which columns hold time, torque and speed, and the speed's unit.
struct Columns {
    time: usize,
    torque: usize,
    speed: usize,
    speed_unit: SpeedUnit,
}

fn columns(header: &csv::ByteRecord) -> Result<Columns, HistoryError> {
    let find = |name: &str| header.iter().position(|h| h == name.as_bytes());
    let names: Vec<String> = header
        .iter()
        .map(|h| String::from_utf8_lossy(h).into_owned())
        .collect();
    // One column whose name holds another separator: the file was written with `;` or a
    // tab (a spreadsheet's CSV in a locale with a decimal comma), which the reader, set to
    // commas, cannot split.
    let separator = match names.as_slice() {
        [one] if one.contains(';') => {
            "; the file seems separated by `;`: write it with commas (and a decimal point)"
        }
        [one] if one.contains('\t') => "; the file seems separated by tabs: write it with commas",
        _ => "",
    };
    if let Some(name) = crate::io::table::repeated_column(names.iter().map(String::as_str)) {
        return Err(HistoryError::one(format!(
            "the history's header names the column `{}` twice: keep one (the reader would take the first silently)",
            crate::format::clip(name, crate::format::SHOWN_CHARS)
        )));
    }
    let missing = |what: &str| {
        HistoryError::one(format!(
            "the history has no {what} column (header: {}); expected time_s, torque_nm and input_speed_hz or input_speed_rpm{separator}",
            crate::format::clip(&names.join(","), crate::format::SHOWN_CHARS)
        ))
    };
    let time = find("time_s").ok_or_else(|| missing("`time_s`"))?;
    let torque = find("torque_nm").ok_or_else(|| missing("`torque_nm`"))?;
    let column = |u: SpeedUnit| find(u.input_speed_key());
    let speed_unit = SpeedUnit::given(
        column(SpeedUnit::Hz).is_some(),
        column(SpeedUnit::Rpm).is_some(),
        "",
    )
    .map_err(|both| HistoryError::one(format!("the history's columns {both}")))?
    .ok_or_else(|| missing(&SpeedUnit::either_key("")))?;
    Ok(Columns {
        time,
        torque,
        speed: column(speed_unit).unwrap_or_default(),
        speed_unit,
    })
}

/// A cell as a finite number.
fn cell(raw: Option<&[u8]>) -> Option<f64> {
    let s = std::str::from_utf8(raw?).ok()?.trim();
    s.parse::<f64>().ok().filter(|x| x.is_finite())
}

/// Parse a history CSV (text in memory) and check it; `gap_factor`: the longest interval
/// accepted, as a multiple of the median interval.
pub fn parse_history(bytes: &[u8], gap_factor: f64) -> Result<History, HistoryError> {
    let mut rdr = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(bytes);
    let header = rdr
        .byte_headers()
        .map_err(|e| HistoryError::one(format!("the history has no CSV header: {e}")))?
        .clone();
    let c = columns(&header)?;
    let mut h = History::default();
    let mut problems = Vec::new();
    let mut rec = csv::ByteRecord::new();
    let mut row = 0usize;
    loop {
        match rdr.read_byte_record(&mut rec) {
            Ok(false) => break,
            Ok(true) => {}
            Err(e) => {
                problems.push(format!("row {} (line {}): {e}", row + 1, row + 2));
                break;
            }
        }
        row += 1;
        let mut get = |i: usize, name: &str| match cell(rec.get(i)) {
            Some(x) => Some(x),
            None => {
                if problems.len() < MAX_PROBLEMS {
                    let raw = rec.get(i).map(String::from_utf8_lossy).unwrap_or_default();
                    problems.push(format!(
                        "row {row} (line {}): `{name}` = `{}` is not a finite number (a gap in the record: remove the row or fill it)",
                        row + 1,
                        crate::format::clip(&raw, crate::format::SHOWN_CHARS)
                    ));
                }
                None
            }
        };
        let (t, q, f) = (
            get(c.time, "time_s"),
            get(c.torque, "torque_nm"),
            get(c.speed, c.speed_unit.input_speed_key()),
        );
        let speed_limit = c.speed_unit.of_hz(SPEED_LIMIT_HZ);
        let bounds = [
            (t, "time_s", TIME_LIMIT_S),
            (q, "torque_nm", TORQUE_LIMIT_NM),
            (f, c.speed_unit.input_speed_key(), speed_limit),
        ];
        let mut in_range = true;
        for (x, name, limit) in bounds {
            if let Some(x) = x.filter(|x| x.abs() > limit) {
                in_range = false;
                if problems.len() < MAX_PROBLEMS {
                    problems.push(format!(
                        "row {row} (line {}): `{name}` = {} is out of range: expected a number in [-{limit:e}, {limit:e}]",
                        row + 1,
                        crate::format::format_number(x)
                    ));
                }
            }
        }
        if !in_range {
            continue;
        }
        if let (Some(t), Some(q), Some(f)) = (t, q, f) {
            if let Some(prev) = h.time_s.last() {
                if t <= *prev && problems.len() < MAX_PROBLEMS {
                    problems.push(format!(
                        "row {row} (line {}): `time_s` = {t} is not after the previous row's {prev}: time must increase strictly",
                        row + 1
                    ));
                }
            }
            h.time_s.push(t);
            h.torque_nm.push(q);
            h.input_speed_hz.push(c.speed_unit.to_hz(f));
        }
    }
    if problems.is_empty() && h.time_s.len() < 2 {
        problems.push(format!(
            "the history has {} row(s): at least two samples are needed to span any time",
            h.time_s.len()
        ));
    }
    if problems.is_empty() {
        problems.extend(gap_problems(&h.time_s, gap_factor));
    }
    if problems.len() >= MAX_PROBLEMS {
        problems.push("(further rows not checked)".into());
    }
    if problems.is_empty() {
        Ok(h)
    } else {
        Err(HistoryError { problems })
    }
}

/// Median of the sample intervals, s.
pub(crate) fn median_interval_s(time_s: &[f64]) -> f64 {
    let mut d: Vec<f64> = time_s.windows(2).map(|w| w[1] - w[0]).collect();
    if d.is_empty() {
        return 0.0;
    }
    let mid = d.len() / 2;
    let (_, m, _) = d.select_nth_unstable_by(mid, f64::total_cmp);
    *m
}

/// Intervals longer than `gap_factor` times the median, named by row.
fn gap_problems(time_s: &[f64], gap_factor: f64) -> Vec<String> {
    let limit = gap_factor * median_interval_s(time_s);
    time_s
        .windows(2)
        .enumerate()
        .filter(|(_, w)| w[1] - w[0] > limit)
        .take(MAX_PROBLEMS)
        .map(|(i, w)| {
            format!(
                "rows {} and {} (lines {} and {}): a gap of {} s between time_s = {} and {}, longer than {gap_factor} times the median interval ({} s): data are missing there; split the record at the gap, or raise the gap limit knowingly",
                i + 1,
                i + 2,
                i + 2,
                i + 3,
                w[1] - w[0],
                w[0],
                w[1],
                limit / gap_factor
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> String {
        parse_history(text.as_bytes(), DEFAULT_GAP_FACTOR)
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn reads_hz_or_rpm_and_ignores_other_channels() {
        let h = parse_history(
            b"time_s,torque_nm,input_speed_rpm,oil_temp_c\n0,10,1800,40\n0.5,20,900,41\n",
            DEFAULT_GAP_FACTOR,
        )
        .unwrap();
        assert_eq!(h.input_speed_hz, vec![30.0, 15.0]);
        assert_eq!(h.torque_nm, vec![10.0, 20.0]);
    }

    #[test]
    fn bad_histories_name_row_and_column() {
        let e = err("time_s,torque_nm,input_speed_hz\n0,10,30\n1,nan,30\n2,10,30\n");
        assert!(
            e.contains("row 2 (line 3)") && e.contains("torque_nm"),
            "{e}"
        );
        let e = err("time_s,torque_nm,input_speed_hz\n0,10,30\n1,10,\n2,10,30\n");
        assert!(e.contains("row 2") && e.contains("input_speed_hz"), "{e}");
        let e = err("time_s,torque_nm,input_speed_hz\n0,10,30\n2,10,30\n1,10,30\n");
        assert!(e.contains("row 3") && e.contains("strictly"), "{e}");
        let e = err("time_s,torque_nm,input_speed_hz\n0,10,30\n1,10,30\n1,10,30\n");
        assert!(e.contains("row 3") && e.contains("strictly"), "{e}");
        // 1 s sampling with a 60 s hole.
        let mut t = String::from("time_s,torque_nm,input_speed_hz\n");
        for i in (0..20).chain(80..100) {
            t.push_str(&format!("{i},10,30\n"));
        }
        let e = err(&t);
        assert!(
            e.contains("rows 20 and 21") && e.contains("a gap of 61 s"),
            "{e}"
        );
        // Issue 33: 1e307 N m and 1e308 Hz gave inf in the spectrum and null shares.
        let e = err("time_s,torque_nm,input_speed_hz\n0,10,30\n1,1e307,30\n2,10,1e308\n");
        assert!(
            e.contains("row 2 (line 3): `torque_nm` = 1e307 is out of range")
                && e.contains("[-1e7, 1e7]")
                && e.contains("row 3 (line 4): `input_speed_hz` = 1e308"),
            "{e}"
        );
        let e = err("time_s,torque_nm,input_speed_rpm\n0,10,30\n1,10,70000\n");
        assert!(
            e.contains("`input_speed_rpm` = 70000") && e.contains("6e4]"),
            "{e}"
        );
        let e = err("time_s,torque_nm,input_speed_hz\n0,10,30\n1e300,10,30\n");
        assert!(e.contains("`time_s` = 1e300 is out of range"), "{e}");
        let e = err("time,torque_nm,input_speed_hz\n0,10,30\n");
        assert!(e.contains("`time_s` column"), "{e}");
        let e = err("time_s,torque_nm,input_speed_hz\n0,10,30\n");
        assert!(e.contains("at least two samples"), "{e}");
    }
}
