//! `lathe`: a 2-D spline in the x-y plane revolved around the y axis.
//!
//! The spline is a list of segments, each `<x(s), y(s)>` with polynomials of
//! degree ≤ 3 in `s ∈ [0, 1]` (the same segments as `prism`'s outlines, see
//! [`super::prism`]); x is the radius. A ray `o + t d` meets the surface of a
//! segment where `y(s) = o.y + t d.y` and `x(s)² = |o_h + t d_h|²` (`_h` the x-z
//! part). Eliminating t gives, for `d.y ≠ 0`,
//!
//! `a (y − o.y)² + 2 b d.y (y − o.y) + c d.y² − d.y² x² = 0`, with `a = d_h·d_h`,
//! `b = o_h·d_h`, `c = o_h·o_h`,
//!
//! a polynomial of degree ≤ 6 in s solved by [`super::revolve::roots_in`]. For
//! rays (nearly) parallel to the x-z plane that equation degenerates (its roots
//! come in pairs around `y(s) = o.y`), so there the cubic `y(s) = o.y` is solved
//! and t follows from the radius. Either way each hit is polished by Newton steps
//! on the two equations in `(s, t)`.
//!
//! Inside (POV-Ray's rule, measured with its `inside()`): a point at radius r and
//! height y is inside when r is at least the curve's smallest radius and a
//! half-line from `<r, y>` towards +x crosses the curve an odd number of times.

use super::prism::{self, at, closest, curve_box, roots01, tangent, Curve, Spline};
use super::revolve::{mul, roots_in, MAX_DEGREE};
use crate::build::{Aabb, Ray};
use glam::{DVec2, DVec3};

/// The fewest points POV-Ray accepts in a `lathe` of this spline type.
pub fn min_points(spline: Spline) -> usize {
    match spline {
        Spline::Linear => 2,
        Spline::Quadratic => 3,
        Spline::Cubic | Spline::Bezier => 4,
    }
}

/// Which points are control points only (not on the curve), for messages.
pub fn point_rule(spline: Spline) -> &'static str {
    match spline {
        Spline::Linear => "every point is on the curve; each two neighbours make a segment",
        Spline::Quadratic => "the first point is a control point; each further point ends a segment",
        Spline::Cubic => {
            "the first and the last points are control points; each point between them is on the curve"
        }
        Spline::Bezier => "every 4 points are one segment: start, two controls, end",
    }
}

/// Whether point `i` of `n` must have x ≥ 0 (POV-Ray: "Incorrect point in
/// lathe"): every point except the control points of quadratic and cubic splines.
pub fn radius_checked(spline: Spline, i: usize, n: usize) -> bool {
    match spline {
        Spline::Linear | Spline::Bezier => true,
        Spline::Quadratic => i > 0,
        Spline::Cubic => i > 0 && i + 1 < n,
    }
}

/// The segments of POV-Ray's point list (`<x, y>` points; the count is checked
/// by the caller, extra Bézier points are ignored).
pub fn segments(spline: Spline, p: &[DVec2]) -> Vec<Curve> {
    let n = p.len();
    match spline {
        Spline::Linear => p.windows(2).map(|w| prism::line(w[0], w[1])).collect(),
        Spline::Quadratic => p
            .windows(3)
            .map(|w| prism::quadratic(w[0], w[1], w[2]))
            .collect(),
        Spline::Cubic => p
            .windows(4)
            .map(|w| prism::catmull_rom(w[0], w[1], w[2], w[3]))
            .collect(),
        Spline::Bezier => (0..n / 4)
            .map(|k| prism::bezier(p[4 * k], p[4 * k + 1], p[4 * k + 2], p[4 * k + 3]))
            .collect(),
    }
}

/// A lathe ready for rays.
#[derive(Clone, Debug, PartialEq)]
pub struct Lathe {
    curves: Vec<Curve>,
    /// Per segment: its `<x, y>` bounds `(min, max)`.
    boxes: Vec<(DVec2, DVec2)>,
    /// Per segment: its largest |x|.
    radius: Vec<f64>,
    /// Smallest x of the curve (inside needs at least this radius).
    r_min: f64,
    /// Largest |x| of the curve.
    r_max: f64,
    /// Lowest and highest y.
    h: [f64; 2],
}

impl Lathe {
    /// A lathe of `curves` (`<x, y>` segments).
    pub fn new(curves: &[Curve]) -> Lathe {
        let boxes: Vec<_> = curves.iter().map(curve_box).collect();
        let radius: Vec<f64> = boxes.iter().map(|b| b.0.x.abs().max(b.1.x.abs())).collect();
        let lo = boxes.iter().fold(DVec2::INFINITY, |m, b| m.min(b.0));
        let hi = boxes.iter().fold(DVec2::NEG_INFINITY, |m, b| m.max(b.1));
        Lathe {
            curves: curves.to_vec(),
            boxes,
            r_max: radius.iter().copied().fold(0.0, f64::max),
            radius,
            r_min: lo.x,
            h: [lo.y, hi.y],
        }
    }

