//! `rts render` of a timeline: the frames named by `-o frames/shot_####.png`,
//! skipping frames a manifest says are complete, a deterministic share of them
//! with `--shard I/N`, progress, and assembly into GIF/APNG/MP4.

use super::frame::Renderer;
use super::render::RenderArgs;
use super::{assemble, common, manifest, EXIT_ERRORS, EXIT_OK, EXIT_USAGE};
use rts::eval::EvalOptions;
use rts::scene::Timeline;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// What the command line says about time.
#[derive(Clone, Debug, Default)]
pub struct Plan {
    /// `--frames A..B`.
    pub frames: Option<(i64, i64)>,
    /// `--fps`.
    pub fps: Option<f64>,
    /// `--cyclic`.
    pub cyclic: bool,
    /// `--shard I/N`, I from 1.
    pub shard: Option<(u32, u32)>,
    /// `--motion-blur`.
    pub shutter: Option<f64>,
    /// `--motion-samples`.
    pub motion_samples: Option<u32>,
    /// `--preview`.
    pub preview: bool,
}

/// `A..B`: the first and last frame, both included. A lone `N` is refused:
/// it could mean N frames or frame N.
pub fn parse_range(s: &str) -> Result<(i64, i64), String> {
    let Some((a, b)) = s.split_once("..") else {
        return Err(match s.trim().parse::<i64>() {
            Ok(n) => format!(
                "expected FIRST..LAST: 1..{n} for {n} frames, {n}..{n} for frame {n} alone (or --frame {n} for it as a still)"
            ),
            Err(_) => "expected FIRST..LAST, such as 1..144".into(),
        });
    };
    let bad = || "expected FIRST..LAST, such as 1..144".to_string();
    let a: i64 = a.trim().parse().map_err(|_| bad())?;
    let b: i64 = b
        .trim()
        .trim_start_matches('=')
        .parse()
        .map_err(|_| bad())?;
    if b < a {
        return Err("the last frame comes before the first".into());
    }
    if b - a >= rts_max_frames() {
        return Err(format!("at most {} frames", rts_max_frames()));
    }
    Ok((a, b))
}

fn rts_max_frames() -> i64 {
    1_000_000
}

/// `I/N` with 1 <= I <= N.
fn parse_shard(s: &str) -> Result<(u32, u32), String> {
    let bad = || format!("--shard {s}: expected I/N with 1 <= I <= N, such as 2/3");
    let (i, n) = s.split_once('/').ok_or_else(bad)?;
    let i: u32 = i.trim().parse().map_err(|_| bad())?;
    let n: u32 = n.trim().parse().map_err(|_| bad())?;
    if n == 0 || i == 0 || i > n {
        return Err(bad());
    }
    Ok((i, n))
}

impl Plan {
    /// The plan from the options, or a usage message.
    pub fn from_args(args: &RenderArgs) -> Result<Plan, String> {
        if let Some(f) = args.fps {
            if !(f.is_finite() && f > 0.0 && f <= 1000.0) {
                return Err(format!("--fps {f}: must be more than 0 and at most 1000"));
            }
        }
        if let Some(s) = args.motion_blur {
            if !(0.0..=1.0).contains(&s) {
                return Err(format!(
                    "--motion-blur {s}: the shutter is a fraction of a frame, 0 to 1"
                ));
            }
        }
        if let Some(n) = args.motion_samples {
            if !(1..=256).contains(&n) {
                return Err(format!("--motion-samples {n}: must be 1 to 256"));
            }
        }
        if args.scene.clock.is_some() && args.frame.is_some() {
            return Err("--clock and --frame cannot be used together: choose one".into());
        }
        Ok(Plan {
            frames: args.frames,
            fps: args.fps,
            cyclic: args.cyclic,
            shard: args.shard.as_deref().map(parse_shard).transpose()?,
            shutter: args.motion_blur,
            motion_samples: args.motion_samples,
            preview: args.preview,
        })
    }

    /// The timeline to render: the scene's with the command line's changes, or one
    /// from `--frames` alone; `None` when neither gives one (a still).
    pub fn timeline(&self, scene: Option<Timeline>) -> Option<Timeline> {
        let mut t = match (scene, self.frames) {
            (Some(t), _) => t,
            (None, Some((a, b))) => Timeline {
                initial_frame: a,
                final_frame: b,
                ..Timeline::default()
            },
            (None, None) => return None,
        };
        if let Some(f) = self.fps {
            t.fps = f;
        }
        if self.cyclic {
            t.cyclic = true;
        }
        if let Some(s) = self.shutter {
            t.shutter = s;
        }
        if let Some(n) = self.motion_samples {
            t.motion_samples = n;
        }
        Some(t)
    }

