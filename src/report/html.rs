//! The self-contained HTML report of `gearwear run` (issue 5). Pure: data in, one HTML
//! string out. Self-contained means no network and no side files needed to view it:
//! figures are PNG (or, when only SVG was asked, SVG) data URIs (base64), the CSS is
//! inline, there is no script, and a Content-Security-Policy forbids any other resource,
//! so a stray external URL cannot load. An SVG shown through `<img>` runs no script and
//! loads nothing (HTML's image rules), so the policy holds for it too.
//! The only links are relative hrefs to the CSV files written beside the report.

use base64::{engine::general_purpose::STANDARD, Engine as _};
use std::fmt::Write as _;

/// The first eight bytes of every PNG file (PNG specification, section 5.2).
pub const PNG_SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', 0x0D, 0x0A, 0x1A, 0x0A];

/// The whole report.
#[derive(Debug, Clone, Default)]
pub struct Report {
    /// Plain text; page title and top heading.
    pub title: String,
    /// Trusted HTML of our own making, inserted verbatim after the title. Never put user
    /// text here unescaped (use [`escape`]).
    pub intro_html: String,
    /// The numbered sections, in order.
    pub sections: Vec<Section>,
    /// Plain text run metadata (program version, case hash, ...); line breaks are kept.
    /// Empty = no footer.
    pub footer: String,
}

/// One numbered section: heading, then paragraphs, figures and tables in that order.
#[derive(Debug, Clone, Default)]
pub struct Section {
    /// Plain text.
    pub heading: String,
    /// Plain text, one `<p>` each.
    pub paragraphs: Vec<String>,
    /// Figures, after the paragraphs.
    pub figures: Vec<FigureBlock>,
    /// Tables, after the figures.
    pub tables: Vec<TableBlock>,
}

/// A figure embedded as a PNG (or SVG) data URI.
#[derive(Debug, Clone, Default)]
pub struct FigureBlock {
    /// Plain text.
    pub caption: String,
    /// PNG file bytes (e.g. from `plot::render_png`). Bytes without the PNG signature are
    /// shown as a "figure unavailable" note instead of a broken image.
    pub png: Vec<u8>,
    /// An SVG document (e.g. from `plot::render_svg`), embedded instead of `png` when
    /// given: the figure of a job that writes SVG only.
    pub svg: Option<String>,
    /// File name of the figure's data, relative to the report's directory (e.g.
    /// `"csv/fig5.csv"`); linked from the caption.
    pub csv_name: Option<String>,
}

/// A table of plain-text cells. Rows shorter than the widest row are padded with empty cells.
#[derive(Debug, Clone, Default)]
pub struct TableBlock {
    /// Plain text.
    pub caption: String,
    /// Column headings (plain text).
    pub header: Vec<String>,
    /// Rows of plain-text cells.
    pub rows: Vec<Vec<String>>,
    /// Zero-based column shown emphasised (e.g. the relative deviation of a comparison).
    pub highlight_col: Option<usize>,
}

/// One line of a comparison of our result with the paper's published value.
#[derive(Debug, Clone, Default)]
pub struct ComparisonRow {
    /// Plain text, with the display unit, e.g. "max. wear depth, pinion (um)".
    pub quantity: String,
    /// Our value, in the unit named in `quantity`.
    pub ours: f64,
    /// The paper's value, same unit.
    pub paper: f64,
    /// Plain text: why the two differ, or where the paper's value comes from.
    pub explanation: String,
}

/// Header of a comparison table; the deviation column (index 3) is highlighted.
pub const COMPARISON_HEADER: [&str; 5] = [
    "quantity",
    "ours",
    "paper",
    "relative deviation",
    "explanation",
];

/// A comparison table: quantity | ours | paper | relative deviation | explanation, with the
/// deviation `(ours - paper) / |paper|` in percent, highlighted.
pub fn comparison_table(caption: &str, rows: &[ComparisonRow]) -> TableBlock {
    TableBlock {
        caption: caption.to_string(),
        header: COMPARISON_HEADER.iter().map(|s| s.to_string()).collect(),
        rows: rows
            .iter()
            .map(|r| {
                vec![
                    r.quantity.clone(),
                    format_value(r.ours),
                    format_value(r.paper),
                    format_deviation(r.ours, r.paper),
                    r.explanation.clone(),
                ]
            })
            .collect(),
        highlight_col: Some(3),
    }
}

/// `(ours - paper) / |paper|` as a signed percentage for a person ("+10 %", "-12.9 %"); "n/a"
/// when the paper's value is zero or either value is not finite (no meaningful ratio).
pub fn format_deviation(ours: f64, paper: f64) -> String {
    if !ours.is_finite() || !paper.is_finite() || paper == 0.0 {
        return "n/a".to_string();
    }
    crate::format::shown_signed_percent((ours - paper) / paper.abs())
}

/// A number for a person: the project's one rule (`format::shown`).
pub use crate::format::shown as format_value;

