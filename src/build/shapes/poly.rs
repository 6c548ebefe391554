//! `poly`, `cubic` and `quartic`: the surface where a polynomial in x, y, z of
//! order 2 to 4 is zero, inside where it is negative (POV-Ray's convention).
//! Coefficients come in POV-Ray's order: terms by falling power of x, then of y,
//! then of z (for order 4: x⁴, x³y, x³z, x³, x²y², … z, 1).

use crate::build::quartic::{cubic, quartic};
use crate::build::Ray;
use glam::DVec3;

/// Highest order solved (roots of up to a quartic along a ray).
pub const MAX_ORDER: u32 = 4;

/// How many coefficients a polynomial of order `n` has: `(n+1)(n+2)(n+3)/6`.
pub fn term_count(order: u32) -> usize {
    let n = order as usize;
    (n + 1) * (n + 2) * (n + 3) / 6
}

/// A polynomial surface: each term's exponents of x, y, z and its coefficient.
/// Zero terms are dropped.
#[derive(Clone, Debug, PartialEq)]
pub struct Poly {
    terms: Vec<([u8; 3], f64)>,
}

/// A polynomial in the ray distance t, lowest power first.
type InT = [f64; 5];

impl Poly {
    /// The surface of order `order` (2 to [`MAX_ORDER`]) with `coefficients`
    /// in POV-Ray's order (see the module comment); `None` when the count is
    /// not [`term_count`]`(order)`.
    pub fn new(order: u32, coefficients: &[f64]) -> Option<Poly> {
        if !(2..=MAX_ORDER).contains(&order) || coefficients.len() != term_count(order) {
            return None;
        }
        let n = order as u8;
        let mut exps = Vec::with_capacity(coefficients.len());
        for i in (0..=n).rev() {
            for j in (0..=n - i).rev() {
                for k in (0..=n - i - j).rev() {
                    exps.push([i, j, k]);
                }
            }
        }
        let terms = exps
            .into_iter()
            .zip(coefficients.iter().copied())
            .filter(|&(_, c)| c != 0.0)
            .collect();
        Some(Poly { terms })
    }

    /// The polynomial's value at `p` (negative inside).
    pub fn value(&self, p: DVec3) -> f64 {
        self.terms
            .iter()
            .map(|&([i, j, k], c)| c * p.x.powi(i.into()) * p.y.powi(j.into()) * p.z.powi(k.into()))
            .sum()
    }

    /// The gradient at `p`: the outward normal, unnormalised.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let pw = |x: f64, e: u8| {
            if e == 0 {
                0.0
            } else {
                f64::from(e) * x.powi(i32::from(e) - 1)
            }
        };
        let mut g = DVec3::ZERO;
        for &([i, j, k], c) in &self.terms {
            let (xi, yj, zk) = (p.x.powi(i.into()), p.y.powi(j.into()), p.z.powi(k.into()));
            g.x += c * pw(p.x, i) * yj * zk;
            g.y += c * xi * pw(p.y, j) * zk;
            g.z += c * xi * yj * pw(p.z, k);
        }
        g
    }

    /// Whether `p` is strictly inside.
    pub fn inside(&self, p: DVec3) -> bool {
        self.value(p) < 0.0
    }

    /// The polynomial along `ray`: its coefficients in t, lowest power first.
    fn along(&self, ray: &Ray) -> InT {
        // Powers 0..=4 of (o + t d) per axis, each a polynomial in t.
        let powers = |o: f64, d: f64| {
            let mut p = [[0.0; 5]; 5];
            p[0][0] = 1.0;
            for e in 1..5 {
                for m in 0..5 {
                    let lower = if m > 0 { p[e - 1][m - 1] * d } else { 0.0 };
                    p[e][m] = p[e - 1][m] * o + lower;
                }
            }
            p
        };
        let px = powers(ray.origin.x, ray.dir.x);
        let py = powers(ray.origin.y, ray.dir.y);
        let pz = powers(ray.origin.z, ray.dir.z);
        let mut sum: InT = [0.0; 5];
        for &([i, j, k], c) in &self.terms {
            let xy = mul(&px[i as usize], &py[j as usize]);
            let xyz = mul(&xy, &pz[k as usize]);
            for m in 0..5 {
                sum[m] += c * xyz[m];
            }
        }
        sum
    }

    /// Every crossing in `(t_min, t_max)`.
    pub fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(f64)) {
        let p = self.along(ray);
        let mut roots = [0.0; 4];
        let n = roots_of(&p, &mut roots);
        for &t in &roots[..n] {
            if t > t_min && t < t_max {
                f(t);
            }
        }
    }

    /// The nearest crossing in `(t_min, t_max)`.
    pub fn nearest(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
        super::nearest(|f| self.hits(ray, t_min, t_max, f))
    }
}

