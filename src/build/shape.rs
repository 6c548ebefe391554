//! Flattened primitives and the dispatch to each shape's intersection code.

use super::csg::Csg;
use super::mesh::MeshAccel;
use super::shapes::blob::Blob;
use super::shapes::flat::{self, Polygon};
use super::shapes::lathe::Lathe;
use super::shapes::poly::Poly;
use super::shapes::prism::Prism;
use super::shapes::quadric::Frustum;
use super::shapes::sor::Sor;
use super::shapes::superellipsoid::Superellipsoid;
use super::shapes::surface::Quadric;
use super::shapes::{solid, torus};
use super::{Aabb, Ray};
use crate::scene::{Interior, ObjectFlags, Texture, Transform};
use glam::{DMat4, DVec2, DVec3};
use std::sync::Arc;

/// A smooth triangle in world space.
#[derive(Clone, Debug, PartialEq)]
pub struct SmoothTriangle {
    /// First vertex.
    pub a: DVec3,
    /// `b - a`.
    pub e1: DVec3,
    /// `c - a`.
    pub e2: DVec3,
    /// World-space vertex normals.
    pub normals: [DVec3; 3],
}

/// The geometry of one primitive. Most shapes are kept in object space (the
/// primitive's transform places them); triangles are baked into world space
/// (affine maps keep them triangles); a CSG carries world transforms per leaf.
#[derive(Clone, Debug)]
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
    /// A smooth triangle in world space.
    SmoothTriangle(Box<SmoothTriangle>),
    /// A cylinder or cone.
    Frustum(Frustum),
    /// A torus around the y axis.
    Torus {
        /// Ring radius.
        major: f64,
        /// Tube radius.
        minor: f64,
    },
    /// A `quadric` surface (unbounded).
    Quadric(Quadric),
    /// A `poly`, `cubic` or `quartic` surface (unbounded).
    Poly(Arc<Poly>),
    /// A disc (annulus).
    Disc {
        /// Centre.
        center: DVec3,
        /// Unit normal.
        normal: DVec3,
        /// Outer radius squared.
        r2: f64,
        /// Hole radius squared.
        hole2: f64,
    },
    /// A polygon.
    Polygon(Arc<Polygon>),
    /// A convex polyhedron: outward face planes `(n, d)`.
    Polyhedron(Arc<[(DVec3, f64)]>),
    /// A `prism`.
    Prism(Arc<Prism>),
    /// A `lathe`.
    Lathe(Arc<Lathe>),
    /// A `sor`.
    Sor(Arc<Sor>),
    /// An instance of a shared mesh.
    Mesh(Arc<MeshAccel>),
    /// `merge`, `intersection`, `difference` or a clipped object.
    Csg(Arc<Csg>),
    /// A `blob`.
    Blob(Arc<Blob>),
    /// A `superellipsoid`.
    Superellipsoid(Superellipsoid),
    /// An `isosurface`.
    Isosurface(Arc<super::shapes::isosurface::Isosurface>),
    /// A `julia_fractal`.
    Julia(Arc<super::shapes::julia::Julia>),
    /// A `sphere_sweep`.
    SphereSweep(Arc<super::shapes::sweep::SphereSweep>),
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
    /// For a CSG primitive, the index of the leaf hit; else 0.
    pub leaf: u32,
    /// Which part of the shape: the triangle of a mesh, the face of a polyhedron,
    /// side (0) or end cap (1 base, 2 cap) of a cylinder or cone, bottom (0) or top
    /// (1) cap or wall segment (2 + index) of a prism or sor, the segment of a
    /// lathe; else 0.
    pub sub: u32,
}

/// A hit in a shape's own terms: distance, CSG leaf, part.
pub type ShapeHit = (f64, u32, u32);

impl Primitive {
    /// The nearest hit in `(t_min, t_max)` of `ray` (world space).
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<ShapeHit> {
        match &self.transform {
            None => self.shape.intersect(ray, t_min, t_max),
            Some(tr) => self
                .shape
                .intersect(&ray.transformed(&tr.inverse), t_min, t_max),
        }
    }

    /// Whether world point `p` is strictly inside this primitive (POV-Ray's rules:
    /// planes are half-spaces; open cylinders and cones, triangles, discs,
    /// polygons and meshes without `inside_vector` are never inside; `inverse`
    /// swaps inside and outside).
    pub fn inside(&self, p: DVec3) -> bool {
        let local = match &self.transform {
            None => p,
            Some(tr) => tr.inverse.transform_point3(p),
        };
        self.shape.inside(local) != self.flags.inverse
    }

