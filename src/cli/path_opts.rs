//! `rts render` options of the path tracer (`--integrator path`, `--spp`,
//! `--time-limit`, `--resume`, `--aov`, …) and the progressive render loop that
//! writes partial images and checkpoints. See docs/pathtracing.md.

use super::render::RenderArgs;
use super::stats;
use super::{EXIT_ERRORS, EXIT_OK, EXIT_USAGE};
use rts::output::{BitDepth, Format, Gamma, OutputOptions};
use rts::render::path::{checkpoint, render_samples, resolve_crop, Accum, PathOptions, PathScene};
use rts::render::{Film, Progress, RenderOptions, RenderStats, Sampling, Settings};
use rts::scene::{PathTracing, PixelFilter, Scene};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Whether `scene` has media (atmospheric, or in any object's interior).
fn has_media(scene: &Scene) -> bool {
    fn object(o: &rts::scene::Object) -> bool {
        o.interior.as_ref().is_some_and(|i| !i.media.is_empty())
            || match &o.shape {
                rts::scene::Shape::Union { children } | rts::scene::Shape::Csg { children, .. } => {
                    children.iter().any(object)
                }
                _ => false,
            }
    }
    !scene.atmosphere.media.is_empty() || scene.objects.iter().any(object)
}

/// Most samples per pixel (the period of the per-pixel Sobol sequence).
const MAX_SPP: u32 = 1 << 16;

/// Which renderer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Integrator {
    /// POV-Ray's classic model (the default unless the scene has `path_tracing`).
    Classic,
    /// The Monte Carlo path tracer.
    Path,
}

/// `--aov` names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum AovName {
    /// The pigment colour at the first hit.
    Albedo,
    /// The surface normal at the first hit.
    Normal,
}

/// `--pixel-filter` names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum FilterName {
    /// Uniform over the pixel.
    Box,
    /// Gaussian, σ 0.5 pixel, cut at 1.5.
    Gaussian,
}

/// The path tracer's options of `rts render`.
#[derive(Debug, Clone, clap::Args)]
pub struct PathArgs {
    /// Renderer: `classic` or `path` (default: `path` when the scene's
    /// global_settings has `path_tracing { }`, else `classic`).
    #[arg(
        help_heading = "Path tracer (--integrator path)",
        long,
        value_enum,
        value_name = "NAME"
    )]
    pub integrator: Option<Integrator>,
    /// Path tracer: samples per pixel in total (default: the scene's `samples`, else 64).
    #[arg(
        help_heading = "Path tracer (--integrator path)",
        long,
        value_name = "N"
    )]
    pub spp: Option<u32>,
    /// Path tracer: stop adding samples after this long (`90`, `90s`, `2m`, `1h`);
    /// with --spp, whichever comes first.
    #[arg(
        help_heading = "Path tracer (--integrator path)",
        long,
        value_name = "DURATION",
        value_parser = parse_duration
    )]
    pub time_limit: Option<Duration>,
    /// Path tracer: longest path in segments, counting the camera ray.
    #[arg(
        help_heading = "Path tracer (--integrator path)",
        long,
        value_name = "N"
    )]
    pub max_depth: Option<u32>,
    /// Path tracer: largest channel value one sample may add (firefly clamp; 0 off).
    #[arg(
        help_heading = "Path tracer (--integrator path)",
        long,
        value_name = "X"
    )]
    pub clamp: Option<f64>,
    /// Path tracer: reconstruction filter.
    #[arg(
        help_heading = "Path tracer (--integrator path)",
        long,
        value_enum,
        value_name = "NAME"
    )]
    pub pixel_filter: Option<FilterName>,
    /// Path tracer: continue from the checkpoint (see --checkpoint) up to the new
    /// --spp / --time-limit; the result equals an uninterrupted render.
    #[arg(help_heading = "Path tracer (--integrator path)", long)]
    pub resume: bool,
    /// Path tracer: checkpoint file (default OUT.ckpt), written with every partial
    /// image when --time-limit, --resume or this option is given.
    #[arg(
        help_heading = "Path tracer (--integrator path)",
        long,
        value_name = "FILE"
    )]
    pub checkpoint: Option<PathBuf>,
    /// Path tracer: seconds between partial images (and checkpoints) [default: 10].
    #[arg(
        help_heading = "Path tracer (--integrator path)",
        long,
        value_name = "SECONDS"
    )]
    pub save_every: Option<f64>,
    /// Path tracer: also write first-hit AOVs as EXR next to the output
    /// (`albedo`, `normal`, comma-separated): OUT.albedo.exr, OUT.normal.exr.
    #[arg(
        help_heading = "Path tracer (--integrator path)",
        long,
        value_name = "LIST",
        value_enum,
        value_delimiter = ','
    )]
    pub aov: Vec<AovName>,
    /// Path tracer: denoise with Intel Open Image Denoise (needs the `oidn` cargo
    /// feature and the library; uses the albedo and normal AOVs).
    #[arg(help_heading = "Path tracer (--integrator path)", long)]
    pub denoise: bool,
}

