//! `isosurface { function { … } contained_by { … } threshold accuracy
//! max_gradient evaluate open all_intersections max_trace … }`.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{Container, Isosurface, Shape};
use crate::span::Span;
use glam::DVec3;
use std::sync::Arc;

/// The keywords an isosurface takes besides its `function` and `contained_by`.
pub(crate) const ISOSURFACE_ITEMS: &[&str] = &[
    "threshold",
    "accuracy",
    "max_gradient",
    "evaluate",
    "open",
    "all_intersections",
    "max_trace",
];

/// An isosurface being read.
pub(crate) struct IsoSpec {
    function: Option<(Arc<crate::scene::Function>, Span)>,
    container: Container,
    threshold: f64,
    accuracy: f64,
    max_gradient: f64,
    max_gradient_span: Option<Span>,
    open: bool,
    max_trace: u32,
    /// A function was given but could not be used (already reported).
    function_failed: bool,
}

impl Evaluator<'_> {
    /// Reads an isosurface's own items (in any order, before its modifiers).
    pub(crate) fn isosurface_shape(&mut self, c: &mut Cursor) -> R<Shape> {
        let mut spec = IsoSpec {
            function: None,
            container: Container::Box {
                min: DVec3::splat(-1.0),
                max: DVec3::splat(1.0),
            },
            threshold: 0.0,
            accuracy: 0.001,
            max_gradient: 1.1,
            max_gradient_span: None,
            open: false,
            function_failed: false,
            max_trace: 1,
        };
        loop {
            let own = match c.peek() {
                Some(Tok::Block("function" | "contained_by", _, _)) => true,
                Some(Tok::Kw(kw, _)) => ISOSURFACE_ITEMS.contains(kw),
                _ => false,
            };
            if !own {
                break;
            }
            let tok = c.next().expect("peeked");
            if let Err(f) = self.isosurface_item(tok, c, &mut spec) {
                self.report(f);
            }
        }
        let Some((function, fspan)) = spec.function else {
            if spec.function_failed {
                return Err(Fail::silent());
            }
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span.head(),
                "an isosurface needs its function",
            )
            .with_help("write `isosurface { function { x*x + y*y + z*z - 1 } … }`")
            .into());
        };
        let iso = Isosurface {
            function,
            container: spec.container,
            threshold: spec.threshold,
            accuracy: spec.accuracy,
            max_gradient: spec.max_gradient,
            open: spec.open,
            max_trace: spec.max_trace,
            steepest: Default::default(),
        };
        let at = spec.max_gradient_span.unwrap_or(fspan);
        self.check_gradient(&iso, at);
        Ok(Shape::Isosurface(Arc::new(iso)))
    }

    fn isosurface_item(&mut self, tok: Tok, c: &mut Cursor, spec: &mut IsoSpec) -> R<()> {
        match tok {
            Tok::Block("function", Value::Function(f), span) => {
                if f.arity != 3 {
                    spec.function_failed = true;
                    return Err(Diagnostic::error(
                        codes::ARITY,
                        span,
                        format!(
                            "an isosurface's function takes x, y, z; this one takes {}",
                            f.arity
                        ),
                    )
                    .into());
                }
                spec.function = Some((f, span));
            }
            Tok::Block("function", _, _) => {
                spec.function_failed = true;
                return Err(Fail::silent());
            }
            Tok::Block("contained_by", Value::Array(a), span) => {
                let objs: Vec<&Value> = a.elems.iter().flatten().collect();
                let [Value::Object(o)] = objs.as_slice() else {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        span,
                        "`contained_by` takes one box or sphere",
                    )
                    .with_help("write `contained_by { box { <-1, -1, -1>, <1, 1, 1> } }`")
                    .into());
                };
                if o.transform.is_some() {
                    return Err(Diagnostic::error(
                        codes::UNSUPPORTED,
                        span,
                        "a transformed container is not supported",
                    )
                    .with_help("give the box's corners or the sphere's centre and radius directly")
                    .into());
                }
                spec.container = match &o.shape {
                    Shape::Box { min, max } => Container::Box {
                        min: *min,
                        max: *max,
                    },
                    Shape::Sphere { center, radius } => Container::Sphere {
                        center: *center,
                        radius: *radius,
                    },
                    _ => {
                        return Err(Diagnostic::error(
                            codes::TYPE_MISMATCH,
                            span,
                            "`contained_by` takes a box or a sphere",
                        )
                        .into())
                    }
                };
            }
            Tok::Block("contained_by", _, _) => return Err(Fail::silent()),
            Tok::Kw("threshold", _) => spec.threshold = self.take_float(c, "the threshold")?,
            Tok::Kw("accuracy", s) => {
                let a = self.take_float(c, "the accuracy")?;
                if a <= 0.0 {
                    return Err(self.bad_size(s, "accuracy", a));
                }
                spec.accuracy = a;
            }
            Tok::Kw("max_gradient", s) => {
                let g = self.take_float(c, "the largest slope of the function")?;
                if g <= 0.0 {
                    return Err(self.bad_size(s, "max_gradient", g));
                }
                spec.max_gradient = g;
                spec.max_gradient_span = Some(s);
            }
            Tok::Kw("evaluate", s) => {
                let p0 = self.take_float(c, "evaluate's first value (the minimum max_gradient)")?;
                c.comma();
                let p1 = self.take_float(c, "evaluate's second value")?;
                c.comma();
                let _p2 = self.take_float(c, "evaluate's third value")?;
                let g = p0 * p1.max(1.0);
                if g > 0.0 {
                    spec.max_gradient = g;
                    spec.max_gradient_span = Some(s);
                }
            }
            Tok::Kw("open", _) => spec.open = true,
            Tok::Kw("all_intersections", _) => spec.max_trace = 0,
            Tok::Kw("max_trace", s) => {
                let n = self.take_float(c, "how many crossings to report")?;
                if n < 1.0 {
                    return Err(self.bad_size(s, "max_trace", n));
                }
                spec.max_trace = n.min(1e6) as u32;
            }
            _ => {}
        }
        Ok(())
    }
}

