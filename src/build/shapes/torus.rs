//! `torus { MAJOR, MINOR }`: the ring in the x-z plane around the y axis.

use crate::build::quartic::quartic;
use crate::build::{Aabb, Ray};
use glam::DVec3;

/// Every crossing of `ray` with the torus in `(t_min, t_max)`.
pub fn hits(major: f64, minor: f64, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64)) {
    let len = ray.dir.length();
    if len == 0.0 {
        return;
    }
    let d = ray.dir / len;
    // Start the polynomial near the torus: far origins make the quartic's
    // coefficients huge and its roots inaccurate.
    let outer = major + minor;
    let oc = ray.origin;
    let b = oc.dot(d);
    let perp = oc - d * b;
    if perp.length_squared() > outer * outer {
        return;
    }
    let half = (outer * outer - perp.length_squared()).sqrt();
    let shift = (-b - half).max(0.0);
    if -b + half < t_min * len {
        return;
    }
    let o = oc + d * shift;
    let (r2, m2) = (major * major, minor * minor);
    let e = o.dot(d);
    let k = o.length_squared() + r2 - m2;
    let a3 = 4.0 * e;
    let a2 = 4.0 * e * e + 2.0 * k - 4.0 * r2 * (d.x * d.x + d.z * d.z);
    let a1 = 4.0 * e * k - 8.0 * r2 * (o.x * d.x + o.z * d.z);
    let a0 = k * k - 4.0 * r2 * (o.x * o.x + o.z * o.z);
    let mut roots = [0.0; 4];
    let n = quartic(a3, a2, a1, a0, &mut roots);
    for &s in &roots[..n] {
        let t = (s + shift) / len;
        if t > t_min && t < t_max {
            f(t);
        }
    }
}

/// Outward normal at `p`.
pub fn normal(major: f64, p: DVec3) -> DVec3 {
    let q = DVec3::new(p.x, 0.0, p.z);
    let centre = q.normalize_or(DVec3::X) * major;
    p - centre
}

/// Strictly inside the tube.
pub fn inside(major: f64, minor: f64, p: DVec3) -> bool {
    let q = (p.x * p.x + p.z * p.z).sqrt() - major;
    q * q + p.y * p.y < minor * minor
}

/// Object-space bounds.
pub fn bounds(major: f64, minor: f64) -> Aabb {
    let r = major + minor;
    Aabb::new(DVec3::new(-r, -minor, -r), DVec3::new(r, minor, r))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(ray: &Ray) -> Vec<f64> {
        let mut v = Vec::new();
        hits(2.0, 0.5, ray, 0.0, f64::INFINITY, &mut |t| v.push(t));
        v
    }

    #[test]
    fn ray_through_the_ring_along_x() {
        // Along the x axis from far away: crosses at |x| = 1.5 and 2.5.
        let h = all(&Ray::new(DVec3::new(-100.0, 0.0, 0.0), DVec3::X));
        let expect = [97.5, 98.5, 101.5, 102.5];
        assert_eq!(h.len(), 4, "{h:?}");
        for (a, b) in h.iter().zip(expect) {
            assert!((a - b).abs() < 1e-9, "{h:?}");
        }
    }

    #[test]
    fn ray_down_through_the_tube() {
        let h = all(&Ray::new(
            DVec3::new(0.0, 10.0, 2.0),
            DVec3::new(0.0, -3.0, 0.0),
        ));
        assert_eq!(h.len(), 2);
        assert!((h[0] - 9.5 / 3.0).abs() < 1e-12 && (h[1] - 10.5 / 3.0).abs() < 1e-12);
        // Through the hole: no hit.
        assert!(all(&Ray::new(DVec3::new(0.0, 10.0, 0.0), -DVec3::Y)).is_empty());
        assert!(inside(2.0, 0.5, DVec3::new(0.0, 0.1, 2.2)));
        assert!(!inside(2.0, 0.5, DVec3::ZERO));
        let n = normal(2.0, DVec3::new(0.0, 0.5, 2.0)).normalize();
        assert!((n - DVec3::Y).length() < 1e-12);
    }

    #[test]
    fn grazing_and_random_rays_land_on_the_surface() {
        let mut seed = 12345u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        for _ in 0..2000 {
            let o = DVec3::new(rnd(), rnd(), rnd()) * 8.0;
            let target = DVec3::new(rnd() * 2.5, rnd() * 0.5, rnd() * 2.5);
            let ray = Ray::new(o, target - o);
            for t in all(&ray) {
                let p = ray.at(t);
                let q = (p.x * p.x + p.z * p.z).sqrt() - 2.0;
                let dist = (q * q + p.y * p.y).sqrt() - 0.5;
                assert!(dist.abs() < 1e-7, "off surface by {dist} at {p}");
            }
        }
    }
}
