//! Values of the language.

use crate::scene::{
    Colour, Finish, Interior, Light, Normal, Object, Pigment, Reflection, Texture, Transform,
};
use crate::syntax::ast::MacroDef;
use glam::DVec3;
use std::rc::Rc;
use std::sync::Arc;

/// A vector of 2 to 5 components.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vector {
    /// Components; those past `len` are zero.
    pub c: [f64; 5],
    /// How many components (2..=5).
    pub len: u8,
}

impl Vector {
    /// A vector from a slice of 2 to 5 components.
    pub fn from_slice(s: &[f64]) -> Vector {
        let mut c = [0.0; 5];
        c[..s.len()].copy_from_slice(s);
        Vector {
            c,
            len: s.len() as u8,
        }
    }

    /// A 3-vector.
    pub fn v3(v: DVec3) -> Vector {
        Vector::from_slice(&[v.x, v.y, v.z])
    }

    /// The first three components.
    pub fn xyz(&self) -> DVec3 {
        DVec3::new(self.c[0], self.c[1], self.c[2])
    }

    /// The used components.
    pub fn as_slice(&self) -> &[f64] {
        &self.c[..self.len as usize]
    }
}

/// A multi-dimensional array; elements start unset.
#[derive(Clone, Debug)]
pub struct Array {
    /// Size of each dimension.
    pub dims: Vec<usize>,
    /// Elements in row-major order.
    pub elems: Vec<Option<Value>>,
}

/// The camera as written, before `look_at` and `angle` are resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct CameraSpec {
    /// `location`.
    pub location: DVec3,
    /// `direction`.
    pub direction: DVec3,
    /// `up`.
    pub up: DVec3,
    /// `right`.
    pub right: DVec3,
    /// `sky`.
    pub sky: DVec3,
    /// `look_at`, if given.
    pub look_at: Option<DVec3>,
    /// `angle`, if given (horizontal field of view in degrees).
    pub angle: Option<f64>,
    /// Transforms applied after the vectors.
    pub transform: Option<Transform>,
    /// The projection keyword (`perspective`, `orthographic`, `fisheye`, …).
    pub projection: &'static str,
    /// Second value of `angle H, V` (spherical cameras).
    pub v_angle: Option<f64>,
    /// The type of a `cylinder` camera (1 to 4; 0 for other projections).
    pub cylinder: u8,
    /// `aperture` (0 = pinhole).
    pub aperture: f64,
    /// `focal_point`.
    pub focal_point: DVec3,
    /// `blur_samples` (the larger value of `blur_samples MIN, MAX`).
    pub blur_samples: u32,
    /// The smaller value of `blur_samples MIN, MAX` (1 when only MAX is given).
    pub blur_min_samples: u32,
    /// `confidence`.
    pub confidence: f64,
    /// `variance`.
    pub variance: f64,
    /// Whether `right` or `up` was written (an orthographic camera then keeps their
    /// sizes).
    pub sized: bool,
    /// `mesh_camera { … }`, if given.
    pub mesh: Option<Arc<crate::scene::MeshCamera>>,
    /// `normal { … }`, if given.
    pub normal: Option<Arc<crate::scene::Normal>>,
}

impl Default for CameraSpec {
    fn default() -> Self {
        CameraSpec {
            location: DVec3::ZERO,
            direction: DVec3::Z,
            up: DVec3::Y,
            right: DVec3::new(1.33, 0.0, 0.0),
            sky: DVec3::Y,
            look_at: None,
            angle: None,
            transform: None,
            projection: "perspective",
            v_angle: None,
            cylinder: 0,
            aperture: 0.0,
            focal_point: DVec3::ZERO,
            blur_samples: 1,
            blur_min_samples: 1,
            confidence: 0.9,
            variance: 1.0 / 128.0,
            sized: false,
            mesh: None,
            normal: None,
        }
    }
}

