//! The case list of a sweep: `--vary` axes, their cross product in a stable order, and
//! shards of it.
//!
//! Every value is kept as the text handed to `load_case` as `--set KEY=value`, so a sweep
//! case is exactly the case `gearwear dynamics --set KEY=value ...` would run.

/// Largest cross product accepted (a guard against typos such as a step of 1e-9).
pub const MAX_CASES: usize = 1_000_000;

/// One varied key and its values, in the order given.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Axis {
    /// Dotted case key, `section.key`.
    pub key: String,
    /// Values as `--set` text (TOML value or bare string).
    pub values: Vec<String>,
}

/// Parse `KEY=START:STOP:STEP` (numbers, STOP included when the range lands on it) or
/// `KEY=v1,v2,...` (any values the key accepts). Errors name the key.
pub fn parse_vary(text: &str) -> Result<Axis, String> {
    let form = "expected KEY=START:STOP:STEP or KEY=v1,v2,...";
    let Some((key, spec)) = text.split_once('=') else {
        return Err(format!("--vary \"{text}\": {form}"));
    };
    let key = key.trim();
    let spec = spec.trim();
    match key.split_once('.') {
        Some((s, k)) if !s.is_empty() && !k.is_empty() && !k.contains('.') => {}
        _ => {
            return Err(format!(
                "--vary \"{text}\": the key `{key}` must be section.key"
            ))
        }
    }
    if spec.is_empty() {
        return Err(format!("--vary {key}: no values given ({form})"));
    }
    let array_key = matches!(
        crate::config::schema::spec(key).map(|s| s.valid),
        Some(crate::config::schema::Valid::NumArray(_))
    );
    let values = if array_key {
        array_values(key, spec)?
    } else if spec.contains(':') && !spec.contains(',') {
        let parts: Vec<&str> = spec.split(':').map(str::trim).collect();
        let [a, b, c] = parts[..] else {
            return Err(format!(
                "--vary {key}={spec}: a range is START:STOP:STEP (three numbers)"
            ));
        };
        let num = |s: &str, what: &str| -> Result<f64, String> {
            s.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| format!("--vary {key}={spec}: {what} `{s}` is not a finite number"))
        };
        let (start, stop, step) = (num(a, "START")?, num(b, "STOP")?, num(c, "STEP")?);
        range_values(start, stop, step)
            .map_err(|m| format!("--vary {key}={spec}: {m}"))?
            .into_iter()
            .map(format_number)
            .collect()
    } else {
        let items: Vec<String> = spec.split(',').map(|s| s.trim().to_owned()).collect();
        if items.iter().any(String::is_empty) {
            return Err(format!("--vary {key}={spec}: empty value in the list"));
        }
        items
    };
    no_repeats(key, &values)?;
    Ok(Axis {
        key: key.to_owned(),
        values,
    })
}

/// The values of an array key: `[a, b, c],[d, e, f],...` (each value in brackets; the
/// commas inside brackets belong to the value).
fn array_values(key: &str, spec: &str) -> Result<Vec<String>, String> {
    let bad = || {
        format!(
            "--vary {key}={spec}: the key takes an array; give each value in brackets, e.g. --vary {key}=[0.21,0.19,0.15],[0.3,0.25,0.2]"
        )
    };
    let mut values = Vec::new();
    let mut rest = spec.trim();
    while !rest.is_empty() {
        if !rest.starts_with('[') {
            return Err(bad());
        }
        let end = rest.find(']').ok_or_else(bad)?;
        values.push(rest[..=end].to_owned());
        rest = rest[end + 1..].trim_start();
        if let Some(r) = rest.strip_prefix(',') {
            rest = r.trim_start();
            if rest.is_empty() {
                return Err(format!("--vary {key}={spec}: empty value in the list"));
            }
        } else if !rest.is_empty() {
            return Err(bad());
        }
    }
    Ok(values)
}