/// `90`, `90s`, `1.5m`, `2h` as a duration (checked when the command line is
/// read, whichever renderer runs).
pub fn parse_duration(s: &str) -> Result<Duration, String> {
    let t = s.trim();
    let (num, unit) = match t.find(|c: char| c.is_ascii_alphabetic()) {
        Some(i) => (&t[..i], &t[i..]),
        None => (t, "s"),
    };
    let n: f64 = num
        .trim()
        .parse()
        .map_err(|_| "expected a duration such as 60s, 2m or 1h".to_string())?;
    let k = match unit {
        "s" => 1.0,
        "m" | "min" => 60.0,
        "h" => 3600.0,
        _ => {
            return Err(format!(
                "`{unit}` is not a unit: use s, m or h (e.g. 60s, 2m, 1h)"
            ))
        }
    };
    if !(n.is_finite() && n > 0.0 && n * k < 1e9) {
        return Err("must be a positive duration (e.g. 60s, 2m, 1h)".into());
    }
    Ok(Duration::from_secs_f64(n * k))
}

/// The resolved plan of a path traced render.
struct Plan {
    popts: PathOptions,
    spp: u32,
    limit: Option<Duration>,
    checkpoint: Option<PathBuf>,
    aov_albedo: bool,
    aov_normal: bool,
    save_every: f64,
}

fn plan(p: &PathArgs, scene_pt: Option<&PathTracing>, output: &Path) -> Result<Plan, String> {
    let base = scene_pt.copied().unwrap_or_default();
    let mut popts = PathOptions::from(&base);
    if let Some(d) = p.max_depth {
        if d == 0 {
            return Err("--max-depth must be at least 1".into());
        }
        popts.max_depth = d;
    }
    if let Some(c) = p.clamp {
        if !(c.is_finite() && c >= 0.0) {
            return Err(format!("--clamp {c}: must be 0 (off) or positive"));
        }
        popts.clamp = c;
    }
    if let Some(f) = p.pixel_filter {
        popts.filter = match f {
            FilterName::Box => PixelFilter::Box,
            FilterName::Gaussian => PixelFilter::Gaussian,
        };
    }
    let limit = p.time_limit;
    let spp = match (p.spp, limit) {
        (Some(0), _) => return Err("--spp must be at least 1".into()),
        (Some(n), _) if n > MAX_SPP => {
            return Err(format!("--spp {n}: at most {MAX_SPP} samples per pixel"))
        }
        (Some(n), _) => n,
        (None, Some(_)) => MAX_SPP,
        (None, None) => base.samples,
    };
    let save_every = p.save_every.unwrap_or(10.0);
    if !(save_every.is_finite() && save_every > 0.0) {
        return Err("--save-every must be a positive number of seconds".into());
    }
    // Beside a streamed picture (`-o -`, a FIFO, /dev/null) there is no file to
    // put OUT.ckpt or OUT.albedo.exr next to.
    let streamed = super::outputs::is_stream(output);
    let (mut aov_albedo, mut aov_normal) = (false, false);
    for a in &p.aov {
        match a {
            AovName::Albedo => aov_albedo = true,
            AovName::Normal => aov_normal = true,
        }
    }
    if (aov_albedo || aov_normal) && streamed {
        return Err(format!(
            "--aov writes OUT.albedo.exr and OUT.normal.exr beside the picture; `{}` is not a file: give -o FILE",
            output.display()
        ));
    }
    let checkpoint = match &p.checkpoint {
        Some(c) => Some(c.clone()),
        None if streamed && p.resume => {
            return Err(format!(
                "--resume: `{}` is not a file to find OUT.ckpt beside; give --checkpoint FILE",
                output.display()
            ))
        }
        // A time-limited render into a stream keeps no checkpoint unless asked.
        None if streamed => None,
        None if p.resume || limit.is_some() => {
            let mut s = output.as_os_str().to_owned();
            s.push(".ckpt");
            Some(PathBuf::from(s))
        }
        None => None,
    };
    Ok(Plan {
        popts,
        spp,
        limit,
        checkpoint,
        aov_albedo,
        aov_normal,
        save_every,
    })
}

