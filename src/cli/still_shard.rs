//! `rts render --shard I/N` of a still: render row band I of N into a part file
//! (`still.part-2-of-3.png`) with a small manifest beside it
//! (`still.part-2-of-3.png.manifest.json`): the scene hash, the options, the
//! band, the image size and format, and the part's own hash. `rts merge` (see
//! `merge.rs`) stacks the parts into the file one run writes, byte for byte.
//!
//! Each band's rows are the full render's rows: the renderer draws every pixel
//! from (pixel, sample, frame, seed) alone, adaptive anti-aliasing works in whole
//! blocks of the full image, and the passes that look at the whole picture first
//! (radiosity's pretrace, the depth pass's farthest hit; photons are shot for the
//! whole scene anyway) cover the full image in a band too. The path tracer's
//! Gaussian filter spreads a sample over its neighbours, so a band renders
//! [`rts::render::path::FILTER_REACH`] more rows on each side and keeps its own.
//! What no band can reproduce (a time limit, the denoiser, which look at the
//! whole picture or the clock) is refused.

use super::frame::Renderer;
use super::manifest::{fnv64, Manifest};
use super::render::RenderArgs;
use super::{common, EXIT_ERRORS, EXIT_OK, EXIT_USAGE};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Rows in a block of the full image (POV-Ray's render block, which adaptive
/// anti-aliasing works in): bands start on a block when there are enough blocks,
/// so no block is rendered by two shards.
const BAND_ALIGN: u32 = 32;

/// The largest part manifest read.
const MAX_MANIFEST: u64 = 1 << 20;

/// Rows `y0..y1` of band `i` of `n` (i from 1) of an image `height` rows high:
/// whole blocks of [`BAND_ALIGN`] rows shared out in turn when there are at
/// least `n` blocks, else rows. `Err` when there are more shards than rows.
pub fn band(height: u32, i: u32, n: u32) -> Result<(u32, u32), String> {
    if n > height {
        return Err(format!(
            "--shard {i}/{n}: the image has only {height} rows, fewer than {n} shards"
        ));
    }
    let blocks = height.div_ceil(BAND_ALIGN);
    let split = |k: u32, units: u32| (u64::from(k) * u64::from(units) / u64::from(n)) as u32;
    Ok(if n <= blocks {
        (
            split(i - 1, blocks) * BAND_ALIGN,
            (split(i, blocks) * BAND_ALIGN).min(height),
        )
    } else {
        (split(i - 1, height), split(i, height))
    })
}

/// The part file of shard `i` of `n` for output `out`: `still.png` →
/// `still.part-2-of-3.png` (the extension kept, so the part opens as an image).
pub fn part_path(out: &Path, i: u32, n: u32) -> PathBuf {
    let name = out
        .file_name()
        .map_or_else(|| "render.png".into(), |s| s.to_string_lossy().into_owned());
    let (stem, ext) = match name.rfind('.') {
        Some(k) if k > 0 => (&name[..k], &name[k..]),
        _ => (name.as_str(), ""),
    };
    out.with_file_name(format!("{stem}.part-{i}-of-{n}{ext}"))
}

/// The manifest beside part file `part`: its name with `.manifest.json` added.
pub fn manifest_path(part: &Path) -> PathBuf {
    let mut s = part.as_os_str().to_owned();
    s.push(".manifest.json");
    PathBuf::from(s)
}

/// What a part manifest says.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct PartManifest {
    /// Always `still-band`.
    pub kind: String,
    /// Hash of the scene hash and the options: parts of one image share it.
    pub key: String,
    /// Hash of the scene's sources and data files, hex.
    pub scene_hash: String,
    /// The options that shape the pixels, as text.
    pub options: String,
    /// The full image's width.
    pub width: u32,
    /// The full image's height.
    pub height: u32,
    /// `[I, N]`: this is shard I of N.
    pub shard: [u32; 2],
    /// `[y0, y1]`: the rows this part holds (y1 excluded, 0 at the top).
    pub rows: [u32; 2],
    /// The file format (`png`, `ppm`, `exr`, `hdr`).
    pub format: String,
    /// Bits per channel of PNG and PPM (8 or 16).
    pub bit_depth: u8,
    /// The file name `-o` gave (the merged image's).
    pub output: String,
    /// The part file's name (in the manifest's folder).
    pub file: String,
    /// Its size in bytes.
    pub bytes: u64,
    /// FNV-1a of its bytes, hex.
    pub hash: String,
}

