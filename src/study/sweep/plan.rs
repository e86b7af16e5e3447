//! The case list of a sweep: its axes (varied keys and their values), their cross product
//! in a stable order, and shards of it.
//!
//! Each axis names a key of the case file, resolved against the schema when the sweep is
//! planned (an unknown key is refused there), and holds its values typed once (numbers,
//! strings, arrays of numbers, read as an override reads them), each with the label it
//! goes by in tables and case records (the text as given, or the shortest form of a
//! range's number). A case of the sweep is the base case with its values set
//! (`config::load::case_with`), so it is exactly the case an override
//! `KEY=value` of the same value gives. A key of a numbered table (`stage.2.face_width_mm`,
//! the N-th `[[stage]]` or `[[fault]]` table, as an override spells it) is checked as its
//! table's key (`stage.face_width_mm`); whether the case has table N is checked when the
//! cases are resolved.

use crate::config::load::{known_key, override_value};
use crate::config::schema::{KeySpec, TABLE_ARRAYS};
use crate::format::{clip, SHOWN_CHARS};
use crate::remedy::{Arg, Problem, Remedy, Words};
use toml::Value;

/// Largest cross product accepted (a guard against typos such as a step of 1e-9).
pub const MAX_CASES: usize = 1_000_000;

/// One value of an axis.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisValue {
    /// The value as the case reads it.
    pub value: Value,
    /// How the value is shown: in sweep tables, case records and messages.
    pub label: String,
}

impl AxisValue {
    /// A number (a range's value), labelled in its shortest exact form.
    pub fn number(x: f64) -> Self {
        Self {
            value: Value::Float(x),
            label: format_number(x),
        }
    }

    /// A value given as text, read as an override reads it.
    pub fn text(t: &str) -> Self {
        Self {
            value: override_value(t),
            label: t.trim().to_owned(),
        }
    }

    /// The value as a finite number, if it is one.
    pub fn as_number(&self) -> Option<f64> {
        number_of(&self.value).filter(|x| x.is_finite())
    }
}

fn number_of(v: &Value) -> Option<f64> {
    v.as_float().or_else(|| v.as_integer().map(|i| i as f64))
}

/// One varied key and its values, in the order given.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// Dotted case key, `section.key` as the schema spells it, or `section.N.key` for
    /// the N-th table of a numbered section (`stage.2.face_width_mm`).
    pub key: String,
    /// The values, in the order given.
    pub values: Vec<AxisValue>,
}

/// The schema's entry of a varied key and the key as the sweep spells it: `section.key`
/// as the schema does, or `section.N.key` (N a whole number from 1, written without
/// leading zeros) of a numbered section ([[stage]], [[fault]]), whose entry is
/// `section.key`'s.
fn resolve_key(key: &str) -> Result<(&'static KeySpec, String), Problem> {
    let unknown = |e: String| Problem::given(Arg::Vary, clip(key, SHOWN_CHARS), e);
    let parts: Vec<&str> = key.split('.').collect();
    if let [section, n, field] = parts[..] {
        if TABLE_ARRAYS.contains(&section) && !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit())
        {
            let spec = known_key(&format!("{section}.{field}")).map_err(unknown)?;
            let n = n
                .parse::<usize>()
                .ok()
                .filter(|n| *n >= 1)
                .ok_or_else(|| unknown(format!("[[{section}]] tables are numbered from 1")))?;
            return Ok((spec, format!("{section}.{n}.{field}")));
        }
    }
    let spec = known_key(key).map_err(unknown)?;
    Ok((spec, spec.key.to_owned()))
}

impl Axis {
    /// An axis of `key` with `values` (repeats refused, key checked against the schema).
    pub fn new(key: &str, values: Vec<AxisValue>) -> Result<Self, Problem> {
        let (_, key) = resolve_key(key)?;
        if values.is_empty() {
            return Err(Problem::given(Arg::Vary, key, "no values given"));
        }
        no_repeats(&key, &values)?;
        Ok(Self { key, values })
    }

    /// The value labels, in order.
    pub fn labels(&self) -> Vec<String> {
        self.values.iter().map(|v| v.label.clone()).collect()
    }
}

/// Parse `KEY=START:STOP:STEP` or `KEY=v1,v2,...` (the command line's form; see
/// [`parse_axis`]).
pub fn parse_vary(text: &str) -> Result<Axis, Problem> {
    let form = "expected KEY=START:STOP:STEP or KEY=v1,v2,...";
    let Some((key, spec)) = text.split_once('=') else {
        return Err(Problem::given(
            Arg::Vary,
            format!("\"{}\"", clip(text, SHOWN_CHARS)),
            form,
        ));
    };
    parse_axis(key, spec)
}

