//! No import circles between the top-level modules of a crate.
//!
//! Every `.rs` file under `src/` is read; comments, string and character literals are blanked
//! out, and each `crate::<module>` path (in a `use` — grouped `use crate::{a, b::c}` too — or
//! inline in code) is an edge from the file's top-level module (its first path component under
//! `src/`) to `<module>`. `main.rs` and `lib.rs` are the root, above every module, and take no
//! part. A strongly connected set of two or more modules is a circle: the test fails and lists
//! each circle with one file and line for every edge in it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// One reference from a file to another top-level module.
#[derive(Clone, Debug)]
struct Edge {
    from: String,
    to: String,
    /// `file:line` of the first reference seen.
    at: String,
}

#[test]
fn verify_modules_form_no_circle() {
    assert_no_circle(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"));
}

#[test]
fn solver_modules_form_no_circle() {
    assert_no_circle(&Path::new(env!("CARGO_MANIFEST_DIR")).join("../solver/src"));
}

#[test]
fn the_scanner_sees_through_comments_strings_and_groups() {
    let text = r#"
        use crate::a::X; // crate::b::Y
        /* crate::c /* nested crate::c */ */
        let s = "crate::d"; let r = r"crate::d"; let c = '"'; let l: &'static str = "";
        use crate::{e::Z, f, g::{self, W}};
        fn f() { crate::h::go(); $crate::i::m(); notcrate::j::k(); }
    "#;
    let found: Vec<String> = crate_refs(&strip(text))
        .into_iter()
        .map(|(m, _)| m)
        .collect();
    assert_eq!(found, ["a", "e", "f", "g", "h"]);
}

fn assert_no_circle(src: &Path) {
    let edges = edges_of(src);
    assert!(!edges.is_empty(), "no module references found in {src:?}");
    let circles = circles(&edges);
    assert!(
        circles.is_empty(),
        "import circles between the top-level modules of {}:\n{}",
        src.display(),
        circles.join("\n")
    );
}

/// The files under `dir`, recursively, in a stable order.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display())) {
            let p = entry.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|e| e == "rs") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The top-level module of a file under `src` (`None` for the crate root files).
fn top_module(src: &Path, file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src).unwrap();
    let first = rel.components().next()?.as_os_str().to_string_lossy();
    let name = first.strip_suffix(".rs").unwrap_or(&first).to_string();
    (name != "main" && name != "lib").then_some(name)
}

/// Every edge between two different top-level modules, with where it was first seen.
fn edges_of(src: &Path) -> Vec<Edge> {
    let files = rust_files(src);
    let modules: BTreeSet<String> = files.iter().filter_map(|f| top_module(src, f)).collect();
    let mut edges: BTreeMap<(String, String), String> = BTreeMap::new();
    for file in &files {
        let Some(from) = top_module(src, file) else {
            continue;
        };
        let text = std::fs::read_to_string(file).unwrap();
        for (to, offset) in crate_refs(&strip(&text)) {
            // items of the root (`crate::some_macro`) are not modules
            if to == from || !modules.contains(&to) {
                continue;
            }
            let line = 1 + text[..offset].matches('\n').count();
            let rel = file.strip_prefix(src).unwrap().display().to_string();
            edges
                .entry((from.clone(), to))
                .or_insert(format!("{rel}:{line}"));
        }
    }
    edges
        .into_iter()
        .map(|((from, to), at)| Edge { from, to, at })
        .collect()
}

/// `text` with comments and the contents of string and character literals replaced by spaces
/// (line breaks and byte offsets kept).
fn strip(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = b.to_vec();
    let blank = |out: &mut Vec<u8>, from: usize, to: usize| {
        for c in &mut out[from..to] {
            if *c != b'\n' {
                *c = b' ';
            }
        }
    };
    let mut i = 0;
    while i < b.len() {
        let rest = &b[i..];
        if rest.starts_with(b"//") {
            let end = rest
                .iter()
                .position(|&c| c == b'\n')
                .map_or(b.len(), |k| i + k);
            blank(&mut out, i, end);
            i = end;
        } else if rest.starts_with(b"/*") {
            let (mut depth, mut j) = (0usize, i);
            while j < b.len() {
                if b[j..].starts_with(b"/*") {
                    depth += 1;
                    j += 2;
                } else if b[j..].starts_with(b"*/") {
                    depth -= 1;
                    j += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    j += 1;
                }
            }
            blank(&mut out, i, j);
            i = j;
        } else if let Some(hashes) = raw_string_start(b, i) {
            // r"…", r#"…"#, br"…": ends at a quote followed by the same number of hashes
            let open = i + b[i..].iter().position(|&c| c == b'"').unwrap() + 1;
            let close = format!("\"{}", "#".repeat(hashes)).into_bytes();
            let end = (open..b.len())
                .find(|&j| b[j..].starts_with(&close))
                .map_or(b.len(), |j| j + close.len());
            blank(&mut out, i, end);
            i = end;
        } else if b[i] == b'"' {
            let mut j = i + 1;
            while j < b.len() && b[j] != b'"' {
                j += if b[j] == b'\\' { 2 } else { 1 };
            }
            blank(&mut out, i, (j + 1).min(b.len()));
            i = j + 1;
        } else if b[i] == b'\'' {
            // a character literal ('x', '\n', '"'), or else a lifetime ('a)
            let len = if rest.get(1) == Some(&b'\\') {
                rest.iter().skip(2).position(|&c| c == b'\'').map(|k| k + 3)
            } else {
                let c = text[i + 1..].chars().next().map_or(1, char::len_utf8);
                (rest.get(1 + c) == Some(&b'\'')).then_some(2 + c)
            };
            let len = len.unwrap_or(1);
            blank(&mut out, i, i + len);
            i += len;
        } else {
            i += 1;
        }
    }
    String::from_utf8(out).expect("only ASCII bytes were replaced")
}

