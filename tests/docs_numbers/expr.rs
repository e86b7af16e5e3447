//! The expressions of generated numbers: operands that read a run's output, numbers, the
//! four operations, parentheses and `min`, `max`, `abs`, `sqrt`.
//!
//! An operand is one of
//! - `RUN:/json/pointer` (RFC 6901, into the run's `summary.json`), or
//!   `RUN:FILE.json#/json/pointer` (into another JSON file of the run's output folder); a
//!   pointer to an array of numbers takes `@AGG` (below): `RUN:/a/list@max`;
//! - `RUN:FILE.csv#COLUMN@AGG`, a column of a CSV file of the run's output folder reduced
//!   by AGG; `RUN:FILE.csv?KEY=VALUE#COLUMN@AGG` first keeps the rows whose column KEY
//!   reads VALUE (text, or the same number), several filters joined by `&`.
//!
//! AGG: `min`, `max`, `mean`, `first`, `last`, `range` (max - min), `count` (rows), or an
//! index `N`; for CSV columns also `at:X=V` (the column linearly interpolated where column
//! X, in file order, first reaches V), `argmin:Y` and `argmax:Y` (the column in the row
//! where column Y is smallest / largest), `before_jump:Y` and `after_jump:Y` (the column in
//! the rows on either side of the largest change of column Y between neighbouring rows),
//! `mean_over:X` (the mean of the column over column X by the trapezoidal rule: a time
//! mean of unevenly spaced samples).
//! A COLUMN with one `*` stands for every column it matches, each reduced by AGG, the
//! results by a second aggregate: `#tooth*_um@max@mean` is the mean of the teeth's maxima.

use serde_json::Value;
use std::collections::HashMap;
use std::path::Path;

/// Where each run's outputs are: run name -> output folder.
pub type Runs<'a> = &'a HashMap<String, std::path::PathBuf>;

/// The value of `expr`, or what is wrong with it.
pub fn evaluate(expr: &str, runs: Runs) -> Result<f64, String> {
    let toks = tokens(expr)?;
    let mut p = Parser {
        toks: &toks,
        at: 0,
        runs,
    };
    let v = p.sum()?;
    if p.at != toks.len() {
        return Err(format!("`{expr}`: unexpected `{}`", toks[p.at]));
    }
    Ok(v)
}

/// Operators and parentheses are tokens of their own; anything else runs to the next space,
/// parenthesis or comma (so `/` and `-` inside an operand's path belong to it, and an
/// operator after an operand needs a space before it).
fn tokens(expr: &str) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    let c: Vec<char> = expr.chars().collect();
    let mut i = 0;
    while i < c.len() {
        let ch = c[i];
        if ch.is_whitespace() {
            i += 1;
        } else if "+-*/(),".contains(ch) {
            out.push(ch.to_string());
            i += 1;
        } else {
            let start = i;
            while i < c.len() && !c[i].is_whitespace() && !"(),".contains(c[i]) {
                i += 1;
            }
            out.push(c[start..i].iter().collect());
        }
    }
    if out.is_empty() {
        return Err("an empty expression".into());
    }
    Ok(out)
}

struct Parser<'a> {
    toks: &'a [String],
    at: usize,
    runs: Runs<'a>,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&str> {
        self.toks.get(self.at).map(String::as_str)
    }

    fn sum(&mut self) -> Result<f64, String> {
        let mut v = self.product()?;
        while let Some(op) = self.peek().filter(|t| *t == "+" || *t == "-") {
            let plus = op == "+";
            self.at += 1;
            let r = self.product()?;
            v = if plus { v + r } else { v - r };
        }
        Ok(v)
    }

    fn product(&mut self) -> Result<f64, String> {
        let mut v = self.unary()?;
        while let Some(op) = self.peek().filter(|t| *t == "*" || *t == "/") {
            let times = op == "*";
            self.at += 1;
            let r = self.unary()?;
            v = if times { v * r } else { v / r };
        }
        Ok(v)
    }

    fn unary(&mut self) -> Result<f64, String> {
        if self.peek() == Some("-") {
            self.at += 1;
            return Ok(-self.unary()?);
        }
        self.atom()
    }

    fn expect(&mut self, t: &str) -> Result<(), String> {
        if self.peek() == Some(t) {
            self.at += 1;
            Ok(())
        } else {
            Err(format!("expected `{t}`"))
        }
    }

    fn atom(&mut self) -> Result<f64, String> {
        let t = self
            .peek()
            .ok_or("the expression ends too soon")?
            .to_string();
        self.at += 1;
        if t == "(" {
            let v = self.sum()?;
            self.expect(")")?;
            return Ok(v);
        }
        if matches!(t.as_str(), "min" | "max" | "abs" | "sqrt") && self.peek() == Some("(") {
            self.at += 1;
            let mut args = vec![self.sum()?];
            while self.peek() == Some(",") {
                self.at += 1;
                args.push(self.sum()?);
            }
            self.expect(")")?;
            return Ok(match t.as_str() {
                "abs" => args[0].abs(),
                "sqrt" => args[0].sqrt(),
                "min" => args.iter().copied().fold(f64::INFINITY, f64::min),
                _ => args.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            });
        }
        if let Ok(x) = t.parse::<f64>() {
            return Ok(x);
        }
        operand(&t, self.runs)
    }
}