    /// The frames to render before sharding.
    pub fn range(&self, t: &Timeline) -> (i64, i64) {
        self.frames.unwrap_or((t.initial_frame, t.final_frame))
    }

    /// Motion blur as (shutter, instants), when on.
    pub fn blur(&self, t: &Timeline) -> Option<(f64, u32)> {
        (t.shutter > 0.0 && !self.preview).then_some((t.shutter, t.motion_samples.max(1)))
    }
}

/// Evaluation options for frame `n` of `t`: POV-Ray's clock variables.
pub fn frame_options(base: &EvalOptions, t: &Timeline, n: i64) -> EvalOptions {
    EvalOptions {
        clock: t.clock_of(n),
        clock_delta: t.clock_delta(),
        clock_on: true,
        frame_number: n as f64,
        initial_frame: t.initial_frame as f64,
        final_frame: t.reported_final_frame() as f64,
        initial_clock: t.initial_clock,
        final_clock: t.final_clock,
        timeline: Some(t.clone()),
        ..base.clone()
    }
}

/// The instants averaged for frame `n`: its own time, or with motion blur `k`
/// instants spread evenly over the open shutter (the middles of `k` equal slices
/// of `[n, n + shutter]` in frames).
pub fn instants(
    base: &EvalOptions,
    t: &Timeline,
    n: i64,
    blur: Option<(f64, u32)>,
    _preview: bool,
) -> Vec<EvalOptions> {
    match blur {
        None => vec![frame_options(base, t, n)],
        Some((shutter, k)) => (0..k)
            .map(|j| {
                let mut o = frame_options(base, t, n);
                let f = n as f64 + shutter * (f64::from(j) + 0.5) / f64::from(k);
                o.clock = t.clock_at(f);
                o
            })
            .collect(),
    }
}

/// The first run of `#` in the file name of `pattern`: (start, length).
fn hash_run(name: &str) -> Option<(usize, usize)> {
    let start = name.find('#')?;
    let len = name[start..].chars().take_while(|c| *c == '#').count();
    Some((start, len))
}

/// `pattern` with its `#` run replaced by `n`, zero-padded to the run's length.
pub fn frame_path(pattern: &Path, n: i64) -> PathBuf {
    let Some(name) = pattern
        .file_name()
        .map(|s| s.to_string_lossy().into_owned())
    else {
        return pattern.to_path_buf();
    };
    match hash_run(&name) {
        Some((start, len)) => {
            let num = if n < 0 {
                format!("-{:0w$}", -n, w = len.saturating_sub(1))
            } else {
                format!("{n:0len$}")
            };
            pattern.with_file_name(format!("{}{num}{}", &name[..start], &name[start + len..]))
        }
        None => pattern.to_path_buf(),
    }
}

/// `pattern` with the `#` run as printf's `%0Nd` (for ffmpeg).
pub fn printf_pattern(pattern: &str) -> String {
    match hash_run(pattern) {
        Some((start, len)) => format!("{}%0{len}d{}", &pattern[..start], &pattern[start + len..]),
        None => pattern.to_string(),
    }
}

/// A pattern for the frames: `-o` as given when it has a `#` run, else its name
/// with `_####` added before the extension (more `#` for more digits).
fn pattern_for(output: &Path, last: i64) -> PathBuf {
    let name = output
        .file_name()
        .map_or_else(|| "frame.png".into(), |n| n.to_string_lossy().into_owned());
    if name.contains('#') {
        return output.to_path_buf();
    }
    let digits = last.unsigned_abs().to_string().len().max(4);
    let hashes = "#".repeat(digits);
    let (stem, ext) = match name.rfind('.') {
        Some(i) if i > 0 => (&name[..i], &name[i..]),
        _ => (name.as_str(), ""),
    };
    output.with_file_name(format!("{stem}_{hashes}{ext}"))
}

fn human(d: Duration) -> String {
    let s = d.as_secs_f64();
    if s < 60.0 {
        format!("{s:.1}s")
    } else if s < 3600.0 {
        format!("{}m{:02}s", (s / 60.0) as u64, (s % 60.0) as u64)
    } else {
        format!(
            "{}h{:02}m",
            (s / 3600.0) as u64,
            ((s % 3600.0) / 60.0) as u64
        )
    }
}

