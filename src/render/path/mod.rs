//! Physically based rendering of the same scenes: a Monte Carlo path tracer on
//! the same [`World`] as the classic renderer (see docs/pathtracing.md for how
//! POV-Ray's finish and interior terms map to scattering functions).
//!
//! Sampling is progressive: [`render_samples`] adds samples `first..first + n` of
//! every pixel to an [`Accum`] of per-pixel sums. Sample k of pixel (x, y) uses
//! [`Sampler::new`]`(seed, frame, x, y, k)` only, and each pixel adds its samples
//! in index order, so the result is the same for any number of threads and for
//! any split into passes: a render resumed from a [`checkpoint`] equals an
//! uninterrupted one bit for bit.

mod bsdf;
pub mod checkpoint;
mod emitters;
mod environment;
mod integrator;
mod lights;

pub use bsdf::{ggx_alpha, highlight, Bsdf, BsdfSample};
pub use emitters::Emitters;
pub use environment::Environment;
pub use integrator::{radiance, PathSample, PathScene};

use super::{primary_ray, Crop, Film, Progress, RenderOptions, RenderStats, Sampler, Settings};
use crate::build::World;
use crate::scene::{PathTracing, PixelFilter};
use glam::DVec3;
use rayon::prelude::*;
use std::sync::atomic::Ordering;

/// Standard deviation of the Gaussian pixel filter, in pixels.
pub const GAUSSIAN_SIGMA: f64 = 0.5;
/// Radius of the splatted Gaussian (4σ, as Mitsuba's `gaussian` filter).
pub const SPLAT_RADIUS: f64 = 4.0 * GAUSSIAN_SIGMA;

/// How the path tracer renders, beyond [`Settings`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathOptions {
    /// Longest path in segments, counting the camera ray.
    pub max_depth: u32,
    /// Largest channel value one sample may add (0: no clamp).
    pub clamp: f64,
    /// Reconstruction filter.
    pub filter: PixelFilter,
}

impl Default for PathOptions {
    fn default() -> Self {
        PathOptions::from(&PathTracing::default())
    }
}

impl From<&PathTracing> for PathOptions {
    fn from(p: &PathTracing) -> Self {
        PathOptions {
            max_depth: p.max_depth,
            clamp: p.firefly_clamp,
            filter: p.filter,
        }
    }
}

/// Per-pixel sums of a progressive render: the picture is `sum / samples`.
#[derive(Clone, Debug, PartialEq)]
pub struct Accum {
    /// The region rendered (the whole image unless cropped).
    pub crop: Crop,
    /// Samples per pixel added so far.
    pub samples: u32,
    /// Sum of radiance samples, row-major over the region.
    pub sum: Vec<DVec3>,
    /// Sum of first-hit albedos.
    pub albedo: Vec<DVec3>,
    /// Sum of first-hit normals.
    pub normal: Vec<DVec3>,
}

pub use super::resolve_crop;

impl Accum {
    /// Empty sums over `crop`.
    pub fn new(crop: Crop) -> Accum {
        let n = (crop.x1 - crop.x0) as usize * (crop.y1 - crop.y0) as usize;
        Accum {
            crop,
            samples: 0,
            sum: vec![DVec3::ZERO; n],
            albedo: vec![DVec3::ZERO; n],
            normal: vec![DVec3::ZERO; n],
        }
    }

    fn width(&self) -> u32 {
        self.crop.x1 - self.crop.x0
    }

    /// The means of sums `v`, through `f`.
    fn mean(&self, v: &[DVec3], f: impl Fn(DVec3) -> DVec3) -> Film {
        let k = 1.0 / f64::from(self.samples.max(1));
        Film::from_colours(
            self.width(),
            self.crop.y1 - self.crop.y0,
            v.iter().map(|s| f(*s * k)),
        )
    }

    /// The picture so far.
    pub fn film(&self) -> Film {
        self.mean(&self.sum, |c| c)
    }

    /// Mean first-hit albedo.
    pub fn albedo_film(&self) -> Film {
        self.mean(&self.albedo, |c| c)
    }

    /// Mean first-hit normal (unit length where anything was hit; zero elsewhere),
    /// components in -1..1.
    pub fn normal_film(&self) -> Film {
        self.mean(&self.normal, DVec3::normalize_or_zero)
    }
}

