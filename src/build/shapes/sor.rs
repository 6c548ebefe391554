//! `sor`: a surface of revolution around the y axis whose squared radius is a
//! cubic spline over the height, with flat end caps unless `open`.
//!
//! POV-Ray's `sor { N, <r0, h0>, … }` (measured with its `trace()`): segment k
//! runs from point k+1 to point k+2 (the first and last points are control
//! points only); on it `r² = f(u)`, `u = (y − h[k+1]) / (h[k+2] − h[k+1])`, the
//! cubic Hermite curve through `r[k+1]²` and `r[k+2]²` whose slopes (of `r²` per
//! height) are `2 r dr/dh` with `dr/dh` the secant of the radius over the
//! neighbours: `2 r[k+1] (r[k+2] − r[k]) / (h[k+2] − h[k])` and
//! `2 r[k+2] (r[k+3] − r[k+1]) / (h[k+3] − h[k+1])`. A ray `o + t d` meets the wall
//! where `|o_h + t d_h|² = f(u(t))`: a cubic in t, solved on the t-interval
//! where u is in `[0, 1]`. Inside: between the caps' heights and `x² + z² < f`
//! (caps or not, as POV-Ray's `inside()` says).

use super::revolve::{eval, roots_in, MAX_DEGREE};
use crate::build::{Aabb, Ray};
use glam::{DVec2, DVec3};

/// Surface ids ([`crate::build::Hit::sub`]): caps, then one per segment.
const BOTTOM: u32 = 0;
const TOP: u32 = 1;
const FIRST_SIDE: u32 = 2;

/// One segment: heights, `r²` as a cubic in `u ∈ [0, 1]` (lowest power first)
/// and the largest `r²` on it.
#[derive(Clone, Debug, PartialEq)]
struct Segment {
    y0: f64,
    y1: f64,
    f: [f64; 4],
    r2_max: f64,
}

/// A sor ready for rays.
#[derive(Clone, Debug, PartialEq)]
pub struct Sor {
    segments: Vec<Segment>,
    /// Bottom and top cap heights.
    h: [f64; 2],
    /// Bottom and top cap radii squared.
    cap2: [f64; 2],
    r2_max: f64,
    open: bool,
}

/// The `r²` cubic (in u, lowest power first) of the segment from `p[1]` to
/// `p[2]` with neighbours `p[0]` and `p[3]` (points `<r, h>`).
pub fn segment_cubic(p: [DVec2; 4]) -> [f64; 4] {
    let v = p.map(|q| q.x * q.x);
    let dy = p[2].y - p[1].y;
    let m0 = 2.0 * p[1].x * (p[2].x - p[0].x) / (p[2].y - p[0].y) * dy;
    let m1 = 2.0 * p[2].x * (p[3].x - p[1].x) / (p[3].y - p[1].y) * dy;
    [
        v[1],
        m0,
        -3.0 * v[1] - 2.0 * m0 + 3.0 * v[2] - m1,
        2.0 * v[1] + m0 - 2.0 * v[2] + m1,
    ]
}

/// POV-Ray's uv coordinates on a cap of radius `r_cap` (measured): u the
/// angle around y as on the sides, v the distance from the axis as a fraction
/// of the radius, running outwards on the bottom and inwards on the top.
fn cap_uv(p: DVec3, r_cap: f64, top: bool) -> DVec2 {
    let f = (p.x.hypot(p.z) / r_cap.max(f64::MIN_POSITIVE)).min(1.0);
    DVec2::new(super::revolve::around_y(p), if top { 1.0 - f } else { f })
}

impl Sor {
    /// A sor of POV-Ray's points `<r, h>` (at least 4, heights checked by the
    /// caller: increasing up to the last but one, the last differing from the
    /// third from last).
    pub fn new(points: &[DVec2], open: bool) -> Sor {
        let segments: Vec<Segment> = points
            .windows(4)
            .map(|w| {
                let f = segment_cubic([w[0], w[1], w[2], w[3]]);
                let mut r2_max = f[0].max(eval(&f, 1.0));
                let df = [f[1], 2.0 * f[2], 3.0 * f[3]];
                let mut r = [0.0; MAX_DEGREE];
                let n = roots_in(&df, 0.0, 1.0, &mut r);
                for &u in &r[..n] {
                    r2_max = r2_max.max(eval(&f, u));
                }
                Segment {
                    y0: w[1].y,
                    y1: w[2].y,
                    f,
                    r2_max,
                }
            })
            .collect();
        let n = points.len();
        let (h, cap2) = if n >= 4 {
            (
                [points[1].y, points[n - 2].y],
                [points[1].x.powi(2), points[n - 2].x.powi(2)],
            )
        } else {
            ([0.0; 2], [0.0; 2])
        };
        let r2_max = segments.iter().map(|s| s.r2_max).fold(0.0, f64::max);
        Sor {
            segments,
            h,
            cap2,
            r2_max,
            open,
        }
    }

