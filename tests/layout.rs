//! The stages import only what comes before them. The pipeline is
//! `source → syntax → eval → scene → build → render → output`, where `scene`
//! is plain data that `eval` produces (so `eval` imports `scene`, and `scene`
//! imports no stage), and `pattern` is the runtime code `eval`, `build` and
//! `render` share (what a pattern, pigment or function is worth at a point,
//! on scene data only). This test reads the sources and fails when a file
//! names a module its stage may not use, so a backward import cannot come
//! back unnoticed.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The top-level modules a stage may name, besides the shared ones
/// ([`SHARED`]) and itself.
const ALLOWED: &[(&str, &[&str])] = &[
    ("syntax", &[]),
    ("scene", &[]),
    ("pattern", &["scene"]),
    ("build", &["scene", "pattern"]),
    ("eval", &["syntax", "scene", "pattern"]),
    ("render", &["scene", "pattern", "build"]),
    ("output", &["render"]),
];

/// Modules every stage may use: diagnostics, spans and sources, safe file
/// access and memory accounting. They import no stage themselves.
const SHARED: &[&str] = &["diag", "span", "source", "files", "memory"];

/// Every top-level module of the library: a name outside this list in a
/// `crate::` path means the list (or the test) is out of date.
const MODULES: &[&str] = &[
    "syntax", "eval", "scene", "pattern", "build", "render", "output", "diag", "span", "source",
    "files", "memory", "ide",
];

/// Imports that break the order on purpose, each with its reason: the file,
/// the module it names. A listed import that is gone fails the test too, so
/// the list only shrinks.
const KNOWN_EXCEPTIONS: &[(&str, &str, &str)] = &[
    // `trace`, `inside`, `min_extent` and `max_extent` ask for an object's
    // geometry while the scene is read (as in POV-Ray): they build it.
    (
        "src/eval/core/trace.rs",
        "build",
        "trace() builds the object it shoots at",
    ),
    // The readers of these shapes check and store their outlines with the
    // curve code the intersection uses, so both agree on what a point list means.
    (
        "src/eval/objects/shapes.rs",
        "build",
        "prism outlines, poly term counts",
    ),
    ("src/eval/objects/revolve.rs", "build", "lathe segments"),
    (
        "src/eval/objects/text.rs",
        "build",
        "glyph outlines from the font reader",
    ),
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// The source without comments, string and character literals (so words in
/// documentation or messages do not count as imports).
fn code_only(src: &str) -> String {
    let b = src.as_bytes();
    let mut out = String::with_capacity(src.len());
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                let mut depth = 0;
                while i < b.len() {
                    if b[i..].starts_with(b"/*") {
                        depth += 1;
                        i += 2;
                    } else if b[i..].starts_with(b"*/") {
                        depth -= 1;
                        i += 2;
                        if depth == 0 {
                            break;
                        }
                    } else {
                        i += 1;
                    }
                }
                out.push(' ');
            }
            b'r' if matches!(b.get(i + 1), Some(b'"' | b'#'))
                && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_')) =>
            {
                // A raw string: r"…", r#"…"#.
                let mut j = i + 1;
                let mut hashes = 0;
                while b.get(j) == Some(&b'#') {
                    hashes += 1;
                    j += 1;
                }
                if b.get(j) != Some(&b'"') {
                    out.push('r');
                    i += 1;
                    continue;
                }
                let close: Vec<u8> = std::iter::once(b'"')
                    .chain(std::iter::repeat_n(b'#', hashes))
                    .collect();
                j += 1;
                while j < b.len() && !b[j..].starts_with(&close) {
                    j += 1;
                }
                i = j + close.len();
                out.push_str("\"\"");
            }
            b'"' => {
                i += 1;
                while i < b.len() && b[i] != b'"' {
                    if b[i] == b'\\' {
                        i += 1;
                    }
                    i += 1;
                }
                i += 1;
                out.push_str("\"\"");
            }
            b'\'' => {
                // A character literal ('x', '\n', '\u{…}') or a lifetime ('a).
                let end = if b.get(i + 1) == Some(&b'\\') {
                    b[i + 3..]
                        .iter()
                        .position(|&c| c == b'\'')
                        .map(|k| i + 3 + k)
                } else if b.get(i + 2) == Some(&b'\'') {
                    Some(i + 2)
                } else {
                    None
                };
                match end {
                    Some(e) => {
                        out.push_str("' '");
                        i = e + 1;
                    }
                    None => {
                        out.push('\'');
                        i += 1;
                    }
                }
            }
            _ => {
                let len = src[i..].chars().next().map_or(1, char::len_utf8);
                out.push_str(&src[i..i + len]);
                i += len;
            }
        }
    }
    out
}

fn ident_at(s: &str) -> &str {
    let end = s
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    &s[..end]
}

/// The top-level names inside a `{ … }` group at the start of `s` (nested
/// groups belong to the name before them).
fn group_heads(s: &str) -> Vec<String> {
    let mut heads = Vec::new();
    let mut depth = 0;
    let mut start = true;
    for (i, c) in s.char_indices() {
        match c {
            '{' => {
                depth += 1;
                start = depth == 1;
            }
            '}' => {
                depth -= 1;
                if depth == 0 {
                    break;
                }
            }
            ',' if depth == 1 => start = true,
            c if depth == 1 && start && !c.is_whitespace() => {
                heads.push(ident_at(&s[i..]).to_string());
                start = false;
            }
            _ => {}
        }
    }
    heads
}

/// The module path of a file under `src/` (`src/render/path/lights.rs` →
/// `["render", "path", "lights"]`; `mod.rs` is its folder).
fn module_path(rel: &Path) -> Vec<String> {
    let mut parts: Vec<String> = rel
        .iter()
        .skip(1)
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    let last = parts.pop().expect("a file");
    let stem = last.trim_end_matches(".rs");
    if stem != "mod" && stem != "lib" {
        parts.push(stem.to_string());
    }
    parts
}

