//! Primary rays.

use crate::build::Ray;
use crate::scene::Camera;
use glam::DVec3;

/// The unit-direction ray through the centre of pixel (`i`, `j`) of a
/// `width`×`height` image, `j = 0` being the top row:
/// `direction + (u - 0.5) right + (0.5 - v) up`, `u = (i + 0.5) / width`,
/// `v = (j + 0.5) / height`.
pub fn primary_ray(camera: &Camera, i: u32, j: u32, width: u32, height: u32) -> Ray {
    let u = (f64::from(i) + 0.5) / f64::from(width);
    let v = (f64::from(j) + 0.5) / f64::from(height);
    let dir: DVec3 = camera.direction + (u - 0.5) * camera.right + (0.5 - v) * camera.up;
    Ray::new(camera.location, dir.normalize())
}
