//! The contents of a list block (`vertex_vectors { … }`, `face_indices { … }`,
//! …): runs of plain numbers and vectors kept packed as the parser read them
//! (no value per element), and other values (expressions, declared names) one
//! by one. Readers walk the elements in order.

use super::value::{Value, Vector};
use crate::span::Span;
use crate::syntax::data::DataRun;
use std::rc::Rc;

/// The list blocks whose contents are kept packed.
pub(crate) const PACKED_LISTS: [&str; 6] = [
    "vertex_vectors",
    "normal_vectors",
    "uv_vectors",
    "face_indices",
    "normal_indices",
    "uv_indices",
];

/// The elements of a list block.
#[derive(Debug, Default)]
pub struct List {
    parts: Vec<Part>,
    len: usize,
}

#[derive(Debug)]
enum Part {
    Packed(Rc<DataRun>),
    One(Value),
}

/// One element of a [`List`].
#[derive(Clone, Copy, Debug)]
pub(crate) enum Elem<'a> {
    /// A packed number (one) or vector (2 to 5).
    Numbers(&'a [f64]),
    /// Any other value.
    Value(&'a Value),
}

impl Elem<'_> {
    /// The number, if the element is one.
    pub(crate) fn float(&self) -> Option<f64> {
        match *self {
            Elem::Numbers([x]) => Some(*x),
            Elem::Value(Value::Float(x)) => Some(*x),
            _ => None,
        }
    }

    /// The element as a value (a packed vector becomes a vector).
    pub(crate) fn value(&self) -> Value {
        match *self {
            Elem::Numbers([x]) => Value::Float(*x),
            Elem::Numbers(v) => Value::Vector(Vector::from_slice(v)),
            Elem::Value(v) => v.clone(),
        }
    }
}

impl List {
    /// Adds a packed run.
    pub(crate) fn push_packed(&mut self, run: Rc<DataRun>) {
        self.len += run.len;
        self.parts.push(Part::Packed(run));
    }

    /// Adds one value.
    pub(crate) fn push(&mut self, v: Value) {
        self.len += 1;
        self.parts.push(Part::One(v));
    }

    /// How many elements.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// The elements in order.
    pub(crate) fn iter(&self) -> impl Iterator<Item = Elem<'_>> + '_ {
        self.parts
            .iter()
            .flat_map(|p| -> Box<dyn Iterator<Item = Elem<'_>> + '_> {
                match p {
                    Part::Packed(run) => Box::new(run.elements().map(Elem::Numbers)),
                    Part::One(v) => Box::new(std::iter::once(Elem::Value(v))),
                }
            })
    }

    /// The elements as values, each with the list's span (for readers that
    /// take any value).
    pub(crate) fn listed(&self, span: Span) -> Vec<(Value, Span)> {
        self.iter().map(|e| (e.value(), span)).collect()
    }
}
