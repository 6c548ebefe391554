//! One picture of a run: evaluate the scene at one or more instants (motion
//! blur), build with the mesh hierarchies kept from the previous frame, render,
//! average. Shared by stills and sequences.

use super::render::RenderArgs;
use super::{common, stats, EXIT_ERRORS};
use rts::output::{BitDepth, Gamma, OutputOptions};
use rts::render::{Progress, RenderOptions, Sampling, Settings};
use std::time::Instant;

/// One rendered image and what it took.
pub(crate) struct Image {
    /// The picture.
    pub film: rts::render::Film,
    /// Counters (of the last instant when several are averaged).
    pub stats: rts::render::RenderStats,
    /// Evaluating the scene.
    pub t_eval: std::time::Duration,
    /// Building the world.
    pub t_build: std::time::Duration,
    /// Tracing.
    pub t_render: std::time::Duration,
    /// `assumed_gamma` of the scene.
    pub assumed_gamma: Option<f64>,
    /// The scene turns gamma handling off (see [`rts::scene::GlobalSettings::gamma_off`]).
    pub gamma_off: bool,
    /// Top-level objects.
    pub objects: usize,
    /// Light sources.
    pub lights: usize,
}

/// What every image of a run shares: settings, threads and the mesh hierarchies
/// kept from frame to frame.
pub(crate) struct Renderer<'a> {
    /// The command line.
    pub args: &'a RenderArgs,
    /// Sampling, crop, pass, seed.
    pub settings: Settings,
    /// Image size (after --preview).
    pub width: u32,
    /// Image height.
    pub height: u32,
    pool: Option<rayon::ThreadPool>,
    build_cache: rts::build::BuildCache,
    /// Whether to draw the per-image progress bar.
    pub show_progress: bool,
    /// Prints each evaluation's diagnostics (a message once for all frames).
    pub messages: common::Messages,
    /// Whether the frames are a sequence's (their messages say which frame).
    pub sequence: bool,
}

