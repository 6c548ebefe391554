//! The camera, resolved to the vectors POV-Ray's perspective camera uses.

use crate::span::Span;
use glam::DVec3;

/// Camera projections.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CameraKind {
    /// `perspective` (the default).
    #[default]
    Perspective,
}

/// A camera after `look_at`, `angle` and `sky` have been applied, as POV-Ray does:
/// the primary ray through screen point (sx, sy) in [-0.5, 0.5]² (sy up) has direction
/// `direction + sx * right + sy * up`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The projection.
    pub kind: CameraKind,
    /// Eye position.
    pub location: DVec3,
    /// Vector from the eye to the centre of the image plane.
    pub direction: DVec3,
    /// Full image-plane vector from left edge to right edge.
    pub right: DVec3,
    /// Full image-plane vector from bottom edge to top edge.
    pub up: DVec3,
    /// Where the camera was written (default span for the default camera).
    pub span: Span,
}

impl Default for Camera {
    /// POV-Ray's default camera: at the origin looking along +z, `right 1.33*x`.
    fn default() -> Self {
        Camera {
            kind: CameraKind::Perspective,
            location: DVec3::ZERO,
            direction: DVec3::Z,
            right: DVec3::new(1.33, 0.0, 0.0),
            up: DVec3::Y,
            span: Span::default(),
        }
    }
}