/// The options that decide the pixels of every frame, as text for the manifest.
fn options_text(
    r: &Renderer,
    base: &EvalOptions,
    t: &Timeline,
    format: rts::output::Format,
    path_traced: bool,
) -> String {
    let a = r.args;
    format!(
        "rts {}\nsize {}x{}\nsettings {:?}\ngamma {:?} bit_depth {} format {:?}\ndefines {:?}\n\
         include {:?}\ntimeline frames {}..{} clock {}..{} fps {} cyclic {} shutter {} samples {}\npreview {}\n{}\n",
        env!("CARGO_PKG_VERSION"),
        r.width,
        r.height,
        r.settings,
        a.gamma,
        a.bit_depth,
        format,
        base.defines,
        base.access.include_dirs,
        t.initial_frame,
        t.final_frame,
        t.initial_clock,
        t.final_clock,
        t.fps,
        t.cyclic,
        t.shutter,
        t.motion_samples,
        a.preview,
        // The path tracer's options shape its frames as much as --samples the
        // classic renderer's.
        super::path_opts::key_text(a, path_traced)
    )
}

/// Removes the temporary files a run killed without warning (power cut, SIGKILL)
/// left beside this run's frames and manifest: `.NAME.XXXXXX.tmp`, NAME one of
/// `files` (a run stopped by Ctrl-C or `kill` removes its own). Frames of other
/// shards are left alone: they may be rendering now.
fn remove_stale_temporaries(dir: &Path, files: &[PathBuf]) {
    let names: std::collections::HashSet<String> = files
        .iter()
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    let dir = if dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        dir
    };
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    for e in rd.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let Some((base, random)) = name
            .strip_prefix('.')
            .and_then(|n| n.strip_suffix(".tmp"))
            .and_then(|n| n.rsplit_once('.'))
        else {
            continue;
        };
        let temporary = random.len() == 6 && random.chars().all(|c| c.is_ascii_alphanumeric());
        if temporary && names.contains(base) && e.file_type().is_ok_and(|t| t.is_file()) {
            let _ = std::fs::remove_file(e.path());
        }
    }
}