    /// The unit world-space geometric normal at world point `p` of part `sub`
    /// (outward for closed shapes, `normal` for planes, `e1 × e2` for triangles;
    /// not flipped to face any ray). Not for CSG primitives (see
    /// [`super::World::surface`]).
    pub fn normal(&self, p: DVec3) -> DVec3 {
        self.normal_of(p, 0)
    }

    fn normal_of(&self, p: DVec3, sub: u32) -> DVec3 {
        match &self.transform {
            None => self.shape.normal(p, sub),
            Some(tr) => tr.normal(self.shape.normal(tr.inverse.transform_point3(p), sub)),
        }
        .normalize()
    }

    /// World-space bounds of this primitive, `None` when unbounded.
    pub fn compute_bounds(shape: &PrimShape, transform: Option<&Transform>) -> Option<Aabb> {
        let local = shape.local_bounds()?;
        Some(match transform {
            None => local,
            Some(tr) => Aabb::from_points(local.corners().map(|c| tr.point(c))),
        })
    }
}

impl PrimShape {
    /// Nearest hit in `(t_min, t_max)` of `ray` (in this shape's space).
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<ShapeHit> {
        let accept = |t: f64| (t > t_min && t < t_max).then_some((t, 0, 0));
        match self {
            PrimShape::Sphere { center, radius } => {
                let (t0, t1) = sphere_roots(*center, *radius, ray)?;
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
                let (near, far) = box_span(*min, *max, ray)?;
                accept(near).or_else(|| accept(far))
            }
            PrimShape::Triangle { a, e1, e2 } => accept(flat::triangle(*a, *e1, *e2, ray)?.0),
            PrimShape::SmoothTriangle(s) => accept(flat::triangle(s.a, s.e1, s.e2, ray)?.0),
            PrimShape::Disc {
                center,
                normal,
                r2,
                hole2,
            } => accept(flat::disc(*center, *normal, *r2, *hole2, ray)?),
            PrimShape::Polygon(p) => accept(p.hit(ray)?),
            PrimShape::Polyhedron(planes) => {
                let ((t0, i0), (t1, i1)) = solid::slab(planes, ray)?;
                let ok = |t: f64| t > t_min && t < t_max;
                if ok(t0) {
                    Some((t0, 0, i0))
                } else if ok(t1) {
                    Some((t1, 0, i1))
                } else {
                    None
                }
            }
            PrimShape::Quadric(q) => q.nearest(ray, t_min, t_max).map(|t| (t, 0, 0)),
            PrimShape::Poly(q) => q.nearest(ray, t_min, t_max).map(|t| (t, 0, 0)),
            PrimShape::Mesh(m) => m.intersect(ray, t_min, t_max).map(|(t, i)| (t, 0, i)),
            PrimShape::Prism(p) => p.nearest(ray, t_min, t_max).map(|(t, sub)| (t, 0, sub)),
            PrimShape::Lathe(l) => l.nearest(ray, t_min, t_max).map(|(t, sub)| (t, 0, sub)),
            PrimShape::Sor(s) => s.nearest(ray, t_min, t_max).map(|(t, sub)| (t, 0, sub)),
            PrimShape::Csg(c) => c.intersect(ray, t_min, t_max),
            PrimShape::Blob(b) => b.nearest(ray, t_min, t_max).map(|t| (t, 0, 0)),
            PrimShape::Superellipsoid(s) => s.nearest(ray, t_min, t_max).map(|t| (t, 0, 0)),
            PrimShape::Isosurface(i) => i.nearest(ray, t_min, t_max).map(|(t, sub)| (t, 0, sub)),
            PrimShape::Julia(j) => j.nearest(ray, t_min, t_max).map(|t| (t, 0, 0)),
            PrimShape::SphereSweep(s) => s.nearest(ray, t_min, t_max).map(|t| (t, 0, 0)),
            PrimShape::Frustum(_) | PrimShape::Torus { .. } => {
                let mut best: Option<ShapeHit> = None;
                self.hits(ray, t_min, t_max, &mut |t, sub| {
                    if best.is_none_or(|b| t < b.0) {
                        best = Some((t, 0, sub));
                    }
                });
                best
            }
        }
    }