    /// Every crossing of `ray` in `(t_min, t_max)` with its surface id, unordered.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64, u32)) {
        let (o, d) = (ray.origin, ray.dir);
        let a = d.x * d.x + d.z * d.z;
        let b = o.x * d.x + o.z * d.z;
        let c = o.x * o.x + o.z * o.z;
        let rho2 = if a > 0.0 { (c - b * b / a).max(0.0) } else { c };
        if rho2 > self.r2_max {
            return;
        }
        let mut put = |t: f64, sub: u32| {
            if t > t_min && t < t_max {
                f(t, sub)
            }
        };
        let last = self.segments.len().saturating_sub(1);
        for (k, sg) in self.segments.iter().enumerate() {
            if rho2 > sg.r2_max {
                continue;
            }
            let dy = sg.y1 - sg.y0;
            let u0 = (o.y - sg.y0) / dy;
            let du = d.y / dy;
            let mut roots = [0.0; MAX_DEGREE];
            let in_segment = |u: f64| u >= 0.0 && (u < 1.0 || (k == last && u <= 1.0));
            if du == 0.0 {
                if !in_segment(u0) {
                    continue;
                }
                let p = [c - eval(&sg.f, u0), 2.0 * b, a];
                let m = roots_in(&p, t_min, t_max, &mut roots);
                for &t in &roots[..m] {
                    put(t, FIRST_SIDE + k as u32);
                }
                continue;
            }
            // f(u0 + w) as a polynomial in w = t du (Taylor at u0), then in t.
            let ff = &sg.f;
            let g = [
                eval(ff, u0),
                (3.0 * ff[3] * u0 + 2.0 * ff[2]) * u0 + ff[1],
                3.0 * ff[3] * u0 + ff[2],
                ff[3],
            ];
            let p = [
                c - g[0],
                2.0 * b - g[1] * du,
                a - g[2] * du * du,
                -g[3] * du * du * du,
            ];
            let (ta, tb) = ((0.0 - u0) / du, (1.0 - u0) / du);
            let (lo, hi) = (ta.min(tb).max(t_min), ta.max(tb).min(t_max));
            let m = roots_in(&p, lo, hi, &mut roots);
            for &t in &roots[..m] {
                if in_segment(u0 + t * du) {
                    put(t, FIRST_SIDE + k as u32);
                }
            }
        }
        if self.open || d.y == 0.0 {
            return;
        }
        for (i, id) in [BOTTOM, TOP].into_iter().enumerate() {
            let t = (self.h[i] - o.y) / d.y;
            let (x, z) = (o.x + t * d.x, o.z + t * d.z);
            if x * x + z * z <= self.cap2[i] {
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

    /// The segment holding height y (the last one for its top), if any.
    fn segment_at(&self, y: f64) -> Option<&Segment> {
        let k = self.segments.partition_point(|s| s.y1 <= y);
        self.segments
            .get(k)
            .filter(|s| y >= s.y0)
            .or_else(|| self.segments.last().filter(|s| y == s.y1))
    }

    /// Whether `p` is strictly inside: between the cap heights and within the
    /// radius there (`open` does not change this, as in POV-Ray).
    pub fn inside(&self, p: DVec3) -> bool {
        if !(p.y > self.h[0] && p.y < self.h[1]) {
            return false;
        }
        let Some(s) = self.segment_at(p.y) else {
            return false;
        };
        p.x * p.x + p.z * p.z < eval(&s.f, (p.y - s.y0) / (s.y1 - s.y0))
    }

    /// Outward normal (unnormalised) of surface `sub` at `p`.
    pub fn normal(&self, p: DVec3, sub: u32) -> DVec3 {
        match sub {
            BOTTOM => DVec3::NEG_Y,
            TOP => DVec3::Y,
            _ => {
                let Some(s) = self.segments.get((sub - FIRST_SIDE) as usize) else {
                    return DVec3::Y;
                };
                let dy = s.y1 - s.y0;
                let u = (p.y - s.y0) / dy;
                let df = ((3.0 * s.f[3] * u + 2.0 * s.f[2]) * u + s.f[1]) / dy;
                // Gradient of x² + z² − f(y).
                DVec3::new(2.0 * p.x, -df, 2.0 * p.z)
            }
        }
    }

    /// POV-Ray's uv coordinates at `p` on surface `sub`: on the sides u is the
    /// angle around y (as on a sphere) and v the height through the segments,
    /// each an equal share of [0, 1]; caps are mapped as described on
    /// [`cap_uv`] (measured against POV-Ray).
    pub fn uv(&self, p: DVec3, sub: u32) -> DVec2 {
        let u = super::revolve::around_y(p);
        match sub {
            BOTTOM | TOP => cap_uv(p, self.cap2[(sub == TOP) as usize].sqrt(), sub == TOP),
            _ => {
                let k = sub - FIRST_SIDE;
                let Some(s) = self.segments.get(k as usize) else {
                    return DVec2::new(u, 0.0);
                };
                let f = ((p.y - s.y0) / (s.y1 - s.y0)).clamp(0.0, 1.0);
                DVec2::new(u, (f64::from(k) + f) / self.segments.len() as f64)
            }
        }
    }

    /// Bounds in object space.
    pub fn bounds(&self) -> Aabb {
        if self.segments.is_empty() {
            return Aabb::EMPTY;
        }
        let r = self.r2_max.sqrt();
        let y0 = self.segments[0].y0;
        let y1 = self.segments[self.segments.len() - 1].y1;
        let pad = 1e-9 * (1.0 + r.max(y0.abs()).max(y1.abs()));
        Aabb::new(
            DVec3::new(-r - pad, y0 - pad, -r - pad),
            DVec3::new(r + pad, y1 + pad, r + pad),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn probe() -> Sor {
        let p = [(0.0, -1.0), (1.0, 0.0), (2.0, 1.0), (1.0, 2.0), (0.0, 3.0)];
        Sor::new(&p.map(|(r, h)| DVec2::new(r, h)), false)
    }

    #[test]
    fn radii_match_povray_trace() {
        // trace() from <5, y, 0> towards −x in POV-Ray 3.7.
        let s = probe();
        for (y, r) in [
            (0.25, 1.322876),
            (0.5, 1.658312),
            (0.75, 1.903943),
            (1.25, 1.903943),
            (1.5, 1.658312),
            (1.75, 1.322876),
        ] {
            let ray = Ray::new(DVec3::new(5.0, y, 0.0), DVec3::NEG_X);
            let (t, _) = s.nearest(&ray, 0.0, f64::INFINITY).unwrap();
            assert!((5.0 - t - r).abs() < 1e-6, "{y}: {}", 5.0 - t);
        }
    }

    #[test]
    fn uneven_heights_match_povray_trace() {
        // trace() from <5, y, 0.3> towards −x in POV-Ray 3.7: x of the hit and
        // the normal there.
        let p = [
            (0.5, -1.0),
            (1.0, 0.0),
            (0.4, 0.5),
            (1.2, 1.5),
            (0.8, 2.0),
            (0.0, 2.2),
        ];
        let s = Sor::new(&p.map(|(r, h)| DVec2::new(r, h)), false);
        for (y, x, n) in [
            (0.4, 0.385227, [0.422250, 0.844733, 0.328832]),
            (0.8, 0.567309, [0.595289, -0.739280, 0.314796]),
            (1.7, 1.116305, [0.809650, 0.545090, 0.217588]),
        ] {
            let ray = Ray::new(DVec3::new(5.0, y, 0.3), DVec3::NEG_X);
            let (t, sub) = s.nearest(&ray, 0.0, f64::INFINITY).unwrap();
            assert!((5.0 - t - x).abs() < 1e-6, "{y}: {}", 5.0 - t);
            let got = s.normal(ray.origin + ray.dir * t, sub).normalize();
            assert!(got.abs_diff_eq(DVec3::from(n), 1e-5), "{y}: {got}");
        }
    }

    #[test]
    fn caps_and_inside() {
        let s = probe();
        let down = Ray::new(DVec3::new(0.3, 5.0, 0.0), DVec3::NEG_Y);
        assert_eq!(s.nearest(&down, 0.0, f64::INFINITY), Some((3.0, TOP)));
        let up = Ray::new(DVec3::new(0.3, -5.0, 0.0), DVec3::Y);
        assert_eq!(s.nearest(&up, 0.0, f64::INFINITY), Some((5.0, BOTTOM)));
        let open = Sor {
            open: true,
            ..s.clone()
        };
        assert_eq!(open.nearest(&down, 0.0, f64::INFINITY), None);
        assert!(s.inside(DVec3::new(0.5, 1.0, 0.0)));
        assert!(open.inside(DVec3::new(0.0, 1.0, 0.5)));
        assert!(!s.inside(DVec3::new(2.5, 1.0, 0.0)));
        assert!(!s.inside(DVec3::new(0.5, 2.5, 0.0)));
        assert!(!s.inside(DVec3::new(0.5, -0.5, 0.0)));
    }

    #[test]
    fn every_crossing_of_a_slanted_ray_pairs_up() {
        let s = probe();
        let ray = Ray::new(DVec3::new(-4.0, -0.7, 0.3), DVec3::new(1.0, 0.45, 0.05));
        let mut ts = Vec::new();
        s.hits(&ray, 0.0, f64::INFINITY, &mut |t, _| ts.push(t));
        ts.sort_by(f64::total_cmp);
        assert_eq!(ts.len() % 2, 0, "{ts:?}");
        let first = ray.origin + ray.dir * ts[0];
        assert!(!s.inside(ray.origin + ray.dir * (ts[0] - 1e-6)));
        assert!(s.inside(ray.origin + ray.dir * (ts[0] + 1e-6)), "{first}");
    }
}