/// The path tracer options that change pixels, as text for a manifest's key
/// (with whether the path tracer renders at all).
pub fn key_text(args: &RenderArgs, path_traced: bool) -> String {
    let p = &args.path;
    format!(
        "path_traced {path_traced} spp {:?} samples {:?} max_depth {:?} clamp {:?} pixel_filter {:?}",
        p.spp, args.samples, p.max_depth, p.clamp, p.pixel_filter
    )
}

/// `OUT` with `.NAME.exr` in place of its extension.
fn aov_path(output: &Path, name: &str) -> PathBuf {
    output.with_extension(format!("{name}.exr"))
}

/// Whether the path tracer renders this scene.
pub fn wanted(args: &RenderArgs, scene: &Scene) -> bool {
    match args.path.integrator {
        Some(Integrator::Path) => true,
        Some(Integrator::Classic) => false,
        None => scene.global.path_tracing.is_some(),
    }
}

/// Renders `scene` with the path tracer when it or the options ask for it; `None`
/// leaves the render to the classic renderer.
pub fn run(
    args: &RenderArgs,
    scene: &Scene,
    (width, height): (u32, u32),
    output: &Path,
    format: Format,
    settings: &Settings,
    t_start: Instant,
    t_parse: Duration,
) -> Option<i32> {
    if !wanted(args, scene) {
        return None;
    }
    let fail = |msg: String| {
        eprintln!("error: {msg}");
        Some(EXIT_USAGE)
    };
    if !matches!(settings.pass, rts::render::Pass::Beauty) {
        return fail("--pass is for the classic renderer; the path tracer writes AOVs with --aov albedo,normal".into());
    }
    if args.antialias.is_some() {
        return fail("--antialias is for the classic renderer; the path tracer takes --spp".into());
    }
    if has_media(scene) {
        // Once per render: the path tracer has no participating media yet.
        eprintln!(
            "warning[{}]: the path tracer ignores media: this scene's `media` is not rendered \
             (render with --integrator classic to see it)",
            rts::diag::codes::MEDIA_IGNORED
        );
    }
    let mut p = args.path.clone();
    if p.spp.is_none() {
        p.spp = args.samples;
    }
    let plan = match plan(&p, scene.global.path_tracing.as_ref(), output) {
        Ok(x) => x,
        Err(e) => return fail(e),
    };
    // Checked (a FIFO or device refused, the folder made) before rendering.
    if let Some(c) = &plan.checkpoint {
        if let Err(e) = super::outputs::prepare(c, rts::files::Policy::FileOnly, "the checkpoint") {
            eprintln!("error: {e}");
            return Some(EXIT_ERRORS);
        }
    }
    if p.denoise && !cfg!(feature = "oidn") {
        return fail("--denoise needs rts built with `--features oidn` (and Intel Open Image Denoise installed); see docs/pathtracing.md".into());
    }
    let opts = RenderOptions { width, height };
    let out = OutputOptions {
        // Physically based output is always display-encoded.
        gamma: args.gamma.unwrap_or(Gamma::Srgb),
        bit_depth: if args.bit_depth == 16 {
            BitDepth::Sixteen
        } else {
            BitDepth::Eight
        },
        assumed_gamma: scene.global.assumed_gamma,
    };
    let crop = resolve_crop(settings, opts.width, opts.height);
    let mut fp_text =
        rts::files::read_regular(&args.scene_file, args.scene.max_source_size).unwrap_or_default();
    fp_text.extend(format!("{:?}{:?}", args.scene.define, args.scene.clock).bytes());
    let key = checkpoint::Key::new(
        &opts,
        settings,
        crop,
        &plan.popts,
        checkpoint::fingerprint(&fp_text),
    );
    let accum = if p.resume {
        let path = plan.checkpoint.as_deref().expect("resume has a checkpoint");
        match checkpoint::load(path, &key) {
            Ok(a) => a,
            Err(e) => {
                eprintln!("error: {e}");
                return Some(EXIT_ERRORS);
            }
        }
    } else {
        Accum::new(crop)
    };
    let show_progress = !args.quiet && stats::stderr_is_terminal();
    // A partial picture is not written into a stream (a reader of `-o -` gets
    // one picture), only the checkpoint.
    let streamed = super::outputs::is_stream(output);
    let write_all = |accum: &Accum, denoise: bool, partial: bool| -> Result<(), String> {
        if !(partial && streamed) {
            let mut film = accum.film();
            if denoise {
                film = denoise_film(&film, &accum.albedo_film(), &accum.normal_film())?;
            }
            rts::output::write_as(&film, output, format, &out).map_err(|e| e.to_string())?;
        }
        let linear = OutputOptions {
            gamma: Gamma::Power(1.0),
            bit_depth: BitDepth::Eight,
            assumed_gamma: None,
        };
        if plan.aov_albedo {
            let path = aov_path(output, "albedo");
            rts::output::write_as(&accum.albedo_film(), &path, Format::Exr, &out)
                .map_err(|e| e.to_string())?;
        }
        if plan.aov_normal {
            let path = aov_path(output, "normal");
            rts::output::write_as(&accum.normal_film(), &path, Format::Exr, &linear)
                .map_err(|e| e.to_string())?;
        }
        if let Some(c) = &plan.checkpoint {
            checkpoint::save(c, &key, accum)
                .map_err(|e| format!("cannot write checkpoint `{}`: {e}", c.display()))?;
        }
        Ok(())
    };
    let accum = std::sync::Mutex::new(accum);
    let progress = Progress::default();
    let rows = u64::from(crop.y1 - crop.y0);
    let job = || -> Result<(RenderStats, Duration, Duration, usize), String> {
        let t1 = Instant::now();
        let world = rts::build::build(scene);
        let sc = PathScene::new(&world, plan.popts.max_depth);
        let t_build = t1.elapsed();
        let t2 = Instant::now();
        let done = AtomicBool::new(false);
        let total = std::thread::scope(|s| -> Result<RenderStats, String> {
            if show_progress {
                s.spawn(|| stats::progress_bar(&progress, &done));
            }
            let mut accum = accum
                .lock()
                .map_err(|_| "render thread failed".to_string())?;
            let r = progressive(
                &sc, &opts, settings, &plan, &mut accum, rows, &progress, &write_all, t2,
            );
            done.store(true, Ordering::Relaxed);
            r
        })?;
        Ok((total, t_build, t2.elapsed(), rayon::current_num_threads()))
    };
    let result = match args.threads {
        Some(n) => match super::thread_pool(n) {
            Ok(pool) => pool.install(job),
            Err(e) => Err(format!("cannot start {n} threads: {e}")),
        },
        None => job(),
    };
    let (rstats, t_build, t_render, threads) = match result {
        Ok(x) => x,
        Err(e) => {
            eprintln!("error: {e}");
            return Some(EXIT_ERRORS);
        }
    };
    let accum = match accum.into_inner() {
        Ok(a) => a,
        Err(_) => return Some(EXIT_ERRORS),
    };
    let t3 = Instant::now();
    if let Err(e) = write_all(&accum, p.denoise, false) {
        eprintln!("error: {e}");
        return Some(EXIT_ERRORS);
    }
    let shown = Settings {
        sampling: Sampling::Fixed(accum.samples),
        ..*settings
    };
    let report = stats::Report {
        output,
        format,
        width,
        height,
        settings: &shown,
        threads,
        objects: scene.objects.len(),
        lights: scene.lights.len(),
        stats: rstats,
        times: stats::Times {
            parse_eval: t_parse,
            build: t_build,
            render: t_render,
            write: t3.elapsed(),
            total: t_start.elapsed(),
        },
        peak_memory: stats::peak_memory_bytes(),
    };
    if !args.quiet {
        eprint!(
            "path tracer: {} samples per pixel, {:.0} samples/s; ",
            accum.samples,
            rstats.samples as f64 / t_render.as_secs_f64().max(1e-9)
        );
        eprint!("{}", report.human());
    }
    if let Some(path) = &args.stats_json {
        let mut j = report.json();
        j["integrator"] = "path".into();
        j["samples_per_second"] = (rstats.samples as f64 / t_render.as_secs_f64().max(1e-9)).into();
        if let Err(code) = stats::write_json(path, &j) {
            return Some(code);
        }
    }
    Some(EXIT_OK)
}