/// A value as the case reads it: numbers compared as numbers (`30` = `30.0` = `3e1`),
/// arrays element by element, anything else as its text.
fn canonical(v: &str) -> String {
    let num = |x: &toml::Value| x.as_float().or_else(|| x.as_integer().map(|i| i as f64));
    match toml::from_str::<toml::Table>(&format!("v = {v}"))
        .ok()
        .and_then(|t| t.get("v").cloned())
    {
        Some(x) if num(&x).is_some() => format!("{:?}", num(&x)),
        Some(toml::Value::Array(a)) if a.iter().all(|x| num(x).is_some()) => {
            format!("{:?}", a.iter().filter_map(num).collect::<Vec<_>>())
        }
        _ => v.trim().to_owned(),
    }
}

/// Error when two values of an axis are the same value (which would run one case twice).
/// Linear in the number of values (a hash of the canonical forms).
fn no_repeats(key: &str, values: &[String]) -> Result<(), String> {
    let mut seen: std::collections::HashMap<String, usize> =
        std::collections::HashMap::with_capacity(values.len());
    for (i, v) in values.iter().enumerate() {
        if let Some(j) = seen.insert(canonical(v), i) {
            return Err(format!(
                "--vary {key}: value `{}` is the same as `{}`: each value may be listed once (the case would run twice)",
                values[i], values[j]
            ));
        }
    }
    Ok(())
}

/// `start, start + step, ...` up to `stop`. `stop` is included (exactly) when
/// (stop - start) / step is within 1e-9 (relative, floor 1e-9 absolute) of a whole
/// number; the values between are start + k step rounded to 15 significant digits, so
/// 0.1:0.5:0.1 gives 0.3, not 0.30000000000000004.
pub fn range_values(start: f64, stop: f64, step: f64) -> Result<Vec<f64>, String> {
    if step <= 0.0 {
        return Err(format!("STEP must be > 0, got {step}"));
    }
    let q = (stop - start) / step;
    let tol = 1e-9 * q.abs().max(1.0);
    if q < -tol {
        return Err(format!("empty range: STOP {stop} < START {start}"));
    }
    let lands = (q - q.round()).abs() <= tol;
    let n = if lands { q.round() } else { q.floor() }.max(0.0);
    if n >= MAX_CASES as f64 {
        return Err(format!("{} values (more than {MAX_CASES})", n + 1.0));
    }
    let n = n as usize;
    Ok((0..=n)
        .map(|k| match k {
            0 => start,
            _ if k == n && lands => stop,
            _ => round_sig(start + k as f64 * step, 15),
        })
        .collect())
}

/// `x` rounded to `digits` significant decimal digits.
fn round_sig(x: f64, digits: usize) -> f64 {
    format!("{x:.*e}", digits - 1).parse().unwrap_or(x)
}

pub use crate::format::format_number;

/// The cross product of the axes. Case ids number it with the first axis varying
/// slowest (row-major), so ids do not depend on sharding.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SweepPlan {
    pub axes: Vec<Axis>,
}

impl SweepPlan {
    /// Checks: at least one axis, no key twice, at most [`MAX_CASES`] cases.
    pub fn new(axes: Vec<Axis>) -> Result<Self, String> {
        if axes.is_empty() {
            return Err("sweep: give at least one --vary".into());
        }
        for (i, a) in axes.iter().enumerate() {
            if axes[..i].iter().any(|b| b.key == a.key) {
                return Err(format!("--vary {}: the key is varied twice", a.key));
            }
        }
        let mut n: usize = 1;
        for a in &axes {
            n = n
                .checked_mul(a.values.len())
                .filter(|n| *n <= MAX_CASES)
                .ok_or_else(|| format!("sweep: more than {MAX_CASES} cases"))?;
        }
        Ok(Self { axes })
    }

