//! Emitting surfaces (`finish { emission … }`) as lights: which primitives emit,
//! picking one in proportion to its power, and sampling a point on it uniformly by
//! area. Shapes without an area sampler here (planes, CSG, tori, …) still emit;
//! paths find them by BSDF sampling only.

use crate::build::mesh::MeshAccel;
use crate::build::{PrimShape, World};
use crate::render::sampler::turn;
use crate::scene::{Object, Texture};
use glam::{DMat3, DMat4, DVec3};
use rustc_hash::FxHashSet;
use std::f64::consts::PI;
use std::sync::Arc;

/// A point sampled on an emitter.
#[derive(Clone, Copy, Debug)]
pub struct EmitterPoint {
    /// World position.
    pub p: DVec3,
    /// Unit world normal there (either side).
    pub n: DVec3,
    /// Density per unit world area, including the choice of this emitter.
    pub pdf_area: f64,
    /// Emitted radiance there.
    pub radiance: DVec3,
}

/// Shapes with an area sampler, in the primitive's own space.
#[derive(Clone, Debug)]
enum Sampled {
    Sphere {
        center: DVec3,
        radius: f64,
    },
    Disc {
        center: DVec3,
        normal: DVec3,
        r2: f64,
        hole2: f64,
    },
    Box {
        min: DVec3,
        max: DVec3,
    },
    Triangle {
        a: DVec3,
        e1: DVec3,
        e2: DVec3,
        /// `e1 × e2` normalised (as [`triangle_point`] computes it).
        n: DVec3,
    },
    /// Triangles picked by their share of the area (cumulative areas).
    Mesh {
        mesh: Arc<MeshAccel>,
        cdf: Vec<f64>,
    },
}

/// One sampled emitter.
#[derive(Clone, Debug)]
struct Emitter {
    prim: u32,
    shape: Sampled,
    /// Area in the shape's own space.
    area: f64,
    /// World centre and radius of a sphere kept round by its transform: sampled
    /// by the solid angle it subtends instead of by area.
    ball: Option<(DVec3, f64)>,
    /// The radiance when it is the same all over (a solid pigment).
    radiance: Option<DVec3>,
}

/// Every emitter of a world, and the `looks_like` objects.
#[derive(Clone, Debug, Default)]
pub struct Emitters {
    list: Vec<Emitter>,
    /// Cumulative selection weights.
    cdf: Vec<f64>,
    /// Per primitive: index + 1 into `list`, 0 when not sampled.
    index: Vec<u32>,
    /// Textures of `looks_like` objects (by address).
    looks_like: FxHashSet<usize>,
}

/// The radiance `texture` emits at world point `p`: `emission × pigment × opacity`
/// of its top layer.
pub fn emitted(texture: &Texture, texture_from_world: Option<&DMat4>, p: DVec3) -> DVec3 {
    let e = texture.finish.emission;
    if e.max_element() <= 0.0 {
        return DVec3::ZERO;
    }
    let tp = texture_from_world.map_or(p, |m| m.transform_point3(p));
    let c = crate::pattern::evaluate(&texture.pigment, tp);
    let opacity = (1.0 - c.filter - c.transmit).clamp(0.0, 1.0);
    e * c.rgb.max(DVec3::ZERO) * opacity
}

fn collect_textures(o: &Object, out: &mut FxHashSet<usize>) {
    if let Some(t) = &o.texture {
        out.insert(Arc::as_ptr(t) as usize);
    }
    if let crate::scene::Shape::Union { children } | crate::scene::Shape::Csg { children, .. } =
        &o.shape
    {
        for c in children {
            collect_textures(c, out);
        }
    }
}

