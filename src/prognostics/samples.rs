//! The posterior samples CSV: `sample` and one column per parameter
//! (`wear_coefficient_m2_per_n`, `roughness_scale`, `load_torque_nm`).

use super::prior::{Parameter, Theta, PARAMETERS};
use crate::remedy::Problems;

/// Most rows of a samples file: `calibrate` writes at most 1e6
/// (`limits::CALIBRATE_SAMPLES`).
pub const MAX_ROWS: usize = 1_000_000;

/// The valid range of each parameter, as the case's keys: k as `wear.coefficient_m2_per_n`
/// and the prior's bounds (1e-22 to 1e-11 m^2/N), the roughness factor as the prior's
/// (0.01 to 10), the torque as `operating.load_torque_nm` (1e-3 to 1e7 N m).
pub const RANGES: [(f64, f64); 3] = [(1e-22, 1e-11), (0.01, 10.0), (1e-3, 1e7)];

/// Read a samples CSV. Parameters without a column take `defaults`. Errors name the row
/// and column.
pub fn read_samples(text: &str, source: &str, defaults: Theta) -> Result<Vec<Theta>, Problems> {
    let mut rdr = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let header: Vec<String> = match rdr.headers() {
        Ok(h) => h.iter().map(str::to_owned).collect(),
        Err(e) => return Err(vec![format!("{source}: cannot read the header: {e}")].into()),
    };
    let mut problems = Vec::new();
    let mut cols: Vec<(usize, usize)> = Vec::new();
    for (j, h) in header.iter().enumerate() {
        if header[..j].contains(h) {
            problems.push(format!("{source}: column `{h}` appears twice"));
            continue;
        }
        match Parameter::parse(h) {
            Some(p) => cols.push((PARAMETERS.iter().position(|x| *x == p).unwrap_or(0), j)),
            None if h == "sample" => {}
            None => problems.push(format!(
                "{source}: unknown column `{h}`; valid: sample, {}",
                PARAMETERS.map(|p| p.column()).join(", ")
            )),
        }
    }
    if !cols.iter().any(|c| c.0 == 0) {
        problems.push(format!("{source}: no `wear_coefficient_m2_per_n` column"));
    }
    if !problems.is_empty() {
        return Err(problems.into());
    }
    let mut out = Vec::new();
    for (r, rec) in rdr.records().enumerate() {
        if r >= MAX_ROWS {
            problems.push(format!(
                "{source}: more than {MAX_ROWS} rows (calibrate writes at most that many)"
            ));
            break;
        }
        if problems.len() >= 100 {
            break; // enough to go on with
        }
        let at = format!("{source}: row {} (line {})", r + 1, r + 2);
        let rec = match rec {
            Ok(x) => x,
            Err(e) => {
                problems.push(format!("{at}: {e}"));
                continue;
            }
        };
        let mut t = defaults;
        for (i, j) in &cols {
            let cell = rec.get(*j).unwrap_or("");
            let (lo, hi) = RANGES[*i];
            match cell.parse::<f64>() {
                Ok(x) if (lo..=hi).contains(&x) => t[*i] = x,
                _ => problems.push(format!(
                    "{at}: `{}` = `{}` is not a number in [{lo:e}, {hi:e}]",
                    PARAMETERS[*i].column(),
                    crate::format::clip(&cell.escape_debug().to_string(), 40)
                )),
            }
        }
        out.push(t);
    }
    if out.is_empty() && problems.is_empty() {
        problems.push(format!("{source}: no samples"));
    }
    if problems.is_empty() {
        Ok(out)
    } else {
        Err(problems.into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_errors() {
        let text = "sample,wear_coefficient_m2_per_n,roughness_scale,load_torque_nm\n\
                    0,2.5e-16,1,60\n1,3e-16,1.1,55\n";
        let s = vec![[2.5e-16, 1.0, 60.0], [3e-16, 1.1, 55.0]];
        assert_eq!(read_samples(text, "p.csv", [0.0; 3]).unwrap(), s);
        // Missing columns take the defaults.
        let r = read_samples(
            "wear_coefficient_m2_per_n\n1e-16\n",
            "p.csv",
            [0.0, 1.0, 60.0],
        );
        assert_eq!(r.unwrap(), vec![[1e-16, 1.0, 60.0]]);
        let e = read_samples("wear_coefficient_m2_per_n\n1e-16\n-1\n", "p.csv", [0.0; 3]);
        assert!(e.unwrap_err().messages()[0].contains("row 2 (line 3)"));
        let e = read_samples("k\n1\n", "p.csv", [0.0; 3]).unwrap_err();
        assert!(e.messages()[0].contains("unknown column `k`"));
        // Outside the case's ranges, subnormal, or a column twice.
        for bad in ["1e-9", "5e-324", "0"] {
            let e = read_samples(
                &format!("wear_coefficient_m2_per_n\n{bad}\n"),
                "p.csv",
                [0.0; 3],
            );
            assert!(e.unwrap_err().messages()[0].contains("1e-22"), "{bad}");
        }
        let e = read_samples(
            "wear_coefficient_m2_per_n,wear_coefficient_m2_per_n\n1e-16,1e-16\n",
            "p.csv",
            [0.0; 3],
        );
        assert!(e.unwrap_err().messages()[0].contains("twice"));
    }
}
