//! Rays and the epsilon policy for secondary rays.

use glam::{DMat4, DVec3};

/// A ray `origin + t * dir`; `dir` need not be unit length (object-space rays are
/// not), and distances along a transformed ray equal those along the original.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Start point.
    pub origin: DVec3,
    /// Direction.
    pub dir: DVec3,
}

impl Ray {
    /// A ray from its parts.
    pub fn new(origin: DVec3, dir: DVec3) -> Ray {
        Ray { origin, dir }
    }

    /// The point at distance parameter `t`.
    #[inline]
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + self.dir * t
    }

    /// The ray mapped through an affine matrix.
    #[inline]
    pub fn transformed(&self, m: &DMat4) -> Ray {
        Ray {
            origin: m.transform_point3(self.origin),
            dir: m.transform_vector3(self.dir),
        }
    }

    /// A secondary ray leaving surface point `p` (geometric normal `n`, either side)
    /// in direction `dir`, together with the minimum distance to accept hits at.
    ///
    /// Rounding leaves `p` up to a few ulps off the surface, so a ray started there
    /// could hit its own surface again (grazing shadow rays on spheres are the worst
    /// case). The origin is pushed off the surface by [`surface_offset`] along the
    /// normal, on the side `dir` leaves towards, and hits closer than that same
    /// offset are ignored.
    pub fn secondary(p: DVec3, n: DVec3, dir: DVec3) -> (Ray, f64) {
        let eps = surface_offset(p);
        let side = if n.dot(dir) >= 0.0 { n } else { -n };
        (Ray::new(p + side * eps, dir), eps)
    }
}

/// The distance secondary rays start off a surface at `p`: relative to the size of
/// the coordinates so it stays above rounding error far from the origin.
#[inline]
pub fn surface_offset(p: DVec3) -> f64 {
    const RELATIVE: f64 = 1e-9;
    const ABSOLUTE: f64 = 1e-9;
    ABSOLUTE + RELATIVE * p.abs().max_element()
}
