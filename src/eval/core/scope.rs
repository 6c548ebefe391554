//! Identifier scopes: the global table plus one local table per macro call and
//! include file, searched innermost first.
//!
//! Each binding carries a stamp that changes whenever it is written (see
//! `reuse.rs`): while a top-level item is evaluated, a [`Journal`] notes which
//! names it read (with the stamps it found) and which bindings of the scopes
//! that outlive the item it wrote, so a later frame can tell whether the item
//! would read the same values and, if so, reuse what it did.

use super::value::Value;
use crate::span::Span;
use crate::syntax::Sym;
use rustc_hash::{FxHashMap, FxHashSet};
use std::cell::{Cell, RefCell};

/// One binding: the value, where it was declared and whether it was ever read.
#[derive(Clone, Debug)]
pub(crate) struct Binding {
    pub(crate) value: Value,
    pub(crate) span: Span,
    pub(crate) used: Cell<bool>,
    /// Which write made this value (0: not stamped, in a scope the item
    /// being journaled opened itself).
    pub(crate) stamp: u64,
}

impl Binding {
    fn new(value: Value, span: Span) -> Binding {
        Binding {
            value,
            span,
            used: Cell::new(false),
            stamp: 0,
        }
    }
}

/// One scope's bindings.
pub(crate) type Frame = FxHashMap<Sym, Binding>;

/// What one top-level item did to the scopes that were open when it began.
#[derive(Default)]
pub(crate) struct Journal {
    /// Scopes below this index were open when the item began.
    base: usize,
    /// `base` while the local scopes are hidden (see [`Scopes::hide_locals`]).
    saved_bases: Vec<usize>,
    /// Each name the item read from those scopes before writing it: the stamp
    /// found (0: not bound) and whether the read marked it used.
    pub(crate) reads: FxHashMap<Sym, (u64, bool)>,
    /// The (scope, name) bindings the item wrote, in first-write order.
    pub(crate) writes: Vec<(usize, Sym)>,
    wrote: FxHashSet<(usize, Sym)>,
    /// The item read something not named here (every visible name).
    pub(crate) opaque: bool,
}

impl Journal {
    /// A read of `name` found in scope `at` (`None`: not bound) with `stamp`.
    /// A binding the item wrote itself is no dependency.
    fn read(&mut self, at: Option<usize>, name: Sym, stamp: u64, used: bool) {
        if at.is_some_and(|at| self.wrote.contains(&(at, name))) {
            return;
        }
        let e = self.reads.entry(name).or_insert((stamp, false));
        e.1 |= used;
    }

    fn write(&mut self, frame: usize, name: Sym) {
        if frame < self.base && self.wrote.insert((frame, name)) {
            self.writes.push((frame, name));
        }
    }
}

/// A binding a journaled item wrote: its scope, its name and the binding it
/// left (`None`: removed).
pub(crate) type Written = (usize, Sym, Option<Binding>);

/// The stack of scopes; index 0 is global.
pub(crate) struct Scopes {
    frames: Vec<Frame>,
    /// The journal of the top-level item being evaluated, if any.
    journal: RefCell<Option<Journal>>,
    /// The next fresh stamp (see `reuse.rs`).
    pub(crate) next_stamp: Cell<u64>,
}

impl Scopes {
    pub(crate) fn new() -> Scopes {
        Scopes {
            frames: vec![FxHashMap::default()],
            journal: RefCell::new(None),
            next_stamp: Cell::new(1),
        }
    }

    /// A stamp no write made before.
    pub(crate) fn fresh_stamp(&self) -> u64 {
        let s = self.next_stamp.get();
        self.next_stamp.set(s + 1);
        s
    }

    /// Starts journaling a top-level item (the scopes open now outlive it).
    pub(crate) fn begin_journal(&mut self) {
        *self.journal.get_mut() = Some(Journal {
            base: self.frames.len(),
            ..Journal::default()
        });
    }

