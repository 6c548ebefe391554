//! `rts watch SCENE -o preview.png`: renders the scene, then renders it again whenever
//! the scene or a file it includes changes. Each render is progressive: a fast pass at
//! a fraction of the resolution (scaled up, written at once), then the full-quality
//! pass. A scene with errors prints its diagnostics and keeps the last good image.
//! Folders are watched rather than files, since editors save by writing a new file
//! and renaming it over the old one.

use super::{common, SceneArgs, EXIT_ERRORS, EXIT_USAGE};
use notify_debouncer_mini::notify::RecursiveMode;
use notify_debouncer_mini::{new_debouncer, DebounceEventResult};
use rts::output::OutputOptions;
use rts::render::{Antialias, Film, RenderOptions, Sampling, Settings};
use std::collections::hash_map::DefaultHasher;
use std::collections::{HashMap, HashSet};
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// Arguments of `rts watch`.
#[derive(Debug, clap::Args)]
pub struct WatchArgs {
    /// The scene file.
    #[arg(value_name = "SCENE")]
    pub scene_file: PathBuf,
    /// The image to keep up to date (.png, .ppm, .exr, .hdr).
    #[arg(
        short = 'o',
        long = "output",
        value_name = "OUT",
        default_value = "preview.png"
    )]
    pub output: PathBuf,
    /// Image width in pixels.
    #[arg(short = 'W', long = "width", default_value_t = 640)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(short = 'H', long = "height", default_value_t = 480)]
    pub height: u32,
    /// The first pass renders at 1/N of the width and height (1: no fast pass).
    #[arg(long, value_name = "N", default_value_t = 4)]
    pub preview_divisor: u32,
    /// Adaptive anti-aliasing threshold of the full-quality pass (0: none).
    #[arg(long, value_name = "THRESHOLD", default_value_t = 0.3)]
    pub antialias: f64,
    /// Wait this long after the last change before rendering (milliseconds).
    #[arg(long, value_name = "MS", default_value_t = 150)]
    pub debounce: u64,
    /// Options for reading scenes.
    #[command(flatten)]
    pub scene: SceneArgs,
}

/// Watches and renders until interrupted.
pub fn run(args: &WatchArgs) -> i32 {
    if args.width == 0
        || args.height == 0
        || u64::from(args.width) * u64::from(args.height) > 1 << 26
    {
        eprintln!("error: -W/-H: the image must have 1 to 67108864 pixels");
        return EXIT_USAGE;
    }
    if !(args.antialias.is_finite() && args.antialias >= 0.0) || args.preview_divisor == 0 {
        eprintln!("error: --antialias must be 0 or more and --preview-divisor at least 1");
        return EXIT_USAGE;
    }
    let options = match common::eval_options(&args.scene, args.width, args.height) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_USAGE;
        }
    };
    // As `rts render`: the image's folder is made (or the output refused) first.
    if let Err(e) = super::outputs::prepare(&args.output, rts::files::Policy::Stream, "the image") {
        eprintln!("error: {e}");
        return EXIT_ERRORS;
    }
    let (tx, rx) = mpsc::channel::<DebounceEventResult>();
    let mut debouncer = match new_debouncer(Duration::from_millis(args.debounce), tx) {
        Ok(d) => d,
        Err(e) => {
            eprintln!("error: cannot watch files: {e}");
            return EXIT_ERRORS;
        }
    };
    // Ctrl-C while a picture is being written leaves no temporary file.
    super::interrupt::install();
    let mut watched_dirs: HashSet<PathBuf> = HashSet::new();
    loop {
        let files = render_once(args, &options);
        // Reading files makes events too (and editors touch files without changing
        // them): only a change of contents starts a new render.
        let seen = fingerprint(&files, args.scene.max_source_size);
        // Watch the folder of every file read (new includes may have appeared).
        for dir in files.iter().filter_map(|f| f.parent()) {
            if watched_dirs.insert(dir.to_path_buf()) {
                if let Err(e) = debouncer.watcher().watch(dir, RecursiveMode::NonRecursive) {
                    eprintln!("warning: cannot watch {}: {e}", dir.display());
                }
            }
        }
        eprintln!("watching {} file(s); press Ctrl-C to stop", files.len());
        // Wait for a change to one of the files.
        loop {
            let Ok(events) = rx.recv() else {
                return EXIT_ERRORS;
            };
            let Ok(events) = events else {
                continue;
            };
            let hit = events.iter().any(|e| {
                let p = e.path.canonicalize().unwrap_or_else(|_| e.path.clone());
                files.contains(&p)
            });
            if hit && fingerprint(&files, args.scene.max_source_size) != seen {
                // Collect any further events of the same save.
                while rx.try_recv().is_ok() {}
                break;
            }
        }
    }
}

