//! `camera_path { }` (ours): a camera whose location, target, angle and roll are
//! keyed, and which never flips when it looks straight up or down.
//!
//! ```text
//! camera_path {
//!   location keyframes { catmull_rom key 0, <0, 1, -6>  key 1, <6, 3, 0> }  // or a spline's name
//!   look_at <0, 1, 0>          // a point, a keyframes { }, a spline; or
//!   look_along                 // look along the path (the default)
//!   angle keyframes { key 0, 60  key 1, 35 }
//!   roll 10                    // degrees about the view direction (keyable)
//!   sky <0, 1, 0>              // "up" for a level camera (default y)
//! }
//! ```
//!
//! The camera stays level (its right vector is horizontal, perpendicular to `sky`)
//! unless rolled. Where it passes through straight up or down, POV-Ray's `look_at`
//! turns the picture over in one frame; here the right vector is followed from the
//! start of the timeline to the current time, so it carries on continuously (the
//! camera goes over the top and comes out upside down, as a real one on that path
//! would). That walk depends only on the time, so every frame and shard agrees.

use super::keyframe::Keyframes;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Sink};
use crate::eval::core::value::{CameraSpec, Value};
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::Spline;
use crate::syntax::ast::{Block, Item};
use glam::DVec3;
use std::rc::Rc;
use std::sync::Arc;

/// A value over time.
enum Curve {
    Const([f64; 5]),
    Spline(Rc<Spline>),
    Keys(Box<Keyframes>),
}

impl Curve {
    fn at(&self, t: f64) -> [f64; 5] {
        match self {
            Curve::Const(v) => *v,
            Curve::Spline(s) => s.eval(t),
            Curve::Keys(k) => k.eval(t),
        }
    }

    fn vec3(&self, t: f64) -> DVec3 {
        let v = self.at(t);
        DVec3::new(v[0], v[1], v[2])
    }
}

/// Keywords valid in `camera_path { }`.
pub(crate) const CAMERA_PATH_ITEMS: &[&str] =
    &["location", "look_at", "look_along", "angle", "roll", "sky"];

/// Samples per clock unit when following the right vector from the start.
const WALK_STEPS_PER_UNIT: f64 = 512.0;

