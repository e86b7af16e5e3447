//! A measured transfer path: a table of accelerances (FRFs) from the bearing-force inputs
//! to the sensors, read from CSV.
//!
//! Format (one row per frequency, sensor and input; `#` starts a comment line):
//!
//! ```text
//! frequency_hz,sensor,input,real_m_per_s2_per_n,imag_m_per_s2_per_n
//! 0,input,pinion_y,0,0
//! 100,input,pinion_y,-0.0012,0.0001
//! ...
//! ```
//!
//! `input` is one of `pinion_x`, `pinion_y`, `gear_x`, `gear_y`; sensors are named freely
//! and become the channels, in the order they first appear. For each sensor and input
//! the frequencies must be non-negative and strictly increasing. A pair that is absent
//! transmits nothing. Between rows the real and imaginary parts are interpolated
//! linearly; below the first frequency the accelerance falls as f^2 (that of any
//! structure held to the ground, A ~ -omega^2 / k at low frequency); above the last it is
//! taken as zero (the table says nothing there, and the caller warns when the recorded
//! band reaches beyond it).

use super::bearing::INPUTS;
use realfft::num_complex::Complex64;

/// One FRF: frequencies (ascending) and complex accelerances.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Frf {
    /// Frequency of each point, Hz (ascending).
    pub frequency_hz: Vec<f64>,
    /// Complex accelerance at each frequency, m/s^2 per N.
    pub value: Vec<Complex64>,
}

impl Frf {
    /// Accelerance at `f_hz` (module docs for the ends).
    pub fn at(&self, f_hz: f64) -> Complex64 {
        let f = &self.frequency_hz;
        let Some((&first, &last)) = f.first().zip(f.last()) else {
            return Complex64::new(0.0, 0.0);
        };
        if f_hz > last {
            return Complex64::new(0.0, 0.0);
        }
        if f_hz <= first {
            return if first > 0.0 {
                self.value[0] * (f_hz / first).powi(2)
            } else {
                self.value[0]
            };
        }
        let j = f.partition_point(|x| *x < f_hz);
        let w = (f_hz - f[j - 1]) / (f[j] - f[j - 1]);
        self.value[j - 1] * (1.0 - w) + self.value[j] * w
    }
}

/// A table of FRFs per sensor and input.
#[derive(Debug, Clone, PartialEq)]
pub struct FrfTable {
    /// Sensor names, in channel order.
    pub sensors: Vec<String>,
    /// `frf[s][j]`: sensor s, input j (`INPUTS` order).
    pub frf: Vec<[Frf; 4]>,
}

impl FrfTable {
    /// Accelerance from input `j` (`INPUTS` order) to sensor `s` at `f_hz` (Hz), m/s^2 per N.
    pub fn at(&self, s: usize, j: usize, f_hz: f64) -> Complex64 {
        self.frf[s][j].at(f_hz)
    }

    /// Highest frequency any FRF of the table covers, Hz.
    pub(crate) fn max_frequency_hz(&self) -> f64 {
        self.frf
            .iter()
            .flat_map(|row| row.iter())
            .filter_map(|f| f.frequency_hz.last().copied())
            .fold(0.0, f64::max)
    }
}

const HEADER: [&str; 5] = [
    "frequency_hz",
    "sensor",
    "input",
    "real_m_per_s2_per_n",
    "imag_m_per_s2_per_n",
];

/// Range of the real and of the imaginary part of an accelerance in a table, m/s^2 per N:
/// within +-1e6, the accelerance of an effective mass of 1 microgram, far beyond any
/// structure, as a modal path's gains are bounded (`path_file`); a bearing force times it
/// stays finite.
const ACCELERANCE_RANGE: (f64, f64) = (-1e6, 1e6);
/// Range of a table's row frequencies, Hz (a modal path's modes reach 1e7 Hz too; a
/// negative one is refused with its own message after this).
const FREQUENCY_RANGE_HZ: (f64, f64) = (f64::NEG_INFINITY, 1e7);

/// A row's frequency, real and imaginary part, each None (its problem added, naming the
/// line `at`) where it is not a finite number or out of its range (issue 33: values of
/// 1e308 overflowed to inf in the record, its channels came out empty).
fn row_numbers(
    rec: &csv::StringRecord,
    at: &str,
    problems: &mut Vec<String>,
) -> (Option<f64>, Option<f64>, Option<f64>) {
    let mut num = |i: usize, range: (f64, f64)| -> Option<f64> {
        let x = match rec[i].parse::<f64>() {
            Ok(x) if x.is_finite() => x,
            _ => {
                problems.push(format!(
                    "{at}: `{}` = `{}` is not a finite number",
                    HEADER[i], &rec[i]
                ));
                return None;
            }
        };
        bounded(Some(x), HEADER[i], range, at, problems)
    };
    (
        num(0, FREQUENCY_RANGE_HZ),
        num(3, ACCELERANCE_RANGE),
        num(4, ACCELERANCE_RANGE),
    )
}

/// `x` if it lies in `range`, else None with the problem (the line `at`, the column
/// `what`, the value and the range) added to `problems`.
fn bounded(
    x: Option<f64>,
    what: &str,
    (lo, hi): (f64, f64),
    at: &str,
    problems: &mut Vec<String>,
) -> Option<f64> {
    let x = x?;
    if (lo..=hi).contains(&x) {
        return Some(x);
    }
    let range = if lo == f64::NEG_INFINITY {
        format!("at most {hi:e}")
    } else {
        format!("within +-{hi:e}")
    };
    problems.push(format!(
        "{at}: `{what}` = {} is out of range: expected a number {range}",
        crate::format::format_number(x)
    ));
    None
}