/// Adds samples `accum.samples .. accum.samples + n` of every pixel of the
/// accumulator's region to it. `progress`, when given, counts rows × samples.
///
/// With the box filter each sample lands in its own pixel. With the Gaussian
/// filter each sample (uniform in its pixel) is splatted onto the pixels within
/// [`SPLAT_RADIUS`] with the filter's weight there, as Mitsuba does: every pixel
/// then averages about π times as many samples, so its variance at equal sample
/// count is about a third of what it would be with the samples placed by the
/// filter (filter importance sampling). The weights integrate to one over the
/// plane (and are renormalised near the region's border), so the estimate is
/// unbiased: the expected picture is the image convolved with the filter either
/// way. Per-pixel determinism holds: the contributions to a pixel are added in
/// the order (sample index, source pixel), whatever the threads or passes.
pub fn render_samples(
    sc: &PathScene,
    opts: &RenderOptions,
    settings: &Settings,
    popts: &PathOptions,
    accum: &mut Accum,
    n: u32,
    progress: Option<&Progress>,
) -> RenderStats {
    let cw = accum.width() as usize;
    if cw == 0 || n == 0 {
        return RenderStats::default();
    }
    let stats = match popts.filter {
        PixelFilter::Box => render_box(sc, opts, settings, popts, accum, n, progress),
        PixelFilter::Gaussian => render_splat(sc, opts, settings, popts, accum, n, progress),
    };
    accum.samples += n;
    stats
}

/// One camera sample at pixel (`x`, `y`) placed at offset `(dx, dy)` in it:
/// (clamped radiance, first-hit albedo, first-hit normal), `None` without a ray.
#[inline]
fn camera_sample(
    sc: &PathScene,
    opts: &RenderOptions,
    popts: &PathOptions,
    (x, y): (u32, u32),
    (dx, dy): (f64, f64),
    s: &mut Sampler,
    st: &mut RenderStats,
) -> Option<PathSample> {
    st.samples += 1;
    let ray = primary_ray(
        &sc.world.camera,
        f64::from(x) + dx,
        f64::from(y) + dy,
        opts.width,
        opts.height,
        s,
    )?;
    st.rays.camera += 1;
    let mut r = radiance(sc, ray, s, &mut st.rays);
    if !r.radiance.is_finite() {
        r.radiance = DVec3::ZERO;
    }
    let m = r.radiance.max_element();
    if popts.clamp > 0.0 && m > popts.clamp {
        r.radiance *= popts.clamp / m;
    }
    Some(r)
}

/// [`render_samples`] with the box filter: every sample in its own pixel.
fn render_box(
    sc: &PathScene,
    opts: &RenderOptions,
    settings: &Settings,
    popts: &PathOptions,
    accum: &mut Accum,
    n: u32,
    progress: Option<&Progress>,
) -> RenderStats {
    let crop = accum.crop;
    let cw = accum.width() as usize;
    let first = accum.samples;
    let stats: Vec<RenderStats> = accum
        .sum
        .par_chunks_mut(cw)
        .zip(accum.albedo.par_chunks_mut(cw))
        .zip(accum.normal.par_chunks_mut(cw))
        .enumerate()
        .map(|(j, ((sum, alb), nrm))| {
            let y = crop.y0 + j as u32;
            let mut st = RenderStats::default();
            for i in 0..cw {
                let x = crop.x0 + i as u32;
                for k in first..first + n {
                    let mut s = Sampler::new(settings.seed, settings.frame, x, y, k);
                    let off = s.next_2d();
                    if let Some(r) = camera_sample(sc, opts, popts, (x, y), off, &mut s, &mut st) {
                        sum[i] += r.radiance;
                        alb[i] += r.albedo;
                        nrm[i] += r.normal;
                    }
                }
                st.pixels += 1;
            }
            if let Some(p) = progress {
                p.done.fetch_add(u64::from(n), Ordering::Relaxed);
            }
            st
        })
        .collect();
    let mut total = RenderStats::default();
    for s in stats {
        total += s;
    }
    total
}

/// The Gaussian's exponent factor: exp(a t²) with a = −1 / (2σ²).
const SPLAT_A: f64 = -1.0 / (2.0 * GAUSSIAN_SIGMA * GAUSSIAN_SIGMA);
/// Pixels on each side a splatted sample reaches.
const SPLAT_REACH: usize = 2;
/// Pixels on each side of its own that a sample can change (through the
/// Gaussian filter's splat): a band of rows rendered with this many more rows
/// above and below holds the full image's values in its middle.
pub const FILTER_REACH: u32 = SPLAT_REACH as u32;
/// Pixels across a splat.
const SPLAT_WIDTH: usize = 2 * SPLAT_REACH + 1;