/// One picture of a sequence or one instant of motion blur (`instants` of them
/// share the samples): the path tracer when it is wanted, else the classic
/// renderer. Sequences get no checkpoints or AOVs.
pub fn render_frame(
    args: &RenderArgs,
    scene: &Scene,
    world: &rts::build::World,
    opts: &RenderOptions,
    settings: &Settings,
    instants: usize,
    progress: &Progress,
) -> rts::render::Rendered {
    if !wanted(args, scene) {
        return rts::render::render_with(world, opts, settings, Some(progress));
    }
    let base = scene.global.path_tracing.unwrap_or_default();
    let mut p = args.path.clone();
    if p.spp.is_none() {
        p.spp = args.samples;
    }
    let (popts, spp) = match plan(&p, Some(&base), Path::new("frame")) {
        Ok(pl) => (pl.popts, pl.spp.min(MAX_SPP)),
        Err(_) => (PathOptions::from(&base), base.samples),
    };
    let spp = spp.div_ceil(instants.max(1) as u32).max(1);
    let sc = PathScene::new(world, popts.max_depth);
    let mut acc = Accum::new(resolve_crop(settings, opts.width, opts.height));
    let rows = u64::from(acc.crop.y1 - acc.crop.y0);
    progress
        .total
        .store(rows * u64::from(spp), Ordering::Relaxed);
    progress.done.store(0, Ordering::Relaxed);
    let stats = render_samples(&sc, opts, settings, &popts, &mut acc, spp, Some(progress));
    rts::render::Rendered {
        film: acc.film(),
        stats,
    }
}

