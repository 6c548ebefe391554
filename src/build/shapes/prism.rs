//! `prism`: closed 2-D curves in the x-z plane swept along y, straight up
//! (`linear_sweep`) or from a point at the origin (`conic_sweep`).
//!
//! The outline is a list of curve segments, each a polynomial of degree ≤ 3 in
//! its parameter `s ∈ [0, 1]` per coordinate (`<x, z>`). Whatever the spline
//! type, a ray meets a segment's wall where a polynomial of degree ≤ 3 in `s`
//! is zero:
//!
//! - linear sweep: the wall over the curve is vertical, so the ray's shadow on
//!   the x-z plane (a 2-D line) must cross the curve: `d₂ × (P(s) − o₂) = 0`;
//! - conic sweep: the wall is made of the lines from the origin through
//!   `<x, 1, z>` for the curve's points; the ray meets such a line when the
//!   origin, the ray and the line are coplanar: `(o × d) · <x(s), 1, z(s)> = 0`.
//!
//! Caps are planes at the two heights, filled by the even-odd rule (a point is
//! inside when a half-line from it crosses the outline an odd number of times).

use crate::build::quartic::cubic;
use crate::build::{Aabb, Ray};
use glam::{DVec2, DVec3};

/// A curve segment `c[0] + c[1] s + c[2] s² + c[3] s³` for `s ∈ [0, 1]`, as
/// `<x, z>` points.
pub type Curve = [DVec2; 4];

/// How the points of a `prism` are joined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spline {
    /// `linear_spline`: straight lines; a sub-shape closes on its first point.
    Linear,
    /// `quadratic_spline`: each segment on the parabola through the point before,
    /// its start and its end; the first point of a sub-shape is a control point.
    Quadratic,
    /// `cubic_spline`: Catmull-Rom segments; a sub-shape has a leading and a
    /// trailing control point.
    Cubic,
    /// `bezier_spline`: every four points are one cubic Bézier segment.
    Bezier,
}

impl Spline {
    /// The spline of a keyword, if it is one of the four.
    pub fn from_keyword(kw: &str) -> Option<Spline> {
        Some(match kw {
            "linear_spline" => Spline::Linear,
            "quadratic_spline" => Spline::Quadratic,
            "cubic_spline" => Spline::Cubic,
            "bezier_spline" => Spline::Bezier,
            _ => return None,
        })
    }

    /// The keyword.
    pub fn keyword(self) -> &'static str {
        match self {
            Spline::Linear => "linear_spline",
            Spline::Quadratic => "quadratic_spline",
            Spline::Cubic => "cubic_spline",
            Spline::Bezier => "bezier_spline",
        }
    }

    /// The fewest points POV-Ray accepts for this spline.
    pub fn min_points(self) -> usize {
        match self {
            Spline::Linear => 3,
            Spline::Quadratic => 5,
            Spline::Cubic => 6,
            Spline::Bezier => 4,
        }
    }

    /// How a sub-shape closes, for messages.
    pub fn closing_rule(self) -> &'static str {
        match self {
            Spline::Linear => "a sub-shape closes when a point repeats its first point",
            Spline::Quadratic => {
                "the first point of a sub-shape is a control point; the sub-shape closes \
                 when a point repeats its second point"
            }
            Spline::Cubic => {
                "the first point of a sub-shape is a control point; the sub-shape closes \
                 when a point repeats its second point, and one more control point follows"
            }
            Spline::Bezier => {
                "every 4 points are one segment (start, two controls, end); a sub-shape \
                 closes when a segment ends on the sub-shape's first point"
            }
        }
    }
}

/// What happened to points after the last closed sub-shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tail {
    /// Every point belongs to a closed sub-shape.
    Closed,
    /// A `linear_spline` outline that did not close was closed with a line back
    /// to its first point (POV-Ray does the same, with a warning).
    ClosedForYou,
    /// Points from this index on make no closed sub-shape and were dropped.
    Ignored(usize),
    /// Points from this index on make at least one whole segment but do not
    /// close (POV-Ray stops with "too few points in prism").
    Unclosed(usize),
}

