//! `rts render SCENE [-o OUT] [options]`: see docs/cli.md for every option.

use super::frame::Renderer;
use super::{
    common, interrupt, outputs, sequence, stats, MessageFormat, SceneArgs, EXIT_ERRORS, EXIT_OK,
    EXIT_USAGE,
};
use rts::output::{Format, Gamma};
use rts::render::{Antialias, Crop, Pass, Sampling, Settings};
use std::path::PathBuf;
use std::time::Instant;

/// Most pixels in one image (8192 × 8192).
const MAX_PIXELS: u64 = 1 << 26;

/// Most samples per pixel for `--samples`.
const MAX_SAMPLES: u32 = 1 << 16;

/// `--pass` names.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum PassName {
    /// The shaded picture.
    #[default]
    Beauty,
    /// Distance to the first hit as grey (white near, black at --depth-max).
    Depth,
    /// Surface normal as colour (n * 0.5 + 0.5).
    Normal,
    /// Pigment colour before lighting.
    Albedo,
}

/// Arguments of `rts render`.
#[derive(Debug, clap::Args)]
pub struct RenderArgs {
    /// The scene file.
    #[arg(value_name = "SCENE")]
    pub scene_file: PathBuf,
    /// Output image; its extension (.png, .ppm, .exr, .hdr) picks the format unless
    /// --format is given. Defaults to the scene's name in the current folder. `-`
    /// writes the image to standard output; a FIFO or device (`/dev/null`) is
    /// written directly (PNG unless --format says otherwise).
    #[arg(
        help_heading = "Output",
        short = 'o',
        long = "output",
        value_name = "OUT"
    )]
    pub output: Option<PathBuf>,
    /// Output format: png, ppm, exr or hdr (overrides the extension).
    #[arg(help_heading = "Output", long, value_name = "FORMAT")]
    pub format: Option<Format>,
    /// Image width in pixels.
    #[arg(
        help_heading = "Output",
        short = 'W',
        long = "width",
        default_value_t = 800
    )]
    pub width: u32,
    /// Image height in pixels.
    #[arg(
        help_heading = "Output",
        short = 'H',
        long = "height",
        default_value_t = 600
    )]
    pub height: u32,
    /// The file's gamma: `srgb` (POV-Ray 3.7's default) or a number (`1.0` writes linear
    /// values). Without it, a scene with neither `assumed_gamma` nor `#version 3.7` is
    /// written as POV-Ray does, with gamma handling off.
    #[arg(help_heading = "Output", long, value_name = "srgb|G")]
    pub gamma: Option<Gamma>,
    /// Bits per channel in PNG and PPM files.
    #[arg(help_heading = "Output", long, value_name = "8|16", default_value_t = 8, value_parser = clap::value_parser!(u8).range(8..=16))]
    pub bit_depth: u8,
    /// Adaptive anti-aliasing like POV-Ray's +A (method 1): supersample pixels whose
    /// colour differs from a neighbour's by at least THRESHOLD (POV-Ray's default 0.3).
    #[arg(help_heading = "Sampling", long, value_name = "THRESHOLD")]
    pub antialias: Option<f64>,
    /// Anti-aliasing grid per side, 1 to 9 (POV-Ray's +R; 3 takes 3×3 more rays)
    /// [default: 3].
    #[arg(help_heading = "Sampling", long, value_name = "N")]
    pub aa_depth: Option<u32>,
    /// Anti-aliasing jitter, 0 (regular grid) to 1 (POV-Ray's +J, on with 1.0 by default).
    #[arg(help_heading = "Sampling", long, value_name = "AMOUNT")]
    pub jitter: Option<f64>,
    /// Gamma applied to colours before the anti-aliasing comparison (POV-Ray's
    /// Antialias_Gamma) [default: 2.5].
    #[arg(help_heading = "Sampling", long, value_name = "G")]
    pub aa_gamma: Option<f64>,
    /// Take N stratified samples in every pixel and average them (instead of --antialias).
    #[arg(help_heading = "Sampling", long, value_name = "N")]
    pub samples: Option<u32>,
    /// Seed of every random number (jitter, sample positions).
    #[arg(help_heading = "Sampling", long, value_name = "N", default_value_t = 0)]
    pub seed: u64,
    /// Render frame N of the timeline as a still (its clock, frame_number and
    /// random numbers); a `#` run in -o becomes the frame number.
    #[arg(
        help_heading = "Animation",
        long,
        value_name = "N",
        allow_negative_numbers = true
    )]
    pub frame: Option<i64>,
    /// Frames to render, `A..B` (both included): a part of the scene's
    /// `animation { }` timeline, or the timeline itself (clock 0 to 1) when the
    /// scene has none.
    #[arg(help_heading = "Animation", long, value_name = "A..B", value_parser = super::sequence::parse_range)]
    pub frames: Option<(i64, i64)>,
    /// Frames per second (overrides the scene's `animation { fps }`; default 24).
    #[arg(help_heading = "Animation", long, value_name = "F")]
    pub fps: Option<f64>,
    /// Cyclic animation (POV-Ray's +KC): the last frame stops one step before the
    /// first comes round again.
    #[arg(help_heading = "Animation", long)]
    pub cyclic: bool,
    /// Re-render every frame of a sequence, even those already complete.
    #[arg(help_heading = "Animation", long)]
    pub force: bool,
    /// Render only part I of N (I from 1 to N), so N machines together render
    /// everything once: of a sequence, frames dealt out in turn; of a still, row
    /// band I, written to OUT-stem.part-I-of-N.EXT for `rts merge`.
    #[arg(help_heading = "Animation", long, value_name = "I/N")]
    pub shard: Option<String>,
    /// After a sequence, assemble its frames into an animated GIF.
    #[arg(help_heading = "Animation", long, value_name = "OUT.gif")]
    pub gif: Option<PathBuf>,
    /// After a sequence, assemble its frames into an animated PNG.
    #[arg(help_heading = "Animation", long, value_name = "OUT.png")]
    pub apng: Option<PathBuf>,
    /// After a sequence, assemble its frames into an MP4 with ffmpeg (when installed).
    #[arg(help_heading = "Animation", long, value_name = "OUT.mp4")]
    pub mp4: Option<PathBuf>,
    /// Quick look: half the width and height, one ray per pixel, no motion blur.
    #[arg(help_heading = "Animation", long)]
    pub preview: bool,
    /// Motion blur: keep the shutter open for this fraction of a frame (0 to 1),
    /// averaging the scene at several instants (overrides `animation { motion_blur }`).
    #[arg(help_heading = "Animation", long, value_name = "SHUTTER")]
    pub motion_blur: Option<f64>,
    /// Instants averaged for motion blur (default 8).
    #[arg(help_heading = "Animation", long, value_name = "N")]
    pub motion_samples: Option<u32>,
    /// Evaluate every item of the scene for every frame, instead of reusing
    /// what the items the clock does not touch did in the first frame (same
    /// pictures; for comparison).
    #[arg(help_heading = "Animation", long)]
    pub no_eval_cache: bool,
    /// Render only the pixels X0..X1 × Y0..Y1 (0-based, ends excluded, top-left
    /// origin); the output image has the region's size.
    #[arg(help_heading = "Output", long, value_name = "X0,Y0,X1,Y1")]
    pub crop: Option<String>,
    /// Write a debug pass instead of the shaded picture.
    #[arg(help_heading = "Output", long, value_enum, default_value_t = PassName::Beauty)]
    pub pass: PassName,
    /// Distance drawn black in --pass depth (default: the farthest hit).
    #[arg(help_heading = "Output", long, value_name = "D")]
    pub depth_max: Option<f64>,
    /// Number of threads (default: all cores). The image is the same for any number.
    #[arg(help_heading = "Sampling", long, value_name = "N")]
    pub threads: Option<usize>,
    /// SIMD level of the ray-box and traversal kernels: auto (the best the
    /// processor has), scalar, v3 (AVX2) or v4 (AVX-512); overrides RTS_SIMD.
    /// The image is the same at every level.
    #[arg(help_heading = "Sampling", long, value_name = "LEVEL")]
    pub simd: Option<String>,
    /// Write the statistics as JSON to FILE (`-` for stdout).
    #[arg(help_heading = "Output", long, value_name = "FILE")]
    pub stats_json: Option<PathBuf>,
    /// Print no progress bar and no statistics, only diagnostics.
    #[arg(help_heading = "Output", short, long)]
    pub quiet: bool,
    /// Options for reading the scene.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Path tracer options.
    #[command(flatten)]
    pub path: super::path_opts::PathArgs,
}