/// The product of two polynomials in t, truncated to degree 4 (the products
/// of a term's powers never exceed its order).
fn mul(a: &InT, b: &InT) -> InT {
    let mut r = [0.0; 5];
    for (i, &x) in a.iter().enumerate() {
        if x == 0.0 {
            continue;
        }
        for (j, &y) in b.iter().enumerate().take(5 - i) {
            r[i + j] += x * y;
        }
    }
    r
}

/// Real roots of `p` (lowest power first, degree ≤ 4) into `out`; returns how
/// many. Leading coefficients tiny against the largest are dropped, so rays along
/// which the surface degenerates to a lower order are solved at that order; a
/// root of the shortened polynomial is kept only where the whole one vanishes
/// too (far along the ray a dropped term can outweigh the rest: a Piriform
/// rotated by 90° showed a false sheet at the horizon, 8.7e6 units away).
fn roots_of(p: &InT, out: &mut [f64; 4]) -> usize {
    let n = reduced_roots_of(p, out);
    let mut kept = 0;
    for i in 0..n {
        let t = out[i];
        let (mut value, mut size, mut power) = (0.0, 0.0, 1.0);
        for c in p {
            value += c * power;
            size += (c * power).abs();
            power *= t;
        }
        if value.abs() <= 1e-6 * size {
            out[kept] = t;
            kept += 1;
        }
    }
    kept
}

