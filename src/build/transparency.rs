//! Which surfaces may let light through: a shadow ray blocked by any other
//! surface is simply dark, and both renderers skip walking its hits.

use super::{PrimShape, Primitive};
use crate::scene::{Pattern, PatternMap, Pigment, Texture};

/// For each of `primitives`, whether any of its textures (any layer, CSG leaves
/// and mesh texture lists included) may let light through: a pigment with filter
/// or transmit anywhere, or an image map with such pixels or `once`.
pub(super) fn translucent(primitives: &[Primitive]) -> Vec<bool> {
    fn pigment(p: &Pigment) -> bool {
        match &p.pattern {
            Pattern::Solid(c) => c.filter + c.transmit > 0.0,
            Pattern::Checker(pair) => pair.iter().any(pigment),
            Pattern::Image(m) => m.see_through,
            Pattern::Uv(p) => pigment(p),
            Pattern::Mapped(m) => match &m.map {
                PatternMap::Colours(e) => e.iter().any(|(_, c)| c.filter + c.transmit > 0.0),
                PatternMap::Pigments(e) => e.iter().any(|(_, p)| pigment(p)),
                PatternMap::List(l) => l.iter().any(pigment),
            },
        }
    }
    fn texture(t: &Texture) -> bool {
        t.any_plain(&mut |x| pigment(&x.pigment))
    }
    primitives
        .iter()
        .map(|p| {
            texture(&p.texture)
                || match &p.shape {
                    PrimShape::Csg(c) => c.leaves.iter().any(|l| {
                        texture(&l.texture)
                            || matches!(&l.shape, PrimShape::Blob(b) if b.own_textures().any(|t| texture(t)))
                    }),
                    PrimShape::Blob(b) => b.own_textures().any(|t| texture(t)),
                    PrimShape::Mesh(m) => m.data.textures.iter().any(|t| texture(t)),
                    _ => false,
                }
        })
        .collect()
}
