//! The HTML report is self-contained and safe: plain text is escaped, figures are PNG data
//! URIs that decode back to the PNG that went in, no network URL appears, tables keep their
//! row counts. Also writes a sample page to `target/tmp/report.html` for
//! `tests/browser_check.sh` (a real browser check, run by hand or in an opt-in CI step).

use base64::{engine::general_purpose::STANDARD, Engine as _};
use gearwear::report::html::{
    comparison_table, render, ComparisonRow, FigureBlock, Report, Section, TableBlock,
    PNG_SIGNATURE,
};
use gearwear::report::plot::{render_png, Figure, LineStyle, Panel, PanelKind, Series};

const HOSTILE: &str = "<script>alert('x')</script> & \"quoted\"";

/// A real PNG from the plotting layer: one period of a sine and a cosine.
fn sine_png(title: &str, width: u32, height: u32) -> Vec<u8> {
    let x: Vec<f64> = (0..=200).map(|i| f64::from(i) / 200.0).collect();
    let wave = |f: fn(f64) -> f64| x.iter().map(|t| f(std::f64::consts::TAU * t)).collect();
    let fig = Figure {
        title: title.into(),
        panels: vec![Panel {
            x_label: "mesh period (-)".into(),
            y_label: "value (-)".into(),
            series: vec![
                Series {
                    name: "sin".into(),
                    x: x.clone(),
                    y: wave(f64::sin),
                    style: LineStyle::Solid,
                    ..Default::default()
                },
                Series {
                    name: "cos".into(),
                    x: x.clone(),
                    y: wave(f64::cos),
                    style: LineStyle::Dashed,
                    ..Default::default()
                },
            ],
            vlines: vec![(0.5, "half period".into())],
            log_y: false,
            kind: PanelKind::Lines,
            ..Default::default()
        }],
    };
    render_png(&fig, width, height).expect("plot renders")
}

fn table(rows: usize, cols: usize) -> TableBlock {
    TableBlock {
        caption: format!("{rows} by {cols}"),
        header: (0..cols).map(|j| format!("c{j}")).collect(),
        rows: (0..rows)
            .map(|i| (0..cols).map(|j| format!("{}", i * cols + j)).collect())
            .collect(),
        highlight_col: Some(1),
    }
}

/// A report with hostile text in every plain-text field, two real figures, one bad figure
/// and tables of 0, 1, 3 and 7 rows.
fn sample() -> (Report, Vec<Vec<u8>>) {
    let pngs = vec![sine_png("first", 600, 300), sine_png("second", 400, 400)];
    let report = Report {
        title: format!("title {HOSTILE}"),
        intro_html: "<p>Our <em>own</em> intro.</p>".into(),
        sections: vec![
            Section {
                heading: format!("heading {HOSTILE}"),
                paragraphs: vec![format!("paragraph {HOSTILE}"), "plain".into()],
                figures: vec![
                    FigureBlock {
                        caption: format!("caption {HOSTILE}"),
                        png: pngs[0].clone(),
                        csv_name: Some("csv/fig 1.csv".into()),
                        svg: None,
                    },
                    FigureBlock {
                        caption: "no data".into(),
                        png: Vec::new(),
                        csv_name: None,
                        svg: None,
                    },
                ],
                tables: vec![table(0, 2), table(3, 4)],
            },
            Section {
                heading: "second".into(),
                paragraphs: vec![],
                figures: vec![FigureBlock {
                    caption: "second figure".into(),
                    png: pngs[1].clone(),
                    // A name that looks like a URL must still become a relative href.
                    csv_name: Some("http://example.com/x.csv".into()),
                    svg: None,
                }],
                tables: vec![
                    table(1, 1),
                    TableBlock {
                        caption: format!("cells {HOSTILE}"),
                        header: vec![HOSTILE.into(), "b".into()],
                        // Ragged rows: padded to the widest.
                        rows: vec![
                            vec![HOSTILE.into()],
                            vec!["1".into(), "2".into(), "3".into()],
                            vec![],
                            vec!["x".into()],
                            vec!["y".into()],
                            vec!["z".into()],
                            vec!["w".into()],
                        ],
                        highlight_col: None,
                    },
                ],
            },
        ],
        footer: format!("gearwear 0.1.0, case sha256 abc123 {HOSTILE}"),
    };
    (report, pngs)
}