/// An axis from its key and values text: `START:STOP:STEP` (numbers, STOP included when
/// the range lands on it) or `v1,v2,...` (any values the key accepts; an array key takes
/// `[a, b],[c, d]`). Errors name the key.
pub fn parse_axis(key: &str, spec: &str) -> Result<Axis, Problem> {
    let key = key.trim();
    let spec = spec.trim();
    let form = "expected KEY=START:STOP:STEP or KEY=v1,v2,...";
    let numbered = |s: &str, n: &str| {
        TABLE_ARRAYS.contains(&s) && !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit())
    };
    match key.split('.').collect::<Vec<_>>()[..] {
        [s, k] if !s.is_empty() && !k.is_empty() => {}
        [s, n, k] if numbered(s, n) && !k.is_empty() => {}
        _ => {
            return Err(Problem::given(
                Arg::Vary,
                format!("\"{}={}\"", clip(key, SHOWN_CHARS), clip(spec, SHOWN_CHARS)),
                format!(
                    "the key `{}` must be section.key (section.N.key for the N-th [[stage]] or [[fault]] table)",
                    clip(key, SHOWN_CHARS)
                ),
            ))
        }
    }
    let (spec_of, key) = resolve_key(key)?;
    let key = key.as_str();
    if spec.is_empty() {
        return Err(Problem::given(
            Arg::Vary,
            key,
            format!("no values given ({form})"),
        ));
    }
    let given = format!("{key}={}", clip(spec, SHOWN_CHARS));
    let bad = |what: String| Problem::given(Arg::Vary, given.clone(), what);
    let array_key = matches!(spec_of.valid, crate::config::schema::Valid::NumArray(_));
    let values = if array_key {
        array_values(spec).map_err(|e| e.into_problem(&given))?
    } else if spec.contains(':') && !spec.contains(',') {
        let parts: Vec<&str> = spec.split(':').map(str::trim).collect();
        let [a, b, c] = parts[..] else {
            return Err(bad("a range is START:STOP:STEP (three numbers)".into()));
        };
        let num = |s: &str, what: &str| -> Result<f64, Problem> {
            s.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| bad(format!("{what} `{s}` is not a finite number")))
        };
        let (start, stop, step) = (num(a, "START")?, num(b, "STOP")?, num(c, "STEP")?);
        range_values(start, stop, step)
            .map_err(bad)?
            .into_iter()
            .map(AxisValue::number)
            .collect()
    } else {
        let items: Vec<&str> = spec.split(',').map(str::trim).collect();
        if items.iter().any(|s| s.is_empty()) {
            return Err(bad("empty value in the list".into()));
        }
        items.into_iter().map(AxisValue::text).collect()
    };
    Axis::new(key, values)
}

/// Why an array key's values do not parse.
enum ArrayError {
    Form,
    Empty,
}

impl ArrayError {
    fn into_problem(self, given: &str) -> Problem {
        match self {
            ArrayError::Empty => Problem::given(Arg::Vary, given, "empty value in the list"),
            ArrayError::Form => {
                let key = given.split('=').next().unwrap_or(given);
                Problem::given(Arg::Vary, given, "the key takes an array").remedy(Remedy::new(
                    Words::new()
                        .text("give each value in brackets, e.g. ")
                        .arg(Arg::Vary)
                        .text(format!(" {key}=[0.21,0.19,0.15],[0.3,0.25,0.2]")),
                ))
            }
        }
    }
}

/// The values of an array key: `[a, b, c],[d, e, f],...` (each value in brackets; the
/// commas inside brackets belong to the value).
fn array_values(spec: &str) -> Result<Vec<AxisValue>, ArrayError> {
    let mut values = Vec::new();
    let mut rest = spec.trim();
    while !rest.is_empty() {
        if !rest.starts_with('[') {
            return Err(ArrayError::Form);
        }
        let end = rest.find(']').ok_or(ArrayError::Form)?;
        values.push(AxisValue::text(&rest[..=end]));
        rest = rest[end + 1..].trim_start();
        if let Some(r) = rest.strip_prefix(',') {
            rest = r.trim_start();
            if rest.is_empty() {
                return Err(ArrayError::Empty);
            }
        } else if !rest.is_empty() {
            return Err(ArrayError::Form);
        }
    }
    Ok(values)
}

/// A value as the case reads it, for comparison: numbers as numbers (`30` = `30.0` =
/// `3e1`), arrays element by element, anything else as its text.
fn canonical(v: &AxisValue) -> String {
    match &v.value {
        x if number_of(x).is_some() => format!("{:?}", number_of(x)),
        Value::Array(a) if a.iter().all(|x| number_of(x).is_some()) => {
            format!("{:?}", a.iter().filter_map(number_of).collect::<Vec<_>>())
        }
        _ => v.label.clone(),
    }
}