impl Evaluator<'_> {
    /// One keyable value: a `keyframes { }` block (kept as a curve), a spline, a
    /// float or a vector.
    fn curve(&mut self, item: &Item) -> R<Curve> {
        match item {
            Item::Block(b) if b.keyword.name == "keyframes" => {
                let mut toks = Sink::new();
                self.expand(&b.items, &mut toks);
                let mut c = Cursor::new(toks.toks, "keyframes", b.span);
                let (k, _) = self.keyframes(&mut c)?;
                Ok(Curve::Keys(Box::new(k)))
            }
            Item::Expr(e) => match self.expr(e)? {
                Value::Spline(s) => Ok(Curve::Spline(s)),
                Value::Float(f) => Ok(Curve::Const([f, f, f, 0.0, 0.0])),
                Value::Vector(v) => Ok(Curve::Const(v.c)),
                Value::Poison => Err(Fail::silent()),
                other => Err(self.mismatch(
                    "a vector, a float, a spline or keyframes { }",
                    &other,
                    e.span,
                )),
            },
            other => Err(Diagnostic::error(
                codes::MISSING_VALUE,
                other.span(),
                "expected a value, a spline's name or a `keyframes { }` block",
            )
            .into()),
        }
    }

    /// `camera_path { … }`: the camera at the current clock.
    pub(crate) fn camera_path(&mut self, b: &Block) -> R<Value> {
        let mut location: Option<Curve> = None;
        let mut look_at: Option<Curve> = None;
        let mut angle: Option<Curve> = None;
        let mut roll: Option<Curve> = None;
        let mut sky = DVec3::Y;
        let mut items = b.items.iter().filter(|i| !matches!(i, Item::Comma(_)));
        let mut seen: Vec<&str> = Vec::new();
        while let Some(item) = items.next() {
            let Item::Keyword(kw) = item else {
                if let Item::Expr(e) = item {
                    if let crate::syntax::ast::ExprKind::Ident(name) = &e.kind {
                        let c = Cursor::new(Vec::new(), "camera_path", b.span);
                        return Err(self.unknown_keyword(
                            &c,
                            &name.name(),
                            e.span,
                            CAMERA_PATH_ITEMS,
                        ));
                    }
                }
                return Err(Diagnostic::error(
                    codes::UNEXPECTED_ITEM,
                    item.span(),
                    "expected a `camera_path` parameter",
                )
                .with_help(format!(
                    "`camera_path` accepts: {}",
                    CAMERA_PATH_ITEMS.join(", ")
                ))
                .into());
            };
            if !CAMERA_PATH_ITEMS.contains(&kw.name) {
                let c = Cursor::new(Vec::new(), "camera_path", b.span);
                return Err(self.unknown_keyword(&c, kw.name, kw.span, CAMERA_PATH_ITEMS));
            }
            if seen.contains(&kw.name) {
                return Err(Diagnostic::error(
                    codes::DUPLICATE_PARAMETER,
                    kw.span,
                    format!("`{}` is given twice in this `camera_path`", kw.name),
                )
                .into());
            }
            seen.push(kw.name);
            if kw.name == "look_along" {
                if seen.contains(&"look_at") {
                    return Err(Diagnostic::error(
                        codes::DUPLICATE_PARAMETER,
                        kw.span,
                        "give either `look_at` or `look_along`",
                    )
                    .into());
                }
                continue;
            }
            let Some(value) = items.next() else {
                return Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    kw.span,
                    format!("`{}` needs a value", kw.name),
                )
                .into());
            };
            let curve = self.curve(value)?;
            match kw.name {
                "location" => location = Some(curve),
                "look_at" => {
                    if seen.contains(&"look_along") {
                        return Err(Diagnostic::error(
                            codes::DUPLICATE_PARAMETER,
                            kw.span,
                            "give either `look_at` or `look_along`",
                        )
                        .into());
                    }
                    look_at = Some(curve)
                }
                "angle" => angle = Some(curve),
                "roll" => roll = Some(curve),
                _ => {
                    sky = curve.vec3(0.0);
                    if sky.length_squared() == 0.0 {
                        return Err(Diagnostic::error(
                            codes::BAD_CAMERA,
                            value.span(),
                            "the sky vector must not be zero",
                        )
                        .into());
                    }
                }
            }
        }
        let Some(location) = location else {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                b.span,
                "this camera_path has no location",
            )
            .with_help("add `location keyframes { key 0, <0, 1, -5>  key 1, <5, 1, 0> }`")
            .into());
        };
        let tl = self.timeline();
        self.moving();
        let t = self.options.clock;
        let t0 = tl.initial_clock.min(t);
        let span = (tl.final_clock - tl.initial_clock).abs().max(1e-6);
        let h = span * 1e-4;
        let dir_at = |t: f64| -> DVec3 {
            let p = location.vec3(t);
            let d = match &look_at {
                Some(target) => target.vec3(t) - p,
                None => location.vec3(t + h) - location.vec3(t - h),
            };
            d.normalize_or_zero()
        };
        let sky = sky.normalize();
        // Follow the right vector from the start so it never turns over at once.
        let steps = (((t - t0) * WALK_STEPS_PER_UNIT / span).ceil() as usize).clamp(1, 100_000);
        let mut sign = 1.0;
        let mut prev: Option<DVec3> = None;
        let mut last_dir = DVec3::Z;
        for k in 0..=steps {
            let tk = t0 + (t - t0) * k as f64 / steps as f64;
            let d = dir_at(tk);
            if d == DVec3::ZERO {
                continue;
            }
            last_dir = d;
            let r = sky.cross(d);
            if r.length() < 1e-9 {
                continue;
            }
            let r = r.normalize();
            if let Some(p) = prev {
                if r.dot(p) < 0.0 {
                    sign = -sign;
                }
            }
            prev = Some(r);
        }
        let dir = last_dir;
        let right = prev.map_or(DVec3::X, |r| r * sign);
        let mut up = dir.cross(right).normalize_or_zero();
        if up == DVec3::ZERO {
            up = sky;
        }
        if let Some(r) = &roll {
            let a = r.at(t)[0].to_radians();
            up = (up * a.cos() + dir.cross(up) * a.sin()).normalize();
        }
        let loc = location.vec3(t);
        let spec = CameraSpec {
            location: loc,
            look_at: Some(loc + dir),
            sky: up,
            angle: angle.as_ref().map(|a| a.at(t)[0]),
            ..CameraSpec::default()
        };
        Ok(Value::Camera(Arc::new(spec)))
    }
}