impl PartManifest {
    /// Reads the manifest at `path`.
    pub fn load(path: &Path) -> Result<PartManifest, String> {
        let bytes = rts::files::read_regular(path, MAX_MANIFEST)
            .map_err(|e| format!("cannot read `{}`: {e}", path.display()))?;
        let m: PartManifest = serde_json::from_slice(&bytes)
            .map_err(|e| format!("`{}` is not a part manifest: {e}", path.display()))?;
        if m.kind != "still-band" {
            return Err(format!(
                "`{}` is not a part manifest of a still",
                path.display()
            ));
        }
        Ok(m)
    }

    /// Writes the manifest atomically.
    pub fn save(&self, path: &Path) -> std::io::Result<()> {
        use std::io::Write;
        let text = serde_json::to_string_pretty(self).map_err(std::io::Error::other)?;
        let mut f = rts::files::create(path, rts::files::Policy::FileOnly)?;
        f.write_all(text.as_bytes())?;
        f.write_all(b"\n")?;
        f.commit()
    }

    /// Whether `part` is the file this manifest recorded (same size and hash).
    pub fn matches_file(&self, part: &Path) -> bool {
        rts::files::read_regular(part, u64::MAX).is_ok_and(|b| {
            b.len() as u64 == self.bytes && format!("{:016x}", fnv64(&b)) == self.hash
        })
    }
}

/// The key of `scene_hash` and `options`, as a sequence manifest's.
pub fn key(scene_hash: u64, options: &str) -> String {
    Manifest::new(scene_hash, options.to_string()).key
}

/// Why these options cannot render an exact band, if they cannot.
pub fn unsupported(args: &RenderArgs, output: &Path) -> Option<String> {
    let p = &args.path;
    let why = if args.crop.is_some() {
        "--crop picks its own region; a shard is a band of rows of the whole image"
    } else if super::outputs::is_stream(output) {
        "a still's shard is written to a part file beside -o, and -o names no file: give -o FILE"
    } else if p.time_limit.is_some() {
        "--time-limit stops each machine after its own number of samples, so the bands would not \
         meet: give --spp"
    } else if p.denoise {
        "the denoiser looks at the whole picture: denoise the merged image instead"
    } else if !p.aov.is_empty() {
        "--aov images are not split into bands: render them without --shard"
    } else if p.resume || p.checkpoint.is_some() {
        "checkpoints are for one progressive render: a shard renders its band in one go"
    } else {
        return None;
    };
    Some(why.to_string())
}

/// The still a run renders, as `render.rs` resolved it.
pub(crate) struct Still {
    /// The instants averaged (one, or several for motion blur).
    pub instants: Vec<rts::eval::EvalOptions>,
    /// The scene already evaluated for the only instant, if it was.
    pub first: Option<rts::scene::Scene>,
    /// The frame number (0 for a plain still).
    pub frame: i64,
    /// `-o` (the merged image's name).
    pub output: PathBuf,
    /// Its format.
    pub format: rts::output::Format,
    /// `--shard I/N`.
    pub shard: (u32, u32),
    /// The path tracer renders it.
    pub path_traced: bool,
    /// Reading and first evaluating the scene took this long.
    pub t_parse: std::time::Duration,
}

/// The options that decide a still's pixels and bytes, as text for the manifest
/// (not the band, the threads or the file names).
fn options_text(
    r: &Renderer,
    base: &rts::eval::EvalOptions,
    still: &Still,
    format: rts::output::Format,
) -> String {
    let a = r.args;
    let settings = rts::render::Settings {
        crop: None,
        frame: still.frame as u32,
        ..r.settings
    };
    format!(
        "rts {}\nsize {}x{}\nsettings {:?}\ngamma {:?} bit_depth {} format {:?}\ndefines {:?}\n\
         include {:?}\nclock {:?} frame {} frames {:?} fps {:?} cyclic {} motion_blur {:?} motion_samples {:?}\n\
         preview {}\n{}\n",
        env!("CARGO_PKG_VERSION"),
        r.width,
        r.height,
        settings,
        a.gamma,
        a.bit_depth,
        format,
        base.defines,
        base.access.include_dirs,
        a.scene.clock,
        still.frame,
        a.frames,
        a.fps,
        a.cyclic,
        a.motion_blur,
        a.motion_samples,
        a.preview,
        super::path_opts::key_text(a, still.path_traced),
    )
}

