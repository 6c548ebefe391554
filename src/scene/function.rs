//! The compiled form of a `function { }`: a flat stack program. A function is
//! compiled once when it is declared (by the evaluator) and run millions of
//! times by isosurfaces and function patterns (the interpreter is
//! `crate::pattern::function`), so the program names nothing and needs no
//! tables: a list of operations on a value stack.

use super::Pigment;
use std::sync::Arc;

/// The deepest value stack a program may need (checked when compiling).
pub const MAX_STACK: usize = 64;

/// The deepest chain of functions calling functions (checked when compiling).
pub const MAX_CALL_DEPTH: usize = 32;

/// One instruction. Operands are popped from the value stack and the result
/// pushed; binary operators pop the right operand first.
#[derive(Clone, Debug)]
pub enum Op {
    /// Push a constant.
    Const(f64),
    /// Push parameter `i`.
    Param(u8),
    /// `-a`.
    Neg,
    /// `!a`: 1 when a is 0, else 0.
    Not,
    /// `a + b`.
    Add,
    /// `a - b`.
    Sub,
    /// `a * b`.
    Mul,
    /// `a / b` (IEEE: a division by 0 gives an infinity, as in POV-Ray's VM).
    Div,
    /// `a < b` (1 or 0).
    Lt,
    /// `a <= b`.
    Le,
    /// `a > b`.
    Gt,
    /// `a >= b`.
    Ge,
    /// `a = b`.
    Eq,
    /// `a != b`.
    Ne,
    /// `a & b`.
    And,
    /// `a | b`.
    Or,
    /// A float function of one argument (`sin`, `sqrt`, …).
    F1(fn(f64) -> f64),
    /// A float function of two arguments (`pow`, `atan2`, `min`, …).
    F2(fn(f64, f64) -> f64),
    /// `select(c, a, b)`: a when c < 0, else b.
    Select3,
    /// `select(c, a, b, d)`: a when c < 0, b when c = 0, d when c > 0.
    Select4,
    /// `c ? a : b`.
    Cond,
    /// Call a declared function with the top `n` values as arguments.
    Call(Arc<Function>, u8),
    /// Component `c` (0 red/x, 1 green/y, 2 blue/z, 3 filter, 4 transmit, 5 gray)
    /// of a colour- or vector-valued function called with the top values (as many
    /// as it takes).
    Component(Arc<Function>, u8),
    /// A built-in internal function (`functions.inc`'s, see `crate::pattern::internal`)
    /// of the top `n` values.
    Internal(fn(&[f64]) -> f64, u8),
}

/// What a function computes.
#[derive(Clone, Debug)]
pub enum Body {
    /// A float expression.
    Float(Vec<Op>),
    /// `function { pigment { … } }`: the pigment's colour at `<x, y, z>`.
    Pigment(Arc<Pigment>),
    /// `function { pattern { … } }`: the pattern's value at `<x, y, z>` in [0, 1].
    Pattern(Arc<Pigment>),
    /// `function { spline { … } }`: the spline's value (a vector) at the argument.
    Spline(Arc<super::Spline>),
}

/// A compiled function.
#[derive(Clone, Debug)]
pub struct Function {
    /// How many arguments it takes.
    pub arity: usize,
    /// What it computes.
    pub body: Body,
    /// How deep calls to other functions nest inside it (1 for none).
    pub depth: usize,
}

impl PartialEq for Function {
    fn eq(&self, other: &Function) -> bool {
        std::ptr::eq(self, other)
    }
}

impl Function {
    /// Whether the function gives a colour or vector (a pigment or spline
    /// function) rather than a float.
    pub fn is_colour(&self) -> bool {
        matches!(self.body, Body::Pigment(_) | Body::Spline(_))
    }
}

/// How many values `op` pops and pushes.
pub fn stack_effect(op: &Op) -> (usize, usize) {
    match op {
        Op::Const(_) | Op::Param(_) => (0, 1),
        Op::Neg | Op::Not | Op::F1(_) => (1, 1),
        Op::Select3 | Op::Cond => (3, 1),
        Op::Select4 => (4, 1),
        Op::Call(_, n) | Op::Internal(_, n) => (*n as usize, 1),
        Op::Component(f, _) => (f.arity, 1),
        _ => (2, 1),
    }
}

/// The deepest stack `ops` reaches, or `None` when an operator would find too
/// few operands (a compiler bug) or the end leaves other than one value.
pub fn max_depth(ops: &[Op]) -> Option<usize> {
    let mut sp = 0usize;
    let mut max = 0;
    for op in ops {
        let (pop, push) = stack_effect(op);
        sp = sp.checked_sub(pop)? + push;
        max = max.max(sp);
    }
    (sp == 1).then_some(max)
}
