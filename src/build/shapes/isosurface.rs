//! `isosurface { function { … } contained_by { … } … }`: the surface where a
//! function equals its threshold, found along each ray inside the container.
//!
//! The function is bounded in slope by `max_gradient` (a Lipschitz bound), so
//! at a point where it is `|f - threshold|` away from the threshold the surface
//! is at least `|f - threshold| / max_gradient` away: the march steps that far
//! (at least `accuracy`), and where the sign changes it bisects to `accuracy`.
//! Inside is where the function is below the threshold (within the container);
//! where the container's surface is inside, it shows (unless `open`).

use crate::build::Ray;
pub use crate::scene::{Container, Isosurface};
use glam::DVec3;

impl Container {
    /// Entry and exit parameters of `ray` through the container.
    pub fn span(&self, ray: &Ray) -> Option<(f64, f64)> {
        match *self {
            Container::Box { min, max } => crate::build::shape::box_span(min, max, ray),
            Container::Sphere { center, radius } => {
                crate::build::shape::sphere_roots(center, radius, ray)
            }
        }
    }

    /// Whether `p` is strictly inside.
    pub fn contains(&self, p: DVec3) -> bool {
        match *self {
            Container::Box { min, max } => p.cmpgt(min).all() && p.cmplt(max).all(),
            Container::Sphere { center, radius } => (p - center).length_squared() < radius * radius,
        }
    }

    /// The outward normal of the container's surface near `p`.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        match *self {
            Container::Box { min, max } => crate::build::shape::box_normal(min, max, p),
            Container::Sphere { center, .. } => p - center,
        }
    }

    /// The container's bounding box.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        match *self {
            Container::Box { min, max } => (min, max),
            Container::Sphere { center, radius } => {
                (center - DVec3::splat(radius), center + DVec3::splat(radius))
            }
        }
    }
}

/// Most function evaluations one ray may spend in one isosurface (a function
/// far steeper than its `max_gradient` promise cannot hang the render).
const MAX_STEPS: usize = 1 << 16;

impl Isosurface {
    /// The function minus the threshold at `p` (NaN reads as outside).
    #[inline]
    fn g(&self, p: DVec3) -> f64 {
        let v = self.function.eval3(p) - self.threshold;
        if v.is_nan() {
            f64::MAX
        } else {
            v
        }
    }

