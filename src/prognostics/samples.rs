//! The posterior samples CSV: `sample` and one column per parameter
//! (`wear_coefficient_m2_per_n`, `roughness_scale`, `load_torque_nm`).

use super::prior::{Parameter, Theta, PARAMETERS};

/// Read a samples CSV. Parameters without a column take `defaults`. Errors name the row
/// and column.
pub fn read_samples(text: &str, source: &str, defaults: Theta) -> Result<Vec<Theta>, Vec<String>> {
    let mut rdr = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let header: Vec<String> = match rdr.headers() {
        Ok(h) => h.iter().map(str::to_owned).collect(),
        Err(e) => return Err(vec![format!("{source}: cannot read the header: {e}")]),
    };
    let mut problems = Vec::new();
    let mut cols: Vec<(usize, usize)> = Vec::new();
    for (j, h) in header.iter().enumerate() {
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
        return Err(problems);
    }
    let mut out = Vec::new();
    for (r, rec) in rdr.records().enumerate() {
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
            match cell.parse::<f64>() {
                Ok(x) if x.is_finite() && x > 0.0 => t[*i] = x,
                _ => problems.push(format!(
                    "{at}: `{}` = `{cell}` is not a finite number > 0",
                    PARAMETERS[*i].column()
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
        Err(problems)
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
        assert!(e.unwrap_err()[0].contains("row 2 (line 3)"));
        let e = read_samples("k\n1\n", "p.csv", [0.0; 3]).unwrap_err();
        assert!(e[0].contains("unknown column `k`"));
    }
}
