//! `sphere_sweep`: the volume a sphere of varying radius fills as it moves
//! along a spline (`linear_spline`, `b_spline` or `cubic_spline`).
//!
//! The sweep is the union of the spheres of every spline point, so
//! `min over s (|p − C(s)| − R(s))` is a lower bound on the distance from `p` to
//! its surface, outside and (as `|…|`) inside: rays are sphere-traced with it
//! and the crossing is bisected to a tiny fraction of the sweep's size. The
//! normal at a surface point is the direction from the centre of the sphere
//! it lies on. Inside is inside any of the spheres.

use crate::build::Ray;
pub use crate::scene::SweepSpline;
use glam::DVec3;

/// One piece of the sweep: centre `Σ c[k] sᵏ` and radius `Σ r[k] sᵏ` for
/// `s ∈ [0, 1]`, with a sphere enclosing all its spheres.
#[derive(Clone, Debug, PartialEq)]
struct Segment {
    c: [DVec3; 4],
    r: [f64; 4],
    linear: bool,
    center: DVec3,
    reach: f64,
}

impl Segment {
    fn at(&self, s: f64) -> (DVec3, f64) {
        let c = self.c[0] + s * (self.c[1] + s * (self.c[2] + s * self.c[3]));
        let r = self.r[0] + s * (self.r[1] + s * (self.r[2] + s * self.r[3]));
        (c, r)
    }

    /// `min over s (|p − C(s)| − R(s))` and the `s` where it is reached.
    fn distance(&self, p: DVec3) -> (f64, f64) {
        let g = |s: f64| {
            let (c, r) = self.at(s);
            (p - c).length() - r
        };
        if self.linear {
            // Closed form of the round cone: convex in s.
            let d = self.c[1];
            let l2 = d.length_squared();
            if l2 == 0.0 {
                let s = if self.r[1] > 0.0 { 1.0 } else { 0.0 };
                return (g(s), s);
            }
            let l = l2.sqrt();
            let q = p - self.c[0];
            let a = q.dot(d) / l;
            let h = (q.length_squared() - a * a).max(0.0).sqrt();
            let k = self.r[1] / l;
            let x = if k.abs() < 1.0 {
                a + k * h / (1.0 - k * k).sqrt()
            } else if k > 0.0 {
                l
            } else {
                0.0
            };
            let s = (x / l).clamp(0.0, 1.0);
            return (g(s), s);
        }
        // Sample, then narrow around the best sample by golden sections.
        const N: usize = 12;
        let mut best = (f64::INFINITY, 0.0);
        for i in 0..=N {
            let s = i as f64 / N as f64;
            let v = g(s);
            if v < best.0 {
                best = (v, s);
            }
        }
        let (mut lo, mut hi) = (
            (best.1 - 1.0 / N as f64).max(0.0),
            (best.1 + 1.0 / N as f64).min(1.0),
        );
        const PHI: f64 = 0.618_033_988_749_894_8;
        let mut x1 = hi - PHI * (hi - lo);
        let mut x2 = lo + PHI * (hi - lo);
        let (mut g1, mut g2) = (g(x1), g(x2));
        for _ in 0..28 {
            if g1 < g2 {
                hi = x2;
                x2 = x1;
                g2 = g1;
                x1 = hi - PHI * (hi - lo);
                g1 = g(x1);
            } else {
                lo = x1;
                x1 = x2;
                g1 = g2;
                x2 = lo + PHI * (hi - lo);
                g2 = g(x2);
            }
        }
        let s = 0.5 * (lo + hi);
        let v = g(s);
        if v < best.0 {
            (v, s)
        } else {
            best
        }
    }
}

/// A sphere sweep ready to intersect.
#[derive(Clone, Debug, PartialEq)]
pub struct SphereSweep {
    segments: Vec<Segment>,
    min: DVec3,
    max: DVec3,
    /// Crossings are found to this distance (object units).
    eps: f64,
}

/// Most sphere-tracing steps one ray may take.
const MAX_STEPS: usize = 4096;

