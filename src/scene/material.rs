//! Colours, pigments, finishes and textures.

use super::Transform;
use glam::DVec3;
use std::sync::Arc;

/// A POV-Ray colour: red, green, blue, filter and transmit.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Colour {
    /// Red, green and blue.
    pub rgb: DVec3,
    /// `filter`: light passing through, tinted by the colour.
    pub filter: f64,
    /// `transmit`: light passing through untinted.
    pub transmit: f64,
}

impl Colour {
    /// Opaque black.
    pub const BLACK: Colour = Colour {
        rgb: DVec3::ZERO,
        filter: 0.0,
        transmit: 0.0,
    };

    /// An opaque colour.
    pub fn rgb(r: f64, g: f64, b: f64) -> Colour {
        Colour {
            rgb: DVec3::new(r, g, b),
            filter: 0.0,
            transmit: 0.0,
        }
    }
}

/// `texture { pigment { … } finish { … } }`.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Texture {
    /// The colour pattern.
    pub pigment: Pigment,
    /// How the surface responds to light.
    pub finish: Finish,
}

/// `pigment { PATTERN … [transforms] }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Pigment {
    /// The pattern that gives the colour at a point.
    pub pattern: Pattern,
    /// `pattern_from_object`… stored as `object_from_pattern`: the transforms written
    /// inside the pigment (and those applied to the texture/object after it).
    pub transform: Option<Arc<Transform>>,
}

impl Default for Pigment {
    /// POV-Ray's default pigment is black.
    fn default() -> Self {
        Pigment {
            pattern: Pattern::Solid(Colour::BLACK),
            transform: None,
        }
    }
}

/// The colour patterns of this release.
#[derive(Clone, Debug, PartialEq)]
pub enum Pattern {
    /// One colour everywhere.
    Solid(Colour),
    /// `checker A, B`: unit cubes alternating between two pigments.
    Checker(Box<[Pigment; 2]>),
}

/// `reflection { MIN, MAX fresnel falloff metallic }` or `reflection COLOUR`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reflection {
    /// Reflection at normal incidence (and the only value when `max` equals it).
    pub min: DVec3,
    /// Reflection at grazing incidence.
    pub max: DVec3,
    /// `fresnel`: use the Fresnel equations with the interior's ior between min and max.
    pub fresnel: bool,
    /// `falloff`: exponent of the blend from min to max.
    pub falloff: f64,
    /// `metallic`: tint the reflection by the surface colour.
    pub metallic: f64,
}

impl Default for Reflection {
    fn default() -> Self {
        Reflection {
            min: DVec3::ZERO,
            max: DVec3::ZERO,
            fresnel: false,
            falloff: 1.0,
            metallic: 0.0,
        }
    }
}

/// `finish { ambient diffuse brilliance phong phong_size specular roughness metallic reflection }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Finish {
    /// `ambient`: light the surface has without any source (default 0.1).
    pub ambient: DVec3,
    /// `diffuse`: Lambertian response (default 0.6).
    pub diffuse: f64,
    /// `brilliance`: exponent on the diffuse cosine (default 1).
    pub brilliance: f64,
    /// `phong`: Phong highlight strength (default 0).
    pub phong: f64,
    /// `phong_size`: Phong exponent (default 40).
    pub phong_size: f64,
    /// `specular`: Blinn highlight strength (default 0).
    pub specular: f64,
    /// `roughness`: Blinn highlight size (default 0.05; exponent is 1/roughness).
    pub roughness: f64,
    /// `metallic`: how much highlights take the surface colour (0 to 1).
    pub metallic: f64,
    /// Mirror reflection.
    pub reflection: Reflection,
}

impl Default for Finish {
    fn default() -> Self {
        Finish {
            ambient: DVec3::splat(0.1),
            diffuse: 0.6,
            brilliance: 1.0,
            phong: 0.0,
            phong_size: 40.0,
            specular: 0.0,
            roughness: 0.05,
            metallic: 0.0,
            reflection: Reflection::default(),
        }
    }
}

/// `interior { ior fade_distance fade_power }`: what is inside a surface, for rays
/// that pass through it (filter/transmit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interior {
    /// `ior`: index of refraction (1 = no bending).
    pub ior: f64,
    /// `fade_distance`: distance at which light inside has faded to half (0 = no
    /// fading).
    pub fade_distance: f64,
    /// `fade_power`: exponent of the fading (0 = no fading).
    pub fade_power: f64,
}

impl Default for Interior {
    /// POV-Ray's default interior: ior 1, no fading.
    fn default() -> Self {
        Interior {
            ior: 1.0,
            fade_distance: 0.0,
            fade_power: 0.0,
        }
    }
}