    /// Stops journaling; the bindings the item wrote get fresh stamps.
    /// Returns the journal and the bindings written (`None`: removed).
    pub(crate) fn end_journal(&mut self) -> Option<(Journal, Vec<Written>)> {
        let j = self.journal.get_mut().take()?;
        let mut out = Vec::with_capacity(j.writes.len());
        for &(frame, name) in &j.writes {
            let b = self.frames.get_mut(frame).and_then(|f| f.get_mut(&name));
            let b = b.map(|b| {
                b.stamp = self.next_stamp.get();
                self.next_stamp.set(b.stamp + 1);
                b.clone()
            });
            out.push((frame, name, b));
        }
        Some((j, out))
    }

    /// Whether an item is being journaled.
    pub(crate) fn journaling(&self) -> bool {
        self.journal.borrow().is_some()
    }

    /// Notes a read of the binding found at scope `at` (or of no binding).
    fn note_read(&self, found: Option<(usize, &Binding)>, name: Sym, used: bool) {
        let mut j = self.journal.borrow_mut();
        let Some(j) = j.as_mut() else { return };
        match found {
            Some((at, _)) if at >= j.base => {}
            Some((at, b)) => j.read(Some(at), name, b.stamp, used),
            None => j.read(None, name, 0, used),
        }
    }

    /// Notes a write of `name` in scope `frame`; outside a journal, the
    /// binding gets a fresh stamp at once.
    fn note_write(&mut self, frame: usize, name: Sym) {
        match self.journal.get_mut() {
            Some(j) => j.write(frame, name),
            None => {
                let s = self.fresh_stamp();
                if let Some(b) = self.frames.get_mut(frame).and_then(|f| f.get_mut(&name)) {
                    b.stamp = s;
                }
            }
        }
    }

    /// The innermost binding of `name` and the index of its scope.
    fn find(&self, name: Sym) -> Option<(usize, &Binding)> {
        self.frames
            .iter()
            .enumerate()
            .rev()
            .find_map(|(i, f)| f.get(&name).map(|b| (i, b)))
    }

    /// The stamp of the binding `name` has now (0: none).
    pub(crate) fn stamp_of(&self, name: Sym) -> u64 {
        self.find(name).map_or(0, |(_, b)| b.stamp)
    }

    /// Gives the binding of `name` in scope `frame` the stamp `stamp`.
    pub(crate) fn set_stamp(&mut self, frame: usize, name: Sym, stamp: u64) {
        if let Some(b) = self.frames.get_mut(frame).and_then(|f| f.get_mut(&name)) {
            b.stamp = stamp;
        }
    }

    /// Puts back what a journaled item did: `b` as the binding of `name` in
    /// scope `frame` (`None`: unbound there).
    pub(crate) fn restore(&mut self, frame: usize, name: Sym, b: Option<&Binding>) {
        let Some(f) = self.frames.get_mut(frame) else {
            return;
        };
        match b {
            Some(b) => {
                f.insert(name, b.clone());
            }
            None => {
                f.remove(&name);
            }
        }
    }

    /// Looks `name` up, innermost scope first, and marks it as used.
    pub(crate) fn get(&self, name: Sym) -> Option<&Binding> {
        let found = self.find(name);
        self.note_read(found, name, true);
        let (_, b) = found?;
        b.used.set(true);
        Some(b)
    }

