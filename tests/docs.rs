//! The documentation stands alone: every relative link of README.md and docs/*.md names a
//! file inside the repository, and nothing in the repository cites notes that are not in
//! it (the paper notes live in docs/PAPER_NOTES.md).

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// README.md and every Markdown file under docs/.
fn markdown_files() -> Vec<PathBuf> {
    let mut files = vec![root().join("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(root().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    docs.sort();
    files.extend(docs);
    files
}

/// Targets of the inline links `[text](target)` and images `![alt](target)` of `text`,
/// outside code spans and fenced code blocks (where brackets are code, not links).
fn link_targets(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        // Drop code spans: the text between pairs of backticks.
        let prose: String = line
            .split('`')
            .enumerate()
            .filter(|(i, _)| i % 2 == 0)
            .map(|(_, s)| s)
            .collect::<Vec<_>>()
            .join(" ");
        let mut rest = prose.as_str();
        while let Some(i) = rest.find("](") {
            let after = &rest[i + 2..];
            let Some(end) = after.find(')') else { break };
            // A link target ends at the first space (an optional title follows it).
            let target = after[..end].split_whitespace().next().unwrap_or("");
            out.push(target.to_string());
            rest = &after[end..];
        }
    }
    out
}

/// Whether a link target points at a place outside the repository's files (a URL or an
/// anchor of the same page).
fn is_external(target: &str) -> bool {
    target.is_empty()
        || target.starts_with('#')
        || target.contains("://")
        || target.starts_with("mailto:")
}

#[test]
fn the_link_parser_finds_links_and_skips_code() {
    let text = "See [model](MODEL.md#wear) and ![fig](img/a.png \"title\").\n\
                `[not](a link)` and\n```\n[no](link)\n```\n[url](https://example.org)";
    assert_eq!(
        link_targets(text),
        vec!["MODEL.md#wear", "img/a.png", "https://example.org"]
    );
}

#[test]
fn every_relative_link_of_the_docs_resolves_inside_the_repository() {
    let root = root().canonicalize().unwrap();
    let mut checked = 0;
    let mut broken = Vec::new();
    for file in markdown_files() {
        let text = std::fs::read_to_string(&file).unwrap();
        let dir = file.parent().unwrap();
        for target in link_targets(&text) {
            if is_external(&target) {
                continue;
            }
            let path = target.split('#').next().unwrap();
            let resolved = dir.join(path).canonicalize();
            checked += 1;
            match resolved {
                Ok(p) if p.starts_with(&root) => {}
                _ => broken.push(format!("{}: {target}", file.display())),
            }
        }
    }
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
    // The docs do link to each other (MODEL.md, PAPER_NOTES.md, the figures): a parser
    // that found nothing would pass vacuously.
    assert!(checked >= 10, "only {checked} relative links found");
}

/// Every file under `dir`, skipping build output, version control and local results.
fn repository_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        if path.is_dir() {
            if !["target", ".git", "results"].contains(&name.as_str()) {
                repository_files(&path, out);
            }
        } else {
            out.push(path);
        }
    }
}