    /// Every crossing in `(t_min, t_max)`, in order, with its part (0 the
    /// function's surface, 1 the container's); stops after the first when
    /// `first_only`.
    pub fn hits(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        first_only: bool,
        f: &mut dyn FnMut(f64, u32),
    ) {
        let limit = if first_only || self.max_trace == 1 {
            1
        } else if self.max_trace == 0 {
            usize::MAX
        } else {
            self.max_trace as usize
        };
        let mut found = 0usize;
        let Some((t0, t1)) = self.container.span(ray) else {
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
        let min_step = self.accuracy.max(1e-9) / len;
        let slope = self.max_gradient.max(1e-9) * len;
        let mut t = a;
        let mut gt = self.g(ray.at(t));
        if t0 > t_min && !self.open && gt < 0.0 {
            f(t0, 1);
            found += 1;
            if found >= limit {
                return;
            }
        }
        let mut steps = 0;
        // The steepest secant between march points (a lower bound on the
        // function's slope), for the warning after the render.
        let mut steepest = 0.0f64;
        while t < b && steps < MAX_STEPS {
            steps += 1;
            let step = (gt.abs() / slope).max(min_step);
            let tn = (t + step).min(b);
            let gn = self.g(ray.at(tn));
            // Only a secant steeper than the bound is worth a division.
            let rise = (gn - gt).abs();
            if rise > slope * (tn - t) && gn != f64::MAX && gt != f64::MAX {
                steepest = steepest.max(rise / (tn - t));
            }
            if (gt < 0.0) != (gn < 0.0) {
                // Bisect to the accuracy.
                let (mut lo, mut hi, mut glo) = (t, tn, gt);
                while hi - lo > min_step * 0.5 && steps < MAX_STEPS {
                    steps += 1;
                    let mid = 0.5 * (lo + hi);
                    let gm = self.g(ray.at(mid));
                    let rise = (gm - glo).abs();
                    if rise > slope * (mid - lo) && gm != f64::MAX && glo != f64::MAX {
                        steepest = steepest.max(rise / (mid - lo));
                    }
                    if (gm < 0.0) == (glo < 0.0) {
                        lo = mid;
                        glo = gm;
                    } else {
                        hi = mid;
                    }
                }
                let root = 0.5 * (lo + hi);
                // A root within twice the accuracy of the ray's start is the
                // surface the ray leaves (found only that closely): skipped, as
                // POV-Ray does, so surfaces do not shadow themselves.
                if root > t_min && root < t_max && root * len > 2.0 * self.accuracy {
                    f(root, 0);
                    found += 1;
                    if found >= limit {
                        self.note_slope(steepest, len);
                        return;
                    }
                }
            }
            t = tn;
            gt = gn;
        }
        self.note_slope(steepest, len);
        if t1 < t_max && !self.open && gt < 0.0 && t1 > t_min {
            f(t1, 1);
        }
    }

    /// Notes `steepest` (a slope per unit of the ray's parameter; `len` the
    /// length of its direction) when it exceeds `max_gradient`.
    fn note_slope(&self, steepest: f64, len: f64) {
        let slope = steepest / len;
        if slope > self.max_gradient {
            self.steepest.observe(slope);
        }
    }

    /// The nearest crossing in `(t_min, t_max)` and its part.
    pub fn nearest(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, u32)> {
        let mut best = None;
        self.hits(ray, t_min, t_max, true, &mut |t, sub| {
            if best.is_none() {
                best = Some((t, sub));
            }
        });
        best
    }

    /// The outward normal at `p` on part `sub`: the function's gradient, or the
    /// container's normal.
    pub fn normal(&self, p: DVec3, sub: u32) -> DVec3 {
        if sub == 1 {
            return self.container.normal(p);
        }
        let h = (self.accuracy * 0.5).max(1e-7);
        let gx = self.function.eval3(p + DVec3::X * h) - self.function.eval3(p - DVec3::X * h);
        let gy = self.function.eval3(p + DVec3::Y * h) - self.function.eval3(p - DVec3::Y * h);
        let gz = self.function.eval3(p + DVec3::Z * h) - self.function.eval3(p - DVec3::Z * h);
        let n = DVec3::new(gx, gy, gz);
        if n.length_squared() > 0.0 && n.is_finite() {
            n
        } else {
            self.container.normal(p)
        }
    }

    /// Whether `p` is inside: in the container and below the threshold.
    pub fn inside(&self, p: DVec3) -> bool {
        self.container.contains(p) && self.g(p) < 0.0
    }

    /// The largest slope of the function measured on a grid of points in the
    /// container (central differences), for the `max_gradient` warning.
    pub fn measured_gradient(&self) -> f64 {
        let (lo, hi) = self.container.bounds();
        let size = hi - lo;
        let n = 8;
        let h = size.max_element() * 1e-4;
        // The points are independent (and max is order-free): sampled in
        // parallel, as a pigment function can cost thousands of instructions.
        use rayon::prelude::*;
        (0..n * n * n)
            .into_par_iter()
            .map(|idx| {
                let (i, j, k) = (idx / (n * n), (idx / n) % n, idx % n);
                let c = lo + size * (DVec3::new(i as f64, j as f64, k as f64) + 0.5) / n as f64;
                if !self.container.contains(c) {
                    return 0.0;
                }
                let f = |q: DVec3| self.function.eval3(q);
                let g = DVec3::new(
                    f(c + DVec3::X * h) - f(c - DVec3::X * h),
                    f(c + DVec3::Y * h) - f(c - DVec3::Y * h),
                    f(c + DVec3::Z * h) - f(c - DVec3::Z * h),
                ) / (2.0 * h);
                let l = g.length();
                if l.is_finite() {
                    l
                } else {
                    0.0
                }
            })
            .reduce(|| 0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::function::{Body, Op};
    use crate::scene::Function;
    use std::sync::Arc;

    fn sphere_fn() -> Arc<Function> {
        // sqrt(x*x + y*y + z*z) - 1
        Arc::new(Function {
            arity: 3,
            body: Body::Float(vec![
                Op::Param(0),
                Op::Param(0),
                Op::Mul,
                Op::Param(1),
                Op::Param(1),
                Op::Mul,
                Op::Add,
                Op::Param(2),
                Op::Param(2),
                Op::Mul,
                Op::Add,
                Op::F1(f64::sqrt),
                Op::Const(1.0),
                Op::Sub,
            ]),
            depth: 1,
        })
    }

    fn iso(open: bool, r: f64) -> Isosurface {
        Isosurface {
            function: sphere_fn(),
            container: Container::Box {
                min: DVec3::splat(-r),
                max: DVec3::splat(r),
            },
            threshold: 0.0,
            accuracy: 1e-4,
            max_gradient: 1.1,
            open,
            max_trace: 0,
            steepest: Default::default(),
        }
    }

    #[test]
    fn unit_sphere_roots() {
        let s = iso(false, 2.0);
        let ray = Ray::new(DVec3::new(0.1, 0.2, -5.0), DVec3::Z);
        let mut ts = Vec::new();
        s.hits(&ray, 0.0, f64::INFINITY, false, &mut |t, sub| {
            ts.push((t, sub))
        });
        let d = (1.0f64 - 0.05).sqrt();
        assert_eq!(ts.len(), 2, "{ts:?}");
        assert!((ts[0].0 - (5.0 - d)).abs() < 1e-4 && ts[0].1 == 0);
        assert!((ts[1].0 - (5.0 + d)).abs() < 1e-4);
        let n = s.normal(ray.at(ts[0].0), 0).normalize();
        assert!((n - ray.at(ts[0].0).normalize()).length() < 1e-3);
        assert!(s.inside(DVec3::ZERO) && !s.inside(DVec3::splat(0.9)));
    }

    #[test]
    fn container_cuts_the_surface() {
        // A container smaller than the sphere: the box's faces show.
        let s = iso(false, 0.5);
        let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z * 2.0);
        let (t, sub) = s.nearest(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((t - 2.25).abs() < 1e-9 && sub == 1);
        let open = iso(true, 0.5);
        assert!(open.nearest(&ray, 0.0, f64::INFINITY).is_none());
    }

    #[test]
    fn measured_gradient_of_distance_is_one() {
        let g = iso(false, 2.0).measured_gradient();
        assert!((g - 1.0).abs() < 1e-3, "{g}");
    }

    #[test]
    fn the_march_notes_slopes_above_max_gradient_only() {
        // A distance function (slope 1) under its bound 1.1: nothing noted,
        // whatever the ray's length.
        let s = iso(false, 2.0);
        let ray = Ray::new(DVec3::new(0.1, 0.2, -5.0), DVec3::Z * 3.0);
        s.nearest(&ray, 0.0, f64::INFINITY);
        assert_eq!(s.steepest.steepest(), 0.0);
        // The same surface with a bound below its slope: the slope is noted,
        // in object units (the direction's length divided out).
        let mut low = iso(false, 2.0);
        low.max_gradient = 0.5;
        low.nearest(&ray, 0.0, f64::INFINITY);
        let seen = low.steepest.steepest();
        assert!(seen > 0.5 && seen <= 1.0 + 1e-9, "{seen}");
        // Copies share the meter.
        assert_eq!(low.clone().steepest.steepest(), seen);
    }
}