/// The byte ranges of the inline modules (`mod NAME { … }`) in `code`.
fn inline_module_depths(code: &str) -> Vec<(usize, usize)> {
    let mut ranges = Vec::new();
    let mut open: Vec<Option<usize>> = Vec::new();
    for (i, c) in code.char_indices() {
        match c {
            '{' => {
                let before = code[..i].trim_end();
                let name_start = before
                    .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .map_or(0, |k| k + 1);
                let is_mod =
                    before[..name_start].trim_end().ends_with("mod") && name_start < before.len();
                open.push(is_mod.then_some(i));
            }
            '}' => {
                if let Some(Some(start)) = open.pop() {
                    ranges.push((start, i));
                }
            }
            _ => {}
        }
    }
    ranges
}

/// Every top-level module `code` (the file at module path `path`) names.
fn named_modules(code: &str, path: &[String]) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    let boundary = |i: usize| {
        i == 0 || {
            let c = code.as_bytes()[i - 1];
            !(c.is_ascii_alphanumeric() || c == b'_' || c == b':')
        }
    };
    for (i, _) in code.match_indices("crate::") {
        if !boundary(i) {
            continue;
        }
        let rest = code[i + "crate::".len()..].trim_start();
        if rest.starts_with('{') {
            found.extend(group_heads(rest));
        } else {
            found.insert(ident_at(rest).to_string());
        }
    }
    // `super::super::…` past the top of the stage reaches the crate root
    // (counting the inline modules, such as `mod tests { … }`, it is in).
    let inline = inline_module_depths(code);
    for (i, _) in code.match_indices("super::") {
        if !boundary(i) {
            continue;
        }
        let depth = path.len() + inline.iter().filter(|(a, b)| *a < i && i < *b).count();
        let mut rest = &code[i..];
        let mut ups = 0;
        while let Some(r) = rest.strip_prefix("super::") {
            ups += 1;
            rest = r.trim_start();
        }
        if ups >= depth {
            if rest.starts_with('{') {
                found.extend(group_heads(rest));
            } else {
                found.insert(ident_at(rest).to_string());
            }
        }
    }
    found.retain(|m| !m.is_empty() && m != "self");
    found
}

#[test]
fn no_stage_imports_a_later_one() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    let mut errors = Vec::new();
    let mut exceptions_used = BTreeSet::new();
    let mut checked = 0;
    for file in &files {
        let rel = file.strip_prefix(root).expect("under the crate");
        let rel_str = rel.to_string_lossy().replace('\\', "/");
        let path = module_path(rel);
        let Some(stage) = path.first() else { continue };
        if stage == "main" || stage == "cli" {
            // The binary: its `crate::` is another crate, and it uses anything.
            continue;
        }
        let src = std::fs::read_to_string(file).expect("readable source");
        let named = named_modules(&code_only(&src), &path);
        for m in &named {
            assert!(
                MODULES.contains(&m.as_str()),
                "{rel_str} names crate::{m}, which this test does not know: add it to MODULES (and to ALLOWED if it is a stage)"
            );
        }
        let allowed: Option<&[&str]> = if SHARED.contains(&stage.as_str()) {
            Some(&[])
        } else {
            ALLOWED.iter().find(|(s, _)| s == stage).map(|(_, a)| *a)
        };
        let Some(allowed) = allowed else {
            // The editor analysis (`ide`) uses anything.
            continue;
        };
        checked += 1;
        for m in named {
            if m == *stage || SHARED.contains(&m.as_str()) || allowed.contains(&m.as_str()) {
                continue;
            }
            if KNOWN_EXCEPTIONS
                .iter()
                .any(|(f, t, _)| *f == rel_str && *t == m)
            {
                exceptions_used.insert((rel_str.clone(), m));
                continue;
            }
            errors.push(format!(
                "{rel_str}: `{stage}` imports `crate::{m}` (it may use {allowed:?} and {SHARED:?})"
            ));
        }
    }
    assert!(
        checked > 100,
        "only {checked} files were checked: is src/ where it was?"
    );
    for (f, t, why) in KNOWN_EXCEPTIONS {
        if !exceptions_used.contains(&(f.to_string(), t.to_string())) {
            errors.push(format!(
                "{f} no longer imports `crate::{t}` ({why}): remove it from KNOWN_EXCEPTIONS"
            ));
        }
    }
    assert!(
        errors.is_empty(),
        "imports against the pipeline order:\n{}",
        errors.join("\n")
    );
}

#[test]
fn the_reader_of_imports_sees_what_it_should() {
    let path = [
        "render".to_string(),
        "path".to_string(),
        "lights".to_string(),
    ];
    let code = code_only(
        "use crate::{scene::Light, build::{World, Ray}};\n\
         // use crate::eval::X;\n\
         let s = \"crate::output\";\n\
         let c = '\"'; let r = r#\"crate::cli\"#;\n\
         fn f<'a>(x: &'a str) { super::super::super::ide::go(); super::shade::g(); }\n\
         mod tests { fn t() { super::super::super::Render::x(); super::super::super::super::diag::y(); } }\n\
         let v = crate::pattern::noise; let q = '\\''; let e = crate::output;",
    );
    let found: Vec<String> = named_modules(&code, &path).into_iter().collect();
    assert_eq!(
        found,
        ["build", "diag", "ide", "output", "pattern", "scene"]
    );
    assert_eq!(
        module_path(Path::new("src/eval/core/mod.rs")),
        ["eval", "core"]
    );
    assert_eq!(module_path(Path::new("src/lib.rs")), Vec::<String>::new());
}
