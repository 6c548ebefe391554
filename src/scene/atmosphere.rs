//! What rays meet outside objects: `sky_sphere` and `fog`.

use super::{Colour, Pigment, Transform};
use glam::DVec3;

/// Everything between and beyond the objects.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Atmosphere {
    /// `sky_sphere { … }`, drawn behind everything (over the background).
    pub sky_sphere: Option<SkySphere>,
    /// `fog { … }` blocks, applied to every ray in file order.
    pub fogs: Vec<Fog>,
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

/// `fog { fog_type distance COLOUR [fog_offset fog_alt up] }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    /// Constant fog or ground fog.
    pub kind: FogKind,
    /// `distance`: where the fog lets through `exp(-1)` of what is behind it.
    pub distance: f64,
    /// The fog colour; `filter` tints and `transmit` lets through what is behind.
    pub colour: Colour,
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
