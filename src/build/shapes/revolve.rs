//! What the shapes of revolution (`lathe`, `sor`) share: real roots of a
//! polynomial of degree ≤ 6 inside an interval.
//!
//! A ray against a curve revolved around the y axis gives a polynomial equation
//! (degree 6 in the curve's parameter for a cubic `lathe` segment, degree 3 in
//! the ray distance for a `sor` segment). Its roots in an interval are isolated
//! by the roots of its derivative (found the same way, down to a line): between
//! two neighbouring critical points the polynomial is monotone, so a sign change
//! there brackets exactly one root, which a safeguarded Newton iteration finds
//! to machine precision. Double roots (a ray grazing the surface) are not
//! reported, as they change nothing for inside tests and shading.

/// The highest degree [`roots_in`] solves.
pub const MAX_DEGREE: usize = 6;

/// A polynomial of degree ≤ [`MAX_DEGREE`], lowest power first.
pub type Poly = [f64; MAX_DEGREE + 1];

/// The value of `p` at `x`.
#[inline]
pub fn eval(p: &[f64], x: f64) -> f64 {
    p.iter().rev().fold(0.0, |acc, &c| acc * x + c)
}

/// The product of two polynomials (lowest power first) whose degrees add up to
/// at most [`MAX_DEGREE`].
pub fn mul(a: &[f64], b: &[f64]) -> Poly {
    let mut r = [0.0; MAX_DEGREE + 1];
    for (i, &x) in a.iter().enumerate() {
        for (j, &y) in b.iter().enumerate() {
            if x != 0.0 && y != 0.0 {
                r[i + j] += x * y;
            }
        }
    }
    r
}

/// The real roots of `p` (lowest power first, degree ≤ [`MAX_DEGREE`]) in
/// `[lo, hi]`, ascending, into `out`; returns how many. Degrees above 2 need a
/// finite interval.
pub fn roots_in(p: &[f64], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    let deg = match p.iter().rposition(|&c| c != 0.0) {
        Some(d) => d.min(MAX_DEGREE),
        None => return 0,
    };
    // Also rejects NaN bounds.
    if lo
        .partial_cmp(&hi)
        .is_none_or(|o| o == std::cmp::Ordering::Greater)
    {
        return 0;
    }
    let inside = |x: f64| x >= lo && x <= hi;
    match deg {
        0 => 0,
        1 => {
            let x = -p[0] / p[1];
            if inside(x) {
                out[0] = x;
                1
            } else {
                0
            }
        }
        2 => {
            let (a, b, c) = (p[2], p[1], p[0]);
            let disc = b * b - 4.0 * a * c;
            if disc < 0.0 {
                return 0;
            }
            let q = -0.5 * (b + disc.sqrt().copysign(b));
            let mut r = if q == 0.0 { [0.0, 0.0] } else { [q / a, c / q] };
            r.sort_by(f64::total_cmp);
            let mut n = 0;
            for x in r {
                if inside(x) && (n == 0 || out[n - 1] != x) {
                    out[n] = x;
                    n += 1;
                }
            }
            n
        }
        _ => {
            let p = &p[..=deg];
            let mut dp = [0.0; MAX_DEGREE + 1];
            for k in 1..=deg {
                dp[k - 1] = k as f64 * p[k];
            }
            let mut crit = [0.0; MAX_DEGREE];
            let m = roots_in(&dp[..deg], lo, hi, &mut crit);
            let mut n = 0;
            let mut a = lo;
            let mut fa = eval(p, a);
            for &b in crit[..m].iter().chain(std::iter::once(&hi)) {
                let fb = eval(p, b);
                if fa == 0.0 {
                    if n == 0 || out[n - 1] != a {
                        out[n] = a;
                        n += 1;
                    }
                } else if fb != 0.0 && (fa < 0.0) != (fb < 0.0) {
                    out[n] = bracketed(p, &dp[..deg], a, b, fa);
                    n += 1;
                }
                (a, fa) = (b, fb);
            }
            if fa == 0.0 && (n == 0 || out[n - 1] != a) && n < MAX_DEGREE {
                out[n] = a;
                n += 1;
            }
            n
        }
    }
}

