//! The SIMD kernels, generic over the level ([`pulp::Simd`]): one ray against
//! the eight f32 boxes of a wide node. They run inside one dispatch per
//! traversal ([`super::simd::dispatch`]), so they inline into code compiled for
//! that level: eight lanes at once with AVX2, sixteen-lane registers half used
//! with AVX-512, one lane at a time at the scalar level. Only correctly rounded
//! operations (no fused multiply-add) on values that are never NaN, so every
//! level gives the same lanes bit for bit.
//!
//! The boxes are rounded outwards when stored (see [`super::builder::Box32`]),
//! and the ray's f64 origin and direction are rounded so that every box test
//! errs towards a hit (see [`RayBoxes::new`]), never towards a miss.

use pulp::bytemuck;
use pulp::Simd;

use super::Ray;

/// Children a wide node holds.
pub(super) const WIDTH: usize = 8;

/// Eight boxes as structure of arrays: `[min, max]`, each x, y, z, each eight
/// lanes.
pub(super) type Boxes8 = [[[f32; WIDTH]; 3]; 2];

/// The box of an empty lane: all at +∞, so a ray enters it at +∞ or leaves it at
/// −∞, and far limits are finite (see [`far`]).
pub(super) const EMPTY_BOXES: Boxes8 = [[[f32::INFINITY; WIDTH]; 3]; 2];

/// Slack on far distances for the rounding of the subtraction, the product and
/// the reciprocal (each within 2⁻²⁴ relative): 16 times what they can add up to.
const FAR_SLACK: f32 = 1.0 + 1.0 / (1 << 20) as f32;
/// Largest reciprocal direction used: a zero component would give ∞ and, for an
/// origin on a box face, 0 × ∞ = NaN. With the origin margin below, a ray lying in
/// a face plane still sees that slab reach past 10¹⁰.
const MAX_INV: f64 = 1e30;
/// Smallest reciprocal direction used: a zero one would give ∞ × 0 = NaN against
/// an empty lane. (A direction component above 10³⁰ is no ray a scene makes.)
const MIN_INV: f64 = 1e-30;
/// Relative margin on the origin (and on distance limits).
const MARGIN: f32 = 1.0 / (1 << 20) as f32;
/// Largest origin coordinate used, so the origin is finite in f32.
const MAX_ORIGIN: f64 = 1e37;

/// A ray prepared for box tests in f32.
pub(super) struct RayBoxes {
    /// Per axis, whether the ray enters boxes through their max plane
    /// (negative direction): indexes [`Boxes8`].
    back: [usize; 3],
    /// Origin per axis as used against near planes and far planes: moved by a
    /// margin so each plane's distance comes out on the side of a hit.
    near: [f32; 3],
    far: [f32; 3],
    inv: [f32; 3],
}

impl RayBoxes {
    /// Prepares `ray`. Against the planes a ray enters by, the f32 origin is
    /// moved a margin of about `|o|·2⁻²⁰ + 10⁻²⁰` forwards, against those it
    /// leaves by as far back (16 times the rounding of the origin and of the
    /// sum, so without branches): every box is tested as if grown by that
    /// margin, and rounding can only turn misses into hits.
    #[inline(always)]
    pub(super) fn new(ray: &Ray) -> RayBoxes {
        let mut r = RayBoxes {
            back: [0; 3],
            near: [0.0; 3],
            far: [0.0; 3],
            inv: [0.0; 3],
        };
        for a in 0..3 {
            let o = ray.origin[a].clamp(-MAX_ORIGIN, MAX_ORIGIN) as f32;
            let inv = 1.0 / ray.dir[a];
            // Keep the sign (of a zero too) and clamp the size.
            let inv = inv.abs().clamp(MIN_INV, MAX_INV).copysign(inv) as f32;
            let margin = (o.abs() * MARGIN + 1e-20).copysign(inv);
            r.back[a] = usize::from(inv < 0.0);
            r.near[a] = o + margin;
            r.far[a] = o - margin;
            r.inv[a] = inv;
        }
        r
    }
}

