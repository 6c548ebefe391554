//! Stage 1: source text to syntax tree.
//!
//! [`parse`] runs the lexical [`prepass`] and then the pest grammar. When the grammar
//! fails, parsing restarts item by item and resynchronises at the next line that
//! starts at column 0, so several independent syntax errors are reported in one run.

pub mod ast;
pub mod builtins;
pub mod data;
pub mod decimal;
pub mod intern;
pub mod keywords;
mod lower;
mod names;
mod parser;
pub mod prepass;
mod recovery;
pub mod trivia;

pub use intern::{intern, Sym};
pub use lower::MAX_CHAIN;

use crate::diag::{codes, Diagnostic};
use crate::span::{FileId, Span};
use parser::{RtsParser, Rule};
use pest::Parser;

/// Parses one file. Returns the items that parsed and the problems found; when the
/// list holds an error the tree is incomplete and should not be evaluated.
pub fn parse(text: &str, file: FileId) -> (ast::File, Vec<Diagnostic>) {
    parse_at(text, file, 0)
}

/// [`parse`] for `text` found at byte `base` of file `file` (a part of a larger
/// file): every span of the tree and the diagnostics is the file's.
pub fn parse_at(text: &str, file: FileId, base: usize) -> (ast::File, Vec<Diagnostic>) {
    parse_with(text, file, base, false)
}

/// [`parse_at`], and for rendering (`defer_branches`) the long branch bodies
/// of `#if`, `#ifdef`, `#ifndef` and `#switch` left unread
/// ([`ast::Item::Deferred`]; see [`prepass::Marks::deferred`]) to be parsed
/// when evaluation takes their branch, as POV-Ray skips the branches it does
/// not take. A syntax error in a branch not taken then goes unreported, as in
/// POV-Ray; `rts check` and the editor read every branch.
pub fn parse_with(
    text: &str,
    file: FileId,
    base: usize,
    defer_branches: bool,
) -> (ast::File, Vec<Diagnostic>) {
    let (mut diags, mut marks) = prepass::check_marking(text, file);
    if !defer_branches {
        marks.deferred.clear();
    }
    for d in &mut diags {
        d.shift(base);
    }
    if diags.iter().any(Diagnostic::is_error) {
        return (ast::File::default(), diags);
    }
    // Block bodies of plain numbers and vectors have their `{` marked in the
    // parser's copy of the text (same length, so every offset stays), so the
    // grammar skips them whole; the lowering takes the numbers the prepass read.
    let original = text;
    let marked;
    // Vectors of plain numbers have their `<` marked the same way. Comments,
    // byte-order marks and stray `#`s, macro bodies read token by token at
    // their calls and deferred branch bodies are blanked (spaces, newlines
    // kept), after the marks (over any inside them): the grammar sees spaces
    // and empty bodies.
    let text = if marks.data_bodies.is_empty()
        && marks.token_level.is_empty()
        && marks.blank.is_empty()
        && marks.deferred.is_empty()
        && marks.plain_vectors.is_empty()
    {
        text
    } else {
        let mut bytes = text.as_bytes().to_vec();
        for &at in &marks.data_bodies {
            bytes[at] = prepass::DATA_BODY;
        }
        for &at in &marks.plain_vectors {
            bytes[at] = prepass::PLAIN_VECTOR;
        }
        let blanked = marks.blank.iter().chain(&marks.token_level);
        for &(start, end) in blanked.chain(&marks.deferred) {
            for b in &mut bytes[start..end] {
                if *b != b'\n' {
                    *b = b' ';
                }
            }
        }
        marked = String::from_utf8(bytes).unwrap_or_else(|_| text.to_string());
        marked.as_str()
    };
    let mut lower = lower::Lowerer {
        file,
        offset: base,
        // The prepass's warnings come first.
        diags,
        token_level: marks
            .token_level
            .iter()
            .map(|&(s, e)| (s + base, e + base))
            .collect(),
        deferred: marks
            .deferred
            .iter()
            .map(|&(s, e)| (s + base, e + base))
            .collect(),
        runs: std::mem::take(&mut marks.data_runs)
            .into_iter()
            .map(|(at, run)| (at + base, Some(run)))
            .collect(),
    };
    match RtsParser::parse(Rule::file, text) {
        Ok(mut pairs) => {
            let file_pair = pairs.next().expect("file rule");
            let items = lower.items(file_pair.into_inner());
            (
                ast::File {
                    items,
                    ..Default::default()
                },
                lower.diags,
            )
        }
        Err(_) => recover(text, original, file, lower, base),
    }
}

