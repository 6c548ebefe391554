//! Rendering a [`World`] into a [`Film`] of working-space colours.
//!
//! Every sample is a function of (pixel, sample index, frame, seed) only, and ray
//! counters are summed per row, so the picture and the statistics do not depend on
//! the number of threads. [`render`] takes one ray per pixel centre; [`render_with`]
//! adds anti-aliasing, fixed sampling, a crop region, debug passes, statistics and
//! progress.

mod aa;
mod atmosphere;
mod camera;
mod film;
mod focal_blur;
pub mod ior;
mod irid;
mod lights;
mod media;
mod passes;
pub mod path;
pub mod photons;
pub mod radiosity;
mod sampler;
mod shade;
mod stats;

pub use crate::pattern::{checker_index, evaluate as evaluate_pigment, CHECKER_OFFSET};
pub use aa::{Antialias, Sampling};
pub use atmosphere::{apply_atmosphere, sky};
pub use camera::primary_ray;
pub use film::Film;
pub use lights::{cylinder_attenuation, fade, incident, shadow, spot_attenuation, Incident};
pub use passes::Pass;
pub use sampler::Sampler;
pub use shade::{metallic_tint, metallic_weight, reflection_amount, trace, TraceCtx};
pub use stats::RayStats;

use crate::build::{Ray, RayKind, World};
use glam::{DVec3, Vec3};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};

/// What to render.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderOptions {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
}

impl Default for RenderOptions {
    /// POV-Ray's default 320×240.
    fn default() -> Self {
        RenderOptions {
            width: 320,
            height: 240,
        }
    }
}

/// A rectangle of pixels: columns `x0..x1` and rows `y0..y1` (ends excluded),
/// `(0, 0)` at the top-left of the full image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Crop {
    /// First column.
    pub x0: u32,
    /// First row.
    pub y0: u32,
    /// One past the last column.
    pub x1: u32,
    /// One past the last row.
    pub y1: u32,
}

/// How to render, beyond the image size; the default is one ray per pixel centre,
/// the whole image, the shaded picture.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Settings {
    /// Rays per pixel.
    pub sampling: Sampling,
    /// Render only this region (clamped to the image); the film then has the
    /// region's size, and every pixel in it is the same as in a full render.
    pub crop: Option<Crop>,
    /// Which picture to make.
    pub pass: Pass,
    /// Seed of every random number ([`Sampler`]).
    pub seed: u64,
    /// Animation frame number (also keys the [`Sampler`]).
    pub frame: u32,
}

/// Work done, to watch a render from another thread: `done` of `total` units
/// (rows; blocks of [`aa::BLOCK`] pixels for an anti-aliased render).
#[derive(Debug, Default)]
pub struct Progress {
    /// Units finished.
    pub done: AtomicU64,
    /// Units in the whole render, set when it starts.
    pub total: AtomicU64,
    /// Radiosity's pretrace is running (`done`/`total` then count its pixels).
    pub pretrace: std::sync::atomic::AtomicBool,
    /// Photons are being shot (before anything else).
    pub photons: std::sync::atomic::AtomicBool,
}

/// Counts from one render; the same for any number of threads.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderStats {
    /// Rays by kind.
    pub rays: RayStats,
    /// Pixels rendered.
    pub pixels: u64,
    /// Camera samples taken (rays through the image plane, whether or not the
    /// camera made a ray).
    pub samples: u64,
    /// Pixels adaptive anti-aliasing supersampled.
    pub supersampled: u64,
    /// Photons shot from the lights.
    pub photons_shot: u64,
    /// Photons stored where they landed.
    pub photons_stored: u64,
}

impl std::ops::AddAssign for RenderStats {
    fn add_assign(&mut self, o: RenderStats) {
        self.rays += o.rays;
        self.pixels += o.pixels;
        self.samples += o.samples;
        self.supersampled += o.supersampled;
        self.photons_shot += o.photons_shot;
        self.photons_stored += o.photons_stored;
    }
}

