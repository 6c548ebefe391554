//! Objects: `sphere`, `plane`, `box`, `triangle`, `union`, `object`, and their
//! modifiers; transforms shared by all blocks.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{CsgOp, Members, Object, Shape, Texture, Transform};
use crate::span::Span;
use glam::{DMat4, DVec4};
use std::sync::Arc;

/// Keywords every object accepts after its shape parameters.
pub(crate) const OBJECT_MODIFIERS: &[&str] = &[
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
    "texture",
    "pigment",
    "finish",
    "normal",
    "interior",
    "interior_texture",
    "material",
    "no_shadow",
    "no_image",
    "no_reflection",
    "no_radiosity",
    "radiosity",
    "photons",
    "uv_mapping",
    "inverse",
    "hollow",
    "double_illuminate",
    "sturm",
    "clipped_by",
    "bounded_by",
];

/// The transform keywords.
pub(crate) const TRANSFORMS: &[&str] = &["translate", "rotate", "scale", "matrix", "transform"];

/// The keywords of object blocks (their items may modify the object's texture).
pub(crate) const OBJECT_BLOCKS: &[&str] = &[
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
    fn check_nesting(&mut self, obj: &Object) -> R<()> {
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

    /// What an object-level `pigment`, `finish` or `normal` block (`kw`) modifies:
    /// the object's texture's (or the default texture's), with its patterns as they
    /// lie in the world now (the object's transforms so far applied back); `None`
    /// for a patterned texture, which has no single one.
    fn material_base(&self, obj: &Object, kw: &str) -> Option<Value> {
        let tex = obj.texture.as_deref().unwrap_or(&self.default_texture);
        if tex.patterned.is_some() {
            return None;
        }
        // The object's own texture lies in its frame (see `attach`).
        let frame = obj.texture.as_ref().and(obj.transform.as_deref());
        let moved = |pattern: &mut Option<Arc<Transform>>| {
            if let Some(t) = frame {
                crate::scene::compose(pattern, t);
            }
        };
        match kw {
            "pigment" => {
                let mut p = tex.pigment.clone();
                moved(&mut p.transform);
                Some(Value::Pigment(Arc::new(p)))
            }
            "finish" => Some(Value::Finish(Arc::new(tex.finish))),
            _ => tex.normal.clone().map(|mut n| {
                moved(&mut n.transform);
                Value::Normal(Arc::new(n))
            }),
        }
    }

    /// The modifiers after an object's parameters; errors are reported and skipped.
    fn modifiers(&mut self, obj: &mut Object, c: &mut Cursor, is_union: bool) {
        let mut media_at = None;
        // `uv_mapping` before a texture or pigment (POV-Ray's
        // `uv_mapping texture { … }`): where it was written.
        let mut uv_next: Option<Span> = None;
        while let Some(mut tok) = c.next() {
            if let Tok::Kw("uv_mapping", span) = tok {
                uv_next = Some(span);
                continue;
            }
            if let Some(at) = uv_next.take() {
                tok = match self.uv_mapped_item(obj, tok, at) {
                    Ok(t) => t,
                    Err(f) => {
                        self.report(f);
                        continue;
                    }
                };
            }
            match &tok {
                Tok::Block(_, Value::Interior(i), s) if !i.media.is_empty() => media_at = Some(*s),
                Tok::Block(_, Value::Material(m), s)
                    if m.interior.as_ref().is_some_and(|i| !i.media.is_empty()) =>
                {
                    media_at = Some(*s)
                }
                _ => {}
            }
            if let Err(f) = self.modifier(obj, c, tok, is_union) {
                self.report(f);
            }
        }
        if let Some(span) = media_at {
            if !obj.flags.hollow {
                // As in POV-Ray, media (and fog) act only where every object a
                // ray is in is hollow: in a solid object the media is not seen.
                self.warn(
                    Diagnostic::warning(
                        codes::MEDIA_NOT_HOLLOW,
                        span,
                        "this object's media will not be seen: the object is not hollow",
                    )
                    .with_label("media inside a solid object")
                    .with_help("add `hollow` to the object, as POV-Ray requires for media"),
                );
            }
        }
    }

    /// The item after an object's `uv_mapping`, its pigment looked up by the
    /// surface's uv coordinates: a texture (not a patterned one) or a pigment.
    fn uv_mapped_item(&mut self, obj: &Object, tok: Tok, at: Span) -> R<Tok> {
        let tok = match tok {
            Tok::Deferred(b) => {
                let base = self.material_base(obj, b.block.keyword.name);
                self.undefer(&b, base)
            }
            t => t,
        };
        match tok {
            Tok::Block(kw, Value::Texture(t), span) if t.patterned.is_none() => {
                let mut tex = (*t).clone();
                tex.pigment = crate::eval::materials::texture::uv_mapped(std::mem::take(&mut tex.pigment));
                Ok(Tok::Block(kw, Value::Texture(Arc::new(tex)), span))
            }
            Tok::Block(kw, Value::Pigment(p), span) => Ok(Tok::Block(
                kw,
                Value::Pigment(Arc::new(crate::eval::materials::texture::uv_mapped((*p).clone()))),
                span,
            )),
            other => Err(Diagnostic::error(
                codes::UNEXPECTED_ITEM,
                other.span(),
                format!(
                    "`uv_mapping` here applies to the texture or pigment after it, not to {}",
                    other.describe()
                ),
            )
            .with_secondary(at, "uv_mapping")
            .with_help("write `uv_mapping texture { … }` or `uv_mapping pigment { … }` (a patterned texture: put uv_mapping in the pigments it chooses)")
            .into()),
        }
    }

    pub(crate) fn modifier(
        &mut self,
        obj: &mut Object,
        c: &mut Cursor,
        tok: Tok,
        is_union: bool,
    ) -> R<()> {
        let tok = match tok {
            Tok::Deferred(b) => {
                let base = self.material_base(obj, b.block.keyword.name);
                self.undefer(&b, base)
            }
            t => t,
        };
        if matches!(tok, Tok::Kw("global_lights", _)) && c.block == "light_group" {
            // After a light_group's transforms too, as POV-Ray allows.
            obj.flags.global_lights = Some(self.take_switch(c)?);
            return Ok(());
        }
        if let (Tok::Kw(kw, _), Shape::Isosurface(iso)) = (&tok, &mut obj.shape) {
            if super::isosurface::ISOSURFACE_ITEMS.contains(kw) {
                return self.isosurface_late(iso, tok, c);
            }
        }
        match tok {
            Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => {
                let t = self.transform_kw(kw, span, c)?;
                apply_transform(obj, &t);
            }
            Tok::Block(_, Value::Transform(t), _) => apply_transform(obj, &t),
            Tok::Block("interior_texture", Value::Texture(t), _) => {
                let inside = attach(obj, (*t).clone());
                let mut tex = match obj.texture.as_deref() {
                    Some(t) => t.clone(),
                    None => (*attach(obj, (*self.default_texture).clone())).clone(),
                };
                tex.interior_texture = Some(inside);
                obj.texture = Some(Arc::new(tex));
            }
            Tok::Block(_, Value::Texture(t), span) => {
                let top = attach(obj, (*t).clone());
                let inside = obj
                    .texture
                    .as_ref()
                    .and_then(|t| t.interior_texture.clone());
                let mut layered = crate::eval::materials::texture::layer_texture(
                    obj.texture.as_ref(),
                    top,
                    span,
                )?;
                if let Some(inside) = inside {
                    // A texture written after `interior_texture` keeps it.
                    Arc::make_mut(&mut layered).interior_texture = Some(inside);
                }
                obj.texture = Some(layered);
            }
            Tok::Block(kw @ ("pigment" | "normal" | "finish"), _, span)
                if obj.texture.as_ref().is_some_and(|t| t.patterned.is_some()) =>
            {
                crate::eval::materials::texture::check_not_patterned(
                    obj.texture.as_ref(),
                    kw,
                    span,
                )?;
            }
            Tok::Block(_, Value::Interior(i), _) => obj.interior = Some(attach_interior(obj, i)),
            Tok::Block(_, Value::Material(m), span) => {
                if let Some(t) = &m.texture {
                    let top = attach(obj, (**t).clone());
                    obj.texture = Some(crate::eval::materials::texture::layer_texture(
                        obj.texture.as_ref(),
                        top,
                        span,
                    )?);
                }
                if let Some(i) = &m.interior {
                    obj.interior = Some(attach_interior(obj, i.clone()));
                }
            }
            Tok::Block(_, Value::Normal(n), _) => {
                let mut tex = match obj.texture.as_deref() {
                    Some(t) => t.clone(),
                    None => (*attach(obj, (*self.default_texture).clone())).clone(),
                };
                let mut tmp = Texture {
                    normal: Some((*n).clone()),
                    ..Texture::default()
                };
                if let Some(ot) = obj.transform.as_deref() {
                    tmp.transform_patterns(&Transform {
                        matrix: ot.inverse,
                        inverse: ot.matrix,
                    });
                }
                tex.normal = tmp.normal;
                obj.texture = Some(Arc::new(tex));
            }
            Tok::Block(_, Value::Pigment(p), _) => {
                let finish = match obj.texture.as_deref() {
                    Some(t) => t.finish,
                    None => self.default_texture.finish,
                };
                let normal = obj.texture.as_deref().and_then(|t| t.normal.clone());
                let tex = Texture {
                    pigment: (*p).clone(),
                    finish,
                    ..Texture::default()
                };
                let mut tex = (*attach(obj, tex)).clone();
                tex.normal = normal;
                obj.texture = Some(Arc::new(tex));
            }
            Tok::Block(_, Value::Finish(f), _) => {
                let mut tex = match obj.texture.as_deref() {
                    Some(t) => t.clone(),
                    None => {
                        // A finish alone keeps the default pigment, in the object's frame.
                        let t = (*self.default_texture).clone();
                        (*attach(obj, t)).clone()
                    }
                };
                tex.finish = *f;
                obj.texture = Some(Arc::new(tex));
            }
            Tok::Kw("no_shadow", _) => {
                // Photons pass through shadowless objects (POV-Ray's rule).
                obj.flags.no_shadow = true;
                obj.flags.photons.pass_through = true;
            }
            Tok::Kw("no_image", _) => obj.flags.no_image = true,
            Tok::Kw("no_reflection", _) => obj.flags.no_reflection = true,
            Tok::Kw("no_radiosity", _) => obj.flags.no_radiosity = true,
            Tok::Block("radiosity", Value::Radiosity(b), span) => {
                if let Some(at) = b.global_item {
                    return Err(Diagnostic::error(
                        codes::UNEXPECTED_ITEM,
                        at,
                        "an object's `radiosity { }` takes only `importance`",
                    )
                    .with_secondary(span, "in this object's radiosity block")
                    .with_help("radiosity settings go in global_settings { radiosity { … } }")
                    .into());
                }
                if let Some((x, _)) = b.importance {
                    obj.flags.importance = Some((x * 10_000.0).round().clamp(1.0, 10_000.0) as u16);
                }
            }
            Tok::Block("photons", Value::Photons(b), span) => {
                self.photons_for(&b, crate::eval::settings::photons::PhotonsIn::Object, span);
                let own = b.object;
                obj.flags.photons = crate::scene::ObjectPhotons {
                    // `no_shadow` makes photons pass unless the block says otherwise.
                    pass_through: own.pass_through
                        || (obj.flags.photons.pass_through && !b.pass_through_off),
                    ..own
                };
            }
            Tok::Kw("inverse", _) => obj.flags.inverse = !obj.flags.inverse,
            Tok::Kw(kw @ ("hollow" | "double_illuminate" | "sturm"), _) => {
                // `sturm` is accepted: the torus solver is always the careful one.
                let on = self.take_switch(c)?;
                match kw {
                    "hollow" => obj.flags.hollow = on,
                    "double_illuminate" => obj.flags.double_illuminate = on,
                    _ => {}
                }
            }
            Tok::Kw("open", _)
                if matches!(
                    obj.shape,
                    Shape::Cylinder { .. }
                        | Shape::Cone { .. }
                        | Shape::Prism { .. }
                        | Shape::Sor { .. }
                ) =>
            {
                if let Shape::Cylinder { open, .. }
                | Shape::Cone { open, .. }
                | Shape::Prism { open, .. }
                | Shape::Sor { open, .. } = &mut obj.shape
                {
                    *open = true;
                }
            }
            Tok::Block("clipped_by", Value::Array(a), span) => {
                // The clipping objects are where they are now; later transforms of
                // this object move them with it.
                let inv = obj.transform.as_deref().map(|t| Transform {
                    matrix: t.inverse,
                    inverse: t.matrix,
                });
                let mut clips = obj.clipped_by.as_deref().cloned().unwrap_or_default();
                for e in a.elems.iter().flatten() {
                    match e {
                        Value::Object(o) => {
                            let mut o = (**o).clone();
                            if let Some(inv) = &inv {
                                apply_transform(&mut o, inv);
                            }
                            clips.push(o);
                        }
                        Value::Poison => {}
                        other => return Err(self.mismatch("an object to clip by", other, span)),
                    }
                }
                if clips.is_empty() {
                    return Err(Diagnostic::error(
                        codes::MISSING_VALUE,
                        span,
                        "`clipped_by` needs an object",
                    )
                    .with_help("write e.g. `clipped_by { plane { y, 0 } }`")
                    .into());
                }
                obj.nesting = clips
                    .iter()
                    .map(|c| c.nesting + 1)
                    .fold(obj.nesting, u32::max);
                self.check_nesting(obj)?;
                obj.clipped_by = Some(Arc::new(clips));
            }
            Tok::Block("bounded_by", _, _) => {
                // Accepted and ignored: rts bounds every object itself.
            }
            Tok::Block(_, Value::Object(_), span) if !is_union => {
                return Err(Diagnostic::error(
                    codes::UNEXPECTED_ITEM,
                    span,
                    format!("an object inside `{}`", c.block),
                )
                .with_help("to group objects use `union { … }`")
                .into());
            }
            Tok::Block(_, Value::Object(_), span) => {
                return Err(Diagnostic::error(
                    codes::UNEXPECTED_ITEM,
                    span,
                    "objects must come before the union's modifiers",
                )
                .with_help("move this object above the first transform or texture of the union")
                .into());
            }
            Tok::Kw("open", span) => {
                return Err(Diagnostic::error(
                    codes::UNKNOWN_PARAMETER,
                    span,
                    format!("`open` is not valid in `{}`", c.block),
                )
                .with_help("`open` applies to cylinders, cones, prisms, sors and isosurfaces only")
                .into());
            }
            other => return Err(self.unexpected(c, &other, OBJECT_MODIFIERS)),
        }
        Ok(())
    }

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

fn value_of(t: &Tok) -> Value {
    match t {
        Tok::Val(v, _) | Tok::Block(_, v, _) => v.clone(),
        _ => Value::Poison,
    }
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
                members.append(children);
                return child.nesting;
            }
            _ => {}
        }
    }
    let nesting = child.nesting + 1;
    members.push_back(child);
    nesting
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

/// Attaches a texture given now: its pattern stays where it is in the world, so in the
/// object's frame it is `object_from_world ∘ world_from_pattern`.
fn attach(obj: &Object, mut tex: Texture) -> Arc<Texture> {
    if let Some(ot) = obj.transform.as_deref() {
        let inv = Transform {
            matrix: ot.inverse,
            inverse: ot.matrix,
        };
        tex.transform_patterns(&inv);
    }
    Arc::new(tex)
}

/// Attaches an interior given now: as a texture's patterns, its media's densities
/// stay where they are in the world (later transforms of the object move them).
fn attach_interior(obj: &Object, i: Arc<crate::scene::Interior>) -> Arc<crate::scene::Interior> {
    match obj.transform.as_deref() {
        Some(ot) if !i.media.is_empty() => {
            let inv = Transform {
                matrix: ot.inverse,
                inverse: ot.matrix,
            };
            let mut own = (*i).clone();
            for m in &mut own.media {
                m.transform(&inv);
            }
            Arc::new(own)
        }
        _ => i,
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

/// Most `light_group`s a scene may have (one bit each in an object's mask).
pub(crate) const MAX_LIGHT_GROUPS: u32 = 64;

impl Evaluator<'_> {
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