/// Escape text for HTML content and quoted attribute values (& < > " ').
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// Render the report as one HTML5 document.
pub fn render(report: &Report) -> String {
    let mut h = String::with_capacity(4096 + png_bytes(report) * 4 / 3);
    let title = escape(&report.title);
    // `write!` into a String cannot fail; the results are ignored on purpose.
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta http-equiv=\"Content-Security-Policy\" content=\"{CSP}\">\n\
         <meta name=\"generator\" content=\"gearwear {}\">\n\
         <title>{title}</title>\n<style>{CSS}</style>\n</head>\n<body>\n<main>\n\
         <h1>{title}</h1>\n",
        env!("CARGO_PKG_VERSION")
    );
    if !report.intro_html.is_empty() {
        let _ = writeln!(h, "<div class=\"intro\">\n{}\n</div>", report.intro_html);
    }
    if report.sections.len() > 1 {
        contents(&mut h, &report.sections);
    }
    let mut counters = Counters::default();
    for (i, section) in report.sections.iter().enumerate() {
        write_section(&mut h, i + 1, section, &mut counters);
    }
    h.push_str("</main>\n");
    if !report.footer.is_empty() {
        let _ = writeln!(h, "<footer>{}</footer>", escape(&report.footer));
    }
    h.push_str("</body>\n</html>\n");
    h
}

/// Only inline styles and data-URI images; everything else (scripts, fonts, frames, fetches,
/// form targets) is refused by the browser.
const CSP: &str =
    "default-src 'none'; img-src data:; style-src 'unsafe-inline'; base-uri 'none'; form-action 'none'";

/// Sober print-like style: system fonts, ~1000 px column, bordered tables, full-width figures.
const CSS: &str = r#"
:root { color-scheme: light; }
body { margin: 0; padding: 0 1.25rem; background: #fff; color: #1b1b1b;
  font: 16px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial,
    "Noto Sans", "DejaVu Sans", sans-serif; }
