//! The built-in functions our `functions.inc` declares (`f_sphere`, `f_noise3d`,
//! …), each written from the meaning POV-Ray's manual documents for it and
//! checked against POV-Ray's values (the noise-based ones use rts's own noise, so
//! their values differ in detail). Arguments: x, y, z, then the parameters.

use super::noise::{noise, signed_noise};
use glam::DVec3;

/// A built-in function of its arguments.
pub type Native = fn(&[f64]) -> f64;

/// `(name, number of arguments, function)` for every internal function.
pub const INTERNALS: &[(&str, usize, Native)] = &[
    ("f_sphere", 4, f_sphere),
    ("f_torus", 5, f_torus),
    ("f_rounded_box", 7, f_rounded_box),
    ("f_superellipsoid", 5, f_superellipsoid),
    ("f_noise3d", 3, f_noise3d),
    ("f_snoise3d", 3, f_snoise3d),
    ("f_noise_generator", 4, f_noise_generator),
    ("f_ridged_mf", 9, f_ridged_mf),
    ("f_r", 3, f_r),
    ("f_th", 3, f_th),
    ("f_ph", 3, f_ph),
    ("f_spherical", 3, f_spherical),
    ("f_cylindrical", 3, f_cylindrical),
    ("f_boxed", 3, f_boxed),
    ("f_planar", 3, f_planar),
];

fn p(a: &[f64]) -> DVec3 {
    DVec3::new(a[0], a[1], a[2])
}

/// `f_sphere(x, y, z, R)`: distance from the origin minus R.
fn f_sphere(a: &[f64]) -> f64 {
    p(a).length() - a[3]
}

/// `f_torus(x, y, z, MAJOR, MINOR)`: distance from the ring of radius MAJOR in
/// the x-z plane, minus MINOR.
fn f_torus(a: &[f64]) -> f64 {
    let r = (a[0] * a[0] + a[2] * a[2]).sqrt() - a[3];
    (r * r + a[1] * a[1]).sqrt() - a[4]
}

/// `f_rounded_box(x, y, z, R, SX, SY, SZ)`: a box of half sizes SX, SY, SZ with
/// edges rounded by radius R: distance outside, -R everywhere inside.
fn f_rounded_box(a: &[f64]) -> f64 {
    let r = a[3];
    let q = p(a).abs() - (DVec3::new(a[4], a[5], a[6]) - DVec3::splat(r));
    q.max(DVec3::ZERO).length() - r
}

/// `f_superellipsoid(x, y, z, E, N)`: 1 minus the superellipsoid's sum, so
/// positive inside (as POV-Ray's).
fn f_superellipsoid(a: &[f64]) -> f64 {
    let (e, n) = (a[3], a[4]);
    let xy = (a[0].abs().powf(2.0 / e) + a[1].abs().powf(2.0 / e)).powf(e / n);
    1.0 - (xy + a[2].abs().powf(2.0 / n))
}

/// `f_noise3d(x, y, z)`: solid noise in [0, 1].
fn f_noise3d(a: &[f64]) -> f64 {
    noise(p(a), 2)
}

/// `f_snoise3d(x, y, z)`: solid noise in [-1, 1] (`2 f_noise3d - 1`).
fn f_snoise3d(a: &[f64]) -> f64 {
    2.0 * noise(p(a), 2) - 1.0
}

/// `f_noise_generator(x, y, z, G)`: the noise of generator G (1 to 3).
fn f_noise_generator(a: &[f64]) -> f64 {
    noise(p(a), a[3].clamp(1.0, 3.0) as u8)
}

/// `f_ridged_mf(x, y, z, H, LACUNARITY, OCTAVES, OFFSET, GAIN, G)`: Musgrave's
/// ridged multifractal: octaves of `(OFFSET - |noise|)²`, each weighted by the
/// previous one times GAIN and scaled by `LACUNARITY^(-i H)`.
fn f_ridged_mf(a: &[f64]) -> f64 {
    let (h, lac, octaves, offset, gain) = (a[3], a[4], a[5], a[6], a[7]);
    let mut q = p(a);
    let mut signal = offset - signed_noise(q).abs();
    signal *= signal;
    let mut result = signal;
    let mut weight;
    let n = octaves.clamp(1.0, 32.0) as usize;
    for i in 1..n {
        q *= lac;
        weight = (signal * gain).clamp(0.0, 1.0);
        signal = offset - signed_noise(q).abs();
        signal = signal * signal * weight;
        result += signal * lac.powf(-(i as f64) * h);
    }
    result
}

