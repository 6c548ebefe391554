//! `rts render SCENE [-o OUT] [-W W] [-H H] [--gamma G] [--bit-depth 8|16] [--threads N]`.

use super::{common, SceneArgs, EXIT_ERRORS, EXIT_OK, EXIT_USAGE};
use rts::output::{BitDepth, Gamma, OutputOptions};
use rts::render::RenderOptions;
use std::path::PathBuf;
use std::time::Instant;

/// Most pixels in one image (8192 × 8192).
const MAX_PIXELS: u64 = 1 << 26;

/// Arguments of `rts render`.
#[derive(Debug, clap::Args)]
pub struct RenderArgs {
    /// The scene file.
    #[arg(value_name = "SCENE")]
    pub scene_file: PathBuf,
    /// Output image (PNG); defaults to the scene's name with `.png` in the current folder.
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: Option<PathBuf>,
    /// Image width in pixels.
    #[arg(short = 'W', long = "width", default_value_t = 800)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(short = 'H', long = "height", default_value_t = 600)]
    pub height: u32,
    /// The file's gamma: `srgb` (POV-Ray 3.7's default) or a number (`1.0` writes linear values).
    #[arg(long, value_name = "srgb|G", default_value = "srgb")]
    pub gamma: Gamma,
    /// Bits per channel in the PNG.
    #[arg(long, value_name = "8|16", default_value_t = 8, value_parser = clap::value_parser!(u8).range(8..=16))]
    pub bit_depth: u8,
    /// Number of threads (default: all cores). The image is the same for any number.
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Print nothing but diagnostics.
    #[arg(short, long)]
    pub quiet: bool,
    /// Options for reading the scene.
    #[command(flatten)]
    pub scene: SceneArgs,
}

/// Renders the scene.
pub fn run(args: &RenderArgs) -> i32 {
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
        eprintln!("error: --bit-depth must be 8 or 16");
        return EXIT_USAGE;
    }
    let output = args.output.clone().unwrap_or_else(|| {
        let stem = args
            .scene_file
            .file_stem()
            .map_or("render".into(), |s| s.to_string_lossy().into_owned());
        PathBuf::from(format!("{stem}.png"))
    });
    match output
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("png") => {}
        other => {
            eprintln!(
                "error: cannot write `{}`: {} is not a supported format (this release writes .png)",
                output.display(),
                other.map_or("no extension".to_string(), |e| format!(".{e}"))
            );
            return EXIT_USAGE;
        }
    }
    let options = match common::eval_options(&args.scene, args.width, args.height) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_USAGE;
        }
    };
    let t0 = Instant::now();
    let loaded = match common::load(&args.scene_file, &options) {
        Ok(l) => l,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_ERRORS;
        }
    };
    common::print(
        &loaded.diagnostics,
        &loaded.sources,
        args.scene.message_format,
    );
    let Some(scene) = loaded.scene else {
        return EXIT_ERRORS;
    };
    let t_parse = t0.elapsed();
    let job = || {
        let t1 = Instant::now();
        let world = rts::build::build(&scene);
        let t_build = t1.elapsed();
        let t2 = Instant::now();
        let film = rts::render::render(
            &world,
            &RenderOptions {
                width: args.width,
                height: args.height,
            },
        );
        (film, t_build, t2.elapsed(), world.global.assumed_gamma)
    };
    let (film, t_build, t_trace, assumed_gamma) = match args.threads {
        Some(n) => match rayon::ThreadPoolBuilder::new()
            .num_threads(n.max(1))
            .build()
        {
            Ok(pool) => pool.install(job),
            Err(e) => {
                eprintln!("error: cannot start {n} threads: {e}");
                return EXIT_ERRORS;
            }
        },
        None => job(),
    };
    let out = OutputOptions {
        gamma: args.gamma,
        bit_depth: if args.bit_depth == 16 {
            BitDepth::Sixteen
        } else {
            BitDepth::Eight
        },
        assumed_gamma,
    };
    if let Err(e) = rts::output::write(&film, &output, &out) {
        eprintln!("error: {e}");
        return EXIT_ERRORS;
    }
    if !args.quiet {
        eprintln!(
            "rendered {}x{} → {} (parse+eval {:.3}s, build {:.3}s, trace {:.3}s; {} objects, {} lights)",
            args.width,
            args.height,
            output.display(),
            t_parse.as_secs_f64(),
            t_build.as_secs_f64(),
            t_trace.as_secs_f64(),
            scene.objects.len(),
            scene.lights.len()
        );
    }
    EXIT_OK
}