/// The value an operand names.
fn operand(t: &str, runs: Runs) -> Result<f64, String> {
    let (run, path) = t.split_once(':').ok_or_else(|| {
        format!("`{t}` is not RUN:/pointer, RUN:FILE.json#/pointer or RUN:FILE.csv#COLUMN@AGG")
    })?;
    let dir = runs
        .get(run)
        .ok_or_else(|| format!("`{t}`: no run named `{run}` (gw-run)"))?;
    let (file, rest) = match path.split_once('#') {
        Some((file, rest)) => (file, rest),
        None => ("summary.json", path),
    };
    let (file, filters) = file.split_once('?').unwrap_or((file, ""));
    if file.ends_with(".json") {
        if !filters.is_empty() {
            return Err(format!("`{t}`: row filters apply to CSV files"));
        }
        return json_value(&dir.join(file), rest).map_err(|e| format!("`{t}`: {e}"));
    }
    let (column, agg) = rest
        .split_once('@')
        .ok_or_else(|| format!("`{t}`: a CSV operand needs @AGG"))?;
    csv_column(&dir.join(file), filters, column, agg).map_err(|e| format!("`{t}`: {e}"))
}

/// The number (or the aggregate `@AGG` of the array of numbers) at a pointer of a JSON file.
fn json_value(file: &Path, pointer: &str) -> Result<f64, String> {
    let (pointer, agg) = match pointer.rsplit_once('@') {
        Some((p, a)) => (p, Some(a)),
        None => (pointer, None),
    };
    let doc = read_json(file)?;
    let v = doc
        .pointer(pointer)
        .ok_or_else(|| format!("no key {pointer} in {}", file.display()))?;
    let number = |v: &Value| v.as_f64().ok_or_else(|| format!("{v} is not a number"));
    match (agg, v.as_array()) {
        (None, _) => number(v),
        (Some(agg), Some(items)) => {
            let xs = items.iter().map(number).collect::<Result<Vec<_>, _>>()?;
            reduce(&xs, agg)
        }
        (Some(_), None) => Err(format!("@AGG needs an array; {pointer} is {v}")),
    }
}

fn read_json(p: &Path) -> Result<Value, String> {
    let text = std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", p.display()))
}

/// A CSV file as its header and rows of text.
struct Table {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl Table {
    fn read(file: &Path) -> Result<Table, String> {
        let mut r = csv::Reader::from_path(file).map_err(|e| format!("{}: {e}", file.display()))?;
        let header = r.headers().map_err(|e| e.to_string())?;
        let header = header.iter().map(String::from).collect();
        let mut rows = Vec::new();
        for rec in r.records() {
            let rec = rec.map_err(|e| e.to_string())?;
            rows.push(rec.iter().map(String::from).collect());
        }
        Ok(Table { header, rows })
    }

    fn index(&self, column: &str) -> Result<usize, String> {
        self.header
            .iter()
            .position(|h| h == column)
            .ok_or_else(|| format!("no column `{column}`"))
    }

    /// Keeps the rows where every `KEY=VALUE` of `filters` (joined by `&`) holds.
    fn filter(&mut self, filters: &str) -> Result<(), String> {
        for f in filters.split('&').filter(|f| !f.is_empty()) {
            let (key, want) = f
                .split_once('=')
                .ok_or_else(|| format!("a row filter is KEY=VALUE, not `{f}`"))?;
            let k = self.index(key)?;
            let same = |cell: &str| {
                cell == want
                    || matches!((cell.parse::<f64>(), want.parse::<f64>()), (Ok(a), Ok(b)) if a == b)
            };
            self.rows.retain(|r| r.get(k).is_some_and(|c| same(c)));
        }
        if self.rows.is_empty() {
            return Err(format!("no rows match `{filters}`"));
        }
        Ok(())
    }

