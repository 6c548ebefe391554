//! Rendering a [`World`] into a [`Film`] of working-space colours.
//!
//! Every pixel is computed independently from one ray through its centre, so the
//! result does not depend on the number of threads.

mod atmosphere;
mod camera;
mod film;
mod lights;
mod pigment;
mod sampler;
mod shade;
mod stats;

pub use atmosphere::{apply_fog, sky};
pub use camera::primary_ray;
pub use film::Film;
pub use lights::{cylinder_attenuation, fade, incident, shadow, spot_attenuation, Incident};
pub use pigment::{checker_index, evaluate as evaluate_pigment, CHECKER_OFFSET};
pub use sampler::Sampler;
pub use shade::{metallic_tint, metallic_weight, reflection_amount, trace, TraceCtx};
pub use stats::RayStats;

use crate::build::{RayKind, World};
use glam::DVec3;
use rayon::prelude::*;

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

/// Renders `world` with rayon, one row per task.
pub fn render(world: &World, opts: &RenderOptions) -> Film {
    let (w, h) = (opts.width, opts.height);
    let mut pixels = vec![DVec3::ZERO; w as usize * h as usize];
    if w > 0 {
        pixels
            .par_chunks_mut(w as usize)
            .enumerate()
            .for_each(|(j, row)| {
                for (i, px) in row.iter_mut().enumerate() {
                    *px = render_pixel(world, i as u32, j as u32, w, h);
                }
            });
    }
    Film {
        width: w,
        height: h,
        pixels,
    }
}

/// The working-space colour of pixel (`i`, `j`), `j = 0` at the top.
pub fn render_pixel(world: &World, i: u32, j: u32, width: u32, height: u32) -> DVec3 {
    // A depth-of-field camera averages `blur_samples` lens samples per pixel.
    let cam = &world.camera;
    if cam.aperture > 0.0 && cam.blur_samples > 1 {
        let n = cam.blur_samples;
        let sum: DVec3 = (0..n)
            .map(|s| sample_pixel(world, i, j, s, width, height))
            .sum();
        return sum / f64::from(n);
    }
    sample_pixel(world, i, j, 0, width, height)
}

/// Sample `index` of pixel (`i`, `j`), through the pixel centre.
fn sample_pixel(world: &World, i: u32, j: u32, index: u32, width: u32, height: u32) -> DVec3 {
    let mut sampler = Sampler::new(0, 0, i, j, index);
    let mut stats = RayStats::default();
    let mut ctx = TraceCtx {
        sampler: &mut sampler,
        stats: &mut stats,
    };
    let (x, y) = (f64::from(i) + 0.5, f64::from(j) + 0.5);
    let Some(ray) = primary_ray(&world.camera, x, y, width, height, ctx.sampler) else {
        return DVec3::ZERO;
    };
    ctx.stats.camera += 1;
    trace(world, &ray, 0.0, RayKind::Camera, 1, 1.0, &mut ctx)
}
