//! Reading figure files back: sizes from the files themselves (the SVG root element's
//! attributes, the PNG IHDR chunk), independently of the renderer's bookkeeping.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Files in `dir` (not below) ending in `.ext`.
pub fn files(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == ext))
        .collect();
    v.sort();
    v
}

/// Every file below `dir` by its path relative to `dir`, hidden files (the folder's state
/// record and lock) left out.
pub fn tree(dir: &Path) -> BTreeMap<String, PathBuf> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            let name = p.file_name().unwrap().to_str().unwrap().to_owned();
            if name.starts_with('.') {
                continue;
            }
            if p.is_dir() {
                stack.push(p);
            } else {
                let rel = p.strip_prefix(dir).unwrap().to_str().unwrap().to_owned();
                out.insert(rel, p);
            }
        }
    }
    out
}

/// Value of attribute `name` in the opening tag `tag` (up to its first '>').
pub fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let head = tag.split('>').next()?;
    let start = head.find(&format!(" {name}=\""))? + name.len() + 3;
    head[start..].split('"').next()
}

/// The `width` and `height` attributes of the SVG root element, in px.
pub fn svg_size(path: &Path) -> (u32, u32) {
    let text = std::fs::read_to_string(path).unwrap();
    let start = text
        .find("<svg")
        .unwrap_or_else(|| panic!("{path:?}: no <svg> root"));
    let tag = &text[start..start + text[start..].find('>').unwrap()];
    let attr = |name: &str| -> u32 {
        let key = format!(" {name}=\"");
        let i = tag.find(&key).unwrap_or_else(|| panic!("{tag}: no {name}")) + key.len();
        tag[i..i + tag[i..].find('"').unwrap()].parse().unwrap()
    };
    assert!(
        text.trim_end().ends_with("</svg>"),
        "{path:?}: not a whole SVG document"
    );
    (attr("width"), attr("height"))
}

/// Width and height of a PNG from its IHDR chunk (PNG spec 11.2.2: the first chunk, its
/// width and height big-endian at bytes 16-23 of the file).
pub fn png_size(path: &Path) -> (u32, u32) {
    let b = std::fs::read(path).unwrap();
    assert_eq!(&b[..8], b"\x89PNG\r\n\x1a\n", "{path:?}: not a PNG");
    assert_eq!(&b[12..16], b"IHDR");
    let be = |i: usize| u32::from_be_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
    (be(16), be(20))
}

/// The paths every manifest in `dir` lists (`manifest.json`, `STEM.manifest.json`).
pub fn manifest_paths(dir: &Path) -> Vec<String> {
    let mut paths = Vec::new();
    for p in files(dir, "json") {
        let name = p.file_name().unwrap().to_str().unwrap();
        if name == "manifest.json" || name.ends_with(".manifest.json") {
            let m: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(&p).unwrap()).unwrap();
            for f in m["files"].as_array().unwrap() {
                paths.push(f["path"].as_str().unwrap().to_owned());
            }
        }
    }
    paths
}