    /// Number of cases in the full (unsharded) sweep.
    pub fn len(&self) -> usize {
        self.axes.iter().map(|a| a.values.len()).product()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    pub fn keys(&self) -> Vec<String> {
        self.axes.iter().map(|a| a.key.clone()).collect()
    }

    /// Values of case `id` (< len), one per axis.
    pub fn values_of(&self, id: usize) -> Vec<String> {
        let mut rest = id;
        let mut out = vec![String::new(); self.axes.len()];
        for (i, a) in self.axes.iter().enumerate().rev() {
            out[i] = a.values[rest % a.values.len()].clone();
            rest /= a.values.len();
        }
        out
    }

    /// `--set` overrides of case `id`.
    pub fn overrides_of(&self, id: usize) -> Vec<String> {
        self.axes
            .iter()
            .zip(self.values_of(id))
            .map(|(a, v)| format!("{}={v}", a.key))
            .collect()
    }
}

/// `--shard I/N`: the I-th (1-based) of N round-robin slices, i.e. the case ids with
/// id mod N = I - 1. Round-robin, not contiguous: neighbouring cases of a sweep cost
/// about the same, so interleaving gives every shard a similar mix.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
}

impl Shard {
    /// The whole sweep as one shard.
    pub const ALL: Shard = Shard { index: 1, count: 1 };

    pub fn parse(text: &str) -> Result<Self, String> {
        let bad = || format!("--shard {text}: expected I/N with whole numbers 1 <= I <= N");
        let (i, n) = text.split_once('/').ok_or_else(bad)?;
        let i: usize = i.trim().parse().map_err(|_| bad())?;
        let n: usize = n.trim().parse().map_err(|_| bad())?;
        if i == 0 || n == 0 || i > n {
            return Err(bad());
        }
        Ok(Self { index: i, count: n })
    }

    /// This shard's case ids among `total`, ascending.
    pub fn ids(&self, total: usize) -> Vec<usize> {
        (self.index - 1..total).step_by(self.count).collect()
    }