/// Error when two values of an axis are the same value (which would run one case twice).
/// Linear in the number of values (a hash of the canonical forms).
fn no_repeats(key: &str, values: &[AxisValue]) -> Result<(), Problem> {
    let mut seen: std::collections::HashMap<String, usize> =
        std::collections::HashMap::with_capacity(values.len());
    for (i, v) in values.iter().enumerate() {
        if let Some(j) = seen.insert(canonical(v), i) {
            return Err(Problem::given(
                Arg::Vary,
                key,
                format!(
                    "value `{}` is the same as `{}`: each value may be listed once (the case would run twice)",
                    values[i].label, values[j].label
                ),
            ));
        }
    }
    Ok(())
}

/// `start, start + step, ...` up to `stop`. `stop` is included (exactly) when
/// (stop - start) / step is within 1e-9 (relative, floor 1e-9 absolute) of a whole
/// number; the values between are start + k step rounded to 15 significant digits, so
/// 0.1:0.5:0.1 gives 0.3, not 0.30000000000000004.
pub(crate) fn range_values(start: f64, stop: f64, step: f64) -> Result<Vec<f64>, String> {
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
#[derive(Debug, Clone, PartialEq)]
pub struct SweepPlan {
    /// The varied keys, first varying slowest.
    pub axes: Vec<Axis>,
}

impl SweepPlan {
    /// Checks: at least one axis, no key twice, at most [`MAX_CASES`] cases.
    pub fn new(axes: Vec<Axis>) -> Result<Self, Problem> {
        if axes.is_empty() {
            return Err(Problem::new(
                Words::new()
                    .text("a sweep needs at least one ")
                    .arg(Arg::Vary),
            ));
        }
        for (i, a) in axes.iter().enumerate() {
            if axes[..i].iter().any(|b| b.key == a.key) {
                return Err(Problem::given(Arg::Vary, &a.key, "the key is varied twice"));
            }
        }
        let mut n: usize = 1;
        for a in &axes {
            n = n
                .checked_mul(a.values.len())
                .filter(|n| *n <= MAX_CASES)
                .ok_or_else(|| Problem::new(format!("a sweep of more than {MAX_CASES} cases")))?;
        }
        Ok(Self { axes })
    }

    /// Number of cases in the full (unsharded) sweep.
    pub fn len(&self) -> usize {
        self.axes.iter().map(|a| a.values.len()).product()
    }

    /// Whether the sweep has no case.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The varied keys, in axis order.
    pub fn keys(&self) -> Vec<String> {
        self.axes.iter().map(|a| a.key.clone()).collect()
    }

    /// Values of case `id` (< len), one per axis.
    pub fn values_of(&self, id: usize) -> Vec<&AxisValue> {
        let mut rest = id;
        let mut out = Vec::with_capacity(self.axes.len());
        for a in self.axes.iter().rev() {
            out.push(&a.values[rest % a.values.len()]);
            rest /= a.values.len();
        }
        out.reverse();
        out
    }

    /// The value labels of case `id`, one per axis.
    pub fn labels_of(&self, id: usize) -> Vec<String> {
        self.values_of(id).iter().map(|v| v.label.clone()).collect()
    }

    /// The (key, value) settings of case `id` (`config::load::case_with`).
    pub fn settings_of(&self, id: usize) -> Vec<(&str, Value)> {
        self.axes
            .iter()
            .zip(self.values_of(id))
            .map(|(a, v)| (a.key.as_str(), v.value.clone()))
            .collect()
    }

    /// "KEY=label, KEY=label" of case `id`, for messages.
    pub fn describe(&self, id: usize) -> String {
        self.axes
            .iter()
            .zip(self.values_of(id))
            .map(|(a, v)| format!("{}={}", a.key, v.label))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// A shard `I/N`: the I-th (1-based) of N round-robin slices, i.e. the case ids with
/// id mod N = I - 1. Round-robin, not contiguous: neighbouring cases of a sweep cost
/// about the same, so interleaving gives every shard a similar mix.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// I: this shard, 1-based (1 <= I <= N).
    pub index: usize,
    /// N: the number of shards.
    pub count: usize,
}

impl Shard {
    /// The whole sweep as one shard.
    pub const ALL: Shard = Shard { index: 1, count: 1 };

    /// A shard from `I/N`; refused (naming `--shard`) unless 1 <= I <= N.
    pub fn parse(text: &str) -> Result<Self, Problem> {
        let bad = || {
            Problem::given(
                Arg::Shard,
                clip(text, SHOWN_CHARS),
                "expected I/N with whole numbers 1 <= I <= N",
            )
        };
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

    fn labels(a: &Axis) -> Vec<String> {
        a.labels()
    }

    #[test]
    fn parse_forms_and_errors_name_the_key() {
        let a = parse_vary("operating.input_speed_hz=20:30:5").unwrap();
        assert_eq!(labels(&a), vec!["20", "25", "30"]);
        assert_eq!(a.values[1].value, Value::Float(25.0));
        let a = parse_vary(" friction.model = xu2007, constant ").unwrap();
        assert_eq!((a.key.as_str(), a.values.len()), ("friction.model", 2));
        assert_eq!(a.values[0].value, Value::String("xu2007".into()));
        for bad in [
            "operating.input_speed_hz=1:2",
            "operating.input_speed_hz=5:1:1",
            "operating.input_speed_hz=1:2:0",
            "operating.input_speed_hz=a:2:1",
            "operating.input_speed_hz=1,,2",
            "operating.input_speed_hz=",
            "operating.speed_hz=1,2",
        ] {
            let e = parse_vary(bad).unwrap_err().to_string();
            assert!(
                e.contains(bad.split(['=', '.']).nth(1).unwrap()),
                "{bad}: {e}"
            );
            assert!(e.contains("operating."), "{bad}: {e}");
        }
        assert!(parse_vary("speed").is_err());
        let e = parse_vary("speed=1,2").unwrap_err().to_string();
        assert!(e.contains("section.key"), "{e}");
        let e = parse_vary("operating.speed_hz=1,2")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("unknown key") && e.contains("operating.input_speed_hz"),
            "{e}"
        );
    }

    #[test]
    fn numbered_table_keys_are_checked_as_their_tables_keys() {
        // `stage.N.KEY` is `stage.KEY` of the N-th table: its values are typed as that
        // key's, and the key keeps its table number (written without leading zeros).
        let a = parse_vary("stage.02.face_width_mm=20,25").unwrap();
        assert_eq!(a.key, "stage.2.face_width_mm");
        assert_eq!(a.values[1].value, Value::Integer(25));
        let e = parse_vary("stage.0.face_width_mm=20")
            .unwrap_err()
            .to_string();
        assert!(e.contains("numbered from 1"), "{e}");
        let e = parse_vary("stage.2.face_width=20").unwrap_err().to_string();
        assert!(e.contains("unknown key"), "{e}");
        // Only [[stage]] and [[fault]] tables are numbered.
        let e = parse_vary("gear.2.module_mm=2").unwrap_err().to_string();
        assert!(e.contains("section.N.key"), "{e}");
        let p = SweepPlan::new(vec![a, parse_vary("stage.2.face_width_mm=30").unwrap()]);
        assert!(p.unwrap_err().to_string().contains("varied twice"));
    }

    #[test]
    fn equal_values_are_listed_once() {
        for bad in [
            "operating.input_speed_hz=30,30.0",
            "operating.input_speed_hz=30,3e1",
            "friction.model=none,none",
        ] {
            let e = parse_vary(bad).unwrap_err().to_string();
            assert!(e.contains("same as"), "{bad}: {e}");
        }
        assert_eq!(
            parse_vary("operating.input_speed_hz=30,30.5")
                .unwrap()
                .values
                .len(),
            2
        );
    }

    #[test]
    fn array_keys_take_bracketed_values() {
        let key = "surface.roughness_table_rms_um";
        let a = parse_vary(&format!("{key}=[0.21,0.19,0.15], [0.3, 0.2, 0.1]")).unwrap();
        assert_eq!(labels(&a), vec!["[0.21,0.19,0.15]", "[0.3, 0.2, 0.1]"]);
        for bad in ["1,2", "0.1:0.3:0.1", "[1,2],3", "[1,2", "[1],"] {
            let e = parse_vary(&format!("{key}={bad}")).unwrap_err().to_string();
            assert!(e.contains(key), "{bad}: {e}");
        }
        let e = parse_vary(&format!("{key}=1,2")).unwrap_err().to_string();
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
            parse_vary("operating.input_speed_hz=1,2").unwrap(),
            parse_vary("friction.model=none,constant,xu2007").unwrap(),
        ])
        .unwrap();
        assert_eq!(p.len(), 6);
        assert_eq!(p.labels_of(0), vec!["1", "none"]);
        assert_eq!(p.labels_of(2), vec!["1", "xu2007"]);
        assert_eq!(p.labels_of(3), vec!["2", "none"]);
        assert_eq!(
            p.settings_of(5),
            vec![
                ("operating.input_speed_hz", Value::Integer(2)),
                ("friction.model", Value::String("xu2007".into()))
            ]
        );
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
            parse_vary("operating.input_speed_hz=1").unwrap(),
            parse_vary("operating.input_speed_hz=2").unwrap()
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
