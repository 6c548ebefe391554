//! What every object takes besides its shape: texture, pigment, normal,
//! finish, interior and material, clipping and bounding, flags such as
//! `no_shadow` and `hollow`, photons and radiosity settings.

use super::object::apply_transform;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, R};
use crate::scene::{Object, Shape, Texture, Transform};
use crate::span::Span;
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

impl Evaluator<'_> {
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
    pub(super) fn modifiers(&mut self, obj: &mut Object, c: &mut Cursor, is_union: bool) {
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
                tex.pigment = crate::eval::materials::pigment::uv_mapped(std::mem::take(&mut tex.pigment));
                Ok(Tok::Block(kw, Value::Texture(Arc::new(tex)), span))
            }
            Tok::Block(kw, Value::Pigment(p), span) => Ok(Tok::Block(
                kw,
                Value::Pigment(Arc::new(crate::eval::materials::pigment::uv_mapped((*p).clone()))),
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
}
