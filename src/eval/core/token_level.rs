//! Macros read token by token, as POV-Ray reads them. A macro such as
//!
//! ```text
//! #if (WriteFile) #write (F, "mesh2 {\n", N, #else mesh2 { vertex_vectors { N, #end
//! ```
//!
//! opens brackets in one `#if` branch and closes them in another one later on:
//! only the branches taken balance. The prepass keeps such a body as text
//! ([`crate::syntax::ast::MacroDef::raw`]); at each call the `#if`, `#ifdef` and
//! `#ifndef` whose conditions read only names the body never assigns are
//! decided on entry (so they decide the same way wherever they stand, even in a
//! loop), the branches not taken and the directives themselves are blanked, and
//! what is left is parsed like any macro body. Each set of decisions is parsed
//! once per evaluation.

use super::{Evaluator, Fail, R};
use crate::diag::{codes, Diagnostic};
use crate::span::Span;
use crate::syntax::ast::{DirectiveKind, Item, MacroDef};
use crate::syntax::trivia::comment_end;
use std::rc::Rc;

/// What the calls of macros read token by token keep for the next call: each
/// body's directives (scanned once per macro), its conditions (parsed once)
/// and the bodies parsed so far, by macro and decisions.
#[derive(Default)]
pub(crate) struct TokenBodies {
    scans: rustc_hash::FxHashMap<usize, Rc<Scan>>,
    conditions: rustc_hash::FxHashMap<(usize, usize), Rc<crate::syntax::ast::File>>,
    bodies: rustc_hash::FxHashMap<(usize, Vec<u8>), Rc<[Item]>>,
}

/// A body's text with its directive groups and the names it assigns.
struct Scan {
    text: String,
    groups: Vec<Group>,
    assigned: rustc_hash::FxHashSet<String>,
}

/// A directive of the body: the offsets of its `#`, of the end of its word and
/// (for conditions) of the end of its parenthesised condition.
#[derive(Clone, Copy, Debug)]
struct Mark {
    word: &'static str,
    hash: usize,
    word_end: usize,
    cond_end: usize,
}

/// An `#if`/`#ifdef`/`#ifndef`, `#while`, `#for`, `#switch` or `#macro` and
/// what it holds.
#[derive(Debug)]
struct Group {
    /// The opening directive, then each `#elseif`/`#else` (or `#case`…).
    parts: Vec<Mark>,
    /// The `#end`.
    end: Mark,
    children: Vec<Group>,
}

const OPENING: &[&str] = &["if", "ifdef", "ifndef", "while", "for", "switch", "macro"];
const MIDDLE: &[&str] = &["else", "elseif", "case", "range", "break"];

/// The directives of `t` (strings and comments skipped).
fn marks(t: &[u8]) -> Vec<Mark> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < t.len() {
        match t[i] {
            b'/' if comment_end(t, i).is_some() => i = comment_end(t, i).unwrap_or(t.len()),
            b'"' => i = string_end(t, i),
            b'#' => {
                let hash = i;
                i += 1;
                while i < t.len() && matches!(t[i], b' ' | b'\t') {
                    i += 1;
                }
                let start = i;
                while i < t.len() && (t[i].is_ascii_alphanumeric() || t[i] == b'_') {
                    i += 1;
                }
                let word = std::str::from_utf8(&t[start..i]).unwrap_or("");
                let Some(word) = OPENING
                    .iter()
                    .chain(MIDDLE)
                    .chain(&["end"])
                    .find(|w| **w == word)
                else {
                    continue;
                };
                let cond_end = if matches!(*word, "if" | "ifdef" | "ifndef" | "elseif") {
                    condition_end(t, i).unwrap_or(i)
                } else {
                    i
                };
                out.push(Mark {
                    word,
                    hash,
                    word_end: i,
                    cond_end,
                });
            }
            _ => i += 1,
        }
    }
    out
}

/// The offset after the string starting at `i`.
fn string_end(t: &[u8], mut i: usize) -> usize {
    i += 1;
    while i < t.len() && !matches!(t[i], b'"' | b'\n') {
        i += if t[i] == b'\\' { 2 } else { 1 };
    }
    (i + 1).min(t.len())
}