    /// Every crossing in `(t_min, t_max)` with its part id, unordered (for CSG).
    /// A CSG shape reports its nearest hit only.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64, u32)) {
        let mut put = |t: f64, sub: u32| {
            if t > t_min && t < t_max {
                f(t, sub)
            }
        };
        match self {
            PrimShape::Sphere { center, radius } => {
                if let Some((t0, t1)) = sphere_roots(*center, *radius, ray) {
                    put(t0, 0);
                    put(t1, 0);
                }
            }
            PrimShape::Box { min, max } => {
                if let Some((t0, t1)) = box_span(*min, *max, ray) {
                    put(t0, 0);
                    put(t1, 0);
                }
            }
            PrimShape::Polyhedron(planes) => {
                if let Some(((t0, i0), (t1, i1))) = solid::slab(planes, ray) {
                    put(t0, i0);
                    put(t1, i1);
                }
            }
            PrimShape::Frustum(fr) => fr.hits(ray, t_min, t_max, f),
            PrimShape::Torus { major, minor } => {
                torus::hits(*major, *minor, ray, t_min, t_max, &mut |t| f(t, 0))
            }
            PrimShape::Mesh(m) => m.hits(ray, t_min, t_max, f),
            PrimShape::Prism(p) => p.hits(ray, t_min, t_max, f),
            PrimShape::Lathe(l) => l.hits(ray, t_min, t_max, f),
            PrimShape::Sor(s) => s.hits(ray, t_min, t_max, f),
            PrimShape::Quadric(q) => q.hits(ray, t_min, t_max, &mut |t| f(t, 0)),
            PrimShape::Poly(q) => q.hits(ray, t_min, t_max, &mut |t| f(t, 0)),
            PrimShape::Blob(b) => b.hits(ray, t_min, t_max, &mut |t| {
                f(t, 0);
                true
            }),
            PrimShape::Superellipsoid(s) => s.hits(ray, t_min, t_max, &mut |t| {
                f(t, 0);
                true
            }),
            PrimShape::Isosurface(i) => i.hits(ray, t_min, t_max, false, f),
            PrimShape::Julia(j) => j.hits(ray, t_min, t_max, &mut |t| {
                f(t, 0);
                true
            }),
            PrimShape::SphereSweep(s) => s.hits(ray, t_min, t_max, &mut |t| {
                f(t, 0);
                true
            }),
            _ => {
                if let Some((t, _, sub)) = self.intersect(ray, t_min, t_max) {
                    f(t, sub)
                }
            }
        }
    }

    /// Whether the side the normal points to comes from how the scene wrote the
    /// surface (the order of a triangle's corners, a disc's normal) rather than
    /// from an inside: triangles, meshes, polygons and discs. Rays then tell
    /// entering from leaving by the interiors they are in, as POV-Ray does for
    /// every object (measured: a glass mesh cube renders the same wound either
    /// way round).
    pub fn sided_by_winding(&self) -> bool {
        matches!(
            self,
            PrimShape::Triangle { .. }
                | PrimShape::SmoothTriangle(_)
                | PrimShape::Mesh(_)
                | PrimShape::Polygon(_)
                | PrimShape::Disc { .. }
        )
    }

    /// Unnormalised outward geometric normal at `p` on part `sub` (this shape's space).
    pub fn normal(&self, p: DVec3, sub: u32) -> DVec3 {
        match self {
            PrimShape::Sphere { center, .. } => p - *center,
            PrimShape::Plane { normal, .. } => *normal,
            PrimShape::Box { min, max } => box_normal(*min, *max, p),
            PrimShape::Triangle { e1, e2, .. } => e1.cross(*e2),
            PrimShape::SmoothTriangle(s) => s.e1.cross(s.e2),
            PrimShape::Frustum(f) => f.normal(p, sub),
            PrimShape::Torus { major, .. } => torus::normal(*major, p),
            PrimShape::Disc { normal, .. } => *normal,
            PrimShape::Quadric(q) => q.normal(p),
            PrimShape::Poly(q) => q.normal(p),
            PrimShape::Polygon(pg) => pg.normal,
            PrimShape::Polyhedron(planes) => planes.get(sub as usize).map_or(DVec3::Y, |pl| pl.0),
            PrimShape::Mesh(m) => m.normal(sub),
            PrimShape::Prism(pr) => pr.normal(p, sub),
            PrimShape::Lathe(l) => l.normal(p, sub),
            PrimShape::Sor(s) => s.normal(p, sub),
            PrimShape::Csg(_) => DVec3::Y,
            PrimShape::Blob(b) => b.normal(p),
            PrimShape::Superellipsoid(s) => s.normal(p),
            PrimShape::Isosurface(i) => i.normal(p, sub),
            PrimShape::Julia(j) => j.normal(p),
            PrimShape::SphereSweep(s) => s.normal(p),
        }
    }

    /// The interpolated normal of smooth triangles and meshes with normals
    /// (unnormalised, this shape's space); `None` where it is the geometric one.
    pub fn shading_normal(&self, p: DVec3, sub: u32) -> Option<DVec3> {
        match self {
            PrimShape::SmoothTriangle(s) => {
                let (u, v) = flat::barycentric(s.a, s.e1, s.e2, p);
                let n = s.normals[0] * (1.0 - u - v) + s.normals[1] * u + s.normals[2] * v;
                (n.length_squared() > 0.0).then_some(n)
            }
            PrimShape::Mesh(m) => m.shading_normal(sub, p),
            _ => None,
        }
    }

    /// The shape's uv coordinates at `p` where it defines them, POV-Ray's
    /// (measured against its `uv_mapping`): spheres (u = longitude
    /// `atan2(z, x) / 2π` in [0, 1), v = latitude from 0 at the bottom to 1 at the
    /// top), boxes (a net, see [`box_uv`]), tori, lathes, sors and meshes with
    /// `uv_vectors`.
    pub fn uv(&self, p: DVec3, sub: u32) -> Option<DVec2> {
        match self {
            PrimShape::Sphere { center, .. } => {
                let d = (p - *center).normalize_or_zero();
                let u = (d.z.atan2(d.x) / std::f64::consts::TAU).rem_euclid(1.0);
                let v = d.y.clamp(-1.0, 1.0).asin() / std::f64::consts::PI + 0.5;
                Some(DVec2::new(u, v))
            }
            PrimShape::Mesh(m) => m.uv(sub, p),
            PrimShape::Box { min, max } => Some(box_uv(*min, *max, p)),
            PrimShape::Lathe(l) => Some(l.uv(p, sub)),
            PrimShape::Sor(s) => Some(s.uv(p, sub)),
            PrimShape::Torus { major, .. } => {
                let tau = std::f64::consts::TAU;
                // u runs once around the ring, v once around the tube; both
                // measured pixel-exact against POV-Ray's `uv_mapping`.
                let u = (-p.z).atan2(p.x) / tau + 0.5;
                let rho = (p.x * p.x + p.z * p.z).sqrt();
                let v = p.y.atan2(rho - major) / tau + 0.5;
                Some(DVec2::new(u.rem_euclid(1.0), v.rem_euclid(1.0)))
            }
            _ => None,
        }
    }

    /// Whether `p` (this shape's space) is strictly inside, before `inverse`.
    pub fn inside(&self, p: DVec3) -> bool {
        match self {
            PrimShape::Sphere { center, radius } => {
                (p - *center).length_squared() < radius * radius
            }
            PrimShape::Plane { normal, distance } => normal.dot(p) < *distance,
            PrimShape::Box { min, max } => p.cmpgt(*min).all() && p.cmplt(*max).all(),
            PrimShape::Frustum(f) => f.inside(p),
            PrimShape::Torus { major, minor } => torus::inside(*major, *minor, p),
            PrimShape::Polyhedron(planes) => solid::inside(planes, p),
            PrimShape::Quadric(q) => q.inside(p),
            PrimShape::Poly(q) => q.inside(p),
            PrimShape::Mesh(m) => m.inside(p),
            PrimShape::Prism(pr) => pr.inside(p),
            PrimShape::Lathe(l) => l.inside(p),
            PrimShape::Sor(s) => s.inside(p),
            PrimShape::Csg(c) => c.inside(p),
            PrimShape::Blob(b) => b.inside(p),
            PrimShape::Superellipsoid(s) => s.inside(p),
            PrimShape::Isosurface(i) => i.inside(p),
            PrimShape::Julia(j) => j.inside(p),
            PrimShape::SphereSweep(s) => s.inside(p),
            PrimShape::Triangle { .. }
            | PrimShape::SmoothTriangle(_)
            | PrimShape::Disc { .. }
            | PrimShape::Polygon(_) => false,
        }
    }

    /// Bounds in this shape's space; `None` when unbounded.
    pub fn local_bounds(&self) -> Option<Aabb> {
        Some(match self {
            PrimShape::Plane { .. } | PrimShape::Quadric(_) | PrimShape::Poly(_) => return None,
            PrimShape::Sphere { center, radius } => Aabb::new(
                *center - DVec3::splat(*radius),
                *center + DVec3::splat(*radius),
            ),
            PrimShape::Box { min, max } => Aabb::new(*min, *max),
            PrimShape::Triangle { a, e1, e2 } => Aabb::from_points([*a, *a + *e1, *a + *e2]),
            PrimShape::SmoothTriangle(s) => Aabb::from_points([s.a, s.a + s.e1, s.a + s.e2]),
            PrimShape::Frustum(f) => f.bounds(),
            PrimShape::Torus { major, minor } => torus::bounds(*major, *minor),
            PrimShape::Disc {
                center, normal, r2, ..
            } => {
                let e = (DVec3::ONE - *normal * *normal).max(DVec3::ZERO);
                let ext = DVec3::new(e.x.sqrt(), e.y.sqrt(), e.z.sqrt()) * r2.sqrt();
                Aabb::new(*center - ext, *center + ext)
            }
            PrimShape::Polygon(p) => {
                let pts = p.edges.iter().map(|e| p.origin + p.u * e.0.x + p.v * e.0.y);
                Aabb::from_points(pts)
            }
            PrimShape::Polyhedron(planes) => polyhedron_bounds(planes)?,
            PrimShape::Mesh(m) => m.bounds(),
            PrimShape::Prism(p) => p.bounds(),
            PrimShape::Lathe(l) => l.bounds(),
            PrimShape::Sor(s) => s.bounds(),
            PrimShape::Csg(c) => return c.bounds(),
            PrimShape::Blob(b) => return b.bounds(),
            PrimShape::Superellipsoid(s) => s.bounds(),
            PrimShape::Isosurface(i) => {
                let (lo, hi) = i.container.bounds();
                Aabb::new(lo, hi)
            }
            PrimShape::Julia(j) => {
                let (lo, hi) = j.bounds();
                Aabb::new(lo, hi)
            }
            PrimShape::SphereSweep(s) => {
                let (lo, hi) = s.bounds();
                Aabb::new(lo, hi)
            }
        })
    }
}