/// The attribute text of every `<tag ...>` opening in `html`.
fn openings<'a>(html: &'a str, tag: &str) -> Vec<&'a str> {
    let open = format!("<{tag} ");
    let mut out = Vec::new();
    let mut rest = html;
    while let Some(i) = rest.find(&open) {
        rest = &rest[i + open.len()..];
        let end = rest.find('>').expect("tag closes");
        out.push(&rest[..end]);
        rest = &rest[end..];
    }
    out
}

/// The content between each `<tag ...>` and its `</tag>` (tables here do not nest).
fn bodies<'a>(html: &'a str, tag: &str) -> Vec<&'a str> {
    let (open, close) = (format!("<{tag}"), format!("</{tag}>"));
    let mut out = Vec::new();
    let mut rest = html;
    while let Some(i) = rest.find(&open) {
        rest = &rest[i + open.len()..];
        // Skip longer tag names with the same prefix (<th> vs <thead>).
        if !rest.starts_with(['>', ' ']) {
            continue;
        }
        rest = &rest[rest.find('>').expect("tag closes") + 1..];
        let end = rest.find(&close).expect("element closes");
        out.push(&rest[..end]);
        rest = &rest[end..];
    }
    out
}

#[test]
fn plain_text_is_escaped_everywhere() {
    let html = render(&sample().0);
    // The only tags are the ones the renderer writes: no injected script survives.
    assert!(!html.contains("<script"), "raw <script> in output");
    assert!(!html.contains("alert('x')"), "raw quote in output");
    let escaped = "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;quoted&quot;";
    // title (twice: <title> and <h1>), heading (+ contents entry), paragraph, caption (+ alt),
    // table caption, header cell, body cell, footer.
    let n = html.matches(escaped).count();
    assert_eq!(n, 11, "escaped hostile text found {n} times");
    // Trusted intro HTML is kept verbatim.
    assert!(html.contains("<p>Our <em>own</em> intro.</p>"));
}

#[test]
fn images_are_png_data_uris_that_round_trip() {
    let (report, pngs) = sample();
    let html = render(&report);
    let imgs = openings(&html, "img");
    // Two real PNGs; the empty one is a placeholder, not a broken <img>.
    assert_eq!(imgs.len(), pngs.len());
    assert!(html.contains("figure unavailable"));
    for (attrs, png) in imgs.iter().zip(&pngs) {
        let src = attrs
            .strip_prefix("src=\"data:image/png;base64,")
            .expect("src is a PNG data URI");
        let b64 = &src[..src.find('"').expect("src closes")];
        let bytes = STANDARD.decode(b64).expect("valid base64");
        assert!(bytes.starts_with(&PNG_SIGNATURE));
        assert_eq!(&bytes, png, "decoded image differs from the PNG given");
    }
}

#[test]
fn self_contained_no_network_urls() {
    let html = render(&sample().0);
    let lower = html.to_ascii_lowercase();
    for needle in [
        "http://", "https://", "<script", "<link", "<iframe", "@import", "url(",
    ] {
        assert!(!lower.contains(needle), "found {needle:?}");
    }
    // Every src is a data URI; every href is in-page or relative to the report's directory.
    for tag in ["img", "source", "video", "audio", "embed", "object"] {
        for attrs in openings(&html, tag) {
            assert!(attrs.contains("src=\"data:"), "<{tag} {attrs}>");
        }
    }
    let hrefs: Vec<&str> = openings(&html, "a")
        .into_iter()
        .map(|a| a.strip_prefix("href=\"").expect("href first"))
        .collect();
    assert_eq!(hrefs.len(), 2 + 2, "two contents links + two CSV links");
    for h in hrefs {
        assert!(h.starts_with('#') || h.starts_with("./"), "href {h}");
    }
    assert!(html.contains("href=\"./csv/fig%201.csv\""));
    // The CSP meta refuses everything but inline style and data images.
    assert!(html.contains("default-src 'none'; img-src data:;"));
}

