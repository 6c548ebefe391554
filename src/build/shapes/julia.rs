//! `julia_fractal`: a 4D Julia set `z ← f(z) + c` cut by a 3D hyperplane.
//!
//! A point of the slice is inside when its orbit stays within the bailout
//! radius 2 for `max_iteration` steps (POV-Ray's rule), so the surface is the
//! boundary of that iteration-limited set. Rays march through the bounding
//! sphere with steps from the distance estimate `|z| ln|z| / 2|z'|` (at least
//! `1 / precision` of the shape's size divided by 64, so thin parts of a coarse
//! estimate are still sampled), and bisect where a step goes from outside to
//! inside. The normal is the gradient of `|zₖ|²` for the step `k` at which the
//! points just outside escape.
//!
//! Quaternions multiply as `(a, v)(b, w) = (ab − v·w, aw + bv + v × w)`; only
//! `sqr` and `cube` are defined for them. Hypercomplex (bicomplex) numbers
//! `x + yi + zj + wk` (`ij = k`, `k² = 1`) split into two complex numbers
//! `(x − w) + (y + z)i` and `(x + w) + (y − z)i` on which any complex function
//! acts separately.

use crate::build::Ray;
pub use crate::scene::{Algebra, Julia, JuliaFn};
use glam::{DVec3, DVec4};

/// The bailout: orbits whose squared norm passes this escape.
const BAILOUT2: f64 = 4.0;
/// Most steps one ray may take through one fractal.
const MAX_MARCH: usize = 1 << 14;

/// A complex number.
#[derive(Clone, Copy, Debug, PartialEq)]
struct C(f64, f64);

