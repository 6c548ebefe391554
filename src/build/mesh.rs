//! Meshes: the shared triangle data with its own BVH in object space. Every
//! object using a mesh is an instance (a transform and an `Arc` of this).

use super::accel::Triangles;
use super::shapes::flat::{barycentric, triangle};
use super::{Aabb, Bvh, Ray};
use crate::scene::MeshData;
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// A mesh ready for rendering: its triangles and a hierarchy over them.
#[derive(Debug)]
pub struct MeshAccel {
    /// The triangles (shared with the scene description).
    pub data: Arc<MeshData>,
    /// Hierarchy over triangle indices, in object space.
    pub bvh: Bvh,
}

impl MeshAccel {
    /// Builds the hierarchy over `data`'s triangles.
    pub fn new(data: Arc<MeshData>) -> MeshAccel {
        let bvh = Bvh::build_indexed(data.triangles.len(), |i| Aabb::from_points(data.corners(i)));
        MeshAccel { data, bvh }
    }

    /// Object-space bounds.
    pub fn bounds(&self) -> Aabb {
        self.bvh.bounds()
    }

    #[inline(always)]
    fn tri_hit(&self, i: u32, ray: &Ray) -> Option<f64> {
        let [a, b, c] = self.data.corners(i as usize);
        triangle(a, b - a, c - a, ray).map(|h| h.0)
    }