/// `f_r(x, y, z)`: distance from the origin.
fn f_r(a: &[f64]) -> f64 {
    p(a).length()
}

/// `f_th(x, y, z)`: the angle around the y axis, `atan2(x, z)`.
fn f_th(a: &[f64]) -> f64 {
    a[0].atan2(a[2])
}

/// `f_ph(x, y, z)`: the angle from the +y axis, `acos(y / r)`.
fn f_ph(a: &[f64]) -> f64 {
    let r = p(a).length();
    if r == 0.0 {
        0.0
    } else {
        (a[1] / r).clamp(-1.0, 1.0).acos()
    }
}

/// `f_spherical(x, y, z)`: 1 at the origin falling to 0 at distance 1.
fn f_spherical(a: &[f64]) -> f64 {
    (1.0 - p(a).length()).max(0.0)
}

/// `f_cylindrical(x, y, z)`: 1 on the y axis falling to 0 at distance 1.
fn f_cylindrical(a: &[f64]) -> f64 {
    (1.0 - (a[0] * a[0] + a[2] * a[2]).sqrt()).max(0.0)
}

/// `f_boxed(x, y, z)`: 1 at the origin falling to 0 on the cube of side 2.
fn f_boxed(a: &[f64]) -> f64 {
    (1.0 - a[0].abs().max(a[1].abs()).max(a[2].abs())).max(0.0)
}

/// `f_planar(x, y, z)`: 1 on the x-z plane falling to 0 at |y| = 1.
fn f_planar(a: &[f64]) -> f64 {
    (1.0 - a[1].abs()).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn call(name: &str, a: &[f64]) -> f64 {
        let f = INTERNALS.iter().find(|e| e.0 == name).unwrap();
        assert_eq!(f.1, a.len());
        (f.2)(a)
    }

    #[test]
    fn values_match_povray() {
        // Values printed by POV-Ray 3.7 (`#debug str(f_…(…), 0, 6)`).
        let cases: &[(&str, &[f64], f64)] = &[
            ("f_sphere", &[2.0, 0.5, 0.0, 1.0], 1.061553),
            ("f_sphere", &[0.5, 0.0, 0.0, 1.0], -0.5),
            ("f_torus", &[2.0, 0.5, 0.3, 1.0, 0.25], 0.888091),
            ("f_rounded_box", &[2.0, 0.5, 0.3, 0.1, 1.0, 0.7, 0.4], 1.0),
            ("f_rounded_box", &[0.1, 0.2, 0.1, 0.1, 1.0, 0.7, 0.4], -0.1),
            (
                "f_rounded_box",
                &[1.5, 1.5, 1.5, 0.1, 1.0, 0.7, 0.4],
                1.515548,
            ),
            ("f_r", &[1.0, 2.0, 3.0], 3.741657),
            ("f_th", &[1.0, 2.0, 3.0], 0.321751),
            ("f_ph", &[1.0, 2.0, 3.0], 1.006854),
            ("f_superellipsoid", &[0.5, 0.3, 0.2, 0.5, 2.0], 0.284533),
            ("f_spherical", &[0.3, 0.2, 0.1], 0.625834),
            ("f_cylindrical", &[0.3, 0.2, 0.1], 0.683772),
            ("f_boxed", &[0.3, 0.2, 0.1], 0.7),
            ("f_planar", &[0.3, 0.2, 0.1], 0.8),
        ];
        for (name, a, want) in cases {
            let got = call(name, a);
            assert!(
                (got - want).abs() < 2e-6,
                "{name}{a:?} = {got}, POV-Ray {want}"
            );
        }
    }

    #[test]
    fn noise_functions_in_range() {
        for i in 0..100 {
            let a = [i as f64 * 0.37, i as f64 * 0.11 - 3.0, 1.7];
            let n = call("f_noise3d", &a);
            assert!((0.0..=1.0).contains(&n));
            assert!((call("f_snoise3d", &a) - (2.0 * n - 1.0)).abs() < 1e-12);
        }
    }
}
