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
/// Radius at which the Gaussian pixel filter is cut off, in pixels.
pub const GAUSSIAN_RADIUS: f64 = 1.5;

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

    fn mean(&self, v: &[DVec3]) -> Film {
        let k = 1.0 / f64::from(self.samples.max(1));
        Film {
            width: self.width(),
            height: self.crop.y1 - self.crop.y0,
            pixels: v.iter().map(|s| *s * k).collect(),
        }
    }

    /// The picture so far.
    pub fn film(&self) -> Film {
        self.mean(&self.sum)
    }

    /// Mean first-hit albedo.
    pub fn albedo_film(&self) -> Film {
        self.mean(&self.albedo)
    }

    /// Mean first-hit normal (unit length where anything was hit; zero elsewhere),
    /// components in -1..1.
    pub fn normal_film(&self) -> Film {
        let mut f = self.mean(&self.normal);
        for p in &mut f.pixels {
            *p = p.normalize_or_zero();
        }
        f
    }
}

/// Offset in the pixel (0..1 for the box; around 0.5 for the Gaussian) of a sample
/// from a point on the unit square. The Gaussian is sampled exactly (radially,
/// truncated at [`GAUSSIAN_RADIUS`]) so every sample has weight one.
pub fn filter_offset(filter: PixelFilter, (u, v): (f64, f64)) -> (f64, f64) {
    match filter {
        PixelFilter::Box => (u, v),
        PixelFilter::Gaussian => {
            let s2 = 2.0 * GAUSSIAN_SIGMA * GAUSSIAN_SIGMA;
            let cut = 1.0 - (-GAUSSIAN_RADIUS * GAUSSIAN_RADIUS / s2).exp();
            let r = (-s2 * (1.0 - u * cut).ln()).max(0.0).sqrt();
            let (c, s) = bsdf::turn(v);
            (0.5 + r * c, 0.5 + r * s)
        }
    }
}

/// Adds samples `accum.samples .. accum.samples + n` of every pixel of the
/// accumulator's region to it. `progress`, when given, counts rows × samples.
pub fn render_samples(
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
    if cw == 0 || n == 0 {
        return RenderStats::default();
    }
    let first = accum.samples;
    let world: &World = sc.world;
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
                    let (dx, dy) = filter_offset(popts.filter, s.next_2d());
                    st.samples += 1;
                    let Some(ray) = primary_ray(
                        &world.camera,
                        f64::from(x) + dx,
                        f64::from(y) + dy,
                        opts.width,
                        opts.height,
                        &mut s,
                    ) else {
                        continue;
                    };
                    st.rays.camera += 1;
                    let r = radiance(sc, ray, &mut s, &mut st.rays);
                    let mut l = r.radiance;
                    if !l.is_finite() {
                        l = DVec3::ZERO;
                    }
                    if popts.clamp > 0.0 && l.max_element() > popts.clamp {
                        l *= popts.clamp / l.max_element();
                    }
                    sum[i] += l;
                    alb[i] += r.albedo;
                    nrm[i] += r.normal;
                }
                st.pixels += 1;
            }
            if let Some(p) = progress {
                p.done.fetch_add(u64::from(n), Ordering::Relaxed);
            }
            st
        })
        .collect();
    accum.samples += n;
    let mut total = RenderStats::default();
    for s in stats {
        total += s;
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
    fn gaussian_offsets_stay_within_the_cut_off_and_centre_on_the_pixel() {
        let mut mean = (0.0, 0.0);
        let n = 1000;
        for i in 0..n {
            let mut s = Sampler::new(1, 0, 2, 3, i);
            let (x, y) = filter_offset(PixelFilter::Gaussian, s.next_2d());
            let r = ((x - 0.5).powi(2) + (y - 0.5).powi(2)).sqrt();
            assert!(r <= GAUSSIAN_RADIUS + 1e-12);
            mean.0 += x / f64::from(n);
            mean.1 += y / f64::from(n);
        }
        assert!(
            (mean.0 - 0.5).abs() < 0.02 && (mean.1 - 0.5).abs() < 0.02,
            "{mean:?}"
        );
    }
}