    /// Nearest hit in `(t_min, t_max)`: distance and triangle index.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, u32)> {
        let mut best = None;
        let tris = Triangles {
            positions: &self.data.positions,
            triangles: &self.data.triangles,
        };
        self.bvh
            .traverse_triangles(ray, t_min, t_max, tris, |i, t_max| {
                if let Some(t) = self.tri_hit(i, ray) {
                    if t > t_min && t < t_max {
                        best = Some((t, i));
                        return Some(t);
                    }
                }
                Some(t_max)
            });
        best
    }

    /// Every hit in `(t_min, t_max)`, unordered.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64, u32)) {
        self.bvh.traverse(ray, t_min, t_max, |i, t_max| {
            if let Some(t) = self.tri_hit(i, ray) {
                if t > t_min && t < t_max {
                    f(t, i);
                }
            }
            Some(t_max)
        });
    }

    /// With `inside_vector`: inside when a ray from `p` along it crosses the mesh
    /// an odd number of times. Without: never (a mesh is not a solid).
    pub fn inside(&self, p: DVec3) -> bool {
        let Some(dir) = self.data.inside_vector else {
            return false;
        };
        // A tiny tilt off the given direction keeps rays along axes from passing
        // exactly through the shared edges of axis-aligned faces (counted twice).
        let dir = dir.normalize() + DVec3::new(3.1e-6, 1.7e-6, 2.3e-6);
        let mut n = 0u32;
        self.hits(&Ray::new(p, dir), 0.0, f64::INFINITY, &mut |_, _| n += 1);
        n % 2 == 1
    }

    /// Unnormalised geometric normal of triangle `i` (`(b - a) × (c - a)`).
    pub fn normal(&self, i: u32) -> DVec3 {
        let [a, b, c] = self.data.corners(i as usize);
        (b - a).cross(c - a)
    }

    /// Corner weights of `p` in triangle `i`: `[wa, wb, wc]`.
    fn weights(&self, i: u32, p: DVec3) -> [f64; 3] {
        let [a, b, c] = self.data.corners(i as usize);
        let (u, v) = barycentric(a, b - a, c - a, p);
        [1.0 - u - v, u, v]
    }

    /// The interpolated vertex normal at `p` on triangle `i`, when it has normals.
    pub fn shading_normal(&self, i: u32, p: DVec3) -> Option<DVec3> {
        let idx = *self.data.normal_indices.get(i as usize)?;
        if idx[0] == u32::MAX {
            return None;
        }
        let w = self.weights(i, p);
        let mut n = DVec3::ZERO;
        for k in 0..3 {
            let m = self.data.normals[idx[k] as usize];
            n += DVec3::new(m[0] as f64, m[1] as f64, m[2] as f64) * w[k];
        }
        (n.length_squared() > 0.0).then_some(n)
    }

    /// The interpolated uv at `p` on triangle `i`, when the mesh has uvs.
    pub fn uv(&self, i: u32, p: DVec3) -> Option<DVec2> {
        let idx = *self.data.uv_indices.get(i as usize)?;
        let w = self.weights(i, p);
        let mut uv = DVec2::ZERO;
        for k in 0..3 {
            let m = self.data.uvs[idx[k] as usize];
            uv += DVec2::new(m[0] as f64, m[1] as f64) * w[k];
        }
        Some(uv)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand_core::{RngCore, SeedableRng};

    /// The nearest hit by testing every triangle in f64.
    fn brute(m: &MeshAccel, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
        let mut best: Option<f64> = None;
        for i in 0..m.data.triangles.len() as u32 {
            if let Some(t) = m.tri_hit(i, ray) {
                if t > t_min && t < best.unwrap_or(t_max) {
                    best = Some(t);
                }
            }
        }
        best
    }

    /// [`MeshAccel::intersect`] with the f32 cull of the leaves always on.
    fn culled(m: &MeshAccel, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
        let mut best = None;
        let tris = Triangles {
            positions: &m.data.positions,
            triangles: &m.data.triangles,
        };
        m.bvh.traverse_culled(ray, t_min, t_max, tris, |i, t_max| {
            if let Some(t) = m.tri_hit(i, ray) {
                if t > t_min && t < t_max {
                    best = Some(t);
                    return Some(t);
                }
            }
            Some(t_max)
        });
        best
    }

    #[test]
    fn the_f32_cull_never_drops_a_triangle_the_f64_test_hits() {
        // A soup of triangles: ordinary, tiny, long and thin, far from the
        // origin, and a grid whose shared edges and corners rays pass through;
        // rays from near and far, some grazing the grid's plane, some along axes.
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(11);
        let mut unit = move || (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        let mut data = MeshData::default();
        let add = |data: &mut MeshData, ps: [[f32; 3]; 3]| {
            let k = data.positions.len() as u32;
            data.positions.extend(ps);
            data.triangles.push([k, k + 1, k + 2]);
        };
        for i in 0..2000 {
            let scale = [1.0, 1e-3, 50.0, 1e4][i % 4];
            let c = [unit(), unit(), unit()].map(|x| ((x * 2.0 - 1.0) * 4.0) as f32);
            let off = if i % 7 == 0 { 1e4 } else { 0.0 };
            let mut p = || {
                let mut v = [0.0f32; 3];
                for a in 0..3 {
                    v[a] = c[a] + off + ((unit() - 0.5) * scale) as f32;
                }
                v
            };
            let tri = [p(), p(), p()];
            add(&mut data, tri);
        }
        for j in 0..30 {
            for i in 0..30 {
                let (x, z) = (i as f32 * 0.25 - 4.0, j as f32 * 0.25 - 4.0);
                add(
                    &mut data,
                    [[x, 0.0, z], [x + 0.25, 0.0, z], [x, 0.0, z + 0.25]],
                );
                add(
                    &mut data,
                    [
                        [x + 0.25, 0.0, z],
                        [x + 0.25, 0.0, z + 0.25],
                        [x, 0.0, z + 0.25],
                    ],
                );
            }
        }
        let mesh = MeshAccel::new(Arc::new(data));
        for k in 0..20000 {
            let far = if k % 5 == 0 { 1e5 } else { 10.0 };
            let origin = DVec3::new(unit(), unit(), unit()) * 2.0 * far - DVec3::splat(far);
            let target = match k % 3 {
                // Grid vertices and edges.
                0 => DVec3::new(
                    (unit() * 32.0).floor() * 0.25 - 4.0,
                    0.0,
                    (unit() * 64.0).floor() * 0.125 - 4.0,
                ),
                _ => DVec3::new(unit(), unit(), unit()) * 8.0 - DVec3::splat(4.0),
            };
            let mut dir = target - origin;
            if k % 11 == 0 {
                dir.y = 0.0;
            }
            if k % 13 == 0 {
                dir = DVec3::new(0.0, -1.0, 0.0);
            }
            let ray = Ray::new(origin, dir);
            let t_max = if k % 4 == 0 {
                unit() * 2.0
            } else {
                f64::INFINITY
            };
            let want = brute(&mesh, &ray, 0.0, t_max);
            let got = mesh.intersect(&ray, 0.0, t_max).map(|h| h.0);
            assert_eq!(got, want, "ray {k} {ray:?} to {t_max}");
            let got = culled(&mesh, &ray, 0.0, t_max);
            assert_eq!(got, want, "culled: ray {k} {ray:?} to {t_max}");
        }
    }
}
