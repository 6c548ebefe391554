//! Where the evaluator is: what the items being expanded are inside. Some
//! items mean something else in some blocks (a `sphere { }` in a `blob` is a
//! component, an `object { }` in a pigment is the object pattern, a long
//! vector in a `poly` is a list of coefficients), so a block's items are
//! expanded in a [`Context`] made from the block's keyword and the context
//! the block itself is in, set by [`Evaluator::within`] and restored after.

use super::Evaluator;
use crate::syntax::Sym;

/// What the items being expanded are inside. Small and `Copy`: a block's
/// context is made from its keyword and the one around it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Context {
    /// In the items of a `poly`, `cubic` or `quartic` block: there, a vector
    /// of more than 5 numbers (other than a 12-number matrix) is a list of
    /// coefficients (a one-dimensional array).
    pub(crate) coefficient_lists: bool,
    /// In the items of a texture (or a texture_map's entries) or an object:
    /// there a `pigment`, `finish` or `normal` block modifies the one in force,
    /// as in POV-Ray, so it is kept unevaluated
    /// ([`super::cursor::Tok::Deferred`]) until the reader knows what it
    /// modifies (see `materials/modify.rs`).
    pub(crate) defer_material_blocks: bool,
    /// In the items of a `blob`: there a `sphere` or `cylinder` block is a blob
    /// component (see `objects/blob.rs`).
    pub(crate) blob_items: bool,
    /// In the items of a `pigment`, `normal`, `texture` or `density`: there an
    /// `object { OBJECT A, B }` block is the object pattern.
    pub(crate) pattern_items: bool,
    /// In `#declare NAME = function { … }`: the name it binds. POV-Ray's
    /// functions.inc declares its built-ins as `function { internal(NUMBER) }`,
    /// and rts knows them by that name, not by POV-Ray's private numbers.
    pub(crate) declaring_function: Option<Sym>,
}

impl Context {
    /// The context of the items of a `kw { … }` block written in this one;
    /// `object_pattern`: the block is the object pattern (see
    /// [`Context::is_object_pattern`]).
    pub(crate) fn items_of(self, kw: &str, object_pattern: bool) -> Context {
        Context {
            coefficient_lists: matches!(kw, "poly" | "cubic" | "quartic"),
            // Texture bodies (also a texture_map's entries) and objects read a
            // pigment, finish or normal as a change to the one in force.
            defer_material_blocks: (matches!(kw, "texture" | "texture_map" | "interior_texture")
                || crate::eval::objects::object::is_object_block(kw))
                && !object_pattern,
            blob_items: kw == "blob",
            pattern_items: matches!(kw, "pigment" | "normal" | "texture" | "density"),
            declaring_function: self.declaring_function,
        }
    }

    /// The context of the items of a deferred `pigment`, `finish` or `normal`
    /// block (`kw`), evaluated in this one once its reader knows what it
    /// modifies: what is inside the block is not itself in a texture or object.
    pub(crate) fn deferred_items_of(self, kw: &str) -> Context {
        Context {
            defer_material_blocks: false,
            pattern_items: matches!(kw, "pigment" | "normal"),
            ..self
        }
    }

    /// Whether a `kw { … }` block written in this context is the object
    /// pattern: `object { … }` among a pigment's, normal's or texture's items
    /// (its object is read as usual, its pigments, normals or textures are
    /// entries, not the object's own).
    pub(crate) fn is_object_pattern(self, kw: &str) -> bool {
        kw == "object" && self.pattern_items
    }

    /// Whether a `kw { … }` block written in this context is a blob component.
    pub(crate) fn is_blob_component(self, kw: &str) -> bool {
        self.blob_items && matches!(kw, "sphere" | "cylinder")
    }
}

impl Evaluator<'_> {
    /// Runs `f` in context `ctx`, then restores the context it replaced.
    pub(crate) fn within<T>(&mut self, ctx: Context, f: impl FnOnce(&mut Self) -> T) -> T {
        let outer = std::mem::replace(&mut self.ctx, ctx);
        let r = f(self);
        self.ctx = outer;
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_block_sets_what_its_items_are_in() {
        let top = Context::default();
        let poly = top.items_of("poly", false);
        assert!(poly.coefficient_lists && poly.defer_material_blocks);
        let blob = top.items_of("blob", false);
        assert!(blob.blob_items && blob.is_blob_component("sphere"));
        assert!(!blob.items_of("sphere", false).blob_items);
        let pigment = top.items_of("pigment", false);
        assert!(pigment.is_object_pattern("object") && !pigment.defer_material_blocks);
        assert!(!pigment.items_of("object", true).defer_material_blocks);
        assert!(pigment.items_of("object", false).defer_material_blocks);
    }

    #[test]
    fn the_declared_name_reaches_nested_blocks() {
        let name = crate::syntax::intern::intern("f_context_test");
        let declaring = Context {
            declaring_function: Some(name),
            ..Context::default()
        };
        let inner = declaring
            .items_of("pigment", false)
            .items_of("texture", false);
        assert_eq!(inner.declaring_function, Some(name));
    }

    #[test]
    fn a_deferred_block_keeps_the_rest_of_the_context() {
        let poly_texture = Context::default()
            .items_of("poly", false)
            .items_of("texture", false);
        let around = Context {
            coefficient_lists: true,
            ..poly_texture
        };
        let inner = around.deferred_items_of("finish");
        assert!(inner.coefficient_lists);
        assert!(!inner.defer_material_blocks && !inner.pattern_items);
        assert!(around.deferred_items_of("pigment").pattern_items);
    }
}
