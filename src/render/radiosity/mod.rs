//! POV-Ray 3.7's radiosity in the classic renderer: the `ambient` term of every
//! diffuse surface replaced by light gathered from its surroundings, after
//! Greg Ward's irradiance caching.
//!
//! A pretrace (mosaic passes of camera rays, blocks halving from
//! `pretrace_start` to `pretrace_end`) fills a [`Cache`] of gathered values;
//! the final render blends them. A value is gathered by `count` cosine-
//! distributed rays whose hits are shaded in full (their own diffuse light
//! coming from the next bounce's values, up to `recursion_limit`).
//!
//! Determinism: a pretrace pass traces its pixels in parallel against the cache
//! as the previous pass left it; the values each pixel gathers (visible to
//! that pixel's later lookups) are added to the cache in pixel order after the
//! pass. The final render only reads the cache; where no value is close enough
//! it gathers one for the point without keeping it. So the picture does not
//! depend on the number of threads.

mod cache;

pub use cache::{Blend, Cache, Sample};

use super::camera::primary_ray;
use super::shade::{trace, trace_found, TraceCtx};
use super::stats::RayStats;
use super::{media, Crop, Progress, Sampler};
use crate::build::{Ray, RayKind, World};
use crate::scene::Radiosity;
use glam::DVec3;
use rayon::prelude::*;
use std::sync::atomic::Ordering;

/// What shading needs to know of radiosity during one phase of a render.
#[derive(Debug)]
pub struct State<'a> {
    /// The scene's settings.
    pub settings: Radiosity,
    /// Values gathered so far.
    pub cache: &'a Cache,
    /// Where the camera is (reuse radii are fractions of the distance from it).
    pub eye: DVec3,
    /// A pretrace pass (gathers where fewer than `nearest_count` values blend,
    /// under the lowered error bound) rather than the final render.
    pub pretrace: bool,
    /// The photons shot before the render (their light is gathered too).
    pub photons: Option<&'a super::photons::PhotonMap>,
}

/// Per camera sample: which bounce is being gathered and what the pretrace
/// gathered along the way.
#[derive(Clone, Debug, Default)]
pub struct Local {
    /// 0 on surfaces the camera sees (directly or by reflection and
    /// refraction); `k` on what the rays gathering bounce `k − 1` meet.
    pub depth: u32,
    /// Values this pixel gathered in the current pretrace wave, indexed as
    /// the shared cache is (a pixel can gather thousands on deep bounces).
    pub fresh: Cache,
}

impl Local {
    /// For a pretrace pixel under `set`.
    pub fn pretrace(set: &Radiosity) -> Local {
        Local {
            depth: 0,
            fresh: Cache::new(set.error_bound),
        }
    }
}

impl State<'_> {
    /// The error bound for bounce `depth`: lowered by `low_error_factor` for
    /// the surfaces the camera sees during the pretrace.
    fn error_bound(&self, depth: u32) -> f64 {
        if self.pretrace && depth == 0 {
            self.settings.error_bound * self.settings.low_error_factor
        } else {
            self.settings.error_bound
        }
    }

    /// Whether rays of the current gathering should pass through media.
    pub fn skips_media(&self, local: &Local) -> bool {
        local.depth > 0 && !self.settings.media
    }
}

/// A point light is gathered at: position, geometric normal and the normal
/// gathered about (both unit and facing the viewer).
#[derive(Clone, Copy, Debug)]
pub struct Spot {
    /// The point.
    pub p: DVec3,
    /// The surface's own normal (rays must leave on its side).
    pub geo_n: DVec3,
    /// The normal gathering is about (perturbed when `normal on`).
    pub n: DVec3,
}

/// The diffuse light arriving at `at`, already multiplied by `brightness`:
/// what a surface's `diffuse · colour` multiplies in place of `ambient`.
/// `level` is the trace level of the ray that found the point.
pub fn irradiance(world: &World, rs: &State, at: Spot, level: u32, ctx: &mut TraceCtx) -> DVec3 {
    let Spot { p, n, .. } = at;
    let set = &rs.settings;
    let depth = ctx.rad.depth;
    if depth >= set.recursion_limit {
        return DVec3::ZERO;
    }
    let eb = rs.error_bound(depth);
    let mut blend = Blend::default();
    rs.cache.blend(p, n, depth, eb, &mut blend);
    ctx.rad.fresh.blend(p, n, depth, eb, &mut blend);
    // On the surfaces the camera sees, the pretrace (and, with
    // `always_sample`, the final render) gathers where fewer than
    // `nearest_count` values blend; otherwise a value is gathered only where
    // none can be reused. (Asking `nearest_count` of every bounce multiplies
    // the cost by itself per bounce: POV-Ray's radiosity/cornell.pov,
    // `count 200 recursion_limit 3 nearest_count 10`, took minutes instead of
    // seconds.)
    let enough = if depth == 0 && (rs.pretrace || set.always_sample) {
        set.nearest_count
    } else {
        1
    };
    if blend.count < enough {
        let s = gather(world, rs, at, level, ctx);
        blend.add(&s, p, n, eb);
        if rs.pretrace {
            ctx.rad.fresh.push(s);
        }
    }
    blend.value() * set.brightness
}