/// The two roots of a ray with a sphere, ascending.
#[inline]
pub(crate) fn sphere_roots(center: DVec3, radius: f64, ray: &Ray) -> Option<(f64, f64)> {
    let oc = ray.origin - center;
    let a = ray.dir.length_squared();
    let b = oc.dot(ray.dir);
    // Discriminant in the form that loses no precision for distant origins:
    // r² - |oc - (b/a) d|², scaled by a.
    let perp = oc - ray.dir * (b / a);
    let disc = radius * radius - perp.length_squared();
    if disc < 0.0 {
        return None;
    }
    let root = (a * disc).sqrt();
    // Stable pair of roots: q = -(b + sign(b) root).
    let q = -(b + root.copysign(b));
    let (t0, t1) = (
        q / a,
        if q != 0.0 {
            (oc.length_squared() - radius * radius) / q
        } else {
            0.0
        },
    );
    Some(if t0 > t1 { (t1, t0) } else { (t0, t1) })
}

/// Entry and exit distances of a ray through a box.
#[inline]
pub(crate) fn box_span(min: DVec3, max: DVec3, ray: &Ray) -> Option<(f64, f64)> {
    let inv = ray.dir.recip();
    let t0 = (min - ray.origin) * inv;
    let t1 = (max - ray.origin) * inv;
    let near = t0.min(t1).max_element();
    let far = t0.max(t1).min_element();
    (near <= far).then_some((near, far))
}