/// Loads and renders the scene once; returns the files to watch (canonical paths).
fn render_once(args: &WatchArgs, options: &rts::eval::EvalOptions) -> HashSet<PathBuf> {
    let start = Instant::now();
    let mut files: HashSet<PathBuf> = HashSet::new();
    files.insert(canonical(&args.scene_file));
    let loaded = match common::load(&args.scene_file, options) {
        Ok(l) => l,
        Err(e) => {
            eprintln!("error: {e}");
            return files;
        }
    };
    for (_, f) in loaded.sources.files() {
        if let Some(p) = &f.path {
            if p.is_file() {
                files.insert(canonical(p));
            }
        }
    }
    common::print(
        &loaded.diagnostics,
        &loaded.sources,
        args.scene.message_format,
    );
    let Some(scene) = loaded.scene else {
        eprintln!(
            "{}: the scene has errors; {} keeps the last good image",
            args.scene_file.display(),
            args.output.display()
        );
        return files;
    };
    let world = rts::build::build(&scene);
    let out = OutputOptions {
        assumed_gamma: scene.global.assumed_gamma,
        // Gamma handling off, as `rts render` without `--gamma` writes it.
        gamma: if scene.global.gamma_off {
            rts::output::Gamma::Power(1.0)
        } else {
            rts::output::Gamma::Srgb
        },
        ..OutputOptions::default()
    };
    let d = args.preview_divisor;
    if d > 1 {
        let opts = RenderOptions {
            width: (args.width / d).max(1),
            height: (args.height / d).max(1),
        };
        let small = rts::render::render_with(&world, &opts, &Settings::default(), None).film;
        let film = upscale(&small, args.width, args.height);
        if !write(&film, &args.output, &out) {
            return files;
        }
        eprintln!(
            "preview {}x{} in {:.2?}",
            opts.width,
            opts.height,
            start.elapsed()
        );
    }
    let sampling = if args.antialias > 0.0 {
        Sampling::Adaptive(Antialias {
            threshold: args.antialias,
            ..Antialias::default()
        })
    } else {
        Sampling::Centre
    };
    let settings = Settings {
        sampling,
        ..Settings::default()
    };
    let opts = RenderOptions {
        width: args.width,
        height: args.height,
    };
    let film = rts::render::render_with(&world, &opts, &settings, None).film;
    if write(&film, &args.output, &out) {
        eprintln!(
            "rendered {} ({}x{}) in {:.2?}",
            args.output.display(),
            args.width,
            args.height,
            start.elapsed()
        );
    }
    files
}

/// A hash of each file's contents (`None`: unreadable), to tell real changes from
/// events that changed nothing.
fn fingerprint(files: &HashSet<PathBuf>, limit: u64) -> HashMap<PathBuf, Option<u64>> {
    files
        .iter()
        .map(|f| {
            let h = rts::files::read_regular(f, limit).ok().map(|bytes| {
                let mut h = DefaultHasher::new();
                bytes.hash(&mut h);
                h.finish()
            });
            (f.clone(), h)
        })
        .collect()
}

fn canonical(p: &Path) -> PathBuf {
    p.canonicalize().unwrap_or_else(|_| p.to_path_buf())
}

fn write(film: &Film, path: &Path, out: &OutputOptions) -> bool {
    match rts::output::write(film, path, out) {
        Ok(()) => true,
        Err(e) => {
            eprintln!("error: cannot write {}: {}", e.path.display(), e.source);
            false
        }
    }
}

/// `small` scaled to `width`×`height` by repeating pixels.
fn upscale(small: &Film, width: u32, height: u32) -> Film {
    let mut pixels = Vec::with_capacity(width as usize * height as usize);
    for y in 0..height {
        let sy = (u64::from(y) * u64::from(small.height) / u64::from(height)) as u32;
        for x in 0..width {
            let sx = (u64::from(x) * u64::from(small.width) / u64::from(width)) as u32;
            pixels.push(small.pixels[sy as usize * small.width as usize + sx as usize]);
        }
    }
    Film {
        width,
        height,
        pixels,
    }
}