/// Item-by-item parsing after a failure of the whole-file parse. `text` is the
/// parser's copy (data bodies marked), `original` the file as written (for
/// messages; the offsets agree). What was skipped is kept in the file's
/// [`ast::File::unparsed`], with the names declared there, so evaluation can
/// go on with the rest without reporting what the skipped text would have
/// defined.
fn recover(
    text: &str,
    original: &str,
    file: FileId,
    mut lower: lower::Lowerer,
    base: usize,
) -> (ast::File, Vec<Diagnostic>) {
    pest::set_error_detail(true);
    let mut items = Vec::new();
    let mut diags = Vec::new();
    let mut unparsed = Vec::new();
    let mut pos = 0;
    while pos < text.len() {
        let rest = &text[pos..];
        if RtsParser::parse(Rule::only_trivia, rest).is_ok() {
            break;
        }
        match RtsParser::parse(Rule::one_item, rest) {
            Ok(mut pairs) => {
                let pair = pairs.next().expect("one_item");
                let end = pair.as_span().end();
                lower.offset = base + pos;
                items.extend(lower.items(pair.into_inner()));
                pos += end.max(1);
                // Skip to the next char boundary in the unlikely case of zero progress.
                while !text.is_char_boundary(pos) {
                    pos += 1;
                }
            }
            Err(e) => {
                let at = pos + error_offset(&e);
                let mut first = syntax_error(original, file, at, &e);
                first.shift(base);
                let next = resync(text, at.max(pos + 1));
                // Other misspelled block keywords in the skipped text: each
                // would stop the parse there too.
                let first_span = first.span;
                // `sphear {`: the word parsed as a name just before; it is the
                // block's misspelled keyword, not a value of its own.
                if first.code == codes::UNKNOWN_BLOCK {
                    while items
                        .last()
                        .is_some_and(|i: &ast::Item| i.span().start == first_span.start)
                    {
                        items.pop();
                    }
                }
                diags.push(first);
                diags.extend(
                    recovery::unknown_blocks(original, pos, next, file)
                        .into_iter()
                        .map(|mut d| {
                            d.shift(base);
                            d
                        })
                        .filter(|d| d.span != first_span),
                );
                unparsed.push(Span::new(file, base + pos, base + next));
                pos = next;
            }
        }
    }
    pest::set_error_detail(false);
    diags.extend(lower.diags);
    let names = unparsed
        .iter()
        .flat_map(|s| {
            recovery::declared_names(&original[s.start as usize - base..s.end as usize - base])
        })
        .collect();
    (
        ast::File {
            items,
            unparsed,
            unparsed_names: names,
        },
        diags,
    )
}

fn error_offset(e: &pest::error::Error<Rule>) -> usize {
    match e.location {
        pest::error::InputLocation::Pos(p) => p,
        pest::error::InputLocation::Span((s, _)) => s,
    }
}

/// The start of the next line after `at` that begins at column 0 with a letter or `#`,
/// or the end of the text.
fn resync(text: &str, at: usize) -> usize {
    let bytes = text.as_bytes();
    let mut i = at.min(text.len());
    while !text.is_char_boundary(i) {
        i += 1;
    }
    loop {
        match text[i..].find('\n') {
            None => return text.len(),
            Some(n) => {
                i += n + 1;
                if let Some(&c) = bytes.get(i) {
                    if c.is_ascii_alphabetic() || c == b'#' {
                        return i;
                    }
                }
            }
        }
    }
}

/// The token at `at`, for "found …" in messages.
fn token_at(text: &str, at: usize) -> (String, usize) {
    let rest = &text[at.min(text.len())..];
    let Some(c) = rest.chars().next() else {
        return ("end of file".into(), 0);
    };
    let len = if c.is_alphanumeric() || c == '_' {
        rest.find(|ch: char| !(ch.is_alphanumeric() || ch == '_' || ch == '.'))
            .unwrap_or(rest.len())
    } else {
        c.len_utf8()
    };
    (format!("`{}`", &rest[..len]), len)
}

