//! Generated numbers and figures of the documentation: the marks, the runs behind them, the
//! formats, and the check or the rewrite of a Markdown file.
//!
//! Marks (HTML comments, invisible where the Markdown is rendered):
//! - `<!-- gw-run NAME: ARGS -->`: the run NAME is `gearwear ARGS --out DIR --quiet`;
//! - `<!-- gw:EXPR|FMT -->TEXT<!-- /gw -->`: TEXT is EXPR (see `expr`) formatted by FMT;
//! - `<!-- gw-img RUN:FILE -->` before an image `![..](PATH)` on the same or the next
//!   line: the image is the file FILE of the run's output folder, byte for byte.
//!
//! Formats: `.Nf` (N decimals), `+.Nf` (with its sign), `Ng` (N significant digits, plain),
//! `Ne` (N significant digits, exponent form: `4.00e8`), `int` (a whole number), `sep` (a
//! whole number with a space between thousands: `3 512`), `pct.N` (a ratio shown as a
//! percentage with its sign and N decimals: 0.2164 -> `+21.6`).

pub mod expr;

use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};

/// A run a document asks for: its name and its arguments.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSpec {
    pub name: String,
    pub args: Vec<String>,
}

/// What one Markdown file holds: its runs, and its marks with their byte spans.
#[derive(Debug, Default)]
pub struct Marks {
    pub runs: Vec<RunSpec>,
    /// (line, expression, format, span of the text between the marks).
    pub numbers: Vec<(usize, String, String, std::ops::Range<usize>)>,
    /// (line, RUN:FILE, image path relative to the Markdown file).
    pub images: Vec<(usize, String, String)>,
}

fn line_of(text: &str, at: usize) -> usize {
    text[..at].matches('\n').count() + 1
}

/// The marks of a Markdown text.
pub fn parse(text: &str) -> Result<Marks, String> {
    let mut m = Marks::default();
    let mut at = 0;
    while let Some(k) = text[at..].find("<!-- gw") {
        let start = at + k;
        let end = start
            + text[start..]
                .find("-->")
                .ok_or_else(|| format!("line {}: a gw mark without -->", line_of(text, start)))?;
        let body = text[start + 4..end].trim();
        let line = line_of(text, start);
        at = end + 3;
        if let Some(rest) = body.strip_prefix("gw-run ") {
            let (name, args) = rest
                .split_once(':')
                .ok_or_else(|| format!("line {line}: gw-run NAME: ARGS"))?;
            m.runs.push(RunSpec {
                name: name.trim().into(),
                args: args.split_whitespace().map(String::from).collect(),
            });
        } else if let Some(rest) = body.strip_prefix("gw-img ") {
            let after = &text[at..];
            let img = after
                .find("](")
                .filter(|&i| after[..i].matches('\n').count() <= 1);
            let i = img.ok_or_else(|| {
                format!("line {line}: gw-img must precede an image on the same or the next line")
            })?;
            let close = after[i..]
                .find(')')
                .ok_or_else(|| format!("line {line}: an image without )"))?;
            m.images.push((
                line,
                rest.trim().into(),
                after[i + 2..i + close].trim().into(),
            ));
        } else if let Some(rest) = body.strip_prefix("gw:") {
            let (expr, fmt) = rest
                .rsplit_once('|')
                .ok_or_else(|| format!("line {line}: gw:EXPR|FMT"))?;
            let close = text[at..]
                .find("<!-- /gw -->")
                .ok_or_else(|| format!("line {line}: a gw number without <!-- /gw -->"))?;
            m.numbers
                .push((line, expr.trim().into(), fmt.trim().into(), at..at + close));
            at += close + "<!-- /gw -->".len();
        } else {
            return Err(format!(
                "line {line}: unknown mark `{}`",
                body.chars().take(30).collect::<String>()
            ));
        }
    }
    Ok(m)
}

/// `x` written in format `fmt`.
pub fn format(x: f64, fmt: &str) -> Result<String, String> {
    if !x.is_finite() {
        return Err(format!("{x} is not a finite number"));
    }
    let digits = |s: &str| {
        s.parse::<usize>()
            .map_err(|_| format!("unknown format `{fmt}`"))
    };
    if let Some(n) = fmt.strip_prefix("+.").and_then(|f| f.strip_suffix('f')) {
        return Ok(format!("{:+.*}", digits(n)?, x));
    }
    if let Some(n) = fmt.strip_prefix('.').and_then(|f| f.strip_suffix('f')) {
        return Ok(format!("{:.*}", digits(n)?, x));
    }
    if let Some(n) = fmt.strip_prefix("pct.") {
        return Ok(format!("{:+.*}", digits(n)?, 100.0 * x));
    }
    if let Some(n) = fmt.strip_suffix('e') {
        let n = digits(n)?.max(1);
        return Ok(format!("{:.*e}", n - 1, x));
    }
    if let Some(n) = fmt.strip_suffix('g') {
        return Ok(significant(x, digits(n)?.max(1)));
    }
    match fmt {
        "int" => Ok(format!("{:.0}", x)),
        "sep" => Ok(thousands(&format!("{:.0}", x))),
        _ => Err(format!("unknown format `{fmt}`")),
    }
}