/// The offset after the parenthesised condition that starts (after blanks) at
/// `i`, if there is one.
fn condition_end(t: &[u8], mut i: usize) -> Option<usize> {
    while i < t.len() && t[i].is_ascii_whitespace() {
        i += 1;
    }
    if t.get(i) != Some(&b'(') {
        return None;
    }
    let mut depth = 0;
    while i < t.len() {
        match t[i] {
            b'"' => {
                i = string_end(t, i);
                continue;
            }
            b'(' => depth += 1,
            b')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i + 1);
                }
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// The directive groups of the body, outermost first; `None` when the
/// directives do not nest (the prepass has reported that).
fn groups(marks: &[Mark]) -> Option<Vec<Group>> {
    let mut stack: Vec<Group> = Vec::new();
    let mut top = Vec::new();
    for &m in marks {
        if OPENING.contains(&m.word) {
            stack.push(Group {
                parts: vec![m],
                end: m,
                children: Vec::new(),
            });
        } else if m.word == "end" {
            let mut g = stack.pop()?;
            g.end = m;
            match stack.last_mut() {
                Some(parent) => parent.children.push(g),
                None => top.push(g),
            }
        } else {
            stack.last_mut()?.parts.push(m);
        }
    }
    stack.is_empty().then_some(top)
}

/// The names the body assigns: `#declare`/`#local NAME`, `#for (NAME, …)`,
/// `#read (F, NAME, …)` (all of them, to be safe).
fn assigned(t: &str) -> rustc_hash::FxHashSet<&str> {
    let mut out = rustc_hash::FxHashSet::default();
    let w = words(t);
    for (k, &(at, word)) in w.iter().enumerate() {
        let after_hash = t[..at].trim_end().ends_with('#');
        if !after_hash {
            continue;
        }
        match word {
            "declare" | "local" | "for" => {
                if let Some(&(_, name)) = w.get(k + 1) {
                    out.insert(name);
                }
            }
            "read" => {
                // Every name in the argument list may be assigned.
                let end = t[at..].find(')').map_or(t.len(), |e| at + e);
                for &(p, name) in &w[k + 1..] {
                    if p >= end {
                        break;
                    }
                    out.insert(name);
                }
            }
            _ => {}
        }
    }
    out
}

impl Evaluator<'_> {
    /// The items of `m`'s body for this call (its parameters bound): the
    /// `#if`s the call decides decided, the rest parsed (see the module's text).
    pub(crate) fn token_level_body(&mut self, m: &Rc<MacroDef>, raw: Span) -> R<Rc<[Item]>> {
        let id = Rc::as_ptr(m) as usize;
        let scan = match self.token_bodies.scans.get(&id) {
            Some(s) => s.clone(),
            None => {
                let text: String = self
                    .sources
                    .get(raw.file)
                    .text
                    .get(raw.start as usize..raw.end as usize)
                    .unwrap_or("")
                    .to_string();
                let Some(groups) = groups(&marks(text.as_bytes())) else {
                    return Err(Fail::silent());
                };
                let assigned = assigned(&text).into_iter().map(str::to_string).collect();
                let s = Rc::new(Scan {
                    text,
                    groups,
                    assigned,
                });
                self.token_bodies.scans.insert(id, s.clone());
                s
            }
        };
        let mut blank: Vec<(usize, usize)> = Vec::new();
        let mut decisions = Vec::new();
        for g in &scan.groups {
            self.decide(id, g, &scan, raw, &mut blank, &mut decisions)?;
        }
        let key = (id, decisions);
        if let Some(items) = self.token_bodies.bodies.get(&key) {
            return Ok(items.clone());
        }
        let mut bytes = scan.text.clone().into_bytes();
        for (s, e) in blank {
            for b in &mut bytes[s..e] {
                if *b != b'\n' {
                    *b = b' ';
                }
            }
        }
        let resolved = String::from_utf8(bytes).unwrap_or_default();
        let (file, diags) = crate::syntax::parse_at(&resolved, raw.file, raw.start as usize);
        let failed = diags.iter().any(Diagnostic::is_error);
        for mut d in diags {
            if d.is_error() {
                d.notes.push(format!(
                    "the body of macro `{}` balances its brackets only across `#if` branches; \
                     rts reads it at the call, after deciding the `#if`s whose conditions \
                     the body does not change, and what was left does not parse",
                    m.name
                ));
            }
            self.report(d.into());
        }
        if failed || !file.unparsed.is_empty() {
            return Err(Fail::silent());
        }
        let items: Rc<[Item]> = file.items.into();
        self.token_bodies.bodies.insert(key, items.clone());
        Ok(items)
    }

    /// Decides `g` (and what it holds) when it is an `#if`-like group whose
    /// conditions read nothing `assigned`: records the branch taken in
    /// `decisions` and the text to blank in `blank`. Other groups stay, their
    /// contents decided.
    fn decide(
        &mut self,
        id: usize,
        g: &Group,
        scan: &Scan,
        raw: Span,
        blank: &mut Vec<(usize, usize)>,
        decisions: &mut Vec<u8>,
    ) -> R<()> {
        let (text, assigned) = (&scan.text, &scan.assigned);
        let first = g.parts[0];
        let decidable = matches!(first.word, "if" | "ifdef" | "ifndef")
            && g.parts.iter().all(|p| {
                p.word == "else"
                    || (p.cond_end > p.word_end
                        && !names(&text[p.word_end..p.cond_end]).any(|n| assigned.contains(n)))
            });
        if !decidable {
            for c in &g.children {
                self.decide(id, c, scan, raw, blank, decisions)?;
            }
            return Ok(());
        }
        // The branch taken: the first whose condition holds, else `#else`.
        let mut taken = None;
        for (k, p) in g.parts.iter().enumerate() {
            let holds = match p.word {
                "else" => true,
                word => self.condition(id, word, text, p, raw)?,
            };
            if holds {
                taken = Some(k);
                break;
            }
        }
        decisions.push(taken.map_or(u8::MAX, |k| k.min(254) as u8));
        let Some(k) = taken else {
            blank.push((first.hash, g.end.word_end));
            return Ok(());
        };
        let from = g.parts[k].cond_end;
        let to = g.parts.get(k + 1).map_or(g.end.hash, |p| p.hash);
        blank.push((first.hash, from));
        blank.push((to, g.end.word_end));
        for c in g
            .children
            .iter()
            .filter(|c| c.parts[0].hash >= from && c.end.hash < to)
        {
            self.decide(id, c, scan, raw, blank, decisions)?;
        }
        Ok(())
    }

    /// Whether the condition of `p` (an `#if`, `#elseif`, `#ifdef` or
    /// `#ifndef`) holds now.
    fn condition(&mut self, id: usize, word: &str, text: &str, p: &Mark, raw: Span) -> R<bool> {
        let file = match self.token_bodies.conditions.get(&(id, p.hash)) {
            Some(f) => f.clone(),
            None => {
                // The directive and its condition as written, closed by an
                // `#end` (the spans of the condition are the file's).
                let head = &text[p.hash..p.cond_end];
                let word = if word == "elseif" { "if" } else { word };
                let src = format!("#{word}{}\n#end", &head[p.word_end - p.hash..]);
                let base = raw.start as usize + p.word_end - word.len() - 1;
                let (file, diags) = crate::syntax::parse_at(&src, raw.file, base);
                if diags.iter().any(Diagnostic::is_error) {
                    for d in diags {
                        self.report(d.into());
                    }
                    return Err(Fail::silent());
                }
                let file = Rc::new(file);
                self.token_bodies
                    .conditions
                    .insert((id, p.hash), file.clone());
                file
            }
        };
        let kind = file.items.first().and_then(|i| match i {
            Item::Directive(d) => Some(&d.kind),
            _ => None,
        });
        match kind {
            Some(DirectiveKind::If { branches, .. }) if !branches.is_empty() => {
                let cond = &branches[0].0;
                let v = self.expr(cond)?;
                Ok(self.to_float(&v, cond.span)? != 0.0)
            }
            Some(DirectiveKind::IfDef { negate, target, .. }) => {
                Ok(self.is_defined(target)? != *negate)
            }
            _ => Err(Diagnostic::error(
                codes::SYNTAX_EXPECTED,
                Span::new(
                    raw.file,
                    raw.start as usize + p.hash,
                    raw.start as usize + p.cond_end,
                ),
                "cannot read this condition",
            )
            .into()),
        }
    }
}

/// The words of `s` with their offsets.
fn words(s: &str) -> Vec<(usize, &str)> {
    let mut v = Vec::new();
    let b = s.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if b[i].is_ascii_alphabetic() || b[i] == b'_' {
            let start = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            v.push((start, &s[start..i]));
        } else {
            i += 1;
        }
    }
    v
}

/// The names written in `s`.
fn names(s: &str) -> impl Iterator<Item = &str> {
    s.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| w.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_'))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directives_group_and_conditions_end() {
        let t = "#if (A) { #else ( #end #while (I<3) #if (I) x #end #end";
        let m = marks(t.as_bytes());
        let g = groups(&m).expect("groups");
        assert_eq!(g.len(), 2);
        assert_eq!(g[0].parts.len(), 2);
        assert_eq!(&t[g[0].parts[0].word_end..g[0].parts[0].cond_end], " (A)");
        assert_eq!(g[1].children.len(), 1);
    }

    #[test]
    fn assigned_names_are_found() {
        let a = assigned("#local J = 1; # declare K=2; #for (I, 1, 3) #read (F, X, Y) #end");
        for n in ["J", "K", "I", "X", "Y"] {
            assert!(a.contains(n), "{n}");
        }
        assert!(!a.contains("WriteFile"));
    }
}
