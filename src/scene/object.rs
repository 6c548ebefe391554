//! Objects: shapes with placement, material and flags.

use super::{Interior, Texture, Transform};
use crate::span::Span;
use glam::DVec3;
use std::sync::Arc;

/// Per-object flags (`no_shadow`, `no_image`, …) kept together.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ObjectFlags {
    /// `no_shadow`: the object casts no shadow.
    pub no_shadow: bool,
    /// `no_image`: invisible to camera rays.
    pub no_image: bool,
    /// `no_reflection`: invisible in reflections.
    pub no_reflection: bool,
    /// `inverse`: inside and outside swapped.
    pub inverse: bool,
}

/// One object: a shape, its placement and its material.
#[derive(Clone, Debug)]
pub struct Object {
    /// The geometry, in object space.
    pub shape: Shape,
    /// `world_from_object`, the product of the object's `translate rotate scale matrix`
    /// in the order written; `None` for the identity.
    pub transform: Option<Arc<Transform>>,
    /// The object's texture; `None` inherits from an enclosing CSG object or the
    /// `#default` texture that was in force.
    pub texture: Option<Arc<Texture>>,
    /// `interior { … }`; `None` inherits from an enclosing CSG object, else
    /// POV-Ray's default interior.
    pub interior: Option<Arc<Interior>>,
    /// Flags such as `no_shadow`.
    pub flags: ObjectFlags,
    /// Where the object was written.
    pub span: Span,
}

impl Object {
    /// A shape with no transform, no texture (inherited or default) and no flags.
    pub fn new(shape: Shape, span: Span) -> Object {
        Object {
            shape,
            transform: None,
            texture: None,
            interior: None,
            flags: ObjectFlags::default(),
            span,
        }
    }
}

/// The shapes of this release, in object space.
#[derive(Clone, Debug)]
pub enum Shape {
    /// `sphere { CENTER, RADIUS }`.
    Sphere {
        /// Centre.
        center: DVec3,
        /// Radius (> 0).
        radius: f64,
    },
    /// `plane { NORMAL, DISTANCE }`: the points p with `p·n = distance`, inside below.
    Plane {
        /// Unit normal.
        normal: DVec3,
        /// Offset along the normal.
        distance: f64,
    },
    /// `box { CORNER1, CORNER2 }` with the corners sorted so `min <= max`.
    Box {
        /// Lowest corner.
        min: DVec3,
        /// Highest corner.
        max: DVec3,
    },
    /// `triangle { A, B, C }`.
    Triangle {
        /// Vertices.
        vertices: [DVec3; 3],
    },
    /// `union { OBJECT… }`: the children keep their own transforms, which are applied
    /// before the union's.
    Union {
        /// The member objects.
        children: Vec<Object>,
    },
}