/// Why the options cannot be used.
fn usage(msg: impl std::fmt::Display) -> i32 {
    eprintln!("error: {msg}");
    EXIT_USAGE
}

/// Sets the SIMD level from `--simd`, else from `RTS_SIMD` (see
/// [`rts::build::accel::set_simd_level`]).
pub fn choose_simd(flag: Option<&str>) -> Result<(), String> {
    use rts::build::accel::{set_simd_level, SimdLevel, SIMD_ENV};
    let (value, from) = match flag {
        Some(v) => (v.to_string(), "--simd".to_string()),
        None => match std::env::var(SIMD_ENV) {
            Ok(v) => (v, SIMD_ENV.to_string()),
            Err(_) => return Ok(()),
        },
    };
    let level = SimdLevel::parse(&value).ok_or_else(|| {
        format!("{from} {value}: expected auto, scalar, v3 (AVX2) or v4 (AVX-512)")
    })?;
    set_simd_level(level);
    Ok(())
}

/// `X0,Y0,X1,Y1` checked against a `w`×`h` image.
fn parse_crop(s: &str, w: u32, h: u32) -> Result<Crop, String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let nums: Result<Vec<u32>, _> = parts.iter().map(|p| p.parse::<u32>()).collect();
    match nums.as_deref() {
        Ok([x0, y0, x1, y1]) => {
            if x0 >= x1 || y0 >= y1 || *x1 > w || *y1 > h {
                Err(format!(
                    "--crop {s}: the region must satisfy X0 < X1 <= {w} and Y0 < Y1 <= {h} (ends are excluded)"
                ))
            } else {
                Ok(Crop {
                    x0: *x0,
                    y0: *y0,
                    x1: *x1,
                    y1: *y1,
                })
            }
        }
        _ => Err(format!(
            "--crop {s}: expected four whole numbers X0,Y0,X1,Y1 such as 0,0,160,120"
        )),
    }
}