/// Bounds of a convex polyhedron: the box of the vertices where three face
/// planes meet inside all the others; `None` when that is not closed.
fn polyhedron_bounds(planes: &[(DVec3, f64)]) -> Option<Aabb> {
    let mut b = Aabb::EMPTY;
    let n = planes.len();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let (a, c, e) = (planes[i], planes[j], planes[k]);
                let det = a.0.dot(c.0.cross(e.0));
                if det.abs() < 1e-12 {
                    continue;
                }
                let p = (c.0.cross(e.0) * a.1 + e.0.cross(a.0) * c.1 + a.0.cross(c.0) * e.1) / det;
                let scale = 1e-9 * (1.0 + p.abs().max_element());
                if planes.iter().all(|&(m, d)| m.dot(p) <= d + scale) {
                    b = b.grow(p);
                }
            }
        }
    }
    // Unbounded if some direction escapes: test the box against every plane set.
    if b.is_empty() {
        return None;
    }
    let pad = 1e-9 * (1.0 + b.max.abs().max(b.min.abs()).max_element());
    Some(Aabb::new(
        b.min - DVec3::splat(pad),
        b.max + DVec3::splat(pad),
    ))
}

/// Normal of the box face nearest to `p`, measured relative to the box size.
pub(crate) fn box_normal(min: DVec3, max: DVec3, p: DVec3) -> DVec3 {
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

/// POV-Ray's uv net of a box (measured on its renders): the four sides run
/// around u in quarters (−x, +z, +x, −z) over the middle third of v; the top
/// takes v's upper third and the bottom its lower third, both in the +z quarter.
/// Coordinates are fractions of the box's size, so the net stretches with it.
fn box_uv(min: DVec3, max: DVec3, p: DVec3) -> DVec2 {
    let size = (max - min).max(DVec3::splat(f64::MIN_POSITIVE));
    let f = ((p - min) / size).clamp(DVec3::ZERO, DVec3::ONE);
    let n = box_normal(min, max, p);
    let (u, v) = if n.x < 0.0 {
        (f.z / 4.0, f.y)
    } else if n.z > 0.0 {
        (0.25 + f.x / 4.0, f.y)
    } else if n.x > 0.0 {
        (0.5 + (1.0 - f.z) / 4.0, f.y)
    } else if n.z < 0.0 {
        (0.75 + (1.0 - f.x) / 4.0, f.y)
    } else if n.y > 0.0 {
        return DVec2::new(0.25 + f.x / 4.0, (2.0 + (1.0 - f.z)) / 3.0);
    } else {
        return DVec2::new(0.25 + f.x / 4.0, f.z / 3.0);
    };
    DVec2::new(u, (1.0 + v) / 3.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_uv_matches_povray_samples() {
        // (point, u, v) read from orthographic POV-Ray 3.7 renders of each face of
        // `box { -1, 1 uv_mapping pigment { gradient x / y } }`.
        let b = PrimShape::Box {
            min: DVec3::splat(-1.0),
            max: DVec3::ONE,
        };
        for (p, u, v) in [
            (DVec3::new(-0.85, 0.85, -1.0), 0.98, 0.64),
            (DVec3::new(0.85, -0.85, -1.0), 0.77, 0.36),
            (DVec3::new(0.85, 0.85, 1.0), 0.48, 0.64),
            (DVec3::new(-1.0, 0.85, 0.85), 0.23, 0.64),
            (DVec3::new(1.0, -0.85, -0.85), 0.73, 0.36),
            (DVec3::new(0.85, 1.0, 0.85), 0.48, 0.69),
            (DVec3::new(-0.85, -1.0, 0.85), 0.27, 0.31),
        ] {
            let uv = b.uv(p, 0).unwrap();
            assert!(
                (uv.x - u).abs() < 0.01 && (uv.y - v).abs() < 0.01,
                "{p}: {uv}"
            );
        }
    }

    #[test]
    fn sphere_uv_matches_povray_samples() {
        // (point, u, v) read from POV-Ray 3.7 renders of `uv_mapping gradient x / y`.
        let s = PrimShape::Sphere {
            center: DVec3::ONE,
            radius: 2.0,
        };
        for (p, u, v) in [
            (DVec3::new(0.0, 0.0, -1.0), 0.749, 0.502),
            (DVec3::new(0.871, 0.0, -0.491), 0.9216, 0.502),
            (DVec3::new(-0.871, 0.0, -0.491), 0.5804, 0.502),
            (DVec3::new(0.0, 0.653, -0.757), 0.749, 0.7294),
            (DVec3::new(0.436, -0.436, -0.788), 0.8314, 0.3569),
        ] {
            let uv = s.uv(DVec3::ONE + p * 2.0, 0).unwrap();
            assert!(
                (uv.x - u).abs() < 0.006 && (uv.y - v).abs() < 0.006,
                "{p}: {uv}"
            );
        }
    }
}