impl Emitters {
    /// Finds the emitters of `world`.
    pub fn new(world: &World) -> Emitters {
        let mut e = Emitters {
            index: vec![0; world.primitives.len()],
            ..Emitters::default()
        };
        for l in &world.lights {
            if let Some(o) = &l.looks_like {
                collect_textures(o, &mut e.looks_like);
            }
        }
        let mut total = 0.0;
        for (i, prim) in world.primitives.iter().enumerate() {
            let power = prim.texture.finish.emission.max_element();
            if power <= 0.0 || e.is_looks_like(&prim.texture) {
                continue;
            }
            let shape = match &prim.shape {
                PrimShape::Sphere { center, radius } if *radius > 0.0 => Sampled::Sphere {
                    center: *center,
                    radius: *radius,
                },
                PrimShape::Disc {
                    center,
                    normal,
                    r2,
                    hole2,
                } if r2 > hole2 => Sampled::Disc {
                    center: *center,
                    normal: normal.normalize(),
                    r2: *r2,
                    hole2: *hole2,
                },
                PrimShape::Box { min, max } => Sampled::Box {
                    min: *min,
                    max: *max,
                },
                PrimShape::Triangle { a, e1, e2 } => Sampled::Triangle {
                    a: *a,
                    e1: *e1,
                    e2: *e2,
                    n: e1.cross(*e2).normalize_or_zero(),
                },
                PrimShape::SmoothTriangle(t) => Sampled::Triangle {
                    a: t.a,
                    e1: t.e1,
                    e2: t.e2,
                    n: t.e1.cross(t.e2).normalize_or_zero(),
                },
                PrimShape::Mesh(m) => {
                    let mut acc = 0.0;
                    let cdf = (0..m.data.triangles.len())
                        .map(|k| {
                            let [a, b, c] = m.data.corners(k);
                            acc += 0.5 * (b - a).cross(c - a).length();
                            acc
                        })
                        .collect();
                    Sampled::Mesh {
                        mesh: m.clone(),
                        cdf,
                    }
                }
                _ => continue,
            };
            let area = shape_area(&shape);
            if !(area > 0.0 && area.is_finite()) {
                continue;
            }
            let scale = prim.transform.map_or(1.0, |t| {
                DMat3::from_mat4(t.matrix)
                    .determinant()
                    .abs()
                    .powf(2.0 / 3.0)
            });
            total += area * scale * power;
            let ball = match (&shape, &prim.transform) {
                (Sampled::Sphere { center, radius }, None) => Some((*center, *radius)),
                (Sampled::Sphere { center, radius }, Some(t)) => {
                    let m = DMat3::from_mat4(t.matrix);
                    let (a, b, c) = (m.x_axis, m.y_axis, m.z_axis);
                    let l = a.length();
                    let round = (b.length() - l).abs() < 1e-9 * l
                        && (c.length() - l).abs() < 1e-9 * l
                        && a.dot(b).abs() < 1e-9 * l * l
                        && b.dot(c).abs() < 1e-9 * l * l
                        && a.dot(c).abs() < 1e-9 * l * l;
                    round.then(|| (t.point(*center), radius * l))
                }
                _ => None,
            };
            let radiance = match prim.texture.pigment.pattern {
                crate::scene::Pattern::Solid(_) => Some(emitted(
                    &prim.texture,
                    prim.texture_from_world.as_ref(),
                    DVec3::ZERO,
                )),
                _ => None,
            };
            e.list.push(Emitter {
                prim: i as u32,
                shape,
                area,
                ball,
                radiance,
            });
            e.cdf.push(total);
            e.index[i] = e.list.len() as u32;
        }
        e
    }

    /// Whether `texture` belongs to a `looks_like` object (the visible stand-in of
    /// a light source, which the light itself illuminates with).
    pub fn is_looks_like(&self, texture: &Arc<Texture>) -> bool {
        !self.looks_like.is_empty() && self.looks_like.contains(&(Arc::as_ptr(texture) as usize))
    }

    /// Whether there is any emitter to sample.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// Probability of picking emitter `k`.
    fn pick_pdf(&self, k: usize) -> f64 {
        let total = *self.cdf.last().unwrap_or(&1.0);
        let lo = if k == 0 { 0.0 } else { self.cdf[k - 1] };
        (self.cdf[k] - lo) / total
    }

    /// A point on an emitter for lighting point `from`: `u` picks the emitter, `u2`
    /// the point.
    pub fn sample(
        &self,
        world: &World,
        from: DVec3,
        u: f64,
        u2: (f64, f64),
    ) -> Option<EmitterPoint> {
        let total = *self.cdf.last()?;
        let x = u * total;
        let k = self
            .cdf
            .partition_point(|c| *c <= x)
            .min(self.list.len() - 1);
        let e = &self.list[k];
        let prim = &world.primitives[e.prim as usize];
        if let Some(cone) = e.ball.and_then(|(c, r)| Cone::new(c, r, from)) {
            let (p, n) = cone.sample(u2);
            let radiance = e
                .radiance
                .unwrap_or_else(|| emitted(&prim.texture, prim.texture_from_world.as_ref(), p));
            return Some(EmitterPoint {
                p,
                n,
                pdf_area: self.pick_pdf(k) * cone.pdf_area(p, n, from),
                radiance,
            });
        }
        let (p_obj, n_obj) = sample_shape(&e.shape, u2);
        let (p, n, jac) = to_world(
            prim.transform.as_ref().map(|t| (&t.matrix, &t.inverse)),
            p_obj,
            n_obj,
        );
        let radiance = e
            .radiance
            .unwrap_or_else(|| emitted(&prim.texture, prim.texture_from_world.as_ref(), p));
        Some(EmitterPoint {
            p,
            n,
            pdf_area: self.pick_pdf(k) / (e.area * jac),
            radiance,
        })
    }

