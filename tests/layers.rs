//! The house's layering, checked on the sources (issue 28).
//!
//! The layer order is written down once, in the table of docs/ARCHITECTURE.md between the
//! `layers:begin` and `layers:end` markers: one module of `src/` per row, the ground
//! first. This test reads that table, parses every `crate::`, `super::`, `self::` and
//! `gearwear::` path of every file of `src/` (comments, strings and `#[cfg(test)]` items
//! left out), and fails
//! - on an import that runs up: a file of one module naming a module of a later row (the
//!   message names the file, the line and both modules with their rows);
//! - on a circle between files: files that import each other, directly or round a loop
//!   (edges into a module's root file, `mod.rs` or `a.rs` beside `a/`, are left out, so
//!   that re-exports do not count; nor do edges between a module and its own parent);
//! - on a module of `src/` missing from the table, or a row naming no module.
//!
//! The checker works on file texts, so the tests at the end run it on small made-up
//! trees and show that each rule can fail.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A module path inside the crate: `["dynamics", "model"]`; the crate root is empty.
type ModPath = Vec<String>;

/// One import found in a file.
struct Import {
    line: usize,
    target: ModPath,
}

/// The layer table: module name -> row (0 = the ground's first row).
fn read_layer_table(doc: &str) -> Vec<String> {
    let begin = doc
        .find("layers:begin")
        .expect("docs/ARCHITECTURE.md: no layers:begin marker");
    let end = doc
        .find("layers:end")
        .expect("docs/ARCHITECTURE.md: no layers:end marker");
    let mut rows = Vec::new();
    for line in doc[begin..end].lines() {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        // | row | `module` | floor | what it holds |
        if cells.len() < 4 || cells[1].parse::<usize>().is_err() {
            continue;
        }
        let name = cells[2].trim_matches('`').to_string();
        assert_eq!(
            cells[1].parse::<usize>().unwrap(),
            rows.len() + 1,
            "docs/ARCHITECTURE.md: the layer rows must be numbered 1, 2, ... in order (at {name})"
        );
        rows.push(name);
    }
    assert!(
        !rows.is_empty(),
        "docs/ARCHITECTURE.md: the layer table has no rows"
    );
    rows
}

/// The module path of a file, from its path relative to `src/`.
fn module_of(rel: &str) -> ModPath {
    let mut segs: Vec<String> = rel
        .trim_end_matches(".rs")
        .split('/')
        .map(String::from)
        .collect();
    if segs.last().map(String::as_str) == Some("mod") {
        segs.pop();
    }
    if segs.len() == 1 && (segs[0] == "lib" || segs[0] == "main") {
        segs.clear();
    }
    segs
}

/// The text with comments removed and string and character literals emptied; newlines
/// are kept, so positions still give line numbers.
fn strip_comments_and_literals(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    let blank = |ch: char| if ch == '\n' { '\n' } else { ' ' };
    while i < c.len() {
        let next = c.get(i + 1).copied();
        if c[i] == '/' && next == Some('/') {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if c[i] == '/' && next == Some('*') {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    out.push(blank(c[i]));
                    i += 1;
                }
            }
        } else if c[i] == 'r'
            && (next == Some('"') || next == Some('#'))
            && !ident_char_before(&c, i)
        {
            // Raw string r"..." or r#"..."#.
            let mut j = i + 1;
            let mut hashes = 0;
            while c.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            if c.get(j) != Some(&'"') {
                out.push(c[i]);
                i += 1;
                continue;
            }
            j += 1;
            out.push_str("\"\"");
            while j < c.len() {
                if c[j] == '"' && (0..hashes).all(|k| c.get(j + 1 + k) == Some(&'#')) {
                    j += 1 + hashes;
                    break;
                }
                if c[j] == '\n' {
                    out.push('\n');
                }
                j += 1;
            }
            i = j;
        } else if c[i] == '"' {
            out.push_str("\"\"");
            i += 1;
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' {
                    i += 1;
                }
                if i < c.len() && c[i] == '\n' {
                    out.push('\n');
                }
                i += 1;
            }
            i += 1;
        } else if c[i] == '\'' {
            // A character literal ('x', '\n', '\u{..}') or a lifetime ('a).
            if next == Some('\\') {
                i += 2;
                while i < c.len() && c[i] != '\'' {
                    i += 1;
                }
                i += 1;
                out.push_str("' '");
            } else if c.get(i + 2) == Some(&'\'') {
                i += 3;
                out.push_str("' '");
            } else {
                out.push('\'');
                i += 1;
            }
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    out
}

