//! Which SIMD level the traversal kernels run at: the best the processor has
//! (AVX-512, AVX2+FMA, or plain scalar code), or one forced lower by
//! `RTS_SIMD=scalar|v3|v4|auto` or the `--simd` render flag. Every level gives the
//! same bytes: the kernels use only correctly rounded IEEE operations (no fused
//! multiply-add) on values that are never NaN, so lanes agree bit for bit.

use pulp::{Arch, Scalar, Simd, WithSimd};
use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::OnceLock;

/// A SIMD level the kernels can be asked to run at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SimdLevel {
    /// The best the processor supports.
    Auto,
    /// No SIMD instructions beyond the baseline: one lane at a time.
    Scalar,
    /// x86-64-v3: AVX2 and FMA, 8 f32 lanes.
    V3,
    /// x86-64-v4: AVX-512, 16 f32 lanes.
    V4,
}

impl SimdLevel {
    /// The level named `s` (`auto`, `scalar`, `v3`, `v4`; also `avx2`, `avx512`).
    pub fn parse(s: &str) -> Option<SimdLevel> {
        Some(match s.trim().to_ascii_lowercase().as_str() {
            "auto" | "" => SimdLevel::Auto,
            "scalar" | "none" | "off" => SimdLevel::Scalar,
            "v3" | "avx2" => SimdLevel::V3,
            "v4" | "avx512" => SimdLevel::V4,
            _ => return None,
        })
    }

    /// Its name as [`SimdLevel::parse`] reads it.
    pub fn name(self) -> &'static str {
        match self {
            SimdLevel::Auto => "auto",
            SimdLevel::Scalar => "scalar",
            SimdLevel::V3 => "v3",
            SimdLevel::V4 => "v4",
        }
    }
}

/// 0: not chosen yet; else 1 + the level in force (1 scalar, 2 v3, 3 v4).
static CHOSEN: AtomicU8 = AtomicU8::new(0);

/// The environment variable that caps the SIMD level.
pub const SIMD_ENV: &str = "RTS_SIMD";

/// Caps the SIMD level the kernels use from now on (`Auto`: the best the
/// processor has). A level above what the processor supports falls back to the
/// best it does support. Call it before rendering: renders in flight may mix
/// levels, which is harmless (every level gives the same answers) but makes
/// measurements meaningless.
pub fn set_simd_level(level: SimdLevel) {
    #[cfg(target_arch = "x86_64")]
    let best = match best() {
        Arch::V4(_) => 3,
        Arch::V3(_) => 2,
        _ => 1,
    };
    // Elsewhere (NEON and the like): SIMD or not.
    #[cfg(not(target_arch = "x86_64"))]
    let best = 3;
    let want = match level {
        SimdLevel::Auto => 3,
        SimdLevel::Scalar => 1,
        SimdLevel::V3 => 2,
        SimdLevel::V4 => 3,
    };
    CHOSEN.store(want.min(best), Ordering::Relaxed);
}

/// The level in force: [`set_simd_level`]'s, else `RTS_SIMD`'s (an unknown
/// value counts as `auto`), else the processor's best.
pub fn simd_level() -> SimdLevel {
    match chosen() {
        1 => SimdLevel::Scalar,
        2 => SimdLevel::V3,
        _ => SimdLevel::V4,
    }
}

#[inline]
fn chosen() -> u8 {
    let c = CHOSEN.load(Ordering::Relaxed);
    if c != 0 {
        return c;
    }
    let level = std::env::var(SIMD_ENV)
        .ok()
        .and_then(|v| SimdLevel::parse(&v))
        .unwrap_or(SimdLevel::Auto);
    set_simd_level(level);
    CHOSEN.load(Ordering::Relaxed)
}

/// The best level the processor has, found once.
fn best() -> Arch {
    static BEST: OnceLock<Arch> = OnceLock::new();
    *BEST.get_or_init(Arch::new)
}

/// Runs `op` at the level in force ([`simd_level`]): once per traversal, so the
/// kernels inline into one function compiled for that level.
#[inline(always)]
pub(super) fn dispatch<Op: WithSimd>(op: Op) -> Op::Output {
    let c = chosen();
    #[cfg(target_arch = "x86_64")]
    match best() {
        Arch::V4(v4) if c >= 3 => Simd::vectorize(v4, op),
        Arch::V4(v4) if c == 2 => Simd::vectorize(*v4, op),
        Arch::V3(v3) if c >= 2 => Simd::vectorize(v3, op),
        _ => Simd::vectorize(Scalar::new(), op),
    }
    #[cfg(not(target_arch = "x86_64"))]
    if c == 1 {
        Simd::vectorize(Scalar::new(), op)
    } else {
        best().dispatch(op)
    }
}