impl Evaluator<'_> {
    /// An isosurface keyword (`threshold`, `open`, …) met among the object's
    /// modifiers, after a texture or transform: applied to the isosurface.
    pub(crate) fn isosurface_late(
        &mut self,
        iso: &mut Arc<Isosurface>,
        tok: Tok,
        c: &mut Cursor,
    ) -> R<()> {
        let mut spec = IsoSpec {
            function: None,
            container: iso.container,
            threshold: iso.threshold,
            accuracy: iso.accuracy,
            max_gradient: iso.max_gradient,
            max_gradient_span: None,
            open: iso.open,
            function_failed: false,
            max_trace: iso.max_trace,
        };
        self.isosurface_item(tok, c, &mut spec)?;
        let regrade = spec.max_gradient != iso.max_gradient;
        let it = Arc::make_mut(iso);
        it.threshold = spec.threshold;
        it.accuracy = spec.accuracy;
        it.max_gradient = spec.max_gradient;
        it.open = spec.open;
        it.max_trace = spec.max_trace;
        if regrade {
            // Another bound: measured on its own.
            it.steepest = Default::default();
            let at = spec.max_gradient_span.unwrap_or(c.span);
            self.check_gradient(iso, at);
        }
        Ok(())
    }

    /// The `max_gradient` warning for `iso`, at `at`: from a grid of samples
    /// now when no render follows, else from what the render meets.
    fn check_gradient(&mut self, iso: &Isosurface, at: Span) {
        if !self.options.sample_gradients {
            self.slope_checks.push(crate::eval::SlopeCheck {
                meter: iso.steepest.clone(),
                max_gradient: iso.max_gradient,
                span: at,
            });
            return;
        }
        let measured = iso.measured_gradient();
        if measured > iso.max_gradient * 1.5 {
            self.warn(
                Diagnostic::warning(
                    codes::MAX_GRADIENT,
                    at,
                    format!(
                        "max_gradient {} is below the function's slope in the container (about {:.3} measured): the surface may show holes",
                        iso.max_gradient, measured
                    ),
                )
                .with_help(format!("write `max_gradient {:.3}` (a larger value is safe but slower)", measured * 1.05)),
            );
        }
    }
}