/// [`roots_of`] without the check against the whole polynomial.
fn reduced_roots_of(p: &InT, out: &mut [f64; 4]) -> usize {
    let scale = p.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    if scale == 0.0 || !scale.is_finite() {
        return 0;
    }
    let Some(deg) = (1..5).rev().find(|&d| p[d].abs() > 1e-12 * scale) else {
        return 0;
    };
    let lead = p[deg];
    match deg {
        4 => quartic(p[3] / lead, p[2] / lead, p[1] / lead, p[0] / lead, out),
        3 => {
            let mut r = [0.0; 3];
            let n = cubic(p[2] / lead, p[1] / lead, p[0] / lead, &mut r);
            out[..n].copy_from_slice(&r[..n]);
            n
        }
        2 => {
            let (b, c) = (p[1] / lead, p[0] / lead);
            let disc = b * b - 4.0 * c;
            if disc < 0.0 {
                return 0;
            }
            let q = -0.5 * (b + disc.sqrt().copysign(b));
            out[0] = q;
            if q != 0.0 {
                out[1] = c / q;
                2
            } else {
                1
            }
        }
        _ => {
            out[0] = -p[0] / lead;
            1
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// POV-Ray's sample torus: major radius √40, minor √12, in the xz plane.
    fn torus() -> Poly {
        #[rustfmt::skip]
        let c = [
            1.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 2.0, 0.0, -104.0,
            0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
            1.0, 0.0, 0.0, 2.0, 0.0, 56.0, 0.0, 0.0, 0.0, 0.0,
            1.0, 0.0, -104.0, 0.0, 784.0,
        ];
        Poly::new(4, &c).expect("35 coefficients")
    }

    #[test]
    fn a_root_only_the_shortened_polynomial_has_is_dropped() {
        // Along a ray nearly across a rotated Piriform's axis the t⁴ term is
        // tiny against the others and is dropped; the cubic left has a root
        // at t ≈ 8.7e6, where the t⁴ term outweighs everything else.
        let p = [
            68.19753086419753,
            -8.931134036866125,
            0.44445273597657714,
            -5.1172408769164256e-8,
            3.867159662355276e-11,
        ];
        let mut roots = [0.0; 4];
        assert_eq!(roots_of(&p, &mut roots), 0, "{roots:?}");
        // A true root of a shortened polynomial stays.
        let q = [-1.0, 0.0, 1.0, 0.0, 1e-20];
        let n = roots_of(&q, &mut roots);
        let mut found = roots[..n].to_vec();
        found.sort_by(f64::total_cmp);
        assert_eq!(found, [-1.0, 1.0]);
    }

    #[test]
    fn term_counts_follow_the_order() {
        assert_eq!(
            [2, 3, 4].map(term_count),
            [10, 20, 35],
            "quadric, cubic, quartic"
        );
        assert!(Poly::new(4, &[1.0; 34]).is_none());
        assert!(Poly::new(5, &[1.0; 56]).is_none());
    }

    #[test]
    fn the_sample_torus_is_hit_where_a_torus_is() {
        let (big, small) = (40f64.sqrt(), 12f64.sqrt());
        let p = torus();
        // Along the x axis from outside: the tube's four crossings.
        let ray = Ray::new(DVec3::new(-20.0, 0.0, 0.0), DVec3::X);
        let mut ts = Vec::new();
        p.hits(&ray, 0.0, f64::INFINITY, &mut |t| ts.push(t));
        ts.sort_by(f64::total_cmp);
        let want = [-big - small, -big + small, big - small, big + small].map(|x| x + 20.0);
        assert_eq!(ts.len(), 4);
        for (t, w) in ts.iter().zip(want) {
            assert!((t - w).abs() < 1e-9, "{t} vs {w}");
        }
        // Inside the tube and outside it; the normal at the outer rim points out.
        assert!(p.inside(DVec3::new(big, 0.0, 0.0)));
        assert!(!p.inside(DVec3::ZERO));
        let n = p.normal(DVec3::new(0.0, 0.0, big + small)).normalize();
        assert!((n - DVec3::Z).length() < 1e-9, "{n}");
        // Straight down onto the top of the tube.
        let down = Ray::new(DVec3::new(0.0, 10.0, big), DVec3::NEG_Y);
        let t = p.nearest(&down, 0.0, f64::INFINITY).expect("hit");
        assert!((t - (10.0 - small)).abs() < 1e-9, "{t}");
    }

    #[test]
    fn lower_orders_and_degenerate_rays() {
        // poly { 2, … }: the unit sphere x² + y² + z² - 1.
        let mut c = [0.0; 10];
        c[0] = 1.0; // x²
        c[4] = 1.0; // y²
        c[7] = 1.0; // z²
        c[9] = -1.0;
        let s = Poly::new(2, &c).expect("10 coefficients");
        let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        assert!((s.nearest(&ray, 0.0, f64::INFINITY).unwrap() - 4.0).abs() < 1e-12);
        // cubic: the plane-like surface x³ - 1 = 0 (x = 1), met along any ray
        // crossing x = 1; parallel rays see a constant and no root.
        let mut c = [0.0; 20];
        c[0] = 1.0;
        c[19] = -1.0;
        let cb = Poly::new(3, &c).expect("20 coefficients");
        let ray = Ray::new(DVec3::new(-3.0, 0.5, 0.0), DVec3::new(2.0, 0.3, 0.0));
        let t = cb.nearest(&ray, 0.0, f64::INFINITY).expect("hit");
        assert!((ray.at(t).x - 1.0).abs() < 1e-9);
        assert!(cb
            .nearest(&Ray::new(DVec3::ZERO, DVec3::Y), 0.0, 1e9)
            .is_none());
        // A ray along which the quartic term vanishes (x⁴ surface, ray along y).
        let mut c = [0.0; 35];
        c[0] = 1.0; // x⁴
        c[25] = 1.0; // y²
        c[34] = -4.0;
        let q = Poly::new(4, &c).expect("35 coefficients");
        let t = q
            .nearest(&Ray::new(DVec3::new(0.0, -5.0, 0.0), DVec3::Y), 0.0, 1e9)
            .expect("hit");
        assert!((t - 3.0).abs() < 1e-9, "{t}");
    }
}