    /// The density (per unit world area, including the pick) with which
    /// [`Emitters::sample`] for lighting point `from` returns world point `p` on
    /// primitive `prim`; 0 when that primitive is not sampled. `sub` is the hit's
    /// part (the triangle of a mesh).
    pub fn pdf_area(&self, world: &World, prim: u32, sub: u32, p: DVec3, from: DVec3) -> f64 {
        let k = match self.index.get(prim as usize) {
            Some(&k) if k > 0 => k as usize - 1,
            _ => return 0.0,
        };
        let e = &self.list[k];
        if let Some(cone) = e.ball.and_then(|(c, r)| Cone::new(c, r, from)) {
            let n = (p - cone.centre).normalize_or_zero();
            return self.pick_pdf(k) * cone.pdf_area(p, n, from);
        }
        let pr = &world.primitives[prim as usize];
        let jac = match &pr.transform {
            None => 1.0,
            Some(t) => {
                let local = t.inverse.transform_point3(p);
                let n_obj = shape_normal(&e.shape, local, sub);
                jacobian(&t.matrix, &t.inverse, n_obj)
            }
        };
        self.pick_pdf(k) / (e.area * jac)
    }
}

/// The cone a sphere subtends from a point outside it, for sampling by solid angle.
#[derive(Clone, Copy, Debug)]
struct Cone {
    centre: DVec3,
    radius: f64,
    from: DVec3,
    /// Unit axis from `from` to the centre.
    axis: DVec3,
    dist: f64,
    /// `1 - cos θmax`, computed stably.
    one_minus_cos: f64,
}

impl Cone {
    /// `None` when `from` is inside (or on) the sphere.
    fn new(centre: DVec3, radius: f64, from: DVec3) -> Option<Cone> {
        let to = centre - from;
        let d2 = to.length_squared();
        if d2 <= radius * radius * (1.0 + 1e-6) {
            return None;
        }
        let dist = d2.sqrt();
        let sin2 = radius * radius / d2;
        let cos_max = (1.0 - sin2).max(0.0).sqrt();
        Some(Cone {
            centre,
            radius,
            from,
            axis: to / dist,
            dist,
            one_minus_cos: sin2 / (1.0 + cos_max),
        })
    }

    /// A point on the visible cap and its outward normal.
    fn sample(&self, (u, v): (f64, f64)) -> (DVec3, DVec3) {
        let cos_t = 1.0 - u * self.one_minus_cos;
        let sin_t = (1.0 - cos_t * cos_t).max(0.0).sqrt();
        let (c, s) = turn(v);
        let (t, b) = self.axis.any_orthonormal_pair();
        let w = sin_t * c * t + sin_t * s * b + cos_t * self.axis;
        let disc = self.radius * self.radius - self.dist * self.dist * sin_t * sin_t;
        let along = self.dist * cos_t - disc.max(0.0).sqrt();
        let p = self.from + along * w;
        (p, (p - self.centre) / self.radius)
    }

    /// Density per unit area at `p` (normal `n`) of [`Cone::sample`].
    fn pdf_area(&self, p: DVec3, n: DVec3, from: DVec3) -> f64 {
        let to = p - from;
        let d2 = to.length_squared();
        let cos = n.dot(to).abs() / d2.sqrt();
        cos / (2.0 * PI * self.one_minus_cos * d2)
    }
}

/// Area of a shape in its own space.
fn shape_area(s: &Sampled) -> f64 {
    match s {
        Sampled::Sphere { radius, .. } => 4.0 * PI * radius * radius,
        Sampled::Disc { r2, hole2, .. } => PI * (r2 - hole2),
        Sampled::Box { min, max } => {
            let d = *max - *min;
            2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
        }
        Sampled::Triangle { e1, e2, .. } => 0.5 * e1.cross(*e2).length(),
        Sampled::Mesh { cdf, .. } => *cdf.last().unwrap_or(&0.0),
    }
}