    /// File stem of this shard's outputs: `sweep` unsharded, else `sweep_shard_I_of_N`
    /// (so shards may share one output directory).
    pub fn stem(&self) -> String {
        if self.count == 1 {
            "sweep".into()
        } else {
            format!("sweep_shard_{}_of_{}", self.index, self.count)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn range_includes_stop_when_it_lands_on_it() {
        // 0.1 * 3 = 0.30000000000000004 in binary: rounding to 15 digits gives 0.3.
        let v = range_values(0.1, 0.5, 0.1).unwrap();
        assert_eq!(v, vec![0.1, 0.2, 0.3, 0.4, 0.5]);
        // (0.9 - 0.3) / 0.2 = 2.9999999999999996: within 1e-9 of 3, so 0.9 is in.
        assert_eq!(
            range_values(0.3, 0.9, 0.2).unwrap(),
            vec![0.3, 0.5, 0.7, 0.9]
        );
        // Not landing: stops below STOP.
        assert_eq!(
            range_values(10.0, 20.0, 4.0).unwrap(),
            vec![10.0, 14.0, 18.0]
        );
        // START = STOP: one value.
        assert_eq!(range_values(30.0, 30.0, 5.0).unwrap(), vec![30.0]);
    }

    #[test]
    fn range_rejects_bad_step_and_empty_range() {
        assert!(range_values(1.0, 2.0, 0.0).unwrap_err().contains("STEP"));
        assert!(range_values(1.0, 2.0, -1.0).unwrap_err().contains("STEP"));
        assert!(range_values(2.0, 1.0, 0.5).unwrap_err().contains("empty"));
        assert!(range_values(0.0, 1.0, 1e-12).is_err());
    }

    #[test]
    fn parse_forms_and_errors_name_the_key() {
        let a = parse_vary("operating.input_speed_hz=20:30:5").unwrap();
        assert_eq!(a.values, vec!["20", "25", "30"]);
        let a = parse_vary(" friction.model = xu2007, constant ").unwrap();
        assert_eq!((a.key.as_str(), a.values.len()), ("friction.model", 2));
        for bad in [
            "operating.input_speed_hz=1:2",
            "operating.input_speed_hz=5:1:1",
            "operating.input_speed_hz=1:2:0",
            "operating.input_speed_hz=a:2:1",
            "operating.input_speed_hz=1,,2",
            "operating.input_speed_hz=",
        ] {
            let e = parse_vary(bad).unwrap_err();
            assert!(e.contains("operating.input_speed_hz"), "{bad}: {e}");
        }
        assert!(parse_vary("speed").is_err());
        assert!(parse_vary("speed=1,2").unwrap_err().contains("section.key"));
    }

    #[test]
    fn equal_values_are_listed_once() {
        for bad in ["a.x=30,30.0", "a.x=30,3e1", "friction.model=none,none"] {
            let e = parse_vary(bad).unwrap_err();
            assert!(e.contains("same as"), "{bad}: {e}");
        }
        assert_eq!(parse_vary("a.x=30,30.5").unwrap().values.len(), 2);
    }

    #[test]
    fn array_keys_take_bracketed_values() {
        let key = "surface.roughness_table_rms_um";
        let a = parse_vary(&format!("{key}=[0.21,0.19,0.15], [0.3, 0.2, 0.1]")).unwrap();
        assert_eq!(a.values, vec!["[0.21,0.19,0.15]", "[0.3, 0.2, 0.1]"]);
        for bad in ["1,2", "0.1:0.3:0.1", "[1,2],3", "[1,2", "[1],"] {
            let e = parse_vary(&format!("{key}={bad}")).unwrap_err();
            assert!(e.contains(key), "{bad}: {e}");
        }
        let e = parse_vary(&format!("{key}=1,2")).unwrap_err();
        assert!(
            e.contains("takes an array") && !e.contains("integer"),
            "{e}"
        );
        assert!(parse_vary(&format!("{key}=[1,2],[1.0,2.0]")).is_err());
    }

    #[test]
    fn numbers_read_back_exactly() {
        for x in [30.0, 32.5, 0.3, 1e-7, 2.5e16, -4.25, 0.0] {
            assert_eq!(format_number(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(format_number(30.0), "30");
    }

    #[test]
    fn first_axis_varies_slowest_and_shards_partition() {
        let p = SweepPlan::new(vec![
            parse_vary("a.x=1,2").unwrap(),
            parse_vary("b.y=p,q,r").unwrap(),
        ])
        .unwrap();
        assert_eq!(p.len(), 6);
        assert_eq!(p.values_of(0), vec!["1", "p"]);
        assert_eq!(p.values_of(2), vec!["1", "r"]);
        assert_eq!(p.values_of(3), vec!["2", "p"]);
        assert_eq!(p.overrides_of(5), vec!["a.x=2", "b.y=r"]);
        // Every id in exactly one shard, for several shard counts (including more shards
        // than cases).
        for n in 1..=8 {
            let mut all: Vec<usize> = (1..=n)
                .flat_map(|i| Shard { index: i, count: n }.ids(6))
                .collect();
            all.sort_unstable();
            assert_eq!(all, (0..6).collect::<Vec<_>>(), "N = {n}");
        }
        assert!(SweepPlan::new(vec![
            parse_vary("a.x=1").unwrap(),
            parse_vary("a.x=2").unwrap()
        ])
        .is_err());
    }

    #[test]
    fn shard_parse() {
        assert_eq!(Shard::parse("2/3").unwrap(), Shard { index: 2, count: 3 });
        for bad in ["0/3", "4/3", "1/0", "x/2", "3"] {
            assert!(Shard::parse(bad).is_err(), "{bad}");
        }
        assert_eq!(Shard::parse("1/1").unwrap().stem(), "sweep");
        assert_eq!(Shard::parse("2/4").unwrap().stem(), "sweep_shard_2_of_4");
    }
}