/// A new value at `at`: `count` rays over the hemisphere about its normal.
fn gather(world: &World, rs: &State, at: Spot, level: u32, ctx: &mut TraceCtx) -> Sample {
    let Spot { p, geo_n, n } = at;
    let set = &rs.settings;
    let depth = ctx.rad.depth;
    let key = hash(p, depth);
    // The directions: a Sobol (0, 2)-sequence (every prefix well spread, which
    // `importance` relies on), turned about the normal by an angle of the
    // point's own so that neighbouring values do not share one pattern.
    let turn = (key >> 11) as f64 / (1u64 << 53) as f64;
    let pool = set.count_pool.max(set.count);
    let offset = if pool > set.count {
        (key % u64::from(pool)) as u32
    } else {
        0
    };
    let (t1, t2) = frame(n);
    // Gathering rays stop where their weight falls below radiosity's own
    // adc_bailout: shading compares weights with the global one.
    let weight = if set.adc_bailout > 0.0 {
        world.global.adc_bailout / set.adc_bailout
    } else {
        f64::INFINITY
    };
    let count = set.count;
    let mut sum = DVec3::ZERO;
    let mut inverse_distance = 0.0;
    ctx.rad.depth = depth + 1;
    for k in 0..count {
        let j = (offset + k) % pool;
        let u1 = f64::from(sobol_burley::sample(j, 0, 0x5ad1_05e7));
        let u2 = f64::from(sobol_burley::sample(j, 1, 0x5ad1_05e7));
        let r = u1.sqrt();
        let (c, s) = super::sampler::turn((u2 + turn).fract());
        let dir = (r * c) * t1 + (r * s) * t2 + (1.0 - u1).max(0.0).sqrt() * n;
        if dir.dot(geo_n) <= 0.0 {
            // Below the surface itself (a perturbed normal): no light.
            continue;
        }
        let (ray, eps) = Ray::secondary(p, geo_n, dir);
        ctx.stats.radiosity += 1;
        let hit = world.intersect(&ray, eps, f64::INFINITY, RayKind::Radiosity);
        let mut share = 1.0;
        if let Some(h) = &hit {
            inverse_distance += 1.0 / h.t.max(1e-9);
            if let Some(imp) = world.primitives[h.prim as usize].flags.importance {
                // Only the first count·importance rays of the sequence that
                // meet this object are traced, each standing for 1/importance.
                let imp = f64::from(imp) / 10_000.0;
                if f64::from(k) >= (f64::from(count) * imp).ceil() {
                    continue;
                }
                share = 1.0 / imp;
            }
        }
        sum += share * trace_found(world, &ray, hit, level + 1, weight, ctx);
    }
    ctx.rad.depth = depth;
    let mut e = sum / f64::from(count.max(1));
    if set.max_sample > 0.0 && e.max_element() > set.max_sample {
        e *= set.max_sample / e.max_element();
    }
    if set.gray_threshold > 0.0 {
        let grey = DVec3::splat(e.dot(DVec3::new(0.299, 0.587, 0.114)));
        e = e.lerp(grey, set.gray_threshold);
    }
    let harmonic = if inverse_distance > 0.0 {
        f64::from(count) / inverse_distance
    } else {
        f64::INFINITY
    };
    let from_eye = (p - rs.eye).length().max(1e-9);
    Sample {
        p,
        n,
        e,
        r: harmonic.clamp(set.minimum_reuse * from_eye, set.maximum_reuse * from_eye),
        depth,
    }
}

/// Two unit vectors completing `n` to an orthonormal frame (not glam's
/// `any_orthonormal_pair`: its frame turns the gathering directions, so every
/// radiosity picture would change at the noise level).
fn frame(n: DVec3) -> (DVec3, DVec3) {
    let t = if n.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let t1 = n.cross(t).normalize();
    (t1, n.cross(t1))
}

/// A 64-bit hash of a point and bounce (SplitMix64 over the coordinates' bits).
fn hash(p: DVec3, depth: u32) -> u64 {
    let mut h = u64::from(depth) ^ 0x2545_f491_4f6c_dd1d;
    for v in [p.x, p.y, p.z] {
        h = super::sampler::mix(h ^ v.to_bits());
    }
    h
}

/// Block sizes of the pretrace passes, in pixels: `pretrace_start` of the
/// image's larger side, halving down to `pretrace_end`.
pub fn pretrace_blocks(set: &Radiosity, width: u32, height: u32) -> Vec<f64> {
    let side = f64::from(width.max(height));
    let end = (set.pretrace_end * side).max(1.0);
    let mut size = (set.pretrace_start * side).max(end);
    let mut out = vec![size];
    while size / 2.0 >= end * 0.999 && out.len() < 32 {
        size /= 2.0;
        out.push(size);
    }
    if size > end * 1.001 {
        out.push(end);
    }
    out
}

