//! Dispatch from a block's keyword to the code that evaluates it.

use super::cursor::{Cursor, Sink, Tok};
use super::value::Value;
use super::{Evaluator, R};
use crate::diag::{codes, Diagnostic};
use crate::eval::objects::object::{is_object_block, OBJECT_BLOCKS};
use crate::syntax::ast::Block;

/// Blocks this release evaluates besides the objects ([`OBJECT_BLOCKS`]).
pub(crate) const BLOCKS: &[&str] = &[
    "clipped_by",
    "bounded_by",
    "vertex_vectors",
    "normal_vectors",
    "uv_vectors",
    "face_indices",
    "normal_indices",
    "uv_indices",
    "texture_list",
    "texture",
    "pigment",
    "finish",
    "reflection",
    "normal",
    "interior",
    "color_map",
    "colour_map",
    "pigment_map",
    "texture_map",
    "tiles",
    "image_map",
    "camera",
    "mesh_camera",
    "light_source",
    "transform",
    "global_settings",
    "background",
    "sky_sphere",
    "fog",
    "rainbow",
    "media",
    "scattering",
    "density",
    "density_map",
    "material",
    "looks_like",
    "projected_through",
    "spline",
    "keyframes",
    "animation",
    "camera_path",
    "path_tracing",
    "radiosity",
    "photons",
    "function",
    "contained_by",
    "warp",
    "irid",
    "pigment_pattern",
    "image_pattern",
    "slope",
    "normal_map",
    "slope_map",
    "bump_map",
    "material_map",
    "interior_texture",
    "subsurface",
];

/// Whether `k` opens a block this release evaluates.
pub(crate) fn is_evaluated_block(k: &str) -> bool {
    static SET: std::sync::LazyLock<rustc_hash::FxHashSet<&'static str>> =
        std::sync::LazyLock::new(|| BLOCKS.iter().chain(OBJECT_BLOCKS).copied().collect());
    SET.contains(k)
}

/// Whether `k` opens a block (`k { … }`).
pub(crate) fn is_block_keyword(k: &str) -> bool {
    is_evaluated_block(k)
}

