//! Flat shapes, none of them solid: triangles, `disc`, `polygon`.

use crate::build::Ray;
use glam::{DVec2, DVec3};

/// Möller–Trumbore: `(t, u, v)` where `ray` meets triangle `a, a+e1, a+e2`
/// (`u`, `v` are the weights of the second and third corners).
#[inline]
pub fn triangle(a: DVec3, e1: DVec3, e2: DVec3, ray: &Ray) -> Option<(f64, f64, f64)> {
    let p = ray.dir.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv_det = 1.0 / det;
    let s = ray.origin - a;
    let u = s.dot(p) * inv_det;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = ray.dir.dot(q) * inv_det;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    Some((e2.dot(q) * inv_det, u, v))
}

/// The weights `(u, v)` of the second and third corners for a point `p` in the
/// plane of triangle `a, a+e1, a+e2`.
pub fn barycentric(a: DVec3, e1: DVec3, e2: DVec3, p: DVec3) -> (f64, f64) {
    let w = p - a;
    let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let (w1, w2) = (w.dot(e1), w.dot(e2));
    let det = d11 * d22 - d12 * d12;
    if det == 0.0 {
        return (0.0, 0.0);
    }
    ((d22 * w1 - d12 * w2) / det, (d11 * w2 - d12 * w1) / det)
}

/// `disc`: the hit distance of `ray` with the annulus `hole² <= r² <= radius²`.
pub fn disc(center: DVec3, normal: DVec3, r2: f64, hole2: f64, ray: &Ray) -> Option<f64> {
    let denom = normal.dot(ray.dir);
    if denom == 0.0 {
        return None;
    }
    let t = normal.dot(center - ray.origin) / denom;
    let d2 = (ray.at(t) - center).length_squared();
    (d2 <= r2 && d2 >= hole2).then_some(t)
}

/// A `polygon` in its own plane: the edges of all sub-polygons in 2-D
/// coordinates `(p - origin)·u, (p - origin)·v`; filled by the even-odd rule.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    /// A point of the plane.
    pub origin: DVec3,
    /// In-plane axes (orthonormal).
    pub u: DVec3,
    /// Second in-plane axis.
    pub v: DVec3,
    /// Unit normal `u × v`.
    pub normal: DVec3,
    /// Edges `(from, to)` in plane coordinates.
    pub edges: Vec<(DVec2, DVec2)>,
}

impl Polygon {
    /// From POV-Ray's point list (each sub-polygon closes by repeating its first
    /// point; an unclosed last one is closed). `None` when the points span no plane.
    pub fn new(points: &[DVec3]) -> Option<Polygon> {
        let origin = *points.first()?;
        // Newell's normal is robust for any simple or self-touching outline.
        let mut n = DVec3::ZERO;
        for w in points.windows(2) {
            n += (w[0] - origin).cross(w[1] - origin);
        }
        if n.length_squared() == 0.0 {
            // All sub-polygons might cancel: take the first non-degenerate corner.
            n = points
                .windows(3)
                .map(|w| (w[1] - w[0]).cross(w[2] - w[0]))
                .find(|c| c.length_squared() > 0.0)?;
        }
        let normal = n.normalize();
        let u = normal.any_orthonormal_vector();
        let v = normal.cross(u);
        let to2 = |p: DVec3| DVec2::new((p - origin).dot(u), (p - origin).dot(v));
        let mut edges = Vec::new();
        let mut start = 0;
        let mut i = 1;
        while i < points.len() {
            edges.push((to2(points[i - 1]), to2(points[i])));
            if points[i] == points[start] {
                start = i + 1;
                i += 2;
            } else {
                i += 1;
            }
        }
        if start < points.len() && points[points.len() - 1] != points[start] {
            edges.push((to2(points[points.len() - 1]), to2(points[start])));
        }
        Some(Polygon {
            origin,
            u,
            v,
            normal,
            edges,
        })
    }

    /// Hit distance of `ray` with the filled polygon.
    pub fn hit(&self, ray: &Ray) -> Option<f64> {
        let denom = self.normal.dot(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = self.normal.dot(self.origin - ray.origin) / denom;
        let p = ray.at(t) - self.origin;
        let q = DVec2::new(p.dot(self.u), p.dot(self.v));
        let mut inside = false;
        for &(a, b) in &self.edges {
            if (a.y > q.y) != (b.y > q.y) {
                let x = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if q.x < x {
                    inside = !inside;
                }
            }
        }
        inside.then_some(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polygon_with_a_hole() {
        // An outer square with an inner square hole, as POV-Ray writes it.
        let sq = |r: f64| {
            vec![
                DVec3::new(-r, -r, 0.0),
                DVec3::new(r, -r, 0.0),
                DVec3::new(r, r, 0.0),
                DVec3::new(-r, r, 0.0),
                DVec3::new(-r, -r, 0.0),
            ]
        };
        let mut pts = sq(2.0);
        pts.extend(sq(1.0));
        let p = Polygon::new(&pts).unwrap();
        let at = |x: f64, y: f64| p.hit(&Ray::new(DVec3::new(x, y, -5.0), DVec3::Z));
        assert_eq!(at(1.5, 0.0), Some(5.0));
        assert_eq!(at(0.0, 0.0), None);
        assert_eq!(at(3.0, 0.0), None);
    }

    #[test]
    fn barycentric_inverts_the_hit() {
        let (a, e1, e2) = (DVec3::ZERO, DVec3::X * 2.0, DVec3::Y * 3.0);
        let (t, u, v) =
            triangle(a, e1, e2, &Ray::new(DVec3::new(0.5, 0.6, 1.0), -DVec3::Z)).unwrap();
        assert_eq!(t, 1.0);
        let (bu, bv) = barycentric(a, e1, e2, DVec3::new(0.5, 0.6, 0.0));
        assert!((bu - u).abs() < 1e-12 && (bv - v).abs() < 1e-12);
        assert!(disc(
            DVec3::ZERO,
            DVec3::Z,
            1.0,
            0.25,
            &Ray::new(DVec3::new(0.7, 0.0, 1.0), -DVec3::Z)
        )
        .is_some());
        assert!(disc(
            DVec3::ZERO,
            DVec3::Z,
            1.0,
            0.25,
            &Ray::new(DVec3::new(0.3, 0.0, 1.0), -DVec3::Z)
        )
        .is_none());
    }
}