    /// Looks `name` up without marking it used.
    pub(crate) fn get_quiet(&self, name: Sym) -> Option<&Binding> {
        let found = self.find(name);
        self.note_read(found, name, false);
        found.map(|(_, b)| b)
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

    /// Mutable access to the innermost binding of `name` (a write of it).
    pub(crate) fn get_mut(&mut self, name: Sym) -> Option<&mut Binding> {
        let found = self.find(name);
        self.note_read(found, name, false);
        let (at, _) = found?;
        self.note_write(at, name);
        self.frames[at].get_mut(&name)
    }

    /// `#declare`: updates the innermost existing binding, else creates a global one.
    pub(crate) fn declare(&mut self, name: Sym, value: Value, span: Span) {
        if let Some(b) = self.get_mut(name) {
            b.value = value;
            b.span = span;
        } else {
            self.frames[0].insert(name, Binding::new(value, span));
            self.note_write(0, name);
        }
    }

    /// `#local`: binds in the innermost scope.
    pub(crate) fn local(&mut self, name: Sym, value: Value, span: Span) {
        let at = self.frames.len() - 1;
        self.frames
            .last_mut()
            .expect("global scope")
            .insert(name, Binding::new(value, span));
        self.note_write(at, name);
    }

    /// `#undef`: removes the innermost binding; false if there was none.
    pub(crate) fn undef(&mut self, name: Sym) -> bool {
        let found = self.find(name);
        self.note_read(found, name, false);
        let Some((at, _)) = found else {
            return false;
        };
        self.frames[at].remove(&name);
        self.note_write(at, name);
        true
    }

    /// Opens a local scope.
    pub(crate) fn push(&mut self) {
        self.frames.push(FxHashMap::default());
    }

    /// Copies of the local scopes (all but the global one), innermost last.
    /// (What is read through the copies later is not journaled, so every
    /// binding of an outliving local scope counts as read now.)
    pub(crate) fn locals(&self) -> Vec<Frame> {
        if let Some(j) = self.journal.borrow_mut().as_mut() {
            for (at, f) in self.frames.iter().enumerate().take(j.base).skip(1) {
                for (n, b) in f {
                    j.read(Some(at), *n, b.stamp, false);
                }
            }
        }
        self.frames[1..].to_vec()
    }

    /// Opens the local scopes `frames` (as [`Scopes::locals`] gave them) above
    /// the current ones; [`Scopes::pop`] each to close them.
    pub(crate) fn reopen(&mut self, frames: &[Frame]) {
        self.frames.extend(frames.iter().cloned());
    }

    /// The index of the scope `name` is found in (innermost first).
    pub(crate) fn frame_of(&self, name: Sym) -> Option<usize> {
        let found = self.find(name);
        self.note_read(found, name, false);
        found.map(|(at, _)| at)
    }

    /// Gives `name` in scope `frame` the value `value`, if it is still bound
    /// there (see [`Scopes::frame_of`]).
    pub(crate) fn set_in(&mut self, frame: usize, name: Sym, value: Value) {
        if let Some(b) = self.frames.get_mut(frame).and_then(|f| f.get_mut(&name)) {
            b.value = value;
            self.note_write(frame, name);
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
        // The innermost binding tells (a journal notes it as read).
        let found = self.find(name);
        self.note_read(found, name, false);
        self.frames[1..].iter().any(|f| f.contains_key(&name))
    }

    /// How many scopes are open (1: only the global one).
    pub(crate) fn depth(&self) -> usize {
        self.frames.len()
    }

    /// Takes the local scopes away, leaving the global one alone visible;
    /// [`Scopes::restore_locals`] puts them back.
    pub(crate) fn hide_locals(&mut self) -> Vec<Frame> {
        if let Some(j) = self.journal.get_mut() {
            j.saved_bases.push(j.base);
            j.base = j.base.min(1);
        }
        self.frames.split_off(1)
    }

    /// Puts back the local scopes [`Scopes::hide_locals`] took (any opened
    /// since are closed).
    pub(crate) fn restore_locals(&mut self, locals: Vec<Frame>) {
        self.frames.truncate(1);
        self.frames.extend(locals);
        if let Some(j) = self.journal.get_mut() {
            j.base = j.saved_bases.pop().unwrap_or(j.base);
        }
    }

    /// Every name visible now, for "did you mean".
    pub(crate) fn names(&self) -> Vec<Sym> {
        if let Some(j) = self.journal.borrow_mut().as_mut() {
            j.opaque = true;
        }
        self.frames.iter().flat_map(|f| f.keys().copied()).collect()
    }
}
