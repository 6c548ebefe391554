//! `superellipsoid { <E, N> }`: the surface
//! `(|x|^(2/E) + |y|^(2/E))^(E/N) + |z|^(2/N) = 1` in the box from −1 to 1.
//!
//! The equation is solved as `N(p) = 1` with the equivalent function
//! `N(p) = ‖(‖(x, y)‖_E, z)‖_N`, where `‖(a, b)‖_k = (|a|^(2/k) + |b|^(2/k))^(k/2)`:
//! it grows linearly with the distance from the centre (`N(λp) = λ N(p)`), so it
//! stays well scaled near the flat faces and sharp edges of small exponents,
//! where the powers themselves are flat or steep. With both exponents at most 2
//! the shape is convex and `N` is a convex function along any ray: between two
//! points where it is above 1 it dips below at most once, and the tangents at
//! the ends bound how low it can go, so no crossing is missed. Larger exponents
//! give pinched, star-like shapes: there the ray is cut where a coordinate
//! changes sign or two are equal in size (thin rims and arms lie there), `N`
//! is bounded on each stretch by its values at the smallest and largest sizes
//! the coordinates take there (it grows with each), and stretches that may
//! hold the surface are halved until they are small.

use crate::build::{Aabb, Ray};
use glam::DVec3;

/// A superellipsoid in its own space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Superellipsoid {
    e: f64,
    n: f64,
}

impl Superellipsoid {
    /// The shape of exponents `e` (east-west) and `n` (north-south), both > 0.
    pub fn new(e: f64, n: f64) -> Superellipsoid {
        Superellipsoid { e, n }
    }

    fn convex(&self) -> bool {
        self.e <= 2.0 && self.n <= 2.0
    }

    /// `N(p)`: 1 on the surface, below inside, homogeneous of degree 1.
    pub fn norm(&self, p: DVec3) -> f64 {
        norm2(norm2(p.x, p.y, self.e), p.z, self.n)
    }

    /// Strictly inside.
    pub fn inside(&self, p: DVec3) -> bool {
        self.norm(p) < 1.0
    }