/// The render settings from the options, or a usage message.
fn settings(args: &RenderArgs) -> Result<Settings, String> {
    if let Some(d) = args.aa_depth.filter(|d| !(1..=9).contains(d)) {
        return Err(format!("--aa-depth {d}: must be 1 to 9"));
    }
    if let Some(j) = args.jitter.filter(|j| !(0.0..=1.0).contains(j)) {
        return Err(format!("--jitter {j}: must be 0 to 1"));
    }
    if let Some(g) = args.aa_gamma.filter(|g| !(g.is_finite() && *g > 0.0)) {
        return Err(format!("--aa-gamma {g}: must be positive"));
    }
    let sampling = match (args.antialias, args.samples) {
        (Some(_), Some(_)) => {
            return Err("--antialias and --samples cannot be used together: choose one".into())
        }
        (Some(t), None) => {
            if !(t.is_finite() && t >= 0.0) {
                return Err(format!(
                    "--antialias {t}: the threshold must be 0 or more (POV-Ray's default is 0.3)"
                ));
            }
            Sampling::Adaptive(Antialias {
                threshold: t,
                depth: args.aa_depth.unwrap_or(3),
                jitter: args.jitter.unwrap_or(1.0),
                gamma: args.aa_gamma.unwrap_or(2.5),
            })
        }
        (None, Some(n)) => {
            if n == 0 || n > MAX_SAMPLES {
                return Err(format!("--samples {n}: must be 1 to {MAX_SAMPLES}"));
            }
            Sampling::Fixed(n)
        }
        (None, None) => Sampling::Centre,
    };
    let crop = match &args.crop {
        Some(c) => Some(parse_crop(c, args.width, args.height)?),
        None => None,
    };
    if let Some(d) = args.depth_max {
        if !(d.is_finite() && d > 0.0) {
            return Err(format!("--depth-max {d}: must be a positive distance"));
        }
    }
    let pass = match args.pass {
        PassName::Beauty => Pass::Beauty,
        PassName::Depth => Pass::Depth {
            max: args.depth_max,
        },
        PassName::Normal => Pass::Normal,
        PassName::Albedo => Pass::Albedo,
    };
    Ok(Settings {
        sampling,
        crop,
        pass,
        seed: args.seed,
        frame: 0,
    })
}

