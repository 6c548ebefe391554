//! Transforms shared by all blocks: `translate`, `rotate`, `scale`, `matrix`
//! and `transform { }`.

use super::cursor::{Cursor, Tok};
use super::value::Value;
use super::{Evaluator, Fail, R};
use crate::diag::{codes, Diagnostic};
use crate::scene::Transform;
use crate::span::Span;
use glam::{DMat4, DVec4};

/// The transform keywords.
pub(crate) const TRANSFORMS: &[&str] = &["translate", "rotate", "scale", "matrix", "transform"];

fn value_of(t: &Tok) -> Value {
    match t {
        Tok::Val(v, _) | Tok::Block(_, v, _) => v.clone(),
        _ => Value::Poison,
    }
}

/// Builds the transform POV-Ray's `matrix <12 numbers>` describes (rows of a 4×3
/// matrix applied to row vectors); `None` when it cannot be inverted.
pub(crate) fn matrix_from_12(m: &[f64]) -> Option<Transform> {
    let col = |i: usize, w: f64| DVec4::new(m[3 * i], m[3 * i + 1], m[3 * i + 2], w);
    Transform::from_matrix(DMat4::from_cols(
        col(0, 0.0),
        col(1, 0.0),
        col(2, 0.0),
        col(3, 1.0),
    ))
}

impl Evaluator<'_> {
    /// Evaluates one transform keyword (`translate V`, …) already taken from `c`.
    pub(crate) fn transform_kw(&mut self, kw: &str, kw_span: Span, c: &mut Cursor) -> R<Transform> {
        match kw {
            "translate" => Ok(Transform::translate(
                self.take_vec3(c, "a vector to translate by")?,
            )),
            "rotate" => Ok(Transform::rotate(
                self.take_vec3(c, "the rotation angles <x, y, z> in degrees")?,
            )),
            "scale" => {
                let (v, s) = c.value("a scale factor")?;
                let f = self.to_vec3(&v, s)?;
                if f.x == 0.0 || f.y == 0.0 || f.z == 0.0 {
                    return Err(Diagnostic::error(
                        codes::DEGENERATE_TRANSFORM,
                        s,
                        "scale by 0 flattens the object",
                    )
                    .with_label("a component is 0")
                    .with_help("use a small non-zero scale instead, or remove the object")
                    .into());
                }
                Ok(Transform::scale(f))
            }
            "matrix" => {
                let (v, s) = c.value("12 numbers `<…>` for the matrix")?;
                match v {
                    Value::Transform(t) => Ok(*t),
                    other => Err(self.mismatch(
                        "a matrix `<m00, m01, m02, … m32>` of 12 numbers",
                        &other,
                        s,
                    )),
                }
            }
            _ => match c.next() {
                Some(Tok::Val(Value::Transform(t), _) | Tok::Block(_, Value::Transform(t), _)) => {
                    Ok(*t)
                }
                Some(Tok::Val(Value::Poison, _)) => Err(Fail::silent()),
                Some(t) => Err(self.mismatch("a transform", &value_of(&t), t.span())),
                None => Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    kw_span,
                    "`transform` needs a transform",
                )
                .with_help("write `transform { rotate … translate … }` or `transform My_Transform`")
                .into()),
            },
        }
    }

    /// `transform { translate … rotate … inverse }`.
    pub(crate) fn transform_block(&mut self, c: &mut Cursor) -> R<Transform> {
        let mut t = Transform::IDENTITY;
        while let Some(tok) = c.next() {
            let step = match tok {
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => self.transform_kw(kw, span, c),
                Tok::Val(Value::Transform(x), _) | Tok::Block(_, Value::Transform(x), _) => Ok(*x),
                Tok::Kw("inverse", _) => {
                    t = Transform {
                        matrix: t.inverse,
                        inverse: t.matrix,
                    };
                    continue;
                }
                other => Err(self.unexpected(
                    c,
                    &other,
                    &[
                        "translate",
                        "rotate",
                        "scale",
                        "matrix",
                        "transform",
                        "inverse",
                    ],
                )),
            };
            match step {
                Ok(s) => t = t.then(&s),
                Err(f) => self.report(f),
            }
        }
        Ok(t)
    }
}
