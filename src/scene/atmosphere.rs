//! What rays meet outside objects: `sky_sphere`, `fog` and `rainbow`.

use super::{Colour, Pigment, Transform};
use glam::DVec3;

/// Everything between and beyond the objects.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Atmosphere {
    /// `sky_sphere { … }`, drawn behind everything (over the background).
    pub sky_sphere: Option<SkySphere>,
    /// `fog { … }` blocks, applied to every ray in file order.
    pub fogs: Vec<Fog>,
    /// `rainbow { … }` blocks.
    pub rainbows: Vec<Rainbow>,
    /// Top-level `media { … }` blocks: atmospheric media filling all space
    /// (outside non-hollow objects).
    pub media: Vec<super::Media>,
}

/// `sky_sphere { pigment { … } … [transforms] }`: pigments evaluated at the unit
/// ray direction; later pigments lie over earlier ones where they are opaque.
#[derive(Clone, Debug, PartialEq)]
pub struct SkySphere {
    /// The pigments, bottom first.
    pub pigments: Vec<Pigment>,
    /// Transforms of the sky sphere (applied to directions).
    pub transform: Option<Transform>,
}

/// `fog { fog_type distance COLOUR [fog_offset fog_alt up] [turbulence …] }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    /// Constant fog or ground fog.
    pub kind: FogKind,
    /// `distance`: where the fog lets through `exp(-1)` of what is behind it.
    pub distance: f64,
    /// The fog colour; `filter` tints and `transmit` lets through what is behind.
    pub colour: Colour,
    /// `turbulence`: varies the fog's thickness from ray to ray; `None` when the
    /// fog has none (or a zero amount).
    pub turbulence: Option<FogTurbulence>,
}

/// `turbulence <AMOUNT> [turb_depth D] [octaves N] [omega W] [lambda L]` in a fog:
/// the distance-based attenuation along each ray is scaled by a turbulence value
/// taken at one point of the ray (see `render::atmosphere`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogTurbulence {
    /// `turbulence`: per axis, how much the turbulence varies along that axis
    /// (the sampling point is scaled by it).
    pub amount: DVec3,
    /// `turb_depth` (default 0.5): where along the ray the turbulence is taken,
    /// 0 at the ray's start, 1 at what it hits.
    pub depth: f64,
    /// `octaves` (default 6).
    pub octaves: u32,
    /// `omega` (default 0.5).
    pub omega: f64,
    /// `lambda` (default 2).
    pub lambda: f64,
}

/// The fog types.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FogKind {
    /// `fog_type 1`: the same density everywhere.
    Constant,
    /// `fog_type 2`: full density below `offset` along `up`, decreasing as
    /// `1 / (1 + ((h - offset) / alt)²)` above it.
    Ground {
        /// `fog_offset`: height below which the fog is at full density.
        offset: f64,
        /// `fog_alt`: how fast the density falls above the offset.
        alt: f64,
        /// `up`: the direction of height (unit; default +y).
        up: DVec3,
    },
}

/// `rainbow { direction <D> angle A width W [distance D] [jitter J] [up <U>]
/// [arc_angle ARC] [falloff_angle FALL] colour_map { … } }`: a fog-like band of
/// colour seen where the angle between a ray and `direction` is within
/// `angle ± width / 2`.
#[derive(Clone, Debug, PartialEq)]
pub struct Rainbow {
    /// `direction`: the (unit) direction the rainbow's light travels in; the
    /// rainbow is a ring around it.
    pub direction: DVec3,
    /// `angle`, in degrees: the angle of the ring's middle from `direction`.
    pub angle: f64,
    /// `width`, in degrees: the ring's width (index 0 at its inner edge, 1 at
    /// its outer edge).
    pub width: f64,
    /// `distance`: as a fog's: something at depth d along the ray keeps
    /// `exp(-d / distance)` of its colour (the rainbow shows in front of
    /// objects only when this is small).
    pub distance: f64,
    /// `jitter`: the index moves by up to ± this, at random per ray.
    pub jitter: f64,
    /// The colours over the index (its `filter` and `transmit` as a fog's).
    pub colour_map: std::sync::Arc<Vec<(f64, Colour)>>,
    /// The arc: unit `up` (made perpendicular to `direction`) marks its middle.
    pub up: DVec3,
    /// `arc_angle` in degrees (360: a full circle).
    pub arc_angle: f64,
    /// `falloff_angle` in degrees (no greater than `arc_angle`): the middle part
    /// of the arc at full strength; beyond it the rainbow fades out towards the
    /// ends of the arc.
    pub falloff_angle: f64,
}