fn ident_char_before(c: &[char], i: usize) -> bool {
    i > 0 && (c[i - 1].is_alphanumeric() || c[i - 1] == '_')
}

/// The text with every `#[cfg(test)]` item cut out (up to its `;` or its matching `}`).
fn without_test_items(text: &str) -> String {
    let mut s = text.to_string();
    while let Some(at) = s.find("#[cfg(test)]") {
        let b: Vec<(usize, char)> = s[at..].char_indices().collect();
        let mut depth = 0usize;
        let mut end = s.len();
        for &(k, ch) in &b {
            match ch {
                ';' if depth == 0 => {
                    end = at + k + 1;
                    break;
                }
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = at + k + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        // Keep the newlines so that later line numbers stay right.
        let newlines = s[at..end].matches('\n').count();
        s.replace_range(at..end, &"\n".repeat(newlines));
    }
    s
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    Path, // ::
    Open,
    Close,
    Comma,
    Star,
    Other,
}

fn tokens(text: &str) -> Vec<(Tok, usize)> {
    let c: Vec<char> = text.chars().collect();
    let (mut i, mut line, mut out) = (0, 1, Vec::new());
    while i < c.len() {
        let ch = c[i];
        if ch == '\n' {
            line += 1;
            i += 1;
        } else if ch.is_whitespace() {
            i += 1;
        } else if ch.is_alphanumeric() || ch == '_' {
            let start = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            out.push((Tok::Ident(c[start..i].iter().collect()), line));
        } else if ch == ':' && c.get(i + 1) == Some(&':') {
            out.push((Tok::Path, line));
            i += 2;
        } else {
            let t = match ch {
                '{' => Tok::Open,
                '}' => Tok::Close,
                ',' => Tok::Comma,
                '*' => Tok::Star,
                _ => Tok::Other,
            };
            out.push((t, line));
            i += 1;
        }
    }
    out
}

/// Reads one path tree from `toks[*i]` on (after its first segment was taken into
/// `prefix`), pushing each full path with the line of its first segment.
fn read_tree(
    toks: &[(Tok, usize)],
    i: &mut usize,
    prefix: Vec<String>,
    line: usize,
    out: &mut Vec<(Vec<String>, usize)>,
) {
    let mut path = prefix;
    loop {
        if toks.get(*i).map(|t| &t.0) != Some(&Tok::Path) {
            out.push((path, line));
            return;
        }
        *i += 1;
        match toks.get(*i).map(|t| t.0.clone()) {
            Some(Tok::Ident(name)) => {
                *i += 1;
                path.push(name);
            }
            Some(Tok::Open) => {
                *i += 1;
                loop {
                    match toks.get(*i).map(|t| t.0.clone()) {
                        Some(Tok::Close) | None => {
                            *i += 1;
                            return;
                        }
                        Some(Tok::Comma) => *i += 1,
                        Some(Tok::Ident(name)) => {
                            let l = toks[*i].1;
                            *i += 1;
                            let mut p = path.clone();
                            if name != "self" {
                                p.push(name);
                            }
                            read_tree(toks, i, p, l, out);
                        }
                        Some(Tok::Star) => {
                            *i += 1;
                            out.push((path.clone(), line));
                        }
                        Some(_) => *i += 1,
                    }
                }
            }
            _ => {
                out.push((path, line));
                return;
            }
        }
    }
}

/// Every path starting at `crate`, `super`, `self` or `gearwear`, with its line.
fn crate_paths(text: &str) -> Vec<(Vec<String>, usize)> {
    let toks = tokens(text);
    let mut out = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        let (t, line) = &toks[i];
        let preceded_by_path = i > 0 && toks[i - 1].0 == Tok::Path;
        match t {
            Tok::Ident(n)
                if !preceded_by_path
                    && matches!(n.as_str(), "crate" | "super" | "self" | "gearwear")
                    && toks.get(i + 1).map(|t| &t.0) == Some(&Tok::Path) =>
            {
                let (start, line) = (n.clone(), *line);
                i += 1;
                read_tree(&toks, &mut i, vec![start], line, &mut out);
            }
            _ => i += 1,
        }
    }
    out
}

/// The module a path names: the longest prefix of it that is a module of the crate.
fn resolve(path: &[String], here: &ModPath, modules: &BTreeSet<ModPath>) -> Option<ModPath> {
    let (mut base, mut rest): (ModPath, &[String]) = match path[0].as_str() {
        "crate" | "gearwear" => (Vec::new(), &path[1..]),
        "self" | "super" => (here.clone(), path),
        _ => return None,
    };
    while let Some(first) = rest.first() {
        match first.as_str() {
            "super" => {
                base.pop();
            }
            "self" => {}
            _ => break,
        }
        rest = &rest[1..];
    }
    (0..=rest.len())
        .rev()
        .map(|k| {
            let mut m = base.clone();
            m.extend(rest[..k].iter().cloned());
            m
        })
        .find(|m| modules.contains(m))
}

/// The imports of each file: module path -> (file name, imports).
fn import_graph(files: &BTreeMap<String, String>) -> BTreeMap<ModPath, (String, Vec<Import>)> {
    let modules: BTreeSet<ModPath> = files.keys().map(|f| module_of(f)).collect();
    let mut graph = BTreeMap::new();
    for (name, text) in files {
        let here = module_of(name);
        let clean = without_test_items(&strip_comments_and_literals(text));
        let imports = crate_paths(&clean)
            .into_iter()
            .filter_map(|(p, line)| {
                resolve(&p, &here, &modules).map(|target| Import { line, target })
            })
            .filter(|im| im.target != here)
            .collect();
        graph.insert(here, (name.clone(), imports));
    }
    graph
}

/// Imports that run up the layer table, and modules the table does not place.
fn upward_imports(
    graph: &BTreeMap<ModPath, (String, Vec<Import>)>,
    rows: &[String],
) -> Vec<String> {
    let row = |m: &str| rows.iter().position(|r| r == m);
    let mut problems = Vec::new();
    let tops: BTreeSet<&String> = graph.keys().filter_map(|m| m.first()).collect();
    for t in &tops {
        if row(t).is_none() {
            problems.push(format!(
                "module `{t}` of src/ has no row in the layer table"
            ));
        }
    }
    for r in rows {
        if !tops.contains(r) {
            problems.push(format!(
                "the layer table's row `{r}` names no module of src/"
            ));
        }
    }
    for (here, (file, imports)) in graph {
        let Some(from) = here.first() else { continue };
        for im in imports {
            let Some(to) = im.target.first() else {
                continue;
            };
            if let (Some(a), Some(b)) = (row(from), row(to)) {
                if b > a {
                    problems.push(format!(
                        "src/{file}:{}: `{from}` (row {}) imports `{}` (row {}): an import that runs up a layer",
                        im.line,
                        a + 1,
                        im.target.join("::"),
                        b + 1
                    ));
                }
            }
        }
    }
    problems
}

/// Circles between files (strongly connected sets of more than one file).
fn file_circles(graph: &BTreeMap<ModPath, (String, Vec<Import>)>) -> Vec<Vec<String>> {
    let nodes: Vec<&ModPath> = graph.keys().collect();
    let roots: BTreeSet<&ModPath> = nodes
        .iter()
        .copied()
        .filter(|m| nodes.iter().any(|k| k.len() > m.len() && k.starts_with(m)))
        .collect();
    let index: BTreeMap<&ModPath, usize> = nodes.iter().enumerate().map(|(i, m)| (*m, i)).collect();
    let adj: Vec<BTreeSet<usize>> = nodes
        .iter()
        .map(|a| {
            graph[*a]
                .1
                .iter()
                .map(|im| &im.target)
                .filter(|b| !roots.contains(b) && !a.starts_with(b) && !b.starts_with(a))
                .filter_map(|b| index.get(b).copied())
                .collect()
        })
        .collect();
    strongly_connected(&adj)
        .into_iter()
        .filter(|c| c.len() > 1)
        .map(|c| {
            let mut names: Vec<String> = c.iter().map(|&i| nodes[i].join("::")).collect();
            names.sort();
            names
        })
        .collect()
}

/// Tarjan's strongly connected components (iterative).
fn strongly_connected(adj: &[BTreeSet<usize>]) -> Vec<Vec<usize>> {
    let n = adj.len();
    let (mut index, mut low, mut on) = (vec![usize::MAX; n], vec![0; n], vec![false; n]);
    let (mut stack, mut out, mut next) = (Vec::new(), Vec::new(), 0);
    for root in 0..n {
        if index[root] != usize::MAX {
            continue;
        }
        let mut work: Vec<(usize, Vec<usize>)> = vec![(root, adj[root].iter().copied().collect())];
        index[root] = next;
        low[root] = next;
        next += 1;
        stack.push(root);
        on[root] = true;
        while let Some((v, pending)) = work.last_mut() {
            let v = *v;
            if let Some(w) = pending.pop() {
                if index[w] == usize::MAX {
                    index[w] = next;
                    low[w] = next;
                    next += 1;
                    stack.push(w);
                    on[w] = true;
                    work.push((w, adj[w].iter().copied().collect()));
                } else if on[w] {
                    low[v] = low[v].min(index[w]);
                }
            } else {
                work.pop();
                if let Some((u, _)) = work.last() {
                    low[*u] = low[*u].min(low[v]);
                }
                if low[v] == index[v] {
                    let mut comp = Vec::new();
                    while let Some(w) = stack.pop() {
                        on[w] = false;
                        comp.push(w);
                        if w == v {
                            break;
                        }
                    }
                    out.push(comp);
                }
            }
        }
    }
    out
}

fn read_tree_of_files(dir: &Path, rel: &str, out: &mut BTreeMap<String, String>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        let name = p.file_name().unwrap().to_string_lossy().to_string();
        let r = if rel.is_empty() {
            name.clone()
        } else {
            format!("{rel}/{name}")
        };
        if p.is_dir() {
            read_tree_of_files(&p, &r, out);
        } else if name.ends_with(".rs") && !name.starts_with("tests_") {
            out.insert(r, std::fs::read_to_string(&p).unwrap());
        }
    }
}