#[test]
fn tables_keep_rows_and_columns() {
    let (report, _) = sample();
    let html = render(&report);
    let tables: Vec<&TableBlock> = report.sections.iter().flat_map(|s| &s.tables).collect();
    let rendered = bodies(&html, "table");
    assert_eq!(rendered.len(), tables.len());
    for (t, body) in tables.iter().zip(&rendered) {
        let tbody = bodies(body, "tbody");
        assert_eq!(tbody.len(), 1);
        let rows = bodies(tbody[0], "tr");
        assert_eq!(rows.len(), t.rows.len(), "table {:?}", t.caption);
        // Every row, header included, is padded to the widest row.
        let width = t.rows.iter().map(Vec::len).chain([t.header.len()]).max();
        for r in &rows {
            assert_eq!(Some(bodies(r, "td").len()), width);
        }
        assert_eq!(Some(bodies(body, "th").len()), width);
    }
}

#[test]
fn footer_and_comparison_table() {
    let t = comparison_table(
        "ours vs paper",
        &[ComparisonRow {
            quantity: "max. wear depth (um)".into(),
            ours: 11.0,
            paper: 10.0,
            explanation: "x".into(),
        }],
    );
    assert_eq!(t.header.len(), 5);
    assert_eq!(t.highlight_col, Some(3));
    // (11 - 10) / 10 = +10 %, by definition of the relative deviation (a whole
    // percentage prints whole: gearwear::format).
    assert_eq!(t.rows[0][3], "+10 %");
    let report = Report {
        title: "t".into(),
        sections: vec![Section {
            heading: "h".into(),
            tables: vec![t],
            ..Default::default()
        }],
        footer: "gearwear 0.1.0\ncase sha256 0123abcd".into(),
        ..Default::default()
    };
    let html = render(&report);
    let footer = bodies(&html, "footer");
    assert_eq!(footer, ["gearwear 0.1.0\ncase sha256 0123abcd"]);
    assert!(html.contains("<td class=\"num hl\">+10 %</td>"));
    // No footer element without metadata; a single section gets no contents list.
    let bare = render(&Report {
        footer: String::new(),
        ..report
    });
    assert!(!bare.contains("<footer") && !bare.contains("<nav"));
}

/// Writes a representative page to `target/tmp/report.html` (Cargo's per-target scratch
/// directory) for `tests/browser_check.sh`. The numbers are layout fillers, not results.
#[test]
fn writes_sample_report_for_browser_check() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"));
    let report = Report {
        title: "gearwear run: sample report (layout test)".into(),
        intro_html: "<p>Layout sample written by <code>tests/report_html.rs</code>; \
                     the numbers below are fillers, not results.</p>"
            .into(),
        sections: vec![
            Section {
                heading: "Figures".into(),
                paragraphs: vec![
                    "Two figures from the plotting layer, then one without data \
                                  (placeholder). Escaping check: <b>not bold</b> & co."
                        .into(),
                ],
                figures: vec![
                    FigureBlock {
                        caption: "Sine and cosine over one mesh period.".into(),
                        png: sine_png("Wide figure", 1200, 500),
                        csv_name: Some("fig1.csv".into()),
                        svg: None,
                    },
                    FigureBlock {
                        caption: "The same, square.".into(),
                        png: sine_png("Square figure", 600, 600),
                        csv_name: None,
                        svg: None,
                    },
                    FigureBlock {
                        caption: "Figure whose plot failed.".into(),
                        png: Vec::new(),
                        csv_name: None,
                        svg: None,
                    },
                ],
                tables: vec![],
            },
            Section {
                heading: "Comparison with the paper".into(),
                paragraphs: vec!["Filler values.".into()],
                figures: vec![],
                tables: vec![comparison_table(
                    "Layout of the comparison table.",
                    &[
                        ComparisonRow {
                            quantity: "quantity A (um)".into(),
                            ours: 11.0,
                            paper: 10.0,
                            explanation: "a longer explanation that wraps over more than one \
                                          line in the last column of the table"
                                .into(),
                        },
                        ComparisonRow {
                            quantity: "quantity B (N/m)".into(),
                            ours: 1.93e8,
                            paper: 2.0e8,
                            explanation: "short".into(),
                        },
                    ],
                )],
            },
        ],
        footer: format!(
            "gearwear {}\ncase sha256 (sample)",
            env!("CARGO_PKG_VERSION")
        ),
    };
    let path = dir.join("report.html");
    std::fs::write(&path, render(&report)).expect("write sample report");
    assert!(std::fs::metadata(&path).expect("written").len() > 1000);
}
