//! `blob`: the surface where the summed field of spherical and cylindrical
//! components equals the threshold, inside where the field is above it.
//!
//! A component's field is `s · (1 − q)²` where `q = d²/r²` (`d` the distance to
//! the centre, or to the axis segment of a cylinder) and 0 where `q ≥ 1`. Along a
//! ray `q` is quadratic in the distance, so each component adds a quartic over
//! the interval where the ray is within its radius (a cylinder: up to three
//! intervals, body and two round ends). The intervals' ends cut the ray into
//! segments; in each, the active quartics are summed and the roots of
//! `sum − threshold` found by isolating them between the critical points of the
//! polynomial (found the same way, recursively), which needs no closed form and
//! copes with tiny leading coefficients. A hierarchy over the components' bounds
//! picks the ones a ray can meet when there are many.

use crate::build::{Aabb, Bvh, Ray};
use crate::scene::{BlobData, BlobKind, Texture, Transform};
use glam::{DMat3, DMat4, DVec3};
use std::sync::Arc;

/// Up to this many components are tested one by one, without the hierarchy.
const LINEAR: usize = 8;

/// A blob ready for intersection, in the blob's own space.
#[derive(Clone, Debug)]
pub struct Blob {
    threshold: f64,
    comps: Vec<Comp>,
    bvh: Option<Bvh>,
    bounds: Aabb,
    /// Per component: its own texture and `texture_from_world`, or `None` for
    /// the blob's texture.
    textures: Vec<Option<OwnTexture>>,
}

/// A component's own texture and its `texture_from_world`.
pub type OwnTexture = (Arc<Texture>, DMat4);

#[derive(Clone, Debug)]
struct Comp {
    field: Field,
    strength: f64,
    /// `component_from_blob`, `None` for the identity.
    inv: Option<DMat4>,
    /// The transpose of `inv`'s linear part: turns component-space gradients
    /// into blob-space ones.
    grad: DMat3,
    /// In the blob's space.
    bounds: Aabb,
}

#[derive(Clone, Copy, Debug)]
enum Field {
    Sphere {
        c: DVec3,
        r2: f64,
    },
    Cylinder {
        a: DVec3,
        /// Unit axis from `a`.
        axis: DVec3,
        len: f64,
        r2: f64,
    },
}

/// A polynomial in the ray parameter, lowest power first.
type Quartic = [f64; 5];

/// One stretch of the ray within a component's radius and that component's
/// field there.
#[derive(Clone, Copy, Debug)]
struct Interval {
    u0: f64,
    u1: f64,
    poly: Quartic,
    /// The component's strength if positive, else 0 (bounds the field).
    positive: f64,
}

impl Blob {
    /// The blob of `data` placed at `world_from_blob` (which only places the
    /// components' own textures).
    pub fn new(data: &BlobData, world_from_blob: Option<&Transform>) -> Blob {
        let mut comps = Vec::new();
        let mut textures = Vec::new();
        for c in &data.components {
            if c.strength == 0.0 {
                continue;
            }
            let (field, local) = match c.kind {
                BlobKind::Sphere { center, radius } => (
                    Field::Sphere {
                        c: center,
                        r2: radius * radius,
                    },
                    Aabb::new(center - DVec3::splat(radius), center + DVec3::splat(radius)),
                ),
                BlobKind::Cylinder { a, b, radius } => {
                    let len = (b - a).length();
                    let r = DVec3::splat(radius);
                    let bounds = Aabb::new(a.min(b) - r, a.max(b) + r);
                    if len == 0.0 {
                        (
                            Field::Sphere {
                                c: a,
                                r2: radius * radius,
                            },
                            bounds,
                        )
                    } else {
                        (
                            Field::Cylinder {
                                a,
                                axis: (b - a) / len,
                                len,
                                r2: radius * radius,
                            },
                            bounds,
                        )
                    }
                }
            };
            let (inv, grad, bounds) = match c.transform.as_deref() {
                None => (None, DMat3::IDENTITY, local),
                Some(t) => (
                    Some(t.inverse),
                    DMat3::from_mat4(t.inverse).transpose(),
                    Aabb::from_points(local.corners().map(|p| t.point(p))),
                ),
            };
            comps.push(Comp {
                field,
                strength: c.strength,
                inv,
                grad,
                bounds,
            });
            textures.push(c.texture.as_ref().map(|tex| {
                let blob_from_world = world_from_blob.map_or(DMat4::IDENTITY, |w| w.inverse);
                let comp_from_blob = c
                    .transform
                    .as_deref()
                    .map_or(DMat4::IDENTITY, |t| t.inverse);
                (tex.clone(), comp_from_blob * blob_from_world)
            }));
        }
        let bounds = comps.iter().fold(Aabb::EMPTY, |b, c| b.union(&c.bounds));
        let bvh =
            (comps.len() > LINEAR).then(|| Bvh::build_indexed(comps.len(), |i| comps[i].bounds));
        Blob {
            threshold: data.threshold,
            comps,
            bvh,
            bounds,
            textures,
        }
    }

