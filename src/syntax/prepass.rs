//! Lexical checks before parsing: unclosed strings, comments, brackets and directives,
//! stray closers, unknown directives, and nesting limits.
//!
//! These give better messages than a parser can (they point at the opener, not at the
//! end of the file) and they guarantee the recursive grammar never meets input nested
//! deeper than [`MAX_NESTING`].

use super::trivia::comment_end;
use crate::diag::{codes, did_you_mean, Diagnostic};
use crate::span::{FileId, Span};

/// The deepest nesting of brackets, block comments, directives, vectors, colour
/// keywords, prefix operators or `?:` accepted.
pub const MAX_NESTING: usize = 256;

const OPENING_DIRECTIVES: &[&str] = &["if", "ifdef", "ifndef", "while", "for", "macro", "switch"];
const MIDDLE_DIRECTIVES: &[&str] = &["else", "elseif", "case", "range", "break"];
const PLAIN_DIRECTIVES: &[&str] = &[
    "declare", "local", "undef", "include", "debug", "warning", "error", "default", "version",
    "fopen", "fclose", "read", "write",
];

struct Scanner<'a> {
    bytes: &'a [u8],
    file: FileId,
    diags: Vec<Diagnostic>,
    brackets: Vec<(u8, usize)>,
    directives: Vec<(&'static str, usize, usize)>,
    angle_depth: usize,
    prefix_run: usize,
    question_depth: usize,
    /// The last significant byte, to tell a vector's `<` from less-than.
    prev: u8,
    /// The `{` of every block body that holds only plain numbers and vectors.
    data_bodies: Vec<usize>,
    /// Their numbers, by the offset of the `{`.
    data_runs: Vec<(usize, super::data::DataRun)>,
    /// The numbers of the body being read.
    scratch: Vec<f64>,
    /// The first `}` that starts its line indented less than the line of the
    /// `{` it closes (`{` offset, `}` offset): where a block whose own `}` is
    /// missing most likely ends, when one stays open at the end.
    misindented: Option<(usize, usize)>,
    /// The `#macro` being scanned: the offset of its `#`, its place in
    /// `directives` and the bracket depth at its start.
    open_macro: Option<(usize, usize, usize)>,
    /// Macro bodies whose brackets balance only once their `#if` choices are
    /// made (see [`Marks::token_level`]).
    token_level: Vec<(usize, usize)>,
    /// Comments, byte-order marks and stray `#`s (see [`Marks::blank`]).
    blank: Vec<(usize, usize)>,
    /// The `<` of every plain vector (see [`Marks::plain_vectors`]).
    plain_vectors: Vec<usize>,
    /// The branch bodies of the `#if`s and `#switch` clauses open here,
    /// innermost last (see [`Marks::deferred`]).
    open_bodies: Vec<OpenBody>,
    /// The bodies that may be left unread (see [`Marks::deferred`]).
    deferred: Vec<(usize, usize)>,
}

/// A branch body being scanned: of an `#if`, `#ifdef`, `#ifndef`, `#elseif`,
/// `#else`, `#case` or `#range`.
struct OpenBody {
    /// The directive nesting (`directives.len()`) of the group it belongs to.
    group: usize,
    /// Where the body starts, once its head (`(condition)`) is read.
    start: Option<usize>,
    /// Brackets open before the head's `(` (the head ends where they are
    /// back to this), then brackets open at the body's start.
    brackets: usize,
    /// False once the body closed a bracket opened before it.
    balanced: bool,
}

/// Bodies shorter than this are parsed with the rest (deferring costs a
/// second parse setup when the branch is taken).
const DEFER_MIN: usize = 256;