    /// Every crossing of `ray` in `(t_min, t_max)` with its segment index, unordered.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64, u32)) {
        let (o, d) = (ray.origin, ray.dir);
        let a = d.x * d.x + d.z * d.z;
        let b = o.x * d.x + o.z * d.z;
        let c = o.x * o.x + o.z * o.z;
        // Closest approach to the axis (in x-z): at t0, squared distance rho2.
        let (t0, rho2) = if a > 0.0 {
            (-b / a, (c - b * b / a).max(0.0))
        } else {
            (0.0, c)
        };
        if rho2 > self.r_max * self.r_max {
            return;
        }
        let flat = d.y * d.y < 1e-10 * a;
        let last = self.curves.len().saturating_sub(1);
        for (i, cv) in self.curves.iter().enumerate() {
            let r = self.radius[i];
            if rho2 > r * r {
                continue;
            }
            // The ray's heights while it is within the segment's radius.
            let (y0, y1) = (self.boxes[i].0.y, self.boxes[i].1.y);
            if a > 0.0 {
                let w = ((r * r - rho2) / a).sqrt();
                let (ya, yb) = (o.y + (t0 - w) * d.y, o.y + (t0 + w) * d.y);
                if ya.max(yb) < y0 || ya.min(yb) > y1 {
                    continue;
                }
            } else if d.y == 0.0 {
                continue;
            }
            let seg = Segment {
                c: cv,
                o,
                d,
                a,
                b,
                cc: c,
            };
            let mut put = |s: f64, t: f64| {
                if let Some((s, t)) = seg.polish(s, t) {
                    let s_ok = s >= -1e-9 && (s < 1.0 || (i == last && s <= 1.0 + 1e-9));
                    if s_ok && t > t_min && t < t_max {
                        f(t, i as u32);
                    }
                }
            };
            if flat {
                // y(s) = o.y, then the radius gives t on either side of t0.
                let k = [cv[0].y - o.y, cv[1].y, cv[2].y, cv[3].y];
                let mut r3 = [0.0; 3];
                let m = roots01(k, &mut r3);
                for &s in &r3[..m] {
                    let x = at(cv, s).x;
                    let e = x * x - rho2;
                    if e < 0.0 {
                        continue;
                    }
                    let w = (e / a).sqrt();
                    put(s, t0 - w);
                    put(s, t0 + w);
                }
            } else {
                let yc = [cv[0].y - o.y, cv[1].y, cv[2].y, cv[3].y];
                let x = [cv[0].x, cv[1].x, cv[2].x, cv[3].x];
                let yy = mul(&yc, &yc);
                let xx = mul(&x, &x);
                let mut p = [0.0; MAX_DEGREE + 1];
                for k in 0..=MAX_DEGREE {
                    p[k] = a * yy[k] - d.y * d.y * xx[k];
                }
                for k in 0..4 {
                    p[k] += 2.0 * b * d.y * yc[k];
                }
                p[0] += c * d.y * d.y;
                let mut roots = [0.0; MAX_DEGREE];
                let m = roots_in(&p, 0.0, 1.0, &mut roots);
                for &s in &roots[..m] {
                    let y = at(cv, s).y - o.y;
                    put(s, y / d.y);
                }
            }
        }
    }

    /// The nearest crossing in `(t_min, t_max)` and its segment index.
    pub fn nearest(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, u32)> {
        let mut best: Option<(f64, u32)> = None;
        self.hits(ray, t_min, t_max, &mut |t, sub| {
            if best.is_none_or(|b| t < b.0) {
                best = Some((t, sub));
            }
        });
        best
    }

    /// Whether `<r, y>` (radius, height) is inside: at least the smallest radius
    /// and an odd number of crossings towards +x.
    fn inside2(&self, q: DVec2) -> bool {
        q.x >= self.r_min && prism::even_odd(&self.curves, &self.boxes, q)
    }

    /// Whether `p` is strictly inside (POV-Ray's rule, see the module notes).
    pub fn inside(&self, p: DVec3) -> bool {
        self.inside2(DVec2::new(p.x.hypot(p.z), p.y))
    }

    /// Outward normal (unnormalised) at `p` on segment `sub`: out of the region
    /// [`Lathe::inside`] fills.
    pub fn normal(&self, p: DVec3, sub: u32) -> DVec3 {
        let Some(c) = self.curves.get(sub as usize) else {
            return DVec3::Y;
        };
        let rho = p.x.hypot(p.z);
        let q = DVec2::new(rho, p.y);
        let s = closest(c, q);
        let mut t = tangent(c, s);
        if t.length_squared() == 0.0 {
            let (lo, hi) = ((s - 1e-4).max(0.0), (s + 1e-4).min(1.0));
            t = at(c, hi) - at(c, lo);
        }
        let mut n2 = DVec2::new(t.y, -t.x).normalize_or_zero();
        let size = (self.r_max + self.h[1] - self.h[0]).max(1e-300);
        let eps = 1e-6 * size;
        let on = at(c, s);
        if self.inside2(on + n2 * eps) && !self.inside2(on - n2 * eps) {
            n2 = -n2;
        }
        if rho == 0.0 {
            return DVec3::new(0.0, n2.y.signum(), 0.0);
        }
        DVec3::new(n2.x * p.x / rho, n2.y, n2.x * p.z / rho)
    }

    /// POV-Ray's uv coordinates at `p` on segment `sub`: u the angle around y
    /// (as on a sphere), v the curve's parameter across all segments, each
    /// segment an equal share of [0, 1] (measured against POV-Ray).
    pub fn uv(&self, p: DVec3, sub: u32) -> DVec2 {
        let u = super::revolve::around_y(p);
        let Some(c) = self.curves.get(sub as usize) else {
            return DVec2::new(u, 0.0);
        };
        let s = closest(c, DVec2::new(p.x.hypot(p.z), p.y));
        DVec2::new(u, (f64::from(sub) + s) / self.curves.len() as f64)
    }

    /// Bounds in object space; empty for no segments.
    pub fn bounds(&self) -> Aabb {
        if self.curves.is_empty() {
            return Aabb::EMPTY;
        }
        let r = self.r_max;
        let [h0, h1] = self.h;
        let pad = 1e-9 * (1.0 + r.max(h0.abs()).max(h1.abs()));
        Aabb::new(
            DVec3::new(-r - pad, h0 - pad, -r - pad),
            DVec3::new(r + pad, h1 + pad, r + pad),
        )
    }
}

