//! Real roots of cubic and quartic polynomials (for the torus), polished with
//! Newton steps so they are accurate to near machine precision.

/// Real roots of `x³ + a x² + b x + c`, unsorted; returns how many were written.
pub fn cubic(a: f64, b: f64, c: f64, out: &mut [f64; 3]) -> usize {
    // Depress: x = y - a/3 → y³ + p y + q.
    let a3 = a / 3.0;
    let p = b - a * a3;
    let q = c - b * a3 + 2.0 * a3 * a3 * a3;
    let (p3, q2) = (p / 3.0, q / 2.0);
    let disc = q2 * q2 + p3 * p3 * p3;
    let n = if disc > 0.0 {
        let s = disc.sqrt();
        // Cancellation-free: pick the larger-magnitude term first.
        let u = (-q2 - s.copysign(q2)).cbrt();
        let v = if u != 0.0 { -p3 / u } else { 0.0 };
        out[0] = u + v - a3;
        1
    } else if p3 == 0.0 {
        out[0] = -a3;
        1
    } else {
        let r = (-p3).sqrt();
        let phi = (q2 / (r * r * r)).clamp(-1.0, 1.0).acos() / 3.0;
        let tau = std::f64::consts::TAU / 3.0;
        for (k, o) in out.iter_mut().enumerate() {
            *o = -2.0 * r * (phi + tau * k as f64).cos() - a3;
        }
        3
    };
    for x in out.iter_mut().take(n) {
        *x = polish(*x, |x| {
            (((x + a) * x + b) * x + c, (3.0 * x + 2.0 * a) * x + b)
        });
    }
    n
}

/// Real roots of `x⁴ + a x³ + b x² + c x + d`, sorted ascending; returns how many.
pub fn quartic(a: f64, b: f64, c: f64, d: f64, out: &mut [f64; 4]) -> usize {
    let f = |x: f64| {
        (
            (((x + a) * x + b) * x + c) * x + d,
            ((4.0 * x + 3.0 * a) * x + 2.0 * b) * x + c,
        )
    };
    // Depress: x = y - a/4 → y⁴ + p y² + q y + r.
    let a4 = a / 4.0;
    let a2 = a4 * a4;
    let p = b - 6.0 * a2;
    let q = c - 2.0 * b * a4 + 8.0 * a2 * a4;
    let r = d - c * a4 + b * a2 - 3.0 * a2 * a2;
    let mut n = 0;
    let mut push = |y: f64, out: &mut [f64; 4]| {
        if n < 4 {
            out[n] = polish(y - a4, f);
            n += 1;
        }
    };
    let scale = 1.0 + p.abs() + r.abs().sqrt();
    if q.abs() <= 1e-14 * scale * scale.sqrt() {
        // Biquadratic: z = y².
        let mut z = [0.0; 2];
        let k = quadratic(p, r, &mut z);
        for &zz in &z[..k] {
            if zz >= 0.0 {
                let y = zz.sqrt();
                push(y, out);
                push(-y, out);
            }
        }
    } else {
        // Resolvent: 8m³ + 8p m² + (2p² - 8r) m - q² = 0 has a root m > 0.
        let mut ms = [0.0; 3];
        let k = cubic(p, p * p / 4.0 - r, -q * q / 8.0, &mut ms);
        let m = ms[..k].iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if m <= 0.0 || !m.is_finite() {
            return 0;
        }
        let s = (2.0 * m).sqrt();
        let h = q / (2.0 * s);
        let mut y = [0.0; 2];
        for &(b1, c1) in &[(-s, p / 2.0 + m + h), (s, p / 2.0 + m - h)] {
            let k = quadratic(b1, c1, &mut y);
            for &yy in &y[..k] {
                push(yy, out);
            }
        }
    }
    out[..n].sort_by(f64::total_cmp);
    n
}

/// Real roots of `x² + b x + c`; returns how many.
fn quadratic(b: f64, c: f64, out: &mut [f64; 2]) -> usize {
    let disc = b * b - 4.0 * c;
    if disc < 0.0 {
        return 0;
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    if q == 0.0 {
        out[0] = 0.0;
        return 1;
    }
    out[0] = q;
    out[1] = c / q;
    2
}

/// A few Newton steps from `x`, keeping the best point seen.
fn polish(mut x: f64, f: impl Fn(f64) -> (f64, f64)) -> f64 {
    let (mut fx, mut dfx) = f(x);
    for _ in 0..4 {
        if dfx == 0.0 || fx == 0.0 {
            break;
        }
        let nx = x - fx / dfx;
        let (nf, nd) = f(nx);
        // Stop unless strictly better (a NaN is never better).
        if nf.abs().partial_cmp(&fx.abs()) != Some(std::cmp::Ordering::Less) {
            break;
        }
        (x, fx, dfx) = (nx, nf, nd);
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    fn from_roots(r: [f64; 4]) -> (f64, f64, f64, f64) {
        let [r0, r1, r2, r3] = r;
        let a = -(r0 + r1 + r2 + r3);
        let b = r0 * r1 + r0 * r2 + r0 * r3 + r1 * r2 + r1 * r3 + r2 * r3;
        let c = -(r0 * r1 * r2 + r0 * r1 * r3 + r0 * r2 * r3 + r1 * r2 * r3);
        let d = r0 * r1 * r2 * r3;
        (a, b, c, d)
    }

    #[test]
    fn quartic_recovers_four_real_roots() {
        for roots in [
            [-3.0, -1.0, 2.0, 5.0],
            [0.1, 0.2, 0.3, 0.4],
            [-10.0, 1.0, 1.5, 100.0],
            [1.0, 2.0, 3.0, 4.0],
            [-2.0, -1.0, 1.0, 2.0],
        ] {
            let (a, b, c, d) = from_roots(roots);
            let mut out = [0.0; 4];
            assert_eq!(quartic(a, b, c, d, &mut out), 4, "{roots:?}");
            for (x, r) in out.iter().zip(roots) {
                assert!(
                    (x - r).abs() < 1e-7 * (1.0 + r.abs()),
                    "{out:?} vs {roots:?}"
                );
            }
        }
    }

    #[test]
    fn quartic_with_complex_pairs() {
        // (x² + 1)(x - 1)(x - 3) = x⁴ - 4x³ + 4x² - 4x + 3.
        let mut out = [0.0; 4];
        let n = quartic(-4.0, 4.0, -4.0, 3.0, &mut out);
        assert_eq!(n, 2);
        assert!((out[0] - 1.0).abs() < 1e-10 && (out[1] - 3.0).abs() < 1e-10);
        // (x² + 1)(x² + 4): no real roots.
        assert_eq!(quartic(0.0, 5.0, 0.0, 4.0, &mut out), 0);
    }

    #[test]
    fn cubic_roots() {
        let mut out = [0.0; 3];
        // (x-1)(x-2)(x-3) = x³ - 6x² + 11x - 6.
        let n = cubic(-6.0, 11.0, -6.0, &mut out);
        assert_eq!(n, 3);
        let mut r = out;
        r.sort_by(f64::total_cmp);
        for (x, e) in r.iter().zip([1.0, 2.0, 3.0]) {
            assert!((x - e).abs() < 1e-12);
        }
        // x³ - 8: one real root 2.
        assert_eq!(cubic(0.0, 0.0, -8.0, &mut out), 1);
        assert!((out[0] - 2.0).abs() < 1e-12);
    }
}