impl Evaluator<'_> {
    /// Evaluates a block; `None` for blocks that only have effects (`global_settings`).
    pub(crate) fn block(&mut self, b: &Block) -> R<Option<Value>> {
        let kw = b.keyword.name;
        if !is_evaluated_block(kw) {
            return Err(Diagnostic::error(
                codes::UNEXPECTED_ITEM,
                b.keyword.span,
                format!("`{kw}` does not take a `{{ }}` block"),
            )
            .with_help(format!(
                "write `{kw}` followed by its value, without braces"
            ))
            .into());
        }
        if kw == "function" {
            // Its body is compiled, not evaluated.
            return self.function_block(b).map(Some);
        }
        if kw == "camera_path" {
            // Its keyframes stay curves: it reads its items itself.
            return self.camera_path(b).map(Some);
        }
        let mut toks = Sink::new();
        toks.packed = super::list::PACKED_LISTS.contains(&kw);
        let outer = self.ctx;
        let object_pattern = outer.is_object_pattern(kw);
        self.within(outer.items_of(kw, object_pattern), |ev| {
            ev.expand(&b.items, &mut toks);
        });
        let mut c = Cursor::new(toks.toks, kw, b.span);
        if object_pattern {
            return self.object_pattern(&mut c).map(Some);
        }
        if kw == "object" && matches!(c.peek(), Some(Tok::Val(Value::Light(_), _))) {
            return Ok(Some(Value::Light(std::sync::Arc::new(
                self.light_object(&mut c)?,
            ))));
        }
        Ok(Some(match kw {
            kw if outer.is_blob_component(kw) => {
                Value::Object(std::sync::Arc::new(self.blob_component(&mut c)?))
            }
            kw if is_object_block(kw) => Value::Object(std::sync::Arc::new(self.object(&mut c)?)),
            "clipped_by" | "bounded_by" | "contained_by" | "vertex_vectors" | "normal_vectors"
            | "uv_vectors" | "face_indices" | "normal_indices" | "uv_indices" | "texture_list" => {
                self.list_block(&mut c)?
            }
            "texture" | "interior_texture" => {
                Value::Texture(std::sync::Arc::new(self.texture(&mut c)?))
            }
            "pigment_pattern" => self.pigment_pattern(&mut c)?,
            "image_pattern" => self.image_pattern(&mut c)?,
            "slope" => self.slope_block(&mut c)?,
            "normal_map" => Value::NormalMap(std::sync::Arc::new(self.normal_map(&mut c)?)),
            "slope_map" => Value::SlopeMap(std::sync::Arc::new(self.slope_map(&mut c)?)),
            "bump_map" => Value::Normal(std::sync::Arc::new(self.bump_map(&mut c)?)),
            "material_map" => Value::Texture(std::sync::Arc::new(self.material_map(&mut c)?)),
            "pigment" => Value::Pigment(std::sync::Arc::new(self.pigment(&mut c)?)),
            "finish" => Value::Finish(std::sync::Arc::new(self.finish(&mut c)?)),
            "reflection" => Value::Reflection(self.reflection(&mut c)?),
            "warp" => Value::Warp(std::sync::Arc::new(self.warp_block(&mut c)?)),
            "irid" => Value::Irid(self.irid_block(&mut c)?),
            "normal" => Value::Normal(std::sync::Arc::new(self.normal(&mut c)?)),
            "interior" => Value::Interior(std::sync::Arc::new(self.interior(&mut c)?)),
            // As in POV-Ray, a density map's entries may be densities (a map of
            // densities, as a pigment map is of pigments) or colours.
            "density_map" if c.rest().any(holds_pigment) => {
                Value::PigmentMap(std::sync::Arc::new(self.pigment_map(&mut c)?))
            }
            "color_map" | "colour_map" | "density_map" => {
                Value::ColourMap(std::sync::Arc::new(self.colour_map(&mut c)?))
            }
            "pigment_map" => Value::PigmentMap(std::sync::Arc::new(self.pigment_map(&mut c)?)),
            "texture_map" => Value::TextureMap(std::sync::Arc::new(self.texture_map(&mut c)?)),
            "image_map" => Value::Pigment(std::sync::Arc::new(self.image_map(&mut c)?)),
            "camera" => Value::Camera(std::sync::Arc::new(self.camera(&mut c)?)),
            "mesh_camera" => Value::MeshCamera(std::sync::Arc::new(self.mesh_camera(&mut c)?)),
            "light_source" => Value::Light(std::sync::Arc::new(self.light(&mut c)?)),
            "transform" => Value::Transform(std::sync::Arc::new(self.transform_block(&mut c)?)),
            "looks_like" | "projected_through" => {
                Value::Object(std::sync::Arc::new(self.looks_like(&mut c, kw)?))
            }
            "spline" => self.spline_block(&mut c)?,
            "keyframes" => self.keyframes_block(&mut c)?,
            "camera_path" => unreachable!("read above"),
            "animation" => {
                self.animation_block(&mut c)?;
                return Ok(None);
            }
            "sky_sphere" => Value::SkySphere(std::sync::Arc::new(self.sky_sphere(&mut c)?)),
            "fog" => Value::Fog(std::sync::Arc::new(self.fog(&mut c)?)),
            "rainbow" => Value::Rainbow(std::sync::Arc::new(self.rainbow(&mut c)?)),
            "media" => Value::Media(std::sync::Arc::new(self.media(&mut c)?)),
            "scattering" => Value::Scattering(self.scattering(&mut c)?),
            "density" => Value::Pigment(std::sync::Arc::new(self.density(&mut c)?)),
            "tiles" => Value::Texture(std::sync::Arc::new(self.tiles(&mut c)?)),
            "material" => Value::Material(std::sync::Arc::new(self.material(&mut c)?)),
            "radiosity" => Value::Radiosity(std::sync::Arc::new(self.radiosity_block(&mut c)?)),
            "photons" => Value::Photons(std::sync::Arc::new(self.photons_block(&mut c)?)),
            "path_tracing" => {
                self.path_tracing(&mut c)?;
                return Ok(None);
            }
            "global_settings" => {
                self.global_settings(&mut c);
                return Ok(None);
            }
            "subsurface" => {
                self.subsurface(&mut c)?;
                return Ok(None);
            }
            _ => {
                self.background(&mut c)?;
                return Ok(None);
            }
        }))
    }

    /// Evaluates a block that must give a value (`#declare X = sphere { … }`).
    pub(crate) fn block_value(&mut self, b: &Block) -> R<Value> {
        match self.block(b)? {
            Some(v) => Ok(v),
            None => Err(Diagnostic::error(
                codes::TYPE_MISMATCH,
                b.span,
                format!("`{}` has no value to declare or pass", b.keyword.name),
            )
            .with_help(format!(
                "write `{} {{ … }}` at top level instead",
                b.keyword.name
            ))
            .into()),
        }
    }
}

/// Whether map entry `t` (`[VALUE …]`) holds a pigment or density.
fn holds_pigment(t: &Tok) -> bool {
    matches!(t, Tok::Bracket(items, _) if items.iter().any(|i| matches!(
        i,
        Tok::Val(Value::Pigment(_), _) | Tok::Block(_, Value::Pigment(_), _)
    )))
}
