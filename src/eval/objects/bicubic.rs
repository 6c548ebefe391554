//! `bicubic_patch`: a Bézier patch of 4 × 4 control points, approximated as
//! POV-Ray does by a grid of triangles whose corners lie on the patch, shaded
//! with the patch's own normals there.
//!
//! Measured against POV-Ray 3.7: `u_steps N` splits the patch into 2^N strips
//! across its rows of control points (the first index), `v_steps M` into 2^M
//! along them; 0 (the default) keeps the four corners only. Types 0 and 1 give
//! the same picture. A patch has no inside.

use crate::scene::MeshData;
use glam::{DVec2, DVec3};

/// The most subdivisions per direction rts accepts (2^8 = 256 strips).
pub const MAX_STEPS: u32 = 8;

/// The cubic Bernstein weights at `t` and their derivatives.
fn bernstein(t: f64) -> ([f64; 4], [f64; 4]) {
    let s = 1.0 - t;
    (
        [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t],
        [
            -3.0 * s * s,
            3.0 * s * s - 6.0 * t * s,
            6.0 * t * s - 3.0 * t * t,
            3.0 * t * t,
        ],
    )
}

/// The patch point at `(u, v)` (u across rows, v along a row) and its two
/// partial derivatives.
pub fn eval(points: &[DVec3; 16], u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
    let (bu, du) = bernstein(u);
    let (bv, dv) = bernstein(v);
    let (mut p, mut pu, mut pv) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
    for i in 0..4 {
        for j in 0..4 {
            let c = points[i * 4 + j];
            p += c * (bu[i] * bv[j]);
            pu += c * (du[i] * bv[j]);
            pv += c * (bu[i] * dv[j]);
        }
    }
    (p, pu, pv)
}

/// The patch's normal at `(u, v)`: `∂u × ∂v`, taken a little inside the patch
/// where that vanishes (a corner or edge collapsed to a point); zero when the
/// patch is degenerate there in every direction.
pub fn normal(points: &[DVec3; 16], u: f64, v: f64) -> DVec3 {
    let (_, pu, pv) = eval(points, u, v);
    if let Some(n) = normal_from(pu, pv) {
        return n;
    }
    for d in [1e-4, 1e-3, 1e-2] {
        let (u2, v2) = (
            u + if u > 0.5 { -d } else { d },
            v + if v > 0.5 { -d } else { d },
        );
        let (_, pu, pv) = eval(points, u2, v2);
        let n = pu.cross(pv);
        if n.length_squared() > 0.0 {
            return n;
        }
    }
    DVec3::ZERO
}

/// `pu × pv` when it does not vanish against the tangents' lengths.
fn normal_from(pu: DVec3, pv: DVec3) -> Option<DVec3> {
    let n = pu.cross(pv);
    let scale = pu.length() * pv.length();
    (n.length_squared() > 1e-18 * scale * scale && scale > 0.0).then_some(n)
}

