//! Tests of `gearwear::report::plot` through its public API: PNG structure checked by hand
//! against the PNG specification, SVG content, degenerate data, size limits, threads.

use std::path::Path;

use gearwear::report::plot::*;

fn line(name: &str, x: Vec<f64>, y: Vec<f64>) -> Series {
    let name = name.to_string();
    Series {
        name,
        x,
        y,
        style: LineStyle::Solid,
        ..Default::default()
    }
}

fn panel(series: Vec<Series>) -> Panel {
    Panel {
        x_label: "t (s)".into(),
        y_label: "F (N)".into(),
        series,
        ..Default::default()
    }
}

/// Three named solid sine series in one panel.
fn sine_figure() -> Figure {
    let t: Vec<f64> = (0..200).map(|i| f64::from(i) * 0.05).collect();
    let f = |k: f64| t.iter().map(|v| (k * v).sin()).collect();
    let series = vec![
        line("a", t.clone(), f(1.0)),
        line("b", t.clone(), f(2.0)),
        line("c", t.clone(), f(3.0)),
    ];
    Figure {
        title: "Mesh force history".into(),
        panels: vec![panel(series)],
    }
}

/// CRC-32 (ISO 3309 / ITU-T V.42, reflected polynomial 0xEDB88320), as PNG chunks use it.
fn crc32(bytes: &[u8]) -> u32 {
    let mut c = !0u32;
    for &b in bytes {
        c ^= u32::from(b);
        for _ in 0..8 {
            c = if c & 1 == 1 {
                0xEDB8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
        }
    }
    !c
}

/// Checks the PNG container by hand (PNG spec, ISO/IEC 15948 sections 5.2-5.6, 11.2.2):
/// signature; IHDR first with the requested width/height, bit depth 8 and an RGB(A) colour
/// type; every chunk's CRC; at least one IDAT; IEND as the last chunk, ending the file.
fn assert_png(bytes: &[u8], width: u32, height: u32) {
    let be = |i: usize| u32::from_be_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "signature");
    assert_eq!((be(8), &bytes[12..16]), (13, &b"IHDR"[..]));
    assert_eq!((be(16), be(20)), (width, height));
    assert_eq!(bytes[24], 8, "bit depth");
    assert!([2, 6].contains(&bytes[25]), "colour type {}", bytes[25]);
    let (mut pos, mut names) = (8, Vec::new());
    while pos + 12 <= bytes.len() {
        let len = be(pos) as usize;
        let body = &bytes[pos + 4..pos + 8 + len];
        assert_eq!(crc32(body), be(pos + 8 + len), "CRC of chunk at byte {pos}");
        names.push(body[..4].to_vec());
        pos += 12 + len;
    }
    assert_eq!(pos, bytes.len(), "chunks must tile the file");
    assert!(names.iter().any(|n| n == b"IDAT"));
    assert_eq!(names.last().map(Vec::as_slice), Some(&b"IEND"[..]));
}

/// Trimmed text contents of the SVG's <text> elements.
fn svg_texts(svg: &str) -> Vec<String> {
    let inner = |t: &str| {
        Some(
            t.split_once('>')?
                .1
                .split("</text>")
                .next()?
                .trim()
                .to_string(),
        )
    };
    svg.split("<text").skip(1).filter_map(inner).collect()
}

/// Number of <polyline> elements stroked in `color`.
fn polylines(svg: &str, color: &str) -> usize {
    let tag_has = |p: &&str| p.split('>').next().unwrap_or("").contains(color);
    svg.split("<polyline").skip(1).filter(tag_has).count()
}

#[test]
fn crc32_matches_the_standard_check_value() {
    // Published check value of CRC-32/ISO-HDLC for the ASCII string "123456789".
    assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
}

#[test]
fn png_has_signature_size_and_valid_chunks() {
    let png = render_png(&sine_figure(), 640, 360).unwrap();
    assert_png(&png, 640, 360);
}