/// A film and what it took.
#[derive(Clone, Debug, PartialEq)]
pub struct Rendered {
    /// The picture (the crop region's size when cropped).
    pub film: Film,
    /// Counts.
    pub stats: RenderStats,
}

/// Renders `world` with one ray through each pixel centre, with rayon, one row per
/// task.
pub fn render(world: &World, opts: &RenderOptions) -> Film {
    render_with(world, opts, &Settings::default(), None).film
}

/// The region `settings.crop` asks for, clamped to a `w`×`h` image (the whole
/// image without a crop).
pub fn resolve_crop(settings: &Settings, w: u32, h: u32) -> Crop {
    settings.crop.map_or(
        Crop {
            x0: 0,
            y0: 0,
            x1: w,
            y1: h,
        },
        |c| Crop {
            x0: c.x0.min(w),
            y0: c.y0.min(h),
            x1: c.x1.min(w).max(c.x0.min(w)),
            y1: c.y1.min(h).max(c.y0.min(h)),
        },
    )
}

/// Renders `world` as `settings` say. `progress`, when given, is updated as rows
/// finish.
pub fn render_with(
    world: &World,
    opts: &RenderOptions,
    settings: &Settings,
    progress: Option<&Progress>,
) -> Rendered {
    let (w, h) = (opts.width, opts.height);
    let crop = resolve_crop(settings, w, h);
    let (cw, ch) = (crop.x1 - crop.x0, crop.y1 - crop.y0);
    // Passes that look at the whole picture before any pixel (the radiosity
    // pretrace, the depth pass's farthest hit) cover the full image even when
    // cropped, so a crop's pixels are the full render's (`rts render --shard`
    // on a still relies on it).
    let full = Crop {
        x0: 0,
        y0: 0,
        x1: w,
        y1: h,
    };
    let sampling = settings.sampling;
    // Photons: shot first; radiosity's gathering sees their light too.
    let shot = match (world.global.photons, settings.pass) {
        (Some(_), Pass::Beauty) if cw > 0 && ch > 0 => {
            if let Some(p) = progress {
                p.photons.store(true, Ordering::Relaxed);
            }
            Some(photons::shoot(world, settings.seed))
        }
        _ => None,
    };
    let photon_map = shot.as_ref().map(|s| &s.map);
    // Radiosity: the pretrace fills the cache the render then reads.
    let mut pretrace_rays = RayStats::default();
    let cache = match (world.global.radiosity, settings.pass) {
        (Some(_), Pass::Beauty) if cw > 0 && ch > 0 => Some(radiosity::pretrace(
            world,
            (w, h),
            &full,
            (settings.seed, settings.frame),
            &mut pretrace_rays,
            progress,
            photon_map,
        )),
        _ => None,
    };
    let rad_state = cache.as_ref().and_then(|cache| {
        Some(radiosity::State {
            settings: world.global.radiosity?,
            cache,
            eye: world.camera.location,
            pretrace: false,
            photons: photon_map,
        })
    });
    let r = Renderer {
        world,
        w,
        h,
        settings,
        max_depth: 0.0,
        blur_z: focal_blur::quantile(world.camera.confidence),
        radiosity: rad_state.as_ref(),
        photons: photon_map,
        camera_iors: ior::IorStack::at_camera(world),
    };
    let max_depth = match settings.pass {
        Pass::Depth { max: Some(m) } => m,
        Pass::Depth { max: None } => r.farthest_hit(&full),
        _ => 0.0,
    };
    let r = Renderer { max_depth, ..r };
    let adaptive = matches!(sampling, Sampling::Adaptive(_));
    if let Some(p) = progress {
        let units = if adaptive {
            aa::blocks(&crop, w, h).len() as u64
        } else {
            u64::from(ch)
        };
        p.total.store(units, Ordering::Relaxed);
        p.done.store(0, Ordering::Relaxed);
        p.pretrace.store(false, Ordering::Relaxed);
        p.photons.store(false, Ordering::Relaxed);
    }
    let tick = || {
        if let Some(p) = progress {
            p.done.fetch_add(1, Ordering::Relaxed);
        }
    };
    let mut film = Film::new(cw, ch);
    let mut stats = RenderStats::default();
    stats.rays += pretrace_rays;
    if let Some(s) = &shot {
        stats.photons_shot = s.shot;
        stats.photons_stored = s.map.len() as u64;
    }
    if cw == 0 || ch == 0 {
        return Rendered { film, stats };
    }
    let row_stats: Vec<RenderStats> = match sampling {
        Sampling::Centre | Sampling::Fixed(_) => {
            let n = match sampling {
                Sampling::Fixed(n) => n.max(1),
                _ => 0,
            };
            film.pixels
                .par_chunks_mut(cw as usize)
                .enumerate()
                .map(|(j, row)| {
                    let y = crop.y0 + j as u32;
                    let mut st = RenderStats::default();
                    for (i, px) in row.iter_mut().enumerate() {
                        let x = crop.x0 + i as u32;
                        let c = if n == 0 {
                            r.centre(x, y, &mut st)
                        } else {
                            r.fixed(x, y, n, &mut st)
                        };
                        *px = c.as_vec3();
                        st.pixels += 1;
                    }
                    tick();
                    st
                })
                .collect()
        }
        Sampling::Adaptive(aa) => {
            // Each row of blocks fills its band of the film (its blocks in
            // parallel, and the bands in parallel), so only the blocks in
            // progress hold their values, not the whole picture a second time.
            let blocks = aa::blocks(&crop, w, h);
            let mut bands: Vec<(u32, &mut [Vec3], &[aa::Block])> = Vec::new();
            let mut rest: &mut [Vec3] = &mut film.pixels;
            for group in blocks.chunk_by(|a, b| a.y0 == b.y0) {
                let (y0, y1) = (group[0].y0.max(crop.y0), group[0].y1.min(crop.y1));
                let (band, tail) =
                    std::mem::take(&mut rest).split_at_mut((y1 - y0) as usize * cw as usize);
                bands.push((y0, band, group));
                rest = tail;
            }
            bands
                .into_par_iter()
                .flat_map_iter(|(band_y0, band, group)| {
                    let results: Vec<(aa::Block, Vec<DVec3>, RenderStats)> = group
                        .par_iter()
                        .map(|b| {
                            let mut st = RenderStats::default();
                            let values = aa::render_block(
                                b,
                                &aa,
                                |x, y, st: &mut RenderStats| r.centre(x, y, st),
                                |x, y, c, st: &mut RenderStats| r.supersample(x, y, c, &aa, st),
                                &mut st,
                            );
                            tick();
                            (*b, values, st)
                        })
                        .collect();
                    let mut all = Vec::with_capacity(results.len());
                    for (b, values, mut st) in results {
                        for y in b.y0.max(crop.y0)..b.y1.min(crop.y1) {
                            for x in b.x0.max(crop.x0)..b.x1.min(crop.x1) {
                                st.pixels += 1;
                                let v = values[((y - b.y0) * (b.x1 - b.x0) + (x - b.x0)) as usize];
                                band[((y - band_y0) * cw + (x - crop.x0)) as usize] = v.as_vec3();
                            }
                        }
                        all.push(st);
                    }
                    all
                })
                .collect()
        }
    };
    for s in row_stats {
        stats += s;
    }
    Rendered { film, stats }
}

