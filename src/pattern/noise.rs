//! Solid noise: our own gradient noise (Perlin's method: pseudo-random gradients at
//! the integer lattice, blended with a quintic fade), scaled to POV-Ray's
//! conventions: `noise` in [0, 1] with mean 0.5, `dnoise` a vector in about [-1, 1]³,
//! and the turbulence sums POV-Ray documents (`octaves`, `omega`, `lambda`).

use glam::DVec3;

/// A fixed permutation of 0..256, built from a small LCG so it is ours and
/// deterministic.
const PERM: [u8; 256] = {
    let mut p = [0u8; 256];
    let mut i = 0;
    while i < 256 {
        p[i] = i as u8;
        i += 1;
    }
    let mut state: u32 = 0x2545_F491;
    let mut i = 255;
    while i > 0 {
        state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        let j = ((state >> 8) % (i as u32 + 1)) as usize;
        let t = p[i];
        p[i] = p[j];
        p[j] = t;
        i -= 1;
    }
    p
};

/// [`PERM`] twice over, so a sum of two entries (or an entry, a coordinate's
/// low 8 bits and 1) indexes it without wrapping.
const PERM2: [u8; 512] = {
    let mut p = [0u8; 512];
    let mut i = 0;
    while i < 512 {
        p[i] = PERM[i & 255];
        i += 1;
    }
    p
};

/// The hashes of the eight corners of the lattice cell whose lowest corner is
/// `(i, j, k)`, corner `c` at `(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))`:
/// the values the first noise's per-corner hash gave, from 14 table reads instead of 24.
#[inline]
fn corner_hashes(i: i64, j: i64, k: i64) -> [usize; 8] {
    let (i, j, k) = ((i & 255) as usize, (j & 255) as usize, (k & 255) as usize);
    let a0 = PERM2[i] as usize;
    let a1 = PERM2[i + 1] as usize;
    let b = [
        PERM2[a0 + j] as usize,
        PERM2[a1 + j] as usize,
        PERM2[(a0 + j + 1) & 511] as usize,
        PERM2[(a1 + j + 1) & 511] as usize,
    ];
    let mut h = [0; 8];
    for (c, slot) in h.iter_mut().enumerate() {
        *slot = PERM2[(b[c & 3] + k + (c >> 2)) & 511] as usize;
    }
    h
}

/// The lattice cell of one coordinate and the place in it: `(floor(x) as i64,
/// x - floor(x))`, bit for bit as [`floor`] gives them. Below 2^51 in size the
/// integer comes from rounding by adding 1.5·2^52 (exact: the sum's last bit
/// is a unit) and reading it from the sum's bits, without a conversion.
#[inline]
fn cell(x: f64) -> (i64, f64) {
    const MAGIC: f64 = 6_755_399_441_055_744.0;
    // NaN fails the comparison and takes the general path.
    if x.abs() < 2_251_799_813_685_248.0 {
        let sum = x + MAGIC;
        let nearest = sum - MAGIC;
        let t = (sum.to_bits() as i64).wrapping_sub(MAGIC.to_bits() as i64);
        // `+ 0.0` makes an exact -0.0 difference +0.0, as `x - x` is.
        if nearest > x {
            (t - 1, x - (nearest - 1.0))
        } else {
            (t, (x - nearest) + 0.0)
        }
    } else {
        let f = floor(x);
        (f as i64, x - f)
    }
}

/// The 12 edge directions of a cube (plus 4 repeats to fill 16 slots).
const GRAD: [[f64; 3]; 16] = [
    [1.0, 1.0, 0.0],
    [-1.0, 1.0, 0.0],
    [1.0, -1.0, 0.0],
    [-1.0, -1.0, 0.0],
    [1.0, 0.0, 1.0],
    [-1.0, 0.0, 1.0],
    [1.0, 0.0, -1.0],
    [-1.0, 0.0, -1.0],
    [0.0, 1.0, 1.0],
    [0.0, -1.0, 1.0],
    [0.0, 1.0, -1.0],
    [0.0, -1.0, -1.0],
    [1.0, 1.0, 0.0],
    [0.0, -1.0, 1.0],
    [-1.0, 1.0, 0.0],
    [0.0, -1.0, -1.0],
];