/// What [`check_marking`] finds besides the problems.
#[derive(Debug, Default)]
pub struct Marks {
    /// The offsets of the `{` of every block body that holds nothing but two or
    /// more plain numbers and vectors separated by commas.
    pub data_bodies: Vec<usize>,
    /// The numbers of those bodies, read as they were checked, by the offset
    /// of their `{` (a body whose numbers do not all fit in an `f64` has none:
    /// the lowering reads it again to report the number).
    pub data_runs: Vec<(usize, super::data::DataRun)>,
    /// The bodies (from after the parameter list to the `#` of `#end`) of the
    /// macros whose brackets do not balance as written, such as
    /// `#if (F) #write (H, "{", #else mesh2 { #end`: POV-Ray reads a macro token by
    /// token as it runs, so only the branches taken need to balance. The grammar
    /// sees such a body as empty; it is parsed at each call, after the `#if`s
    /// it can decide on entry are decided (see the evaluator's `token_level.rs`).
    pub token_level: Vec<(usize, usize)>,
    /// The ranges that separate tokens but are not whitespace: comments,
    /// byte-order marks and `#`s that no directive name follows. The parser's
    /// copy of the text has them as spaces (line breaks kept), so the grammar
    /// knows only whitespace.
    pub blank: Vec<(usize, usize)>,
    /// The branch bodies (`#if (C)` … up to the `#` of the `#elseif`, `#else`,
    /// `#end`, `#case`, `#range` or `#break` that ends them; `#else` … and
    /// `#switch` clauses alike) of at least [`DEFER_MIN`] bytes whose brackets
    /// balance, outermost only. A parse for rendering leaves them unread, as
    /// POV-Ray skips the branches it does not take, and reads one when its
    /// branch is taken (see [`super::parse_with`]).
    pub deferred: Vec<(usize, usize)>,
    /// The offsets of the `<` of every vector of 2 to 5 plain numbers with
    /// commas (`<1, -2.5, 3e-2>`, the shape of the grammar's `data_vector`):
    /// the parser's copy has [`PLAIN_VECTOR`] there and the grammar skips to
    /// its `>` at memory speed; the lowering reads the numbers.
    pub plain_vectors: Vec<usize>,
}

/// The marker the parser's copy of the text has in place of the `{` of a block
/// body that holds only plain numbers and vectors (see [`check_marking`]).
pub const DATA_BODY: u8 = 0x01;

/// The marker the parser's copy of the text has in place of the `<` of a
/// vector of plain numbers (see [`Marks::plain_vectors`]).
pub const PLAIN_VECTOR: u8 = 0x02;

/// A byte-order mark (U+FEFF) in UTF-8: POV-Ray reads it as a space.
const BOM: &[u8] = "\u{FEFF}".as_bytes();

/// Checks `text`; returns the problems found (empty when the file may be parsed).
pub fn check(text: &str, file: FileId) -> Vec<Diagnostic> {
    check_marking(text, file).0
}

/// [`check`], and the offsets of the `{` of every block body that holds nothing
/// but two or more plain numbers and vectors separated by commas (a mesh's
/// `vertex_vectors { 3, <0,0,0>, … }`): the parser skips such a body at memory
/// speed; its numbers are read here, as it is checked ([`Marks::data_runs`]).
pub fn check_marking(text: &str, file: FileId) -> (Vec<Diagnostic>, Marks) {
    let mut s = Scanner {
        bytes: text.as_bytes(),
        file,
        diags: Vec::new(),
        brackets: Vec::new(),
        directives: Vec::new(),
        angle_depth: 0,
        prefix_run: 0,
        question_depth: 0,
        prev: b'{',
        data_bodies: Vec::new(),
        data_runs: Vec::new(),
        scratch: Vec::new(),
        misindented: None,
        open_macro: None,
        token_level: Vec::new(),
        blank: Vec::new(),
        plain_vectors: Vec::new(),
        open_bodies: Vec::new(),
        deferred: Vec::new(),
    };
    s.run();
    (
        s.diags,
        Marks {
            data_bodies: s.data_bodies,
            data_runs: s.data_runs,
            token_level: s.token_level,
            blank: s.blank,
            deferred: s.deferred,
            plain_vectors: s.plain_vectors,
        },
    )
}

