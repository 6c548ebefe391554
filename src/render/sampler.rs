//! Deterministic sample values: every random number the renderer uses is a function
//! of (pixel, sample index, frame, seed, dimension), so a picture does not depend on
//! the number of threads or the order pixels are computed in.
//!
//! The first [`SOBOL_DIMENSIONS`] dimensions of a sample come from an Owen-scrambled
//! Sobol sequence (`sobol_burley`), decorrelated per pixel by the scramble seed; later
//! dimensions from a PCG generator keyed the same way.

use rand_core::{RngCore, SeedableRng};
use rand_pcg::Pcg64Mcg;
use sobol_burley::parts::{self, Int4};
use std::sync::LazyLock;

/// Dimensions served by the Sobol sequence.
pub const SOBOL_DIMENSIONS: u32 = sobol_burley::NUM_DIMENSIONS;

/// The sample values for one (pixel, sample, frame, seed).
#[derive(Clone, Debug)]
pub struct Sampler {
    /// Hash of pixel, frame and seed: the scramble seed of this pixel.
    pixel_key: u32,
    /// Which sample of the pixel this is.
    index: u32,
    /// The sample index as `sobol_burley` shuffles it (bit-reversed, Owen
    /// scrambled by the pixel's seed): the same for every dimension, so computed
    /// once instead of in each `sample_4d` call.
    shuffled_rev: u32,
    /// The next dimension to hand out.
    dimension: u32,
    /// Generator for dimensions past the Sobol ones, made on first use.
    overflow: Option<Pcg64Mcg>,
    /// Sobol dimensions `4k .. 4k + 4` computed together (`sobol_burley::sample_4d`
    /// gives the same values as four `sample` calls, for a quarter of the work).
    cached: [f32; 4],
}

impl Sampler {
    /// The sampler for sample `index` of pixel (`x`, `y`) in `frame`, under the
    /// render's `seed`.
    pub fn new(seed: u64, frame: u32, x: u32, y: u32, index: u32) -> Sampler {
        let key =
            mix(seed ^ mix(u64::from(frame) << 32 | u64::from(x)) ^ mix(u64::from(y) + 0x9e37));
        let pixel_key = (key ^ (key >> 32)) as u32;
        Sampler {
            pixel_key,
            index,
            shuffled_rev: parts::owen_scramble_rev(
                index.reverse_bits(),
                parts::hash(pixel_key ^ 0x79c6_8e4a),
            ),
            dimension: 0,
            overflow: None,
            cached: [0.0; 4],
        }
    }

    /// The next value in [0, 1).
    #[inline]
    pub fn next_f64(&mut self) -> f64 {
        let d = self.dimension;
        self.dimension += 1;
        if d < SOBOL_DIMENSIONS {
            if d.is_multiple_of(4) {
                self.cached = self.sobol_4d(d / 4);
            }
            return f64::from(self.cached[d as usize % 4]);
        }
        self.next_overflow()
    }

    /// `sobol_burley::sample_4d(index, set, pixel_key)` (the same values, tested)
    /// with the index shuffle done once per sampler.
    fn sobol_4d(&self, set: u32) -> [f32; 4] {
        let sobol = sobol_int4_rev(self.shuffled_rev, set);
        let scramble = Int4::from([self.pixel_key.wrapping_mul(0x9c8f_2d3b); 4])
            ^ Int4::from([set; 4])
            ^ Int4::from([0x912f_69ba, 0x174f_18ab, 0x691e_72ca, 0xb40c_c1b8]);
        parts::owen_scramble_int4_rev(sobol, parts::hash_int4(scramble))
            .reverse_bits()
            .to_f32_norm()
    }