/// `x.floor()` without a call into the maths library (the portable build has
/// no rounding instruction, and noise floors three numbers per lookup): the
/// same value for every input, `-0.0`, infinities and NaN included.
#[inline]
pub(crate) fn floor(x: f64) -> f64 {
    // From 2^52 on every f64 is an integer; NaN is returned as it is.
    if x.is_nan() || x.abs() >= 4_503_599_627_370_496.0 {
        return x;
    }
    let t = x as i64 as f64;
    if t > x {
        t - 1.0
    } else if t == x {
        x
    } else {
        t
    }
}

#[inline]
fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

#[inline]
fn lerp(t: f64, a: f64, b: f64) -> f64 {
    a + t * (b - a)
}

/// Signed gradient noise, about [-1, 1], 0 at every lattice point.
pub fn signed_noise(p: DVec3) -> f64 {
    let (i, dx) = cell(p.x);
    let (j, dy) = cell(p.y);
    let (k, dz) = cell(p.z);
    let h = corner_hashes(i, j, k);
    let (ex, ey, ez) = (dx - 1.0, dy - 1.0, dz - 1.0);
    let g = |c: usize, x: f64, y: f64, z: f64| {
        let n = GRAD[h[c] & 15];
        n[0] * x + n[1] * y + n[2] * z
    };
    let (u, v, w) = (fade(dx), fade(dy), fade(dz));
    lerp(
        w,
        lerp(
            v,
            lerp(u, g(0, dx, dy, dz), g(1, ex, dy, dz)),
            lerp(u, g(2, dx, ey, dz), g(3, ex, ey, dz)),
        ),
        lerp(
            v,
            lerp(u, g(4, dx, dy, ez), g(5, ex, dy, ez)),
            lerp(u, g(6, dx, ey, ez), g(7, ex, ey, ez)),
        ),
    )
}