/// The splatting filter: a Gaussian of σ [`GAUSSIAN_SIGMA`] less its value at
/// [`SPLAT_RADIUS`] (so it falls to zero there), separable in x and y.
#[derive(Clone, Copy, Debug)]
struct Splat {
    /// 1 / the filter's integral over the line.
    norm: f64,
    /// exp(a R²) (the value subtracted), exp(a), exp(4a) for a = [`SPLAT_A`].
    consts: [f64; 3],
    /// Share of the filter's weight that falls on pixel offsets −2..=2 from a
    /// sample's own pixel, averaged over positions in the pixel.
    shares: [f64; SPLAT_WIDTH],
}

impl Splat {
    fn new() -> Splat {
        let raw = |t: f64| Splat::raw(t);
        // Simpson's rule (the integrands are smooth between nodes).
        let simpson = |a: f64, b: f64, f: &dyn Fn(f64) -> f64| {
            let m = 2000;
            let h = (b - a) / f64::from(m);
            let mut acc = f(a) + f(b);
            for k in 1..m {
                acc += f(a + h * f64::from(k)) * if k % 2 == 1 { 4.0 } else { 2.0 };
            }
            acc * h / 3.0
        };
        let total = simpson(-SPLAT_RADIUS, SPLAT_RADIUS, &raw);
        let norm = 1.0 / total;
        // Offset m (target − source pixel): the sample at u ∈ [0, 1) in its pixel
        // is at u − 0.5 − m from the target's centre. The kink at the radius
        // falls on u = 0.5 (a node) for |m| = 2 and outside the pixel for the
        // rest.
        let mut shares = [0.0; SPLAT_WIDTH];
        for (k, share) in shares.iter_mut().enumerate() {
            let m = k as f64 - SPLAT_REACH as f64;
            *share = norm * simpson(0.0, 1.0, &|u| raw(u - 0.5 - m));
        }
        let a = SPLAT_A;
        Splat {
            norm,
            shares,
            consts: [
                (a * SPLAT_RADIUS * SPLAT_RADIUS).exp(),
                a.exp(),
                (4.0 * a).exp(),
            ],
        }
    }

    /// The filter before normalisation at distance `t` (pixels) on one axis.
    #[inline]
    fn raw(t: f64) -> f64 {
        let a = SPLAT_A;
        ((a * t * t).exp() - (a * SPLAT_RADIUS * SPLAT_RADIUS).exp()).max(0.0)
    }

    /// Normalised weights on one axis for a sample at `u` in its pixel, for the
    /// pixels at offsets −2..=2 from it.
    #[inline]
    fn weights(&self, u: f64) -> [f64; SPLAT_WIDTH] {
        // exp(a (d − m)²) = exp(a d²) · exp(−2ad)^m · exp(a m²): two calls of
        // exp for the five offsets instead of five.
        let a = SPLAT_A;
        let [bias, c1, c2] = self.consts;
        let d = u - 0.5;
        let e = (a * d * d).exp();
        let r = (-2.0 * a * d).exp();
        let g = [
            e * c2 / (r * r),
            e * c1 / r,
            e,
            e * c1 * r,
            e * c2 * (r * r),
        ];
        g.map(|v| self.norm * (v - bias).max(0.0))
    }

    /// 1 / the expected total weight a pixel at `i` of `len` receives (1 inside;
    /// more near the border, where pixels beyond it send nothing).
    fn border(&self, i: usize, len: usize) -> f64 {
        let full: f64 = self.shares.iter().sum();
        let mut got = 0.0;
        for (k, share) in self.shares.iter().enumerate() {
            // Source pixel i − m for offset m = k − 2.
            let src = i as i64 - (k as i64 - SPLAT_REACH as i64);
            if src >= 0 && (src as usize) < len {
                got += share;
            }
        }
        if got == full {
            1.0
        } else {
            full / got
        }
    }
}

/// One sample of a pixel waiting to be splatted (64 bytes: the weights are kept
/// in f32, whose rounding, 6e-8 of each weight, is far below any noise).
#[derive(Clone, Copy, Debug, Default)]
struct Pending {
    radiance: DVec3,
    /// Weights towards the columns at offsets −2..=2.
    wx: [f32; SPLAT_WIDTH],
    /// Weights towards the rows at offsets −2..=2.
    wy: [f32; SPLAT_WIDTH],
}

