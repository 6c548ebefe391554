//! The components of a `blob`.

use super::{Texture, Transform};
use glam::DVec3;
use std::sync::Arc;

/// `blob { threshold T sphere { … } cylinder { … } … }`: the surface where the
/// summed field of the components equals the threshold, inside where it is above.
#[derive(Clone, Debug, PartialEq)]
pub struct BlobData {
    /// `threshold` (POV-Ray's default 1).
    pub threshold: f64,
    /// The components, in the order written.
    pub components: Vec<BlobComponent>,
}

/// One component of a blob: its field is `strength · (1 − (d/r)²)²` at distance
/// `d < r` from its centre (sphere) or axis segment (cylinder), 0 beyond.
#[derive(Clone, Debug, PartialEq)]
pub struct BlobComponent {
    /// The shape of the field.
    pub kind: BlobKind,
    /// The field at the centre or on the axis (may be negative).
    pub strength: f64,
    /// `component_from_blob`'s inverse: the component's own transforms, which
    /// place it in the blob's space; `None` for the identity.
    pub transform: Option<Arc<Transform>>,
    /// The component's own texture (in the component's frame); `None` takes the
    /// blob's.
    pub texture: Option<Arc<Texture>>,
}

/// Where a component's field lives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BlobKind {
    /// `sphere { CENTER, RADIUS, [strength] S }` (and the old `component S, R, CENTER`).
    Sphere {
        /// Centre.
        center: DVec3,
        /// Radius (> 0).
        radius: f64,
    },
    /// `cylinder { END1, END2, RADIUS, [strength] S }`: the distance is to the
    /// segment, so the ends are round.
    Cylinder {
        /// One end of the axis.
        a: DVec3,
        /// The other end.
        b: DVec3,
        /// Radius (> 0).
        radius: f64,
    },
}
