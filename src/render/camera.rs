//! Primary rays for every camera type.

use super::Sampler;
use crate::build::Ray;
use crate::scene::{Camera, CameraKind, CameraMesh, MeshCamera};
use glam::{DVec2, DVec3};

/// The ray through image point (`x`, `y`) in pixel units of a `width`×`height`
/// image: (0, 0) is the top-left corner of the top-left pixel, so the centre of pixel
/// (i, j) is (i + 0.5, j + 0.5). With screen coordinates `sx = x / width - 0.5`,
/// `sy = 0.5 - y / height` the perspective direction is
/// `direction + sx right + sy up`, normalised; see [`CameraKind`] for the others.
///
/// A camera with an `aperture` takes its point on the lens from `sampler` (two
/// values) and aims at the point of the pinhole ray on the focal plane. `None` when
/// the point is outside the camera's image (outside a fisheye's circle).
pub fn primary_ray(
    camera: &Camera,
    x: f64,
    y: f64,
    width: u32,
    height: u32,
    sampler: &mut Sampler,
) -> Option<Ray> {
    if let Some(mesh) = &camera.mesh {
        return mesh_ray(mesh, x, y, width, height, 0);
    }
    let sx = x / f64::from(width) - 0.5;
    let sy = 0.5 - y / f64::from(height);
    let (origin, dir) = pinhole(camera, sx, sy)?;
    let dir = match &camera.normal {
        Some(n) => crate::pattern::perturb_camera_ray(n, dir.normalize(), sx, sy),
        None => dir.normalize(),
    };
    if camera.aperture <= 0.0 || camera.kind == CameraKind::Orthographic {
        return Some(Ray::new(origin, dir));
    }
    let axis = camera.direction.normalize();
    let along = dir.dot(axis);
    if along <= 1e-9 {
        return Some(Ray::new(origin, dir));
    }
    let focus = origin + dir * (camera.focal_distance / along);
    let (a, b) = sampler.next_2d();
    let (lx, ly) = super::sampler::concentric_disc(a, b);
    // Lens radius aperture / 4: measured against POV-Ray 3.7 (255 blur samples),
    // this gives the same width of blur; aperture / 2 blurs twice as much.
    let lens = 0.25
        * camera.aperture
        * (lx * camera.right.normalize_or_zero() + ly * camera.up.normalize_or_zero());
    let o = origin + lens;
    Some(Ray::new(o, (focus - o).normalize()))
}

/// Ray `ray_number` (0 up to `rays_per_pixel`) of a mesh camera at image point
/// (`x`, `y`), as POV-Ray 3.7 shoots them (measured on small meshes):
///
/// - distributions 0 to 2 take one face per pixel, from the pixel's column and
///   row, except that the first two rows both use row 0 of the faces (POV-Ray's
///   row is one less, never below 0); a face index past the faces shoots nothing;
///   0: face `row × width + column` of mesh `ray_number`; 1: face `ray_number ×
///   width × height + row × width + column` of all meshes in turn; 2: the image is
///   cut into one block of columns per mesh, and mesh `column / block` gives face
///   `row × block + column`;
/// - the ray starts at the face's centroid, along `(c - a) × (b - a)`;
/// - distribution 3 maps the image onto uv space (`u = x / width`, `v = 1 - y /
///   height` at a pixel's centre sample, so sub-samples sweep the pixel) and
///   starts at the point of the face whose uv triangle holds it, along the face's
///   direction or, with `smooth`, the interpolated vertex normal;
/// - every ray starts `location.z` along its direction from the face, and goes
///   the other way when `direction.z` is negative.
pub fn mesh_ray(
    mesh: &MeshCamera,
    x: f64,
    y: f64,
    width: u32,
    height: u32,
    ray_number: u32,
) -> Option<Ray> {
    let (point, dir) = if mesh.distribution == 3 {
        if ray_number > 0 {
            return None;
        }
        let uv = DVec2::new(
            (x - 0.5) / f64::from(width),
            1.0 - (y - 0.5) / f64::from(height),
        );
        let (face, w) = mesh.uv_grid.find(&mesh.meshes, uv)?;
        let [a, b, c] = face.corners;
        let p = a * w[0] + b * w[1] + c * w[2];
        let d = match face.normals {
            Some([na, nb, nc]) if mesh.smooth => {
                (na * w[0] + nb * w[1] + nc * w[2]).normalize_or_zero()
            }
            _ => face.flat_direction(),
        };
        (p, d)
    } else {
        let column = (x.floor().max(0.0) as u64).min(u64::from(width.max(1) - 1));
        let row = (y.floor().max(0.0) as u64)
            .min(u64::from(height.max(1) - 1))
            .saturating_sub(1);
        let (w, h) = (u64::from(width), u64::from(height));
        let pick = |m: &CameraMesh, i: u64| (i < m.len() as u64).then(|| m.face(i as usize));
        let face = match mesh.distribution {
            0 => pick(mesh.meshes.get(ray_number as usize)?, row * w + column)?,
            1 => {
                let mut index = u64::from(ray_number) * w * h + row * w + column;
                let mut found = None;
                for m in &mesh.meshes {
                    let n = m.len() as u64;
                    if index < n {
                        found = pick(m, index);
                        break;
                    }
                    index -= n;
                }
                found?
            }
            _ => {
                if ray_number > 0 {
                    return None;
                }
                let n = mesh.meshes.len().max(1) as u64;
                let block = (w / n).max(1);
                let m = (column / block).min(n - 1);
                pick(mesh.meshes.get(m as usize)?, row * block + column)?
            }
        };
        let [a, b, c] = face.corners;
        ((a + b + c) / 3.0, face.flat_direction())
    };
    if dir == DVec3::ZERO {
        return None;
    }
    let dir = if mesh.reversed { -dir } else { dir };
    Some(Ray::new(point + dir * mesh.offset, dir))
}

