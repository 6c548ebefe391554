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

/// Distances to the planes `plane` (lanes `from..`) from `o` with reciprocal
/// direction `inv`.
#[inline(always)]
fn slab<S: Simd>(s: S, plane: &[f32; WIDTH], from: usize, o: f32, inv: f32) -> S::f32s {
    s.mul_f32s(
        s.sub_f32s(load(s, plane, from), s.splat_f32s(o)),
        s.splat_f32s(inv),
    )
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
    let step = S::F32_LANES.min(WIDTH);
    let mut mask = 0;
    let mut from = 0;
    // (No closures here: a closure is not compiled for the caller's target
    // features, so its intrinsics would not inline.)
    while from < WIDTH {
        let enter = s.max_f32s(
            s.max_f32s(
                slab(s, &b[r.back[0]][0], from, r.near[0], r.inv[0]),
                slab(s, &b[r.back[1]][1], from, r.near[1], r.inv[1]),
            ),
            s.max_f32s(
                slab(s, &b[r.back[2]][2], from, r.near[2], r.inv[2]),
                s.splat_f32s(near),
            ),
        );
        let leave = s.min_f32s(
            s.min_f32s(
                slab(s, &b[r.back[0] ^ 1][0], from, r.far[0], r.inv[0]),
                slab(s, &b[r.back[1] ^ 1][1], from, r.far[1], r.inv[1]),
            ),
            slab(s, &b[r.back[2] ^ 1][2], from, r.far[2], r.inv[2]),
        );
        let leave = s.min_f32s(
            s.mul_f32s(leave, s.splat_f32s(FAR_SLACK)),
            s.splat_f32s(far),
        );
        mask |= bits(s, s.less_than_or_equal_f32s(enter, leave)) << from;
        let e: &[f32] = bytemuck::cast_slice(core::slice::from_ref(&enter));
        dist[from..from + step].copy_from_slice(&e[..step]);
        from += step;
    }
    mask & ((1 << WIDTH) - 1)
}

/// Most triangles [`tri_keep`] tests at once.
pub(super) const TRI_CHUNK: usize = 16;
/// Tolerance of the f32 triangle cull, relative to the size of each quantity's
/// terms: some 2⁶ times the rounding the f32 inputs and arithmetic can add up
/// to, so a triangle the f64 test hits is never culled.
const TRI_TOL: f32 = 1.0 / 4096.0;

/// A ray prepared for the triangle cull in f32.
pub(super) struct RayTri {
    o: [f32; 3],
    d: [f32; 3],
    /// Largest origin and direction components.
    o_mag: f32,
    d_mag: f32,
}

impl RayTri {
    /// `ray` in f32 (components clamped to finite values).
    #[inline(always)]
    pub(super) fn new(ray: &Ray) -> RayTri {
        let f = |x: f64| x.clamp(-MAX_ORIGIN, MAX_ORIGIN) as f32;
        let o = [f(ray.origin.x), f(ray.origin.y), f(ray.origin.z)];
        let d = [f(ray.dir.x), f(ray.dir.y), f(ray.dir.z)];
        let mag = |v: [f32; 3]| v[0].abs().max(v[1].abs()).max(v[2].abs());
        RayTri {
            o,
            d,
            o_mag: mag(o),
            d_mag: mag(d),
        }
    }
}

/// The cross product of `a` and `b` lane by lane.
#[inline(always)]
fn cross<S: Simd>(s: S, a: [S::f32s; 3], b: [S::f32s; 3]) -> [S::f32s; 3] {
    [
        s.sub_f32s(s.mul_f32s(a[1], b[2]), s.mul_f32s(a[2], b[1])),
        s.sub_f32s(s.mul_f32s(a[2], b[0]), s.mul_f32s(a[0], b[2])),
        s.sub_f32s(s.mul_f32s(a[0], b[1]), s.mul_f32s(a[1], b[0])),
    ]
}

/// The dot product of `a` and `b` lane by lane.
#[inline(always)]
fn dot<S: Simd>(s: S, a: [S::f32s; 3], b: [S::f32s; 3]) -> S::f32s {
    s.add_f32s(
        s.add_f32s(s.mul_f32s(a[0], b[0]), s.mul_f32s(a[1], b[1])),
        s.mul_f32s(a[2], b[2]),
    )
}

/// The largest absolute component of `a`, lane by lane.
#[inline(always)]
fn mag<S: Simd>(s: S, a: [S::f32s; 3]) -> S::f32s {
    s.max_f32s(
        s.max_f32s(s.abs_f32s(a[0]), s.abs_f32s(a[1])),
        s.abs_f32s(a[2]),
    )
}

/// Lanes `from..` of `a` as one register (zeros past the end).
#[inline(always)]
fn load16<S: Simd>(s: S, a: &[f32; TRI_CHUNK], from: usize) -> S::f32s {
    let (head, tail) = S::as_simd_f32s(&a[from..]);
    match head.first() {
        Some(&v) => v,
        None => s.partial_load_f32s(tail),
    }
}

