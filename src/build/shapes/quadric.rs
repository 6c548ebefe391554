//! `cylinder` and `cone`: a radius varying linearly along an axis segment.

use crate::build::{Aabb, Ray};
use glam::DVec3;

/// A cylinder or cone between two end points (a cylinder has equal radii).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frustum {
    /// Centre of the base end.
    pub base: DVec3,
    /// Unit axis from base to cap.
    pub axis: DVec3,
    /// Distance from base to cap.
    pub len: f64,
    /// Radius at the base.
    pub r0: f64,
    /// Radius at the cap.
    pub r1: f64,
    /// No end caps; not a solid.
    pub open: bool,
}

/// Surface ids ([`crate::build::Hit::sub`]).
const SIDE: u32 = 0;
const BASE_CAP: u32 = 1;
const TOP_CAP: u32 = 2;

impl Frustum {
    /// From the end points and radii; `None` when the ends coincide.
    pub fn new(base: DVec3, r0: f64, cap: DVec3, r1: f64, open: bool) -> Option<Frustum> {
        let d = cap - base;
        let len = d.length();
        (len > 0.0 && len.is_finite()).then(|| Frustum {
            base,
            axis: d / len,
            len,
            r0,
            r1,
            open,
        })
    }

    fn slope(&self) -> f64 {
        (self.r1 - self.r0) / self.len
    }

    /// Every crossing in `(t_min, t_max)`, with its surface id.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64, u32)) {
        let o = ray.origin - self.base;
        let (oz, dz) = (o.dot(self.axis), ray.dir.dot(self.axis));
        let op = o - self.axis * oz;
        let dp = ray.dir - self.axis * dz;
        let k = self.slope();
        let r_at = |z: f64| self.r0 + k * z;
        // |op + t dp|² = (r0 + k (oz + t dz))².
        let ro = r_at(oz);
        let a = dp.length_squared() - k * k * dz * dz;
        let b = op.dot(dp) - k * dz * ro;
        let c = op.length_squared() - ro * ro;
        let mut side = |t: f64| {
            let z = oz + t * dz;
            if t > t_min && t < t_max && z >= 0.0 && z <= self.len {
                f(t, SIDE);
            }
        };
        if a.abs() > 1e-300 {
            let disc = b * b - a * c;
            if disc >= 0.0 {
                let q = -(b + disc.sqrt().copysign(b));
                side(q / a);
                if q != 0.0 {
                    side(c / q);
                }
            }
        } else if b != 0.0 {
            side(-c / (2.0 * b));
        }
        if self.open || dz == 0.0 {
            return;
        }
        for (z, r, id) in [(0.0, self.r0, BASE_CAP), (self.len, self.r1, TOP_CAP)] {
            let t = (z - oz) / dz;
            if t > t_min && t < t_max && r > 0.0 && (op + dp * t).length_squared() <= r * r {
                f(t, id);
            }
        }
    }

    /// Outward normal of surface `sub` at `p`.
    pub fn normal(&self, p: DVec3, sub: u32) -> DVec3 {
        match sub {
            BASE_CAP => -self.axis,
            TOP_CAP => self.axis,
            _ => {
                let o = p - self.base;
                let radial = o - self.axis * o.dot(self.axis);
                let u = radial.normalize_or(self.axis.any_orthonormal_vector());
                // Gradient of |perp| - r(z).
                u - self.axis * self.slope()
            }
        }
    }

    /// Strictly inside the solid (never for `open`).
    pub fn inside(&self, p: DVec3) -> bool {
        if self.open {
            return false;
        }
        let o = p - self.base;
        let z = o.dot(self.axis);
        if z <= 0.0 || z >= self.len {
            return false;
        }
        let r = self.r0 + self.slope() * z;
        (o - self.axis * z).length_squared() < r * r
    }

    /// Bounds: the two end discs' boxes.
    pub fn bounds(&self) -> Aabb {
        let cap = self.base + self.axis * self.len;
        // Extent of a disc of radius r with normal a along axis i: r·sqrt(1 - a_i²).
        let e = (DVec3::ONE - self.axis * self.axis).max(DVec3::ZERO);
        let ext = DVec3::new(e.x.sqrt(), e.y.sqrt(), e.z.sqrt());
        Aabb::new(self.base - ext * self.r0, self.base + ext * self.r0)
            .union(&Aabb::new(cap - ext * self.r1, cap + ext * self.r1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(f: &Frustum, ray: &Ray) -> Vec<(f64, u32)> {
        let mut v = Vec::new();
        f.hits(ray, 0.0, f64::INFINITY, &mut |t, s| v.push((t, s)));
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        v
    }

    #[test]
    fn cylinder_side_and_caps() {
        let c = Frustum::new(DVec3::ZERO, 1.0, DVec3::Y * 2.0, 1.0, false).unwrap();
        let h = all(&c, &Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X));
        assert_eq!(h.len(), 2);
        assert!((h[0].0 - 4.0).abs() < 1e-12 && (h[1].0 - 6.0).abs() < 1e-12);
        let h = all(&c, &Ray::new(DVec3::new(0.5, 5.0, 0.0), -DVec3::Y));
        assert_eq!(h, vec![(3.0, TOP_CAP), (5.0, BASE_CAP)]);
        assert!(c.inside(DVec3::new(0.5, 1.0, 0.0)));
        assert!(!c.inside(DVec3::new(0.5, 2.5, 0.0)));
        let open = Frustum { open: true, ..c };
        assert!(all(&open, &Ray::new(DVec3::new(0.5, 5.0, 0.0), -DVec3::Y)).is_empty());
        assert!(!open.inside(DVec3::new(0.5, 1.0, 0.0)));
        let b = c.bounds();
        assert_eq!(
            (b.min, b.max),
            (DVec3::new(-1.0, 0.0, -1.0), DVec3::new(1.0, 2.0, 1.0))
        );
    }

    #[test]
    fn cone_side_hit_and_normal() {
        // Apex at y = 1, base radius 1 at y = 0: side is x + y = 1 in the x-y plane.
        let c = Frustum::new(DVec3::ZERO, 1.0, DVec3::Y, 0.0, false).unwrap();
        let h = all(&c, &Ray::new(DVec3::new(5.0, 0.5, 0.0), -DVec3::X));
        assert_eq!(h.len(), 2);
        assert!((h[0].0 - 4.5).abs() < 1e-12, "{h:?}");
        let n = c.normal(DVec3::new(0.5, 0.5, 0.0), SIDE).normalize();
        assert!((n - DVec3::new(1.0, 1.0, 0.0).normalize()).length() < 1e-12);
        // The other nappe (above the apex) is not part of the cone.
        assert!(all(&c, &Ray::new(DVec3::new(5.0, 1.5, 0.0), -DVec3::X)).is_empty());
    }
}
