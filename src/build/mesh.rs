//! Meshes: the shared triangle data with its own BVH in object space. Every
//! object using a mesh is an instance (a transform and an `Arc` of this).

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
        self.bvh.traverse(ray, t_min, t_max, |i, t_max| {
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