/// Origin and (unnormalised) direction of the pinhole ray at screen point (sx, sy).
fn pinhole(camera: &Camera, sx: f64, sy: f64) -> Option<(DVec3, DVec3)> {
    let (loc, d, r, u) = (camera.location, camera.direction, camera.right, camera.up);
    // Unit vectors and aspect only for the projections that use them: the common
    // perspective and orthographic rays need no square roots.
    let units = || {
        (
            d.normalize(),
            r.normalize(),
            u.normalize(),
            r.length() / u.length(),
        )
    };
    Some(match camera.kind {
        CameraKind::Perspective => (loc, d + sx * r + sy * u),
        CameraKind::Orthographic => (loc + sx * r + sy * u, d),
        CameraKind::Fisheye { angle } => {
            let (dn, rn, un, aspect) = units();
            let (mut x0, mut y0) = (2.0 * sx, 2.0 * sy);
            if aspect > 1.0 {
                x0 *= aspect;
            } else {
                y0 /= aspect;
            }
            let rad = (x0 * x0 + y0 * y0).sqrt();
            if rad > 1.0 {
                return None;
            }
            let theta = rad * angle.to_radians() / 2.0;
            let (st, ct) = theta.sin_cos();
            // cos φ and sin φ of the screen angle φ = atan2(y0, x0), without trigonometry.
            let (cp, sp) = if rad > 0.0 {
                (x0 / rad, y0 / rad)
            } else {
                (1.0, 0.0)
            };
            (loc, st * cp * rn + st * sp * un + ct * dn)
        }
        CameraKind::UltraWideAngle { angle } => {
            let (dn, rn, un, aspect) = units();
            let half = angle.to_radians() / 2.0;
            let lon = 2.0 * sx * half;
            let lat = 2.0 * sy * half / aspect;
            let ((sl, cl), (sb, cb)) = (lon.sin_cos(), lat.sin_cos());
            (loc, sl * rn + sb * un + cl * cb * dn)
        }
        CameraKind::Panoramic => {
            let (_, _, un, _) = units();
            let (a, b) = (std::f64::consts::PI * sx, std::f64::consts::PI * sy);
            if b.abs() >= std::f64::consts::FRAC_PI_2 - 1e-12 {
                (loc, un * b.signum())
            } else {
                (loc, a.sin() * r + b.tan() * u + a.cos() * d)
            }
        }
        CameraKind::Cylinder { kind, angle } => {
            let (dn, rn, un, _) = units();
            // Around the axis from one screen coordinate, along it from the other.
            let (around, along, side, axis) = if kind % 2 == 1 {
                (sx, sy, rn, u)
            } else {
                (sy, sx, un, r)
            };
            let (s, c) = (around * angle.to_radians()).sin_cos();
            let flat = c * dn + s * side;
            if kind <= 2 {
                (loc, flat + along * axis)
            } else {
                (loc + along * axis, flat)
            }
        }
        CameraKind::Spherical { h_angle, v_angle } => {
            let (dn, rn, un, _) = units();
            let lon = sx * h_angle.to_radians();
            let lat = sy * v_angle.to_radians();
            let (sl, cl) = lon.sin_cos();
            let (sb, cb) = lat.sin_cos();
            (loc, cb * sl * rn + sb * un + cb * cl * dn)
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cam(kind: CameraKind) -> Camera {
        Camera {
            kind,
            right: DVec3::X,
            ..Camera::default()
        }
    }

    fn ray(c: &Camera, x: f64, y: f64) -> Option<Ray> {
        primary_ray(c, x, y, 100, 100, &mut Sampler::new(0, 0, 0, 0, 0))
    }

    #[test]
    fn orthographic_rays_are_parallel_from_the_image_plane() {
        let c = Camera {
            right: DVec3::X * 4.0,
            up: DVec3::Y * 3.0,
            ..cam(CameraKind::Orthographic)
        };
        let r = primary_ray(&c, 0.0, 0.0, 40, 30, &mut Sampler::new(0, 0, 0, 0, 0)).unwrap();
        assert!((r.origin - DVec3::new(-2.0, 1.5, 0.0)).length() < 1e-12);
        assert!((r.dir - DVec3::Z).length() < 1e-12);
        let r = primary_ray(&c, 40.0, 30.0, 40, 30, &mut Sampler::new(0, 0, 0, 0, 0)).unwrap();
        assert!((r.origin - DVec3::new(2.0, -1.5, 0.0)).length() < 1e-12);
    }

    #[test]
    fn fisheye_angle_grows_linearly_from_the_centre() {
        let c = cam(CameraKind::Fisheye { angle: 180.0 });
        let centre = ray(&c, 50.0, 50.0).unwrap();
        assert!((centre.dir - DVec3::Z).length() < 1e-12);
        // Right edge of the circle: 90° off the axis, pointing along +x.
        let edge = ray(&c, 100.0, 50.0).unwrap();
        assert!((edge.dir - DVec3::X).length() < 1e-9);
        // Halfway: 45°.
        let half = ray(&c, 75.0, 50.0).unwrap();
        assert!((half.dir.dot(DVec3::Z) - 45f64.to_radians().cos()).abs() < 1e-12);
        // Top: +y.
        let top = ray(&c, 50.0, 0.0).unwrap();
        assert!((top.dir - DVec3::Y).length() < 1e-9);
        assert!(ray(&c, 0.0, 0.0).is_none());
    }

    #[test]
    fn cylinder_cameras_wrap_one_axis_and_run_straight_along_the_other() {
        let c = |kind| Camera {
            right: DVec3::X * 2.0,
            up: DVec3::Y * 3.0,
            ..cam(CameraKind::Cylinder { kind, angle: 180.0 })
        };
        // Type 1: the right edge is 90° to the right; the top rises by |up| / 2.
        let r = ray(&c(1), 100.0, 50.0).unwrap();
        assert!((r.dir - DVec3::X).length() < 1e-9);
        let r = ray(&c(1), 50.0, 0.0).unwrap();
        assert!((r.dir - DVec3::new(0.0, 1.5, 1.0).normalize()).length() < 1e-9);
        assert_eq!(r.origin, DVec3::ZERO);
        // Type 2: the top edge is 90° up; the right edge moves sideways by |right| / 2.
        let r = ray(&c(2), 50.0, 0.0).unwrap();
        assert!((r.dir - DVec3::Y).length() < 1e-9);
        let r = ray(&c(2), 100.0, 50.0).unwrap();
        assert!((r.dir - DVec3::new(1.0, 0.0, 1.0).normalize()).length() < 1e-9);
        // Types 3 and 4: the start moves along the axis, the rays stay flat.
        let r = ray(&c(3), 50.0, 0.0).unwrap();
        assert!((r.origin - DVec3::new(0.0, 1.5, 0.0)).length() < 1e-12);
        assert!((r.dir - DVec3::Z).length() < 1e-12);
        let r = ray(&c(4), 0.0, 0.0).unwrap();
        assert!((r.origin - DVec3::new(-1.0, 0.0, 0.0)).length() < 1e-12);
        assert!((r.dir - DVec3::Y).length() < 1e-9);
    }

    #[test]
    fn spherical_maps_longitude_and_latitude_linearly() {
        let c = cam(CameraKind::Spherical {
            h_angle: 360.0,
            v_angle: 180.0,
        });
        let r = ray(&c, 75.0, 50.0).unwrap();
        assert!((r.dir - DVec3::X).length() < 1e-9);
        let r = ray(&c, 0.0, 50.0).unwrap();
        assert!((r.dir + DVec3::Z).length() < 1e-9);
        let r = ray(&c, 50.0, 0.0).unwrap();
        assert!((r.dir - DVec3::Y).length() < 1e-9);
    }

    #[test]
    fn depth_of_field_keeps_the_focal_plane_sharp() {
        let c = Camera {
            aperture: 0.5,
            focal_distance: 4.0,
            ..cam(CameraKind::Perspective)
        };
        let pin = ray(&c, 30.0, 60.0).unwrap();
        let focus = pin.origin + pin.dir * (4.0 / pin.dir.z);
        for i in 0..16 {
            let r =
                primary_ray(&c, 30.0, 60.0, 100, 100, &mut Sampler::new(0, 0, 1, 2, i)).unwrap();
            let t = (focus.z - r.origin.z) / r.dir.z;
            assert!((r.origin + r.dir * t - focus).length() < 1e-9);
            assert!(r.origin.z == 0.0 && r.origin.length() <= 0.125 + 1e-12);
        }
    }
}
