//! Objects: the `sphere`, `plane`, `box`, `triangle`, `union`, `object` and
//! CSG blocks read by one reader, CSG nesting and flattening, and `light_group`.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{CsgOp, Members, Object, Shape, Transform};
use crate::span::Span;
use std::sync::Arc;

/// The keywords of object blocks (their items may modify the object's texture):
/// every shape and CSG block the evaluator reads. Editors offer these.
pub const OBJECT_BLOCKS: &[&str] = &[
    "sphere",
    "light_group",
    "plane",
    "box",
    "triangle",
    "union",
    "object",
    "cylinder",
    "cone",
    "torus",
    "quadric",
    "poly",
    "cubic",
    "quartic",
    "disc",
    "height_field",
    "smooth_triangle",
    "polygon",
    "mesh",
    "mesh2",
    "polyhedron",
    "prism",
    "lathe",
    "sor",
    "text",
    "blob",
    "superellipsoid",
    "merge",
    "intersection",
    "difference",
    "isosurface",
    "bicubic_patch",
    "julia_fractal",
    "sphere_sweep",
];

/// Whether `k` is one of [`OBJECT_BLOCKS`] (one hash lookup: every block asks).
pub(crate) fn is_object_block(k: &str) -> bool {
    static SET: std::sync::LazyLock<rustc_hash::FxHashSet<&'static str>> =
        std::sync::LazyLock::new(|| OBJECT_BLOCKS.iter().copied().collect());
    SET.contains(k)
}

/// Adds `child` to the members of a new group (`op`: `None` for a union) and
/// returns the nesting the group gets from it. A child that is a group of the
/// same kind with nothing of its own (no transform, texture, interior, flags,
/// clipping or lights) gives its members instead: `union { union { A B } C }` is
/// `union { A B C }` (likewise merge in merge, intersection in intersection, and
/// a difference as the first operand of a difference), so a union grown in a
/// loop (`#declare U = union { object { U } box { … } }`) stays one flat union,
/// each step taking constant time.
fn add_member(members: &mut Members, child: Object, op: Option<CsgOp>) -> u32 {
    let same_kind = match (&child.shape, op) {
        (Shape::Union { .. }, None) => true,
        (Shape::Csg { op: inner, .. }, Some(CsgOp::Difference)) => {
            *inner == CsgOp::Difference && members.is_empty()
        }
        (Shape::Csg { op: inner, .. }, Some(outer)) => *inner == outer,
        _ => false,
    };
    let plain = child.transform.is_none()
        && child.texture.is_none()
        && child.interior.is_none()
        && child.flags == crate::scene::ObjectFlags::default()
        && child.clipped_by.is_none()
        && child.lights.is_empty();
    if same_kind && plain {
        match child.shape {
            Shape::Union { children } | Shape::Csg { children, .. } if !children.is_empty() => {
                append_members(members, children);
                return child.nesting;
            }
            _ => {}
        }
    }
    let nesting = child.nesting + 1;
    members.push_back(child);
    nesting
}

/// `members` followed by `more`, in time proportional to the shorter of the two
/// (the longer one's tree is kept and the other's objects are moved onto it;
/// joining the trees themselves copied nodes of objects on both sides).
fn append_members(members: &mut Members, more: Members) {
    if members.len() >= more.len() {
        members.extend(more);
    } else {
        let mut merged = more;
        for m in std::mem::take(members).into_iter().rev() {
            merged.push_front(m);
        }
        *members = merged;
    }
}

/// Applies a transform to an object (its texture moves with it: textures are kept in
/// the object's own frame).
pub(crate) fn apply_transform(obj: &mut Object, t: &Transform) {
    let current = obj
        .transform
        .as_deref()
        .copied()
        .unwrap_or(Transform::IDENTITY);
    obj.transform = Some(Arc::new(current.then(t)));
}

/// Most `light_group`s a scene may have (one bit each in an object's mask).
pub(crate) const MAX_LIGHT_GROUPS: u32 = 64;