impl SphereSweep {
    /// The sweep of `points` (centre, radius) along `spline`; `None` when there
    /// are too few points. `tolerance` (POV-Ray's, default 1e-6) sets how
    /// closely crossings are found, relative to the sweep's size.
    pub fn new(
        spline: SweepSpline,
        points: &[(DVec3, f64)],
        tolerance: f64,
    ) -> Option<SphereSweep> {
        if points.len() < spline.min_points() {
            return None;
        }
        let mut segments = Vec::new();
        let mut push = |c: [DVec3; 4], r: [f64; 4], linear: bool| {
            let mut seg = Segment {
                c,
                r,
                linear,
                center: DVec3::ZERO,
                reach: 0.0,
            };
            const N: usize = 32;
            let samples: Vec<(DVec3, f64)> = (0..=N).map(|i| seg.at(i as f64 / N as f64)).collect();
            let center = samples.iter().map(|s| s.0).sum::<DVec3>() / samples.len() as f64;
            let step = samples
                .windows(2)
                .map(|w| (w[1].0 - w[0].0).length() + (w[1].1 - w[0].1).abs())
                .fold(0.0, f64::max);
            seg.center = center;
            seg.reach = samples
                .iter()
                .map(|(c, r)| (*c - center).length() + r)
                .fold(0.0, f64::max)
                + step;
            segments.push(seg);
        };
        match spline {
            SweepSpline::Linear => {
                for w in points.windows(2) {
                    let (p0, r0) = w[0];
                    let (p1, r1) = w[1];
                    push(
                        [p0, p1 - p0, DVec3::ZERO, DVec3::ZERO],
                        [r0, r1 - r0, 0.0, 0.0],
                        true,
                    );
                }
            }
            SweepSpline::BSpline => {
                for w in points.windows(4) {
                    let k = |f: &dyn Fn(usize) -> f64| -> [f64; 4] {
                        let (a, b, c, d) = (f(0), f(1), f(2), f(3));
                        [
                            (a + 4.0 * b + c) / 6.0,
                            (-3.0 * a + 3.0 * c) / 6.0,
                            (3.0 * a - 6.0 * b + 3.0 * c) / 6.0,
                            (-a + 3.0 * b - 3.0 * c + d) / 6.0,
                        ]
                    };
                    push(vec_coeffs(w, &k), k(&|i| w[i].1), false);
                }
            }
            SweepSpline::Cubic => {
                for w in points.windows(4) {
                    let k = |f: &dyn Fn(usize) -> f64| -> [f64; 4] {
                        let (a, b, c, d) = (f(0), f(1), f(2), f(3));
                        [
                            b,
                            0.5 * (c - a),
                            0.5 * (2.0 * a - 5.0 * b + 4.0 * c - d),
                            0.5 * (-a + 3.0 * b - 3.0 * c + d),
                        ]
                    };
                    push(vec_coeffs(w, &k), k(&|i| w[i].1), false);
                }
            }
        }
        let mut min = DVec3::splat(f64::INFINITY);
        let mut max = DVec3::splat(f64::NEG_INFINITY);
        for seg in &segments {
            const N: usize = 64;
            for i in 0..=N {
                let (c, r) = seg.at(i as f64 / N as f64);
                let r = r.abs();
                min = min.min(c - DVec3::splat(r));
                max = max.max(c + DVec3::splat(r));
            }
        }
        let size = (max - min).length().max(1e-12);
        let (min, max) = (
            min - DVec3::splat(size * 0.01),
            max + DVec3::splat(size * 0.01),
        );
        let eps = size * tolerance.clamp(1e-9, 1e-3).max(1e-7);
        Some(SphereSweep {
            segments,
            min,
            max,
            eps,
        })
    }

    /// The distance bound at `p`, and the nearest sphere's centre.
    fn distance(&self, p: DVec3) -> (f64, DVec3) {
        let mut best = (f64::INFINITY, DVec3::ZERO);
        for seg in &self.segments {
            if (p - seg.center).length() - seg.reach >= best.0 {
                continue;
            }
            let (d, s) = seg.distance(p);
            if d < best.0 {
                best = (d, seg.at(s).0);
            }
        }
        best
    }

    /// Whether `p` is strictly inside.
    pub fn inside(&self, p: DVec3) -> bool {
        self.distance(p).0 < 0.0
    }