/// The output path and format from `-o` and `--format`.
fn output_target(args: &RenderArgs) -> Result<(PathBuf, Format), String> {
    match (&args.output, args.format) {
        (Some(p), Some(f)) => Ok((p.clone(), f)),
        // `-`, /dev/null, a FIFO: no extension to go by.
        (Some(p), None) if outputs::is_stream(p) && Format::from_path(p).is_none() => {
            Ok((p.clone(), Format::Png))
        }
        (Some(p), None) => match Format::from_path(p) {
            Some(f) => Ok((p.clone(), f)),
            None => Err(format!(
                "cannot write `{}`: {} is not a supported format; use .png, .ppm, .exr or .hdr, or say --format",
                p.display(),
                p.extension()
                    .map_or("no extension".to_string(), |e| format!(".{}", e.to_string_lossy()))
            )),
        },
        (None, f) => {
            let f = f.unwrap_or(Format::Png);
            let stem = args
                .scene_file
                .file_stem()
                .map_or("render".into(), |s| s.to_string_lossy().into_owned());
            Ok((PathBuf::from(format!("{stem}.{}", f.extension())), f))
        }
    }
}

/// Checks the files the render will write before anything else is done: the
/// image's format, `-o -` against other uses of standard output, and every
/// output's folder (created when missing).
fn check_outputs(args: &RenderArgs) -> Result<(), i32> {
    let (output, format) = output_target(args).map_err(usage)?;
    if format == Format::Exr && outputs::is_stream(&output) {
        return Err(usage(format!(
            "OpenEXR is written out of order and needs a regular file, and `{}` is a stream: use -o FILE.exr, or another --format",
            output.display()
        )));
    }
    if output.as_os_str() == "-" {
        if args.stats_json.as_deref() == Some(std::path::Path::new("-")) {
            return Err(usage(
                "-o - and --stats-json - both write to standard output: give --stats-json a file",
            ));
        }
        if args.scene.message_format != MessageFormat::Human {
            return Err(usage(
                "-o - writes the image to standard output, where --message-format short and json print diagnostics: use --message-format human (standard error), or -o FILE",
            ));
        }
    }
    outputs::prepare_all(args, &output).map_err(|e| {
        eprintln!("error: {e}");
        EXIT_ERRORS
    })
}