/// The curve segments of POV-Ray's point list, and what became of the last points.
pub fn outline(spline: Spline, p: &[DVec2]) -> (Vec<Curve>, Tail) {
    let n = p.len();
    let mut curves = Vec::new();
    let mut s = 0;
    let close = |from: usize, start: DVec2| (from..n).find(|&i| same(p[i], start));
    while s < n {
        match spline {
            Spline::Linear => match close(s + 1, p[s]) {
                Some(c) => {
                    curves.extend((s..c).map(|i| line(p[i], p[i + 1])));
                    s = c + 1;
                }
                None => {
                    if n - s < 2 {
                        return (curves, Tail::Ignored(s));
                    }
                    curves.extend((s..n - 1).map(|i| line(p[i], p[i + 1])));
                    curves.push(line(p[n - 1], p[s]));
                    return (curves, Tail::ClosedForYou);
                }
            },
            Spline::Quadratic | Spline::Cubic => {
                let cubic_spline = spline == Spline::Cubic;
                let seg_points = if cubic_spline { 4 } else { 3 };
                let c = if s + 1 < n {
                    close(s + 2, p[s + 1])
                } else {
                    None
                };
                match c {
                    Some(c) if !cubic_spline || c + 1 < n => {
                        for i in s + 1..c {
                            curves.push(if cubic_spline {
                                catmull_rom(p[i - 1], p[i], p[i + 1], p[i + 2])
                            } else {
                                quadratic(p[i - 1], p[i], p[i + 1])
                            });
                        }
                        s = if cubic_spline { c + 2 } else { c + 1 };
                    }
                    _ => {
                        let tail = if n - s >= seg_points {
                            Tail::Unclosed(s)
                        } else {
                            Tail::Ignored(s)
                        };
                        return (curves, tail);
                    }
                }
            }
            Spline::Bezier => {
                let mut k = s;
                let mut closed = None;
                while k + 4 <= n {
                    if same(p[k + 3], p[s]) {
                        closed = Some(k + 4);
                        break;
                    }
                    k += 4;
                }
                match closed {
                    Some(end) => {
                        curves.extend(
                            (s..end)
                                .step_by(4)
                                .map(|i| bezier(p[i], p[i + 1], p[i + 2], p[i + 3])),
                        );
                        s = end;
                    }
                    None => return (curves, Tail::Ignored(s)),
                }
            }
        }
    }
    (curves, Tail::Closed)
}

/// Whether two points are the same for closing a sub-shape (POV-Ray compares
/// with a small tolerance too).
fn same(a: DVec2, b: DVec2) -> bool {
    (a - b).abs().max_element() <= 1e-10 * (1.0 + a.abs().max_element())
}

pub(crate) fn line(a: DVec2, b: DVec2) -> Curve {
    [a, b - a, DVec2::ZERO, DVec2::ZERO]
}

/// From `p2` to `p3` along the parabola through `p1`, `p2`, `p3` (at s = −1, 0, 1;
/// measured against POV-Ray's pictures).
pub(crate) fn quadratic(p1: DVec2, p2: DVec2, p3: DVec2) -> Curve {
    [p2, (p3 - p1) * 0.5, (p1 - 2.0 * p2 + p3) * 0.5, DVec2::ZERO]
}

/// The Catmull-Rom segment from `p2` to `p3`.
pub(crate) fn catmull_rom(p1: DVec2, p2: DVec2, p3: DVec2, p4: DVec2) -> Curve {
    [
        p2,
        (p3 - p1) * 0.5,
        (2.0 * p1 - 5.0 * p2 + 4.0 * p3 - p4) * 0.5,
        (-p1 + 3.0 * p2 - 3.0 * p3 + p4) * 0.5,
    ]
}

