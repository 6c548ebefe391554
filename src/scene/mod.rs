//! The scene description: plain data produced by [`crate::eval`] and consumed by
//! [`crate::build`]. Every entity keeps the [`Span`] it came from so later stages can
//! report problems at the source, but nothing here refers to syntax.
//!
//! The types are closed enums so new shapes, patterns and lights are added as variants
//! without reshaping what exists.

mod camera;
mod material;
mod transform;

pub use camera::{Camera, CameraKind};
pub use material::{Colour, Finish, Pattern, Pigment, Reflection, Texture};
pub use transform::Transform;

use crate::span::Span;
use glam::DVec3;
use std::sync::Arc;

/// A whole evaluated scene: what one frame of a `.rts` file describes.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The camera (POV-Ray's default camera when the file has none).
    pub camera: Camera,
    /// Light sources, in file order.
    pub lights: Vec<Light>,
    /// Top-level objects, in file order.
    pub objects: Vec<Object>,
    /// Colour of rays that hit nothing (`background { … }`; black by default).
    pub background: Colour,
    /// `global_settings { … }`.
    pub global: GlobalSettings,
}

impl Default for Scene {
    fn default() -> Self {
        Scene {
            camera: Camera::default(),
            lights: Vec::new(),
            objects: Vec::new(),
            background: Colour::BLACK,
            global: GlobalSettings::default(),
        }
    }
}

/// `global_settings { ambient_light assumed_gamma max_trace_level adc_bailout }`.
#[derive(Clone, Debug, PartialEq)]
pub struct GlobalSettings {
    /// `ambient_light`: multiplies every finish's `ambient` (default white).
    pub ambient_light: DVec3,
    /// `assumed_gamma`: the gamma of the working colour space; `None` when the scene
    /// does not say (POV-Ray 3.7 then behaves as `assumed_gamma 1.0` with a warning).
    pub assumed_gamma: Option<f64>,
    /// `max_trace_level`: deepest recursion of reflected rays (default 5).
    pub max_trace_level: u32,
    /// `adc_bailout`: rays whose contribution falls below this are not traced further
    /// (default 1/255).
    pub adc_bailout: f64,
}

impl Default for GlobalSettings {
    fn default() -> Self {
        GlobalSettings {
            ambient_light: DVec3::ONE,
            assumed_gamma: None,
            max_trace_level: 5,
            adc_bailout: 1.0 / 255.0,
        }
    }
}

/// `light_source { LOCATION, COLOUR [parallel point_at P] }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    /// Position in world space.
    pub location: DVec3,
    /// Colour, used as intensity (may exceed 1).
    pub colour: DVec3,
    /// What kind of light this is.
    pub kind: LightKind,
    /// `shadowless`: this light casts no shadows.
    pub shadowless: bool,
    /// Where the light was written.
    pub span: Span,
}

/// The kinds of light source.
#[derive(Clone, Debug, PartialEq)]
pub enum LightKind {
    /// An omnidirectional point light.
    Point,
    /// `parallel`: light arrives everywhere from the direction `location - point_at`;
    /// only objects in front of the plane through `location` cast shadows.
    Parallel {
        /// The point the light shines at (`point_at`, default origin).
        point_at: DVec3,
    },
}

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