impl C {
    fn add(self, o: C) -> C {
        C(self.0 + o.0, self.1 + o.1)
    }
    fn sub(self, o: C) -> C {
        C(self.0 - o.0, self.1 - o.1)
    }
    fn mul(self, o: C) -> C {
        C(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
    fn div(self, o: C) -> C {
        let d = o.0 * o.0 + o.1 * o.1;
        C(
            (self.0 * o.0 + self.1 * o.1) / d,
            (self.1 * o.0 - self.0 * o.1) / d,
        )
    }
    fn scale(self, k: f64) -> C {
        C(self.0 * k, self.1 * k)
    }
    fn norm2(self) -> f64 {
        self.0 * self.0 + self.1 * self.1
    }
    fn exp(self) -> C {
        let e = self.0.exp();
        C(e * self.1.cos(), e * self.1.sin())
    }
    fn ln(self) -> C {
        C(0.5 * self.norm2().ln(), self.1.atan2(self.0))
    }
    fn sqrt(self) -> C {
        let r = self.norm2().sqrt().sqrt();
        let a = 0.5 * self.1.atan2(self.0);
        C(r * a.cos(), r * a.sin())
    }
    fn sin(self) -> C {
        C(self.0.sin() * self.1.cosh(), self.0.cos() * self.1.sinh())
    }
    fn cos(self) -> C {
        C(self.0.cos() * self.1.cosh(), -self.0.sin() * self.1.sinh())
    }
    fn sinh(self) -> C {
        C(self.0.sinh() * self.1.cos(), self.0.cosh() * self.1.sin())
    }
    fn cosh(self) -> C {
        C(self.0.cosh() * self.1.cos(), self.0.sinh() * self.1.sin())
    }
    /// `f(z)` and `f'(z)`.
    fn apply(self, f: JuliaFn) -> (C, C) {
        const ONE: C = C(1.0, 0.0);
        const I: C = C(0.0, 1.0);
        let z = self;
        let z2 = z.mul(z);
        match f {
            JuliaFn::Sqr => (z2, z.scale(2.0)),
            JuliaFn::Cube => (z2.mul(z), z2.scale(3.0)),
            JuliaFn::Exp => {
                let e = z.exp();
                (e, e)
            }
            JuliaFn::Reciprocal => (ONE.div(z), C(-1.0, 0.0).div(z2)),
            JuliaFn::Sin => (z.sin(), z.cos()),
            JuliaFn::Cos => (z.cos(), z.sin().scale(-1.0)),
            JuliaFn::Sinh => (z.sinh(), z.cosh()),
            JuliaFn::Cosh => (z.cosh(), z.sinh()),
            JuliaFn::Tan => {
                let (s, c) = (z.sin(), z.cos());
                (s.div(c), ONE.div(c.mul(c)))
            }
            JuliaFn::Tanh => {
                let (s, c) = (z.sinh(), z.cosh());
                (s.div(c), ONE.div(c.mul(c)))
            }
            JuliaFn::Ln => (z.ln(), ONE.div(z)),
            JuliaFn::Asin => {
                // asin z = −i ln(iz + √(1 − z²))
                let r = ONE.sub(z2).sqrt();
                (I.mul(z).add(r).ln().mul(C(0.0, -1.0)), ONE.div(r))
            }
            JuliaFn::Acos => {
                // acos z = π/2 − asin z
                let r = ONE.sub(z2).sqrt();
                let asin = I.mul(z).add(r).ln().mul(C(0.0, -1.0));
                (
                    C(std::f64::consts::FRAC_PI_2, 0.0).sub(asin),
                    C(-1.0, 0.0).div(r),
                )
            }
            JuliaFn::Asinh => {
                let r = z2.add(ONE).sqrt();
                (z.add(r).ln(), ONE.div(r))
            }
            JuliaFn::Acosh => {
                let r = z.sub(ONE).sqrt().mul(z.add(ONE).sqrt());
                (z.add(r).ln(), ONE.div(r))
            }
            JuliaFn::Atan => {
                // atan z = (i/2) ln((i + z)/(i − z))
                let v = I.add(z).div(I.sub(z)).ln().mul(C(0.0, 0.5));
                (v, ONE.div(ONE.add(z2)))
            }
            JuliaFn::Atanh => {
                let v = ONE.add(z).div(ONE.sub(z)).ln().scale(0.5);
                (v, ONE.div(ONE.sub(z2)))
            }
            JuliaFn::Pwr(x, y) => {
                let w = C(x, y);
                let v = w.mul(z.ln()).exp();
                (v, w.mul(v).div(z))
            }
        }
    }
}

impl Julia {
    /// The radius of the sphere around the origin the set lies in.
    pub fn radius(&self) -> f64 {
        let c = self.c.length();
        let escape = match self.function {
            JuliaFn::Sqr => 0.5 * (1.0 + (1.0 + 4.0 * c).sqrt()),
            JuliaFn::Cube => 1.0 + c.sqrt(),
            _ => 2.0,
        };
        let r = escape.max(2.0);
        // Hypercomplex norms mix the two complex parts: a point may stay inside
        // a little beyond the quaternion bound.
        match self.algebra {
            Algebra::Quaternion => r,
            Algebra::Hypercomplex => r * std::f64::consts::SQRT_2,
        }
    }

    /// The 4D point of the slice at 3D point `p`.
    #[inline]
    fn lift(&self, p: DVec3) -> DVec4 {
        let n = self.slice_normal;
        let w = (self.slice_distance - n.x * p.x - n.y * p.y - n.z * p.z) / n.w;
        DVec4::new(p.x, p.y, p.z, w)
    }

    /// The orbit of `p`: the step at which it escaped (`None`: it stayed in),
    /// the last `|z|²` and `|z'|²` (for the distance estimate).
    fn orbit(&self, p: DVec3) -> (Option<u32>, f64, f64) {
        let z0 = self.lift(p);
        match self.algebra {
            Algebra::Quaternion => self.orbit_quaternion(z0),
            Algebra::Hypercomplex => self.orbit_hypercomplex(z0),
        }
    }

    fn orbit_quaternion(&self, z0: DVec4) -> (Option<u32>, f64, f64) {
        let mut z = z0;
        let mut dz = 1.0f64; // |z'|, scalar bound on the derivative's size
        let cube = matches!(self.function, JuliaFn::Cube);
        for k in 0..self.max_iteration {
            let (a, v) = (z.x, DVec3::new(z.y, z.z, z.w));
            let n2 = z.length_squared();
            let next = if cube {
                dz *= 3.0 * n2;
                let vv = v.length_squared();
                let re = a * a * a - 3.0 * a * vv;
                let im = v * (3.0 * a * a - vv);
                DVec4::new(re, im.x, im.y, im.z)
            } else {
                dz *= 2.0 * n2.sqrt();
                let im = v * (2.0 * a);
                DVec4::new(a * a - v.length_squared(), im.x, im.y, im.z)
            };
            z = next + self.c;
            let n2 = z.length_squared();
            if n2 > BAILOUT2 || !n2.is_finite() {
                return (Some(k), n2, dz * dz);
            }
        }
        (None, z.length_squared(), dz * dz)
    }

    fn orbit_hypercomplex(&self, z0: DVec4) -> (Option<u32>, f64, f64) {
        let split = |z: DVec4| (C(z.x - z.w, z.y + z.z), C(z.x + z.w, z.y - z.z));
        let (mut a, mut b) = split(z0);
        let (ca, cb) = split(self.c);
        let (mut da, mut db) = (C(1.0, 0.0), C(1.0, 0.0));
        let norm2 = |a: C, b: C| 0.5 * (a.norm2() + b.norm2());
        for k in 0..self.max_iteration {
            let (fa, fda) = a.apply(self.function);
            let (fb, fdb) = b.apply(self.function);
            da = fda.mul(da);
            db = fdb.mul(db);
            a = fa.add(ca);
            b = fb.add(cb);
            let n2 = norm2(a, b);
            if n2 > BAILOUT2 || !n2.is_finite() {
                return (Some(k), n2, norm2(da, db));
            }
        }
        (None, norm2(a, b), norm2(da, db))
    }

    /// `|zₖ|²` of `p` (or of the last step, if it escapes sooner), for normals.
    fn potential(&self, p: DVec3, k: u32) -> f64 {
        // The escape test stops at bailout; run the fixed count without it.
        let z0 = self.lift(p);
        match self.algebra {
            Algebra::Quaternion => {
                let mut z = z0;
                let cube = matches!(self.function, JuliaFn::Cube);
                for _ in 0..=k {
                    let (a, v) = (z.x, DVec3::new(z.y, z.z, z.w));
                    let vv = v.length_squared();
                    let next = if cube {
                        let im = v * (3.0 * a * a - vv);
                        DVec4::new(a * a * a - 3.0 * a * vv, im.x, im.y, im.z)
                    } else {
                        let im = v * (2.0 * a);
                        DVec4::new(a * a - vv, im.x, im.y, im.z)
                    };
                    z = next + self.c;
                }
                z.length_squared()
            }
            Algebra::Hypercomplex => {
                let split = |z: DVec4| (C(z.x - z.w, z.y + z.z), C(z.x + z.w, z.y - z.z));
                let (mut a, mut b) = split(z0);
                let (ca, cb) = split(self.c);
                for _ in 0..=k {
                    a = a.apply(self.function).0.add(ca);
                    b = b.apply(self.function).0.add(cb);
                }
                0.5 * (a.norm2() + b.norm2())
            }
        }
    }

    /// Whether `p` is inside (its orbit stays bounded for `max_iteration` steps).
    pub fn inside(&self, p: DVec3) -> bool {
        p.length_squared() < self.radius() * self.radius() && self.orbit(p).0.is_none()
    }

    /// A lower estimate of the distance from `p` to the set (0 inside).
    fn distance(&self, p: DVec3) -> f64 {
        match self.orbit(p) {
            (None, _, _) => 0.0,
            (Some(_), z2, dz2) => {
                let z = z2.sqrt();
                let dz = dz2.sqrt();
                if dz > 0.0 && z > 1.0 && dz.is_finite() {
                    0.5 * z * z.ln() / dz
                } else {
                    0.0
                }
            }
        }
    }

    /// Every crossing in `(t_min, t_max)`, in order; `f` returns false to stop.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64) -> bool) {
        let r = self.radius();
        let Some((t0, t1)) = crate::build::shape::sphere_roots(DVec3::ZERO, r, ray) else {
            return;
        };
        let a = t0.max(t_min);
        let b = t1.min(t_max);
        if a >= b {
            return;
        }
        let len = ray.dir.length();
        if len == 0.0 || !len.is_finite() {
            return;
        }
        // Steps never smaller than this (object units), roots found to `eps`.
        let min_step = (r / (64.0 * self.precision.max(1e-3))).min(r * 1e-2);
        let eps = r * 1e-7;
        let mut t = a;
        let mut inside = self.orbit(ray.at(t)).0.is_none();
        let mut steps = 0;
        while t < b && steps < MAX_MARCH {
            steps += 1;
            let step = if inside {
                min_step
            } else {
                (0.5 * self.distance(ray.at(t))).max(min_step)
            } / len;
            let tn = (t + step).min(b);
            let now = self.orbit(ray.at(tn)).0.is_none();
            if now != inside {
                let (mut lo, mut hi) = (t, tn);
                while (hi - lo) * len > eps && steps < MAX_MARCH {
                    steps += 1;
                    let mid = 0.5 * (lo + hi);
                    if (self.orbit(ray.at(mid)).0.is_none()) == inside {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let root = 0.5 * (lo + hi);
                // A crossing this close to the ray's start is the surface it
                // leaves: skipped so the fractal does not shadow itself.
                if root > t_min && root < t_max && (root - t_min) * len > 16.0 * eps && !f(root) {
                    return;
                }
                inside = now;
            }
            t = tn;
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

    /// The outward normal at surface point `p` (unnormalised).
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let r = self.radius();
        let h = r * 1e-5;
        // The step at which points just off the surface escape: the nearest
        // escaping sample around p decides.
        let mut k = self.max_iteration.saturating_sub(1);
        for d in [
            DVec3::X,
            DVec3::NEG_X,
            DVec3::Y,
            DVec3::NEG_Y,
            DVec3::Z,
            DVec3::NEG_Z,
        ] {
            if let (Some(e), _, _) = self.orbit(p + d * (4.0 * h)) {
                k = k.min(e);
            }
        }
        let g = |q: DVec3| self.potential(q, k).max(1e-300).ln();
        let n = DVec3::new(
            g(p + DVec3::X * h) - g(p - DVec3::X * h),
            g(p + DVec3::Y * h) - g(p - DVec3::Y * h),
            g(p + DVec3::Z * h) - g(p - DVec3::Z * h),
        );
        if n.is_finite() && n.length_squared() > 0.0 {
            n
        } else {
            p
        }
    }

    /// The bounding box (of the bounding sphere).
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let r = self.radius();
        (DVec3::splat(-r), DVec3::splat(r))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn julia(c: DVec4, algebra: Algebra, function: JuliaFn) -> Julia {
        Julia {
            c,
            algebra,
            function,
            max_iteration: 20,
            precision: 20.0,
            slice_normal: DVec4::W,
            slice_distance: 0.0,
        }
    }

    #[test]
    fn c_zero_is_the_unit_ball() {
        // z ← z² keeps |z| ≤ 1 bounded and sends |z| > 1 beyond 2 quickly.
        let j = julia(DVec4::ZERO, Algebra::Quaternion, JuliaFn::Sqr);
        assert!(j.inside(DVec3::new(0.5, 0.3, 0.2)));
        assert!(!j.inside(DVec3::new(1.1, 0.0, 0.0)));
        let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        let t = j.nearest(&ray, 0.0, f64::INFINITY).expect("hit");
        assert!((t - 4.0).abs() < 1e-3, "{t}");
        let n = j.normal(DVec3::new(0.0, 0.0, -1.0)).normalize();
        assert!(n.z < -0.99, "{n}");
    }

    #[test]
    fn hypercomplex_sqr_matches_the_complex_plane() {
        // On the slice y = z = w = 0 both parts are the same real number.
        let j = julia(
            DVec4::new(-0.5, 0.0, 0.0, 0.0),
            Algebra::Hypercomplex,
            JuliaFn::Sqr,
        );
        assert!(j.inside(DVec3::new(0.2, 0.0, 0.0)));
        assert!(!j.inside(DVec3::new(1.9, 0.0, 0.0)));
    }

    #[test]
    fn complex_functions_have_their_derivatives() {
        let z = C(0.3, -0.4);
        let h = 1e-6;
        for name in JuliaFn::NAMES.iter().filter(|n| **n != "pwr") {
            let f = JuliaFn::from_name(name).unwrap();
            let (a, d) = z.apply(f);
            let (b, _) = z.add(C(h, 0.0)).apply(f);
            let num = b.sub(a).scale(1.0 / h);
            assert!(num.sub(d).norm2().sqrt() < 1e-4, "{name}: {num:?} vs {d:?}");
        }
    }
}