/// [`signed_noise`] and its gradient, computed together analytically (one lattice
/// walk instead of the six a central difference needs).
pub fn signed_noise_grad(p: DVec3) -> (f64, DVec3) {
    let (i, dx) = cell(p.x);
    let (j, dy) = cell(p.y);
    let (k, dz) = cell(p.z);
    let d = DVec3::new(dx, dy, dz);
    let hashes = corner_hashes(i, j, k);
    let (u, v, w) = (fade(d.x), fade(d.y), fade(d.z));
    let (du, dv, dw) = (fade_slope(d.x), fade_slope(d.y), fade_slope(d.z));
    let mut value = 0.0;
    let mut grad = DVec3::ZERO;
    for corner in 0..8 {
        let (ci, cj, ck) = (corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        let h = GRAD[hashes[corner] & 15];
        let g = h[0] * (d.x - ci as f64) + h[1] * (d.y - cj as f64) + h[2] * (d.z - ck as f64);
        // Trilinear weights and their slopes along each axis.
        let (wx, sx) = if ci == 1 { (u, du) } else { (1.0 - u, -du) };
        let (wy, sy) = if cj == 1 { (v, dv) } else { (1.0 - v, -dv) };
        let (wz, sz) = if ck == 1 { (w, dw) } else { (1.0 - w, -dw) };
        let weight = wx * wy * wz;
        value += weight * g;
        grad += DVec3::new(
            sx * wy * wz * g + weight * h[0],
            wx * sy * wz * g + weight * h[1],
            wx * wy * sz * g + weight * h[2],
        );
    }
    (value, grad)
}

/// The slope of [`fade`]: `30 t² (t - 1)²`.
#[inline]
fn fade_slope(t: f64) -> f64 {
    let s = t * (t - 1.0);
    30.0 * s * s
}

/// The gradient of [`noise`] at `p` (zero where `noise` is clipped to 0 or 1).
pub fn noise_grad(p: DVec3, generator: u8) -> (f64, DVec3) {
    let gain = gain(generator);
    let (s, g) = signed_noise_grad(p);
    let v = 0.5 + gain * s;
    if (0.0..=1.0).contains(&v) {
        (v, g * gain)
    } else {
        (v.clamp(0.0, 1.0), DVec3::ZERO)
    }
}

/// Gain that spreads the signed noise over POV-Ray's range (measured on bozo
/// histograms: POV-Ray's generator 2 fills [0, 1] with a soft peak at 0.5).
const GAIN: f64 = 0.52;

/// POV-Ray's `noise`: [0, 1], 0.5 on average. Generators 2 (the default) and 3
/// have the same spread in POV-Ray 3.7; generator 1 (the original, without range
/// correction) spreads about 2.3 times wider and clips (measured: standard
/// deviation of grey-mapped `bozo`, 22 vs 54 in 8-bit sRGB).
pub fn noise(p: DVec3, generator: u8) -> f64 {
    (0.5 + gain(generator) * signed_noise(p)).clamp(0.0, 1.0)
}

/// The spread of [`noise`] around 0.5 for `noise_generator` `generator`.
fn gain(generator: u8) -> f64 {
    if generator == 1 {
        GAIN * 2.3
    } else {
        GAIN
    }
}

/// Vector noise: three decorrelated noises, each in about [-1, 1].
pub fn dnoise(p: DVec3) -> DVec3 {
    DVec3::new(
        signed_noise(p + DVec3::new(31.416, -17.3, 5.11)),
        signed_noise(p + DVec3::new(-9.73, 47.1, 23.7)),
        signed_noise(p + DVec3::new(13.1, 3.7, -41.9)),
    ) * (2.0 * GAIN)
}

/// POV-Ray's turbulence vector: `Σ omegaⁱ dnoise(p lambdaⁱ)` over `octaves`.
pub fn turbulence_vec(p: DVec3, octaves: u32, omega: f64, lambda: f64) -> DVec3 {
    let (mut sum, mut amp, mut freq) = (DVec3::ZERO, 1.0, 1.0);
    for _ in 0..octaves.max(1) {
        sum += amp * dnoise(p * freq);
        amp *= omega;
        freq *= lambda;
    }
    sum
}

/// Scalar turbulence: `Σ omegaⁱ |signed noise(p lambdaⁱ)|`, about [0, 1].
pub fn turbulence(p: DVec3, octaves: u32, omega: f64, lambda: f64) -> f64 {
    let (mut sum, mut amp, mut freq) = (0.0, 1.0, 1.0);
    for _ in 0..octaves.max(1) {
        sum += amp * (GAIN * signed_noise(p * freq)).abs();
        amp *= omega;
        freq *= lambda;
    }
    sum
}

#[cfg(test)]
mod tests {
    /// Coordinates that test a floor: signed zeros, halves, lattice edges, the
    /// end of the exactly-integer range, huge, tiny, infinite and NaN values;
    /// then `count` ordinary ones over twelve orders of magnitude, from a fixed
    /// sequence.
    fn awkward_values(count: usize) -> Vec<f64> {
        let mut v = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            255.0,
            256.0,
            -256.0,
            -1e-320,
            1e-320,
            4_503_599_627_370_495.5,
            -4_503_599_627_370_495.5,
            4_503_599_627_370_496.0,
            9.3e18,
            -9.3e18,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            f64::MAX,
            f64::MIN,
        ];
        let mut x = 0.123_456_789f64;
        for k in 0..count as i32 {
            x = (x * 9_301.0 + 49_297.0) % 233_280.0;
            v.push((x - 116_640.0) * 10f64.powi(k % 12 - 6));
        }
        v
    }

    #[test]
    fn floor_is_the_library_floor_bit_for_bit() {
        let special = awkward_values(20_000);
        for x in special {
            let (a, b) = (floor(x), x.floor());
            assert!(
                a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
                "{x}: {a} vs {b}"
            );
        }
    }

    use super::*;

    /// Only the low 8 bits of each coordinate count, so callers add to them with
    /// `wrapping_add` (a point far out, or `f64::MAX` cast to `i64::MAX`, must not
    /// overflow).
    fn hash(i: i64, j: i64, k: i64) -> usize {
        let a = PERM[(i & 255) as usize] as usize;
        let b = PERM[(a + (j & 255) as usize) & 255] as usize;
        PERM[(b + (k & 255) as usize) & 255] as usize
    }

    /// The first noise, written corner by corner: the reference the faster
    /// [`signed_noise`] must equal bit for bit.
    fn reference_noise(p: DVec3) -> f64 {
        let f = DVec3::new(p.x.floor(), p.y.floor(), p.z.floor());
        let (i, j, k) = (f.x as i64, f.y as i64, f.z as i64);
        let d = p - f;
        let g = |di: i64, dj: i64, dk: i64| {
            let h = GRAD[hash(i.wrapping_add(di), j.wrapping_add(dj), k.wrapping_add(dk)) & 15];
            h[0] * (d.x - di as f64) + h[1] * (d.y - dj as f64) + h[2] * (d.z - dk as f64)
        };
        let (u, v, w) = (fade(d.x), fade(d.y), fade(d.z));
        lerp(
            w,
            lerp(
                v,
                lerp(u, g(0, 0, 0), g(1, 0, 0)),
                lerp(u, g(0, 1, 0), g(1, 1, 0)),
            ),
            lerp(
                v,
                lerp(u, g(0, 0, 1), g(1, 0, 1)),
                lerp(u, g(0, 1, 1), g(1, 1, 1)),
            ),
        )
    }

    #[test]
    fn noise_equals_the_reference_bit_for_bit() {
        let coords = awkward_values(3_000);
        let n = coords.len();
        for a in 0..n {
            for b in [a, (a * 7 + 3) % n, (a * 13 + 5) % n] {
                let p = DVec3::new(coords[a], coords[b], coords[(a + b) % n]);
                let (fast, slow) = (signed_noise(p), reference_noise(p));
                assert!(
                    fast.to_bits() == slow.to_bits() || (fast.is_nan() && slow.is_nan()),
                    "{p}: {fast} vs {slow}"
                );
            }
        }
    }

    #[test]
    fn noise_is_half_at_lattice_points_and_in_range() {
        for i in -3..3 {
            assert_eq!(noise(DVec3::new(i as f64, 2.0, -5.0), 2), 0.5);
        }
        let mut sum = 0.0;
        let n = 20_000;
        for i in 0..n {
            let p = DVec3::new(
                i as f64 * 0.173,
                (i % 97) as f64 * 0.311,
                (i % 13) as f64 * 0.57,
            );
            let v = noise(p, 2);
            assert!((0.0..=1.0).contains(&v));
            sum += v;
        }
        assert!(
            (sum / n as f64 - 0.5).abs() < 0.02,
            "mean {}",
            sum / n as f64
        );
    }

    #[test]
    fn analytic_gradient_matches_differences() {
        for i in 0..200 {
            let p = DVec3::new(
                i as f64 * 0.377 - 20.0,
                (i % 17) as f64 * 0.61,
                (i % 7) as f64 * -1.3,
            );
            let (v, g) = signed_noise_grad(p);
            assert!((v - signed_noise(p)).abs() < 1e-12);
            let h = 1e-6;
            for (k, axis) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
                let fd = (signed_noise(p + axis * h) - signed_noise(p - axis * h)) / (2.0 * h);
                assert!((fd - g[k]).abs() < 1e-6, "{p} axis {k}: {fd} vs {}", g[k]);
            }
        }
    }

    #[test]
    fn noise_is_continuous() {
        let p = DVec3::new(0.3, 1.7, 2.2);
        let e = DVec3::splat(1e-6);
        assert!((noise(p, 2) - noise(p + e, 2)).abs() < 1e-4);
    }
}
