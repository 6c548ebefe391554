//! The evaluated contents of a block, consumed item by item ("consume, then finish").

use super::value::Value;
use super::{Evaluator, Fail, R};
use crate::diag::{codes, did_you_mean, Diagnostic};
use crate::span::Span;
use glam::DVec3;

/// One evaluated item of a block: directives have run and macros have expanded.
#[derive(Clone, Debug)]
pub(crate) enum Tok {
    /// A bare keyword.
    Kw(&'static str, Span),
    /// A value.
    Val(Value, Span),
    /// A nested block, evaluated: its keyword and value.
    Block(&'static str, Value, Span),
    /// `,`.
    Comma(Span),
    /// `;`.
    Semi(Span),
    /// `[ … ]`, evaluated.
    Bracket(Vec<Tok>, Span),
    /// A `pigment`, `finish` or `normal` block written in a texture or an
    /// object, not evaluated yet: it modifies the one in force there.
    Deferred(std::rc::Rc<Deferred>),
    /// A run of plain numbers and vectors, packed (only in the list blocks
    /// that read it so: see `list.rs`; elsewhere it is read item by item).
    Data(std::rc::Rc<crate::syntax::data::DataRun>),
}

/// A block kept for later evaluation (see [`Tok::Deferred`]), with what it can
/// see where it is written: a macro's parameters and locals outlive the call
/// that wrote the block into its caller's texture, and errors in it show the
/// macro calls that led there.
#[derive(Debug)]
pub(crate) struct Deferred {
    /// The block as written.
    pub(crate) block: std::rc::Rc<crate::syntax::ast::Block>,
    /// The local scopes (not the global one) in force where it is written.
    pub(crate) locals: Vec<super::scope::Frame>,
    /// The macro and include chain where it is written.
    pub(crate) trace: Vec<crate::diag::Label>,
}

impl Tok {
    pub(crate) fn span(&self) -> Span {
        match self {
            Tok::Kw(_, s)
            | Tok::Val(_, s)
            | Tok::Block(_, _, s)
            | Tok::Comma(s)
            | Tok::Semi(s)
            | Tok::Bracket(_, s) => *s,
            Tok::Deferred(b) => b.block.span,
            Tok::Data(d) => d.span,
        }
    }

    /// What the item is, for messages.
    pub(crate) fn describe(&self) -> String {
        match self {
            Tok::Kw(k, _) => format!("the keyword `{k}`"),
            Tok::Val(v, _) => v.kind().to_string(),
            Tok::Block(k, _, _) => format!("a `{k}` block"),
            Tok::Comma(_) => "`,`".into(),
            Tok::Semi(_) => "`;`".into(),
            Tok::Bracket(..) => "`[ … ]`".into(),
            Tok::Deferred(b) => format!("a `{}` block", b.block.keyword.name),
            Tok::Data(_) => "numbers and vectors".into(),
        }
    }
}

/// Where expanded items go: a block's list, or (at top level) straight into the scene,
/// so a loop that makes a million objects never holds them all as items.
pub(crate) struct Sink {
    /// Items not yet placed or consumed.
    pub(crate) toks: Vec<Tok>,
    /// Whether items are placed in the scene as soon as they are produced.
    pub(crate) top: bool,
    /// Whether runs of plain numbers stay packed ([`Tok::Data`]); else each
    /// number and vector is an item of its own.
    pub(crate) packed: bool,
}

impl Sink {
    /// A sink that collects items for a block.
    pub(crate) fn new() -> Sink {
        Sink {
            toks: Vec::new(),
            top: false,
            packed: false,
        }
    }

    /// A sink that places items in the scene.
    pub(crate) fn top() -> Sink {
        Sink {
            toks: Vec::new(),
            top: true,
            packed: false,
        }
    }

    /// Adds an item.
    pub(crate) fn push(&mut self, t: Tok) {
        self.toks.push(t);
    }
}

/// The items of one block being consumed.
pub(crate) struct Cursor {
    toks: std::vec::IntoIter<Tok>,
    peeked: Option<Tok>,
    /// The block's keyword.
    pub(crate) block: &'static str,
    /// The whole block.
    pub(crate) span: Span,
    /// Where the last consumed item ended, for "missing value" reports.
    pub(crate) last: Span,
    seen: Vec<&'static str>,
    /// Set after an erroneous value until the next keyword or block, so values that
    /// belonged to a misspelled keyword are not reported again.
    pub(crate) poisoned: bool,
}

impl Cursor {
    /// Puts `toks` in front of the items still to come (an object pattern's
    /// entries, read where the pattern keyword stood).
    pub(crate) fn inject(&mut self, toks: Vec<Tok>) {
        let mut all = toks;
        all.extend(self.peeked.take());
        all.extend(std::mem::take(&mut self.toks));
        self.toks = all.into_iter();
    }

    pub(crate) fn new(toks: Vec<Tok>, block: &'static str, span: Span) -> Cursor {
        Cursor {
            toks: toks.into_iter(),
            peeked: None,
            block,
            span,
            last: Span {
                end: span.start,
                ..span.head()
            },
            seen: Vec::new(),
            poisoned: false,
        }
    }

    /// The next item.
    pub(crate) fn next(&mut self) -> Option<Tok> {
        let t = self.peeked.take().or_else(|| self.toks.next());
        if let Some(t) = &t {
            self.last = t.span();
            match t {
                Tok::Val(Value::Poison, _) | Tok::Block(_, Value::Poison, _) => {
                    self.poisoned = true
                }
                Tok::Kw(..) | Tok::Block(..) => self.poisoned = false,
                _ => {}
            }
        }
        t
    }

    /// The items still to come, without consuming them.
    pub(crate) fn rest(&self) -> impl Iterator<Item = &Tok> {
        self.peeked.iter().chain(self.toks.as_slice())
    }

    /// The next item without consuming it.
    pub(crate) fn peek(&mut self) -> Option<&Tok> {
        if self.peeked.is_none() {
            self.peeked = self.toks.next();
        }
        self.peeked.as_ref()
    }

    /// Consumes a comma if one is next.
    pub(crate) fn comma(&mut self) {
        if matches!(self.peek(), Some(Tok::Comma(_))) {
            self.next();
        }
    }

    /// Whether the next item is a value (not a keyword or block).
    pub(crate) fn value_next(&mut self) -> bool {
        matches!(self.peek(), Some(Tok::Val(..)))
    }

    /// Takes the next value; `what` names it for the error ("the sphere's radius").
    pub(crate) fn value(&mut self, what: &str) -> R<(Value, Span)> {
        match self.peek() {
            Some(Tok::Val(..)) => match self.next() {
                Some(Tok::Val(Value::Poison, _)) => Err(Fail::silent()),
                Some(Tok::Val(v, s)) => Ok((v, s)),
                _ => unreachable!(),
            },
            Some(other) => {
                let (desc, span) = (other.describe(), other.span());
                Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    span,
                    format!("expected {what}, found {desc}"),
                )
                .with_label(format!("{what} should come before this"))
                .into())
            }
            None => Err(Diagnostic::error(
                codes::MISSING_VALUE,
                Span {
                    start: self.span.end.saturating_sub(1),
                    ..self.span
                },
                format!("expected {what} in `{}`", self.block),
            )
            .with_label(format!("{what} is missing"))
            .with_secondary(self.last, "after this")
            .into()),
        }
    }

