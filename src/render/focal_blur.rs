//! Depth of field: the lens rays one image sample averages, and when to stop.
//!
//! POV-Ray takes up to `blur_samples` rays per sample from jittered lens points
//! and stops early once the mean colour is probably close enough: `confidence`
//! is that probability, `variance` the tolerance. rts's rule (ours; POV-Ray's
//! manual gives the meaning, not the formula): after at least `MIN` rays (and
//! at least [`FIRST_CHECK`]), stop when for every channel the squared half-width
//! of the `confidence` interval of the mean, `z² s² / n`, is at most `variance`
//! (`s²` the sample variance of the `n` rays so far, `z` the two-sided normal
//! quantile of `confidence`).

use crate::scene::Camera;
use glam::DVec3;

/// Rays taken before the stopping rule is first applied: fewer give too poor a
/// variance estimate (two equal rays would look converged).
pub const FIRST_CHECK: u32 = 4;

/// Lens-ray indices of one image sample are `sample * STRIDE + k`; `STRIDE`
/// exceeds the largest `blur_samples` (4096), so every lens ray has its own
/// (pixel, index) pair for the sampler.
pub const STRIDE: u32 = 4096;

/// Whether `camera` blurs: a lens (`aperture > 0`) and more than one ray per sample.
pub fn active(camera: &Camera) -> bool {
    camera.aperture > 0.0
        && camera.blur_samples > 1
        && camera.kind != crate::scene::CameraKind::Orthographic
}

/// The running mean and variance of a sample's lens rays (Welford's method).
#[derive(Clone, Copy, Debug, Default)]
pub struct Running {
    n: u32,
    mean: DVec3,
    m2: DVec3,
}

impl Running {
    /// Adds one ray's colour.
    pub fn push(&mut self, c: DVec3) {
        self.n += 1;
        let d = c - self.mean;
        self.mean += d / f64::from(self.n);
        self.m2 += d * (c - self.mean);
    }

    /// Rays so far.
    pub fn count(&self) -> u32 {
        self.n
    }

    /// The mean colour.
    pub fn mean(&self) -> DVec3 {
        self.mean
    }

    /// Whether `camera`'s stopping rule says enough rays were taken (see the
    /// module documentation); `z` is [`quantile`] of its confidence.
    pub fn converged(&self, camera: &Camera, z: f64) -> bool {
        if self.n >= camera.blur_samples {
            return true;
        }
        if self.n < camera.blur_min_samples.max(FIRST_CHECK) {
            return false;
        }
        let n = f64::from(self.n);
        let var = self.m2 / (n - 1.0);
        let t = student_t(z, n - 1.0);
        t * t * var.max_element() / n <= camera.variance
    }
}

/// The two-sided standard normal quantile of `confidence`: the `z` with
/// P(|Z| ≤ z) = confidence (1.645 for 0.9, 1.960 for 0.95).
pub fn quantile(confidence: f64) -> f64 {
    inverse_normal(0.5 + 0.5 * confidence.clamp(0.0, 0.999_999))
}

/// The Student's t quantile with `df` degrees of freedom matching the normal
/// quantile `z` (Cornish-Fisher expansion, within 1% from 3 degrees of
/// freedom on): the mean of few rays with an estimated variance needs a wider
/// interval than `z` says.
fn student_t(z: f64, df: f64) -> f64 {
    let (z2, v) = (z * z, df.max(1.0));
    let z3 = z2 * z;
    let z5 = z3 * z2;
    let z7 = z5 * z2;
    z + (z3 + z) / (4.0 * v)
        + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * v * v)
        + (3.0 * z7 + 19.0 * z5 + 17.0 * z3 - 15.0 * z) / (384.0 * v * v * v)
}

/// Φ⁻¹(p) for p in (0, 1): P. J. Acklam's rational approximation (relative error
/// below 1.2e-9), which is plenty for a stopping rule.
fn inverse_normal(p: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969_683_028_665_376e1,
        2.209_460_984_245_205e2,
        -2.759_285_104_469_687e2,
        1.383_577_518_672_69e2,
        -3.066_479_806_614_716e1,
        2.506_628_277_459_239,
    ];
    const B: [f64; 5] = [
        -5.447_609_879_822_406e1,
        1.615_858_368_580_409e2,
        -1.556_989_798_598_866e2,
        6.680_131_188_771_972e1,
        -1.328_068_155_288_572e1,
    ];
    const C: [f64; 6] = [
        -7.784_894_002_430_293e-3,
        -3.223_964_580_411_365e-1,
        -2.400_758_277_161_838,
        -2.549_732_539_343_734,
        4.374_664_141_464_968,
        2.938_163_982_698_783,
    ];
    const D: [f64; 4] = [
        7.784_695_709_041_462e-3,
        3.224_671_290_700_398e-1,
        2.445_134_137_142_996,
        3.754_408_661_907_416,
    ];
    let p = p.clamp(1e-300, 1.0 - 1e-16);
    let tail = |q: f64| {
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    };
    if p < 0.02425 {
        tail((-2.0 * p.ln()).sqrt())
    } else if p > 1.0 - 0.02425 {
        -tail((-2.0 * (1.0 - p).ln()).sqrt())
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_quantiles() {
        assert!((quantile(0.9) - 1.644_853_6).abs() < 1e-6);
        assert!((quantile(0.95) - 1.959_964).abs() < 1e-6);
        assert!((quantile(0.99) - 2.575_829).abs() < 1e-6);
        assert!(quantile(0.0).abs() < 1e-9);
    }

    #[test]
    fn student_t_quantiles_within_two_percent() {
        // Two-sided 95%: textbook t values for 3, 10 and 30 degrees of freedom.
        let z = quantile(0.95);
        for (df, t) in [(3.0, 3.182), (10.0, 2.228), (30.0, 2.042)] {
            let ours = student_t(z, df);
            assert!((ours / t - 1.0).abs() < 0.02, "df {df}: {ours} vs {t}");
        }
    }

    #[test]
    fn stops_early_on_flat_colour_and_runs_to_max_on_noise() {
        let cam = Camera {
            aperture: 1.0,
            blur_samples: 24,
            blur_min_samples: 2,
            ..Camera::default()
        };
        let z = quantile(cam.confidence);
        let mut flat = Running::default();
        while !flat.converged(&cam, z) {
            flat.push(DVec3::splat(0.5));
        }
        assert_eq!(flat.count(), FIRST_CHECK);
        let mut noisy = Running::default();
        let mut k = 0;
        while !noisy.converged(&cam, z) {
            noisy.push(DVec3::splat(if k % 2 == 0 { 0.0 } else { 1.0 }));
            k += 1;
        }
        assert_eq!(noisy.count(), 24);
        assert!((noisy.mean().x - 0.5).abs() < 1e-12);
        // MIN is honoured.
        let cam8 = Camera {
            blur_min_samples: 8,
            ..cam
        };
        let mut flat8 = Running::default();
        while !flat8.converged(&cam8, z) {
            flat8.push(DVec3::ONE);
        }
        assert_eq!(flat8.count(), 8);
    }
}
