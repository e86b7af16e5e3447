//! The expressions of generated numbers: operands that read a run's output, numbers, the
//! four operations, parentheses and `min`, `max`, `abs`.
//!
//! An operand is `RUN:/json/pointer` (RFC 6901, into the run's `summary.json`) or
//! `RUN:FILE.csv#COLUMN@AGG`, a column of a CSV file of the run's output folder reduced by
//! AGG: `min`, `max`, `mean`, `first`, `last`, `range` (max - min) or an index `N`.

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
        if matches!(t.as_str(), "min" | "max" | "abs") && self.peek() == Some("(") {
            self.at += 1;
            let mut args = vec![self.sum()?];
            while self.peek() == Some(",") {
                self.at += 1;
                args.push(self.sum()?);
            }
            self.expect(")")?;
            return Ok(match t.as_str() {
                "abs" => args[0].abs(),
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
    let (run, path) = t
        .split_once(':')
        .ok_or_else(|| format!("`{t}` is not RUN:/pointer or RUN:FILE.csv#COLUMN@AGG"))?;
    let dir = runs
        .get(run)
        .ok_or_else(|| format!("`{t}`: no run named `{run}` (gw-run)"))?;
    if let Some((file, rest)) = path.split_once('#') {
        let (column, agg) = rest
            .split_once('@')
            .ok_or_else(|| format!("`{t}`: a CSV operand needs @AGG"))?;
        return csv_column(&dir.join(file), column, agg).map_err(|e| format!("`{t}`: {e}"));
    }
    let summary = read_json(&dir.join("summary.json"))?;
    let v = summary
        .pointer(path)
        .ok_or_else(|| format!("`{t}`: no such key in {}/summary.json", dir.display()))?;
    v.as_f64()
        .ok_or_else(|| format!("`{t}`: {v} is not a number"))
}

fn read_json(p: &Path) -> Result<Value, String> {
    let text = std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", p.display()))
}

fn csv_column(file: &Path, column: &str, agg: &str) -> Result<f64, String> {
    let mut r = csv::Reader::from_path(file).map_err(|e| format!("{}: {e}", file.display()))?;
    let header = r.headers().map_err(|e| e.to_string())?.clone();
    let k = header
        .iter()
        .position(|h| h == column)
        .ok_or_else(|| format!("{} has no column `{column}`", file.display()))?;
    let mut xs = Vec::new();
    for rec in r.records() {
        let rec = rec.map_err(|e| e.to_string())?;
        let cell = rec.get(k).unwrap_or("");
        xs.push(
            cell.parse::<f64>()
                .map_err(|_| format!("`{cell}` in column `{column}` is not a number"))?,
        );
    }
    if xs.is_empty() {
        return Err(format!("{} has no rows", file.display()));
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
        n => {
            let i: usize = n.parse().map_err(|_| format!("unknown aggregate `{n}`"))?;
            *xs.get(i)
                .ok_or_else(|| format!("row {i} is past the end ({} rows)", xs.len()))?
        }
    })
}
