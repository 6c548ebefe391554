//! Identifier scopes: the global table plus one local table per macro call and
//! include file, searched innermost first.

use super::value::Value;
use crate::span::Span;
use crate::syntax::Sym;
use rustc_hash::FxHashMap;
use std::cell::Cell;

/// One binding: the value, where it was declared and whether it was ever read.
#[derive(Clone, Debug)]
pub(crate) struct Binding {
    pub(crate) value: Value,
    pub(crate) span: Span,
    pub(crate) used: Cell<bool>,
}

impl Binding {
    fn new(value: Value, span: Span) -> Binding {
        Binding {
            value,
            span,
            used: Cell::new(false),
        }
    }
}

/// One scope's bindings.
pub(crate) type Frame = FxHashMap<Sym, Binding>;

/// The stack of scopes; index 0 is global.
pub(crate) struct Scopes {
    frames: Vec<Frame>,
}

impl Scopes {
    pub(crate) fn new() -> Scopes {
        Scopes {
            frames: vec![FxHashMap::default()],
        }
    }

    /// Looks `name` up, innermost scope first, and marks it as used.
    pub(crate) fn get(&self, name: Sym) -> Option<&Binding> {
        let b = self.frames.iter().rev().find_map(|f| f.get(&name))?;
        b.used.set(true);
        Some(b)
    }

    /// Looks `name` up without marking it used.
    pub(crate) fn get_quiet(&self, name: Sym) -> Option<&Binding> {
        self.frames.iter().rev().find_map(|f| f.get(&name))
    }

    /// Global bindings never read, in declaration order of their spans.
    pub(crate) fn unused_globals(&self) -> Vec<(Sym, Span)> {
        let mut v: Vec<(Sym, Span)> = self.frames[0]
            .iter()
            .filter(|(_, b)| !b.used.get() && !matches!(b.value, Value::Macro(_)))
            .map(|(n, b)| (*n, b.span))
            .collect();
        v.sort_by_key(|(_, s)| (s.file.0, s.start));
        v
    }

    /// The macros bound globally.
    pub(crate) fn global_macros(&self) -> Vec<std::rc::Rc<crate::syntax::ast::MacroDef>> {
        self.frames[0]
            .values()
            .filter_map(|b| match &b.value {
                Value::Macro(m) => Some(m.clone()),
                _ => None,
            })
            .collect()
    }

    /// The global bindings, with a short display of simple values (for editors).
    pub(crate) fn globals(&self) -> Vec<crate::eval::Declared> {
        let fmt = |v: &[f64]| {
            let parts: Vec<String> = v.iter().map(|c| format!("{c}")).collect();
            format!("<{}>", parts.join(", "))
        };
        self.frames[0]
            .iter()
            .map(|(n, b)| crate::eval::Declared {
                name: n.name().to_string(),
                span: b.span,
                kind: b.value.kind(),
                value: match &b.value {
                    Value::Float(f) => Some(format!("{f}")),
                    Value::Vector(v) => Some(fmt(v.as_slice())),
                    Value::Colour(c) => {
                        Some(format!("rgbft {}", fmt(&super::value::colour_to_array(c))))
                    }
                    Value::Str(s) => Some(format!("{s:?}")),
                    _ => None,
                },
            })
            .collect()
    }

    /// Mutable access to the innermost binding of `name`.
    pub(crate) fn get_mut(&mut self, name: Sym) -> Option<&mut Binding> {
        self.frames.iter_mut().rev().find_map(|f| f.get_mut(&name))
    }

    /// `#declare`: updates the innermost existing binding, else creates a global one.
    pub(crate) fn declare(&mut self, name: Sym, value: Value, span: Span) {
        if let Some(b) = self.get_mut(name) {
            b.value = value;
            b.span = span;
        } else {
            self.frames[0].insert(name, Binding::new(value, span));
        }
    }

    /// `#local`: binds in the innermost scope.
    pub(crate) fn local(&mut self, name: Sym, value: Value, span: Span) {
        self.frames
            .last_mut()
            .expect("global scope")
            .insert(name, Binding::new(value, span));
    }

    /// `#undef`: removes the innermost binding; false if there was none.
    pub(crate) fn undef(&mut self, name: Sym) -> bool {
        self.frames
            .iter_mut()
            .rev()
            .any(|f| f.remove(&name).is_some())
    }

    /// Opens a local scope.
    pub(crate) fn push(&mut self) {
        self.frames.push(FxHashMap::default());
    }

    /// Copies of the local scopes (all but the global one), innermost last.
    pub(crate) fn locals(&self) -> Vec<Frame> {
        self.frames[1..].to_vec()
    }

    /// Opens the local scopes `frames` (as [`Scopes::locals`] gave them) above
    /// the current ones; [`Scopes::pop`] each to close them.
    pub(crate) fn reopen(&mut self, frames: &[Frame]) {
        self.frames.extend(frames.iter().cloned());
    }

    /// The index of the scope `name` is found in (innermost first).
    pub(crate) fn frame_of(&self, name: Sym) -> Option<usize> {
        self.frames.iter().rposition(|f| f.contains_key(&name))
    }

    /// Gives `name` in scope `frame` the value `value`, if it is still bound
    /// there (see [`Scopes::frame_of`]).
    pub(crate) fn set_in(&mut self, frame: usize, name: Sym, value: Value) {
        if let Some(b) = self.frames.get_mut(frame).and_then(|f| f.get_mut(&name)) {
            b.value = value;
        }
    }

    /// Closes the innermost local scope and gives its bindings (an empty table
    /// for the global scope, which stays).
    pub(crate) fn take_top(&mut self) -> Frame {
        if self.frames.len() > 1 {
            self.frames.pop().unwrap_or_default()
        } else {
            Frame::default()
        }
    }

    /// Closes the innermost local scope.
    pub(crate) fn pop(&mut self) {
        if self.frames.len() > 1 {
            self.frames.pop();
        }
    }

    /// Whether `name` is bound in a local scope (a macro's or an include
    /// file's).
    pub(crate) fn is_local(&self, name: Sym) -> bool {
        self.frames[1..].iter().any(|f| f.contains_key(&name))
    }

    /// How many scopes are open (1: only the global one).
    pub(crate) fn depth(&self) -> usize {
        self.frames.len()
    }

    /// Takes the local scopes away, leaving the global one alone visible;
    /// [`Scopes::restore_locals`] puts them back.
    pub(crate) fn hide_locals(&mut self) -> Vec<Frame> {
        self.frames.split_off(1)
    }

    /// Puts back the local scopes [`Scopes::hide_locals`] took (any opened
    /// since are closed).
    pub(crate) fn restore_locals(&mut self, locals: Vec<Frame>) {
        self.frames.truncate(1);
        self.frames.extend(locals);
    }

    /// Every name visible now, for "did you mean".
    pub(crate) fn names(&self) -> Vec<Sym> {
        self.frames.iter().flat_map(|f| f.keys().copied()).collect()
    }
}