    fn numbers(&self, column: &str) -> Result<Vec<f64>, String> {
        let k = self.index(column)?;
        self.rows
            .iter()
            .map(|r| {
                let cell = r.get(k).map_or("", String::as_str);
                cell.parse::<f64>()
                    .map_err(|_| format!("`{cell}` in column `{column}` is not a number"))
            })
            .collect()
    }
}

fn csv_column(file: &Path, filters: &str, column: &str, agg: &str) -> Result<f64, String> {
    let mut table = Table::read(file).map_err(|e| format!("{}: {e}", file.display()))?;
    table
        .filter(filters)
        .map_err(|e| format!("{}: {e}", file.display()))?;
    let at_file = |e: String| format!("{}: {e}", file.display());
    let Some((head, tail)) = column.split_once('*') else {
        return column_value(&table, column, agg).map_err(at_file);
    };
    let (agg, across) = agg
        .rsplit_once('@')
        .ok_or_else(|| at_file(format!("`{column}` needs a second @AGG across its columns")))?;
    let matching: Vec<&String> = table
        .header
        .iter()
        .filter(|h| h.len() >= head.len() + tail.len() && h.starts_with(head) && h.ends_with(tail))
        .collect();
    let values = matching
        .iter()
        .map(|c| column_value(&table, c, agg))
        .collect::<Result<Vec<_>, _>>()
        .map_err(at_file)?;
    reduce(&values, across).map_err(|e| at_file(format!("`{column}`: {e}")))
}

/// One column of a table reduced by AGG.
fn column_value(table: &Table, column: &str, agg: &str) -> Result<f64, String> {
    let xs = table.numbers(column)?;
    let row_of = |ys: &[f64], pick: fn(f64, f64) -> bool| {
        (1..ys.len()).fold(0, |best, i| if pick(ys[i], ys[best]) { i } else { best })
    };
    if let Some((x_col, v)) = agg.strip_prefix("at:").and_then(|a| a.split_once('=')) {
        let v: f64 = v.parse().map_err(|_| format!("`{v}` is not a number"))?;
        return interpolate(&table.numbers(x_col)?, &xs, v)
            .ok_or_else(|| format!("column `{x_col}` never reaches {v}"));
    }
    if let Some(x_col) = agg.strip_prefix("mean_over:") {
        let x = table.numbers(x_col)?;
        let span = x.last().zip(x.first()).map_or(0.0, |(l, f)| l - f);
        if span == 0.0 {
            return Err(format!("column `{x_col}` spans nothing"));
        }
        let area: f64 = (1..x.len())
            .map(|i| (x[i] - x[i - 1]) * (xs[i] + xs[i - 1]) / 2.0)
            .sum();
        return Ok(area / span);
    }
    if let Some(y) = agg.strip_prefix("argmin:") {
        return Ok(xs[row_of(&table.numbers(y)?, |a, b| a < b)]);
    }
    if let Some(y) = agg.strip_prefix("argmax:") {
        return Ok(xs[row_of(&table.numbers(y)?, |a, b| a > b)]);
    }
    for (prefix, after) in [("before_jump:", 0), ("after_jump:", 1)] {
        if let Some(y) = agg.strip_prefix(prefix) {
            let ys = table.numbers(y)?;
            let steps: Vec<f64> = ys.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
            if steps.is_empty() {
                return Err("a jump needs two rows".into());
            }
            return Ok(xs[row_of(&steps, |a, b| a > b) + after]);
        }
    }
    reduce(&xs, agg)
}

/// `ys` linearly interpolated where `xs` first reaches `v` (between neighbouring rows).
fn interpolate(xs: &[f64], ys: &[f64], v: f64) -> Option<f64> {
    (0..xs.len()).find_map(|i| {
        if xs[i] == v {
            return Some(ys[i]);
        }
        let j = i + 1;
        let between = j < xs.len() && (xs[i] - v) * (xs[j] - v) < 0.0;
        between.then(|| ys[i] + (ys[j] - ys[i]) * (v - xs[i]) / (xs[j] - xs[i]))
    })
}

/// A list of numbers reduced by AGG.
fn reduce(xs: &[f64], agg: &str) -> Result<f64, String> {
    if xs.is_empty() {
        return Err("no values".into());
    }
    let (lo, hi) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    Ok(match agg {
        "min" => lo,
        "max" => hi,
        "range" => hi - lo,
        "mean" => xs.iter().sum::<f64>() / xs.len() as f64,
        "first" => xs[0],
        "last" => xs[xs.len() - 1],
        "count" => xs.len() as f64,
        n => {
            let i: usize = n.parse().map_err(|_| format!("unknown aggregate `{n}`"))?;
            *xs.get(i)
                .ok_or_else(|| format!("row {i} is past the end ({} values)", xs.len()))?
        }
    })
}