/// The offset of the `#` of the `#end` that closes `depth` open directives from
/// `from` on (strings and comments skipped), if there is one.
fn directive_end(b: &[u8], from: usize, mut depth: usize) -> Option<usize> {
    let mut i = from;
    while i < b.len() {
        match b[i] {
            b'/' if comment_end(b, i).is_some() => i = comment_end(b, i).unwrap_or(b.len()),
            b'"' => {
                i += 1;
                while i < b.len() && !matches!(b[i], b'"' | b'\n') {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
                i += 1;
            }
            b'#' => {
                let hash = i;
                i += 1;
                while i < b.len() && matches!(b[i], b' ' | b'\t') {
                    i += 1;
                }
                let start = i;
                while i < b.len() && is_word_byte(b[i]) {
                    i += 1;
                }
                let word = std::str::from_utf8(&b[start..i]).unwrap_or("");
                if OPENING_DIRECTIVES.contains(&word) {
                    depth += 1;
                } else if word == "end" {
                    depth -= 1;
                    if depth == 0 {
                        return Some(hash);
                    }
                }
            }
            _ => i += 1,
        }
    }
    None
}

/// The line of `text` holding byte `i`: its indentation (leading spaces and
/// tabs) and whether `i` is the first other character on it.
fn indentation(b: &[u8], i: usize) -> (&[u8], bool) {
    let start = b[..i]
        .iter()
        .rposition(|&c| c == b'\n')
        .map_or(0, |p| p + 1);
    let end = start
        + b[start..]
            .iter()
            .position(|&c| c != b' ' && c != b'\t')
            .unwrap_or(b.len() - start);
    (&b[start..end], end == i)
}

fn closer_for(open: u8) -> u8 {
    match open {
        b'{' => b'}',
        b'(' => b')',
        _ => b']',
    }
}

fn is_word_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

impl Scanner<'_> {
    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.file, start, end)
    }

    fn too_deep(&mut self, at: usize, len: usize, what: &str) {
        self.diags.push(
            Diagnostic::error(
                codes::NESTING_TOO_DEEP,
                self.span(at, at + len),
                format!("{what} nested more than {MAX_NESTING} deep"),
            )
            .with_label("too deep here")
            .with_help("split the expression or block into #declared parts"),
        );
    }

    fn run(&mut self) {
        let b = self.bytes;
        let mut i = 0;
        while i < b.len() {
            let c = b[i];
            match c {
                DATA_BODY | PLAIN_VECTOR => {
                    self.diags.push(
                        Diagnostic::error(
                            codes::SYNTAX_EXPECTED,
                            self.span(i, i + 1),
                            format!("a control character (U+{c:04X}) in the scene"),
                        )
                        .with_label("not a character a scene may hold")
                        .with_help("remove it; the file may not be a text file"),
                    );
                    return;
                }
                b'/' if b.get(i + 1) == Some(&b'/') => {
                    let start = i;
                    while i < b.len() && b[i] != b'\n' {
                        i += 1;
                    }
                    self.blank.push((start, i));
                    continue;
                }
                b'/' if b.get(i + 1) == Some(&b'*') => match self.comment(i) {
                    Some(end) => {
                        self.blank.push((i, end));
                        i = end;
                        continue;
                    }
                    None => return,
                },
                0xEF if b[i..].starts_with(BOM) => {
                    self.blank.push((i, i + BOM.len()));
                    i += BOM.len();
                    continue;
                }
                b'"' => {
                    i = self.string(i);
                    self.prev = b'"';
                    self.prefix_run = 0;
                    continue;
                }
                b'{' | b'(' | b'[' => {
                    self.brackets.push((c, i));
                    if self.brackets.len() > MAX_NESTING {
                        self.too_deep(i, 1, "brackets");
                        return;
                    }
                    // A body of plain numbers and vectors is read here, once,
                    // and skipped to its `}` (which closes it as any other).
                    if c == b'{' {
                        if let Some((end, run)) =
                            super::data::plain_body(b, i + 1, &mut self.scratch)
                        {
                            if b.get(end) == Some(&b'}') {
                                self.data_bodies.push(i);
                                if let Some(run) = run {
                                    self.data_runs.push((i, run));
                                }
                                i = end;
                                continue;
                            }
                        }
                    }
                }
                b'}' | b')' | b']' => {
                    let balances = match self.open_macro {
                        Some((_, _, depth)) => {
                            self.brackets.len() > depth
                                && self
                                    .brackets
                                    .last()
                                    .is_some_and(|&(o, _)| closer_for(o) == c)
                        }
                        None => true,
                    };
                    if !balances {
                        if let Some(end) = self.token_level_macro(i) {
                            i = end;
                            continue;
                        }
                    }
                    if !self.close(c, i) {
                        return;
                    }
                }
                b'<' => {
                    if let Some(end) = super::data::plain_element(b, i) {
                        self.plain_vectors.push(i);
                        i = end;
                        self.prev = b'>';
                        self.prefix_run = 0;
                        continue;
                    }
                    if matches!(
                        self.prev,
                        b'(' | b','
                            | b'<'
                            | b'['
                            | b'{'
                            | b'='
                            | b'+'
                            | b'-'
                            | b'*'
                            | b'/'
                            | b'?'
                            | b':'
                            | b'!'
                            | b'&'
                            | b'|'
                    ) {
                        self.angle_depth += 1;
                        if self.angle_depth > MAX_NESTING {
                            self.too_deep(i, 1, "vectors");
                            return;
                        }
                    }
                }
                b'>' => self.angle_depth = self.angle_depth.saturating_sub(1),
                b'?' => {
                    self.question_depth += 1;
                    if self.question_depth > MAX_NESTING {
                        self.too_deep(i, 1, "conditional expressions");
                        return;
                    }
                }
                b':' => self.question_depth = self.question_depth.saturating_sub(1),
                b'-' | b'+' | b'!' => {
                    self.prefix_run += 1;
                    if self.prefix_run > MAX_NESTING {
                        self.too_deep(i, 1, "prefix operators");
                        return;
                    }
                    self.prev = c;
                    i += 1;
                    continue;
                }
                b'#' if !self.directive(i) => {
                    return;
                }
                _ if c.is_ascii_alphabetic() || c == b'_' => {
                    let start = i;
                    while i < b.len() && is_word_byte(b[i]) {
                        i += 1;
                    }
                    let word = &b[start..i];
                    let colourish = matches!(
                        word,
                        b"rgb"
                            | b"rgbf"
                            | b"rgbt"
                            | b"rgbft"
                            | b"srgb"
                            | b"srgbf"
                            | b"srgbt"
                            | b"srgbft"
                            | b"color"
                            | b"colour"
                    );
                    if colourish {
                        self.prefix_run += 1;
                        if self.prefix_run > MAX_NESTING {
                            self.too_deep(start, i - start, "colour keywords");
                            return;
                        }
                    } else {
                        self.prefix_run = 0;
                    }
                    // Keywords put us in operand position for `<`; names do not, but
                    // after a name a `<` is a comparison only in expressions, and a
                    // false positive merely counts one level more.
                    self.prev = b'a';
                    continue;
                }
                _ => {}
            }
            if !(c.is_ascii_whitespace() || c == 0x0B) {
                self.prev = c;
                if !matches!(c, b'-' | b'+' | b'!') {
                    self.prefix_run = 0;
                }
            }
            i += 1;
        }
        self.finish();
    }

    /// Skips a block comment starting at `start`; `None` if it never closes or nests
    /// too deeply (the diagnostic is recorded).
    fn comment(&mut self, start: usize) -> Option<usize> {
        let b = self.bytes;
        let mut openers = vec![start];
        let mut i = start + 2;
        while i < b.len() {
            if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
                openers.push(i);
                if openers.len() > MAX_NESTING {
                    self.too_deep(i, 2, "block comments");
                    return None;
                }
                i += 2;
            } else if b[i] == b'*' && b.get(i + 1) == Some(&b'/') {
                openers.pop();
                i += 2;
                if openers.is_empty() {
                    return Some(i);
                }
            } else {
                i += 1;
            }
        }
        let at = *openers.last().unwrap_or(&start);
        let mut d = Diagnostic::error(
            codes::UNCLOSED_COMMENT,
            self.span(at, at + 2),
            "unclosed block comment",
        )
        .with_label("this comment is never closed")
        .with_help("add `*/` where the comment should end");
        if openers.len() > 1 {
            d = d.with_note(
                "block comments nest in .rts as in POV-Ray: each `/*` needs its own `*/`",
            );
        }
        self.diags.push(d);
        None
    }

    /// Skips a string literal starting at `start`, reporting it when unclosed.
    fn string(&mut self, start: usize) -> usize {
        let b = self.bytes;
        let mut i = start + 1;
        while i < b.len() {
            match b[i] {
                b'\\' => i += 2,
                b'"' => return i + 1,
                b'\n' => break,
                _ => i += 1,
            }
        }
        let end = i.min(b.len());
        self.diags.push(
            Diagnostic::error(
                codes::UNCLOSED_STRING,
                self.span(start, end),
                "unclosed string",
            )
            .with_label("this string has no closing quote on its line")
            .with_help("add `\"` at the end of the string (strings cannot span lines)"),
        );
        end
    }

    /// A bracket at `i` that does not balance inside the open macro: the
    /// macro's body is read token by token at its calls (see
    /// [`Marks::token_level`]). Returns where scanning goes on (the macro's
    /// `#end`), or `None` outside a macro or when the macro never ends.
    fn token_level_macro(&mut self, i: usize) -> Option<usize> {
        let (hash, slot, depth) = self.open_macro?;
        let open_above = self.directives.len() - slot;
        let end = directive_end(self.bytes, i + 1, open_above)?;
        self.brackets.truncate(depth);
        self.directives.truncate(slot + 1);
        self.data_bodies.retain(|&at| at < hash);
        self.data_runs.retain(|&(at, _)| at < hash);
        // The body starts after the parameter list.
        let body = self.bytes[hash..i]
            .iter()
            .position(|&c| c == b')')
            .map_or(i, |p| hash + p + 1);
        self.token_level.push((body, end));
        Some(end)
    }

    fn close(&mut self, c: u8, i: usize) -> bool {
        match self.brackets.pop() {
            Some((open, at)) if closer_for(open) == c => {
                if open == b'{' && self.misindented.is_none() {
                    let (opener, _) = indentation(self.bytes, at);
                    let (closer, first) = indentation(self.bytes, i);
                    if first && closer.len() < opener.len() && opener.starts_with(closer) {
                        self.misindented = Some((at, i));
                    }
                }
                if !self.open_bodies.is_empty() {
                    self.body_bracket_closed(c, i);
                }
                true
            }
            Some((open, at)) => {
                self.diags.push(
                    Diagnostic::error(
                        codes::UNMATCHED_DELIMITER,
                        self.span(i, i + 1),
                        format!(
                            "`{}` does not close the `{}` before it",
                            c as char, open as char
                        ),
                    )
                    .with_label(format!("expected `{}` here", closer_for(open) as char))
                    .with_secondary(self.span(at, at + 1), "this is the bracket still open")
                    .with_help(format!(
                        "close the `{}` with `{}` first, or remove this `{}`",
                        open as char,
                        closer_for(open) as char,
                        c as char
                    )),
                );
                false
            }
            None => {
                self.diags.push(
                    Diagnostic::error(
                        codes::UNMATCHED_DELIMITER,
                        self.span(i, i + 1),
                        format!("`{}` with nothing to close", c as char),
                    )
                    .with_label("no opening bracket before this")
                    .with_help("remove it, or add the opening bracket it belongs to"),
                );
                false
            }
        }
    }

    /// Handles `#word`; returns false when scanning should stop.
    fn directive(&mut self, hash: usize) -> bool {
        let b = self.bytes;
        let mut i = hash + 1;
        while i < b.len() && matches!(b[i], b' ' | b'\t' | 0x0B | 0x0C) {
            i += 1;
        }
        let start = i;
        while i < b.len() && is_word_byte(b[i]) {
            i += 1;
        }
        let word = std::str::from_utf8(&b[start..i]).unwrap_or("");
        let span = self.span(hash, i);
        if let Some(name) = OPENING_DIRECTIVES.iter().find(|d| **d == word) {
            self.directives.push((name, hash, i));
            if matches!(*name, "if" | "ifdef" | "ifndef") {
                self.open_body(None);
            }
            if *name == "macro" && self.open_macro.is_none() {
                self.open_macro = Some((hash, self.directives.len() - 1, self.brackets.len()));
            }
            if self.directives.len() > MAX_NESTING {
                self.too_deep(hash, i - hash, "directives");
                return false;
            }
        } else if word == "end" {
            if let Some((macro_hash, slot, depth)) = self.open_macro {
                if slot + 1 == self.directives.len() {
                    self.open_macro = None;
                    if self.brackets.len() != depth {
                        // The body leaves brackets open (or they were opened
                        // in branches): read token by token at its calls.
                        let body = self.bytes[macro_hash..hash]
                            .iter()
                            .position(|&c| c == b')')
                            .map_or(hash, |p| macro_hash + p + 1);
                        self.brackets.truncate(depth);
                        self.data_bodies.retain(|&at| at < macro_hash);
                        self.data_runs.retain(|&(at, _)| at < macro_hash);
                        self.deferred.retain(|&(at, _)| at < macro_hash);
                        self.open_bodies.retain(|b| b.group < slot + 1);
                        self.token_level.push((body, hash));
                    }
                }
            }
            self.end_body(hash);
            if self.directives.pop().is_none() {
                self.diags.push(
                    Diagnostic::error(codes::STRAY_DIRECTIVE, span, "`#end` with nothing to close")
                        .with_label("no #if, #while, #for, #macro or #switch is open here")
                        .with_help(
                            "remove this `#end`, or add the directive it was meant to close",
                        ),
                );
                return false;
            }
        } else if MIDDLE_DIRECTIVES.contains(&word) {
            let ok = match self.directives.last() {
                Some((open, ..)) => match word {
                    "else" => matches!(*open, "if" | "ifdef" | "ifndef" | "switch"),
                    "elseif" => *open == "if",
                    _ => *open == "switch",
                },
                None => false,
            };
            if !ok {
                let needs = match word {
                    "else" => "#if, #ifdef, #ifndef or #switch",
                    "elseif" => "#if",
                    _ => "#switch",
                };
                self.diags.push(
                    Diagnostic::error(
                        codes::STRAY_DIRECTIVE,
                        span,
                        format!("`#{word}` outside {needs}"),
                    )
                    .with_label(format!("no {needs} is open here"))
                    .with_help(format!("`#{word}` may only stand inside {needs} … #end")),
                );
                return false;
            }
            self.end_body(hash);
            match word {
                "else" => self.open_body(Some(i)),
                "break" => {}
                _ => self.open_body(None),
            }
        } else if word.is_empty() {
            // POV-Ray ignores a `#` that no directive name follows (its sample
            // language/image_size.pov has one before a `}`); so does the
            // grammar (which sees a space there), with this warning.
            self.blank.push((hash, hash + 1));
            self.diags.push(
                Diagnostic::warning(
                    codes::UNKNOWN_DIRECTIVE,
                    self.span(hash, hash + 1),
                    "a `#` with no directive name after it is ignored",
                )
                .with_label("stray `#`")
                .with_help(
                    "remove it, or write the directive it was meant to start (e.g. `#declare`)",
                ),
            );
            return true;
        } else if !PLAIN_DIRECTIVES.contains(&word) {
            let all = OPENING_DIRECTIVES
                .iter()
                .chain(MIDDLE_DIRECTIVES)
                .chain(PLAIN_DIRECTIVES)
                .chain(&["end"])
                .copied();
            let help = match did_you_mean(word, all) {
                Some(s) => format!("did you mean `#{s}`?"),
                None => "directives are #declare #local #undef #if #ifdef #ifndef #else #elseif #switch #case #range #break #while #for #macro #end #include #debug #warning #error #default #version".into(),
            };
            let msg = format!("unknown directive `#{word}`");
            self.diags.push(
                Diagnostic::error(codes::UNKNOWN_DIRECTIVE, span, msg)
                    .with_label("not a directive")
                    .with_help(help),
            );
            return false;
        }
        self.prev = b'{';
        true
    }

    /// A branch body of the innermost directive begins: at `start`, or after
    /// the parenthesised head that follows.
    fn open_body(&mut self, start: Option<usize>) {
        self.open_bodies.push(OpenBody {
            group: self.directives.len(),
            start,
            brackets: self.brackets.len(),
            balanced: true,
        });
    }

    /// A bracket closed at `i` (`c`): it may end the innermost body's head,
    /// or close, inside a body, a bracket opened before that body.
    fn body_bracket_closed(&mut self, c: u8, i: usize) {
        let open = self.brackets.len();
        if let Some(b) = self.open_bodies.last_mut() {
            if b.start.is_none() && c == b')' && open == b.brackets {
                b.start = Some(i + 1);
                return;
            }
        }
        for b in self.open_bodies.iter_mut().rev() {
            if b.start.is_none() {
                continue;
            }
            if b.brackets <= open {
                break;
            }
            b.balanced = false;
        }
    }

    /// The body of the innermost directive's branch ends at the `#` at `hash`:
    /// noted in [`Marks::deferred`] when it may be left unread.
    fn end_body(&mut self, hash: usize) {
        if self
            .open_bodies
            .last()
            .is_none_or(|b| b.group != self.directives.len())
        {
            return;
        }
        let Some(b) = self.open_bodies.pop() else {
            return;
        };
        if let Some(start) = b.start {
            if b.balanced && b.brackets == self.brackets.len() && hash - start >= DEFER_MIN {
                self.deferred.retain(|&(at, _)| at < start);
                self.deferred.push((start, hash));
            }
        }
    }

    fn finish(&mut self) {
        if let Some(&(name, start, end)) = self.directives.last() {
            self.diags.push(
                Diagnostic::error(
                    codes::UNCLOSED_DIRECTIVE,
                    self.span(start, end),
                    format!("`#{name}` is never closed with `#end`"),
                )
                .with_label("opened here")
                .with_help(format!("add `#end` where the #{name} should end")),
            );
        }
        if let Some(&(open, at)) = self.brackets.last() {
            // A `{` left open at the end: when a `}` earlier was indented like an
            // outer block, the block it closed is most likely the one missing its
            // own `}` (its contents were read as the outer block's).
            if let (b'{', Some((culprit, closer))) = (open, self.misindented) {
                let line = |i: usize| self.bytes[..i].iter().filter(|&&c| c == b'\n').count() + 1;
                self.diags.push(
                    Diagnostic::error(
                        codes::UNCLOSED_DELIMITER,
                        self.span(culprit, culprit + 1),
                        "unclosed block: this `{` is most likely never closed",
                    )
                    .with_label("opened here")
                    .with_secondary(
                        self.span(closer, closer + 1),
                        format!(
                            "indented like an outer block, so probably not this block's `}}` (line {})",
                            line(closer)
                        ),
                    )
                    .with_secondary(
                        self.span(at, at + 1),
                        "so this `{` is still open at the end of the file",
                    )
                    .with_help(format!(
                        "add `}}` where the block opened on line {} should end",
                        line(culprit)
                    )),
                );
                return;
            }
            let what = match open {
                b'{' => "block",
                b'(' => "parenthesis",
                _ => "bracket",
            };
            self.diags.push(
                Diagnostic::error(
                    codes::UNCLOSED_DELIMITER,
                    self.span(at, at + 1),
                    format!("unclosed {what}: `{}` is never closed", open as char),
                )
                .with_label("opened here")
                .with_help(format!(
                    "add `{}` where it should end",
                    closer_for(open) as char
                )),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn codes(text: &str) -> Vec<&'static str> {
        check(text, FileId(0)).into_iter().map(|d| d.code).collect()
    }

    /// Vectors of 2 to 5 plain numbers are marked for the grammar to skip;
    /// anything else at a `<` is left to the grammar.
    #[test]
    fn plain_vectors_are_marked() {
        let marked = |text: &str| check_marking(text, FileId(0)).1.plain_vectors;
        assert_eq!(marked("A <1, -2.5, 3e-2> + < 1 , 2 , >"), [2, 20]);
        for text in [
            "<1 2>",
            "<a, 1>",
            "<1,2,3,4,5,6>",
            "<1e, 2>",
            "<1, /* c */ 2>",
            "<1>",
        ] {
            assert!(marked(text).is_empty(), "{text}");
        }
        assert_eq!(marked("<<1, 2>, 3>"), [1]);
        assert_eq!(codes("sphere { \u{2}1, 2> 1 }"), [codes::SYNTAX_EXPECTED]);
    }

    /// The bodies a parse for rendering may leave unread: long ones whose
    /// brackets balance, outermost only, `#switch` clauses and `#else` alike.
    #[test]
    fn long_balanced_branch_bodies_are_deferred() {
        let long = "sphere { 0, 1 } ".repeat(20);
        let deferred = |text: &str| -> Vec<String> {
            let (_, marks) = check_marking(text, FileId(0));
            marks
                .deferred
                .iter()
                .map(|&(s, e)| text[s..e].trim().to_string())
                .collect()
        };
        let text = format!("#if (A) {long} #elseif (B) x #else {long} #end");
        assert_eq!(deferred(&text), [long.trim(), long.trim()]);
        // Nested: the outer body only.
        let inner = format!("#if (C) {long} #end");
        let text = format!("#if ((A)) {inner} #end");
        assert_eq!(deferred(&text), [inner.as_str()]);
        let text =
            format!("#switch (A) #case (1) {long} #break #range (2, 3) {long} #else {long} #end");
        assert_eq!(deferred(&text).len(), 3);
        // Brackets that cross the body's ends, and a body in a macro read
        // token by token, stay.
        assert!(deferred(&format!("union {{ #if (A) }} {long} union {{ #end }}")).is_empty());
        assert!(deferred(&format!("#if (A) {long} {{ #else }} {long} #end")).is_empty());
        let text = format!("#macro M() #if (A) {long} #write (F, \"{{\") mesh2 {{ #end #end");
        assert!(deferred(&text).is_empty());
        assert!(deferred("#if (A) sphere { 0, 1 } #end").is_empty());
        // The body starts after the head's closing parenthesis.
        let text = format!("#ifdef (A[(1)]) {long}#end");
        assert_eq!(deferred(&text), [long.trim()]);
        let (_, marks) = check_marking(&text, FileId(0));
        assert_eq!(marks.deferred[0].0, "#ifdef (A[(1)])".len());
    }

    #[test]
    fn clean_input_passes() {
        assert!(
            codes("sphere { <0,0,0>, 1 /* a /* nested */ comment */ } // x\n\"s\\\"\"").is_empty()
        );
    }

    #[test]
    fn finds_unclosed_things() {
        assert_eq!(codes("sphere { 0, 1"), vec![codes::UNCLOSED_DELIMITER]);
        assert_eq!(codes("/* open"), vec![codes::UNCLOSED_COMMENT]);
        assert_eq!(codes("#debug \"open\n"), vec![codes::UNCLOSED_STRING]);
        assert_eq!(codes("#if (1)\n"), vec![codes::UNCLOSED_DIRECTIVE]);
        assert_eq!(codes("#end"), vec![codes::STRAY_DIRECTIVE]);
        assert_eq!(codes("#delcare A = 1;"), vec![codes::UNKNOWN_DIRECTIVE]);
        assert_eq!(codes(")"), vec![codes::UNMATCHED_DELIMITER]);
    }

    #[test]
    fn deep_nesting_is_refused() {
        let deep = "(".repeat(20_000) + "1" + &")".repeat(20_000);
        assert_eq!(codes(&deep), vec![codes::NESTING_TOO_DEEP]);
        let neg = "-".repeat(20_000) + "1";
        assert_eq!(codes(&neg), vec![codes::NESTING_TOO_DEEP]);
    }
}