/// A uniform point on the shape and its unit normal, in the shape's space.
fn sample_shape(s: &Sampled, (u, v): (f64, f64)) -> (DVec3, DVec3) {
    match s {
        Sampled::Sphere { center, radius } => {
            let z = 1.0 - 2.0 * u;
            let r = (1.0 - z * z).max(0.0).sqrt();
            let (c, s) = turn(v);
            let d = DVec3::new(r * c, r * s, z);
            (*center + *radius * d, d)
        }
        Sampled::Disc {
            center,
            normal,
            r2,
            hole2,
        } => {
            let r = (hole2 + u * (r2 - hole2)).sqrt();
            let (c, s) = turn(v);
            let (t, b) = normal.any_orthonormal_pair();
            (*center + r * (c * t + s * b), *normal)
        }
        Sampled::Box { min, max } => {
            let d = *max - *min;
            let faces = [d.y * d.z, d.z * d.x, d.x * d.y];
            let half = faces[0] + faces[1] + faces[2];
            // Which face pair, then which of the two, then the point.
            let mut x = u * 2.0 * half;
            let side = x >= half;
            if side {
                x -= half;
            }
            let axis = if x < faces[0] {
                0
            } else if x < faces[0] + faces[1] {
                1
            } else {
                2
            };
            let lo: f64 = faces[..axis].iter().sum();
            let w = ((x - lo) / faces[axis].max(1e-300)).clamp(0.0, 1.0);
            let (a1, a2) = ((axis + 1) % 3, (axis + 2) % 3);
            let mut p = *min;
            p[axis] = if side { max[axis] } else { min[axis] };
            p[a1] = min[a1] + w * d[a1];
            p[a2] = min[a2] + v * d[a2];
            let mut n = DVec3::ZERO;
            n[axis] = if side { 1.0 } else { -1.0 };
            (p, n)
        }
        Sampled::Triangle { a, e1, e2, n } => (triangle_at(*a, *e1, *e2, u, v), *n),
        Sampled::Mesh { mesh, cdf } => {
            let total = *cdf.last().unwrap_or(&0.0);
            let x = u * total;
            let k = cdf.partition_point(|c| *c <= x).min(cdf.len() - 1);
            let lo = if k == 0 { 0.0 } else { cdf[k - 1] };
            let u = ((x - lo) / (cdf[k] - lo).max(1e-300)).clamp(0.0, 1.0);
            let [a, b, c] = mesh.data.corners(k);
            triangle_point(a, b - a, c - a, u, v)
        }
    }
}

/// A uniform point on a triangle (square-root warp) and its normal.
fn triangle_point(a: DVec3, e1: DVec3, e2: DVec3, u: f64, v: f64) -> (DVec3, DVec3) {
    (
        triangle_at(a, e1, e2, u, v),
        e1.cross(e2).normalize_or_zero(),
    )
}

/// A uniform point on a triangle (square-root warp).
fn triangle_at(a: DVec3, e1: DVec3, e2: DVec3, u: f64, v: f64) -> DVec3 {
    let su = u.sqrt();
    let (b1, b2) = (1.0 - su, v * su);
    a + b1 * e1 + b2 * e2
}

/// The shape's unit normal at `p` (in its space).
fn shape_normal(s: &Sampled, p: DVec3, sub: u32) -> DVec3 {
    match s {
        Sampled::Sphere { center, .. } => (p - *center).normalize_or_zero(),
        Sampled::Disc { normal, .. } => *normal,
        Sampled::Box { min, max } => {
            let c = (*min + *max) * 0.5;
            let h = (*max - *min) * 0.5;
            let q = (p - c) / h.max(DVec3::splat(1e-300));
            let a = q.abs();
            let mut n = DVec3::ZERO;
            let axis = if a.x >= a.y && a.x >= a.z {
                0
            } else if a.y >= a.z {
                1
            } else {
                2
            };
            n[axis] = q[axis].signum();
            n
        }
        Sampled::Triangle { e1, e2, .. } => e1.cross(*e2).normalize_or_zero(),
        Sampled::Mesh { mesh, .. } => {
            let k = (sub as usize).min(mesh.data.triangles.len().saturating_sub(1));
            let [a, b, c] = mesh.data.corners(k);
            (b - a).cross(c - a).normalize_or_zero()
        }
    }
}

