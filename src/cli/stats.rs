//! What `rts render` tells about a finished render: a progress bar while it runs
//! (stderr, only on a terminal), statistics after it (stderr), and the same as JSON
//! for scripts (`--stats-json FILE`).

use rts::output::Format;
use rts::render::{Pass, Progress, RenderStats, Sampling, Settings};
use serde_json::{json, Value};
use std::io::IsTerminal;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

/// Whether stderr is a terminal (progress bars are drawn only there).
pub fn stderr_is_terminal() -> bool {
    std::io::stderr().is_terminal()
}

/// Draws a progress bar with ETA on stderr from `progress` until `done` is set.
pub fn progress_bar(progress: &Progress, done: &AtomicBool) {
    let bar = indicatif::ProgressBar::with_draw_target(
        None,
        indicatif::ProgressDrawTarget::stderr_with_hz(10),
    );
    if let Ok(style) = indicatif::ProgressStyle::with_template(
        "{spinner} {msg} [{elapsed_precise}] {wide_bar} {percent:>3}% ETA {eta}",
    ) {
        bar.set_style(style);
    }
    while !done.load(Ordering::Relaxed) {
        let total = progress.total.load(Ordering::Relaxed);
        bar.set_message(if progress.pretrace.load(Ordering::Relaxed) {
            "radiosity pretrace"
        } else if progress.photons.load(Ordering::Relaxed) {
            "shooting photons"
        } else {
            "rendering"
        });
        if total > 0 {
            bar.set_length(total);
            bar.set_position(progress.done.load(Ordering::Relaxed));
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    bar.finish_and_clear();
}

/// Writes `json` as one line to `path` (`-`: standard output) as every output is
/// written (see [`rts::files`]); `Err` is the exit status after the message.
pub fn write_json(path: &Path, json: &Value) -> Result<(), i32> {
    use std::io::Write;
    rts::files::create(path, rts::files::Policy::Stream)
        .and_then(|mut f| {
            writeln!(f, "{json}")?;
            f.commit()
        })
        .map_err(|e| {
            eprintln!("error: cannot write statistics `{}`: {e}", path.display());
            super::EXIT_ERRORS
        })
}

/// The peak resident memory of this process (`VmHWM` of /proc/self/status), when
/// the system tells it.
pub fn peak_memory_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line
        .trim_start_matches("VmHWM:")
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .ok()?;
    Some(kb * 1024)
}

/// Time spent in each stage.
#[derive(Clone, Copy, Debug)]
pub struct Times {
    /// Reading, parsing and evaluating the scene.
    pub parse_eval: Duration,
    /// Building the world (flattening, BVH).
    pub build: Duration,
    /// Tracing rays.
    pub render: Duration,
    /// Encoding and writing the image.
    pub write: Duration,
    /// The whole command.
    pub total: Duration,
}

/// Everything reported about one render.
pub struct Report<'a> {
    /// The image written.
    pub output: &'a Path,
    /// Its format.
    pub format: Format,
    /// Full image width.
    pub width: u32,
    /// Full image height.
    pub height: u32,
    /// How it was rendered.
    pub settings: &'a Settings,
    /// Worker threads.
    pub threads: usize,
    /// Objects in the scene.
    pub objects: usize,
    /// Lights in the scene.
    pub lights: usize,
    /// Counters.
    pub stats: RenderStats,
    /// Stage times.
    pub times: Times,
    /// Peak resident memory in bytes.
    pub peak_memory: Option<u64>,
}

