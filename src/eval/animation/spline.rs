//! POV-Ray's `spline { [linear_spline | quadratic_spline | cubic_spline |
//! natural_spline] T, VALUE … }` blocks, and calls `S(t)` of a spline value
//! (the spline itself, and what each kind means, is [`crate::scene::Spline`]).

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::{Value, Vector};
use crate::eval::core::{Evaluator, R};
use crate::scene::{Spline, SplineKind};
use crate::span::Span;
use std::rc::Rc;

/// Keywords valid in `spline { }`.
pub(crate) const SPLINE_ITEMS: &[&str] = &[
    "linear_spline",
    "quadratic_spline",
    "cubic_spline",
    "natural_spline",
    "a time and a value",
];

/// The value of spline `s` at `t` as a language value (a vector as long as
/// the spline's longest point).
pub(crate) fn spline_value(s: &Spline, t: f64) -> Value {
    let v = s.eval(t);
    Value::Vector(Vector::from_slice(&v[..s.dim as usize]))
}

impl Evaluator<'_> {
    /// `spline { [KIND] [SPLINE] T, V [,] T, V … }`.
    pub(crate) fn spline_block(&mut self, c: &mut Cursor) -> R<Value> {
        let mut kind = SplineKind::Linear;
        let mut points: Vec<(f64, [f64; 5])> = Vec::new();
        let mut dim: u8 = 2;
        let mut first_t: Vec<(f64, Span)> = Vec::new();
        while let Some(tok) = c.next() {
            match tok {
                Tok::Kw(kw, _) if SplineKind::from_keyword(kw).is_some() => {
                    kind = SplineKind::from_keyword(kw).unwrap_or(SplineKind::Linear);
                }
                Tok::Comma(_) => {}
                Tok::Val(Value::Spline(s), _) if points.is_empty() => {
                    kind = s.kind;
                    dim = s.dim;
                    points = s.points.clone();
                }
                Tok::Val(Value::Poison, _) => return Err(crate::eval::core::Fail::silent()),
                Tok::Val(tv, ts) => {
                    let t = self.to_float(&tv, ts)?;
                    c.comma();
                    let (v, vs) = c.value("the value at this time (a float or a vector)")?;
                    let (vals, len) = match &v {
                        Value::Float(f) => ([*f, *f, 0.0, 0.0, 0.0], 2u8),
                        Value::Vector(vec) => (vec.c, vec.len),
                        Value::Colour(col) => (crate::eval::core::value::colour_to_array(col), 5),
                        other => return Err(self.mismatch("a float or a vector", other, vs)),
                    };
                    if let Some((_, prev)) = first_t.iter().find(|(pt, _)| *pt == t) {
                        self.warn(
                            Diagnostic::warning(
                                codes::IGNORED,
                                ts,
                                format!("a second point at t = {t} is ignored"),
                            )
                            .with_secondary(*prev, "the point kept")
                            .with_help(
                                "as in POV-Ray the first point at a time wins; remove one of them",
                            ),
                        );
                    }
                    first_t.push((t, ts));
                    dim = dim.max(len);
                    points.push((t, vals));
                }
                other => return Err(self.unexpected(c, &other, SPLINE_ITEMS)),
            }
        }
        if points.is_empty() {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "this spline has no points",
            )
            .with_help("give pairs of a time and a value: `spline { linear_spline 0, <0,0,0>, 1, <1,2,0> }`")
            .into());
        }
        Ok(Value::Spline(Rc::new(Spline::new(kind, points, dim))))
    }

    /// `S(t)`: a spline called with one float.
    pub(crate) fn call_spline(
        &mut self,
        s: &Spline,
        args: &[(Value, Span)],
        call: Span,
    ) -> R<Value> {
        match args {
            [(v, span)] => {
                let t = self.to_float(v, *span)?;
                Ok(spline_value(s, t))
            }
            _ => Err(Diagnostic::error(
                codes::ARITY,
                call,
                format!(
                    "a spline takes one argument (the time), found {}",
                    args.len()
                ),
            )
            .with_help("write `S(t)`, e.g. `S(clock)`")
            .into()),
        }
    }
}
