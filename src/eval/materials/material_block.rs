//! `material { texture { … } interior { … } transforms }`: a texture and an interior
//! declared and applied together.

use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, R};
use crate::scene::{Interior, Texture, Transform};
use std::sync::Arc;

/// What `material { … }` may hold.
pub(crate) const MATERIAL_ITEMS: &[&str] = &[
    "texture",
    "interior",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
];

/// A `material`: its textures (layered in the order written) and its interior.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Material {
    /// The texture, `None` when the material has none (the object keeps its own).
    pub texture: Option<Arc<Texture>>,
    /// The interior, `None` when the material has none.
    pub interior: Option<Arc<Interior>>,
}

impl Material {
    /// Appends `t` to the transforms of the material's texture patterns (an
    /// interior has no pattern to move).
    fn transform(&mut self, t: &Transform) {
        if let Some(tex) = &mut self.texture {
            let mut moved = (**tex).clone();
            moved.transform_patterns(t);
            *tex = Arc::new(moved);
        }
    }
}

impl Evaluator<'_> {
    /// `material { [MATERIAL_IDENTIFIER] texture { … } … interior { … } transforms }`.
    /// As in POV-Ray, a texture written in a material lies over the declared
    /// material's texture, and an interior replaces its interior.
    pub(crate) fn material(&mut self, c: &mut Cursor) -> R<Material> {
        let mut m = Material::default();
        if let Some(Tok::Val(Value::Material(_), _)) = c.peek() {
            if let Some(Tok::Val(Value::Material(d), _)) = c.next() {
                m = (*d).clone();
            }
        }
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Block(_, Value::Texture(t), span) => {
                    super::texture::layer_texture(m.texture.as_ref(), t, span)
                        .map(|t| m.texture = Some(t))
                }
                Tok::Block(_, Value::Interior(i), _) => {
                    m.interior = Some(i);
                    Ok(())
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => {
                    self.transform_kw(kw, span, c).map(|t| m.transform(&t))
                }
                Tok::Block(_, Value::Transform(t), _) => {
                    m.transform(&t);
                    Ok(())
                }
                other => Err(self.unexpected(c, &other, MATERIAL_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        Ok(m)
    }
}