#[test]
fn no_file_cites_notes_outside_the_repository() {
    // The needle is assembled so that this file does not contain it.
    let notes = ["NOTES", ".md"].concat();
    let spec = ["shared", "/spec"].concat();
    let mut files = Vec::new();
    repository_files(&root(), &mut files);
    assert!(files.iter().any(|p| p.ends_with("docs/PAPER_NOTES.md")));
    let mut bad = Vec::new();
    for path in files {
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue; // not UTF-8 text (images)
        };
        for (n, line) in text.lines().enumerate() {
            let foreign_notes = line
                .match_indices(&notes)
                .any(|(i, _)| !line[..i].ends_with("PAPER_"));
            if foreign_notes || line.contains(&spec) {
                bad.push(format!("{}:{}: {line}", path.display(), n + 1));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "cites notes not in the repository:\n{}",
        bad.join("\n")
    );
}

/// The user-facing install texts: README.md, docs/*.md, python/README.md, the examples'
/// READMEs and the Python examples (script and notebook).
fn install_texts() -> Vec<(PathBuf, String)> {
    let mut files = markdown_files();
    files.push(root().join("python/README.md"));
    files.push(root().join("examples/duty_cycle/README.md"));
    for e in std::fs::read_dir(root().join("python/examples")).unwrap() {
        files.push(e.unwrap().path());
    }
    files
        .into_iter()
        .map(|p| {
            let t = std::fs::read_to_string(&p).unwrap();
            (p, t)
        })
        .collect()
}

#[test]
fn every_cargo_install_is_locked() {
    // `cargo install` ignores Cargo.lock unless told: without `--locked` a user builds
    // with whatever versions are newest that day, not the tested ones.
    let mut seen = 0;
    for (p, t) in install_texts() {
        for l in t.lines().filter(|l| l.contains("cargo install")) {
            seen += 1;
            assert!(l.contains("--locked"), "{}: {l}", p.display());
        }
    }
    assert!(
        seen >= 1,
        "no cargo install found: the test reads the wrong files"
    );
}

/// Top-level modules imported by Python source `code` (`import a.b`, `from a import b`).
fn imported_modules(code: &str) -> Vec<String> {
    code.lines()
        .filter_map(|l| {
            let l = l.trim().trim_start_matches('"');
            let rest = l
                .strip_prefix("import ")
                .or_else(|| l.strip_prefix("from ").filter(|r| r.contains(" import ")))?;
            let name = rest
                .split(|c: char| !(c.is_alphanumeric() || c == '_'))
                .next()?;
            Some(name.to_string())
        })
        .collect()
}

#[test]
fn the_examples_extra_packages_are_named_where_users_install() {
    // Every third-party module the Python examples import is either a dependency of the
    // package or in its `examples` extra (python/pyproject.toml), and the README's and
    // python/README.md's install sections, and each example's own header, install that
    // extra.
    let pyproject = std::fs::read_to_string(root().join("python/pyproject.toml")).unwrap();
    let line = |key: &str| {
        pyproject
            .lines()
            .find(|l| l.starts_with(key))
            .unwrap_or_else(|| panic!("no {key} in pyproject.toml"))
            .to_string()
    };
    let (deps, extra) = (line("dependencies ="), line("examples ="));
    // The standard library modules the examples use, and the package itself.
    let own = [
        "argparse", "pathlib", "sys", "os", "json", "math", "time", "gearwear",
    ];
    let mut third_party = 0;
    for e in std::fs::read_dir(root().join("python/examples")).unwrap() {
        let p = e.unwrap().path();
        let code = std::fs::read_to_string(&p).unwrap();
        for m in imported_modules(&code) {
            if own.contains(&m.as_str()) {
                continue;
            }
            third_party += 1;
            assert!(
                deps.contains(&format!("\"{m}")) || extra.contains(&format!("\"{m}")),
                "{}: imports {m}, which the package does not install (examples extra: {extra})",
                p.display()
            );
        }
        assert!(
            code.contains("./python[examples]"),
            "{}: its header does not install the examples extra",
            p.display()
        );
    }
    assert!(third_party >= 2, "matplotlib and tqdm were not found");
    for f in ["README.md", "python/README.md"] {
        let t = std::fs::read_to_string(root().join(f)).unwrap();
        assert!(t.contains("pip install \"./python[examples]\""), "{f}");
    }
}

/// Where `text` spells the micrometre `um` as a word of its own: not part of a name
/// (`dte_max_um`, `--limit-um`, `{w}um`), a path or a code span. Returns the lines.
fn ascii_micrometres(text: &str) -> Vec<String> {
    let b = text.as_bytes();
    let name = |c: u8| c.is_ascii_alphanumeric() || b"_-`".contains(&c);
    let mut found = Vec::new();
    for (i, _) in text.match_indices("um") {
        let before = if i == 0 { b' ' } else { b[i - 1] };
        let after = b.get(i + 2).copied().unwrap_or(b' ');
        if !name(before) && !b".{}/$".contains(&before) && !name(after) {
            let start = text[..i].rfind('\n').map_or(0, |x| x + 1);
            let end = text[i..].find('\n').map_or(text.len(), |x| i + x);
            found.push(text[start..end].trim().to_string());
        }
    }
    found
}

/// The string literals of Rust source (comments and character literals skipped).
fn string_literals(src: &str) -> Vec<String> {
    let c: Vec<char> = src.chars().collect();
    let (mut out, mut i) = (Vec::new(), 0);
    let at = |i: usize, s: &str| c[i..].iter().take(s.len()).copied().eq(s.chars());
    while i < c.len() {
        if at(i, "//") {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if at(i, "/*") {
            while i + 1 < c.len() && !at(i, "*/") {
                i += 1;
            }
            i += 2;
        } else if c[i] == 'r'
            && (at(i + 1, "\"") || at(i + 1, "#"))
            && (i == 0 || !(c[i - 1].is_alphanumeric() || c[i - 1] == '_'))
        {
            let hashes = c[i + 1..].iter().take_while(|x| **x == '#').count();
            let close: String = std::iter::once('"')
                .chain(std::iter::repeat_n('#', hashes))
                .collect();
            let start = i + 2 + hashes;
            let mut j = start;
            while j < c.len() && !at(j, &close) {
                j += 1;
            }
            out.push(c[start..j.min(c.len())].iter().collect());
            i = j + close.len();
        } else if c[i] == '\'' {
            // A character literal ('x', '\n', '"'), else a lifetime.
            if c.get(i + 1) == Some(&'\\') {
                i += c[i + 2..]
                    .iter()
                    .position(|x| *x == '\'')
                    .map_or(1, |p| p + 3);
            } else if c.get(i + 2) == Some(&'\'') {
                i += 3;
            } else {
                i += 1;
            }
        } else if c[i] == '"' {
            let mut j = i + 1;
            while j < c.len() && c[j] != '"' {
                j += if c[j] == '\\' { 2 } else { 1 };
            }
            out.push(c[i + 1..j.min(c.len())].iter().collect());
            i = j + 1;
        } else {
            i += 1;
        }
    }
    out
}

#[test]
fn the_micrometre_is_spelled_one_way_in_user_facing_text() {
    // Prose, messages, plots and reports write `µm`; names that programs read (CSV
    // columns, case keys, JSON keys, flags, the dataset index's units) keep ASCII `_um`
    // / `um` (docs/CONFIG.md, "Units"). The check: no string literal of the library,
    // the CLI or the Python binding, and no documentation page, spells it `um`.
    let mut sources = Vec::new();
    repository_files(&root().join("src"), &mut sources);
    repository_files(&root().join("python/src"), &mut sources);
    // Unit metadata of dataset files, read by programs like the column names.
    let data_names = root().join("src/study/dataset/index.rs");
    let mut bad = Vec::new();
    let mut literals = 0;
    for p in sources
        .iter()
        .filter(|p| p.extension().is_some_and(|x| x == "rs") && **p != data_names)
    {
        let text = std::fs::read_to_string(p).unwrap();
        for s in string_literals(&text) {
            literals += 1;
            bad.extend(
                ascii_micrometres(&s)
                    .into_iter()
                    .map(|l| format!("{}: {l}", p.display())),
            );
        }
    }
    assert!(
        literals > 1000,
        "{literals} string literals: the scan is broken"
    );
    let mut docs = markdown_files();
    docs.push(root().join("python/README.md"));
    for d in ["python/gearwear", "python/examples"] {
        for e in std::fs::read_dir(root().join(d)).unwrap() {
            let p = e.unwrap().path();
            if p.extension()
                .is_some_and(|x| x == "py" || x == "pyi" || x == "ipynb")
            {
                docs.push(p);
            }
        }
    }
    for p in docs {
        let text = std::fs::read_to_string(&p).unwrap();
        bad.extend(
            ascii_micrometres(&text)
                .into_iter()
                .map(|l| format!("{}: {l}", p.display())),
        );
    }
    assert!(
        bad.is_empty(),
        "`um` where user-facing text writes `µm`:\n{}",
        bad.join("\n")
    );
    // The scanner itself: a unit word is found, names are not.
    assert_eq!(
        ascii_micrometres("wear 5 um, (um) and dte_max_um --limit-um {w}um").len(),
        2
    );
    assert_eq!(
        string_literals("let a = '\"'; // \"x um\"\nlet b = \"5 um\";"),
        vec!["5 um"]
    );
}