/// Adds samples pass by pass until the plan's total or time limit, writing the
/// partial picture (and checkpoint) every `save_every` seconds.
fn progressive(
    sc: &PathScene,
    opts: &RenderOptions,
    settings: &Settings,
    plan: &Plan,
    accum: &mut Accum,
    rows: u64,
    progress: &Progress,
    write_all: &dyn Fn(&Accum, bool, bool) -> Result<(), String>,
    started: Instant,
) -> Result<RenderStats, String> {
    let mut total = RenderStats::default();
    let save_every = Duration::from_secs_f64(plan.save_every);
    let mut last_save = Instant::now();
    let start_samples = accum.samples;
    let target = plan.spp;
    progress.done.store(0, Ordering::Relaxed);
    let known_total = plan.limit.is_none();
    if known_total {
        progress.total.store(
            u64::from(target.saturating_sub(start_samples)) * rows,
            Ordering::Relaxed,
        );
    }
    let mut pass = 1u32;
    while accum.samples < target {
        let elapsed = started.elapsed();
        let done_now = accum.samples - start_samples;
        if let Some(limit) = plan.limit {
            if elapsed >= limit {
                break;
            }
            // Fit the next pass in what is left of the budget.
            if done_now > 0 {
                let per = elapsed.as_secs_f64() / f64::from(done_now);
                let left = (limit - elapsed).as_secs_f64();
                let fit = (left / per).floor();
                if fit < 1.0 {
                    break;
                }
                pass = pass.min(fit as u32).max(1);
            }
            // Progress against the samples the budget is expected to allow.
            let expected = if done_now > 0 {
                f64::from(done_now) * limit.as_secs_f64() / elapsed.as_secs_f64().max(1e-9)
            } else {
                f64::from(pass)
            };
            progress
                .total
                .store(rows * (expected.max(1.0) as u64), Ordering::Relaxed);
        }
        let n = pass.min(target - accum.samples);
        total += render_samples(sc, opts, settings, &plan.popts, accum, n, Some(progress));
        if last_save.elapsed() >= save_every && accum.samples < target {
            write_all(accum, false, true)?;
            last_save = Instant::now();
        }
        pass = (pass * 2).min(64);
    }
    Ok(total)
}