/// Renders the scene: a still, or the frames of its timeline.
pub fn run(args: &RenderArgs) -> i32 {
    let t_start = Instant::now();
    interrupt::install();
    if args.width == 0
        || args.height == 0
        || u64::from(args.width) * u64::from(args.height) > MAX_PIXELS
    {
        eprintln!(
            "error[{}]: image size {}x{} is outside 1x1 to {MAX_PIXELS} pixels",
            rts::diag::codes::IMAGE_SIZE,
            args.width,
            args.height
        );
        return EXIT_USAGE;
    }
    if args.bit_depth != 8 && args.bit_depth != 16 {
        return usage("--bit-depth must be 8 or 16");
    }
    if args.preview && args.crop.is_some() {
        return usage("--preview and --crop cannot be used together");
    }
    if let Err(msg) = choose_simd(args.simd.as_deref()) {
        return usage(msg);
    }
    let (width, height) = if args.preview {
        ((args.width / 2).max(1), (args.height / 2).max(1))
    } else {
        (args.width, args.height)
    };
    let mut settings = match settings(args) {
        Ok(s) => s,
        Err(e) => return usage(e),
    };
    if let Err(code) = check_outputs(args) {
        return code;
    }
    if args.preview {
        settings.sampling = Sampling::Centre;
    }
    let base = match common::eval_options(&args.scene, width, height) {
        // A render runs the scene's #write directives for real.
        Ok(o) => rts::eval::EvalOptions {
            write_files: true,
            reuse: !args.no_eval_cache,
            // The render measures isosurfaces' slopes as it goes.
            sample_gradients: false,
            // and reads the branches it takes only; nothing shows the
            // globals' values.
            defer_branches: true,
            describe_globals: false,
            ..o
        },
        Err(e) => return usage(e),
    };
    let plan = match sequence::Plan::from_args(args) {
        Ok(p) => p,
        Err(e) => return usage(e),
    };
    let t0 = Instant::now();
    let mut parsed = match common::parse(
        &args.scene_file,
        args.scene.max_source_size,
        base.defer_branches,
    ) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_ERRORS;
        }
    };
    common::print(
        &parsed.diagnostics,
        &parsed.sources,
        args.scene.message_format,
    );
    if parsed.file.is_none() || rts::diag::has_errors(&parsed.diagnostics) {
        return EXIT_ERRORS;
    }
    // The first evaluation finds the scene's own timeline.
    let (probe, diags) = parsed.eval(&base);
    let timeline = probe
        .as_ref()
        .and_then(|p| plan.timeline(p.animation.clone()));
    // With a timeline the scene is evaluated again for its frames, whose
    // diagnostics are shown instead (unless this evaluation already failed).
    let quiet_probe = timeline.is_some() && probe.is_some();
    let mut messages = common::Messages::new(args.scene.message_format, args.quiet);
    if !quiet_probe {
        messages.print(&diags, &parsed.sources, None);
    }
    let Some(probe) = probe else {
        return EXIT_ERRORS;
    };
    let t_probe = t0.elapsed();
    let pool = match args.threads {
        Some(n) => match super::thread_pool(n) {
            Ok(pool) => Some(pool),
            Err(e) => {
                eprintln!("error: cannot start {n} threads: {e}");
                return EXIT_ERRORS;
            }
        },
        None => None,
    };
    let mut r = Renderer::new(args, settings, (width, height), pool);
    r.messages = messages;
    // A plain `-o file.png` (no `#` run) asks for one picture: the first frame of
    // the timeline unless --frame or --clock says which.
    let plain_output = args
        .output
        .as_ref()
        .is_some_and(|p| !p.to_string_lossy().contains('#'));
    let wants_sequence = args.frames.is_some()
        || args.gif.is_some()
        || args.apng.is_some()
        || args.mp4.is_some()
        || args.shard.is_some();
    let still = args.scene.clock.is_some()
        || args.frame.is_some()
        || timeline.is_none()
        || (plain_output && !wants_sequence);
    let path_traced = super::path_opts::wanted(args, &probe);
    let sequence = !still && timeline.is_some();
    for w in super::unused::warnings(
        args,
        super::unused::Mode {
            path_traced,
            sequence,
        },
    ) {
        eprintln!("warning: {w}");
    }
    if !still {
        if let Some(tl) = timeline {
            return sequence::run(
                &mut r,
                &mut parsed,
                &base,
                &plan,
                tl,
                (t_start, path_traced),
            );
        }
    }
    // A still: at --clock, at --frame's time, or the scene as first evaluated.
    let (instants, first, frame_no) = match (&timeline, args.frame) {
        (Some(tl), Some(n)) => (
            sequence::instants(&base, tl, n, plan.blur(tl), args.preview),
            None,
            n,
        ),
        (Some(tl), None) if args.scene.clock.is_none() => {
            if !args.quiet {
                let stem = args
                    .output
                    .as_deref()
                    .and_then(|p| p.file_stem())
                    .map_or("frame".into(), |s| s.to_string_lossy().into_owned());
                eprintln!(
                    "note: the scene's timeline has frames {}..{}; this renders frame {} only (-o names one picture). For every frame use -o {stem}_####.png (or --gif/--apng/--mp4), for another one --frame N",
                    tl.initial_frame, tl.final_frame, tl.initial_frame
                );
            }
            (
                sequence::instants(&base, tl, tl.initial_frame, plan.blur(tl), args.preview),
                None,
                tl.initial_frame,
            )
        }
        (Some(tl), None) => {
            let mut o = sequence::frame_options(&base, tl, 0);
            o.clock = base.clock;
            o.clock_on = base.clock_on;
            o.frame_number = 0.0;
            (vec![o], None, 0)
        }
        // --frame without a timeline: that frame_number, POV-Ray's single frame.
        (None, Some(n)) => (
            sequence::instants(&base, &rts::scene::Timeline::default(), n, None, false),
            None,
            n,
        ),
        (None, None) => (vec![base.clone()], Some(probe), 0),
    };
    let (output, format) = match output_target(args) {
        Ok((p, f)) => (sequence::frame_path(&p, frame_no), f),
        Err(e) => return usage(e),
    };
    let t_parse = t_probe;
    if let Some(shard) = plan.shard {
        // One row band of the still, for `rts merge`.
        let still = super::still_shard::Still {
            instants,
            first,
            frame: frame_no,
            output,
            format,
            shard,
            path_traced,
            t_parse,
        };
        return super::still_shard::run(&mut r, &mut parsed, &base, still, t_start);
    }
    if path_traced && instants.len() == 1 {
        // Progressive path tracing of a still (checkpoints, --time-limit, AOVs).
        let scene = match first {
            Some(s) => s,
            None => match parsed.eval(&instants[0]) {
                (Some(s), d) if !rts::diag::has_errors(&d) => s,
                (_, d) => {
                    common::print(&d, &parsed.sources, args.scene.message_format);
                    return EXIT_ERRORS;
                }
            },
        };
        let settings = Settings {
            frame: frame_no as u32,
            ..r.settings
        };
        let size = (width, height);
        let code = super::path_opts::run(
            args, &scene, size, &output, format, &settings, t_start, t_parse,
        )
        .unwrap_or(EXIT_OK);
        let warned = parsed.slope_warnings();
        common::print(&warned, &parsed.sources, args.scene.message_format);
        return code;
    }
    let img = match r.image(&mut parsed, &instants, first, frame_no as u32) {
        Ok(i) => i,
        Err(code) => return code,
    };
    let out = r.output_options(img.assumed_gamma, img.gamma_off);
    let t3 = Instant::now();
    if let Err(e) = rts::output::write_as(&img.film, &output, format, &out) {
        eprintln!("error: {e}");
        return EXIT_ERRORS;
    }
    let settings = Settings {
        frame: frame_no as u32,
        ..r.settings
    };
    let report = stats::Report {
        output: &output,
        format,
        width,
        height,
        settings: &settings,
        threads: r.threads(),
        objects: img.objects,
        lights: img.lights,
        stats: img.stats,
        times: stats::Times {
            parse_eval: t_parse + img.t_eval,
            build: img.t_build,
            render: img.t_render,
            write: t3.elapsed(),
            total: t_start.elapsed(),
        },
        peak_memory: stats::peak_memory_bytes(),
    };
    if !args.quiet {
        eprint!("{}", report.human());
    }
    if let Some(path) = &args.stats_json {
        if let Err(code) = stats::write_json(path, &report.json()) {
            return code;
        }
    }
    EXIT_OK
}