/// The root of `p` in `[a, b]`, where `p` is monotone and changes sign (`fa` is
/// `p(a)`): Newton steps, falling back to bisection when a step leaves the
/// bracket or does not shrink it enough.
fn bracketed(p: &[f64], dp: &[f64], mut a: f64, mut b: f64, fa: f64) -> f64 {
    // Orient so that p(lo) < 0.
    if fa > 0.0 {
        std::mem::swap(&mut a, &mut b);
    }
    let (mut lo, mut hi) = (a, b);
    let mut x = 0.5 * (lo + hi);
    let mut step_before = (hi - lo).abs();
    for _ in 0..100 {
        let f = eval(p, x);
        if f == 0.0 {
            return x;
        }
        if f < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let df = eval(dp, x);
        let newton = x - f / df;
        let within = (newton - lo) * (newton - hi) < 0.0;
        let next = if within && (newton - x).abs() * 2.0 < step_before {
            newton
        } else {
            0.5 * (lo + hi)
        };
        step_before = (next - x).abs();
        if next == x || step_before <= 4.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE) {
            return next;
        }
        x = next;
    }
    x
}

/// The angle of `p` around the y axis as a fraction of a turn in [0, 1),
/// `atan2(z, x) / 2π` (the u of POV-Ray's uv mapping of spheres, lathes and sors).
pub fn around_y(p: glam::DVec3) -> f64 {
    (p.z.atan2(p.x) / std::f64::consts::TAU).rem_euclid(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn from_roots(r: &[f64]) -> Poly {
        let mut p = [0.0; MAX_DEGREE + 1];
        p[0] = 1.0;
        for &x in r {
            p = mul(&p[..MAX_DEGREE], &[-x, 1.0]);
        }
        p
    }

    #[test]
    fn sextic_roots_in_the_unit_interval() {
        let roots = [-0.5, 0.1, 0.2, 0.25, 0.7, 0.99];
        let p = from_roots(&roots);
        let mut out = [0.0; MAX_DEGREE];
        let n = roots_in(&p, 0.0, 1.0, &mut out);
        assert_eq!(n, 5, "{out:?}");
        for (x, r) in out.iter().zip(&roots[1..]) {
            assert!((x - r).abs() < 1e-12, "{out:?}");
        }
    }

    #[test]
    fn no_roots_and_complex_pairs() {
        // (x² + 1)(x − 0.5)(x − 2): one root in [0, 1].
        let p = mul(&[1.0, 0.0, 1.0], &mul(&[-0.5, 1.0], &[-2.0, 1.0])[..3]);
        let mut out = [0.0; MAX_DEGREE];
        assert_eq!(roots_in(&p, 0.0, 1.0, &mut out), 1);
        assert!((out[0] - 0.5).abs() < 1e-14);
        assert_eq!(roots_in(&[1.0, 0.0, 1.0], -5.0, 5.0, &mut out), 0);
        assert_eq!(roots_in(&[0.0; 7], 0.0, 1.0, &mut out), 0);
    }

    #[test]
    fn quadratic_on_an_unbounded_interval() {
        let mut out = [0.0; MAX_DEGREE];
        let n = roots_in(&[-4.0, 0.0, 1.0], 0.0, f64::INFINITY, &mut out);
        assert_eq!((n, out[0]), (1, 2.0));
    }

    #[test]
    fn close_roots_are_separated() {
        let p = from_roots(&[0.5, 0.5 + 1e-6]);
        let mut out = [0.0; MAX_DEGREE];
        assert_eq!(roots_in(&p, 0.0, 1.0, &mut out), 2);
        assert!((out[1] - out[0] - 1e-6).abs() < 1e-9, "{out:?}");
    }
}
