//! Flattened primitives and their ray intersections.

use super::{Aabb, Ray};
use crate::scene::{Interior, ObjectFlags, Texture, Transform};
use glam::{DMat4, DVec3};
use std::sync::Arc;

/// The geometry of one primitive. Spheres, planes and boxes are kept in object
/// space; triangles are baked into world space (affine maps keep them triangles).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PrimShape {
    /// A sphere.
    Sphere {
        /// Centre.
        center: DVec3,
        /// Radius.
        radius: f64,
    },
    /// The plane `p·normal = distance`, inside below.
    Plane {
        /// Unit normal.
        normal: DVec3,
        /// Offset along the normal.
        distance: f64,
    },
    /// An axis-aligned box.
    Box {
        /// Lowest corner.
        min: DVec3,
        /// Highest corner.
        max: DVec3,
    },
    /// A triangle in world space.
    Triangle {
        /// First vertex.
        a: DVec3,
        /// `b - a`.
        e1: DVec3,
        /// `c - a`.
        e2: DVec3,
    },
}

/// One leaf object after flattening: geometry, placement, resolved texture.
#[derive(Clone, Debug)]
pub struct Primitive {
    /// The geometry.
    pub shape: PrimShape,
    /// `world_from_object` with its inverse; `None` for the identity.
    pub transform: Option<Transform>,
    /// The texture in force (own, inherited, or POV-Ray's default).
    pub texture: Arc<Texture>,
    /// Maps world points into the texture's space (the space of the object that
    /// owns the texture); the pigment's own transform is applied after this.
    pub texture_from_world: Option<DMat4>,
    /// The interior in force (own or inherited); `None` is POV-Ray's default.
    pub interior: Option<Arc<Interior>>,
    /// Visibility and shadow flags (inherited flags are OR-ed in).
    pub flags: ObjectFlags,
    /// World-space bounds; `None` when unbounded (planes).
    pub bounds: Option<Aabb>,
}

/// The closest intersection found along a ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance parameter along the ray.
    pub t: f64,
    /// Index of the primitive in [`super::World::primitives`].
    pub prim: u32,
}

impl Primitive {
    /// The smallest `t` in `(t_min, t_max)` where `ray` (world space) meets the surface.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
        match &self.transform {
            None => self.shape.intersect(ray, t_min, t_max),
            Some(tr) => self
                .shape
                .intersect(&ray.transformed(&tr.inverse), t_min, t_max),
        }
    }

    /// The unit world-space geometric normal at world point `p` (outward for closed
    /// shapes, `normal` for planes, `e1 × e2` for triangles; not flipped to face
    /// any ray).
    pub fn normal(&self, p: DVec3) -> DVec3 {
        match &self.transform {
            None => self.shape.normal(p),
            Some(tr) => tr.normal(self.shape.normal(tr.inverse.transform_point3(p))),
        }
        .normalize()
    }

    /// World-space bounds of this primitive, `None` when unbounded.
    pub fn compute_bounds(shape: &PrimShape, transform: Option<&Transform>) -> Option<Aabb> {
        let local = match *shape {
            PrimShape::Plane { .. } => return None,
            PrimShape::Sphere { center, radius } => {
                Aabb::new(center - DVec3::splat(radius), center + DVec3::splat(radius))
            }
            PrimShape::Box { min, max } => Aabb::new(min, max),
            PrimShape::Triangle { a, e1, e2 } => Aabb::from_points([a, a + e1, a + e2]),
        };
        Some(match transform {
            None => local,
            Some(tr) => Aabb::from_points(local.corners().map(|c| tr.point(c))),
        })
    }
}

impl PrimShape {
    /// Smallest `t` in `(t_min, t_max)` where `ray` (in this shape's space) hits it.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
        let accept = |t: f64| (t > t_min && t < t_max).then_some(t);
        match *self {
            PrimShape::Sphere { center, radius } => {
                let oc = ray.origin - center;
                let a = ray.dir.length_squared();
                let b = oc.dot(ray.dir);
                // Discriminant in the form that loses no precision for distant
                // origins: r² - |oc - (b/a) d|², scaled by a.
                let perp = oc - ray.dir * (b / a);
                let disc = radius * radius - perp.length_squared();
                if disc < 0.0 {
                    return None;
                }
                let root = (a * disc).sqrt();
                // Stable pair of roots: q = -(b + sign(b) root).
                let q = -(b + root.copysign(b));
                let (mut t0, mut t1) = (
                    q / a,
                    if q != 0.0 {
                        (oc.length_squared() - radius * radius) / q
                    } else {
                        0.0
                    },
                );
                if t0 > t1 {
                    std::mem::swap(&mut t0, &mut t1);
                }
                accept(t0).or_else(|| accept(t1))
            }
            PrimShape::Plane { normal, distance } => {
                let denom = normal.dot(ray.dir);
                if denom == 0.0 {
                    return None;
                }
                accept((distance - normal.dot(ray.origin)) / denom)
            }
            PrimShape::Box { min, max } => {
                let inv = ray.dir.recip();
                let t0 = (min - ray.origin) * inv;
                let t1 = (max - ray.origin) * inv;
                let near = t0.min(t1).max_element();
                let far = t0.max(t1).min_element();
                if near > far {
                    return None;
                }
                accept(near).or_else(|| accept(far))
            }
            PrimShape::Triangle { a, e1, e2 } => {
                // Möller–Trumbore.
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
                accept(e2.dot(q) * inv_det)
            }
        }
    }

    /// Unnormalised geometric normal at `p` (in this shape's space).
    pub fn normal(&self, p: DVec3) -> DVec3 {
        match *self {
            PrimShape::Sphere { center, .. } => p - center,
            PrimShape::Plane { normal, .. } => normal,
            PrimShape::Box { min, max } => box_normal(min, max, p),
            PrimShape::Triangle { e1, e2, .. } => e1.cross(e2),
        }
    }
}

/// Normal of the box face nearest to `p`, measured relative to the box size.
fn box_normal(min: DVec3, max: DVec3, p: DVec3) -> DVec3 {
    let size = (max - min).max(DVec3::splat(f64::MIN_POSITIVE));
    let mut best = (f64::INFINITY, DVec3::X);
    for axis in 0..3 {
        let e = DVec3::AXES[axis];
        let lo = (p[axis] - min[axis]).abs() / size[axis];
        let hi = (p[axis] - max[axis]).abs() / size[axis];
        if lo < best.0 {
            best = (lo, -e);
        }
        if hi < best.0 {
            best = (hi, e);
        }
    }
    best.1
}
