//! The camera, resolved to the vectors POV-Ray's cameras use.

use crate::span::Span;
use glam::DVec3;

/// Camera projections. Screen coordinates (sx, sy) run over [-0.5, 0.5]² (sy up).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum CameraKind {
    /// `perspective` (the default): direction `direction + sx right + sy up`.
    #[default]
    Perspective,
    /// `orthographic`: parallel rays along `direction` from
    /// `location + sx right + sy up`.
    Orthographic,
    /// `fisheye`: the angle from `direction` grows linearly with the distance from
    /// the image centre, reaching `angle / 2` at the edge of the inscribed circle;
    /// nothing is seen outside it.
    Fisheye {
        /// Full field of view in degrees (default 180).
        angle: f64,
    },
    /// `ultra_wide_angle`: with longitude `2 sx · angle/2` and latitude
    /// `2 sy · angle/2 · |up|/|right|`, the direction
    /// `sin(lon) right + sin(lat) up + cos(lon) cos(lat) direction` (unit vectors).
    UltraWideAngle {
        /// Horizontal field of view in degrees (default 90).
        angle: f64,
    },
    /// `panoramic`: with `a = π sx` and `b = π sy`, the direction
    /// `sin(a) right + tan(b) up + cos(a) direction` (the vectors as they are, not
    /// normalised; measured against POV-Ray 3.7, which ignores `angle` for it).
    Panoramic,
    /// `cylinder 1` to `4` (measured against POV-Ray 3.7). The angle around the
    /// cylinder's axis is `θ = s · angle`, `s` the screen coordinate across the axis;
    /// along the axis the screen coordinate `a` moves the ray by `a` times the
    /// (unnormalised) axis vector. Types 1 and 3 have a vertical axis (`up`; θ
    /// from `sx`, towards `right`), types 2 and 4 a horizontal one (`right`; θ from
    /// `sy`, towards `up`). Types 1 and 2 start every ray at `location` and tilt
    /// the direction `cos θ D + sin θ A + a·axis` (unit `D`, `A`); types 3 and 4
    /// move the start along the axis instead and keep the direction flat.
    Cylinder {
        /// The type, 1 to 4.
        kind: u8,
        /// The angle around the axis the image spans, in degrees (default 90).
        angle: f64,
    },
    /// `spherical`: longitude and latitude mapped linearly onto the image.
    Spherical {
        /// Horizontal field of view in degrees (default 360).
        h_angle: f64,
        /// Vertical field of view in degrees (default half the horizontal).
        v_angle: f64,
    },
}

/// A camera after `look_at`, `angle` and `sky` have been applied, as POV-Ray does:
/// for a perspective camera the primary ray through screen point (sx, sy) in
/// [-0.5, 0.5]² (sy up) has direction `direction + sx * right + sy * up`.
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
    /// `aperture`: size of the lens for depth of field (0 = pinhole); the lens radius
    /// is aperture / 4, which blurs as much as POV-Ray 3.7.
    pub aperture: f64,
    /// Distance from `location` (along `direction`) of the plane in focus, from
    /// `focal_point`.
    pub focal_distance: f64,
    /// `blur_samples [MIN,] MAX`: the most lens rays a depth-of-field camera
    /// averages for one image sample.
    pub blur_samples: u32,
    /// The fewest lens rays per image sample (`MIN` of `blur_samples MIN, MAX`).
    pub blur_min_samples: u32,
    /// `confidence` (default 0.9) and `variance` (default 1/128) of the rule that
    /// stops taking lens rays once the mean is close enough (see
    /// `render::focal_blur`).
    pub confidence: f64,
    /// See `confidence`.
    pub variance: f64,
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
            aperture: 0.0,
            focal_distance: 1.0,
            blur_samples: 1,
            blur_min_samples: 1,
            confidence: 0.9,
            variance: 1.0 / 128.0,
            span: Span::default(),
        }
    }
}
