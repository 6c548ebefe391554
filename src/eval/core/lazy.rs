//! The built-in library read on demand. `#include "textures.inc"` used to parse
//! and evaluate some hundred declarations (and the files they include) for a
//! scene that uses two of them; parsing was nine tenths of a typical sample
//! scene's time. A library file is now cut at its top-level declarations and
//! macros by a cheap scan (no parse); each is parsed and evaluated the first
//! time its name is used, as it would have been at the `#include`:
//!
//! - with only the global scope visible (a macro's locals never shadow what
//!   the library saw), in the library file (its own includes resolve there);
//! - before any global name it mentions is declared again or undefined (those
//!   declarations first evaluate every pending item that mentions the name),
//!   and the include's declaration supersedes an earlier binding of its name,
//!   so the values are those eager evaluation gives.
//!
//! Anything the scan does not recognise (a top-level `#local`, a directive as a
//! declaration's value, …) makes the file read the usual way, and a test
//! checks every library file gives the same names and values both ways.

use super::cursor::Sink;
use super::Evaluator;
use crate::span::{FileId, Span};
use crate::syntax::{intern, Sym};
use rustc_hash::FxHashMap;
use std::rc::Rc;

/// One top-level piece of a library file.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Piece {
    /// `#declare NAME = …` or `#macro NAME(…) … #end`, from `start` to `end`:
    /// evaluated when NAME is first used.
    Named {
        /// The name it binds.
        name: String,
        /// Where it starts.
        start: usize,
        /// Where it ends.
        end: usize,
        /// The words its text mentions, interned, each once.
        words: Vec<Sym>,
    },
    /// Anything else, evaluated at the `#include`.
    Eager {
        /// Where it starts.
        start: usize,
        /// Where it ends.
        end: usize,
    },
    /// `#ifndef (NAME) … #end` around the rest of the file (an include guard):
    /// when NAME is not defined, the pieces inside.
    Guard {
        /// The guard's name.
        name: String,
        /// The pieces inside.
        inner: Vec<Piece>,
    },
}

/// Items of library files not evaluated yet, and who mentions which name.
#[derive(Clone, Default)]
pub(crate) struct Pending {
    /// A hash of every change made so far: two evaluations whose changes hash
    /// the same have the same pending items (see `reuse.rs`).
    pub(crate) state: u64,
    /// Set whenever the pending items are looked at or changed (see `reuse.rs`).
    pub(crate) touched: std::cell::Cell<bool>,
    /// The pending item binding each name.
    by_name: FxHashMap<Sym, usize>,
    /// The pending items mentioning each name.
    mentions: FxHashMap<Sym, Vec<usize>>,
    items: Vec<Option<Item>>,
    /// Library files already cut, by file.
    splits: FxHashMap<FileId, Option<Rc<Vec<Piece>>>>,
    /// The names of the items being evaluated now (innermost last): their own
    /// declaration is not a redeclaration.
    forcing: Vec<Sym>,
}

#[derive(Clone)]
struct Item {
    name: Sym,
    file: FileId,
    start: usize,
    end: usize,
}

impl Pending {
    /// Whether `name` is bound by an item not evaluated yet.
    pub(crate) fn has(&self, name: Sym) -> bool {
        self.touched.set(true);
        self.by_name.contains_key(&name)
    }

    /// The names bound by pending items (for "did you mean").
    pub(crate) fn names(&self) -> impl Iterator<Item = Sym> + '_ {
        self.touched.set(true);
        self.by_name.keys().copied()
    }

    /// Notes a change (`what`, with its operands) in [`Pending::state`].
    fn changed(&mut self, what: u64, a: u64, b: u64) {
        self.touched.set(true);
        let mut h = self.state ^ what.wrapping_mul(0x9E37_79B9_7F4A_7C15);
        for x in [a, b] {
            h = (h ^ x).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            h ^= h >> 31;
        }
        self.state = h;
    }
}

/// Skips spaces, comments and the inside of strings from `i`.
fn skip_trivia(b: &[u8], mut i: usize) -> usize {
    loop {
        match b.get(i) {
            Some(c) if c.is_ascii_whitespace() => i += 1,
            Some(b'/') if crate::syntax::trivia::comment_end(b, i).is_some() => {
                i = crate::syntax::trivia::comment_end(b, i).unwrap_or(b.len());
            }
            _ => return i,
        }
    }
}

