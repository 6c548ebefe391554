//! `lathe { [SPLINE] N, <x, y>… }` and `sor { N, <r, h>… }`, and the list of
//! 2-D points they share with `prism`.

use crate::build::shapes::lathe::{min_points, point_rule, radius_checked, segments};
use crate::build::shapes::prism::Spline;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, R};
use crate::scene::Shape;
use crate::span::Span;
use glam::DVec2;

/// The keywords a `lathe` takes before its count.
pub(crate) const LATHE_ITEMS: &[&str] = &[
    "linear_spline",
    "quadratic_spline",
    "cubic_spline",
    "bezier_spline",
    "sturm",
];

impl Evaluator<'_> {
    /// The `n` points `<u, v>` after a shape's count (written at `count_span`),
    /// each with where it was written; `shape` names the shape in messages and
    /// `help` says what the two coordinates are.
    pub(crate) fn points_2d(
        &mut self,
        c: &mut Cursor,
        n: f64,
        count_span: Span,
        shape: &str,
        help: &str,
    ) -> R<Vec<(DVec2, Span)>> {
        // Not preallocated from the count, which may be anything the user wrote.
        let mut points = Vec::new();
        let mut last = count_span;
        loop {
            if matches!(c.peek(), Some(Tok::Comma(_))) {
                c.next();
            }
            if !c.value_next() {
                break;
            }
            let (v, s) = c.value(&format!("a {shape} point"))?;
            last = s;
            points.push((
                match &v {
                    Value::Float(f) => DVec2::splat(*f),
                    Value::Vector(x) if x.len == 2 => DVec2::new(x.c[0], x.c[1]),
                    Value::Vector(x) => {
                        return Err(Diagnostic::error(
                            codes::TYPE_MISMATCH,
                            s,
                            format!(
                                "a {shape} point is 2-D `<u, v>`, found a vector of {} components",
                                x.len
                            ),
                        )
                        .with_label("not 2-D")
                        .with_help(help)
                        .into())
                    }
                    other => return Err(self.mismatch("a 2-D point `<u, v>`", other, s)),
                },
                s,
            ));
        }
        if points.len() != n as usize {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                count_span,
                format!("this {shape} says {n} points but lists {}", points.len()),
            )
            .with_label("count does not match")
            .with_secondary(last, "the last point")
            .with_help(format!(
                "make the count {}, or list {n} points",
                points.len()
            ))
            .into());
        }
        Ok(points)
    }

    /// `lathe { [SPLINE] [sturm] N, <x, y>… }` (`sturm` after the points is an
    /// object modifier).
    pub(crate) fn lathe(&mut self, c: &mut Cursor) -> R<Shape> {
        let mut spline = Spline::Linear;
        let mut seen: Option<(&'static str, Span)> = None;
        while let Some(Tok::Kw(kw, span)) = c.peek() {
            let (kw, span) = (*kw, *span);
            c.next();
            if kw == "sturm" {
                continue;
            }
            let Some(s) = Spline::from_keyword(kw) else {
                return Err(self.unknown_keyword(c, kw, span, LATHE_ITEMS));
            };
            if let Some((first, first_span)) = seen {
                return Err(Diagnostic::error(
                    codes::DUPLICATE_PARAMETER,
                    span,
                    format!("a lathe has one spline type, and `{first}` is already given"),
                )
                .with_label("second spline type")
                .with_secondary(first_span, "first")
                .with_help(format!("keep one of `{first}` and `{kw}`"))
                .into());
            }
            spline = s;
            seen = Some((kw, span));
        }
        let (v, count_span) = c.value("the number of points")?;
        let n = self.to_float(&v, count_span)?;
        let kw = spline.keyword();
        let min = min_points(spline);
        if n.fract() != 0.0 || n < min as f64 {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                count_span,
                format!("a `{kw}` lathe needs a whole number of at least {min} points, found {n}"),
            )
            .with_label("too few points")
            .with_help(point_rule(spline))
            .into());
        }
        if spline == Spline::Bezier && !(n as usize).is_multiple_of(4) {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                count_span,
                format!("a `bezier_spline` lathe has 4 points per segment, and {n} is not a multiple of 4"),
            )
            .with_label("not a multiple of 4")
            .with_help(point_rule(spline))
            .into());
        }
        c.comma();
        let points = self.points_2d(
            c,
            n,
            count_span,
            "lathe",
            "write `<x, y>`: x is the distance from the y axis, y the height",
        )?;
        let count = points.len();
        for (i, &(p, s)) in points.iter().enumerate() {
            if p.x < 0.0 && radius_checked(spline, i, count) {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    s,
                    format!(
                        "point {} of this lathe has a negative radius x = {}",
                        i + 1,
                        p.x
                    ),
                )
                .with_label("x < 0")
                .with_help(format!(
                    "x is the distance from the y axis and must be 0 or more ({})",
                    point_rule(spline)
                ))
                .into());
            }
        }
        let p: Vec<DVec2> = points.iter().map(|q| q.0).collect();
        Ok(Shape::Lathe {
            curves: segments(spline, &p).into(),
        })
    }

    /// `sor { N, <r, h>… }` (`open` and `sturm` after the points are object
    /// modifiers).
    pub(crate) fn sor(&mut self, c: &mut Cursor) -> R<Shape> {
        const RULE: &str = "the first and last points are control points; the heights of the \
                            points between them must rise";
        if let Some(Tok::Kw("sturm", _)) = c.peek() {
            c.next();
        }
        let (v, count_span) = c.value("the number of points")?;
        let n = self.to_float(&v, count_span)?;
        if n.fract() != 0.0 || n < 4.0 {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                count_span,
                format!("a sor needs a whole number of at least 4 points, found {n}"),
            )
            .with_label("too few points")
            .with_help(RULE)
            .into());
        }
        c.comma();
        let points = self.points_2d(
            c,
            n,
            count_span,
            "sor",
            "write `<r, h>`: the radius r at height h",
        )?;
        for (i, &(p, s)) in points.iter().enumerate() {
            if p.x < 0.0 {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    s,
                    format!("point {} of this sor has a negative radius {}", i + 1, p.x),
                )
                .with_label("r < 0")
                .with_help("the radius is the distance from the y axis: 0 or more")
                .into());
            }
        }
        let m = points.len();
        for i in 2..m - 1 {
            let ((a, sa), (b, sb)) = (points[i - 1], points[i]);
            if b.y <= a.y {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    sb,
                    format!(
                        "the heights of a sor must rise: point {} (h = {}) is not above point {} (h = {})",
                        i + 1,
                        b.y,
                        i,
                        a.y
                    ),
                )
                .with_label("not above the point before")
                .with_secondary(sa, "the point before")
                .with_help(RULE)
                .into());
            }
        }
        // The control points set the slopes at the ends: secants over two points.
        for (ctrl, other, end) in [(0, 2, "bottom"), (m - 1, m - 3, "top")] {
            let ((a, sa), (b, sb)) = (points[other], points[ctrl]);
            if a.y == b.y {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    sb,
                    format!(
                        "control point {} of this sor sets the slope at the {end}, and its height {} \
                         is the height of point {}",
                        ctrl + 1,
                        b.y,
                        other + 1
                    ),
                )
                .with_label("same height")
                .with_secondary(sa, "same height")
                .with_help("give the control point another height (usually below the first or above the last but one)")
                .into());
            }
        }
        Ok(Shape::Sor {
            points: points.iter().map(|q| q.0).collect(),
            open: false,
        })
    }
}