    /// Records keyword `kw` as given; a second time is reported as a duplicate.
    pub(crate) fn once(&mut self, kw: &'static str, span: Span) -> R<()> {
        if self.seen.contains(&kw) {
            // The duplicate's value is still in the stream: do not report it again.
            self.poisoned = true;
            return Err(Diagnostic::error(
                codes::DUPLICATE_PARAMETER,
                span,
                format!("`{kw}` is given twice in this `{}`", self.block),
            )
            .with_label("second time")
            .with_help(format!("remove one of the `{kw}`s"))
            .into());
        }
        self.seen.push(kw);
        Ok(())
    }
}

impl Evaluator<'_> {
    /// The next value as a float.
    pub(crate) fn take_float(&mut self, c: &mut Cursor, what: &str) -> R<f64> {
        let (v, s) = c.value(what)?;
        self.to_float(&v, s)
    }

    /// The optional on/off after a flag keyword (`hollow`, `global_lights on`):
    /// `true` when no value follows.
    pub(crate) fn take_switch(&mut self, c: &mut Cursor) -> R<bool> {
        if c.value_next() {
            Ok(self.take_float(c, "on or off")? != 0.0)
        } else {
            Ok(true)
        }
    }

    /// The next value as a 3-vector (floats promote).
    pub(crate) fn take_vec3(&mut self, c: &mut Cursor, what: &str) -> R<DVec3> {
        let (v, s) = c.value(what)?;
        self.to_vec3(&v, s)
    }

    /// The next value as a colour.
    pub(crate) fn take_colour(&mut self, c: &mut Cursor, what: &str) -> R<crate::scene::Colour> {
        let (v, s) = c.value(what)?;
        self.to_colour(&v, s)
    }

    /// A float if the next item is a value, else `default` (for `metallic [AMOUNT]`).
    pub(crate) fn take_optional_float(&mut self, c: &mut Cursor, default: f64) -> R<f64> {
        if c.value_next() {
            self.take_float(c, "a number")
        } else {
            Ok(default)
        }
    }

    /// "unknown parameter" for a keyword not valid in the block, with a suggestion.
    pub(crate) fn unknown_keyword(&self, c: &Cursor, kw: &str, span: Span, valid: &[&str]) -> Fail {
        let mut d = Diagnostic::error(
            codes::UNKNOWN_PARAMETER,
            span,
            format!("`{kw}` is not valid in `{}`", c.block),
        )
        .with_label(format!("not a `{}` parameter", c.block));
        d = match did_you_mean(kw, valid.iter().copied()) {
            Some(s) => d.with_help(format!("did you mean `{s}`?")),
            None => d.with_help(format!("`{}` accepts: {}", c.block, valid.join(", "))),
        };
        d.into()
    }

    /// An item that does not belong where it stands.
    pub(crate) fn unexpected(&self, c: &Cursor, tok: &Tok, valid: &[&str]) -> Fail {
        if let Tok::Val(Value::Poison, _) | Tok::Block(_, Value::Poison, _) = tok {
            return Fail::silent();
        }
        if c.poisoned && matches!(tok, Tok::Val(..) | Tok::Comma(_)) {
            return Fail::silent();
        }
        if let Tok::Kw(k, s) = tok {
            return self.unknown_keyword(c, k, *s, valid);
        }
        if let Tok::Block(k, _, s) = tok {
            if !valid.contains(k) {
                return self.unknown_keyword(c, k, *s, valid);
            }
        }
        Diagnostic::error(
            codes::UNEXPECTED_ITEM,
            tok.span(),
            format!("{} does not belong in `{}`", tok.describe(), c.block),
        )
        .with_label("does not belong here")
        .with_help(format!("`{}` accepts: {}", c.block, valid.join(", ")))
        .into()
    }
}