/// The radiosity pretrace over `crop` of a `width`×`height` image: the cache
/// the final render blends. `seed` and `frame` key the samplers as the
/// render's own. Rays traced go to `stats`; pixels done to `progress` (with
/// its `pretrace` flag set meanwhile).
pub fn pretrace(
    world: &World,
    (width, height): (u32, u32),
    crop: &Crop,
    (seed, frame): (u64, u32),
    stats: &mut RayStats,
    progress: Option<&Progress>,
    photons: Option<&super::photons::PhotonMap>,
) -> Cache {
    let Some(set) = world.global.radiosity else {
        return Cache::default();
    };
    let mut cache = Cache::new(set.error_bound);
    let passes: Vec<Vec<(f64, f64)>> = pretrace_blocks(&set, width, height)
        .into_iter()
        .map(|block| block_centres(crop, block))
        .collect();
    if let Some(p) = progress {
        let total: usize = passes.iter().map(Vec::len).sum();
        p.total.store(total as u64, Ordering::Relaxed);
        p.done.store(0, Ordering::Relaxed);
        p.pretrace.store(true, Ordering::Relaxed);
    }
    for (pass, centres) in passes.iter().enumerate() {
        // Waves of 1, 2, 4, … pixels, spread over the image (a bit-reversed
        // order): each wave reads what the earlier ones gathered, so the
        // first pixels fill the cache for the rest instead of every pixel of
        // the first pass gathering the same deeper bounces on its own. Wave
        // bounds depend on the pixel count only, not on the threads.
        let order = spread(centres.len());
        let mut start = 0;
        let mut wave = 1;
        while start < order.len() {
            let end = (start + wave).min(order.len());
            let state = State {
                settings: set,
                cache: &cache,
                eye: world.camera.location,
                pretrace: true,
                photons,
            };
            let found = trace_wave(
                world,
                &state,
                &order[start..end],
                centres,
                (width, height),
                (seed, frame, pass as u32),
            );
            if let Some(p) = progress {
                p.done.fetch_add((end - start) as u64, Ordering::Relaxed);
            }
            for (fresh, rays) in found {
                *stats += rays;
                for s in fresh.into_samples() {
                    cache.push(s);
                }
            }
            start = end;
            wave *= 2;
        }
    }
    cache
}

/// The centres of the blocks of side `block` pixels that tile `crop`.
fn block_centres(crop: &Crop, block: f64) -> Vec<(f64, f64)> {
    let mut centres = Vec::new();
    let mut y = f64::from(crop.y0) + block / 2.0;
    while y < f64::from(crop.y1) {
        let mut x = f64::from(crop.x0) + block / 2.0;
        while x < f64::from(crop.x1) {
            centres.push((x, y));
            x += block;
        }
        y += block;
    }
    centres
}

/// `0..n` in bit-reversed order of the next power of two (out-of-range ones
/// skipped): consecutive runs of it are spread evenly over the list.
fn spread(n: usize) -> Vec<usize> {
    if n == 0 {
        return Vec::new();
    }
    let bits = usize::BITS - (n - 1).leading_zeros();
    (0..1usize << bits)
        .map(|i| {
            if bits == 0 {
                0
            } else {
                i.reverse_bits() >> (usize::BITS - bits)
            }
        })
        .filter(|&i| i < n)
        .collect()
}

/// Traces the pretrace pixels `centres[k]` for `k` in `wave`, in parallel:
/// what each gathered and the rays it traced, in wave order.
fn trace_wave(
    world: &World,
    state: &State,
    wave: &[usize],
    centres: &[(f64, f64)],
    (width, height): (u32, u32),
    (seed, frame, pass): (u64, u32, u32),
) -> Vec<(Cache, RayStats)> {
    wave.par_iter()
        .map(|&k| {
            let (x, y) = centres[k];
            let mut sampler = Sampler::new(seed, frame, x as u32, y as u32, 0x7ad0_0000 + pass);
            let mut rays = RayStats::default();
            let Some(ray) = primary_ray(&world.camera, x, y, width, height, &mut sampler) else {
                return (Cache::default(), rays);
            };
            rays.camera += 1;
            let mut ctx = TraceCtx {
                sampler: &mut sampler,
                stats: &mut rays,
                media: if world.tracks_interiors {
                    media::MediaPath::at_camera(world)
                } else {
                    media::MediaPath::default()
                },
                passes: 0,
                radiosity: Some(state),
                rad: Local::pretrace(&state.settings),
                photons: state.photons,
                iors: super::ior::IorStack::at_camera(world),
            };
            trace(world, &ray, 0.0, RayKind::Camera, 1, 1.0, &mut ctx);
            let fresh = std::mem::take(&mut ctx.rad.fresh);
            (fresh, rays)
        })
        .collect()
}