/// The cubic Bézier segment with end points `a`, `d` and controls `b`, `c`.
pub(crate) fn bezier(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Curve {
    [
        a,
        3.0 * (b - a),
        3.0 * (a - 2.0 * b + c),
        -a + 3.0 * b - 3.0 * c + d,
    ]
}

/// The point of curve `c` at `s`.
#[inline]
pub(crate) fn at(c: &Curve, s: f64) -> DVec2 {
    ((c[3] * s + c[2]) * s + c[1]) * s + c[0]
}

/// The tangent of curve `c` at `s`.
#[inline]
pub(crate) fn tangent(c: &Curve, s: f64) -> DVec2 {
    (c[3] * (3.0 * s) + c[2] * 2.0) * s + c[1]
}

/// Surface ids ([`crate::build::Hit::sub`]): caps, then one per segment.
const BOTTOM: u32 = 0;
const TOP: u32 = 1;
const FIRST_SIDE: u32 = 2;

/// A prism ready for rays.
#[derive(Clone, Debug, PartialEq)]
pub struct Prism {
    curves: Vec<Curve>,
    /// Per segment: its 2-D bounds `(min, max)`.
    boxes: Vec<(DVec2, DVec2)>,
    /// Per segment: +1 when `(t.z, −t.x)` of its tangent `t` points out, else −1.
    orient: Vec<f64>,
    /// Bounds of the whole outline.
    outline_box: (DVec2, DVec2),
    /// Lower and upper height.
    h: [f64; 2],
    conic: bool,
    open: bool,
}

impl Prism {
    /// A prism of `curves` (closed outlines) between heights `h0` and `h1` (either
    /// order).
    pub fn new(curves: &[Curve], h0: f64, h1: f64, conic: bool, open: bool) -> Prism {
        let boxes: Vec<_> = curves.iter().map(curve_box).collect();
        let outline_box = boxes.iter().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), b| (lo.min(b.0), hi.max(b.1)),
        );
        let mut prism = Prism {
            curves: curves.to_vec(),
            boxes,
            orient: Vec::new(),
            outline_box,
            h: [h0.min(h1), h0.max(h1)],
            conic,
            open,
        };
        prism.orient = (0..curves.len()).map(|i| prism.orientation(i)).collect();
        prism
    }

    /// Which side of segment `i` is out: sampled at a few points just off the
    /// curve on both sides; the majority decides.
    fn orientation(&self, i: usize) -> f64 {
        let c = &self.curves[i];
        let size = (self.outline_box.1 - self.outline_box.0)
            .max_element()
            .max(1e-300);
        let eps = 1e-7 * size;
        let mut vote = 0i32;
        for s in [0.27, 0.5, 0.73] {
            let t = tangent(c, s);
            let n = DVec2::new(t.y, -t.x).normalize_or_zero();
            if n == DVec2::ZERO {
                continue;
            }
            let m = at(c, s);
            let (plus, minus) = (self.inside2(m + n * eps), self.inside2(m - n * eps));
            if minus && !plus {
                vote += 1;
            } else if plus && !minus {
                vote -= 1;
            }
        }
        if vote < 0 {
            -1.0
        } else {
            1.0
        }
    }

    /// Whether `q` is inside the outline (even-odd rule).
    pub fn inside2(&self, q: DVec2) -> bool {
        even_odd(&self.curves, &self.boxes, q)
    }

    /// Every crossing of `ray` in `(t_min, t_max)` with its surface id, unordered.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64, u32)) {
        let (o, d) = (ray.origin, ray.dir);
        let [h0, h1] = self.h;
        let mut put = |t: f64, sub: u32| {
            if t > t_min && t < t_max {
                f(t, sub)
            }
        };
        let mut roots = [0.0; 3];
        if self.conic {
            let n = o.cross(d);
            if n.length_squared() > 0.0 {
                for (i, c) in self.curves.iter().enumerate() {
                    let k = [
                        n.x * c[0].x + n.y + n.z * c[0].y,
                        n.x * c[1].x + n.z * c[1].y,
                        n.x * c[2].x + n.z * c[2].y,
                        n.x * c[3].x + n.z * c[3].y,
                    ];
                    let m = roots01(k, &mut roots);
                    for &s in &roots[..m] {
                        let p = at(c, s);
                        let w = DVec3::new(p.x, 1.0, p.y);
                        let dw = d.cross(w);
                        let den = dw.length_squared();
                        if den == 0.0 {
                            continue;
                        }
                        let t = -o.cross(w).dot(dw) / den;
                        let y = o.y + t * d.y;
                        if y >= h0 && y <= h1 {
                            put(t, FIRST_SIDE + i as u32);
                        }
                    }
                }
            }
        } else {
            let d2 = DVec2::new(d.x, d.z);
            let o2 = DVec2::new(o.x, o.z);
            let dd = d2.length_squared();
            if dd > 0.0 {
                for (i, (c, b)) in self.curves.iter().zip(&self.boxes).enumerate() {
                    // The segment's box must straddle the ray's 2-D line.
                    let side = |x: f64, z: f64| d2.x * (z - o2.y) - d2.y * (x - o2.x);
                    let corners = [
                        side(b.0.x, b.0.y),
                        side(b.1.x, b.0.y),
                        side(b.0.x, b.1.y),
                        side(b.1.x, b.1.y),
                    ];
                    if corners.iter().all(|&v| v > 0.0) || corners.iter().all(|&v| v < 0.0) {
                        continue;
                    }
                    let k = [
                        side(c[0].x, c[0].y),
                        d2.x * c[1].y - d2.y * c[1].x,
                        d2.x * c[2].y - d2.y * c[2].x,
                        d2.x * c[3].y - d2.y * c[3].x,
                    ];
                    let m = roots01(k, &mut roots);
                    for &s in &roots[..m] {
                        let t = (at(c, s) - o2).dot(d2) / dd;
                        let y = o.y + t * d.y;
                        if y >= h0 && y <= h1 {
                            put(t, FIRST_SIDE + i as u32);
                        }
                    }
                }
            }
        }
        if self.open || d.y == 0.0 {
            return;
        }
        for (h, id) in [(h0, BOTTOM), (h1, TOP)] {
            let t = (h - o.y) / d.y;
            if !(t > t_min && t < t_max) {
                continue;
            }
            let p = o + d * t;
            let q = if self.conic {
                if h == 0.0 {
                    continue;
                }
                DVec2::new(p.x / h, p.z / h)
            } else {
                DVec2::new(p.x, p.z)
            };
            if self.inside2(q) {
                put(t, id);
            }
        }
    }

    /// The nearest crossing in `(t_min, t_max)` and its surface id.
    pub fn nearest(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, u32)> {
        let mut best: Option<(f64, u32)> = None;
        self.hits(ray, t_min, t_max, &mut |t, sub| {
            if best.is_none_or(|b| t < b.0) {
                best = Some((t, sub));
            }
        });
        best
    }

    /// Outward normal (unnormalised) of surface `sub` at `p`.
    pub fn normal(&self, p: DVec3, sub: u32) -> DVec3 {
        match sub {
            BOTTOM => DVec3::NEG_Y,
            TOP => DVec3::Y,
            _ => {
                let i = (sub - FIRST_SIDE) as usize;
                let Some(c) = self.curves.get(i) else {
                    return DVec3::Y;
                };
                let q = if self.conic {
                    if p.y == 0.0 {
                        return DVec3::NEG_Y;
                    }
                    DVec2::new(p.x / p.y, p.z / p.y)
                } else {
                    DVec2::new(p.x, p.z)
                };
                let s = closest(c, q);
                let mut t = tangent(c, s);
                if t.length_squared() == 0.0 {
                    // A cusp: the chord nearby gives the direction.
                    let (a, b) = ((s - 1e-4).max(0.0), (s + 1e-4).min(1.0));
                    t = at(c, b) - at(c, a);
                }
                let n2 = DVec2::new(t.y, -t.x) * self.orient[i];
                if self.conic {
                    // The wall through the origin: ∂/∂y × ∂/∂s of (x(s) y, y, z(s) y).
                    let pq = at(c, s);
                    DVec3::new(n2.x, -(pq.x * n2.x + pq.y * n2.y), n2.y) * p.y.signum()
                } else {
                    DVec3::new(n2.x, 0.0, n2.y)
                }
            }
        }
    }

    /// Whether `p` is strictly inside: between the heights and inside the outline
    /// (scaled by y for `conic_sweep`). `open` does not change this, as in POV-Ray.
    pub fn inside(&self, p: DVec3) -> bool {
        let [h0, h1] = self.h;
        if !(p.y > h0 && p.y < h1) {
            return false;
        }
        if self.conic {
            if p.y == 0.0 {
                return false;
            }
            self.inside2(DVec2::new(p.x / p.y, p.z / p.y))
        } else {
            self.inside2(DVec2::new(p.x, p.z))
        }
    }

    /// Bounds in object space; empty for an outline of no segments.
    pub fn bounds(&self) -> Aabb {
        if self.curves.is_empty() {
            return Aabb::EMPTY;
        }
        let (lo, hi) = self.outline_box;
        let [h0, h1] = self.h;
        let b = if self.conic {
            let xs = [lo.x * h0, hi.x * h0, lo.x * h1, hi.x * h1];
            let zs = [lo.y * h0, hi.y * h0, lo.y * h1, hi.y * h1];
            let min = |v: [f64; 4]| v.into_iter().fold(f64::INFINITY, f64::min);
            let max = |v: [f64; 4]| v.into_iter().fold(f64::NEG_INFINITY, f64::max);
            Aabb::new(
                DVec3::new(min(xs), h0, min(zs)),
                DVec3::new(max(xs), h1, max(zs)),
            )
        } else {
            Aabb::new(DVec3::new(lo.x, h0, lo.y), DVec3::new(hi.x, h1, hi.y))
        };
        let pad = 1e-9 * (1.0 + b.min.abs().max(b.max.abs()).max_element());
        Aabb::new(b.min - DVec3::splat(pad), b.max + DVec3::splat(pad))
    }
}

