//! The convex `polyhedron`: an intersection of half-spaces.

use crate::build::Ray;
use glam::DVec3;

/// Entry and exit of `ray` through the half-spaces `n·p <= d`, with the plane
/// index of each; `None` when the ray misses. An unbounded side gives ±∞.
pub fn slab(planes: &[(DVec3, f64)], ray: &Ray) -> Option<((f64, u32), (f64, u32))> {
    let mut near = (f64::NEG_INFINITY, u32::MAX);
    let mut far = (f64::INFINITY, u32::MAX);
    for (i, &(n, d)) in planes.iter().enumerate() {
        let denom = n.dot(ray.dir);
        let dist = d - n.dot(ray.origin);
        if denom == 0.0 {
            if dist < 0.0 {
                return None;
            }
            continue;
        }
        let t = dist / denom;
        if denom < 0.0 {
            if t > near.0 {
                near = (t, i as u32);
            }
        } else if t < far.0 {
            far = (t, i as u32);
        }
        if near.0 > far.0 {
            return None;
        }
    }
    Some((near, far))
}

/// Strictly inside every half-space.
pub fn inside(planes: &[(DVec3, f64)], p: DVec3) -> bool {
    planes.iter().all(|&(n, d)| n.dot(p) < d)
}

/// Face planes of the convex hull given by `vertices` and `faces` (indices into
/// `vertices`, at least three per face), oriented away from the vertices' centroid.
/// Errors name the face that is degenerate.
pub fn planes(vertices: &[DVec3], faces: &[Vec<usize>]) -> Result<Vec<(DVec3, f64)>, String> {
    let centroid = vertices.iter().copied().sum::<DVec3>() / vertices.len().max(1) as f64;
    let scale = vertices
        .iter()
        .map(|v| (*v - centroid).length())
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let mut out = Vec::with_capacity(faces.len());
    for (k, f) in faces.iter().enumerate() {
        let p: Vec<DVec3> = f.iter().map(|&i| vertices[i]).collect();
        let mut n = DVec3::ZERO;
        for i in 0..p.len() {
            n += p[i].cross(p[(i + 1) % p.len()]);
        }
        if n.length() <= 1e-12 * scale * scale {
            return Err(format!("face {k} has no area: its vertices are in a line"));
        }
        let mut n = n.normalize();
        let mut d = n.dot(p[0]);
        if n.dot(centroid) > d {
            n = -n;
            d = -d;
        }
        if p.iter().any(|q| (n.dot(*q) - d).abs() > 1e-6 * scale) {
            return Err(format!(
                "face {k} is not flat: its vertices are not in one plane"
            ));
        }
        if vertices.iter().any(|v| n.dot(*v) - d > 1e-6 * scale) {
            return Err(format!(
                "face {k} has vertices on both sides: the polyhedron is not convex"
            ));
        }
        out.push((n, d));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_from_faces() {
        let v: Vec<DVec3> = (0..8)
            .map(|i| DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64))
            .collect();
        let faces = vec![
            vec![0, 1, 3, 2],
            vec![4, 5, 7, 6],
            vec![0, 1, 5, 4],
            vec![2, 3, 7, 6],
            vec![0, 2, 6, 4],
            vec![1, 3, 7, 5],
        ];
        let pl = planes(&v, &faces).unwrap();
        let ((t0, _), (t1, _)) =
            slab(&pl, &Ray::new(DVec3::new(0.5, 0.5, -2.0), DVec3::Z)).unwrap();
        assert_eq!((t0, t1), (2.0, 3.0));
        assert!(inside(&pl, DVec3::splat(0.5)));
        assert!(!inside(&pl, DVec3::splat(1.5)));
        assert!(slab(&pl, &Ray::new(DVec3::new(2.0, 0.5, -2.0), DVec3::Z)).is_none());
        assert!(planes(&v, &[vec![0, 1, 3, 6]]).is_err());
    }
}