/// One segment against one ray, for polishing hits.
struct Segment<'a> {
    c: &'a Curve,
    o: DVec3,
    d: DVec3,
    a: f64,
    b: f64,
    cc: f64,
}

impl Segment<'_> {
    /// Newton steps on `y(s) − o.y − t d.y = 0`, `a t² + 2 b t + c − x(s)² = 0`
    /// from `(s, t)`; `None` when the start is not near a solution.
    fn polish(&self, mut s: f64, mut t: f64) -> Option<(f64, f64)> {
        let residual = |s: f64, t: f64| {
            let p = at(self.c, s);
            let f1 = p.y - self.o.y - t * self.d.y;
            let f2 = (self.a * t + 2.0 * self.b) * t + self.cc - p.x * p.x;
            (f1, f2, p)
        };
        let (mut f1, mut f2, _) = residual(s, t);
        // Scales to judge the residuals by.
        let scale = |p: DVec2, t: f64| {
            let r2 = (self.a * t + 2.0 * self.b) * t + self.cc;
            (
                1.0 + p.y.abs() + self.o.y.abs() + (t * self.d.y).abs(),
                1.0 + r2.abs() + p.x * p.x,
            )
        };
        for _ in 0..4 {
            let tg = tangent(self.c, s);
            let x = at(self.c, s).x;
            // Jacobian [[y', −d.y], [−2 x x', 2 (a t + b)]].
            let (j11, j12, j21, j22) = (
                tg.y,
                -self.d.y,
                -2.0 * x * tg.x,
                2.0 * (self.a * t + self.b),
            );
            let det = j11 * j22 - j12 * j21;
            if det == 0.0 || !det.is_finite() {
                break;
            }
            let ds = (-f1 * j22 + f2 * j12) / det;
            let dt = (-f2 * j11 + f1 * j21) / det;
            let (ns, nt) = (s + ds, t + dt);
            let (g1, g2, _) = residual(ns, nt);
            let better = g1.abs() + g2.abs() < f1.abs() + f2.abs();
            if !better {
                break;
            }
            (s, t, f1, f2) = (ns, nt, g1, g2);
        }
        let p = at(self.c, s);
        let (k1, k2) = scale(p, t);
        (f1.abs() <= 1e-6 * k1 && f2.abs() <= 1e-6 * k2 && s.is_finite() && t.is_finite())
            .then_some((s, t))
    }
}

#[cfg(test)]
mod tests;