fn word_at(b: &[u8], i: usize) -> usize {
    let mut j = i;
    while j < b.len() && (b[j].is_ascii_alphanumeric() || b[j] == b'_') {
        j += 1;
    }
    j
}

/// A token of the scan: a directive (`#name`), a word, a string, or one byte.
#[derive(Debug, PartialEq)]
enum Tok<'a> {
    Directive(&'a str),
    Word(&'a str),
    Other(u8),
}

/// The next token at or after `i` (trivia skipped): the token, where it starts
/// and where it ends; `None` at the end.
fn next(text: &str, i: usize) -> Option<(Tok<'_>, usize, usize)> {
    let b = text.as_bytes();
    let i = skip_trivia(b, i);
    let c = *b.get(i)?;
    if c == b'#' {
        let mut j = i + 1;
        while j < b.len() && matches!(b[j], b' ' | b'\t') {
            j += 1;
        }
        let e = word_at(b, j);
        return Some((Tok::Directive(&text[j..e]), i, e));
    }
    if c.is_ascii_alphabetic() || c == b'_' {
        let e = word_at(b, i);
        return Some((Tok::Word(&text[i..e]), i, e));
    }
    if c == b'"' {
        let mut j = i + 1;
        while j < b.len() && b[j] != b'"' && b[j] != b'\n' {
            j += if b[j] == b'\\' { 2 } else { 1 };
        }
        return Some((Tok::Other(b'"'), i, (j + 1).min(b.len())));
    }
    if c.is_ascii_digit() || c == b'.' {
        // A number (`1e5` is one token, not a number and a word).
        let mut j = i;
        while j < b.len() && (b[j].is_ascii_alphanumeric() || b[j] == b'.') {
            j += 1;
        }
        return Some((Tok::Other(b'0'), i, j));
    }
    Some((Tok::Other(c), i, i + 1))
}

const OPENERS: [&str; 7] = ["if", "ifdef", "ifndef", "while", "for", "switch", "macro"];

/// The end of the directive body opened just before `i` (after its `#end`).
fn matching_end(text: &str, mut i: usize) -> Option<usize> {
    let mut depth = 1;
    while let Some((t, _, e)) = next(text, i) {
        i = e;
        if let Tok::Directive(d) = t {
            if OPENERS.contains(&d) {
                depth += 1;
            } else if d == "end" {
                depth -= 1;
                if depth == 0 {
                    return Some(e);
                }
            }
        }
    }
    None
}

/// The end of a declaration's value starting at `i`: after the first `;` at
/// bracket depth 0, else before the next directive at depth 0 (or the end).
fn value_end(text: &str, mut i: usize) -> usize {
    let mut depth = 0i32;
    while let Some((t, s, e)) = next(text, i) {
        match t {
            Tok::Other(b'{' | b'(' | b'[') => depth += 1,
            Tok::Other(b'}' | b')' | b']') => depth -= 1,
            Tok::Other(b';') if depth <= 0 => return e,
            Tok::Directive(_) if depth <= 0 => return s,
            _ => {}
        }
        i = e;
    }
    text.len()
}

/// The words of `text[a..b]` (identifiers, keywords: what it may refer to),
/// each once.
fn words(text: &str, mut a: usize, b: usize) -> Vec<Sym> {
    let mut out: Vec<Sym> = Vec::new();
    while let Some((t, s, e)) = next(text, a) {
        if s >= b {
            break;
        }
        if let Tok::Word(w) = t {
            let w = intern(w);
            if !out.contains(&w) {
                out.push(w);
            }
        }
        a = e;
    }
    out
}

/// Cuts `text[from..to]` into pieces; `None` when it holds something the cut
/// does not understand (the file is then read the usual way).
fn cut(text: &str, from: usize, to: usize) -> Option<Vec<Piece>> {
    let mut pieces: Vec<Piece> = Vec::new();
    let eager = |pieces: &mut Vec<Piece>, start: usize, end: usize| match pieces.last_mut() {
        Some(Piece::Eager { end: e, .. }) if *e <= start => *e = end,
        _ => pieces.push(Piece::Eager { start, end }),
    };
    let mut i = from;
    while let Some((t, s, e)) = next(text, i) {
        if s >= to {
            break;
        }
        match t {
            Tok::Directive("declare") => {
                let (Tok::Word(name), _, ne) = next(text, e)? else {
                    return None;
                };
                let (Tok::Other(b'='), _, ve) = next(text, ne)? else {
                    return None; // `#declare A[I] = …` or worse: read it the usual way
                };
                if matches!(next(text, ve), Some((Tok::Directive(_), _, _))) {
                    return None; // a directive as the value
                }
                let end = value_end(text, ve).min(to);
                pieces.push(Piece::Named {
                    name: name.to_string(),
                    start: s,
                    end,
                    words: words(text, ve, end),
                });
                i = end;
            }
            Tok::Directive("macro") => {
                let (Tok::Word(name), _, ne) = next(text, e)? else {
                    return None;
                };
                let end = matching_end(text, ne)?.min(to);
                pieces.push(Piece::Named {
                    name: name.to_string(),
                    start: s,
                    end,
                    words: words(text, ne, end),
                });
                i = end;
            }
            Tok::Directive("local" | "undef") => return None,
            Tok::Directive("ifndef") if pieces.is_empty() => {
                // An include guard around the whole rest?
                let (Tok::Other(b'('), _, pe) = next(text, e)? else {
                    return None;
                };
                let (Tok::Word(name), _, ne) = next(text, pe)? else {
                    return None;
                };
                let (Tok::Other(b')'), _, body) = next(text, ne)? else {
                    return None;
                };
                let end = matching_end(text, body)?;
                let rest = next(text, end).map(|(_, s, _)| s).unwrap_or(text.len());
                if rest < to {
                    // Something after the `#end`: not a guard around the file.
                    let end = end.min(to);
                    eager(&mut pieces, s, end);
                    i = end;
                    continue;
                }
                // The body without its `#end`.
                let inner_end = text[..end].rfind('#').unwrap_or(end);
                pieces.push(Piece::Guard {
                    name: name.to_string(),
                    inner: cut(text, body, inner_end)?,
                });
                i = end;
            }
            Tok::Directive(d) if OPENERS.contains(&d) => {
                let end = matching_end(text, e)?.min(to);
                eager(&mut pieces, s, end);
                i = end;
            }
            _ => {
                // Up to the next directive at depth 0.
                let end = value_end(text, e).min(to);
                let end = if end <= s { e } else { end };
                eager(&mut pieces, s, end);
                i = end;
            }
        }
    }
    Some(pieces)
}

impl Evaluator<'_> {
    /// Whether library files are read on demand (see the module's doc).
    fn lazy_library(&self, id: FileId) -> bool {
        self.options.lazy_library
            && self.sources.get(id).name.starts_with("<stdlib>/")
            && self.macro_depth == 0
    }

    /// Whether a piece the file would leave pending mentions a name that is
    /// local where the `#include` stands (in an include file's or a macro's
    /// scope): evaluated later, it would not see that local, so the file is
    /// read at the `#include` instead.
    fn mentions_locals(&self, pieces: &[Piece]) -> bool {
        pieces.iter().any(|p| match p {
            Piece::Named { name, words, .. } => {
                self.scope.is_local(intern(name)) || words.iter().any(|&w| self.scope.is_local(w))
            }
            Piece::Guard { name, inner } => {
                self.scope.is_local(intern(name)) || self.mentions_locals(inner)
            }
            Piece::Eager { .. } => false,
        })
    }

    /// `#include` of the library file `id` on demand; false when it must be
    /// read the usual way.
    pub(crate) fn include_lazily(&mut self, id: FileId, out: &mut Sink) -> bool {
        if !self.lazy_library(id) {
            return false;
        }
        self.pending.touched.set(true);
        let pieces = match self.pending.splits.get(&id) {
            Some(p) => p.clone(),
            None => {
                let text = &self.sources.get(id).text;
                let p = cut(text, 0, text.len()).map(Rc::new);
                self.pending.splits.insert(id, p.clone());
                p
            }
        };
        let Some(pieces) = pieces else {
            return false;
        };
        if self.scope.depth() > 1 && self.mentions_locals(&pieces) {
            return false;
        }
        self.include_stack.push(id);
        self.run_pieces(id, &pieces, out);
        self.include_stack.pop();
        true
    }

    fn run_pieces(&mut self, id: FileId, pieces: &[Piece], out: &mut Sink) {
        for piece in pieces {
            if self.stopped {
                return;
            }
            match piece {
                Piece::Eager { start, end } => {
                    let text = self.sources.get(id).text[*start..*end].to_string();
                    let (file, diags) = crate::syntax::parse_at(&text, id, *start);
                    let ok = !crate::diag::has_errors(&diags);
                    for d in diags {
                        self.report(d.into());
                    }
                    // No scope of its own: the cut refuses files with a
                    // top-level `#local` (and an include inside stays on demand).
                    if ok {
                        self.expand(&file.items, out);
                    }
                }
                Piece::Guard { name, inner } => {
                    let sym = intern(name);
                    if self.scope.get(sym).is_none() && !self.pending.has(sym) {
                        self.run_pieces(id, inner, out);
                    }
                }
                Piece::Named {
                    name,
                    start,
                    end,
                    words,
                } => {
                    let sym = intern(name);
                    let span = Span::new(id, *start, *end);
                    // Included again: the item already evaluated, or pending, stays.
                    if self.scope.get(sym).is_some_and(|b| b.span == span)
                        || self
                            .pending
                            .by_name
                            .get(&sym)
                            .and_then(|k| self.pending.items[*k].as_ref())
                            .is_some_and(|it| it.file == id && it.start == *start)
                    {
                        continue;
                    }
                    // The include's declaration replaces what was bound before.
                    self.before_bind(sym);
                    self.scope.undef(sym);
                    let k = self.pending.items.len();
                    self.pending.changed(1, u64::from(sym.0), *start as u64);
                    self.pending.changed(2, u64::from(id.0), *end as u64);
                    self.pending.items.push(Some(Item {
                        name: sym,
                        file: id,
                        start: *start,
                        end: *end,
                    }));
                    self.pending.by_name.insert(sym, k);
                    for &w in words {
                        self.pending.mentions.entry(w).or_default().push(k);
                    }
                }
            }
        }
    }

    /// Evaluates the pending library item binding `name`, if there is one.
    pub(crate) fn force(&mut self, name: Sym) {
        self.pending.touched.set(true);
        let Some(k) = self.pending.by_name.remove(&name) else {
            return;
        };
        self.pending.changed(3, u64::from(name.0), k as u64);
        let Some(item) = self.pending.items[k].take() else {
            return;
        };
        let text = self.sources.get(item.file).text[item.start..item.end].to_string();
        let (file, diags) = crate::syntax::parse_at(&text, item.file, item.start);
        let ok = !crate::diag::has_errors(&diags);
        for d in diags {
            self.report(d.into());
        }
        if !ok {
            return;
        }
        // As at the `#include`: the global scope only, in the library file.
        let locals = self.scope.hide_locals();
        let depth = std::mem::replace(&mut self.macro_depth, 0);
        self.include_stack.push(item.file);
        self.scope.push();
        let mut sink = Sink::new();
        self.pending.forcing.push(item.name);
        self.expand(&file.items, &mut sink);
        self.pending.forcing.pop();
        self.scope.pop();
        self.include_stack.pop();
        self.macro_depth = depth;
        self.scope.restore_locals(locals);
    }

    /// Before the global `name` is bound again or undefined: every pending item
    /// that mentions it is evaluated first (it saw the old value), and a
    /// pending item binding `name` is dropped (the new binding replaces it).
    pub(crate) fn before_bind(&mut self, name: Sym) {
        self.pending.touched.set(true);
        // Nothing saw a value of `name` if it has none (a macro's forward
        // reference to one defined later in the file, say).
        if self.pending.by_name.is_empty()
            || self.pending.forcing.contains(&name)
            || !(self.pending.has(name) || self.scope.get_quiet(name).is_some())
        {
            return;
        }
        if let Some(ks) = self.pending.mentions.remove(&name) {
            self.pending.changed(4, u64::from(name.0), ks.len() as u64);
            for k in ks {
                if let Some(n) = self.pending.items[k].as_ref().map(|i| i.name) {
                    self.force(n);
                }
            }
        }
        if let Some(k) = self.pending.by_name.remove(&name) {
            self.pending.changed(5, u64::from(name.0), k as u64);
            self.pending.items[k] = None;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(pieces: &[Piece]) -> Vec<String> {
        let mut out = Vec::new();
        for p in pieces {
            match p {
                Piece::Named { name, .. } => out.push(name.clone()),
                Piece::Eager { .. } => out.push("*".into()),
                Piece::Guard { name, inner } => {
                    out.push(format!("guard {name}"));
                    out.extend(names(inner));
                }
            }
        }
        out
    }

    #[test]
    fn a_library_is_cut_at_its_declarations_and_macros() {
        let t = "// c\n#include \"colors.inc\"\n#declare A = 1;\n#declare T = texture { pigment { A } } texture { B }\n#macro M(X) #if (X) 1 #end #end\n#version 3.7;\n#declare S = \"a;b#\";\n";
        let p = cut(t, 0, t.len()).expect("understood");
        assert_eq!(names(&p), ["*", "A", "T", "M", "*", "S"]);
        if let Piece::Named { words, .. } = &p[2] {
            assert!(words.contains(&intern("A")) && words.contains(&intern("B")));
        }
    }

    #[test]
    fn an_include_guard_is_seen_through() {
        let t = "#ifndef (G)\n#declare G = 1;\n#declare A = 2;\n#end\n";
        let p = cut(t, 0, t.len()).expect("understood");
        assert_eq!(names(&p), ["guard G", "G", "A"]);
    }

    #[test]
    fn what_the_cut_does_not_understand_is_read_as_usual() {
        assert!(cut("#local A = 1;", 0, 13).is_none());
        let t = "#declare A = #if (1) 2 #else 3 #end";
        assert!(cut(t, 0, t.len()).is_none());
        assert!(cut("#declare A[1] = 2;", 0, 18).is_none());
    }
}

#[cfg(test)]
mod library {
    use crate::eval::{eval, EvalOptions, STDLIB};
    use crate::source::SourceMap;

    /// Every global the scene `text` leaves, with its kind and value, after
    /// every name the library declares has been used (so each pending item
    /// is evaluated).
    fn globals(text: &str, lazy: bool) -> Vec<(String, &'static str, Option<String>)> {
        let mut sources = SourceMap::new();
        let id = sources.add("probe.rts", None, text.to_string());
        let (file, diags) = crate::syntax::parse(text, id);
        assert!(diags.is_empty(), "{diags:?}");
        let options = EvalOptions {
            lazy_library: lazy,
            ..EvalOptions::default()
        };
        let e = eval(&file, id, &mut sources, &options);
        let errors: Vec<_> = e.diagnostics.iter().filter(|d| d.is_error()).collect();
        assert!(errors.is_empty(), "{text}: {errors:?}");
        // Macros are compared by their use elsewhere (they are only parsed
        // when first called).
        let mut g: Vec<_> = e
            .globals
            .into_iter()
            .filter(|d| d.kind != "a macro")
            .map(|d| (d.name, d.kind, d.value))
            .collect();
        g.sort();
        g
    }

    /// A library included from an include file that has a local of a name
    /// the library declares: read at the `#include` (as POV-Ray does, its
    /// `#declare` then updates that local, and no global is left), not on
    /// demand (which would leave a global).
    #[test]
    fn a_library_included_where_its_names_are_local_is_read_at_the_include() {
        let dir = std::env::temp_dir().join(format!("rts-lazy-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        std::fs::write(
            dir.join("user.inc"),
            "#local Gray50 = rgb <1, 0, 0>;\n#include \"colors.inc\"\n",
        )
        .expect("write");
        let main = dir.join("main.rts");
        let text = "#include \"user.inc\"\n\
                    #ifdef (Gray50) #declare Got_ = 1; #else #declare Got_ = 0; #end\n"
            .to_string();
        std::fs::write(&main, &text).expect("write");
        let run = |lazy: bool| {
            let mut sources = SourceMap::new();
            let id = sources.add(main.display().to_string(), Some(main.clone()), text.clone());
            let (file, _) = crate::syntax::parse(&text, id);
            let options = EvalOptions {
                lazy_library: lazy,
                ..EvalOptions::default()
            };
            let e = eval(&file, id, &mut sources, &options);
            e.globals
                .into_iter()
                .find(|d| d.name == "Got_")
                .and_then(|d| d.value)
        };
        let (a, b) = (run(false), run(true));
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(a.as_deref(), Some("0"));
        assert_eq!(a, b);
    }

    #[test]
    fn every_library_file_gives_the_same_values_read_on_demand() {
        let mut lazy_files = 0;
        for (name, text) in STDLIB {
            // The names the file declares (eagerly read), each then used.
            let include = format!("#include \"{name}\"\n");
            let eager = globals(&include, false);
            let mut probe = include.clone();
            for (n, kind, _) in &eager {
                if *kind != "a macro" {
                    probe.push_str(&format!("#declare Probe_ = {n};\n"));
                }
            }
            let a = globals(&probe, false);
            let b = globals(&probe, true);
            assert_eq!(a, b, "{name}");
            if super::cut(text, 0, text.len()).is_some() {
                lazy_files += 1;
            }
        }
        assert!(
            lazy_files >= 10,
            "only {lazy_files} library files are read on demand"
        );
    }
}