#[test]
fn svg_has_title_legend_and_each_series_drawn_segment_by_segment() {
    let svg = render_svg(&sine_figure(), 640, 360).unwrap();
    let texts = svg_texts(&svg);
    assert!(svg.starts_with("<svg") && texts.iter().any(|t| t == "Mesh force history"));
    // Three named solid series of 200 points (fewer than the 4 per pixel column that
    // decimation keeps): each of the first three palette colours (Tableau 10) strokes the
    // 199 segments of its series (drawn one by one, so a wide line has no miter spikes
    // past the data) plus one legend sample; no other element uses them.
    for color in ["#1F77B4", "#FF7F0E", "#2CA02C"] {
        assert_eq!(polylines(&svg, color), 199 + 1, "{color}");
    }
    assert!(["a", "b", "c"].iter().all(|n| texts.iter().any(|t| t == n)));
}

#[test]
fn single_named_series_has_no_legend() {
    let fig = Figure {
        title: "T".into(),
        panels: vec![panel(vec![line("only", vec![0.0, 1.0], vec![1.0, 2.0])])],
    };
    let svg = render_svg(&fig, 400, 300).unwrap();
    assert_eq!(polylines(&svg, "#1F77B4"), 1);
    assert!(!svg_texts(&svg).iter().any(|t| t == "only"));
}

#[test]
fn vline_labels_and_axis_labels_are_drawn() {
    let mut fig = sine_figure();
    fig.panels[0].vlines = vec![(2.0, "pitch point".into()), (f64::NAN, "skipped".into())];
    let texts = svg_texts(&render_svg(&fig, 500, 300).unwrap());
    for want in ["pitch point", "t (s)", "F (N)"] {
        assert!(texts.iter().any(|t| t == want), "{want}");
    }
    assert!(!texts.iter().any(|t| t == "skipped"));
}

#[test]
fn degenerate_data_renders_without_panic() {
    let nan = f64::NAN;
    let cases = vec![
        vec![],
        vec![line("empty", vec![], vec![])],
        vec![line("one", vec![2.0], vec![5.0])],
        vec![line("const", vec![1.0, 2.0, 3.0], vec![0.0; 3])],
        vec![line("nan", vec![nan, f64::INFINITY], vec![1.0, nan])],
        vec![line("short y", vec![1.0, 2.0, 3.0], vec![1.0])],
        vec![line("negative", vec![1.0, 2.0], vec![-1.0, -2.0])],
        vec![line("600 decades", vec![1.0, 2.0], vec![1e-300, 1e300])],
        vec![line("subnormal", vec![1.0, 2.0], vec![5e-324, 1e-310])],
        vec![line("200 decades", vec![1.0, 2.0], vec![1e-100, 1e100])],
        vec![line(
            "huge",
            vec![-f64::MAX, 1.0, f64::MAX],
            vec![f64::MAX, 1.0, -f64::MAX],
        )],
    ];
    let styles = [
        LineStyle::Solid,
        LineStyle::Dashed,
        LineStyle::Dotted,
        LineStyle::Points,
    ];
    let kinds = [PanelKind::Lines, PanelKind::Bars];
    for series in cases {
        for (style, kind, log_y) in styles.iter().flat_map(|s| {
            kinds
                .map(|k| (s, k, false))
                .into_iter()
                .chain(kinds.map(|k| (s, k, true)))
        }) {
            let series = series
                .iter()
                .cloned()
                .map(|s| Series { style: *style, ..s })
                .collect();
            let vlines = vec![
                (nan, "bad".into()),
                (1.5, "mark".into()),
                (1e305, "far".into()),
            ];
            let p = Panel {
                vlines,
                kind,
                log_y,
                ..panel(series)
            };
            let fig = Figure {
                title: String::new(),
                panels: vec![p.clone(), p],
            };
            assert_png(&render_png(&fig, 300, 200).unwrap(), 300, 200);
            assert!(render_svg(&fig, 300, 200).unwrap().starts_with("<svg"));
        }
    }
    assert_png(&render_png(&Figure::default(), 1, 1).unwrap(), 1, 1);
}

