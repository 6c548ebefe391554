//! The interpreter of compiled functions ([`crate::scene::Function`]): a
//! function's value at a point, run by isosurfaces (build), function patterns
//! (render) and calls in expressions (eval). Running touches no names, no hash
//! tables and allocates nothing.

use crate::scene::function::{Body, Function, Op, MAX_STACK};
use crate::scene::Pigment;

impl Function {
    /// The function's float value for `args` (as many as [`Function::arity`];
    /// missing ones read as 0). A colour-valued function gives its gray value.
    pub fn eval(&self, args: &[f64]) -> f64 {
        match &self.body {
            // No operation grows the stack by more than one value, so a
            // short program runs on a short stack (zeroed on every call).
            Body::Float(ops) if ops.len() <= 8 => run::<8>(ops, args),
            Body::Float(ops) if ops.len() <= 24 => run::<24>(ops, args),
            Body::Float(ops) => run::<MAX_STACK>(ops, args),
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
                let c = super::evaluate(p, point(args));
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
    use super::patterns;
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
        Pattern::Checker(_) => super::checker_index(p) as f64,
        _ => 0.0,
    }
}

fn b(c: bool) -> f64 {
    f64::from(u8::from(c))
}

/// Runs a float program on a stack of `N` values. The compiler guarantees the
/// stack never exceeds [`MAX_STACK`] and every operator finds its operands; no
/// operation adds more than one value, so `N` at least the program's length
/// (or [`MAX_STACK`]) is enough.
fn run<const N: usize>(ops: &[Op], args: &[f64]) -> f64 {
    let mut st = [0.0f64; N];
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::function::max_depth;
    use std::sync::Arc;

    fn f(ops: Vec<Op>) -> Function {
        Function {
            arity: 3,
            body: Body::Float(ops),
            depth: 1,
        }
    }

    #[test]
    fn programs_as_deep_as_they_are_long_fit_each_stack_size() {
        // n constants then n - 1 additions: depth n, length 2n - 1; and n
        // constants alone, depth = length, at each stack size's limit.
        for n in [1usize, 4, 5, 8, 9, 12, 13, 24, 25, 32] {
            let mut ops: Vec<Op> = (1..=n).map(|k| Op::Const(k as f64)).collect();
            assert_eq!(f(ops.clone()).eval(&[]), n as f64);
            ops.extend((1..n).map(|_| Op::Add));
            assert_eq!(max_depth(&ops), Some(n));
            assert_eq!(f(ops).eval(&[]), (n * (n + 1) / 2) as f64);
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
