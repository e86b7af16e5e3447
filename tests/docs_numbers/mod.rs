//! Generated numbers and figures of the documentation: the marks, the runs behind them, the
//! formats, and the check or the rewrite of a Markdown file.
//!
//! Marks (HTML comments, invisible where the Markdown is rendered):
//! - `<!-- gw-run NAME: ARGS -->`: the run NAME is `gearwear ARGS --out DIR --quiet`, or,
//!   when ARGS start with a script of the project (`scripts/NAME.sh`), `bash ARGS --out DIR
//!   --quiet` with the binary in the environment (`GEARWEAR_BIN`): for a study that needs
//!   more than one command, such as the prognostics example's observations;
//! - `<!-- gw:EXPR|FMT -->TEXT<!-- /gw -->`: TEXT is EXPR (see `expr`) formatted by FMT;
//! - `<!-- gw-img RUN:FILE -->` before an image `![..](PATH)` on the same or the next
//!   line: the image is the file FILE of the run's output folder, byte for byte;
//! - `<!-- gw-file PATH -->` on the line before a fenced code block: the block shows the
//!   file PATH (relative to the repository root, as the runs' arguments are), line for
//!   line, so an input a run reads and the page that prints it cannot part.
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
    /// (line, file path relative to the repository root, span of the code block's body).
    pub files: Vec<(usize, String, std::ops::Range<usize>)>,
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
        } else if let Some(rest) = body.strip_prefix("gw-file ") {
            let span = fenced_body(text, at)
                .ok_or_else(|| format!("line {line}: gw-file must precede a fenced code block"))?;
            m.files.push((line, rest.trim().into(), span.clone()));
            at = span.end;
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

/// The body of the fenced code block that opens on the line after `at` (from the line
/// after its opening fence to the start of its closing fence).
fn fenced_body(text: &str, at: usize) -> Option<std::ops::Range<usize>> {
    let next = at + text[at..].find('\n')? + 1;
    let fence_end = next + text[next..].find('\n')? + 1;
    if !text[next..fence_end].trim_start().starts_with("```") {
        return None;
    }
    let mut line = fence_end;
    while line < text.len() {
        if text[line..].trim_start().starts_with("```") {
            return Some(fence_end..line);
        }
        line += text[line..].find('\n')? + 1;
    }
    None
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

/// The problems of one file against the runs' outputs (in order of lines), and the file as
/// it should read.
pub fn check_text(
    name: &str,
    text: &str,
    marks: &Marks,
    outputs: expr::Runs,
    doc_dir: &Path,
    root: &Path,
) -> (Vec<String>, String) {
    let mut problems: Vec<(usize, String)> = Vec::new();
    // (span, text it should hold); applied from the end so that earlier spans stay valid
    // (a number's marks inside a code block would show as text, so spans never overlap).
    let mut edits: Vec<(std::ops::Range<usize>, String)> = Vec::new();
    for (line, path, span) in &marks.files {
        match std::fs::read_to_string(root.join(path)) {
            Ok(want) if want == text[span.clone()] => {}
            Ok(want) => {
                problems.push((*line, format!("the code block is not the file {path}")));
                edits.push((span.clone(), want));
            }
            Err(e) => problems.push((*line, format!("{path}: {e}"))),
        }
    }
    for (line, e, fmt, span) in &marks.numbers {
        match expr::evaluate(e, outputs).and_then(|v| format(v, fmt)) {
            Ok(want) if want == text[span.clone()] => {}
            Ok(want) => {
                problems.push((
                    *line,
                    format!(
                        "`{e}` formatted `{fmt}` gives {want}; the text says {}",
                        &text[span.clone()]
                    ),
                ));
                edits.push((span.clone(), want));
            }
            Err(err) => problems.push((*line, err)),
        }
    }
    let mut fixed = text.to_string();
    edits.sort_by_key(|(span, _)| span.start);
    for (span, want) in edits.into_iter().rev() {
        fixed.replace_range(span, &want);
    }
    for (line, source, image) in &marks.images {
        let Some((run, file)) = source.split_once(':') else {
            problems.push((*line, "gw-img RUN:FILE".into()));
            continue;
        };
        let Some(dir) = outputs.get(run) else {
            problems.push((*line, format!("no run named `{run}`")));
            continue;
        };
        let made = std::fs::read(dir.join(file));
        let have = std::fs::read(doc_dir.join(image));
        match made {
            Err(e) => problems.push((*line, format!("the run `{run}` wrote no {file}: {e}"))),
            Ok(bytes) if have.as_ref().ok() != Some(&bytes) => problems.push((
                *line,
                format!("{image} is not the figure {file} of the run `{run}`"),
            )),
            Ok(_) => {}
        }
    }
    problems.sort_by_key(|(line, _)| *line);
    let problems = problems
        .into_iter()
        .map(|(line, p)| format!("{name}:{line}: {p}"))
        .collect();
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

/// Runs `gearwear` for every run into `work/NAME`, at most one per core at a time (the
/// next starts as soon as one ends; the longest are best listed first).
pub fn execute(
    bin: &Path,
    runs: &[RunSpec],
    work: &Path,
    root: &Path,
) -> Result<HashMap<String, PathBuf>, String> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let queue = std::sync::Mutex::new(runs.iter());
    let results = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..cores.min(runs.len()) {
            s.spawn(|| loop {
                let Some(r) = queue.lock().unwrap().next() else {
                    break;
                };
                let done = run_one(bin, r, work, root);
                let failed = done.is_err();
                results.lock().unwrap().push(done);
                if failed {
                    break;
                }
            });
        }
    });
    let mut out = HashMap::new();
    for done in results.into_inner().unwrap() {
        let (name, dir) = done?;
        out.insert(name, dir);
    }
    Ok(out)
}

/// One run: `gearwear ARGS --out work/NAME --quiet` (or `bash SCRIPT ...`) in the repository
/// root, one thread.
fn run_one(bin: &Path, r: &RunSpec, work: &Path, root: &Path) -> Result<(String, PathBuf), String> {
    let dir = work.join(&r.name);
    let script = r
        .args
        .first()
        .is_some_and(|a| a.starts_with("scripts/") && a.ends_with(".sh"));
    let mut command = if script {
        std::process::Command::new("bash")
    } else {
        std::process::Command::new(bin)
    };
    let o = command
        .args(&r.args)
        .arg("--out")
        .arg(&dir)
        .arg("--quiet")
        .current_dir(root)
        .env("RAYON_NUM_THREADS", "1")
        .env("GEARWEAR_BIN", bin)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .output()
        .map_err(|e| format!("run `{}`: {e}", r.name))?;
    if !o.status.success() {
        return Err(format!(
            "run `{}` ({}{}) failed: {}",
            r.name,
            if script { "bash " } else { "gearwear " },
            r.args.join(" "),
            String::from_utf8_lossy(&o.stderr)
        ));
    }
    Ok((r.name.clone(), dir))
}