impl Report<'_> {
    /// Million rays (of every kind) per second of render time.
    pub fn mrays_per_s(&self) -> f64 {
        let s = self.times.render.as_secs_f64();
        if s > 0.0 {
            self.stats.rays.total() as f64 / s / 1e6
        } else {
            0.0
        }
    }

    fn sampling_text(&self) -> String {
        match self.settings.sampling {
            Sampling::Centre => "1 ray per pixel".into(),
            Sampling::Adaptive(a) => format!(
                "anti-aliasing threshold {} depth {} jitter {} ({} of {} pixels supersampled)",
                a.threshold, a.depth, a.jitter, self.stats.supersampled, self.stats.pixels
            ),
            Sampling::Fixed(n) => format!("{n} samples per pixel"),
        }
    }

    fn pass_name(&self) -> &'static str {
        match self.settings.pass {
            Pass::Beauty => "beauty",
            Pass::Depth { .. } => "depth",
            Pass::Normal => "normal",
            Pass::Albedo => "albedo",
        }
    }

    /// The human-readable statistics, several lines.
    pub fn human(&self) -> String {
        let r = &self.stats.rays;
        let t = &self.times;
        let mut s = format!(
            "rendered {}x{} → {} ({} objects, {} lights, {} threads; {}{})\n",
            self.width,
            self.height,
            self.output.display(),
            self.objects,
            self.lights,
            self.threads,
            self.sampling_text(),
            match self.settings.pass {
                Pass::Beauty => String::new(),
                _ => format!(", {} pass", self.pass_name()),
            }
        );
        s += &format!(
            "  rays: {} total, {} camera, {} reflected, {} transmitted, {} shadow{}; {:.2} Mrays/s\n",
            r.total(),
            r.camera,
            r.reflected,
            r.transmitted,
            r.shadow,
            if r.radiosity > 0 {
                format!(", {} radiosity", r.radiosity)
            } else {
                String::new()
            },
            self.mrays_per_s()
        );
        if self.stats.photons_shot > 0 {
            s += &format!(
                "  photons: {} shot, {} stored\n",
                self.stats.photons_shot, self.stats.photons_stored
            );
        }
        s += &format!(
            "  time: parse+eval {:.3}s, build {:.3}s, render {:.3}s, write {:.3}s, total {:.3}s",
            t.parse_eval.as_secs_f64(),
            t.build.as_secs_f64(),
            t.render.as_secs_f64(),
            t.write.as_secs_f64(),
            t.total.as_secs_f64()
        );
        if let Some(m) = self.peak_memory {
            s += &format!("; peak memory {:.1} MiB", m as f64 / (1024.0 * 1024.0));
        }
        s.push('\n');
        s
    }

    /// The statistics as one JSON object (documented in docs/cli.md).
    pub fn json(&self) -> Value {
        let r = &self.stats.rays;
        let t = &self.times;
        let (mode, threshold, depth, jitter, samples) = match self.settings.sampling {
            Sampling::Centre => ("centre", None, None, None, None),
            Sampling::Adaptive(a) => (
                "antialias",
                Some(a.threshold),
                Some(a.depth),
                Some(a.jitter),
                None,
            ),
            Sampling::Fixed(n) => ("samples", None, None, None, Some(n)),
        };
        json!({
            "output": self.output.display().to_string(),
            "format": self.format.extension(),
            "width": self.width,
            "height": self.height,
            "crop": self.settings.crop.map(|c| [c.x0, c.y0, c.x1, c.y1]),
            "pass": self.pass_name(),
            "sampling": {
                "mode": mode,
                "threshold": threshold,
                "depth": depth,
                "jitter": jitter,
                "samples": samples,
            },
            "seed": self.settings.seed,
            "threads": self.threads,
            "objects": self.objects,
            "lights": self.lights,
            "pixels": self.stats.pixels,
            "camera_samples": self.stats.samples,
            "supersampled_pixels": self.stats.supersampled,
            "rays": {
                "camera": r.camera,
                "reflected": r.reflected,
                "transmitted": r.transmitted,
                "shadow": r.shadow,
                "radiosity": r.radiosity,
                "total": r.total(),
            },
            "photons": {
                "shot": self.stats.photons_shot,
                "stored": self.stats.photons_stored,
            },
            "mrays_per_s": self.mrays_per_s(),
            "seconds": {
                "parse_eval": t.parse_eval.as_secs_f64(),
                "build": t.build.as_secs_f64(),
                "render": t.render.as_secs_f64(),
                "write": t.write.as_secs_f64(),
                "total": t.total.as_secs_f64(),
            },
            "peak_memory_bytes": self.peak_memory,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_peak_memory_on_linux() {
        if cfg!(target_os = "linux") {
            assert!(peak_memory_bytes().unwrap() > 0);
        }
    }
}