/// Renders band I of N of `still` into its part file and manifest (or finds
/// it already complete) and returns the exit status.
pub(crate) fn run(
    r: &mut Renderer,
    parsed: &mut common::Parsed,
    base: &rts::eval::EvalOptions,
    still: Still,
    t_start: std::time::Instant,
) -> i32 {
    use rts::diag::codes::SHARD_UNSUPPORTED;
    let args = r.args;
    let (i, n) = still.shard;
    if let Some(why) = unsupported(args, &still.output) {
        eprintln!("error[{SHARD_UNSUPPORTED}]: --shard {i}/{n} of a still: {why}");
        return EXIT_USAGE;
    }
    let (w, h) = (r.width, r.height);
    let (y0, y1) = match band(h, i, n) {
        Ok(b) => b,
        Err(e) => {
            eprintln!("error[{SHARD_UNSUPPORTED}]: {e}: use fewer shards");
            return EXIT_USAGE;
        }
    };
    let format = still.format;
    let options = options_text(r, base, &still, format);
    let scene_hash = super::manifest::scene_hash(&parsed.sources, parsed.cache.data_files());
    let key = key(scene_hash, &options);
    let part = part_path(&still.output, i, n);
    let man_path = manifest_path(&part);
    for p in [&part, &man_path] {
        if let Err(e) = super::outputs::prepare(p, rts::files::Policy::FileOnly, "the part") {
            eprintln!("error: {e}");
            return EXIT_ERRORS;
        }
    }
    if !args.force {
        if let Ok(m) = PartManifest::load(&man_path) {
            if m.key == key && m.rows == [y0, y1] && m.matches_file(&part) {
                if !args.quiet {
                    eprintln!(
                        "part {i}/{n} (rows {y0}..{y1}) is already complete in `{}`: nothing to render (--force renders it again)",
                        part.display()
                    );
                }
                return EXIT_OK;
            }
        }
    }
    // The path tracer's filter reaches FILTER_REACH rows beyond a sample's own.
    let margin = if still.path_traced {
        rts::render::path::FILTER_REACH
    } else {
        0
    };
    let (ry0, ry1) = (y0.saturating_sub(margin), (y1 + margin).min(h));
    r.settings.crop = Some(rts::render::Crop {
        x0: 0,
        y0: ry0,
        x1: w,
        y1: ry1,
    });
    let img = match r.image(parsed, &still.instants, still.first, still.frame as u32) {
        Ok(i) => i,
        Err(code) => return code,
    };
    let keep = (y0 - ry0) as usize * w as usize..(y1 - ry0) as usize * w as usize;
    let film = rts::render::Film {
        width: w,
        height: y1 - y0,
        pixels: img.film.pixels[keep].to_vec(),
    };
    // A path traced still is encoded as `path_opts::run` encodes one.
    let out = if still.path_traced && still.instants.len() == 1 {
        r.output_options(img.assumed_gamma, false)
    } else {
        r.output_options(img.assumed_gamma, img.gamma_off)
    };
    let t_write = std::time::Instant::now();
    if let Err(e) = rts::output::write_as(&film, &part, format, &out) {
        eprintln!("error: {e}");
        return EXIT_ERRORS;
    }
    let bytes = rts::files::read_regular(&part, u64::MAX).unwrap_or_default();
    let name = |p: &Path| {
        p.file_name()
            .map_or_else(String::new, |s| s.to_string_lossy().into_owned())
    };
    let manifest = PartManifest {
        kind: "still-band".into(),
        key,
        scene_hash: format!("{scene_hash:016x}"),
        options,
        width: w,
        height: h,
        shard: [i, n],
        rows: [y0, y1],
        format: format.extension().into(),
        bit_depth: args.bit_depth,
        output: name(&still.output),
        file: name(&part),
        bytes: bytes.len() as u64,
        hash: format!("{:016x}", fnv64(&bytes)),
    };
    if let Err(e) = manifest.save(&man_path) {
        eprintln!(
            "error: cannot write the manifest `{}`: {e}",
            man_path.display()
        );
        return EXIT_ERRORS;
    }
    let settings = rts::render::Settings {
        crop: Some(rts::render::Crop {
            x0: 0,
            y0,
            x1: w,
            y1,
        }),
        frame: still.frame as u32,
        ..r.settings
    };
    let report = super::stats::Report {
        output: &part,
        format,
        width: w,
        height: h,
        settings: &settings,
        threads: r.threads(),
        objects: img.objects,
        lights: img.lights,
        stats: img.stats,
        times: super::stats::Times {
            parse_eval: still.t_parse + img.t_eval,
            build: img.t_build,
            render: img.t_render,
            write: t_write.elapsed(),
            total: t_start.elapsed(),
        },
        peak_memory: super::stats::peak_memory_bytes(),
    };
    if !args.quiet {
        eprint!("{}", report.human());
    }
    if let Some(path) = &args.stats_json {
        if let Err(code) = super::stats::write_json(path, &report.json()) {
            return code;
        }
    }
    if !args.quiet {
        eprintln!(
            "part {i}/{n}: rows {y0}..{y1} of {w}x{h} → {} in {:.1}s; once every part is done, `rts merge -o {}` makes the image",
            part.display(),
            t_start.elapsed().as_secs_f64(),
            still.output.display()
        );
    }
    EXIT_OK
}