/// `x` in f32, a little below it (for near limits).
#[inline(always)]
pub(super) fn down(x: f64) -> f32 {
    let f = x.clamp(-f64::from(f32::MAX), f64::from(f32::MAX)) as f32;
    f - f.abs() * MARGIN
}

/// `x` in f32, a little above it and at most `f32::MAX` (for far limits: empty
/// lanes are entered at +∞).
#[inline(always)]
pub(super) fn far(x: f64) -> f32 {
    let f = x.min(f64::from(f32::MAX)) as f32;
    (f + f.abs() * MARGIN).min(f32::MAX)
}

/// Lane `i`'s bit set for every true lane of `m`, whatever the level's mask
/// type (a vector of all-ones lanes, a bit mask, or one `bool`).
#[inline(always)]
fn bits<S: Simd>(s: S, m: S::m32s) -> u32 {
    let size = core::mem::size_of::<S::m32s>();
    // AVX2 has an instruction for it (the generic gather of sign bits below
    // takes six); the type test is resolved when the kernel is compiled.
    #[cfg(target_arch = "x86_64")]
    if let Some(v3) = (&s as &dyn core::any::Any).downcast_ref::<pulp::x86::V3>() {
        if size == 32 {
            let m = bytemuck::cast::<S::m32s, core::arch::x86_64::__m256>(m);
            return v3.avx._mm256_movemask_ps(m) as u32;
        }
    }
    let _ = s;
    if size == 1 {
        u32::from(bytemuck::cast::<S::m32s, u8>(m) != 0)
    } else if size == 2 {
        u32::from(bytemuck::cast::<S::m32s, u16>(m))
    } else {
        let lanes: &[u32] = bytemuck::cast_slice(core::slice::from_ref(&m));
        let mut b = 0;
        for (i, &x) in lanes.iter().enumerate() {
            b |= (x >> 31) << i;
        }
        b
    }
}

/// Lanes `from..` of `a` as one register (zeros past the end).
#[inline(always)]
fn load<S: Simd>(s: S, a: &[f32; WIDTH], from: usize) -> S::f32s {
    let (head, tail) = S::as_simd_f32s(&a[from..]);
    match head.first() {
        Some(&v) => v,
        None => s.partial_load_f32s(tail),
    }
}

/// Which of the boxes `b` the ray enters within `near..far` (bit per lane),
/// with the entry distances in `dist` (meaningful for entered lanes only).
#[inline(always)]
pub(super) fn hit8<S: Simd>(
    s: S,
    r: &RayBoxes,
    b: &Boxes8,
    near: f32,
    far: f32,
    dist: &mut [f32; WIDTH],
) -> u32 {
    let lanes = S::F32_LANES;
    let step = lanes.min(WIDTH);
    let mut mask = 0;
    let mut from = 0;
    while from < WIDTH {
        let t = |a: usize, leave: bool| {
            let (side, o) = if leave {
                (r.back[a] ^ 1, r.far[a])
            } else {
                (r.back[a], r.near[a])
            };
            let plane = load(s, &b[side][a], from);
            s.mul_f32s(s.sub_f32s(plane, s.splat_f32s(o)), s.splat_f32s(r.inv[a]))
        };
        let enter = s.max_f32s(
            s.max_f32s(t(0, false), t(1, false)),
            s.max_f32s(t(2, false), s.splat_f32s(near)),
        );
        let leave = s.min_f32s(
            s.mul_f32s(
                s.min_f32s(s.min_f32s(t(0, true), t(1, true)), t(2, true)),
                s.splat_f32s(FAR_SLACK),
            ),
            s.splat_f32s(far),
        );
        mask |= bits(s, s.less_than_or_equal_f32s(enter, leave)) << from;
        let e: &[f32] = bytemuck::cast_slice(core::slice::from_ref(&enter));
        dist[from..from + step].copy_from_slice(&e[..step]);
        from += step;
    }
    mask & ((1 << WIDTH) - 1)
}