fn source_files() -> BTreeMap<String, String> {
    let mut files = BTreeMap::new();
    read_tree_of_files(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("src"),
        "",
        &mut files,
    );
    files
}

fn layer_rows() -> Vec<String> {
    let doc =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/ARCHITECTURE.md"))
            .unwrap();
    read_layer_table(&doc)
}

#[test]
fn no_import_runs_up_a_layer() {
    let problems = upward_imports(&import_graph(&source_files()), &layer_rows());
    assert!(
        problems.is_empty(),
        "{} layering problem(s):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// No two files import each other, directly or around a longer circle: the names two
/// files share belong to the file that owns their concept (issue 28 opened the last
/// circles; none may come back).
#[test]
fn no_two_files_import_each_other() {
    let found: Vec<String> = file_circles(&import_graph(&source_files()))
        .iter()
        .map(|c| c.join(" <-> "))
        .collect();
    assert!(
        found.is_empty(),
        "import circle(s) between files: {found:?}; move the shared names into the file that owns the concept"
    );
}

// The checker itself, on made-up trees.

fn tree(files: &[(&str, &str)]) -> BTreeMap<String, String> {
    files
        .iter()
        .map(|(n, t)| (n.to_string(), t.to_string()))
        .collect()
}

fn rows(names: &[&str]) -> Vec<String> {
    names.iter().map(|s| s.to_string()).collect()
}

#[test]
fn an_upward_import_is_named_with_its_file_line_and_rows() {
    let files = tree(&[
        ("lib.rs", "pub mod config;\npub mod study;\n"),
        ("config/mod.rs", "pub mod case;\n"),
        (
            "config/case.rs",
            "//! doc\n\nuse crate::study::plan::Plan; // runs up\n",
        ),
        ("study/mod.rs", "pub mod plan;\n"),
        ("study/plan.rs", "use crate::config::case::Case;\n"),
    ]);
    let p = upward_imports(&import_graph(&files), &rows(&["config", "study"]));
    assert_eq!(p.len(), 1, "{p:?}");
    assert!(
        p[0].starts_with("src/config/case.rs:3: `config` (row 1) imports `study::plan` (row 2)"),
        "{}",
        p[0]
    );
}

#[test]
fn paths_in_groups_super_and_expressions_are_followed_and_comments_strings_tests_are_not() {
    let files = tree(&[
        ("lib.rs", ""),
        ("a/mod.rs", "pub mod x;\n"),
        (
            "a/x.rs",
            "use crate::{b::{self, y}, c};\nfn f() { let _ = super::super::d::z::go(); }\n// crate::e::w\nconst S: &str = \"crate::e::w\";\nconst C: char = '\"';\n#[cfg(test)]\nmod tests { use crate::e::w; }\n",
        ),
        ("b/mod.rs", "pub mod y;\n"),
        ("b/y.rs", ""),
        ("c.rs", ""),
        ("d/mod.rs", "pub mod z;\n"),
        ("d/z.rs", ""),
        ("e/mod.rs", "pub mod w;\n"),
        ("e/w.rs", ""),
    ]);
    let g = import_graph(&files);
    let targets: BTreeSet<String> = g[&vec!["a".to_string(), "x".to_string()]]
        .1
        .iter()
        .map(|i| i.target.join("::"))
        .collect();
    let want: BTreeSet<String> = ["b", "b::y", "c", "d::z"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(targets, want);
    let p = upward_imports(&g, &rows(&["b", "c", "d", "e", "a"]));
    assert!(p.is_empty(), "{p:?}");
    let p = upward_imports(&g, &rows(&["a", "b", "c", "d", "e"]));
    assert_eq!(p.len(), 4, "{p:?}");
}

#[test]
fn a_circle_between_files_is_found_and_a_reexport_is_not_one() {
    let files = tree(&[
        ("lib.rs", ""),
        ("m/mod.rs", "pub mod p;\npub mod q;\npub use p::P;\n"),
        ("m/p.rs", "use super::q::Q;\n"),
        ("m/q.rs", "use super::p::P;\n"),
        ("n/mod.rs", "pub mod r;\npub use r::R;\n"),
        ("n/r.rs", "use crate::n::R;\n"),
    ]);
    let c = file_circles(&import_graph(&files));
    assert_eq!(c, vec![vec!["m::p".to_string(), "m::q".to_string()]]);
}

#[test]
fn a_module_missing_from_the_table_is_named() {
    let files = tree(&[("lib.rs", ""), ("a.rs", ""), ("b.rs", "")]);
    let p = upward_imports(&import_graph(&files), &rows(&["a", "c"]));
    assert_eq!(p.len(), 2, "{p:?}");
}