    /// The gradient of `N` at `p`: the outward normal (unnormalised).
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let g = self.gradient(p);
        if g.length_squared() > 0.0 && g.is_finite() {
            g
        } else {
            // The centre, or a cusp of a pinched shape: the largest coordinate.
            let a = p.abs();
            if a.x >= a.y && a.x >= a.z {
                DVec3::X * p.x.signum()
            } else if a.y >= a.z {
                DVec3::Y * p.y.signum()
            } else {
                DVec3::Z * p.z.signum()
            }
        }
    }

    fn gradient(&self, p: DVec3) -> DVec3 {
        let r = norm2(p.x, p.y, self.e);
        let big = norm2(r, p.z, self.n);
        if big == 0.0 {
            return DVec3::ZERO;
        }
        let (ke, kn) = (2.0 / self.e - 1.0, 2.0 / self.n - 1.0);
        let dr = pw(r / big, kn);
        let dz = p.z.signum() * pw(p.z.abs() / big, kn);
        let (dx, dy) = if r == 0.0 {
            (0.0, 0.0)
        } else {
            (
                p.x.signum() * pw(p.x.abs() / r, ke),
                p.y.signum() * pw(p.y.abs() / r, ke),
            )
        };
        DVec3::new(dr * dx, dr * dy, dz)
    }

    /// Object-space bounds: the box from −1 to 1.
    pub fn bounds(&self) -> Aabb {
        Aabb::new(DVec3::NEG_ONE, DVec3::ONE)
    }

    /// Every crossing of `ray` in `(t_min, t_max)`, in order; `f` returns
    /// `false` to stop.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64) -> bool) {
        let inv = ray.dir.recip();
        let reach = DVec3::splat(1.0 + 1e-9);
        let t0 = (-reach - ray.origin) * inv;
        let t1 = (reach - ray.origin) * inv;
        let near = t0.min(t1).max_element().max(t_min);
        let far = t0.max(t1).min_element().min(t_max);
        if near.is_nan() || far.is_nan() || near >= far {
            return;
        }
        let g = |t: f64| self.norm(ray.at(t)) - 1.0;
        let tol = 1e-12 * (1.0 + near.abs().max(far.abs()));
        let (ga, gb) = (g(near), g(far));
        if !self.convex() {
            // Pieces between the planes where a coordinate changes sign (a
            // pinched shape's thin rims lie there) or, for the arms of a
            // pinched cross-section (E > 2) or profile (N > 2), where two
            // coordinates are equal in size.
            let (o, d) = (ray.origin, ray.dir);
            let mut knots = vec![near, far];
            let mut cut = |num: f64, den: f64| {
                let t = -num / den;
                if den != 0.0 && t > near && t < far {
                    knots.push(t);
                }
            };
            for i in 0..3 {
                cut(o[i], d[i]);
            }
            let pairs: &[(usize, usize)] = match (self.e > 2.0, self.n > 2.0) {
                (true, true) => &[(0, 1), (0, 2), (1, 2)],
                (true, false) => &[(0, 1)],
                (false, true) => &[(0, 2), (1, 2)],
                (false, false) => &[],
            };
            for &(i, j) in pairs {
                cut(o[i] - o[j], d[i] - d[j]);
                cut(o[i] + o[j], d[i] + d[j]);
            }
            knots.sort_by(f64::total_cmp);
            let span = far - near;
            let limits = (span / 64.0, span * 1e-4, tol);
            let mut ga = ga;
            for w in knots.windows(2) {
                let gb = g(w[1]);
                if w[1] > w[0] && !self.search(ray, (w[0], ga), (w[1], gb), limits, f) {
                    return;
                }
                ga = gb;
            }
            return;
        }
        if (ga < 0.0) != (gb < 0.0) {
            f(bisect(&g, near, far, ga, tol));
        } else if ga >= 0.0 {
            let slope = |t: f64| self.gradient(ray.at(t)).dot(ray.dir);
            if let Some((m, gm)) = dip(&g, &slope, near, far, ga, gb, tol) {
                let _ = f(bisect(&g, near, m, ga, tol)) && f(bisect(&g, m, far, gm, tol));
            }
        }
    }

    /// The crossings between `a` and `b` (with `N − 1` there) of a pinched
    /// shape, in order; `false` when `f` asked to stop. `N` only grows with
    /// each coordinate's size, so `N` at the smallest and at the largest sizes
    /// the coordinates take on the stretch bound it there: a stretch entirely
    /// outside or inside is dropped, others are halved. A stretch whose ends
    /// differ in sign and that is shorter than `limits.0` is taken to hold one
    /// crossing; others are halved down to `limits.1` (finding thin spikes and
    /// grazed tips); `limits.2` is the root tolerance.
    fn search(
        &self,
        ray: &Ray,
        (a, ga): (f64, f64),
        (b, gb): (f64, f64),
        limits: (f64, f64, f64),
        f: &mut dyn FnMut(f64) -> bool,
    ) -> bool {
        let (p, q) = (ray.at(a), ray.at(b));
        let low = |i: usize| {
            if (p[i] < 0.0) != (q[i] < 0.0) {
                0.0
            } else {
                p[i].abs().min(q[i].abs())
            }
        };
        let lo = DVec3::new(low(0), low(1), low(2));
        if self.norm(lo) > 1.0 {
            return true;
        }
        if self.norm(p.abs().max(q.abs())) < 1.0 {
            return true;
        }
        let len = b - a;
        let crossing = (ga < 0.0) != (gb < 0.0);
        if (crossing && len <= limits.0) || len <= limits.1 {
            if crossing {
                let g = |t: f64| self.norm(ray.at(t)) - 1.0;
                return f(bisect(&g, a, b, ga, limits.2));
            }
            return true;
        }
        let m = 0.5 * (a + b);
        let gm = self.norm(ray.at(m)) - 1.0;
        self.search(ray, (a, ga), (m, gm), limits, f)
            && self.search(ray, (m, gm), (b, gb), limits, f)
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

/// `(|a|^(2/k) + |b|^(2/k))^(k/2)`, computed relative to the larger of the two.
fn norm2(a: f64, b: f64, k: f64) -> f64 {
    let (a, b) = (a.abs(), b.abs());
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    if hi == 0.0 {
        return 0.0;
    }
    hi * (1.0 + (lo / hi).powf(2.0 / k)).powf(k / 2.0)
}

/// `x^k` for `x` in [0, 1], with `0^k` for negative `k` kept finite.
fn pw(x: f64, k: f64) -> f64 {
    if x <= 0.0 {
        return if k > 0.0 {
            0.0
        } else if k == 0.0 {
            1.0
        } else {
            1e12
        };
    }
    x.powf(k)
}

/// Where `g` (above 0 at both ends, `slope` its derivative) dips below 0
/// between `a` and `b`, if it does, assuming it falls then rises there (true of
/// a convex `g`): the lowest point is bracketed by the sign of the slope, and
/// the tangents at the bracket's ends bound the value from below, so the
/// search stops as soon as that bound is above 0.
fn dip(
    g: &impl Fn(f64) -> f64,
    slope: &impl Fn(f64) -> f64,
    mut a: f64,
    mut b: f64,
    mut ga: f64,
    mut gb: f64,
    tol: f64,
) -> Option<(f64, f64)> {
    let (mut sa, mut sb) = (slope(a), slope(b));
    for _ in 0..80 {
        if !(sa < 0.0 && sb > 0.0) {
            return None;
        }
        // The tangents at a and b meet at x, below the curve there.
        let x = (gb - ga + sa * a - sb * b) / (sa - sb);
        let floor = ga + sa * (x - a);
        if floor > 0.0 || !x.is_finite() {
            return None;
        }
        if b - a <= tol {
            return None;
        }
        let m = if x > a && x < b {
            0.5 * (x + 0.5 * (a + b))
        } else {
            0.5 * (a + b)
        };
        let gm = g(m);
        if gm < 0.0 {
            return Some((m, gm));
        }
        let sm = slope(m);
        if sm < 0.0 {
            (a, ga, sa) = (m, gm, sm);
        } else {
            (b, gb, sb) = (m, gm, sm);
        }
    }
    None
}

/// The crossing of `g` between `a` and `b` (`ga` the value at `a`, the value
/// at `b` of the other sign): bisection with secant steps while they stay in
/// the bracket.
fn bisect(g: &impl Fn(f64) -> f64, mut a: f64, mut b: f64, ga: f64, tol: f64) -> f64 {
    let neg_a = ga < 0.0;
    let (mut fa, mut fb) = (ga, g(b));
    for i in 0..100 {
        if b - a <= tol {
            break;
        }
        // Alternate secant and bisection: fast on smooth stretches, safe on kinks.
        let secant = a - fa * (b - a) / (fb - fa);
        let m = if i % 2 == 0 && secant > a && secant < b {
            secant
        } else {
            0.5 * (a + b)
        };
        let fm = g(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == neg_a {
            (a, fa) = (m, fm);
        } else {
            (b, fb) = (m, fm);
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(s: &Superellipsoid, ray: &Ray) -> Vec<f64> {
        let mut v = Vec::new();
        s.hits(ray, 0.0, f64::INFINITY, &mut |t| {
            v.push(t);
            true
        });
        v
    }

    #[test]
    fn exponent_one_is_a_sphere_and_small_ones_a_box() {
        let s = Superellipsoid::new(1.0, 1.0);
        let ray = Ray::new(DVec3::new(0.3, 0.2, -5.0), DVec3::Z);
        let h = all(&s, &ray);
        let z = (1.0 - 0.13f64).sqrt();
        assert_eq!(h.len(), 2);
        assert!((h[0] - (5.0 - z)).abs() < 1e-10 && (h[1] - (5.0 + z)).abs() < 1e-10);
        let n = s.normal(ray.at(h[0])).normalize();
        assert!((n - DVec3::new(0.3, 0.2, -z)).length() < 1e-9);
        // Nearly a cube: flat faces at ±1.
        let b = Superellipsoid::new(0.05, 0.05);
        let h = all(&b, &Ray::new(DVec3::new(0.5, -0.6, -5.0), DVec3::Z));
        assert!(
            (h[0] - 4.0).abs() < 1e-6 && (h[1] - 6.0).abs() < 1e-6,
            "{h:?}"
        );
        let n = b.normal(DVec3::new(0.5, -0.6, -1.0)).normalize();
        assert!((n + DVec3::Z).length() < 1e-6);
        assert!(b.inside(DVec3::splat(0.9)) && !b.inside(DVec3::splat(1.01)));
    }

    #[test]
    fn a_pinched_profile_keeps_its_thin_rim() {
        // <1, 3>: at z = 0 the shape is the unit disc, and at radius 0.999 it is
        // only ±(1 − 0.999^(2/3))^(3/2) ≈ ±1.7e-5 thick.
        let s = Superellipsoid::new(1.0, 3.0);
        let h = all(&s, &Ray::new(DVec3::new(0.999, 0.0, -2.0), DVec3::Z));
        let half = (1.0 - 0.999f64.powf(2.0 / 3.0)).powf(1.5);
        assert_eq!(h.len(), 2, "{h:?}");
        assert!((h[0] - (2.0 - half)).abs() < 1e-9 && (h[1] - (2.0 + half)).abs() < 1e-9);
    }

    #[test]
    fn crossings_lie_on_the_surface_for_every_exponent() {
        let mut seed = 99u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        for (e, n) in [
            (0.1, 0.1),
            (0.3, 1.0),
            (1.0, 2.0),
            (2.0, 0.5),
            (3.0, 3.0),
            (0.5, 3.0),
        ] {
            let s = Superellipsoid::new(e, n);
            let mut count = 0;
            for _ in 0..500 {
                let o = DVec3::new(rnd(), rnd(), rnd()) * 4.0;
                let target = DVec3::new(rnd(), rnd(), rnd()) * 0.8;
                let ray = Ray::new(o, target - o);
                let h = all(&s, &ray);
                for w in h.windows(2) {
                    assert!(w[0] < w[1]);
                }
                for &t in &h {
                    let v = s.norm(ray.at(t));
                    assert!((v - 1.0).abs() < 1e-9, "<{e}, {n}>: N = {v}");
                    count += 1;
                }
                // The ray's start is outside, so crossings come in pairs.
                if !s.inside(o) {
                    assert!(h.len().is_multiple_of(2), "<{e}, {n}>: {h:?}");
                }
            }
            assert!(count > 200, "<{e}, {n}>: {count}");
        }
    }
}