/// Renders the frames of `t` (the part `plan` asks for) and assembles them;
/// `path_traced`: the path tracer renders them (its options join the manifest's key).
pub fn run(
    r: &mut Renderer,
    parsed: &mut common::Parsed,
    base: &EvalOptions,
    plan: &Plan,
    t: Timeline,
    (t_start, path_traced): (Instant, bool),
) -> i32 {
    let args = r.args;
    let (first, last) = plan.range(&t);
    let output = match &args.output {
        Some(p) => p.clone(),
        None => {
            let stem = args
                .scene_file
                .file_stem()
                .map_or("render".into(), |s| s.to_string_lossy().into_owned());
            PathBuf::from(format!("{stem}.png"))
        }
    };
    if super::outputs::is_stream(&output) {
        eprintln!(
            "error: a sequence is written to files, one per frame, and `{}` is not a file: give a pattern such as -o frames/shot_####.png",
            output.display()
        );
        return EXIT_USAGE;
    }
    let pattern = pattern_for(&output, last);
    if pattern != output && !args.quiet {
        // -o one.png with --gif (or --frames, --shard …): the frames need names.
        eprintln!(
            "note: rendering frames {first}..{last} of the scene's timeline to `{}` (-o names one picture; a sequence writes one file per frame)",
            pattern.display()
        );
    }
    r.sequence = true;
    let format = match args
        .format
        .or_else(|| rts::output::Format::from_path(&pattern))
    {
        Some(f) => f,
        None => {
            eprintln!(
                "error: cannot write `{}`: use .png, .ppm, .exr or .hdr, or say --format",
                pattern.display()
            );
            return EXIT_USAGE;
        }
    };
    if let Some(dir) = pattern.parent().filter(|d| !d.as_os_str().is_empty()) {
        if let Err(e) = std::fs::create_dir_all(dir) {
            eprintln!("error: cannot create `{}`: {e}", dir.display());
            return EXIT_ERRORS;
        }
    }
    let all: Vec<i64> = (first..=last).collect();
    let mine: Vec<i64> = match plan.shard {
        Some((i, n)) => all
            .iter()
            .enumerate()
            .filter(|(k, _)| *k as u64 % u64::from(n) == u64::from(i - 1))
            .map(|(_, f)| *f)
            .collect(),
        None => all.clone(),
    };
    let mut man = manifest::Manifest::new(
        manifest::scene_hash(&parsed.sources, parsed.cache.data_files()),
        options_text(r, base, &t, format, path_traced),
    );
    let man_path = manifest::path_for(&pattern, plan.shard);
    // Every file this run writes must be a regular file (or none yet): a FIFO
    // there would block, a device would be written into.
    let files: Vec<PathBuf> = mine
        .iter()
        .map(|f| frame_path(&pattern, *f))
        .chain([man_path.clone()])
        .collect();
    for p in &files {
        if let Err(e) = rts::files::target(p, rts::files::Policy::FileOnly) {
            eprintln!("error: cannot write `{}`: {e}", p.display());
            return EXIT_ERRORS;
        }
    }
    remove_stale_temporaries(pattern.parent().unwrap_or(Path::new(".")), &files);
    let existing = manifest::load_all(&pattern);
    // Complete frames recorded for the same scene and options stay listed.
    for m in &existing {
        if m.key == man.key {
            for (f, rec) in &m.frames {
                man.frames.entry(*f).or_insert_with(|| rec.clone());
            }
        }
    }
    let show = r.show_progress;
    let blur = plan.blur(&t);
    let (mut rendered, mut skipped) = (0usize, 0usize);
    let mut t_frames = Duration::ZERO;
    let mut t_trace = Duration::ZERO;
    // The same after the first frame rendered (which reads mesh files and builds
    // their hierarchies once for the whole run).
    let (mut t_rest, mut t_trace_rest) = (Duration::ZERO, Duration::ZERO);
    // Of the time outside tracing: evaluating and building, and waiting for
    // the writer to take the frame.
    let (mut t_prep_rest, mut t_wait_rest) = (Duration::ZERO, Duration::ZERO);
    let n = mine.len();
    let key = man.key.clone();
    // Frames are encoded and written (with the manifest) on a second thread while
    // the next frame renders; at most one finished frame waits.
    let (tx, rx) = std::sync::mpsc::sync_channel::<(
        i64,
        PathBuf,
        rts::render::Film,
        rts::output::OutputOptions,
    )>(1);
    let writer_man_path = man_path.clone();
    let outcome: Result<(), i32> = std::thread::scope(|s| {
        let writer = s.spawn(move || -> Result<(), String> {
            let mut man = man;
            // The encoder's parallel loops run on a pool of their own: in the
            // render pool they would wait behind the next frame's tiles (a 640x480
            // frame took 93 ms to write beside rendering, 14 ms alone).
            let own = rayon::ThreadPoolBuilder::new()
                .num_threads(1)
                .thread_name(|_| "rts-frame-writer".into())
                .build()
                .map_err(|e| format!("cannot start the frame writer: {e}"))?;
            for (f, path, film, out) in rx {
                // A FIFO or device put at a frame's name while rendering is refused.
                rts::files::target(&path, rts::files::Policy::FileOnly)
                    .map_err(|e| format!("cannot write `{}`: {e}", path.display()))?;
                own.install(|| rts::output::write_as(&film, &path, format, &out))
                    .map_err(|e| e.to_string())?;
                man.record(f, &path)
                    .and_then(|_| man.save(&writer_man_path))
                    .map_err(|e| {
                        format!(
                            "cannot write the manifest `{}`: {e}",
                            writer_man_path.display()
                        )
                    })?;
            }
            Ok(())
        });
        let mut failed = None;
        for (k, &f) in mine.iter().enumerate() {
            let path = frame_path(&pattern, f);
            if !args.force && manifest::complete(&existing, &key, f, &path) {
                skipped += 1;
                continue;
            }
            let tf = Instant::now();
            let instants = instants(base, &t, f, blur, plan.preview);
            let img = match r.image(parsed, &instants, None, f as u32) {
                Ok(i) => i,
                Err(code) => {
                    eprintln!("error: frame {f} failed; frames already written are kept");
                    failed = Some(code);
                    break;
                }
            };
            let out = r.output_options(img.assumed_gamma, img.gamma_off);
            let t_render = img.t_render;
            let t_prep = img.t_eval + img.t_build;
            let t_send = Instant::now();
            if tx.send((f, path.clone(), img.film, out)).is_err() {
                // The writer stopped on an error, reported below.
                break;
            }
            let t_wait = t_send.elapsed();
            rendered += 1;
            let dt = tf.elapsed();
            t_frames += dt;
            t_trace += t_render;
            if rendered > 1 {
                t_rest += dt;
                t_trace_rest += t_render;
                t_prep_rest += t_prep;
                t_wait_rest += t_wait;
            }
            if show {
                let left = n - k - 1;
                let eta = t_frames / rendered as u32 * left as u32;
                eprintln!(
                    "frame {}/{n} ({}) in {} · ETA {}",
                    k + 1,
                    path.display(),
                    human(dt),
                    human(eta)
                );
            }
        }
        drop(tx);
        match writer.join() {
            Ok(Ok(())) => failed.map_or(Ok(()), Err),
            Ok(Err(e)) => {
                eprintln!("error: {e}");
                Err(EXIT_ERRORS)
            }
            Err(_) => {
                eprintln!("error: the frame writer stopped unexpectedly");
                Err(EXIT_ERRORS)
            }
        }
    });
    if let Err(code) = outcome {
        return code;
    }
    if !args.quiet {
        let avg = if rendered > 0 {
            t_frames / rendered as u32
        } else {
            Duration::ZERO
        };
        let share = |trace: Duration, all: Duration| {
            if all > Duration::ZERO {
                100.0 * (1.0 - trace.as_secs_f64() / all.as_secs_f64())
            } else {
                0.0
            }
        };
        let outside = share(t_trace, t_frames);
        let later = if rendered > 1 {
            let part = |t: Duration| 100.0 * t.as_secs_f64() / t_rest.as_secs_f64().max(1e-9);
            format!(
                ", {:.1}% after the first frame: {:.1}% evaluating and building, {:.1}% waiting to write frames",
                share(t_trace_rest, t_rest),
                part(t_prep_rest),
                part(t_wait_rest)
            )
        } else {
            String::new()
        };
        eprintln!(
            "sequence {} frames {first}..{last}{}: rendered {rendered}, skipped {skipped} already complete, in {} ({} per frame, {outside:.1}% outside tracing{later}) → {}",
            all.len(),
            plan.shard.map_or(String::new(), |(i, n)| format!(" (shard {i}/{n}: {} frames)", mine.len())),
            human(t_start.elapsed()),
            human(avg),
            pattern.display()
        );
    }
    let wants = args.gif.is_some() || args.apng.is_some() || args.mp4.is_some();
    if !wants {
        return EXIT_OK;
    }
    let frames: Vec<PathBuf> = all.iter().map(|f| frame_path(&pattern, *f)).collect();
    if let Some(missing) = frames.iter().find(|p| !p.exists()) {
        eprintln!(
            "note: not assembling yet: `{}` is missing (run the other shards, then this command again without --shard)",
            missing.display()
        );
        return EXIT_OK;
    }
    let mut code = EXIT_OK;
    let mut done = |what: &str, r: Result<(), String>, out: &Path| match r {
        Ok(()) => {
            if !args.quiet {
                eprintln!("{what} → {}", out.display());
            }
        }
        Err(e) => {
            eprintln!("error: {e}");
            code = EXIT_ERRORS;
        }
    };
    if let Some(out) = &args.gif {
        done("GIF", assemble::gif(&frames, t.fps, out), out);
    }
    if let Some(out) = &args.apng {
        done("APNG", assemble::apng(&frames, t.fps, out), out);
    }
    if let Some(out) = &args.mp4 {
        let p = pattern.to_string_lossy().into_owned();
        done("MP4", assemble::mp4(&p, first, t.fps, out), out);
    }
    code
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_names() {
        let p = Path::new("out/shot_####.png");
        assert_eq!(frame_path(p, 7), Path::new("out/shot_0007.png"));
        assert_eq!(frame_path(p, 12345), Path::new("out/shot_12345.png"));
        assert_eq!(frame_path(p, -3), Path::new("out/shot_-003.png"));
        assert_eq!(printf_pattern("out/s_###.png"), "out/s_%03d.png");
        assert_eq!(
            pattern_for(Path::new("a/orbit.png"), 144),
            Path::new("a/orbit_####.png")
        );
    }

    #[test]
    fn ranges_and_shards() {
        assert_eq!(parse_range("1..144"), Ok((1, 144)));
        // A lone number could mean N frames or frame N: refused.
        assert!(parse_range("5").is_err());
        assert_eq!(parse_range("5..5"), Ok((5, 5)));
        assert!(parse_range("9..2").is_err());
        assert_eq!(parse_shard("2/3"), Ok((2, 3)));
        assert!(parse_shard("0/3").is_err());
        assert!(parse_shard("4/3").is_err());
    }
}
