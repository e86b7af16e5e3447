//! Figure formats and size (`--figures`, `--figure-size`): PNG by default and nothing
//! else; SVG documents and PNG images of the requested size; bad values refused with exit
//! 2 before any work. Sizes are read from the files themselves (the SVG root element's
//! attributes, the PNG IHDR chunk), independently of the renderer's bookkeeping.

mod common;

use common::figures::{files, manifest_paths, png_size, svg_size};
use common::{ok, rejected, CHEAP};
use std::path::{Path, PathBuf};

/// `gearwear dynamics` on a cheap case into `out` with `extra` options.
fn dynamics(out: &Path, extra: &[&str]) {
    let mut a = vec!["dynamics"];
    a.extend(CHEAP);
    a.extend(extra);
    a.extend(["--out", out.to_str().unwrap()]);
    ok(&a);
}

#[test]
fn default_output_is_png_only_at_the_default_size() {
    let d = tempfile::tempdir().unwrap();
    dynamics(d.path(), &[]);
    assert!(
        files(d.path(), "svg").is_empty(),
        "an SVG written by default"
    );
    let pngs = files(d.path(), "png");
    assert!(!pngs.is_empty());
    // The documented default one-panel size (README, `--figure-size` help): 900 x 420.
    for p in &pngs {
        assert_eq!(png_size(p), (900, 420), "{p:?}");
    }
}

#[test]
fn svg_only_at_the_requested_size_listed_in_the_manifest() {
    let d = tempfile::tempdir().unwrap();
    dynamics(d.path(), &["--figures", "svg", "--figure-size", "1200x800"]);
    assert!(
        files(d.path(), "png").is_empty(),
        "PNG figures written with --figures svg"
    );
    let svgs = files(d.path(), "svg");
    assert!(!svgs.is_empty());
    let manifest = manifest_paths(d.path());
    for p in &svgs {
        // Every figure of `dynamics` is one panel, so each has exactly the size asked for.
        assert_eq!(svg_size(p), (1200, 800), "{p:?}");
        let name = p.file_name().unwrap().to_str().unwrap();
        assert!(
            manifest.iter().any(|m| m == name),
            "{name} not in the manifest"
        );
    }
}

#[test]
fn png_and_svg_both_written_with_the_same_size() {
    let d = tempfile::tempdir().unwrap();
    dynamics(
        d.path(),
        &["--figures", "png,svg", "--figure-size", "1600x900"],
    );
    let pngs = files(d.path(), "png");
    let svgs = files(d.path(), "svg");
    assert!(!pngs.is_empty());
    // One SVG beside each PNG, same stem.
    let stems =
        |v: &[PathBuf]| -> Vec<PathBuf> { v.iter().map(|p| p.with_extension("")).collect() };
    assert_eq!(stems(&pngs), stems(&svgs));
    for p in &pngs {
        assert_eq!(png_size(p), (1600, 900), "{p:?}");
    }
    for p in &svgs {
        assert_eq!(svg_size(p), (1600, 900), "{p:?}");
    }
}

#[test]
fn figures_of_several_panels_keep_their_height_ratio() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("s");
    let mut a = vec!["stiffness"];
    a.extend(CHEAP);
    a.extend([
        "--figures",
        "png",
        "--figure-size",
        "1800x840",
        "--out",
        out.to_str().unwrap(),
    ]);
    ok(&a);
    let d0 = tempfile::tempdir().unwrap();
    let out0 = d0.path().join("s");
    let mut a0 = vec!["stiffness"];
    a0.extend(CHEAP);
    a0.extend(["--out", out0.to_str().unwrap()]);
    ok(&a0);
    // 1800 x 840 is twice the default one-panel 900 x 420: every figure doubles both sides.
    for p in files(&out0, "png") {
        let (w, h) = png_size(&p);
        assert_eq!(
            png_size(&out.join(p.file_name().unwrap())),
            (2 * w, 2 * h),
            "{p:?}"
        );
    }
}

#[test]
fn bad_formats_and_sizes_exit_2_naming_argument_value_and_range() {
    for cmd in ["run", "wear", "dynamics", "stiffness"] {
        rejected(
            &[cmd, "--figures", "gif"],
            &["--figures", "gif", "png, svg or png,svg"],
        );
    }
    let range = ["width in [400, 8192]", "height in [200, 4096]"];
    for size in ["10x800", "1600x9000", "1600", "-5x300", "axb"] {
        let mut needles = vec!["--figure-size", size];
        needles.extend(range);
        // `=`: a value starting with '-' is the value, not a flag.
        rejected(&["dynamics", &format!("--figure-size={size}")], &needles);
    }
    rejected(
        &["run", "--figure-size", "399x420"],
        &["--figure-size", "399x420"],
    );
}