/// The number of `#` of a raw string literal starting at `i`, if one does.
fn raw_string_start(b: &[u8], i: usize) -> Option<usize> {
    if i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_') {
        return None;
    }
    let j = i + usize::from(b[i] == b'b');
    if b.get(j) != Some(&b'r') {
        return None;
    }
    let hashes = b[j + 1..].iter().take_while(|&&c| c == b'#').count();
    (b.get(j + 1 + hashes) == Some(&b'"')).then_some(hashes)
}

/// The modules named right after `crate::` in stripped source, with their byte offsets.
fn crate_refs(code: &str) -> Vec<(String, usize)> {
    let b = code.as_bytes();
    let mut out = Vec::new();
    for (at, _) in code.match_indices("crate::") {
        let before = at.checked_sub(1).map(|k| b[k]);
        if before.is_some_and(|c| c.is_ascii_alphanumeric() || c == b'_' || c == b'$') {
            continue;
        }
        let after = at + "crate::".len();
        if b.get(after) == Some(&b'{') {
            out.extend(group_heads(code, after));
        } else if let Some(name) = ident_at(code, after) {
            out.push((name, after));
        }
    }
    out
}

/// The first segment of every path in the `{…}` group opening at `open`.
fn group_heads(code: &str, open: usize) -> Vec<(String, usize)> {
    let b = code.as_bytes();
    let mut out = Vec::new();
    let (mut depth, mut expect_head) = (0usize, true);
    for (i, &c) in b.iter().enumerate().skip(open) {
        match c {
            b'{' => {
                depth += 1;
                expect_head = depth == 1;
            }
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    break;
                }
            }
            b',' => expect_head = depth == 1,
            _ if expect_head && (c.is_ascii_alphabetic() || c == b'_') => {
                expect_head = false;
                if let Some(name) = ident_at(code, i) {
                    if name != "self" {
                        out.push((name, i));
                    }
                }
            }
            _ => {}
        }
    }
    out
}

/// The identifier starting at byte `i`, if any.
fn ident_at(code: &str, i: usize) -> Option<String> {
    let name: String = code[i..]
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect();
    (!name.is_empty()).then_some(name)
}

/// Every circle, as one line per cycle: for each edge `a → b` that has a way back from `b` to
/// `a`, the shortest such cycle, with the file and line behind each of its edges (rotations of
/// the same cycle listed once).
fn circles(edges: &[Edge]) -> Vec<String> {
    let mut next: BTreeMap<&str, Vec<&Edge>> = BTreeMap::new();
    for e in edges {
        next.entry(&e.from).or_default().push(e);
    }
    let mut seen = BTreeSet::new();
    let mut out = Vec::new();
    for e in edges {
        let Some(back) = shortest_path(&next, &e.to, &e.from) else {
            continue;
        };
        let mut cycle: Vec<&Edge> = vec![e];
        cycle.extend(back);
        // the same cycle entered at another module is the same circle
        let start = (0..cycle.len()).min_by_key(|&k| &cycle[k].from).unwrap();
        cycle.rotate_left(start);
        let names: Vec<&str> = cycle.iter().map(|e| e.from.as_str()).collect();
        if seen.insert(names.join(" ")) {
            let via: Vec<String> = cycle.iter().map(|e| e.at.clone()).collect();
            out.push(format!(
                "  {} → {}   ({})",
                names.join(" → "),
                names[0],
                via.join(", ")
            ));
        }
    }
    out
}

/// The edges of a shortest path from `from` to `to` (breadth-first), if there is one.
fn shortest_path<'e>(
    next: &BTreeMap<&str, Vec<&'e Edge>>,
    from: &str,
    to: &str,
) -> Option<Vec<&'e Edge>> {
    let mut came_by: BTreeMap<&str, &Edge> = BTreeMap::new();
    let mut queue = std::collections::VecDeque::from([from]);
    while let Some(m) = queue.pop_front() {
        if m == to {
            let mut path = Vec::new();
            let mut at = to;
            while at != from {
                let e = came_by[at];
                path.push(e);
                at = &e.from;
            }
            path.reverse();
            return Some(path);
        }
        for e in next.get(m).into_iter().flatten() {
            if e.to != from && !came_by.contains_key(e.to.as_str()) {
                came_by.insert(&e.to, e);
                queue.push_back(&e.to);
            }
        }
    }
    None
}
