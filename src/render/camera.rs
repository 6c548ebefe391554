//! Primary rays.

use super::Sampler;
use crate::build::Ray;
use crate::scene::Camera;
use glam::DVec3;

/// The ray through image point (`x`, `y`) in pixel units of a `width`×`height`
/// image: (0, 0) is the top-left corner of the top-left pixel, so the centre of pixel
/// (i, j) is (i + 0.5, j + 0.5). The direction is
/// `direction + (u - 0.5) right + (0.5 - v) up` with `u = x / width`,
/// `v = y / height`, normalised. `sampler` supplies the values a camera needs
/// beyond the image point (none for a pinhole perspective camera). `None` when the
/// point is outside the camera's image (not possible for a perspective camera).
pub fn primary_ray(
    camera: &Camera,
    x: f64,
    y: f64,
    width: u32,
    height: u32,
    sampler: &mut Sampler,
) -> Option<Ray> {
    let _ = sampler;
    let u = x / f64::from(width);
    let v = y / f64::from(height);
    let dir: DVec3 = camera.direction + (u - 0.5) * camera.right + (0.5 - v) * camera.up;
    Some(Ray::new(camera.location, dir.normalize()))
}