/// The triangles of a patch: `2^u_steps × 2^v_steps` cells, two triangles
/// each, vertex normals from the patch, and uv from the corners' `uv`
/// (for the control points 1, 4, 16 and 13, interpolated bilinearly). Rows
/// of vertices of a big patch are computed in parallel (each the same
/// whatever the threads).
pub fn tessellate(points: &[DVec3; 16], u_steps: u32, v_steps: u32, uv: [DVec2; 4]) -> MeshData {
    use rayon::prelude::*;
    let nu = 1usize << u_steps.min(MAX_STEPS);
    let nv = 1usize << v_steps.min(MAX_STEPS);
    let along: Vec<(f64, [f64; 4], [f64; 4])> = (0..=nv)
        .map(|j| {
            let v = j as f64 / nv as f64;
            let (bv, dv) = bernstein(v);
            (v, bv, dv)
        })
        .collect();
    type Vertex = ([f32; 3], [f32; 3], [f32; 2]);
    // A task of at least ~4k vertices: a small patch stays on one thread.
    let min_rows = (4096 / (nv + 1)).max(1);
    let rows: Vec<Vec<Vertex>> = (0..nu + 1)
        .into_par_iter()
        .with_min_len(min_rows)
        .map(|i| {
            let u = i as f64 / nu as f64;
            let (bu, du) = bernstein(u);
            // The rows of control points combined at u (and their u-derivative):
            // a cubic in v whose points and tangents the patch has at this u.
            let mut row = [DVec3::ZERO; 4];
            let mut row_u = [DVec3::ZERO; 4];
            for k in 0..4 {
                for j in 0..4 {
                    row[j] += points[k * 4 + j] * bu[k];
                    row_u[j] += points[k * 4 + j] * du[k];
                }
            }
            along
                .iter()
                .map(|&(v, bv, dv)| {
                    let (mut p, mut pu, mut pv) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
                    for j in 0..4 {
                        p += row[j] * bv[j];
                        pu += row_u[j] * bv[j];
                        pv += row[j] * dv[j];
                    }
                    let n = match normal_from(pu, pv) {
                        Some(n) => n,
                        None => normal(points, u, v),
                    }
                    .normalize_or_zero();
                    // Corners: (u, v) = (0, 0) → uv[0], (0, 1) → uv[1], (1, 1) → uv[2], (1, 0) → uv[3].
                    let t = uv[0] * ((1.0 - u) * (1.0 - v))
                        + uv[1] * ((1.0 - u) * v)
                        + uv[2] * (u * v)
                        + uv[3] * (u * (1.0 - v));
                    (
                        [p.x as f32, p.y as f32, p.z as f32],
                        [n.x as f32, n.y as f32, n.z as f32],
                        [t.x as f32, t.y as f32],
                    )
                })
                .collect()
        })
        .collect();
    let mut m = MeshData::default();
    let count = (nu + 1) * (nv + 1);
    m.positions.reserve(count);
    m.normals.reserve(count);
    m.uvs.reserve(count);
    for (p, n, t) in rows.into_iter().flatten() {
        m.positions.push(p);
        m.normals.push(n);
        m.uvs.push(t);
    }
    let at = |i: usize, j: usize| (i * (nv + 1) + j) as u32;
    m.triangles.reserve(2 * nu * nv);
    for i in 0..nu {
        for j in 0..nv {
            let q = [at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)];
            for tri in [[q[0], q[1], q[3]], [q[0], q[3], q[2]]] {
                let [a, b, c] = tri.map(|k| glam::Vec3::from(m.positions[k as usize]));
                if (b - a).cross(c - a).length_squared() > 0.0 {
                    m.triangles.push(tri);
                }
            }
        }
    }
    // A normal that could not be found (a patch collapsed to a line) shades flat.
    m.normal_indices = m
        .triangles
        .iter()
        .map(|t| {
            if t.iter().any(|&k| m.normals[k as usize] == [0.0; 3]) {
                [u32::MAX; 3]
            } else {
                *t
            }
        })
        .collect();
    m.uv_indices = m.triangles.clone();
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat() -> [DVec3; 16] {
        std::array::from_fn(|k| DVec3::new((k % 4) as f64, (k / 4) as f64, 0.0))
    }

    #[test]
    fn corners_lie_on_the_control_points() {
        let mut p = flat();
        p[5].z = 3.0;
        for (u, v, k) in [(0.0, 0.0, 0), (0.0, 1.0, 3), (1.0, 0.0, 12), (1.0, 1.0, 15)] {
            assert!((eval(&p, u, v).0 - p[k]).length() < 1e-12);
        }
    }

    #[test]
    fn steps_give_powers_of_two() {
        let m = tessellate(&flat(), 2, 1, [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y]);
        assert_eq!(m.triangles.len(), 2 * 4 * 2);
        assert_eq!(m.positions.len(), 5 * 3);
        let m0 = tessellate(&flat(), 0, 0, [DVec2::ZERO; 4]);
        assert_eq!(m0.triangles.len(), 2);
    }

    #[test]
    fn a_collapsed_corner_still_has_a_normal() {
        let mut p = flat();
        for q in p.iter_mut().take(4) {
            *q = DVec3::new(1.5, 0.0, 0.0);
        }
        let n = normal(&p, 0.0, 0.5).normalize();
        assert!((n.z.abs() - 1.0).abs() < 1e-6, "{n}");
    }
}
