//! `blob { … }` with its `sphere` and `cylinder` components, and
//! `superellipsoid { <E, N> }`.
//!
//! A `sphere` or `cylinder` block written directly in a blob is a component, not
//! an object: the context the blob's items are read in (`core/context.rs`)
//! tells [`Evaluator::block`] so, and the component comes back as an object whose shape
//! is a blob of that one component (its transforms and texture in the
//! component's own fields), which the blob then takes apart.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, R};
use crate::scene::{BlobComponent, BlobData, BlobKind, Object, Shape};
use crate::span::Span;
use std::sync::Arc;

/// What a component accepts after its numbers (POV-Ray: textures and transforms).
const COMPONENT_MODIFIERS: &[&str] = &[
    "texture",
    "pigment",
    "finish",
    "normal",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
];

/// The smallest superellipsoid exponent: smaller ones (and 0 or negative ones,
/// which POV-Ray accepts) are taken as this, already a box with sharp edges.
const MIN_EXPONENT: f64 = 1e-3;

impl Evaluator<'_> {
    /// `sphere { CENTER, RADIUS, [strength] S … }` or `cylinder { END1, END2,
    /// RADIUS, [strength] S … }` inside a blob.
    pub(crate) fn blob_component(&mut self, c: &mut Cursor) -> R<Object> {
        let span = c.span;
        let kind = if c.block == "sphere" {
            let center = self.take_vec3(c, "the component's centre")?;
            c.comma();
            let radius = self.component_radius(c)?;
            BlobKind::Sphere { center, radius }
        } else {
            let a = self.take_vec3(c, "the component's first end")?;
            c.comma();
            let (v, s) = c.value("the component's second end")?;
            let b = self.to_vec3(&v, s)?;
            if a == b {
                return Err(Diagnostic::error(
                    codes::INVALID_SIZE,
                    s,
                    "the two ends of this cylindrical component are the same",
                )
                .with_help(
                    "give different ends, or use a `sphere { CENTER, RADIUS, STRENGTH }` component",
                )
                .into());
            }
            c.comma();
            let radius = self.component_radius(c)?;
            BlobKind::Cylinder { a, b, radius }
        };
        c.comma();
        if let Some(Tok::Kw("strength", _)) = c.peek() {
            c.next();
        }
        let strength = self.take_float(c, "the component's strength")?;
        let mut obj = Object::new(blob_of(1.0, Vec::new()), span);
        while let Some(tok) = c.next() {
            let fits = match &tok {
                Tok::Kw(k, _) => TRANSFORMS.contains(k),
                Tok::Block(k, _, _) => COMPONENT_MODIFIERS.contains(k),
                Tok::Deferred(_) => true,
                _ => false,
            };
            let done = if fits {
                self.modifier(&mut obj, c, tok, false)
            } else {
                Err(self.unexpected(c, &tok, COMPONENT_MODIFIERS))
            };
            if let Err(f) = done {
                self.report(f);
            }
        }
        let component = BlobComponent {
            kind,
            strength,
            transform: obj.transform.take(),
            texture: obj.texture.take(),
        };
        obj.shape = blob_of(1.0, vec![component]);
        Ok(obj)
    }

    fn component_radius(&mut self, c: &mut Cursor) -> R<f64> {
        let (v, s) = c.value("the component's radius")?;
        let radius = self.to_float(&v, s)?;
        if radius <= 0.0 {
            return Err(self.bad_size(s, "component radius", radius));
        }
        Ok(radius)
    }

    /// `blob { threshold T  COMPONENT…  [MODIFIER…] }`.
    pub(crate) fn blob(&mut self, c: &mut Cursor) -> R<Object> {
        let span = c.span;
        let mut threshold = 1.0;
        let mut components = Vec::new();
        // A component that failed was reported: the blob is not "empty" then.
        let mut failed = false;
        loop {
            match c.peek() {
                Some(Tok::Kw("threshold", _)) => {
                    c.next();
                    threshold = self.take_float(c, "the threshold")?;
                }
                Some(Tok::Kw("component", _)) => {
                    // component STRENGTH, RADIUS, CENTER (POV-Ray's old spelling).
                    c.next();
                    let strength = self.take_float(c, "the component's strength")?;
                    c.comma();
                    let radius = self.component_radius(c)?;
                    c.comma();
                    let center = self.take_vec3(c, "the component's centre")?;
                    components.push(BlobComponent {
                        kind: BlobKind::Sphere { center, radius },
                        strength,
                        transform: None,
                        texture: None,
                    });
                }
                Some(Tok::Block(_, Value::Object(o), _)) => match &o.shape {
                    Shape::Blob(b) => {
                        components.extend(b.components.iter().cloned());
                        c.next();
                    }
                    _ => break,
                },
                Some(Tok::Block(_, Value::Poison, _)) => {
                    failed = true;
                    c.next();
                }
                _ => break,
            }
        }
        if components.is_empty() && !failed {
            self.warn(
                Diagnostic::warning(codes::MISSING_VALUE, span, "this blob has no components")
                    .with_help("add components, e.g. `sphere { <0, 0, 0>, 1, 1 }`"),
            );
        }
        if threshold <= 0.0 {
            self.warn(
                Diagnostic::warning(
                    codes::OUT_OF_RANGE,
                    span,
                    format!("a blob threshold of {threshold} makes all space outside the components inside the blob"),
                )
                .with_help("give a threshold above 0, e.g. `threshold 0.5`"),
            );
        }
        let mut obj = Object::new(blob_of(threshold, components), span);
        while let Some(tok) = c.next() {
            let done = match tok {
                Tok::Kw("hierarchy", _) => {
                    // Accepted: rts builds a hierarchy over many components itself.
                    if c.value_next() {
                        self.take_float(c, "on or off").map(|_| ())
                    } else {
                        Ok(())
                    }
                }
                Tok::Kw(kw @ ("threshold" | "component"), s) => {
                    // Its values are not reported again.
                    c.poisoned = true;
                    Err(late(kw, s))
                }
                Tok::Block(kw @ ("sphere" | "cylinder"), _, s) => Err(late(kw, s)),
                tok => self.modifier(&mut obj, c, tok, false),
            };
            if let Err(f) = done {
                self.report(f);
            }
        }
        Ok(obj)
    }

    /// `superellipsoid { <E, N> }`.
    pub(crate) fn superellipsoid(&mut self, c: &mut Cursor) -> R<Shape> {
        let (v, s) = c.value("the exponents <E, N>")?;
        let en = self.to_vec3(&v, s)?;
        let (mut e, mut n) = (en.x, en.y);
        if e < MIN_EXPONENT || n < MIN_EXPONENT {
            if e <= 0.0 || n <= 0.0 {
                self.warn(
                    Diagnostic::warning(
                        codes::OUT_OF_RANGE,
                        s,
                        format!("superellipsoid exponents must be above 0; <{e}, {n}> is read as <{}, {}>", e.max(MIN_EXPONENT), n.max(MIN_EXPONENT)),
                    )
                    .with_help("small exponents such as 0.01 already give a box with sharp edges"),
                );
            }
            e = e.max(MIN_EXPONENT);
            n = n.max(MIN_EXPONENT);
        }
        Ok(Shape::Superellipsoid { e, n })
    }
}

fn blob_of(threshold: f64, components: Vec<BlobComponent>) -> Shape {
    Shape::Blob(Arc::new(BlobData {
        threshold,
        components,
    }))
}

/// A component or threshold after the blob's modifiers (POV-Ray: a parse error).
fn late(kw: &str, span: Span) -> crate::eval::core::Fail {
    Diagnostic::error(
        codes::UNEXPECTED_ITEM,
        span,
        format!("`{kw}` must come before the blob's modifiers"),
    )
    .with_label("after a transform, texture or other modifier")
    .with_help("move the blob's threshold and components above its first modifier")
    .into()
}