/// `n` significant digits in plain notation: the rounding of the exponent form decides the
/// decimals, so 9.996 to 3 digits is `10.0`.
fn significant(x: f64, n: usize) -> String {
    let e_form = format!("{:.*e}", n - 1, x);
    let exp: i32 = e_form
        .split('e')
        .nth(1)
        .and_then(|e| e.parse().ok())
        .unwrap_or(0);
    let decimals = (n as i32 - 1 - exp).max(0) as usize;
    if decimals > 0 {
        return format!("{:.*}", decimals, x);
    }
    let rounded: f64 = e_form.parse().unwrap_or(x);
    format!("{rounded:.0}")
}

fn thousands(int: &str) -> String {
    let (sign, digits) = int.strip_prefix('-').map_or(("", int), |d| ("-", d));
    let mut out = String::new();
    for (i, ch) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(' ');
        }
        out.push(ch);
    }
    format!("{sign}{out}")
}

/// The problems of one file against the runs' outputs, and the file as it should read.
pub fn check_text(
    name: &str,
    text: &str,
    marks: &Marks,
    outputs: expr::Runs,
    doc_dir: &Path,
) -> (Vec<String>, String) {
    let mut problems = Vec::new();
    let mut fixed = text.to_string();
    // Replace from the end so that earlier spans stay valid.
    for (line, e, fmt, span) in marks.numbers.iter().rev() {
        match expr::evaluate(e, outputs).and_then(|v| format(v, fmt)) {
            Ok(want) if want == text[span.clone()] => {}
            Ok(want) => {
                problems.push(format!(
                    "{name}:{line}: `{e}` formatted `{fmt}` gives {want}; the text says {}",
                    &text[span.clone()]
                ));
                fixed.replace_range(span.clone(), &want);
            }
            Err(err) => problems.push(format!("{name}:{line}: {err}")),
        }
    }
    for (line, source, image) in &marks.images {
        let Some((run, file)) = source.split_once(':') else {
            problems.push(format!("{name}:{line}: gw-img RUN:FILE"));
            continue;
        };
        let Some(dir) = outputs.get(run) else {
            problems.push(format!("{name}:{line}: no run named `{run}`"));
            continue;
        };
        let made = std::fs::read(dir.join(file));
        let have = std::fs::read(doc_dir.join(image));
        match made {
            Err(e) => problems.push(format!(
                "{name}:{line}: the run `{run}` wrote no {file}: {e}"
            )),
            Ok(bytes) if have.as_ref().ok() != Some(&bytes) => problems.push(format!(
                "{name}:{line}: {image} is not the figure {file} of the run `{run}`"
            )),
            Ok(_) => {}
        }
    }
    problems.reverse();
    (problems, fixed)
}

/// Every run the documents ask for, once (a name used twice must mean the same run).
pub fn all_runs(docs: &BTreeMap<PathBuf, Marks>) -> Result<Vec<RunSpec>, String> {
    let mut runs: Vec<RunSpec> = Vec::new();
    for (file, m) in docs {
        for r in &m.runs {
            match runs.iter().find(|x| x.name == r.name) {
                Some(x) if x.args != r.args => {
                    return Err(format!(
                        "{}: the run `{}` is defined twice with different arguments",
                        file.display(),
                        r.name
                    ))
                }
                Some(_) => {}
                None => runs.push(r.clone()),
            }
        }
    }
    Ok(runs)
}

/// Runs `gearwear` for every run into `work/NAME`, at most one per core at a time.
pub fn execute(
    bin: &Path,
    runs: &[RunSpec],
    work: &Path,
    root: &Path,
) -> Result<HashMap<String, PathBuf>, String> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut out = HashMap::new();
    for chunk in runs.chunks(cores) {
        let handles: Vec<_> = chunk
            .iter()
            .map(|r| {
                let dir = work.join(&r.name);
                let child = std::process::Command::new(bin)
                    .args(&r.args)
                    .arg("--out")
                    .arg(&dir)
                    .arg("--quiet")
                    .current_dir(root)
                    .env("RAYON_NUM_THREADS", "1")
                    .stdout(std::process::Stdio::null())
                    .stderr(std::process::Stdio::piped())
                    .spawn();
                (r, dir, child)
            })
            .collect();
        for (r, dir, child) in handles {
            let o = child
                .and_then(|c| c.wait_with_output())
                .map_err(|e| format!("run `{}`: {e}", r.name))?;
            if !o.status.success() {
                return Err(format!(
                    "run `{}` (gearwear {}) failed: {}",
                    r.name,
                    r.args.join(" "),
                    String::from_utf8_lossy(&o.stderr)
                ));
            }
            out.insert(r.name.clone(), dir);
        }
    }
    Ok(out)
}
