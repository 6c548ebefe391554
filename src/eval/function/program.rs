//! The compiled form of a `function { }`: a flat stack program, and the
//! interpreter that runs it. A function is compiled once when it is declared;
//! isosurfaces and function patterns run it millions of times, so running it
//! touches no names, no hash tables and allocates nothing.

use crate::scene::Pigment;
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
    /// A built-in internal function (see [`super::internal`]) of the top `n` values.
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
    Spline(Arc<crate::eval::animation::spline::Spline>),
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

    /// The function's float value for `args` (as many as [`Function::arity`];
    /// missing ones read as 0). A colour-valued function gives its gray value.
    pub fn eval(&self, args: &[f64]) -> f64 {
        match &self.body {
            Body::Float(ops) => run(ops, args),
            Body::Pigment(_) => self.component(args, 5),
            Body::Spline(_) => self.component(args, 0),
            Body::Pattern(p) => pattern_value(p, point(args)),
        }
    }

    /// Shorthand for a function of x, y, z.
    #[inline]
    pub fn eval3(&self, p: glam::DVec3) -> f64 {
        self.eval(&[p.x, p.y, p.z])
    }

    /// The colour `<r, g, b, f, t>` of a pigment function at `args` (for a float
    /// function: its value in every component).
    pub fn colour(&self, args: &[f64]) -> [f64; 5] {
        match &self.body {
            Body::Pigment(p) => {
                let c = crate::render::pigment::evaluate(p, point(args));
                [c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit]
            }
            Body::Spline(s) => s.eval(args.first().copied().unwrap_or(0.0)),
            _ => [self.eval(args); 5],
        }
    }

    /// Component `c` of [`Function::colour`] (5: the gray value).
    pub fn component(&self, args: &[f64], c: u8) -> f64 {
        let v = self.colour(args);
        match c {
            0..=4 => v[c as usize],
            _ => 0.297 * v[0] + 0.589 * v[1] + 0.114 * v[2],
        }
    }
}

fn point(args: &[f64]) -> glam::DVec3 {
    let a = |i: usize| args.get(i).copied().unwrap_or(0.0);
    glam::DVec3::new(a(0), a(1), a(2))
}

/// The value of the pattern of `pigment` at `p` (its transform applied).
fn pattern_value(pigment: &Pigment, p: glam::DVec3) -> f64 {
    use crate::render::pigment::patterns;
    use crate::scene::Pattern;
    let p = match &pigment.transform {
        Some(t) => t.inverse.transform_point3(p),
        None => p,
    };
    match &pigment.pattern {
        Pattern::Mapped(m) if m.kind.is_list() => {
            let q = patterns::warp(p, &m.mods);
            patterns::list_index(&m.kind, q) as f64
        }
        Pattern::Mapped(m) => patterns::value(&m.kind, p, &m.mods),
        Pattern::Checker(_) => crate::render::pigment::checker_index(p) as f64,
        _ => 0.0,
    }
}

fn b(c: bool) -> f64 {
    f64::from(u8::from(c))
}

/// Runs a float program. The compiler guarantees the stack never exceeds
/// [`MAX_STACK`] and every operator finds its operands.
fn run(ops: &[Op], args: &[f64]) -> f64 {
    let mut st = [0.0f64; MAX_STACK];
    let mut sp = 0usize;
    macro_rules! bin {
        ($f:expr) => {{
            sp -= 1;
            let r = st[sp];
            let l = st[sp - 1];
            st[sp - 1] = $f(l, r);
        }};
    }
    for op in ops {
        match op {
            Op::Const(c) => {
                st[sp] = *c;
                sp += 1;
            }
            Op::Param(i) => {
                st[sp] = args.get(*i as usize).copied().unwrap_or(0.0);
                sp += 1;
            }
            Op::Neg => st[sp - 1] = -st[sp - 1],
            Op::Not => st[sp - 1] = b(st[sp - 1] == 0.0),
            Op::Add => bin!(|l, r| l + r),
            Op::Sub => bin!(|l, r| l - r),
            Op::Mul => bin!(|l, r| l * r),
            Op::Div => bin!(|l, r| l / r),
            Op::Lt => bin!(|l, r| b(l < r)),
            Op::Le => bin!(|l, r| b(l <= r)),
            Op::Gt => bin!(|l, r| b(l > r)),
            Op::Ge => bin!(|l, r| b(l >= r)),
            Op::Eq => bin!(|l: f64, r: f64| b((l - r).abs() < 1e-10)),
            Op::Ne => bin!(|l: f64, r: f64| b((l - r).abs() >= 1e-10)),
            Op::And => bin!(|l, r| b(l != 0.0 && r != 0.0)),
            Op::Or => bin!(|l, r| b(l != 0.0 || r != 0.0)),
            Op::F1(f) => st[sp - 1] = f(st[sp - 1]),
            Op::F2(f) => bin!(f),
            Op::Select3 => {
                sp -= 2;
                let c = st[sp - 1];
                st[sp - 1] = if c < 0.0 { st[sp] } else { st[sp + 1] };
            }
            Op::Select4 => {
                sp -= 3;
                let c = st[sp - 1];
                st[sp - 1] = if c < 0.0 {
                    st[sp]
                } else if c == 0.0 {
                    st[sp + 1]
                } else {
                    st[sp + 2]
                };
            }
            Op::Cond => {
                sp -= 2;
                let c = st[sp - 1];
                st[sp - 1] = if c != 0.0 { st[sp] } else { st[sp + 1] };
            }
            Op::Call(f, n) => {
                let n = *n as usize;
                sp -= n;
                let v = f.eval(&st[sp..sp + n]);
                st[sp] = v;
                sp += 1;
            }
            Op::Component(f, c) => {
                let n = f.arity;
                sp -= n;
                let v = f.component(&st[sp..sp + n], *c);
                st[sp] = v;
                sp += 1;
            }
            Op::Internal(f, n) => {
                let n = *n as usize;
                sp -= n;
                let v = f(&st[sp..sp + n]);
                st[sp] = v;
                sp += 1;
            }
        }
    }
    if sp == 0 {
        0.0
    } else {
        st[sp - 1]
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

#[cfg(test)]
mod tests {
    use super::*;

    fn f(ops: Vec<Op>) -> Function {
        Function {
            arity: 3,
            body: Body::Float(ops),
            depth: 1,
        }
    }

    #[test]
    fn sphere_program() {
        // x*x + y*y + z*z - 1
        let g = f(vec![
            Op::Param(0),
            Op::Param(0),
            Op::Mul,
            Op::Param(1),
            Op::Param(1),
            Op::Mul,
            Op::Add,
            Op::Param(2),
            Op::Param(2),
            Op::Mul,
            Op::Add,
            Op::Const(1.0),
            Op::Sub,
        ]);
        assert_eq!(g.eval(&[1.0, 2.0, 2.0]), 8.0);
        if let Body::Float(ops) = &g.body {
            assert_eq!(max_depth(ops), Some(3));
        }
    }

    #[test]
    fn select_and_calls() {
        let inner = Arc::new(f(vec![Op::Param(0), Op::Param(1), Op::Sub]));
        let g = f(vec![
            Op::Param(0),
            Op::Const(10.0),
            Op::Param(1),
            Op::Param(2),
            Op::Call(inner, 2),
            Op::Select3,
        ]);
        assert_eq!(g.eval(&[-1.0, 5.0, 2.0]), 10.0);
        assert_eq!(g.eval(&[1.0, 5.0, 2.0]), 3.0);
    }
}