#[test]
fn minimum_size_renders_and_below_it_is_an_error() {
    let mut fig = sine_figure();
    fig.panels[0].vlines = vec![(1.0, "marker".into())];
    fig.panels.push(Panel {
        log_y: true,
        kind: PanelKind::Bars,
        ..fig.panels[0].clone()
    });
    fig.panels.push(panel(vec![]));
    let (w, h) = min_size(&fig);
    // Title band plus three panels of MIN_PANEL_PX each.
    assert_eq!((w, h), (MIN_PANEL_PX.0, 40 + 3 * MIN_PANEL_PX.1));
    assert_png(&render_png(&fig, w, h).unwrap(), w, h);
    render_svg(&fig, w, h).unwrap();
    for (bw, bh) in [(w - 1, h), (w, h - 1), (0, h), (w, 0), (MAX_SIDE_PX + 1, h)] {
        let err = render_svg(&fig, bw, bh).unwrap_err();
        assert!(matches!(err, PlotError::Size { got, min } if got == (bw, bh) && min == (w, h)));
        assert!(matches!(
            render_png(&fig, bw, bh),
            Err(PlotError::Size { .. })
        ));
    }
}

#[test]
fn save_writes_files_and_reports_io_errors() {
    let dir = tempfile::tempdir().unwrap();
    let (png, svg) = (dir.path().join("f.png"), dir.path().join("f.svg"));
    save_png(&sine_figure(), &png, 320, 240).unwrap();
    save_svg(&sine_figure(), &svg, 320, 240).unwrap();
    assert_png(&std::fs::read(png).unwrap(), 320, 240);
    assert!(std::fs::read_to_string(svg)
        .unwrap()
        .contains("Mesh force history"));
    let missing = Path::new("/nonexistent-dir-gearwear/x.png");
    assert!(matches!(
        save_png(&sine_figure(), missing, 320, 240),
        Err(PlotError::Io(..))
    ));
}

#[test]
fn renders_from_four_threads_at_once() {
    let fig = sine_figure();
    std::thread::scope(|s| {
        let handles: Vec<_> = (0..4u32)
            .map(|i| {
                let fig = &fig;
                s.spawn(move || (render_png(fig, 300 + i, 200), render_svg(fig, 300, 200)))
            })
            .collect();
        for (i, h) in (0..4u32).zip(handles) {
            let (png, svg) = h.join().unwrap();
            assert_png(&png.unwrap(), 300 + i, 200);
            assert!(svg.unwrap().contains("Mesh force history"));
        }
    });
}

/// Point lists of the <polyline> elements stroked in `color`, in SVG pixels.
fn polyline_points(svg: &str, color: &str) -> Vec<Vec<(f64, f64)>> {
    svg.split("<polyline")
        .skip(1)
        .map(|p| p.split('>').next().unwrap_or(""))
        .filter(|tag| tag.contains(color))
        .map(|tag| {
            let pts = tag.split("points=\"").nth(1).unwrap_or("");
            let pts = pts.split('"').next().unwrap_or("");
            pts.split_whitespace()
                .filter_map(|xy| {
                    let (x, y) = xy.split_once(',')?;
                    Some((x.parse().ok()?, y.parse().ok()?))
                })
                .collect()
        })
        .collect()
}

#[test]
fn legend_swatches_are_drawn_in_the_series_line_style() {
    // Solid, dashed and dotted series: inside the legend box (which covers no data, as the
    // layout tests check), each colour draws its swatch as 1, 2 or 5 horizontal pieces,
    // the dash pattern of its data line.
    let mut fig = sine_figure();
    fig.panels[0].series[1].style = LineStyle::Dashed;
    fig.panels[0].series[2].style = LineStyle::Dotted;
    let (w, h) = (640, 360);
    let svg = render_svg(&fig, w, h).unwrap();
    let legend = layout(&fig, w, h).unwrap()[0]
        .legend
        .expect("three named series");
    let inside = |p: &(f64, f64)| {
        let (x, y) = (p.0.round() as i32, p.1.round() as i32);
        legend.contains((x, y))
    };
    for (color, pieces) in [("#1F77B4", 1), ("#FF7F0E", 2), ("#2CA02C", 5)] {
        let swatch: Vec<Vec<(f64, f64)>> = polyline_points(&svg, color)
            .into_iter()
            .filter(|l| !l.is_empty() && l.iter().all(inside))
            .collect();
        assert_eq!(swatch.len(), pieces, "{color}: {swatch:?}");
        for piece in &swatch {
            assert!(
                piece.iter().all(|p| p.1 == piece[0].1),
                "{color}: not level"
            );
        }
    }
}