/// `dA_world / dA_object` for a surface element with unit normal `n` under
/// `matrix` (whose inverse is `inverse`): `|det M| · |M⁻ᵀ n|`.
fn jacobian(matrix: &DMat4, inverse: &DMat4, n: DVec3) -> f64 {
    let m = DMat3::from_mat4(*matrix);
    let it = DMat3::from_mat4(*inverse).transpose();
    m.determinant().abs() * (it * n).length()
}

/// World point, world unit normal and area Jacobian of an object-space sample.
fn to_world(t: Option<(&DMat4, &DMat4)>, p: DVec3, n: DVec3) -> (DVec3, DVec3, f64) {
    match t {
        None => (p, n, 1.0),
        Some((m, inv)) => {
            let it = DMat3::from_mat4(*inv).transpose();
            let nw = it * n;
            (
                m.transform_point3(p),
                nw.normalize_or_zero(),
                DMat3::from_mat4(*m).determinant().abs() * nw.length(),
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_samples_lie_on_the_surface_and_cover_faces_by_area() {
        let s = Sampled::Box {
            min: DVec3::ZERO,
            max: DVec3::new(1.0, 2.0, 4.0),
        };
        let mut counts = [0u32; 3];
        let n = 64;
        for i in 0..n * n {
            let (u, v) = (
                (i % n) as f64 / n as f64 + 0.5 / n as f64,
                (i / n) as f64 / n as f64,
            );
            let (p, nrm) = sample_shape(&s, (u, v));
            let axis = nrm.abs().max_position();
            counts[axis] += 1;
            assert!(p[axis] == 0.0 || p[axis] == [1.0, 2.0, 4.0][axis]);
            let size = [1.0, 2.0, 4.0];
            let on_edge = (0..3).any(|k| k != axis && (p[k] == 0.0 || p[k] == size[k]));
            if !on_edge {
                assert_eq!(shape_normal(&s, p, 0), nrm);
            }
        }
        // Face areas: yz 8, zx 4, xy 2 → shares 8/14, 4/14, 2/14.
        let total = f64::from(counts.iter().sum::<u32>());
        for (c, want) in counts.iter().zip([8.0 / 14.0, 4.0 / 14.0, 2.0 / 14.0]) {
            assert!((f64::from(*c) / total - want).abs() < 0.02, "{counts:?}");
        }
    }

    #[test]
    fn cone_samples_lie_on_the_near_cap_with_a_uniform_solid_angle_density() {
        let c = Cone::new(DVec3::new(0.0, 3.0, 0.0), 1.0, DVec3::ZERO).unwrap();
        // Solid angle of a unit sphere seen from distance 3: 2π(1 - cos θmax).
        let omega = 2.0 * PI * (1.0 - (1.0f64 - 1.0 / 9.0).sqrt());
        let n = 32;
        for i in 0..n * n {
            let (u, v) = (
                (f64::from(i % n) + 0.5) / f64::from(n),
                (f64::from(i / n) + 0.5) / f64::from(n),
            );
            let (p, nrm) = c.sample((u, v));
            assert!(((p - c.centre).length() - 1.0).abs() < 1e-9);
            assert!(nrm.dot(-p.normalize()) >= -1e-9, "on the far side: {p}");
            // Back to solid angle: the same density everywhere in the cone.
            let cos = nrm.dot(-p.normalize()).abs();
            let solid = c.pdf_area(p, nrm, DVec3::ZERO) * p.length_squared() / cos;
            assert!((solid * omega - 1.0).abs() < 1e-6, "{solid}");
        }
    }

    #[test]
    fn jacobian_of_a_uniform_scale_is_its_square() {
        let t = crate::scene::Transform::scale(DVec3::splat(3.0));
        let j = jacobian(&t.matrix, &t.inverse, DVec3::Y);
        assert!((j - 9.0).abs() < 1e-12);
        // Stretching along x does not change the area of a face normal to x… by 1:
        // a face normal to y grows by the x scale.
        let t = crate::scene::Transform::scale(DVec3::new(2.0, 1.0, 1.0));
        assert!((jacobian(&t.matrix, &t.inverse, DVec3::X) - 1.0).abs() < 1e-12);
        assert!((jacobian(&t.matrix, &t.inverse, DVec3::Y) - 2.0).abs() < 1e-12);
    }
}
