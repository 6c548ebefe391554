//! The language's words have one source each, and everything that names a word
//! agrees with it. The grammar's keyword rule is generated from
//! `syntax::keywords::KEYWORDS` (checked in `syntax`), the VS Code grammar from
//! it and the built-in names (`tests/lsp.rs`), the hover documentation covers
//! both (`ide::docs`). This test reads the evaluator's sources and fails when
//! it matches or lists a word the grammar can never produce: a keyword the
//! reader accepts but nobody can write (as `dispersion_samples` once was).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
fn sources(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).expect("source folder") {
            let p = e.expect("entry").path();
            if p.is_dir() {
                todo.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The string literals of `text` (no escapes: the words are plain).
fn literals(text: &str) -> Vec<&str> {
    text.split('"').skip(1).step_by(2).collect()
}

/// The words a source file matches as keywords (`Tok::Kw("a" | "b", …)`) and
/// lists in `const NAME: &[&str] = &[…]` tables.
fn words_named(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find("Tok::Kw(") {
        rest = &rest[i + "Tok::Kw(".len()..];
        // The pattern's literals run up to the first `,` or `)` outside a string.
        let end = rest.find([',', ')']).unwrap_or(rest.len());
        let head = &rest[..end];
        if head.trim_start().starts_with('"') {
            out.extend(literals(head).into_iter().map(str::to_string));
        }
    }
    let mut rest = text;
    while let Some(i) = rest.find(": &[&str] = &[") {
        rest = &rest[i..];
        let end = rest.find("];").expect("end of a word table");
        // Tables of other strings (folders, file names) are not words.
        let table = literals(&rest[..end]);
        let is_word = |w: &&str| {
            w.bytes()
                .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_')
        };
        if table.iter().all(is_word) {
            out.extend(table.into_iter().map(str::to_string));
        }
        rest = &rest[end..];
    }
    out
}

/// The POV-Ray words rts knows it does not implement and does not reserve
/// (`POV_KEYWORDS_NOT_YET` in the evaluator), read from its source.
fn not_reserved(root: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(root.join("src/eval/core/exprs.rs")).expect("exprs.rs");
    let i = text
        .find("const POV_KEYWORDS_NOT_YET")
        .expect("POV_KEYWORDS_NOT_YET in exprs.rs");
    let end = i + text[i..].find("];").expect("end");
    literals(&text[i..end])
        .into_iter()
        .map(str::to_string)
        .collect()
}

/// Directive names (read after `#`, not by the keyword rule).
const DIRECTIVES: &[&str] = &[
    "declare", "local", "undef", "if", "ifdef", "ifndef", "else", "elseif", "end", "while", "for",
    "macro", "switch", "case", "range", "break", "include", "debug", "warning", "error", "default",
    "version", "fopen", "fclose", "read", "write",
];

/// Words the grammar reads outside the keyword rule: colour keywords.
const COLOUR_WORDS: &[&str] = &[
    "color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft", "red",
    "green", "blue", "gray", "grey",
];

#[test]
fn every_word_the_evaluator_names_can_be_written() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let keywords = rts::syntax::keywords::KEYWORDS;
    let later = not_reserved(root);
    let mut unwritable: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut named = 0;
    for file in sources(&root.join("src/eval")) {
        let text = std::fs::read_to_string(&file).expect("source");
        for w in words_named(&text) {
            named += 1;
            let writable = keywords.binary_search(&w.as_str()).is_ok()
                || rts::eval::BUILTIN_NAMES.contains(&w.as_str())
                || COLOUR_WORDS.contains(&w.as_str())
                || DIRECTIVES.contains(&w.as_str())
                || later.contains(&w);
            if !writable {
                let rel = file.strip_prefix(root).unwrap_or(&file);
                unwritable
                    .entry(w)
                    .or_default()
                    .push(rel.display().to_string());
            }
        }
    }
    assert!(
        named > 500,
        "only {named} words found: the scan no longer reads the evaluator"
    );
    assert!(
        unwritable.is_empty(),
        "the evaluator names words the grammar never produces (add them to \
         src/syntax/keywords.rs, then run `RTS_BLESS=1 cargo test --lib keyword_grammar` and \
         `python3 editors/vscode/syntaxes/generate.py`): {unwritable:#?}"
    );
}

#[test]
fn the_keyword_table_is_sorted_and_documented() {
    let keywords = rts::syntax::keywords::KEYWORDS;
    assert!(
        keywords.windows(2).all(|w| w[0] < w[1]),
        "KEYWORDS must stay sorted and without repeats (it is searched by halves)"
    );
    let undocumented: Vec<&str> = keywords
        .iter()
        .copied()
        .filter(|k| rts::ide::docs::lookup(k).is_none())
        .collect();
    assert!(
        undocumented.is_empty(),
        "keywords without hover documentation in src/ide/docs.rs: {undocumented:?}"
    );
}

#[test]
fn editors_offer_every_block_the_evaluator_reads() {
    let keywords = rts::syntax::keywords::KEYWORDS;
    let top = rts::eval::top_level_keywords();
    for b in rts::eval::OBJECT_BLOCKS {
        assert!(keywords.contains(b), "object block `{b}` is no keyword");
        assert!(
            top.contains(b),
            "object block `{b}` is not offered at top level"
        );
    }
    for b in &top {
        assert!(keywords.contains(b), "top-level block `{b}` is no keyword");
        assert!(
            rts::eval::block_keywords(b).is_some(),
            "`{b}` is offered at top level but its items are unknown to completion"
        );
    }
    // Every table of a block's items feeds completion.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let vocabulary =
        std::fs::read_to_string(root.join("src/eval/core/vocabulary.rs")).expect("vocabulary.rs");
    for file in sources(&root.join("src/eval")) {
        let text = std::fs::read_to_string(&file).expect("source");
        for line in text.lines() {
            let Some(rest) = line.split("const ").nth(1) else {
                continue;
            };
            let Some(name) = rest.split(':').next() else {
                continue;
            };
            // Read there directly, or through the function of the same name.
            let function = format!("{}()", name.to_lowercase());
            if name.ends_with("_ITEMS")
                && !vocabulary.contains(name)
                && !vocabulary.contains(&function)
            {
                panic!(
                    "{name} ({}) is not offered by completion: add its block to \
                     block_keywords in src/eval/core/vocabulary.rs",
                    file.display()
                );
            }
        }
    }
    // The shapes the issue found missing from completion.
    for b in [
        "blob",
        "isosurface",
        "lathe",
        "sor",
        "superellipsoid",
        "polyhedron",
        "light_group",
    ] {
        assert!(top.contains(&b), "`{b}` missing from top-level completion");
    }
}