/// A value.
#[derive(Clone, Debug)]
pub enum Value {
    /// A float; booleans are floats (0 is false).
    Float(f64),
    /// A vector of 2–5 components.
    Vector(Vector),
    /// A colour.
    Colour(Colour),
    /// A string.
    Str(Rc<str>),
    /// An array.
    Array(Rc<Array>),
    /// The contents of a list block (`vertex_vectors { … }`, …), packed.
    List(Rc<super::list::List>),
    /// An object.
    Object(Arc<Object>),
    /// A texture.
    Texture(Arc<Texture>),
    /// A pigment.
    Pigment(Arc<Pigment>),
    /// A finish.
    Finish(Arc<Finish>),
    /// A camera.
    Camera(Arc<CameraSpec>),
    /// A `mesh_camera { … }` block, inside a camera.
    MeshCamera(Arc<crate::scene::MeshCamera>),
    /// `object { OBJECT A, B }` read as a pattern: its kind and the entries
    /// after the object (see `pattern_blocks.rs`).
    ObjectPattern(std::rc::Rc<(crate::scene::PatternKind, ObjectPatternEntries)>),
    /// A `radiosity { … }` block: global settings or an object's importance.
    Radiosity(Arc<crate::scene::RadiosityBlock>),
    /// A `photons { … }` block: global settings, an object's or a light's.
    Photons(Arc<crate::scene::PhotonsBlock>),
    /// A light source.
    Light(Arc<Light>),
    /// A `sky_sphere { … }`.
    SkySphere(Arc<crate::scene::SkySphere>),
    /// A `fog { … }`.
    Fog(Arc<crate::scene::Fog>),
    /// A `rainbow { … }`.
    Rainbow(Arc<crate::scene::Rainbow>),
    /// A `media { … }`.
    Media(Arc<crate::scene::Media>),
    /// A `scattering { … }` (only meaningful inside a media).
    Scattering(crate::scene::Scattering),
    /// A `material { … }`.
    Material(Arc<crate::eval::materials::material_block::Material>),
    /// A transform.
    Transform(Arc<Transform>),
    /// `reflection { … }` (only meaningful inside a finish).
    Reflection(Reflection),
    /// A normal (bump pattern).
    Normal(Arc<Normal>),
    /// An interior.
    Interior(Arc<Interior>),
    /// A colour map.
    ColourMap(Arc<Vec<(f64, Colour)>>),
    /// A pigment map.
    PigmentMap(Arc<Vec<(f64, Pigment)>>),
    /// A texture map (entries in the order written).
    TextureMap(crate::scene::TextureMapEntries),
    /// A normal map (entries in the order written).
    NormalMap(Arc<Vec<(f64, Normal)>>),
    /// A slope map: `(value, <height, slope>)` entries in the order written.
    SlopeMap(Arc<Vec<(f64, glam::DVec2)>>),
    /// A pattern written as a block (`pigment_pattern { … }`, `image_pattern
    /// { … }`, `slope { … }`), taken by the pigment, normal or texture it is in.
    Pattern(Arc<crate::scene::PatternKind>),
    /// A macro.
    Macro(Rc<MacroDef>),
    /// A `spline { }`, called as `S(t)`.
    Spline(Rc<crate::scene::Spline>),
    /// A `function { }`, called as `F(x, y, z)`.
    Function(Arc<crate::scene::Function>),
    /// A file opened by `#fopen`.
    File(Rc<std::cell::RefCell<super::file_io::OpenFile>>),
    /// A `warp { … }` (only meaningful inside a pattern).
    Warp(Arc<crate::scene::Warp>),
    /// An `irid { … }` (only meaningful inside a finish).
    Irid(crate::scene::Irid),
    /// The value of something whose evaluation failed (already reported); using it
    /// fails silently so one error does not cascade.
    Poison,
}

impl Value {
    /// The kind of value, as named in messages ("a float", "a vector", …).
    pub fn kind(&self) -> &'static str {
        match self {
            Value::Float(_) => "a float",
            Value::Vector(v) => match v.len {
                2 => "a 2-vector",
                3 => "a vector",
                4 => "a 4-vector",
                _ => "a 5-vector",
            },
            Value::Colour(_) => "a colour",
            Value::Str(_) => "a string",
            Value::Array(_) => "an array",
            Value::List(_) => "a list",
            Value::Object(_) => "an object",
            Value::Texture(_) => "a texture",
            Value::Pigment(_) => "a pigment",
            Value::Finish(_) => "a finish",
            Value::Camera(_) => "a camera",
            Value::MeshCamera(_) => "a mesh_camera block",
            Value::Radiosity(_) => "a radiosity block",
            Value::Photons(_) => "a photons block",
            Value::ObjectPattern(_) => "an object pattern",
            Value::Light(_) => "a light source",
            Value::SkySphere(_) => "a sky_sphere",
            Value::Fog(_) => "a fog",
            Value::Rainbow(_) => "a rainbow",
            Value::Media(_) => "a media",
            Value::Scattering(_) => "a scattering block",
            Value::Material(_) => "a material",
            Value::Transform(_) => "a transform",
            Value::Reflection(_) => "a reflection block",
            Value::Warp(_) => "a warp",
            Value::Irid(_) => "an irid block",
            Value::Normal(_) => "a normal",
            Value::Interior(_) => "an interior",
            Value::ColourMap(_) => "a colour map",
            Value::PigmentMap(_) => "a pigment map",
            Value::NormalMap(_) => "a normal map",
            Value::SlopeMap(_) => "a slope map",
            Value::Pattern(_) => "a pattern",
            Value::TextureMap(_) => "a texture map",
            Value::Macro(_) => "a macro",
            Value::Spline(_) => "a spline",
            Value::Function(_) => "a function",
            Value::File(_) => "a file",
            Value::Poison => "an erroneous value",
        }
    }
}

/// Colour components as a 5-vector `<r, g, b, f, t>`.
pub fn colour_to_array(c: &Colour) -> [f64; 5] {
    [c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit]
}

/// A colour from `<r, g, b, f, t>`.
pub fn colour_from_array(a: [f64; 5]) -> Colour {
    Colour {
        rgb: DVec3::new(a[0], a[1], a[2]),
        filter: a[3],
        transmit: a[4],
    }
}

/// The items after an object pattern's object (its entries), kept as read.
#[derive(Clone, Debug)]
pub struct ObjectPatternEntries(pub(crate) Vec<super::cursor::Tok>);