    /// The outward normal at surface point `p` (unnormalised).
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let (_, c) = self.distance(p);
        let n = p - c;
        if n.length_squared() > 0.0 {
            n
        } else {
            DVec3::Y
        }
    }

    /// The bounding box.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        (self.min, self.max)
    }

    /// Every crossing in `(t_min, t_max)`, in order; `f` returns false to stop.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64) -> bool) {
        let Some((t0, t1)) = crate::build::shape::box_span(self.min, self.max, ray) else {
            return;
        };
        let (a, b) = (t0.max(t_min), t1.min(t_max));
        let len = ray.dir.length();
        if a >= b || len == 0.0 || !len.is_finite() {
            return;
        }
        let eps = self.eps;
        let mut t = a;
        let mut d = self.distance(ray.at(t)).0;
        let mut inside = d < 0.0;
        for _ in 0..MAX_STEPS {
            if t >= b {
                return;
            }
            let step = (0.95 * d.abs()).max(eps) / len;
            let tn = (t + step).min(b);
            let dn = self.distance(ray.at(tn)).0;
            if (dn < 0.0) != inside {
                let (mut lo, mut hi) = (t, tn);
                for _ in 0..64 {
                    if (hi - lo) * len <= eps * 0.5 {
                        break;
                    }
                    let mid = 0.5 * (lo + hi);
                    if (self.distance(ray.at(mid)).0 < 0.0) == inside {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let root = 0.5 * (lo + hi);
                // A crossing at the ray's start is the surface it leaves.
                if root > t_min && root < t_max && (root - t_min) * len > 8.0 * eps && !f(root) {
                    return;
                }
                inside = !inside;
            }
            t = tn;
            d = dn;
        }
    }

    /// The nearest crossing in `(t_min, t_max)`.
    pub fn nearest(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
        let mut best = None;
        self.hits(ray, t_min, t_max, &mut |t| {
            best = Some(t);
            false
        });
        best
    }
}

/// A spline rule: the coefficients of one piece from its four values.
type Rule<'a> = &'a dyn Fn(&dyn Fn(usize) -> f64) -> [f64; 4];

/// The vector coefficients of a spline piece from the scalar rule `k`.
fn vec_coeffs(w: &[(DVec3, f64)], k: Rule) -> [DVec3; 4] {
    let x = k(&|i| w[i].0.x);
    let y = k(&|i| w[i].0.y);
    let z = k(&|i| w[i].0.z);
    std::array::from_fn(|j| DVec3::new(x[j], y[j], z[j]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_linear_sweep_of_equal_spheres_is_a_capsule() {
        let s = SphereSweep::new(
            SweepSpline::Linear,
            &[(DVec3::ZERO, 1.0), (DVec3::new(4.0, 0.0, 0.0), 1.0)],
            1e-6,
        )
        .unwrap();
        let ray = Ray::new(DVec3::new(2.0, 0.0, -5.0), DVec3::Z);
        let t = s.nearest(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((t - 4.0).abs() < 1e-4, "{t}");
        let ray = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        let mut all = Vec::new();
        s.hits(&ray, 0.0, f64::INFINITY, &mut |t| {
            all.push(t);
            true
        });
        assert_eq!(all.len(), 2);
        assert!(
            (all[0] - 4.0).abs() < 1e-4 && (all[1] - 10.0).abs() < 1e-4,
            "{all:?}"
        );
        assert!(s.inside(DVec3::new(4.5, 0.0, 0.0)));
        assert!(!s.inside(DVec3::new(2.0, 1.01, 0.0)));
        let n = s.normal(DVec3::new(2.0, 1.0, 0.0)).normalize();
        assert!((n - DVec3::Y).length() < 1e-9);
    }

    #[test]
    fn splines_need_enough_points() {
        let p = [(DVec3::ZERO, 1.0), (DVec3::X, 1.0), (DVec3::Y, 1.0)];
        assert!(SphereSweep::new(SweepSpline::Linear, &p, 1e-6).is_some());
        assert!(SphereSweep::new(SweepSpline::BSpline, &p, 1e-6).is_none());
        assert!(SphereSweep::new(SweepSpline::Cubic, &p[..1], 1e-6).is_none());
    }

    #[test]
    fn a_cubic_sweep_passes_through_its_inner_points() {
        let p: Vec<(DVec3, f64)> = (0..5)
            .map(|i| (DVec3::new(i as f64, (i as f64).sin(), 0.0), 0.3))
            .collect();
        let s = SphereSweep::new(SweepSpline::Cubic, &p, 1e-6).unwrap();
        for q in &p[1..4] {
            assert!(s.inside(q.0));
            assert!(s.distance(q.0).0 < -0.29);
        }
    }
}
