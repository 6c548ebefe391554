//! `quadric`: the general second-degree surface
//! `A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0`,
//! inside where the left side is negative (POV-Ray's convention).

use crate::build::Ray;
use glam::DVec3;

/// The ten coefficients `A … J` of a quadric, in POV-Ray's order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quadric(pub [f64; 10]);

impl Quadric {
    /// The polynomial's value at `p` (negative inside).
    pub fn value(&self, p: DVec3) -> f64 {
        let [a, b, c, d, e, f, g, h, i, j] = self.0;
        a * p.x * p.x
            + b * p.y * p.y
            + c * p.z * p.z
            + d * p.x * p.y
            + e * p.x * p.z
            + f * p.y * p.z
            + g * p.x
            + h * p.y
            + i * p.z
            + j
    }

    /// Every crossing in `(t_min, t_max)`.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64)) {
        let [a, b, c, d, e, ff, g, h, i, _] = self.0;
        let (o, v) = (ray.origin, ray.dir);
        let qa = a * v.x * v.x
            + b * v.y * v.y
            + c * v.z * v.z
            + d * v.x * v.y
            + e * v.x * v.z
            + ff * v.y * v.z;
        let qb = 2.0 * (a * o.x * v.x + b * o.y * v.y + c * o.z * v.z)
            + d * (o.x * v.y + o.y * v.x)
            + e * (o.x * v.z + o.z * v.x)
            + ff * (o.y * v.z + o.z * v.y)
            + g * v.x
            + h * v.y
            + i * v.z;
        let qc = self.value(o);
        let mut put = |t: f64| {
            if t > t_min && t < t_max {
                f(t)
            }
        };
        let scale = qb.abs().max(qc.abs()).max(1e-300);
        if qa.abs() <= 1e-12 * scale {
            // Linear along this ray (e.g. along a cylinder's axis).
            if qb != 0.0 {
                put(-qc / qb);
            }
            return;
        }
        let disc = qb * qb - 4.0 * qa * qc;
        if disc < 0.0 {
            return;
        }
        let q = -0.5 * (qb + disc.sqrt().copysign(qb));
        put(q / qa);
        if q != 0.0 {
            put(qc / q);
        }
    }

    /// The nearest crossing in `(t_min, t_max)`.
    pub fn nearest(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
        super::nearest(|f| self.hits(ray, t_min, t_max, f))
    }

    /// The gradient at `p`: the outward normal, unnormalised.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let [a, b, c, d, e, f, g, h, i, _] = self.0;
        DVec3::new(
            2.0 * a * p.x + d * p.y + e * p.z + g,
            2.0 * b * p.y + d * p.x + f * p.z + h,
            2.0 * c * p.z + e * p.x + f * p.y + i,
        )
    }

    /// Whether `p` is strictly inside.
    pub fn inside(&self, p: DVec3) -> bool {
        self.value(p) < 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ray(o: DVec3, d: DVec3) -> Ray {
        Ray::new(o, d)
    }

    #[test]
    fn unit_sphere_quadric_matches_the_sphere() {
        let q = Quadric([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let r = ray(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        assert!((q.nearest(&r, 1e-9, f64::INFINITY).unwrap() - 4.0).abs() < 1e-12);
        let p = DVec3::new(0.0, 0.0, -1.0);
        assert!((q.normal(p).normalize() - DVec3::NEG_Z).length() < 1e-12);
        assert!(q.inside(DVec3::ZERO) && !q.inside(DVec3::splat(1.0)));
    }

    #[test]
    fn cylinder_along_its_axis_is_missed_and_crossed_across() {
        // Cylinder_Y: x² + z² = 1.
        let q = Quadric([1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let along = ray(DVec3::new(0.0, -5.0, 0.0), DVec3::Y);
        assert_eq!(q.nearest(&along, 1e-9, f64::INFINITY), None);
        let across = ray(DVec3::new(-3.0, 7.0, 0.0), DVec3::X);
        assert!((q.nearest(&across, 1e-9, f64::INFINITY).unwrap() - 2.0).abs() < 1e-12);
    }

    #[test]
    fn paraboloid_linear_case() {
        // Paraboloid_Y: x² + z² - y = 0, hit straight down the axis: one root.
        let q = Quadric([1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0]);
        let r = ray(DVec3::new(0.0, 4.0, 0.0), DVec3::NEG_Y);
        assert!((q.nearest(&r, 1e-9, f64::INFINITY).unwrap() - 4.0).abs() < 1e-12);
    }
}