/// Denoises `film` with Intel Open Image Denoise (feature `oidn`).
#[cfg(feature = "oidn")]
fn denoise_film(film: &Film, albedo: &Film, normal: &Film) -> Result<Film, String> {
    let flat = |f: &Film| -> Vec<f32> { f.pixels.iter().flat_map(|p| p.to_array()).collect() };
    let (colour, alb, nrm) = (flat(film), flat(albedo), flat(normal));
    let mut outv = vec![0f32; colour.len()];
    let device =
        oidn::Device::new().map_err(|e| format!("cannot start Open Image Denoise: {e:?}"))?;
    let mut filter = oidn::RayTracing::try_new(&device)
        .map_err(|e| format!("cannot make the denoising filter: {e:?}"))?;
    filter
        .srgb(false)
        .hdr(true)
        .image_dimensions(film.width as usize, film.height as usize)
        .albedo_normal(&alb, &nrm);
    filter
        .filter(&colour, &mut outv)
        .map_err(|e| format!("denoising failed: {e:?}"))?;
    if let Err(e) = device.get_error() {
        return Err(format!("denoising failed: {e:?}"));
    }
    Ok(Film {
        width: film.width,
        height: film.height,
        pixels: outv
            .chunks_exact(3)
            .map(|c| glam::Vec3::new(c[0], c[1], c[2]))
            .collect(),
    })
}

/// Without the `oidn` feature there is no denoiser (the caller refuses `--denoise`).
#[cfg(not(feature = "oidn"))]
fn denoise_film(film: &Film, _albedo: &Film, _normal: &Film) -> Result<Film, String> {
    Ok(film.clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations() {
        assert_eq!(parse_duration("90").unwrap(), Duration::from_secs(90));
        assert_eq!(parse_duration("2m").unwrap(), Duration::from_secs(120));
        assert_eq!(parse_duration("0.5s").unwrap(), Duration::from_millis(500));
        assert!(parse_duration("5 parsecs").is_err());
        assert!(parse_duration("-1s").is_err());
    }
}