fn syntax_error(text: &str, file: FileId, at: usize, e: &pest::error::Error<Rule>) -> Diagnostic {
    let mut expected: Vec<&str> = Vec::new();
    if let pest::error::ErrorVariant::ParsingError { positives, .. } = &e.variant {
        expected.extend(positives.iter().filter_map(|r| names::human(*r)));
    }
    if let Some(attempts) = e.parse_attempts() {
        for tok in attempts.expected_tokens() {
            {
                let token = tok.to_string();
                let human = match token.as_str() {
                    "{" => "`{`",
                    "}" => "`}`",
                    "(" => "`(`",
                    ")" => "`)`",
                    "[" => "`[`",
                    "]" => "`]`",
                    ">" => "`>`",
                    "," => "`,`",
                    "=" => "`=`",
                    ";" => "`;`",
                    ":" => "`:`",
                    "#" => "a directive",
                    "\"" => "a string",
                    "<" => "a vector `<…>`",
                    _ => continue,
                };
                expected.push(human);
            }
        }
        for stack in attempts.call_stacks() {
            // A block as the deepest rule of a stack is the block being read
            // (pest folds stacks of many tries into their parent), never one
            // expected where the error is: that would show as its keyword.
            let deepest = stack.deepest.get_rule().copied();
            if let Some(name) = deepest
                .filter(|r| !matches!(r, Rule::block | Rule::item_block))
                .and_then(names::human)
            {
                expected.push(name);
            }
        }
    }
    if expected.len() > 1 {
        expected.retain(|n| *n != "a statement");
    }
    // The tokens that start an expression say nothing more than "an expression".
    if expected.contains(&"an expression") {
        const STARTS: &[&str] = &[
            "`(`",
            "`-`, `+` or `!`",
            "a string",
            "a vector `<…>`",
            "a colour",
            "a keyframes block",
            "a name",
            "a number",
            "a number or a vector",
            "an array",
            "a function call",
        ];
        expected.retain(|n| !STARTS.contains(n));
    }
    expected.sort_unstable();
    expected.dedup();
    if let Some(d) = recovery::unknown_block_before(text, at, file) {
        return d;
    }
    let (found, len) = token_at(text, at);
    if expected.is_empty() {
        if let Some(d) = closer_without_opener(text, at, file) {
            return d;
        }
    }
    let list = match expected.as_slice() {
        [] => "something else".to_string(),
        [one] => one.to_string(),
        [init @ .., last] => format!("{} or {last}", init.join(", ")),
    };
    let mut d = Diagnostic::error(
        codes::SYNTAX_EXPECTED,
        Span::new(file, at, at + len),
        format!("expected {list}, found {found}"),
    )
    .with_label(format!("expected {list}"));
    if found == "`{`" {
        d = d.with_help("only keywords open blocks: is the keyword before `{` misspelled?");
    } else if expected.contains(&"`,`") && found.starts_with("`<") {
        d = d.with_help("separate vectors with commas: `<0,0,0>, <1,1,1>`");
    }
    let word = found.strip_prefix('`').and_then(|s| s.strip_suffix('`'));
    if let Some(word) = word.filter(|w| keywords::KEYWORDS.contains(w)) {
        if expected.contains(&"a name") {
            return d.with_help(format!(
                "`{word}` is a keyword and cannot be a name; choose another (a capital first letter never clashes, e.g. `My_{word}`)"
            ));
        }
    }
    if let Some(word) = word {
        if let Some(s) = crate::diag::did_you_mean(word, keywords::KEYWORDS.iter().copied()) {
            d = d.with_help(format!("did you mean the keyword `{s}`?"));
        }
    }
    d
}