main, footer { max-width: 1000px; margin: 0 auto; }
main { padding: 1.5rem 0 2rem; }
h1 { font-size: 1.75rem; line-height: 1.25; margin: 0 0 1rem; }
h2 { font-size: 1.3rem; margin: 2.25rem 0 0.75rem; padding-bottom: 0.25rem;
  border-bottom: 1px solid #d0d0d0; }
p { margin: 0.6rem 0; }
a { color: #0b57a4; }
nav ol { margin: 0.5rem 0 1.5rem; padding-left: 1.5rem; }
figure { margin: 1.5rem 0; }
figure img { display: block; width: 100%; height: auto; border: 1px solid #e0e0e0; }
figcaption, caption { font-size: 0.92rem; color: #333; margin-top: 0.4rem; text-align: left; }
caption { caption-side: top; margin: 0 0 0.4rem; }
.label { font-weight: 600; }
.missing { padding: 2rem; border: 1px dashed #999; color: #666; text-align: center; }
.table-wrap { overflow-x: auto; margin: 1.5rem 0; }
table { border-collapse: collapse; width: 100%; font-size: 0.92rem; }
th, td { border: 1px solid #bdbdbd; padding: 0.3rem 0.55rem; vertical-align: top; }
th { background: #f2f2f2; text-align: left; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
th.hl, td.hl { background: #fff6d6; font-weight: 600; }
footer { border-top: 1px solid #d0d0d0; padding: 0.75rem 0 1.5rem;
  font-size: 0.85rem; color: #555; white-space: pre-wrap; }
@media print { figure, .table-wrap { break-inside: avoid; } }
"#;

/// Running figure and table numbers across the whole report.
#[derive(Default)]
struct Counters {
    figure: usize,
    table: usize,
}

fn png_bytes(report: &Report) -> usize {
    let figures = report.sections.iter().flat_map(|s| &s.figures);
    figures
        .map(|f| f.svg.as_ref().map_or(f.png.len(), String::len))
        .sum()
}

/// Anchor id of section `n` (1-based).
fn section_id(n: usize) -> String {
    format!("s{n}")
}

fn contents(h: &mut String, sections: &[Section]) {
    h.push_str("<nav>\n<ol>\n");
    for (i, s) in sections.iter().enumerate() {
        let id = section_id(i + 1);
        let _ = writeln!(h, "<li><a href=\"#{id}\">{}</a></li>", escape(&s.heading));
    }
    h.push_str("</ol>\n</nav>\n");
}

fn write_section(h: &mut String, n: usize, s: &Section, counters: &mut Counters) {
    let id = section_id(n);
    let _ = writeln!(h, "<section id=\"{id}\">");
    let _ = writeln!(h, "<h2>{n}. {}</h2>", escape(&s.heading));
    for p in &s.paragraphs {
        let _ = writeln!(h, "<p>{}</p>", escape(p));
    }
    for f in &s.figures {
        counters.figure += 1;
        write_figure(h, counters.figure, f);
    }
    for t in &s.tables {
        counters.table += 1;
        write_table(h, counters.table, t);
    }
    h.push_str("</section>\n");
}

fn write_figure(h: &mut String, n: usize, f: &FigureBlock) {
    let caption = escape(&f.caption);
    h.push_str("<figure>\n");
    if let Some(svg) = &f.svg {
        let _ = writeln!(
            h,
            "<img src=\"data:image/svg+xml;base64,{}\" alt=\"{caption}\">",
            STANDARD.encode(svg.as_bytes())
        );
    } else if f.png.starts_with(&PNG_SIGNATURE) {
        let _ = writeln!(
            h,
            "<img src=\"data:image/png;base64,{}\" alt=\"{caption}\">",
            STANDARD.encode(&f.png)
        );
    } else {
        h.push_str("<div class=\"missing\">figure unavailable (it could not be drawn)</div>\n");
    }
    let _ = write!(
        h,
        "<figcaption><span class=\"label\">Figure {n}.</span> {caption}"
    );
    if let Some(csv) = &f.csv_name {
        let _ = write!(h, " (<a href=\"{}\">data: CSV</a>)", relative_href(csv));
    }
    h.push_str("</figcaption>\n</figure>\n");
}

fn write_table(h: &mut String, n: usize, t: &TableBlock) {
    let cols = t
        .rows
        .iter()
        .map(Vec::len)
        .chain(std::iter::once(t.header.len()))
        .max()
        .unwrap_or(0);
    let class = |j: usize, numeric: bool| -> &'static str {
        match (t.highlight_col == Some(j), numeric) {
            (true, true) => " class=\"num hl\"",
            (true, false) => " class=\"hl\"",
            (false, true) => " class=\"num\"",
            (false, false) => "",
        }
    };
    h.push_str("<div class=\"table-wrap\">\n<table>\n");
    let _ = writeln!(
        h,
        "<caption><span class=\"label\">Table {n}.</span> {}</caption>",
        escape(&t.caption)
    );
    if !t.header.is_empty() {
        h.push_str("<thead>\n<tr>");
        for j in 0..cols {
            let cell = t.header.get(j).map_or("", String::as_str);
            let _ = write!(h, "<th{}>{}</th>", class(j, false), escape(cell));
        }
        h.push_str("</tr>\n</thead>\n");
    }
    h.push_str("<tbody>\n");
    for row in &t.rows {
        h.push_str("<tr>");
        for j in 0..cols {
            let cell = row.get(j).map_or("", String::as_str);
            let _ = write!(h, "<td{}>{}</td>", class(j, is_numeric(cell)), escape(cell));
        }
        h.push_str("</tr>\n");
    }
    h.push_str("</tbody>\n</table>\n</div>\n");
}

/// A cell that reads as one number, optionally with a trailing percent sign: right-aligned.
fn is_numeric(cell: &str) -> bool {
    let s = cell.trim();
    let s = s.strip_suffix('%').unwrap_or(s).trim_end();
    !s.is_empty() && s.parse::<f64>().is_ok()
}

/// A link target that always stays relative to the report's directory: each path segment is
/// percent-encoded (RFC 3986 section 2.1; unreserved characters stay as they are), which also
/// turns a scheme's ':' into "%3A", and a leading "./" keeps a leading '/' from making the
/// href absolute or protocol-relative ("//host").
fn relative_href(name: &str) -> String {
    let mut out = String::from("./");
    for b in name.bytes() {
        let unreserved = b.is_ascii_alphanumeric() || matches!(b, b'-' | b'.' | b'_' | b'~');
        if unreserved || b == b'/' {
            out.push(char::from(b));
        } else {
            let _ = write!(out, "%{b:02X}");
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_all_five_characters() {
        assert_eq!(escape(r#"a&b<c>d"e'f"#), "a&amp;b&lt;c&gt;d&quot;e&#39;f");
    }

    #[test]
    fn href_stays_relative() {
        assert_eq!(relative_href("csv/fig 5.csv"), "./csv/fig%205.csv");
        // A scheme or a protocol-relative prefix cannot escape the report's directory.
        assert_eq!(relative_href("http://x"), "./http%3A//x");
        assert_eq!(relative_href("//host/a"), ".///host/a");
        // Quotes are encoded, so the attribute cannot be closed early.
        assert_eq!(relative_href("a\"b"), "./a%22b");
    }

    #[test]
    fn deviation_and_values() {
        // 110 against 100 is +10 % by definition; -90 against -100 is +10 % of |paper|.
        assert_eq!(format_deviation(110.0, 100.0), "+10 %");
        assert_eq!(format_deviation(-90.0, -100.0), "+10 %");
        assert_eq!(format_deviation(95.0, 100.0), "-5 %");
        assert_eq!(format_deviation(1.0, 0.0), "n/a");
        assert_eq!(format_deviation(f64::NAN, 1.0), "n/a");
        assert_eq!(format_value(1234.5678), "1235");
        assert_eq!(format_value(0.012346), "0.01235");
        assert_eq!(format_value(2.5e-6), "2.5e-6");
        assert_eq!(format_value(f64::INFINITY), "n/a");
    }

    #[test]
    fn numeric_cells() {
        assert!(is_numeric(" 1.5e-3 "));
        assert!(is_numeric("+10.0 %"));
        assert!(!is_numeric("n/a"));
        assert!(!is_numeric(""));
        assert!(!is_numeric("%"));
    }
}