    /// Bounds in the blob's space (the union of the components' reach: the
    /// surface lies within, since the field is 0 outside every component).
    pub fn bounds(&self) -> Option<Aabb> {
        (!self.bounds.is_empty()).then_some(self.bounds)
    }

    /// The components' own textures.
    pub fn own_textures(&self) -> impl Iterator<Item = &Arc<Texture>> {
        self.textures.iter().flatten().map(|(t, _)| t)
    }

    /// Whether any component has a texture of its own.
    pub fn textured(&self) -> bool {
        self.textures.iter().any(Option::is_some)
    }

    /// The summed field at `p`.
    pub fn field(&self, p: DVec3) -> f64 {
        self.comps
            .iter()
            .filter(|c| contains(&c.bounds, p))
            .map(|c| c.density(p).0)
            .sum()
    }

    /// Strictly inside: the field is above the threshold.
    pub fn inside(&self, p: DVec3) -> bool {
        self.field(p) > self.threshold
    }

    /// The outward normal at `p`: minus the field's gradient (unnormalised).
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let g: DVec3 = self
            .comps
            .iter()
            .filter(|c| contains(&c.bounds, p))
            .map(|c| c.density(p).1)
            .sum();
        if g.length_squared() > 0.0 && g.is_finite() {
            -g
        } else {
            DVec3::Y
        }
    }

    /// The textures seen at `p` (blob space) with their weights, which sum to 1:
    /// each component's share is the size of its field there, as POV-Ray blends
    /// them (measured). `None` stands for the blob's own texture; repeated
    /// textures are merged.
    pub fn texture_weights(&self, p: DVec3) -> Vec<(Option<&OwnTexture>, f64)> {
        let mut out: Vec<(Option<&OwnTexture>, f64)> = Vec::new();
        let mut total = 0.0;
        for (c, tex) in self.comps.iter().zip(&self.textures) {
            if !contains(&c.bounds, p) {
                continue;
            }
            let w = c.density(p).0.abs();
            if w <= 0.0 {
                continue;
            }
            total += w;
            let tex = tex.as_ref();
            let same = |t: &Option<&OwnTexture>| match (t, &tex) {
                (None, None) => true,
                (Some(a), Some(b)) => Arc::ptr_eq(&a.0, &b.0) && a.1 == b.1,
                _ => false,
            };
            match out.iter_mut().find(|(t, _)| same(t)) {
                Some(e) => e.1 += w,
                None => out.push((tex, w)),
            }
        }
        if total <= 0.0 {
            return vec![(None, 1.0)];
        }
        for e in &mut out {
            e.1 /= total;
        }
        out
    }

    /// Every crossing of `ray` (blob space) in `(t_min, t_max)`, in order; `f`
    /// returns `false` to stop.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64) -> bool) {
        let len = ray.dir.length();
        if len == 0.0 || self.comps.is_empty() {
            return;
        }
        let inv_dir = ray.dir.recip();
        let Some(enter) = self.bounds.hit(ray, inv_dir, t_min, t_max) else {
            return;
        };
        // Exit from the bounds: the far slab.
        let t0 = (self.bounds.min - ray.origin) * inv_dir;
        let t1 = (self.bounds.max - ray.origin) * inv_dir;
        let exit = t0.max(t1).min_element().min(t_max);
        // Polynomials in u = (t − shift)·|dir| along a unit direction from a
        // point near the blob: small, well-scaled coefficients.
        let shift = if enter.is_finite() { enter } else { 0.0 };
        let local = Ray::new(ray.at(shift), ray.dir / len);
        let (u_lo, u_hi) = ((t_min - shift) * len, (exit - shift) * len);
        let mut spans: Vec<Interval> = Vec::new();
        let add = |c: &Comp, spans: &mut Vec<Interval>| {
            c.intervals(&local, u_lo.max(-1e-9), u_hi, spans);
        };
        match &self.bvh {
            None => {
                for c in &self.comps {
                    add(c, &mut spans);
                }
            }
            Some(bvh) => bvh.traverse(ray, t_min, t_max, |i, tm| {
                add(&self.comps[i as usize], &mut spans);
                Some(tm)
            }),
        }
        if spans.is_empty() {
            return;
        }
        // Events: entries (+) and exits (−) in order.
        let mut events: Vec<(f64, u32, bool)> = Vec::with_capacity(spans.len() * 2);
        for (i, s) in spans.iter().enumerate() {
            events.push((s.u0, i as u32, true));
            events.push((s.u1, i as u32, false));
        }
        events.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut active: Vec<u32> = Vec::new();
        let mut roots = Vec::new();
        for k in 0..events.len() {
            let (u, i, entry) = events[k];
            if entry {
                active.push(i);
            } else if let Some(pos) = active.iter().position(|&a| a == i) {
                active.swap_remove(pos);
            }
            let Some(&(next, _, _)) = events.get(k + 1) else {
                break;
            };
            if next <= u || active.is_empty() {
                continue;
            }
            let reach: f64 = active.iter().map(|&a| spans[a as usize].positive).sum();
            if reach < self.threshold {
                continue;
            }
            let mut p = [0.0; 5];
            for &a in &active {
                for (x, y) in p.iter_mut().zip(spans[a as usize].poly) {
                    *x += y;
                }
            }
            p[0] -= self.threshold;
            roots.clear();
            roots_in(&p, u, next, &mut roots);
            for &r in &roots {
                let t = shift + r / len;
                if t > t_min && t < t_max && !f(t) {
                    return;
                }
            }
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

impl Comp {
    /// The field at blob-space point `p` and its blob-space gradient.
    fn density(&self, p: DVec3) -> (f64, DVec3) {
        let q = self.inv.map_or(p, |m| m.transform_point3(p));
        let (v, r2) = match self.field {
            Field::Sphere { c, r2 } => (q - c, r2),
            Field::Cylinder { a, axis, len, r2 } => {
                let w = q - a;
                let h = w.dot(axis).clamp(0.0, len);
                (w - axis * h, r2)
            }
        };
        let x = v.length_squared() / r2;
        if x >= 1.0 {
            return (0.0, DVec3::ZERO);
        }
        let k = 1.0 - x;
        // d/dp s(1 − |v|²/r²)² = −4 s (1 − x) v / r².
        let g = v * (-4.0 * self.strength * k / r2);
        (self.strength * k * k, self.grad * g)
    }

    /// Appends the stretches of `ray` (blob space, unit direction) within this
    /// component, clipped to `[lo, hi]`.
    fn intervals(&self, ray: &Ray, lo: f64, hi: f64, out: &mut Vec<Interval>) {
        let (o, d) = match &self.inv {
            None => (ray.origin, ray.dir),
            Some(m) => (m.transform_point3(ray.origin), m.transform_vector3(ray.dir)),
        };
        let mut push = |q: [f64; 3], a: f64, b: f64| {
            let (a, b) = (a.max(lo), b.min(hi));
            if a < b {
                out.push(Interval {
                    u0: a,
                    u1: b,
                    poly: self.quartic(q),
                    positive: self.strength.max(0.0),
                });
            }
        };
        match self.field {
            Field::Sphere { c, r2 } => {
                let q = sphere_q(o - c, d, r2);
                if let Some((a, b)) = below_one(q) {
                    push(q, a, b);
                }
            }
            Field::Cylinder { a, axis, len, r2 } => {
                let w = o - a;
                let (h0, h1) = (w.dot(axis), d.dot(axis));
                // The stretch where the axis coordinate lies in [from, to].
                let along = |from: f64, to: f64| -> Option<(f64, f64)> {
                    if h1 == 0.0 {
                        return (h0 >= from && h0 <= to)
                            .then_some((f64::NEG_INFINITY, f64::INFINITY));
                    }
                    let (x, y) = ((from - h0) / h1, (to - h0) / h1);
                    Some((x.min(y), x.max(y)))
                };
                // Body: distance to the axis line.
                let qa = (d.length_squared() - h1 * h1) / r2;
                let qb = 2.0 * (w.dot(d) - h0 * h1) / r2;
                let qc = (w.length_squared() - h0 * h0) / r2;
                let body = [qc, qb, qa];
                let inside = if qa <= 1e-14 * (1.0 + qb.abs() + qc.abs()) {
                    // Along the axis: constant distance.
                    (qc < 1.0).then_some((f64::NEG_INFINITY, f64::INFINITY))
                } else {
                    below_one(body)
                };
                if let (Some((s0, s1)), Some((h_0, h_1))) = (inside, along(0.0, len)) {
                    push(body, s0.max(h_0), s1.min(h_1));
                }
                // Round ends.
                for (centre, from, to) in [
                    (a, f64::NEG_INFINITY, 0.0),
                    (a + axis * len, len, f64::INFINITY),
                ] {
                    let q = sphere_q(o - centre, d, r2);
                    if let (Some((s0, s1)), Some((h_0, h_1))) = (below_one(q), along(from, to)) {
                        push(q, s0.max(h_0), s1.min(h_1));
                    }
                }
            }
        }
    }

    /// `s (1 − q)²` for `q = q0 + q1 u + q2 u²`.
    fn quartic(&self, [c, b, a]: [f64; 3]) -> Quartic {
        let s = self.strength;
        let k = 1.0 - c;
        [
            s * k * k,
            -2.0 * s * b * k,
            s * (b * b - 2.0 * a * k),
            2.0 * s * a * b,
            s * a * a,
        ]
    }
}

fn contains(b: &Aabb, p: DVec3) -> bool {
    p.cmpge(b.min).all() && p.cmple(b.max).all()
}

/// `|w + u d|² / r²` as `[q0, q1, q2]`.
fn sphere_q(w: DVec3, d: DVec3, r2: f64) -> [f64; 3] {
    [
        w.length_squared() / r2,
        2.0 * w.dot(d) / r2,
        d.length_squared() / r2,
    ]
}

/// Where `q0 + q1 u + q2 u² < 1` (`q2 > 0`): the open interval between the roots.
fn below_one([c, b, a]: [f64; 3]) -> Option<(f64, f64)> {
    if a <= 0.0 {
        return None;
    }
    // Stable roots of a u² + b u + (c − 1).
    let c1 = c - 1.0;
    let disc = b * b - 4.0 * a * c1;
    if disc <= 0.0 {
        return None;
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    let (x, y) = if q == 0.0 {
        (0.0, 0.0)
    } else {
        (q / a, c1 / q)
    };
    Some((x.min(y), x.max(y)))
}

/// Horner evaluation of `p` (lowest power first).
fn eval(p: &[f64], x: f64) -> f64 {
    p.iter().rev().fold(0.0, |acc, &c| acc * x + c)
}

/// Appends the roots of polynomial `p` (lowest power first, degree ≤ 4) in
/// `[a, b)`, ascending: the critical points (roots of the derivative, found the
/// same way) cut the interval into monotone pieces, and each piece whose ends
/// differ in sign holds exactly one root.
pub fn roots_in(p: &[f64], a: f64, b: f64, out: &mut Vec<f64>) {
    let mut n = p.len();
    while n > 0 && p[n - 1] == 0.0 {
        n -= 1;
    }
    if n <= 1 {
        return;
    }
    let p = &p[..n];
    if n == 2 {
        let r = -p[0] / p[1];
        if r >= a && r < b {
            out.push(r);
        }
        return;
    }
    let mut d = [0.0; 4];
    for i in 1..n {
        d[i - 1] = p[i] * i as f64;
    }
    let mut knots = Vec::with_capacity(5);
    knots.push(a);
    roots_in(&d[..n - 1], a, b, &mut knots);
    knots.push(b);
    let mut fa = eval(p, a);
    for w in knots.windows(2) {
        let (x0, x1) = (w[0], w[1]);
        let fb = eval(p, x1);
        if x1 > x0 && (fa < 0.0) != (fb < 0.0) {
            out.push(bracketed(p, &d[..n - 1], x0, x1, fa));
        }
        fa = fb;
    }
}

/// The root of `p` (derivative `d`) between `lo` and `hi` where it changes sign
/// (`f_lo` the value at `lo`): Newton steps kept inside a shrinking bracket,
/// bisecting when a step would leave it.
fn bracketed(p: &[f64], d: &[f64], mut lo: f64, mut hi: f64, f_lo: f64) -> f64 {
    let neg_lo = f_lo < 0.0;
    let mut x = 0.5 * (lo + hi);
    for _ in 0..100 {
        let fx = eval(p, x);
        if fx == 0.0 {
            return x;
        }
        if (fx < 0.0) == neg_lo {
            lo = x;
        } else {
            hi = x;
        }
        let dx = eval(d, x);
        let newton = x - fx / dx;
        let next = if dx != 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - x).abs() <= 1e-13 * (1.0 + x.abs()) || hi - lo <= 1e-13 * (1.0 + x.abs()) {
            return next;
        }
        x = next;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::BlobComponent;

    fn sphere(center: DVec3, radius: f64, strength: f64) -> BlobComponent {
        BlobComponent {
            kind: BlobKind::Sphere { center, radius },
            strength,
            transform: None,
            texture: None,
        }
    }

    fn all(b: &Blob, ray: &Ray) -> Vec<f64> {
        let mut v = Vec::new();
        b.hits(ray, 0.0, f64::INFINITY, &mut |t| {
            v.push(t);
            true
        });
        v
    }

    #[test]
    fn roots_of_polynomials_in_an_interval() {
        // (x − 1)(x − 2)(x − 3)(x − 4).
        let p = [24.0, -50.0, 35.0, -10.0, 1.0];
        let mut r = Vec::new();
        roots_in(&p, 0.0, 10.0, &mut r);
        assert_eq!(r.len(), 4, "{r:?}");
        for (x, e) in r.iter().zip([1.0, 2.0, 3.0, 4.0]) {
            assert!((x - e).abs() < 1e-12, "{r:?}");
        }
        r.clear();
        roots_in(&p, 1.5, 3.5, &mut r);
        assert_eq!(r.len(), 2);
        // A tiny leading coefficient: nearly the quadratic x² − 1.
        r.clear();
        roots_in(&[-1.0, 0.0, 1.0, 0.0, 1e-18], -2.0, 2.0, &mut r);
        assert_eq!(r.len(), 2);
        assert!((r[0] + 1.0).abs() < 1e-12 && (r[1] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn one_sphere_is_a_sphere_of_the_apparent_radius() {
        // s (1 − (d/r)²)² = T at d = r √(1 − √(T/s)).
        let data = BlobData {
            threshold: 0.5,
            components: vec![sphere(DVec3::ZERO, 2.0, 1.0)],
        };
        let b = Blob::new(&data, None);
        let r = 2.0 * (1.0 - 0.5f64.sqrt()).sqrt();
        let h = all(&b, &Ray::new(DVec3::new(0.0, 0.0, -10.0), DVec3::Z * 0.5));
        assert_eq!(h.len(), 2, "{h:?}");
        assert!((h[0] - (10.0 - r) * 2.0).abs() < 1e-9, "{h:?}");
        assert!((h[1] - (10.0 + r) * 2.0).abs() < 1e-9, "{h:?}");
        assert!(b.inside(DVec3::ZERO) && !b.inside(DVec3::X * (r + 1e-6)));
        let n = b.normal(DVec3::new(r, 0.0, 0.0)).normalize();
        assert!((n - DVec3::X).length() < 1e-12);
    }

    #[test]
    fn cylinder_has_round_ends_and_negative_strength_carves() {
        let cyl = BlobComponent {
            kind: BlobKind::Cylinder {
                a: DVec3::new(-2.0, 0.0, 0.0),
                b: DVec3::new(2.0, 0.0, 0.0),
                radius: 1.0,
            },
            strength: 1.0,
            transform: None,
            texture: None,
        };
        let data = BlobData {
            threshold: 0.25,
            components: vec![cyl.clone()],
        };
        let b = Blob::new(&data, None);
        let r = (1.0 - 0.5f64).sqrt(); // (1 − x)² = 1/4 → x = 1/2
                                       // Along the axis: the round ends at ±(2 + r).
        let h = all(&b, &Ray::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X));
        assert_eq!(h.len(), 2);
        assert!((h[0] - (8.0 - r)).abs() < 1e-9 && (h[1] - (12.0 + r)).abs() < 1e-9);
        // Across the body, and across an end at an angle.
        let h = all(&b, &Ray::new(DVec3::new(1.0, 5.0, 0.0), -DVec3::Y));
        assert!((h[0] - (5.0 - r)).abs() < 1e-9 && (h[1] - (5.0 + r)).abs() < 1e-9);
        let ray = Ray::new(DVec3::new(-2.3, 5.0, 0.1), DVec3::new(0.05, -1.0, 0.02));
        for t in all(&b, &ray) {
            assert!((b.field(ray.at(t)) - 0.25).abs() < 1e-9);
        }
        // A negative sphere in the middle cuts the bar in two.
        let data = BlobData {
            threshold: 0.25,
            components: vec![cyl, sphere(DVec3::ZERO, 1.0, -2.0)],
        };
        let b = Blob::new(&data, None);
        let h = all(&b, &Ray::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X));
        assert_eq!(h.len(), 4, "{h:?}");
        assert!(!b.inside(DVec3::ZERO));
    }

    #[test]
    fn many_components_use_the_hierarchy_and_agree_with_the_field() {
        let mut comps = Vec::new();
        for i in 0..40 {
            let f = i as f64;
            comps.push(sphere(
                DVec3::new(
                    (f * 0.7).sin() * 3.0,
                    (f * 1.3).cos() * 3.0,
                    (f * 0.37).sin(),
                ),
                1.0 + 0.3 * (f * 2.1).sin(),
                if i % 7 == 3 { -0.5 } else { 1.0 },
            ));
        }
        let data = BlobData {
            threshold: 0.6,
            components: comps,
        };
        let b = Blob::new(&data, None);
        assert!(b.bvh.is_some());
        let mut found = 0;
        for k in 0..200 {
            let f = k as f64;
            let o = DVec3::new((f * 0.91).sin(), (f * 0.53).cos(), -1.0) * 10.0;
            let target = DVec3::new((f * 1.7).sin() * 3.0, (f * 2.3).cos() * 3.0, 0.0);
            let ray = Ray::new(o, target - o);
            let h = all(&b, &ray);
            assert!(h.len().is_multiple_of(2), "{h:?}");
            for w in h.windows(2) {
                assert!(w[0] <= w[1]);
            }
            for &t in &h {
                assert!((b.field(ray.at(t)) - 0.6).abs() < 1e-8);
                found += 1;
            }
            // Inside between pairs.
            for p in h.chunks(2) {
                let mid = ray.at(0.5 * (p[0] + p[1]));
                assert!(b.inside(mid) || (p[1] - p[0]) < 1e-6);
            }
        }
        assert!(found > 100);
    }
}