impl Evaluator<'_> {
    /// Evaluates an object block (`c.block` says which).
    pub(crate) fn object(&mut self, c: &mut Cursor) -> R<Object> {
        let span = c.span;
        if c.block == "blob" {
            return self.blob(c);
        }
        if let Some(mut o) = self.new_shape(c)? {
            self.modifiers(&mut o, c, false);
            return Ok(o);
        }
        if let Some(mut o) = self.more_shape(c)? {
            self.modifiers(&mut o, c, false);
            return Ok(o);
        }
        let mut obj = match c.block {
            "mesh" => self.mesh(c)?,
            "mesh2" => self.mesh2(c)?,
            "height_field" => self.height_field(c)?,
            "sphere" => {
                let center = self.take_vec3(c, "the sphere's centre")?;
                c.comma();
                let (v, s) = c.value("the sphere's radius")?;
                let radius = self.to_float(&v, s)?;
                if radius <= 0.0 {
                    return Err(self.bad_size(s, "sphere radius", radius));
                }
                Object::new(Shape::Sphere { center, radius }, span)
            }
            "plane" => {
                let (v, s) = c.value("the plane's normal")?;
                let normal = self.to_vec3(&v, s)?;
                if normal.length_squared() == 0.0 {
                    return Err(Diagnostic::error(
                        codes::INVALID_SIZE,
                        s,
                        "the plane's normal is <0, 0, 0>",
                    )
                    .with_help("give the direction the plane faces, e.g. `plane { y, 0 }`")
                    .into());
                }
                c.comma();
                let distance = self.take_float(c, "the plane's distance from the origin")?;
                Object::new(
                    Shape::Plane {
                        normal: normal.normalize(),
                        distance,
                    },
                    span,
                )
            }
            "box" => {
                let a = self.take_vec3(c, "the box's first corner")?;
                c.comma();
                let (v, s) = c.value("the box's second corner")?;
                let b = self.to_vec3(&v, s)?;
                let (min, max) = (a.min(b), a.max(b));
                if (max - min).min_element() == 0.0 {
                    self.warn(
                        Diagnostic::warning(
                            codes::INVALID_SIZE,
                            s,
                            "this box is flat: two corners share a coordinate",
                        )
                        .with_help("a box needs corners that differ in x, y and z"),
                    );
                }
                Object::new(Shape::Box { min, max }, span)
            }
            "triangle" => {
                let a = self.take_vec3(c, "the triangle's first corner")?;
                c.comma();
                let b = self.take_vec3(c, "the triangle's second corner")?;
                c.comma();
                let (v, s) = c.value("the triangle's third corner")?;
                let cc = self.to_vec3(&v, s)?;
                if (b - a).cross(cc - a).length_squared() == 0.0 {
                    self.warn(
                        Diagnostic::warning(
                            codes::INVALID_SIZE,
                            s,
                            "this triangle has no area: its corners are in a line",
                        )
                        .with_help("move one corner off the line through the other two"),
                    );
                }
                let uv = self.triangle_uv(c)?;
                Object::new(
                    Shape::Triangle {
                        vertices: [a, b, cc],
                        uv,
                    },
                    span,
                )
            }
            "light_group" => return self.light_group(c),
            "union" | "merge" | "intersection" | "difference" => {
                let kw = c.block;
                let op = match kw {
                    "merge" => Some(CsgOp::Merge),
                    "intersection" => Some(CsgOp::Intersection),
                    "difference" => Some(CsgOp::Difference),
                    _ => None,
                };
                let mut children = Members::new();
                let mut lights = Vec::new();
                let mut nesting = 0;
                while let Some(Tok::Block(
                    _,
                    Value::Object(_) | Value::Light(_) | Value::Poison,
                    _,
                )) = c.peek()
                {
                    match c.next() {
                        Some(Tok::Block(_, Value::Object(o), _)) => {
                            let o = Arc::try_unwrap(o).unwrap_or_else(|a| (*a).clone());
                            nesting = nesting.max(add_member(&mut children, o, op));
                        }
                        // As in POV-Ray, a light among a CSG's members moves with it.
                        Some(Tok::Block(_, Value::Light(l), _)) => lights.push((*l).clone()),
                        _ => {}
                    }
                }
                if children.is_empty() {
                    self.warn(
                        Diagnostic::warning(codes::MISSING_VALUE, span, format!("this {kw} has no objects"))
                            .with_help(format!("put objects inside the {kw}, e.g. `{kw} {{ sphere {{ … }} box {{ … }} }}`")),
                    );
                }
                let shape = match op {
                    Some(op) => Shape::Csg { op, children },
                    None => Shape::Union { children },
                };
                let mut obj = Object::new(shape, span);
                obj.nesting = nesting;
                self.check_nesting(&obj)?;
                obj.lights = lights;
                self.modifiers(&mut obj, c, true);
                return Ok(obj);
            }
            _ => {
                // object { Name modifiers… } or object { sphere { … } modifiers… }
                match c.next() {
                    Some(Tok::Val(Value::Object(o), _) | Tok::Block(_, Value::Object(o), _)) => {
                        let mut o = Arc::try_unwrap(o).unwrap_or_else(|a| (*a).clone());
                        o.span = span;
                        o
                    }
                    Some(Tok::Val(Value::Poison, _) | Tok::Block(_, Value::Poison, _)) => return Err(Fail::silent()),
                    Some(t) => {
                        return Err(Diagnostic::error(
                            codes::TYPE_MISMATCH,
                            t.span(),
                            format!("expected an object, found {}", t.describe()),
                        )
                        .with_help("write `object { My_Object … }` with a #declared object, or an object block inside")
                        .into())
                    }
                    None => {
                        return Err(Diagnostic::error(codes::MISSING_VALUE, span, "`object { }` needs an object")
                            .with_help("write `object { My_Object … }` with a #declared object")
                            .into())
                    }
                }
            }
        };
        self.modifiers(&mut obj, c, false);
        Ok(obj)
    }

    /// Refuses an object nested deeper than `--max-object-depth` (every walk
    /// over the object tree, when building and rendering, is that deep).
    pub(super) fn check_nesting(&mut self, obj: &Object) -> R<()> {
        let max = self.options.max_object_depth;
        if obj.nesting <= max {
            return Ok(());
        }
        self.stopped = true;
        Err(Diagnostic::error(
            codes::OBJECT_DEPTH,
            obj.span,
            format!("objects nested more than {max} deep (CSG inside CSG, or clipped_by)"),
        )
        .with_label(format!("this object is {} levels deep", obj.nesting))
        .with_help("a union of unions is flattened and never counts; check a recursive macro or a loop that wraps the object in itself, or raise the limit with --max-object-depth")
        .into())
    }

    pub(crate) fn bad_size(&self, span: Span, what: &str, v: f64) -> Fail {
        Diagnostic::error(
            codes::INVALID_SIZE,
            span,
            format!("{what} must be positive, found {v}"),
        )
        .with_label("not positive")
        .with_help(format!("give a {what} greater than 0"))
        .into()
    }

    /// `light_group { LIGHTS OBJECTS [global_lights BOOL] [modifiers] }`: a
    /// union whose lights light only its own objects (and those of groups
    /// nested in it); with `global_lights on` the scene's lights light them
    /// too (POV-Ray's default is off).
    fn light_group(&mut self, c: &mut Cursor) -> R<Object> {
        let span = c.span;
        if self.light_groups >= MAX_LIGHT_GROUPS {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                span,
                format!("a scene may have at most {MAX_LIGHT_GROUPS} light groups"),
            )
            .with_help("merge groups that share their lights")
            .into());
        }
        let group = self.light_groups;
        self.light_groups += 1;
        let mut children = Members::new();
        let mut lights = Vec::new();
        let mut global = false;
        let mut nesting = 0;
        loop {
            match c.peek() {
                Some(
                    Tok::Block(_, Value::Object(_) | Value::Light(_) | Value::Poison, _)
                    | Tok::Val(Value::Object(_) | Value::Light(_), _),
                ) => match c.next() {
                    Some(Tok::Block(_, Value::Object(o), _) | Tok::Val(Value::Object(o), _)) => {
                        let o = Arc::try_unwrap(o).unwrap_or_else(|a| (*a).clone());
                        nesting = nesting.max(o.nesting + 1);
                        children.push_back(o);
                    }
                    Some(Tok::Block(_, Value::Light(l), _) | Tok::Val(Value::Light(l), _)) => {
                        let mut l = (*l).clone();
                        l.group = Some(group as u8);
                        lights.push(l);
                    }
                    _ => {}
                },
                Some(Tok::Kw("global_lights", _)) => {
                    c.next();
                    global = self.take_switch(c)?;
                }
                _ => break,
            }
        }
        let mut obj = Object::new(Shape::Union { children }, span);
        obj.nesting = nesting;
        self.check_nesting(&obj)?;
        obj.lights = lights;
        obj.flags.light_groups = 1u64 << group;
        obj.flags.global_lights = Some(global);
        self.modifiers(&mut obj, c, true);
        Ok(obj)
    }
}