/// `#end` (or `#else`, `#case`, …) where a statement was expected: it closes a
/// directive whose start did not parse (item-by-item reading after a syntax
/// error starts again past it), since the prepass has checked that directives
/// balance.
fn closer_without_opener(text: &str, at: usize, file: FileId) -> Option<Diagnostic> {
    let (hash, at) = match text[..at].trim_end().strip_suffix('#') {
        Some(before) => (before.len(), at),
        None if text[at..].starts_with('#') => {
            let rest = &text[at + 1..];
            (at, at + 1 + rest.len() - rest.trim_start().len())
        }
        None => return None,
    };
    let word: String = text[at..]
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect();
    if !matches!(
        word.as_str(),
        "end" | "else" | "elseif" | "case" | "range" | "break"
    ) {
        return None;
    }
    Some(
        Diagnostic::error(
            codes::STRAY_DIRECTIVE,
            Span::new(file, hash, at + word.len()),
            format!("`#{word}` of a directive whose start did not parse"),
        )
        .with_label("what it belongs to was skipped")
        .with_help("fix the syntax error above: the directive this closes starts there"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ok(src: &str) -> ast::File {
        let (f, d) = parse(src, FileId(0));
        assert!(d.is_empty(), "{src}: {d:#?}");
        f
    }

    #[test]
    fn parses_core_forms() {
        let f = ok("#version 3.7;\n#declare A = 1 + 2 * 3;\nsphere { <0,1,0>, A pigment { color rgb <1,0,0> } finish { phong 0.8 } }");
        assert_eq!(f.items.len(), 3);
        ok("#if (A < 2 & B >= 3) #debug \"x\" #elseif (1) #else #end");
        ok("#macro M(A, optional B) sphere { A, 1 } #end M(<1,2,3>)");
        ok("#for (I, 0, 10, 2) #end #while (0) #end #switch (2) #case (1) #break #range (2, 3) #else #end");
        ok("#declare Arr = array[2][2] { {1, 2}, {3, 4} }; #declare V = Arr[1][0] * <1,2,3>.x;");
        ok("pigment { color red 1 green 0.5 } pigment { rgb <1,0,0> filter 0.5 }");
        ok("plane { y, 0 translate -x rotate <0, 30, 0> }");
        ok("/* a /* nested */ comment */ #declare S = \"a\\\"b\\n\";");
        ok("#declare C = A ? 1 : B ? 2 : 3;");
        let f = ok("height_field { function 4, 3 { x } }");
        let ast::Item::Block(b) = &f.items[0] else {
            panic!("a block")
        };
        assert_eq!(b.items.len(), 4, "{:#?}", b.items);
    }

    /// A parse for rendering leaves long branch bodies unread, spans kept;
    /// the parse for checking reads them.
    #[test]
    fn long_branch_bodies_are_deferred_for_rendering_only() {
        let long = "sphere { 0, 1 } ".repeat(20);
        let text = format!("#if (A)\n{long}\n#else\n{long}#end");
        let branches = |f: &ast::File| match &f.items[..] {
            [ast::Item::Directive(d)] => match &d.kind {
                ast::DirectiveKind::If {
                    branches,
                    otherwise,
                } => (branches[0].1.clone(), otherwise.clone().unwrap()),
                k => panic!("{k:?}"),
            },
            i => panic!("{i:?}"),
        };
        let (then, otherwise) = branches(&ok(&text));
        assert_eq!((then.len(), otherwise.len()), (20, 20));
        let (f, d) = parse_with(&text, FileId(0), 0, true);
        assert!(d.is_empty(), "{d:#?}");
        let (then, otherwise) = branches(&f);
        for body in [then, otherwise] {
            let [ast::Item::Deferred(b)] = &body[..] else {
                panic!("{body:?}")
            };
            assert_eq!(
                &text[b.span.start as usize..b.span.end as usize].trim(),
                &long.trim()
            );
        }
    }

    /// Comments, byte-order marks and stray `#`s are blanked before the grammar
    /// runs: they separate tokens anywhere whitespace does, and a string keeps
    /// the comment-like text it holds.
    #[test]
    fn comments_separate_tokens_and_strings_keep_theirs() {
        let f = ok("#declare S = \"a // b /* c */ \u{FEFF}\";");
        assert!(
            format!("{f:?}").contains(r#"Str("a // b /* c */ \u{feff}")"#),
            "{f:?}"
        );
        let plain = ok("#declare A = <1, 2, 3>; sphere { A, 1 }");
        let commented = ok(concat!(
            "\u{FEFF}/* a */# declare/**/A/**/=<1,//\n2,/* b /* nested */ */3>;\n",
            "sphere/* c */{ A\u{FEFF}, 1 // d\n}"
        ));
        assert_eq!(plain.items.len(), commented.items.len());
        let (f, d) = parse("sphere { 0, 1 # }", FileId(0));
        assert_eq!(f.items.len(), 1);
        assert_eq!(d.len(), 1, "{d:#?}");
        assert_eq!(d[0].code, codes::UNKNOWN_DIRECTIVE);
    }

    /// What the word tables and guards of the grammar must keep reading the
    /// same: `default` with and without its `#`, a vector written after a
    /// value without a comma (a run, as the items would be), and what must not
    /// become a run (a sign or `<` that continues an expression).
    #[test]
    fn words_directives_and_runs_read_as_before() {
        for src in [
            "#default { finish { phong 1 } }",
            "default { finish { phong 1 } }",
        ] {
            let f = ok(src);
            assert!(
                matches!(&f.items[..], [ast::Item::Directive(_)]),
                "{src}: {:#?}",
                f.items
            );
        }
        let f = ok("bicubic_patch { type 1 <1, 0, 0> <0, 1, 0>\n <0, 0, 1>, 2 <3, 4> }");
        let ast::Item::Block(b) = &f.items[0] else {
            panic!("a block")
        };
        let runs: Vec<usize> = b
            .items
            .iter()
            .filter_map(|i| match i {
                ast::Item::Data(d) => Some(d.len),
                _ => None,
            })
            .collect();
        assert_eq!(runs, [6], "{:#?}", b.items);
        for src in ["#declare A = <1, 2, 3> - <1, 1, 1>;", "#declare B = 1 < 2;"] {
            ok(src);
        }
        // `1 -2` is a difference and `<1, 2> < 3` a comparison: no run.
        let f = ok("sphere { 1 -2, <1, 2> < 3 }");
        let ast::Item::Block(b) = &f.items[0] else {
            panic!("a block")
        };
        assert!(
            !b.items.iter().any(|i| matches!(i, ast::Item::Data(_))),
            "{:#?}",
            b.items
        );
        // Names that start like reserved words stay names; reserved words do not.
        ok("#declare rgbx = 1; #declare arrays = 2; #declare colorful = 3; #declare red_ = 4;");
        for src in [
            "#declare rgbt = 1;",
            "#declare array = 1;",
            "#declare grey = 1;",
        ] {
            assert!(!parse(src, FileId(0)).1.is_empty(), "{src}");
        }
    }

    /// A vector of plain numbers is read in one step, into the expressions the
    /// general path gives (same signs, numbers and spans).
    #[test]
    fn plain_vectors_lower_like_vectors() {
        let components = |src: &str| {
            let f = ok(src);
            let ast::Item::Directive(d) = &f.items[0] else {
                panic!("a directive")
            };
            let text = format!("{d:?}");
            let from = text.find("Vector(").expect("a vector");
            text[from..].to_string()
        };
        let plain = components("#declare V = < 1, -2.5 ,+ 3e1>;");
        let general = components("#declare V = < 1, -2.5 ,+ 3e1, A>;");
        let cut = plain.rfind("Unary").expect("a signed component");
        assert_eq!(plain[..cut], general[..cut]);
        // Marked by the prepass (above) or not (a comment inside): the same.
        let unmarked = components("#declare V = < 1, -2.5 ,+ 3e1/* c */>;");
        assert_eq!(plain[..cut], unmarked[..cut]);
        let (_, d) = parse("#declare V = <1e999, 0>;", FileId(0));
        assert_eq!(d.len(), 1, "{d:#?}");
        assert_eq!(d[0].code, codes::BAD_NUMBER);
    }

    #[test]
    fn reports_several_errors() {
        let (_, d) = parse("sphere { 0, 1 ]\n", FileId(0));
        assert_eq!(d.len(), 1);
        let (_, d) = parse(
            "sphere { <0,0,0> 1 2 + }\nplane { y, 0 }\nbox { 1, 2 * }\n",
            FileId(0),
        );
        assert_eq!(d.len(), 2, "{d:#?}");
        assert!(d.iter().all(|x| x.code == codes::SYNTAX_EXPECTED));
    }
}