/// Parse an FRF table; `source` names the file in messages. Every problem is returned,
/// each with its line.
pub(crate) fn parse_frf_table(text: &str, source: &str) -> Result<FrfTable, Vec<String>> {
    let mut rdr = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let header: Vec<String> = match rdr.headers() {
        Ok(h) => h.iter().map(str::to_owned).collect(),
        Err(e) => return Err(vec![format!("{source}: cannot read the header: {e}")]),
    };
    if header != HEADER {
        return Err(vec![format!(
            "{source}: the header is `{}`, expected `{}`",
            header.join(","),
            HEADER.join(",")
        )]);
    }
    let mut problems = Vec::new();
    let mut table = FrfTable {
        sensors: Vec::new(),
        frf: Vec::new(),
    };
    for rec in rdr.records() {
        let rec = match rec {
            Ok(r) => r,
            Err(e) => {
                problems.push(format!("{source}: {e}"));
                continue;
            }
        };
        let line = rec.position().map_or(0, |p| p.line());
        let at = format!("{source}, line {line}");
        let (f, re, im) = row_numbers(&rec, &at, &mut problems);
        let Some(j) = INPUTS.iter().position(|n| *n == &rec[2]) else {
            problems.push(format!(
                "{at}: `input` = `{}` is not a bearing-force input; expected one of {}",
                &rec[2],
                INPUTS.join(", ")
            ));
            continue;
        };
        if rec[1].is_empty() {
            problems.push(format!("{at}: `sensor` is empty"));
            continue;
        }
        let (Some(f), Some(re), Some(im)) = (f, re, im) else {
            continue;
        };
        let s = match table.sensors.iter().position(|n| n == &rec[1]) {
            Some(s) => s,
            None => {
                table.sensors.push(rec[1].to_owned());
                table.frf.push(Default::default());
                table.sensors.len() - 1
            }
        };
        let frf = &mut table.frf[s][j];
        if f < 0.0 {
            problems.push(format!(
                "{at}: `frequency_hz` = {f} is negative; frequencies must be >= 0"
            ));
            continue;
        }
        if let Some(&prev) = frf.frequency_hz.last() {
            if f <= prev {
                problems.push(format!(
                    "{at}: `frequency_hz` = {f} for sensor `{}`, input `{}` is not above the previous row's {prev}; frequencies must increase strictly",
                    &rec[1], &rec[2]
                ));
                continue;
            }
        }
        frf.frequency_hz.push(f);
        frf.value.push(Complex64::new(re, im));
    }
    if table.sensors.is_empty() && problems.is_empty() {
        problems.push(format!("{source}: no rows"));
    }
    if problems.is_empty() {
        Ok(table)
    } else {
        Err(problems)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolates_and_extends_as_documented() {
        let text = "frequency_hz,sensor,input,real_m_per_s2_per_n,imag_m_per_s2_per_n\n\
                    # a comment\n\
                    100,top,pinion_y,1,0\n200,top,pinion_y,3,-2\n";
        let t = parse_frf_table(text, "frf.csv").unwrap();
        assert_eq!(t.sensors, vec!["top".to_string()]);
        let v = t.at(0, 1, 150.0);
        assert!((v - Complex64::new(2.0, -1.0)).norm() < 1e-15);
        // f^2 below the first row, zero above the last, zero for an absent pair.
        assert!((t.at(0, 1, 50.0) - Complex64::new(0.25, 0.0)).norm() < 1e-15);
        assert_eq!(t.at(0, 1, 201.0), Complex64::new(0.0, 0.0));
        assert_eq!(t.at(0, 0, 150.0), Complex64::new(0.0, 0.0));
        assert_eq!(t.max_frequency_hz(), 200.0);
    }

    #[test]
    fn values_beyond_any_structure_are_refused_with_their_lines() {
        // Issue 33: accelerances of 1e308 gave inf in the record (empty channels).
        let text = "frequency_hz,sensor,input,real_m_per_s2_per_n,imag_m_per_s2_per_n\n\
                    100,top,pinion_y,1e308,0\n200,top,pinion_y,1,-2e6\n3e7,top,pinion_y,1,0\n";
        let e = parse_frf_table(text, "frf.csv").unwrap_err();
        assert_eq!(e.len(), 3, "{e:?}");
        assert!(
            e[0].contains("line 2") && e[0].contains("`real_m_per_s2_per_n` = 1e308"),
            "{e:?}"
        );
        assert!(e[1].contains("line 3") && e[1].contains("+-1e6"), "{e:?}");
        assert!(
            e[2].contains("line 4") && e[2].contains("`frequency_hz` = 30000000"),
            "{e:?}"
        );
        // The edges are accepted.
        let ok = "frequency_hz,sensor,input,real_m_per_s2_per_n,imag_m_per_s2_per_n\n\
                  0,top,pinion_y,1e6,-1e6\n1e7,top,pinion_y,-1e6,1e6\n";
        assert!(parse_frf_table(ok, "frf.csv").is_ok());
    }

    #[test]
    fn unsorted_and_negative_frequencies_are_refused_with_their_lines() {
        let text = "frequency_hz,sensor,input,real_m_per_s2_per_n,imag_m_per_s2_per_n\n\
                    -5,top,pinion_y,1,0\n100,top,pinion_y,1,0\n90,top,pinion_y,1,0\n\
                    10,top,shaft,1,0\n";
        let e = parse_frf_table(text, "frf.csv").unwrap_err();
        assert_eq!(e.len(), 3, "{e:?}");
        assert!(
            e[0].contains("line 2") && e[0].contains("negative"),
            "{}",
            e[0]
        );
        assert!(
            e[1].contains("line 4") && e[1].contains("increase strictly"),
            "{}",
            e[1]
        );
        assert!(e[2].contains("`shaft`"), "{}", e[2]);
    }
}