    /// Dimensions past the Sobol ones.
    #[cold]
    fn next_overflow(&mut self) -> f64 {
        let (key, index) = (self.pixel_key, self.index);
        let rng = self.overflow.get_or_insert_with(|| {
            Pcg64Mcg::seed_from_u64(mix(u64::from(key) << 32 | u64::from(index)))
        });
        (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// The next two values, for a point on a square.
    #[inline]
    pub fn next_2d(&mut self) -> (f64, f64) {
        (self.next_f64(), self.next_f64())
    }
}

/// Direction numbers of each 4-dimension Sobol set, one per bit of the
/// (reversed) sample index that `sobol_burley` uses (its top 16): read back
/// through `sobol_int4_rev` with one bit set, so they are the crate's own.
static DIRECTIONS: LazyLock<Vec<[Int4; 16]>> = LazyLock::new(|| {
    (0..sobol_burley::NUM_DIMENSION_SETS_4D)
        .map(|set| std::array::from_fn(|i| parts::sobol_int4_rev(0x8000_0000 >> i, set)))
        .collect()
});

/// `sobol_burley::parts::sobol_int4_rev` without branches: every direction
/// number is masked in by its index bit. The crate's loop visits only the set
/// bits, but an Owen-scrambled index has about eight of sixteen set at random,
/// so its exit branch mispredicted often: `sobol_4d` was 14% of a path-traced
/// Cornell box's time, and this is the same numbers (tested).
#[inline]
fn sobol_int4_rev(index_rev: u32, set: u32) -> Int4 {
    let mut sobol = Int4::from([0; 4]);
    for (i, v) in DIRECTIONS[set as usize].iter().enumerate() {
        // All ones when bit 31 - i of the index is set.
        let m = ((index_rev << i) as i32 >> 31) as u32;
        sobol ^= *v & Int4::from([m; 4]);
    }
    sobol
}

/// A point (`a`, `b`) of the unit square mapped onto the unit disc by Shirley and
/// Chiu's concentric mapping (strata stay compact, so stratified lens and light
/// samples stay stratified).
pub(crate) fn concentric_disc(a: f64, b: f64) -> (f64, f64) {
    let (x, y) = (2.0 * a - 1.0, 2.0 * b - 1.0);
    if x == 0.0 && y == 0.0 {
        return (0.0, 0.0);
    }
    let q = std::f64::consts::FRAC_PI_4;
    let (r, phi) = if x.abs() > y.abs() {
        (x, q * (y / x))
    } else {
        (y, 2.0 * q - q * (x / y))
    };
    // φ ≥ -π/4, so the fraction of a turn plus one is positive, as `turn` needs.
    let (c, s) = turn(phi / std::f64::consts::TAU + 1.0);
    (r * c, r * s)
}

/// `(cos 2πu, sin 2πu)`: the point at a fraction `u` of a turn round the unit
/// circle. Every direction the path tracer samples turns by a random angle (and
/// every lens and disc-light sample), and
/// the C library's `sincos` (general arguments, careful range reduction) cost
/// about 170 instructions a call; here the turn is split into the nearest
/// quarter and a remainder within ±π/4, where Taylor series of degree 17 and 16
/// are exact to about 1e-16.
#[inline]
pub fn turn(u: f64) -> (f64, f64) {
    let x = 4.0 * u;
    let q = ((x + 0.5) as i64) as f64; // x ≥ 0: truncation rounds; no libm call
    let a = (x - q) * std::f64::consts::FRAC_PI_2;
    let a2 = a * a;
    let s = a * horner(a2, &SIN_SERIES);
    let c = horner(a2, &COS_SERIES);
    // Rotate by the quarter turns: (cos, sin) of qπ/2 + a.
    let k = (q as i64 & 3) as usize;
    let cs = [c, -s, -c, s];
    (cs[k], cs[(k + 3) & 3])
}

/// Taylor coefficients of sin(a) / a in powers of a², to degree 16.
const SIN_SERIES: [f64; 9] = [
    1.0,
    -1.0 / 6.0,
    1.0 / 120.0,
    -1.0 / 5040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
    1.0 / 355_687_428_096_000.0,
];

/// Taylor coefficients of cos(a) in powers of a², to degree 16.
const COS_SERIES: [f64; 9] = [
    1.0,
    -0.5,
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40_320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
    1.0 / 20_922_789_888_000.0,
];

/// `Σ coeffs[i] xⁱ` by Horner's rule, the highest power innermost.
#[inline(always)]
fn horner(x: f64, coeffs: &[f64; 9]) -> f64 {
    let mut acc = coeffs[8];
    for i in (0..8).rev() {
        acc = coeffs[i] + x * acc;
    }
    acc
}

/// SplitMix64's finaliser: a bijective 64-bit mix.
pub(crate) fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_inputs_same_values_and_pixels_differ() {
        let run = |x, y, i| {
            let mut s = Sampler::new(7, 0, x, y, i);
            (0..300).map(|_| s.next_f64()).collect::<Vec<_>>()
        };
        assert_eq!(run(3, 4, 1), run(3, 4, 1));
        assert_ne!(run(3, 4, 1), run(4, 3, 1));
        assert_ne!(run(3, 4, 1), run(3, 4, 2));
        assert!(run(1, 2, 0).iter().all(|v| (0.0..1.0).contains(v)));
    }

    #[test]
    fn four_dimensions_at_once_equal_one_at_a_time() {
        let mut s = Sampler::new(3, 1, 5, 6, 77);
        for d in 0..SOBOL_DIMENSIONS {
            let want = f64::from(sobol_burley::sample(77, d, s.pixel_key));
            assert_eq!(s.next_f64(), want, "dimension {d}");
        }
    }

    #[test]
    fn cached_index_shuffle_gives_sobol_burleys_values() {
        for (x, y, index) in [(0, 0, 0), (5, 9, 1), (300, 7, 4095), (1, 2, 65535)] {
            let s = Sampler::new(11, 2, x, y, index);
            for set in 0..sobol_burley::NUM_DIMENSION_SETS_4D {
                assert_eq!(
                    s.sobol_4d(set),
                    sobol_burley::sample_4d(index, set, s.pixel_key),
                    "pixel ({x}, {y}) sample {index} set {set}"
                );
            }
        }
    }

    #[test]
    fn branchless_sobol_equals_the_crates() {
        let mut index = 0x1234_5678u32;
        for set in 0..sobol_burley::NUM_DIMENSION_SETS_4D {
            for _ in 0..64 {
                index = index.wrapping_mul(0x2c9277b5).wrapping_add(0xac564b05);
                assert_eq!(
                    <[u32; 4]>::from(sobol_int4_rev(index, set)),
                    <[u32; 4]>::from(parts::sobol_int4_rev(index, set)),
                    "set {set} index {index:#x}"
                );
            }
        }
    }

    #[test]
    fn samples_of_a_pixel_cover_the_square_evenly() {
        // 64 Sobol points: each of the 8 × 8 cells holds about one point.
        let mut cells = [0u32; 64];
        for i in 0..64 {
            let (u, v) = Sampler::new(1, 0, 10, 20, i).next_2d();
            cells[(u * 8.0) as usize * 8 + (v * 8.0) as usize] += 1;
        }
        assert!(cells.iter().all(|&c| c <= 2), "{cells:?}");
    }
}
