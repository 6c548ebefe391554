//! `bicubic_patch`, `julia_fractal` and `sphere_sweep`.

use super::bicubic;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{Algebra, Julia, JuliaFn, Object, Shape, SweepData, SweepSpline};
use crate::span::Span;
use glam::{DVec2, DVec3, DVec4};
use std::sync::Arc;

/// The keywords a `bicubic_patch` takes before its points.
pub(crate) const PATCH_ITEMS: &[&str] = &["type", "flatness", "u_steps", "v_steps", "accuracy"];

/// The keywords a `julia_fractal` takes after its parameter.
pub(crate) const JULIA_ITEMS: &[&str] = &[
    "quaternion",
    "hypercomplex",
    "sqr",
    "cube",
    "reciprocal",
    "max_iteration",
    "precision",
    "slice",
];

/// The keywords a `sphere_sweep` takes.
pub(crate) const SWEEP_ITEMS: &[&str] = &["linear_spline", "b_spline", "cubic_spline", "tolerance"];

impl Evaluator<'_> {
    /// Evaluates the shapes of this file; `None` for other blocks.
    pub(crate) fn more_shape(&mut self, c: &mut Cursor) -> R<Option<Object>> {
        let span = c.span;
        let shape = match c.block {
            "bicubic_patch" => self.bicubic_patch(c)?,
            "julia_fractal" => self.julia_fractal(c)?,
            "sphere_sweep" => self.sphere_sweep(c)?,
            _ => return Ok(None),
        };
        Ok(Some(Object::new(shape, span)))
    }

    fn to_vec4(&self, v: &Value, span: Span) -> R<DVec4> {
        match v {
            Value::Float(f) => Ok(DVec4::splat(*f)),
            Value::Vector(x) if x.len >= 4 => Ok(DVec4::new(x.c[0], x.c[1], x.c[2], x.c[3])),
            Value::Vector(x) => Err(Diagnostic::error(
                codes::TYPE_MISMATCH,
                span,
                format!(
                    "expected a 4D vector <x, y, z, w>, found {} components",
                    x.len
                ),
            )
            .with_help("write four components, e.g. `<-0.08, 0, -0.83, -0.03>`")
            .into()),
            other => Err(self.mismatch("a 4D vector", other, span)),
        }
    }

    /// `bicubic_patch { type T [flatness F] [u_steps N] [v_steps M] [accuracy A]
    /// P1, …, P16 [uv_vectors UV1, UV2, UV3, UV4] … }`.
    fn bicubic_patch(&mut self, c: &mut Cursor) -> R<Shape> {
        let (mut u_steps, mut v_steps) = (0u32, 0u32);
        let mut have_type = false;
        while let Some(Tok::Kw(kw, s)) = c.peek() {
            let (kw, s) = (*kw, *s);
            if !PATCH_ITEMS.contains(&kw) {
                break;
            }
            c.next();
            c.once(kw, s)?;
            let (v, vs) = c.value(&format!("the value of `{kw}`"))?;
            let x = self.to_float(&v, vs)?;
            match kw {
                "type" => {
                    have_type = true;
                    if x != 0.0 && x != 1.0 {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            vs,
                            format!("a bicubic patch's type is 0 or 1, found {x}"),
                        )
                        .with_help("write `type 1` (the two types give the same picture)")
                        .into());
                    }
                }
                "u_steps" | "v_steps" => {
                    if !(0.0..=bicubic::MAX_STEPS as f64).contains(&x) {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            vs,
                            format!(
                                "`{kw}` must be between 0 and {}, found {x}",
                                bicubic::MAX_STEPS
                            ),
                        )
                        .with_help("each step doubles the triangles: 3 or 4 is usually plenty")
                        .into());
                    }
                    if kw == "u_steps" {
                        u_steps = x as u32;
                    } else {
                        v_steps = x as u32;
                    }
                }
                _ => {
                    if x < 0.0 {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            vs,
                            format!("`{kw}` cannot be negative, found {x}"),
                        )
                        .into());
                    }
                }
            }
        }
        if !have_type {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span.head(),
                "a bicubic patch needs its `type` (0 or 1) before its points",
            )
            .with_help("write `bicubic_patch { type 1 u_steps 3 v_steps 3 <points…> }`")
            .into());
        }
        let mut points = [DVec3::ZERO; 16];
        for (k, p) in points.iter_mut().enumerate() {
            // POV-Ray also takes a comma after the last setting.
            c.comma();
            if !c.value_next() {
                let whole = c.span;
                let at = c.peek().map_or(whole, |t| t.span());
                return Err(Diagnostic::error(
                    codes::INVALID_SIZE,
                    at,
                    format!("a bicubic patch needs 16 control points, found {k}"),
                )
                .with_label("expected another point here")
                .with_help("give the 4 × 4 control points, row by row")
                .into());
            }
            *p = self.take_vec3(c, "a control point")?;
        }
        let mut uv = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
        if let Some(Tok::Kw("uv_vectors", _)) = c.peek() {
            // POV-Ray's form: the keyword and four 2D vectors, no braces.
            c.next();
            for (k, slot) in uv.iter_mut().enumerate() {
                if k > 0 {
                    c.comma();
                }
                let p = self.take_vec3(c, "a corner's uv (4 in all)")?;
                *slot = DVec2::new(p.x, p.y);
            }
        } else if let Some((items, s)) = self.take_list(c, "uv_vectors") {
            if items.len() != 4 {
                return Err(Diagnostic::error(
                    codes::INVALID_SIZE,
                    s,
                    format!(
                        "a bicubic patch's uv_vectors are its 4 corners, found {}",
                        items.len()
                    ),
                )
                .into());
            }
            for (slot, (v, vs)) in uv.iter_mut().zip(items) {
                let p = self.to_vec3(&v, vs)?;
                *slot = DVec2::new(p.x, p.y);
            }
        }
        Ok(Shape::Mesh(Arc::new(bicubic::tessellate(
            &points, u_steps, v_steps, uv,
        ))))
    }

    /// `height_field { function W, H { … } … }`: the function of x and y sampled
    /// on a `W × H` grid over [0, 1]² (z = 0), row j at y = j / (H − 1) standing
    /// at z = 1 − y as an image's rows do; heights wrap to [0, 1) as POV-Ray's
    /// do (measured: `2*x - 0.5` gives 0.7 at x = 0.1).
    pub(crate) fn height_field_function(&mut self, c: &mut Cursor) -> R<(Vec<f32>, usize, usize)> {
        let mut size = [0usize; 2];
        let mut last = c.span;
        for (k, slot) in size.iter_mut().enumerate() {
            if k > 0 {
                c.comma();
            }
            let (v, s) = c.value("the function's resolution")?;
            let n = self.to_float(&v, s)?;
            if !(2.0..=8192.0).contains(&n) {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    s,
                    format!("a height field's resolution is 2 to 8192 points, found {n}"),
                )
                .with_help("write e.g. `height_field { function 256, 256 { … } }`")
                .into());
            }
            *slot = n as usize;
            last = s;
        }
        let f = match c.next() {
            Some(Tok::Block("function", Value::Function(f), _)) => f,
            Some(Tok::Block("function", Value::Poison, _)) => return Err(Fail::silent()),
            other => {
                let at = other.as_ref().map_or(last, |t| t.span());
                return Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    at,
                    "expected the height field's `function { … }` after its resolution",
                )
                .with_help("write `height_field { function 256, 256 { EXPR } }`")
                .into());
            }
        };
        let [w, h] = size;
        let bytes = (w * h * std::mem::size_of::<f32>()) as u64;
        self.reserve(bytes, last, &format!("a {w} by {h} height field"))?;
        // Each point is a function of its place only: rows are sampled in
        // parallel (a pigment function full of noise is most of a scene's
        // parse time otherwise: POV-Ray's wallstucco.pov).
        use rayon::prelude::*;
        let mut grid = vec![0f32; w * h];
        grid.par_chunks_mut(w).enumerate().for_each(|(j, row)| {
            let y = j as f64 / (h - 1) as f64;
            for (i, g) in row.iter_mut().enumerate() {
                let x = i as f64 / (w - 1) as f64;
                let v = f.eval(&[x, y, 0.0]);
                *g = if v.is_finite() {
                    v.rem_euclid(1.0) as f32
                } else {
                    0.0
                };
            }
        });
        Ok((grid, w, h))
    }

    /// `julia_fractal { <c> [quaternion|hypercomplex] [FUNCTION] [max_iteration N]
    /// [precision P] [slice <n>, d] … }`.
    fn julia_fractal(&mut self, c: &mut Cursor) -> R<Shape> {
        let (v, vs) = c.value("the Julia parameter, a 4D vector")?;
        let param = self.to_vec4(&v, vs)?;
        let mut j = Julia {
            c: param,
            algebra: Algebra::Quaternion,
            function: JuliaFn::Sqr,
            max_iteration: 20,
            precision: 20.0,
            slice_normal: DVec4::W,
            slice_distance: 0.0,
        };
        let mut fn_span = None;
        loop {
            let (kw, s) = match c.peek() {
                Some(Tok::Kw(kw, s)) if JULIA_ITEMS.contains(kw) => (*kw, *s),
                _ => break,
            };
            c.next();
            match kw {
                "quaternion" => j.algebra = Algebra::Quaternion,
                "hypercomplex" => j.algebra = Algebra::Hypercomplex,
                "sqr" | "cube" | "reciprocal" => {
                    j.function = JuliaFn::from_name(kw).expect("known");
                    fn_span = Some(s);
                }
                "max_iteration" => {
                    c.once(kw, s)?;
                    let (v, vs) = c.value("the number of iterations")?;
                    let n = self.to_float(&v, vs)?;
                    if !(1.0..=1e6).contains(&n) {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            vs,
                            format!("max_iteration must be at least 1, found {n}"),
                        )
                        .with_help(
                            "write e.g. `max_iteration 8` (more iterations give finer detail)",
                        )
                        .into());
                    }
                    j.max_iteration = n as u32;
                }
                "precision" => {
                    c.once(kw, s)?;
                    let (v, vs) = c.value("the precision")?;
                    let p = self.to_float(&v, vs)?;
                    if p <= 0.0 {
                        return Err(self.bad_size(vs, "precision", p));
                    }
                    j.precision = p;
                }
                _ => {
                    c.once(kw, s)?;
                    let (v, vs) = c.value("the slice's 4D normal")?;
                    let n = self.to_vec4(&v, vs)?;
                    c.comma();
                    let d = self.take_float(c, "the slice's distance")?;
                    let len = n.length();
                    if len == 0.0 || n.w == 0.0 {
                        return Err(Diagnostic::error(
                            codes::INVALID_SIZE,
                            vs,
                            "the slice's normal needs a non-zero 4th (w) component",
                        )
                        .with_help("the default slice is `slice <0, 0, 0, 1>, 0`")
                        .into());
                    }
                    j.slice_normal = n / len;
                    j.slice_distance = d / len;
                }
            }
        }
        if j.algebra == Algebra::Quaternion && !matches!(j.function, JuliaFn::Sqr | JuliaFn::Cube) {
            return Err(Diagnostic::error(
                codes::UNSUPPORTED,
                fn_span.unwrap_or(c.span.head()),
                "quaternion fractals only take `sqr` or `cube`",
            )
            .with_help("write `hypercomplex` to use this function")
            .into());
        }
        Ok(Shape::Julia(Arc::new(j)))
    }

    /// `sphere_sweep { SPLINE N, <p1>, r1, … [tolerance T] … }`.
    fn sphere_sweep(&mut self, c: &mut Cursor) -> R<Shape> {
        let spline = match c.next() {
            Some(Tok::Kw("linear_spline", _)) => SweepSpline::Linear,
            Some(Tok::Kw("b_spline", _)) => SweepSpline::BSpline,
            Some(Tok::Kw("cubic_spline", _)) => SweepSpline::Cubic,
            other => {
                let s = other.as_ref().map_or(c.span.head(), |t| t.span());
                return Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    s,
                    "a sphere sweep starts with its spline type",
                )
                .with_help("write `linear_spline`, `b_spline` or `cubic_spline` first")
                .into());
            }
        };
        let (v, ns) = c.value("the number of spheres")?;
        let n = self.to_float(&v, ns)?;
        let need = spline.min_points();
        if n.fract() != 0.0 || n < need as f64 {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                ns,
                format!("this spline needs at least {need} spheres, found {n}"),
            )
            .with_help(match spline {
                SweepSpline::Linear => "give two spheres or more",
                _ => "b_spline and cubic_spline need 4 spheres or more (the first and last only steer)",
            })
            .into());
        }
        let mut points = Vec::new();
        for _ in 0..n as usize {
            c.comma();
            let p = self.take_vec3(c, "a sphere's centre")?;
            c.comma();
            let (v, rs) = c.value("the sphere's radius")?;
            let r = self.to_float(&v, rs)?;
            if r < 0.0 {
                return Err(Diagnostic::error(
                    codes::INVALID_SIZE,
                    rs,
                    format!("a sphere sweep's radius cannot be negative, found {r}"),
                )
                .into());
            }
            points.push((p, r));
        }
        let mut tolerance = 1e-6;
        if let Some(Tok::Kw("tolerance", _)) = c.peek() {
            c.next();
            let (v, ts) = c.value("the tolerance")?;
            tolerance = self.to_float(&v, ts)?;
            if tolerance <= 0.0 {
                return Err(self.bad_size(ts, "tolerance", tolerance));
            }
        }
        if points.len() < spline.min_points() {
            return Err(Fail::silent());
        }
        Ok(Shape::SphereSweep(Arc::new(SweepData {
            spline,
            points,
            tolerance,
        })))
    }
}