/// Which of the (at most [`TRI_CHUNK`]) triangles `prims` the ray may hit within
/// `t_min..t_max` (bit per triangle): Möller–Trumbore in f32, several
/// triangles a register, as a cull only. A triangle is dropped only when it
/// misses by more than the tolerance ([`TRI_TOL`] of the size of the terms of
/// each quantity), so the f64 test that follows sees every triangle it would
/// hit; anything doubtful (a ray nearly in the triangle's plane, a value out of
/// f32's range, a NaN) is kept.
#[inline(always)]
pub(super) fn tri_keep<S: Simd>(
    s: S,
    r: &RayTri,
    positions: &[[f32; 3]],
    triangles: &[[u32; 3]],
    prims: &[u32],
    t_min: f64,
    t_max: f64,
) -> u32 {
    let n = prims.len().min(TRI_CHUNK);
    // Corner a, then edges e1 = b − a and e2 = c − a, by axis and lane.
    let mut g = [[0.0f32; TRI_CHUNK]; 9];
    for (k, &p) in prims[..n].iter().enumerate() {
        let [ia, ib, ic] = triangles[p as usize];
        let (a, b, c) = (
            positions[ia as usize],
            positions[ib as usize],
            positions[ic as usize],
        );
        for ax in 0..3 {
            g[ax][k] = a[ax];
            g[3 + ax][k] = b[ax] - a[ax];
            g[6 + ax][k] = c[ax] - a[ax];
        }
    }
    let t_hi = if t_max < f64::from(f32::MAX) {
        t_max as f32 * (1.0 + TRI_TOL)
    } else {
        f32::INFINITY
    };
    let low_cut = t_min >= 0.0;
    let step = S::F32_LANES.min(TRI_CHUNK);
    let tol = s.splat_f32s(TRI_TOL);
    let d = [
        s.splat_f32s(r.d[0]),
        s.splat_f32s(r.d[1]),
        s.splat_f32s(r.d[2]),
    ];
    let o = [
        s.splat_f32s(r.o[0]),
        s.splat_f32s(r.o[1]),
        s.splat_f32s(r.o[2]),
    ];
    let mut keep = 0u32;
    let mut from = 0;
    while from < n {
        let a = [
            load16(s, &g[0], from),
            load16(s, &g[1], from),
            load16(s, &g[2], from),
        ];
        let e1 = [
            load16(s, &g[3], from),
            load16(s, &g[4], from),
            load16(s, &g[5], from),
        ];
        let e2 = [
            load16(s, &g[6], from),
            load16(s, &g[7], from),
            load16(s, &g[8], from),
        ];
        let p = cross(s, d, e2);
        let det = dot(s, e1, p);
        let t = [
            s.sub_f32s(o[0], a[0]),
            s.sub_f32s(o[1], a[1]),
            s.sub_f32s(o[2], a[2]),
        ];
        let u = dot(s, t, p);
        let q = cross(s, t, e1);
        let v = dot(s, d, q);
        let tn = dot(s, e2, q);
        // Sizes of the terms (the origin's own size bounds its rounding).
        let (m1, m2) = (mag(s, e1), mag(s, e2));
        let mt = s.add_f32s(mag(s, t), s.splat_f32s(r.o_mag));
        let md = s.splat_f32s(r.d_mag);
        let tol_det = s.mul_f32s(tol, s.mul_f32s(s.mul_f32s(m1, m2), md));
        let tol_u = s.mul_f32s(tol, s.mul_f32s(s.mul_f32s(mt, m2), md));
        let tol_v = s.mul_f32s(tol, s.mul_f32s(s.mul_f32s(mt, m1), md));
        let tol_t = s.mul_f32s(tol, s.mul_f32s(s.mul_f32s(mt, m1), m2));
        // Signs as if det were positive.
        let sign = s.and_f32s(det, s.splat_f32s(-0.0));
        let (us, vs, ts) = (
            s.xor_f32s(u, sign),
            s.xor_f32s(v, sign),
            s.xor_f32s(tn, sign),
        );
        let adet = s.abs_f32s(det);
        let slack = s.add_f32s(s.add_f32s(tol_u, tol_v), tol_det);
        let slack2 = s.add_f32s(slack, slack);
        let mut miss = s.less_than_f32s(us, s.sub_f32s(s.splat_f32s(0.0), tol_u));
        miss = s.or_m32s(
            miss,
            s.less_than_f32s(vs, s.sub_f32s(s.splat_f32s(0.0), tol_v)),
        );
        miss = s.or_m32s(
            miss,
            s.greater_than_f32s(s.add_f32s(us, vs), s.add_f32s(adet, slack2)),
        );
        if low_cut {
            miss = s.or_m32s(
                miss,
                s.less_than_f32s(ts, s.sub_f32s(s.splat_f32s(0.0), tol_t)),
            );
        }
        let far_limit = s.add_f32s(
            s.mul_f32s(s.splat_f32s(t_hi), s.add_f32s(adet, tol_det)),
            tol_t,
        );
        miss = s.or_m32s(miss, s.greater_than_f32s(ts, far_limit));
        // Only a plane the ray clearly crosses can rule a triangle out.
        miss = s.and_m32s(miss, s.greater_than_f32s(adet, tol_det));
        keep |= (!bits(s, miss) & ((1u32 << step) - 1)) << from;
        from += step;
    }
    keep & ((1u32 << n) - 1)
}