/// The exact 2-D bounds of a segment: its end points and the extrema inside.
pub(crate) fn curve_box(c: &Curve) -> (DVec2, DVec2) {
    let mut lo = at(c, 0.0).min(at(c, 1.0));
    let mut hi = at(c, 0.0).max(at(c, 1.0));
    for axis in 0..2 {
        // Derivative: c1 + 2 c2 s + 3 c3 s².
        let k = [c[1][axis], 2.0 * c[2][axis], 3.0 * c[3][axis], 0.0];
        let mut r = [0.0; 3];
        let n = roots01(k, &mut r);
        for &s in &r[..n] {
            let p = at(c, s);
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    let pad = 1e-12 * (1.0 + lo.abs().max(hi.abs()).max_element());
    (lo - DVec2::splat(pad), hi + DVec2::splat(pad))
}

/// Whether `q` is inside the outline of `curves` (each within its box in
/// `boxes`) by the even-odd rule: an odd number of crossings towards +x.
pub(crate) fn even_odd(curves: &[Curve], boxes: &[(DVec2, DVec2)], q: DVec2) -> bool {
    let mut odd = false;
    for (c, b) in curves.iter().zip(boxes) {
        if q.y < b.0.y || q.y > b.1.y || q.x > b.1.x {
            continue;
        }
        if crossings(c, q) % 2 == 1 {
            odd = !odd;
        }
    }
    odd
}

/// How many times curve `c` crosses the half-line from `q` towards +x: sign
/// changes of `z(s) − q.z` (zero counts as positive, so a curve touching the
/// line at a joint is counted once over the two segments that meet there).
pub(crate) fn crossings(c: &Curve, q: DVec2) -> u32 {
    let f = |s: f64| at(c, s).y - q.y >= 0.0;
    let k = [c[0].y - q.y, c[1].y, c[2].y, c[3].y];
    let mut r = [0.0; 3];
    let n = roots01(k, &mut r);
    let mut roots = [0.0; 3];
    let mut m = 0;
    for &s in &r[..n] {
        if s > 0.0 && s < 1.0 {
            roots[m] = s;
            m += 1;
        }
    }
    roots[..m].sort_by(f64::total_cmp);
    let mut count = 0;
    let mut flip = |s: f64| {
        if at(c, s).x > q.x {
            count += 1;
        }
    };
    let mut prev_s = 0.0;
    let mut prev = f(0.0);
    for &b in roots[..m].iter().chain(&[1.0]) {
        let mid = f(0.5 * (prev_s + b));
        if mid != prev {
            flip(prev_s);
        }
        prev = mid;
        prev_s = b;
    }
    if f(1.0) != prev {
        flip(1.0);
    }
    count
}

/// The parameter of the point of `c` nearest to `q` (a point on the curve or
/// close to it): among the solutions of `x(s) = q.x` and `z(s) = q.z` and the
/// ends, the one closest to `q`.
pub(crate) fn closest(c: &Curve, q: DVec2) -> f64 {
    let mut best = (f64::INFINITY, 0.0);
    let mut try_s = |s: f64| {
        let s = s.clamp(0.0, 1.0);
        let e = (at(c, s) - q).length_squared();
        if e < best.0 {
            best = (e, s);
        }
    };
    try_s(0.0);
    try_s(1.0);
    for axis in 0..2 {
        let k = [c[0][axis] - q[axis], c[1][axis], c[2][axis], c[3][axis]];
        let mut r = [0.0; 3];
        let n = roots01(k, &mut r);
        for &s in &r[..n] {
            try_s(s);
        }
    }
    best.1
}

/// Real roots in `[0, 1]` (a hair of slack, clamped) of the cubic
/// `k[0] + k[1] s + k[2] s² + k[3] s³`; returns how many. Leading coefficients
/// negligible on `[0, 1]` (below 1e-12 of the largest) are dropped.
pub(crate) fn roots01(k: [f64; 4], out: &mut [f64; 3]) -> usize {
    let scale = k.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    if scale == 0.0 || !scale.is_finite() {
        return 0;
    }
    let Some(deg) = (1..4).rev().find(|&d| k[d].abs() > 1e-12 * scale) else {
        return 0;
    };
    let mut r = [0.0; 3];
    let n = match deg {
        3 => cubic(k[2] / k[3], k[1] / k[3], k[0] / k[3], &mut r),
        2 => {
            let (a, b, c) = (k[2], k[1], k[0]);
            let disc = b * b - 4.0 * a * c;
            if disc < 0.0 {
                0
            } else {
                let q = -0.5 * (b + disc.sqrt().copysign(b));
                if q == 0.0 {
                    r[0] = 0.0;
                    1
                } else {
                    r[0] = q / a;
                    r[1] = c / q;
                    2
                }
            }
        }
        _ => {
            r[0] = -k[0] / k[1];
            1
        }
    };
    let value = |s: f64| ((k[3] * s + k[2]) * s + k[1]) * s + k[0];
    let slope = |s: f64| (3.0 * k[3] * s + 2.0 * k[2]) * s + k[1];
    let mut m = 0;
    for &s0 in &r[..n] {
        // Newton polish on the full polynomial (the dropped terms included).
        let mut s = s0;
        for _ in 0..2 {
            let (v, dv) = (value(s), slope(s));
            if dv == 0.0 || v == 0.0 {
                break;
            }
            let next = s - v / dv;
            // Stop unless strictly better (a NaN is never better).
            if value(next).abs().partial_cmp(&v.abs()) != Some(std::cmp::Ordering::Less) {
                break;
            }
            s = next;
        }
        const SLACK: f64 = 1e-9;
        if (-SLACK..=1.0 + SLACK).contains(&s) {
            out[m] = s.clamp(0.0, 1.0);
            m += 1;
        }
    }
    m
}

#[cfg(test)]
mod tests;
