//! The spectrum figures' harmonic and sideband labels, read back from the SVG a reader
//! gets: no two labels' boxes intersect and every box lies inside the image (issue 34:
//! "mesh frequency|3x mesh frequency" ran together, "+1 gear" and "+1 pinion" collided,
//! the 5x label sat on the right edge). Figures: the `signals` spectrum of the built-in
//! case (mesh harmonics and both shafts' sidebands) and the two spectra of a grade-6
//! hunting period's `dynamics` (harmonics up to 5x; the sideband figure).
mod common;

use common::figures::{attr, svg_size};
use std::path::Path;

/// A label's box in pixels (x0, y0, x1, y1) and its text.
type LabelBox = ((f64, f64, f64, f64), String);

/// Average advance of a character of the labels' sans-serif font, in em, taken above the
/// mean: DejaVu Sans (what `sans-serif` resolves to on Linux; advances from its hmtx
/// table, 2048 units per em) advances "m" 0.97 em, other lower-case letters 0.28-0.64 em,
/// digits 0.64 em, a space 0.32 em, "×", "+" and "−" 0.84 em, so the labels drawn average
/// 0.54 ("+1 pinion") to 0.58 em ("2 × mesh frequency", "+2 gear"): 0.65 em bounds them
/// with 10 % to spare.
const EM_PER_CHAR: f64 = 0.65;

/// The marker labels of an SVG: the grey (#5A5A5A), top-anchored (`dy="0.76em"`),
/// start-aligned texts the renderer writes for vertical markers; each box from the text's
/// anchor, its character count and its font size (`EM_PER_CHAR`), one font size high.
fn marker_labels(svg: &str) -> Vec<LabelBox> {
    svg.split("<text")
        .skip(1)
        .filter(|t| attr(t, "fill") == Some("#5A5A5A") && attr(t, "text-anchor") == Some("start"))
        .filter_map(|t| {
            let text = t
                .split_once('>')?
                .1
                .split("</text>")
                .next()?
                .trim()
                .to_string();
            let (x, y): (f64, f64) = (attr(t, "x")?.parse().ok()?, attr(t, "y")?.parse().ok()?);
            let size: f64 = attr(t, "font-size")?.parse().ok()?;
            let w = text.chars().count() as f64 * EM_PER_CHAR * size;
            Some(((x, y, x + w, y + size), text))
        })
        .collect()
}

/// Every marker label stands on a white back drawn just before it that covers the
/// font's whole line: a top-anchored label (`dy="0.76em"`) spans the ascent above the
/// baseline (0.76 em) and the descent below it (DejaVu Sans: 0.24 em), so from its y to
/// y + 1 em. A marker line that no side of the label could avoid then goes behind the
/// text instead of through it ("+1 |pinion" had the "+2 gear" line through its
/// descender band when the back was the ink height, 9 px of a 12 px font).
fn labels_on_white(svg: &str, file: &Path) {
    let mut back: Option<(f64, f64, f64)> = None; // x, y, height of the last white rect
    for el in svg.split('<').skip(1) {
        if el.starts_with("rect") && attr(el, "fill") == Some("#FFFFFF") {
            let num = |k| attr(el, k).and_then(|v| v.parse::<f64>().ok());
            back = num("x")
                .zip(num("y"))
                .zip(num("height"))
                .map(|((x, y), h)| (x, y, h));
        } else if el.starts_with("text")
            && attr(el, "fill") == Some("#5A5A5A")
            && attr(el, "text-anchor") == Some("start")
        {
            let num = |k| attr(el, k).and_then(|v| v.parse::<f64>().ok()).unwrap();
            let (x, y, size) = (num("x"), num("y"), num("font-size"));
            let text = el.split_once('>').map_or("", |t| t.1);
            let (bx, by, bh) =
                back.unwrap_or_else(|| panic!("{}: {text:?} has no back", file.display()));
            assert!(
                bx <= x && by <= y && by + bh >= y + size,
                "{}: {text:?} at ({x}, {y}), {size} px, on a back ({bx}, {by}) {bh} px high",
                file.display()
            );
            back = None;
        }
    }
}