/// What every sample of one render shares.
struct Renderer<'a> {
    world: &'a World,
    w: u32,
    h: u32,
    settings: &'a Settings,
    /// Black distance of the depth pass.
    max_depth: f64,
    /// The normal quantile of the camera's focal-blur `confidence`.
    blur_z: f64,
    /// Radiosity's cache, read-only during the render.
    radiosity: Option<&'a radiosity::State<'a>>,
    /// The photons shot before the render.
    photons: Option<&'a photons::PhotonMap>,
    /// The interiors around the camera.
    camera_iors: ior::IorStack,
}

impl Renderer<'_> {
    /// The value of sample `index` of pixel (`px`, `py`), taken at image point
    /// (`x`, `y`) (continuous pixel units) using `sampler` for anything the
    /// camera needs. A focal-blur camera averages several lens rays instead
    /// (see [`Renderer::blurred`]).
    fn sample_at(
        &self,
        (px, py, index): (u32, u32, u32),
        (x, y): (f64, f64),
        sampler: &mut Sampler,
        st: &mut RenderStats,
    ) -> DVec3 {
        let world = self.world;
        st.samples += 1;
        if self.settings.pass == Pass::Beauty && focal_blur::active(&world.camera) {
            let jitter = matches!(self.settings.sampling, Sampling::Centre);
            return self.blurred((px, py, index), (x, y), jitter, st);
        }
        self.one_ray((x, y), sampler, st)
    }

    /// POV-Ray's focal blur for one image sample: lens rays (each with its own
    /// sampler, so their lens points are stratified) until the camera's
    /// `confidence`/`variance` rule says the mean is close enough or
    /// `blur_samples` is reached. With one sample per pixel (no anti-aliasing)
    /// each ray also goes through a random point of the pixel, as in POV-Ray.
    fn blurred(
        &self,
        (px, py, index): (u32, u32, u32),
        (x, y): (f64, f64),
        jitter: bool,
        st: &mut RenderStats,
    ) -> DVec3 {
        let cam = &self.world.camera;
        let mut run = focal_blur::Running::default();
        let base = index.wrapping_mul(focal_blur::STRIDE);
        while !run.converged(cam, self.blur_z) {
            let mut s = self.sampler(px, py, base.wrapping_add(run.count()));
            let at = if jitter {
                let (u, v) = s.next_2d();
                (f64::from(px) + u, f64::from(py) + v)
            } else {
                (x, y)
            };
            run.push(self.one_ray(at, &mut s, st));
        }
        run.mean()
    }

    /// The colour of the one camera ray through image point (`x`, `y`) (the mean
    /// of the rays a mesh camera shoots into the pixel).
    fn one_ray(&self, (x, y): (f64, f64), sampler: &mut Sampler, st: &mut RenderStats) -> DVec3 {
        let world = self.world;
        if let Some(mesh) = world
            .camera
            .mesh
            .as_deref()
            .filter(|m| m.rays_per_pixel > 1)
        {
            // Pixels average the rays that have a face; without any they stay black.
            let (mut sum, mut n) = (DVec3::ZERO, 0u32);
            for r in 0..mesh.rays_per_pixel {
                if let Some(ray) = camera::mesh_ray(mesh, x, y, self.w, self.h, r) {
                    sum += self.trace_camera_ray(ray, sampler, st);
                    n += 1;
                }
            }
            return if n > 0 {
                sum / f64::from(n)
            } else {
                DVec3::ZERO
            };
        }
        let Some(ray) = primary_ray(&world.camera, x, y, self.w, self.h, sampler) else {
            return DVec3::ZERO;
        };
        self.trace_camera_ray(ray, sampler, st)
    }

    /// The colour seen along camera ray `ray`.
    fn trace_camera_ray(&self, ray: Ray, sampler: &mut Sampler, st: &mut RenderStats) -> DVec3 {
        let world = self.world;
        st.rays.camera += 1;
        if self.settings.pass != Pass::Beauty {
            return passes::sample(world, &ray, self.settings.pass, self.max_depth);
        }
        let mut ctx = TraceCtx {
            sampler,
            stats: &mut st.rays,
            media: if world.tracks_interiors {
                media::MediaPath::at_camera(world)
            } else {
                media::MediaPath::default()
            },
            passes: 0,
            radiosity: self.radiosity,
            rad: radiosity::Local::default(),
            photons: self.photons,
            iors: self.camera_iors,
        };
        trace(world, &ray, 0.0, RayKind::Camera, 1, 1.0, &mut ctx)
    }

    fn sampler(&self, x: u32, y: u32, index: u32) -> Sampler {
        Sampler::new(self.settings.seed, self.settings.frame, x, y, index)
    }

    /// The ray through the centre of pixel (`x`, `y`): sample 0.
    fn centre(&self, x: u32, y: u32, st: &mut RenderStats) -> DVec3 {
        let mut s = self.sampler(x, y, 0);
        let at = (f64::from(x) + 0.5, f64::from(y) + 0.5);
        self.sample_at((x, y, 0), at, &mut s, st)
    }

    /// Mean of `n` stratified samples of pixel (`x`, `y`).
    fn fixed(&self, x: u32, y: u32, n: u32, st: &mut RenderStats) -> DVec3 {
        let mut sum = DVec3::ZERO;
        for k in 0..n {
            let mut s = self.sampler(x, y, k);
            let (u, v) = s.next_2d();
            sum += self.sample_at((x, y, k), (f64::from(x) + u, f64::from(y) + v), &mut s, st);
        }
        sum / f64::from(n)
    }

    /// POV-Ray's supersampled pixel: mean of the centre colour `centre` and the
    /// `depth²` jittered grid samples (sample indices 1 to `depth²`).
    fn supersample(
        &self,
        x: u32,
        y: u32,
        centre: DVec3,
        aa: &Antialias,
        st: &mut RenderStats,
    ) -> DVec3 {
        let n = aa.depth.max(1);
        let mut sum = centre;
        for k in 0..n * n {
            let mut s = self.sampler(x, y, k + 1);
            // A regular grid (`jitter 0`) draws nothing for the sub-pixel position.
            let jitter = if aa.jitter == 0.0 {
                (0.5, 0.5)
            } else {
                s.next_2d()
            };
            let (dx, dy) = aa.grid_offset(k, jitter);
            let at = (f64::from(x) + dx, f64::from(y) + dy);
            sum += self.sample_at((x, y, k + 1), at, &mut s, st);
        }
        sum / f64::from(n * n + 1)
    }

    /// The farthest first hit on a bounded object of the pixel-centre rays in
    /// `crop`, or on any object when no bounded one is seen (0 if none).
    fn farthest_hit(&self, crop: &Crop) -> f64 {
        let (bounded, any) = (crop.y0..crop.y1)
            .into_par_iter()
            .map(|y| {
                let (mut bounded, mut any): (f64, f64) = (0.0, 0.0);
                for x in crop.x0..crop.x1 {
                    let mut s = self.sampler(x, y, 0);
                    let (px, py) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
                    let ray = primary_ray(&self.world.camera, px, py, self.w, self.h, &mut s);
                    if let Some((t, b)) =
                        ray.and_then(|ray| passes::first_hit_distance(self.world, &ray))
                    {
                        any = any.max(t);
                        if b {
                            bounded = bounded.max(t);
                        }
                    }
                }
                (bounded, any)
            })
            .reduce(|| (0.0, 0.0), |a, b| (a.0.max(b.0), a.1.max(b.1)));
        if bounded > 0.0 {
            bounded
        } else {
            any
        }
    }
}

/// The working-space colour of pixel (`i`, `j`), `j = 0` at the top, from one ray
/// through its centre (radiosity and photons, which need their passes before
/// the render, left out).
pub fn render_pixel(world: &World, i: u32, j: u32, width: u32, height: u32) -> DVec3 {
    let settings = Settings::default();
    let r = Renderer {
        world,
        w: width,
        h: height,
        settings: &settings,
        max_depth: 0.0,
        blur_z: focal_blur::quantile(world.camera.confidence),
        radiosity: None,
        photons: None,
        camera_iors: ior::IorStack::at_camera(world),
    };
    r.centre(i, j, &mut RenderStats::default())
}