/// [`render_samples`] with the Gaussian filter, splatting each sample index in
/// two phases: every pixel's sample k, then every pixel gathers what its
/// neighbours' samples k send it.
fn render_splat(
    sc: &PathScene,
    opts: &RenderOptions,
    settings: &Settings,
    popts: &PathOptions,
    accum: &mut Accum,
    n: u32,
    progress: Option<&Progress>,
) -> RenderStats {
    let crop = accum.crop;
    let cw = accum.width() as usize;
    let ch = (crop.y1 - crop.y0) as usize;
    let first = accum.samples;
    let splat = Splat::new();
    let bx: Vec<f64> = (0..cw).map(|i| splat.border(i, cw)).collect();
    let by: Vec<f64> = (0..ch).map(|j| splat.border(j, ch)).collect();
    let mut pending = vec![Pending::default(); cw * ch];
    let mut total = RenderStats::default();
    for k in first..first + n {
        let stats: Vec<RenderStats> = pending
            .par_chunks_mut(cw)
            .zip(accum.albedo.par_chunks_mut(cw))
            .zip(accum.normal.par_chunks_mut(cw))
            .enumerate()
            .map(|(j, ((pend, alb), nrm))| {
                let y = crop.y0 + j as u32;
                let mut st = RenderStats::default();
                for i in 0..cw {
                    let x = crop.x0 + i as u32;
                    let mut s = Sampler::new(settings.seed, settings.frame, x, y, k);
                    let (u, v) = s.next_2d();
                    let r = camera_sample(sc, opts, popts, (x, y), (u, v), &mut s, &mut st)
                        .unwrap_or_default();
                    pend[i] = Pending {
                        radiance: r.radiance,
                        wx: splat.weights(u).map(|w| w as f32),
                        wy: splat.weights(v).map(|w| w as f32),
                    };
                    alb[i] += r.albedo;
                    nrm[i] += r.normal;
                    st.pixels += u64::from(k == first);
                }
                if let Some(p) = progress {
                    p.done.fetch_add(1, Ordering::Relaxed);
                }
                st
            })
            .collect();
        for s in stats {
            total += s;
        }
        let pending = &pending;
        accum
            .sum
            .par_chunks_mut(cw)
            .enumerate()
            .for_each(|(j, row)| {
                let rows = j.saturating_sub(SPLAT_REACH)..(j + SPLAT_REACH + 1).min(ch);
                for (i, out) in row.iter_mut().enumerate() {
                    let cols = i.saturating_sub(SPLAT_REACH)..(i + SPLAT_REACH + 1).min(cw);
                    let mut acc = DVec3::ZERO;
                    for sj in rows.clone() {
                        let src = &pending[sj * cw..(sj + 1) * cw];
                        // Offset of this pixel from the source: j − sj ∈ −2..=2.
                        let ky = j + SPLAT_REACH - sj;
                        for si in cols.clone() {
                            let p = &src[si];
                            let w = f64::from(p.wx[i + SPLAT_REACH - si]) * f64::from(p.wy[ky]);
                            acc += p.radiance * w;
                        }
                    }
                    *out += acc * (bx[i] * by[j]);
                }
            });
    }
    total
}

/// Renders `world` with `spp` samples per pixel in one go (no checkpoints).
pub fn render(
    world: &World,
    opts: &RenderOptions,
    settings: &Settings,
    popts: &PathOptions,
    spp: u32,
) -> super::Rendered {
    let sc = PathScene::new(world, popts.max_depth);
    let mut acc = Accum::new(resolve_crop(settings, opts.width, opts.height));
    let stats = render_samples(&sc, opts, settings, popts, &mut acc, spp, None);
    super::Rendered {
        film: acc.film(),
        stats,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splat_weights_follow_the_filter_and_integrate_to_one() {
        let sp = Splat::new();
        let full: f64 = sp.shares.iter().sum();
        assert!((full - 1.0).abs() < 1e-12, "{full}");
        for i in 0..=100 {
            let u = f64::from(i) / 100.0;
            let w = sp.weights(u);
            for (k, wk) in w.iter().enumerate() {
                let m = k as f64 - SPLAT_REACH as f64;
                let want = sp.norm * Splat::raw(u - 0.5 - m);
                assert!(
                    (wk - want).abs() < 1e-14,
                    "u {u} offset {m}: {wk} vs {want}"
                );
            }
        }
        // Interior pixels get weight one; the border ones are scaled up.
        assert_eq!(sp.border(10, 20), 1.0);
        assert!(sp.border(0, 20) > 1.0 && (sp.border(19, 20) - sp.border(0, 20)).abs() < 1e-12);
    }
}