/// Checks the labels of `file`; returns how many it has.
fn labels_apart(file: &Path) -> usize {
    let svg = std::fs::read_to_string(file).unwrap();
    labels_on_white(&svg, file);
    let labels = marker_labels(&svg);
    let width = f64::from(svg_size(file).0);
    for (i, ((ax0, ay0, ax1, ay1), a)) in labels.iter().enumerate() {
        assert!(
            *ax0 >= 0.0 && *ax1 <= width,
            "{}: {a:?} leaves the image ({ax0}..{ax1} of {width} px)",
            file.display()
        );
        for ((bx0, by0, bx1, by1), b) in &labels[i + 1..] {
            let apart = ax1 <= bx0 || bx1 <= ax0 || ay1 <= by0 || by1 <= ay0;
            assert!(apart, "{}: labels {a:?} and {b:?} overlap", file.display());
        }
    }
    labels.len()
}

#[test]
fn spectrum_labels_do_not_overlap_in_the_svg() {
    let dir = tempfile::tempdir().unwrap();
    let (sig, dyn6) = (dir.path().join("signals"), dir.path().join("dynamics"));
    let svg = ["--figures", "svg"];
    common::ok(
        &[
            &["-q", "signals"],
            &svg[..],
            &["--out", sig.to_str().unwrap()],
        ]
        .concat(),
    );
    common::ok(
        &[
            &["-q", "dynamics", "--set", "teeth.accuracy_grade=6"],
            &svg[..],
            &["--out", dyn6.to_str().unwrap()],
        ]
        .concat(),
    );
    // At least the harmonics and both shafts' sidebands each figure marks (a figure that
    // lost its labels would pass the overlap check vacuously).
    for (file, least) in [
        (sig.join("spectrum.svg"), 8),
        (dyn6.join("spectrum_velocity_y_pinion.svg"), 5),
        (dyn6.join("teeth_spectrum_sidebands.svg"), 5),
    ] {
        let n = labels_apart(&file);
        assert!(n >= least, "{}: {n} labels", file.display());
    }
}

/// A two-stage train's spectrum marks every mesh's harmonics (issue 29), apart and on
/// white like the pair's. The example's meshes run at 570 Hz (19 teeth at 30 Hz) and
/// 570 x 23 / 31 = 422.9 Hz (23 teeth on the intermediate shaft at 30 x 19 / 31 Hz); the
/// figure spans 5 x 570 Hz, so mesh 1 has harmonics 1-5 and mesh 2 has 1-6
/// (6 x 422.9 = 2537 Hz <= 2850 Hz < 7 x 422.9).
#[test]
fn a_train_spectrum_labels_every_mesh_harmonic() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("train");
    let case = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/two_stage_reducer.toml"
    );
    common::ok(&[
        "-q",
        "dynamics",
        "--config",
        case,
        "--figures",
        "svg",
        "--out",
        out.to_str().unwrap(),
    ]);
    let file = out.join("spectrum_velocity_y_pinion.svg");
    assert_eq!(labels_apart(&file), 11);
    let svg = std::fs::read_to_string(&file).unwrap();
    let texts: Vec<String> = marker_labels(&svg).into_iter().map(|l| l.1).collect();
    for want in ["mesh 1", "5 × mesh 1", "mesh 2", "6 × mesh 2"] {
        assert!(texts.iter().any(|t| t == want), "{want:?} not in {texts:?}");
    }
    assert!(
        !texts.iter().any(|t| t == "6 × mesh 1" || t == "7 × mesh 2"),
        "{texts:?}"
    );

    // The `signals` record of the same train: its recorded band marks the first
    // `signals.mesh_harmonics` (4) of each mesh, both under the band's 10 kHz.
    let sig = dir.path().join("signals");
    common::ok(&[
        "-q",
        "signals",
        "--config",
        case,
        "--figures",
        "svg",
        "--out",
        sig.to_str().unwrap(),
    ]);
    let file = sig.join("spectrum.svg");
    labels_apart(&file);
    let svg = std::fs::read_to_string(&file).unwrap();
    let texts: Vec<String> = marker_labels(&svg).into_iter().map(|l| l.1).collect();
    for want in ["mesh 1", "4 × mesh 1", "mesh 2", "4 × mesh 2"] {
        assert!(texts.iter().any(|t| t == want), "{want:?} not in {texts:?}");
    }
}