impl<'a> Renderer<'a> {
    /// A renderer for `args` (size after --preview) on `pool` (the global one if
    /// `None`).
    pub fn new(
        args: &'a RenderArgs,
        settings: Settings,
        (width, height): (u32, u32),
        pool: Option<rayon::ThreadPool>,
    ) -> Renderer<'a> {
        Renderer {
            args,
            settings,
            width,
            height,
            pool,
            build_cache: rts::build::BuildCache::default(),
            show_progress: !args.quiet && stats::stderr_is_terminal(),
            messages: common::Messages::new(args.scene.message_format, args.quiet),
            sequence: false,
        }
    }

    /// Worker threads.
    pub fn threads(&self) -> usize {
        self.pool
            .as_ref()
            .map_or_else(rayon::current_num_threads, |p| p.current_num_threads())
    }

    /// Evaluates the scene at every instant (reusing `first` for the first when
    /// given), builds and renders each, and averages the pictures. `Err` is the
    /// exit status after the diagnostics were printed.
    pub fn image(
        &mut self,
        parsed: &mut common::Parsed,
        instants: &[rts::eval::EvalOptions],
        mut first: Option<rts::scene::Scene>,
        frame: u32,
    ) -> Result<Image, i32> {
        let mut out: Option<Image> = None;
        // Motion blur: the sum of the instants' pictures.
        let mut sum: Option<Vec<glam::DVec3>> = None;
        let n = instants.len().max(1);
        for (j, options) in instants.iter().enumerate() {
            let t0 = Instant::now();
            let scene = match first.take() {
                Some(s) => s,
                None => {
                    let (scene, diags) = parsed.eval(options);
                    let failed = rts::diag::has_errors(&diags) || scene.is_none();
                    let label = self.sequence.then_some(frame);
                    self.messages.print(&diags, &parsed.sources, label);
                    if failed {
                        return Err(EXIT_ERRORS);
                    }
                    scene.ok_or(EXIT_ERRORS)?
                }
            };
            let t_eval = t0.elapsed();
            // Motion blur: each instant takes its share of the samples, with its
            // own sample positions (another seed), so the average is one picture
            // with `--samples` rays per pixel spread over the shutter.
            let mut settings = Settings {
                frame,
                ..self.settings
            };
            if n > 1 {
                settings.seed = settings
                    .seed
                    .wrapping_add((j as u64 + 1).wrapping_mul(0x9e37_79b9_7f4a_7c15));
                if let Sampling::Fixed(s) = settings.sampling {
                    settings.sampling = Sampling::Fixed(s.div_ceil(n as u32).max(1));
                }
            }
            let (width, height, show) = (self.width, self.height, self.show_progress);
            let args = self.args;
            let cache = &mut self.build_cache;
            let mut job = || {
                let t1 = Instant::now();
                let world = rts::build::build_cached(&scene, cache);
                let t_build = t1.elapsed();
                let t2 = Instant::now();
                let progress = Progress::default();
                let done = std::sync::atomic::AtomicBool::new(false);
                let rendered = std::thread::scope(|s| {
                    if show {
                        s.spawn(|| stats::progress_bar(&progress, &done));
                    }
                    let r = super::path_opts::render_frame(
                        args,
                        &scene,
                        &world,
                        &RenderOptions { width, height },
                        &settings,
                        n,
                        &progress,
                    );
                    done.store(true, std::sync::atomic::Ordering::Relaxed);
                    r
                });
                (rendered, t_build, t2.elapsed(), world.global.assumed_gamma)
            };
            let gamma_off = scene.global.gamma_off;
            let (rendered, t_build, t_render, assumed_gamma) = match &self.pool {
                Some(pool) => pool.install(job),
                None => job(),
            };
            // POV-Ray's warning after a render: an isosurface steeper than
            // its max_gradient.
            let warned = parsed.slope_warnings();
            self.messages
                .print(&warned, &parsed.sources, self.sequence.then_some(frame));
            match &mut out {
                None => {
                    out = Some(Image {
                        film: rendered.film,
                        stats: rendered.stats,
                        t_eval,
                        t_build,
                        t_render,
                        assumed_gamma,
                        gamma_off,
                        objects: scene.objects.len(),
                        lights: scene.lights.len(),
                    })
                }
                Some(img) => {
                    // The instants are summed in double precision.
                    let sum = sum.get_or_insert_with(|| {
                        img.film.pixels.iter().map(|p| p.as_dvec3()).collect()
                    });
                    for (a, b) in sum.iter_mut().zip(&rendered.film.pixels) {
                        *a += b.as_dvec3();
                    }
                    img.stats = rendered.stats;
                    img.t_eval += t_eval;
                    img.t_build += t_build;
                    img.t_render += t_render;
                }
            }
        }
        let mut img = out.ok_or(EXIT_ERRORS)?;
        if let Some(sum) = sum {
            let k = 1.0 / n as f64;
            for (p, s) in img.film.pixels.iter_mut().zip(sum) {
                *p = (s * k).as_vec3();
            }
        }
        Ok(img)
    }

    /// File encoding options for this run.
    /// `gamma_off`: the scene turns gamma handling off, so without `--gamma` the
    /// working values are written as they are.
    pub fn output_options(&self, assumed_gamma: Option<f64>, gamma_off: bool) -> OutputOptions {
        let data = self.settings.pass.is_data();
        OutputOptions {
            gamma: match self.args.gamma {
                _ if data => Gamma::Power(1.0),
                Some(g) => g,
                None if gamma_off => Gamma::Power(1.0),
                None => Gamma::Srgb,
            },
            bit_depth: if self.args.bit_depth == 16 {
                BitDepth::Sixteen
            } else {
                BitDepth::Eight
            },
            assumed_gamma: if data { None } else { assumed_gamma },
        }
    }
}
