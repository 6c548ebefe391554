//! Time: the scene's `animation { }` timeline, `keyframes { }`, `camera_path
//! { }`, and POV-Ray's `spline { }` values.

pub(crate) mod camera_path;
pub mod keyframe;
pub(crate) mod spline;
pub(crate) mod timeline;
