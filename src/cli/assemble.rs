//! Turning a finished frame sequence into one file: an animated GIF (image's GIF
//! encoder), an animated PNG (the png crate's APNG writer), or an MP4 through the
//! `ffmpeg` program when it is installed.

use rts::files::{OutputFile, Policy};
use std::io::BufReader;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Reads a frame back as 8-bit RGB.
fn read_rgb(path: &Path) -> Result<image::RgbImage, String> {
    let img = rts::files::open_regular(path)
        .map_err(std::io::Error::other)
        .and_then(|f| image::ImageReader::new(BufReader::new(f)).with_guessed_format())
        .map_err(|e| format!("cannot read frame `{}`: {e}", path.display()))?
        .decode()
        .map_err(|e| format!("cannot decode frame `{}`: {e}", path.display()))?;
    Ok(img.to_rgb8())
}

/// Writes `out` atomically: `write` fills a temporary file which is then renamed
/// (or, for a FIFO or device, the stream itself; see [`rts::files::create`]).
fn atomic(
    out: &Path,
    write: impl FnOnce(&mut OutputFile) -> Result<(), String>,
) -> Result<(), String> {
    let cannot = |e: std::io::Error| format!("cannot write `{}`: {e}", out.display());
    let mut file = rts::files::create(out, Policy::Stream).map_err(cannot)?;
    write(&mut file)?;
    file.commit().map_err(cannot)
}

/// An animated GIF of `frames` at `fps` frames per second, looping forever.
pub fn gif(frames: &[PathBuf], fps: f64, out: &Path) -> Result<(), String> {
    use image::codecs::gif::{GifEncoder, Repeat};
    use image::{Delay, Frame};
    atomic(out, |file| {
        let mut enc = GifEncoder::new_with_speed(file, 10);
        enc.set_repeat(Repeat::Infinite)
            .map_err(|e| e.to_string())?;
        let delay = Delay::from_numer_denom_ms(1000, fps.round().max(1.0) as u32);
        for f in frames {
            let rgb = read_rgb(f)?;
            let rgba = image::DynamicImage::ImageRgb8(rgb).to_rgba8();
            enc.encode_frame(Frame::from_parts(rgba, 0, 0, delay))
                .map_err(|e| format!("cannot encode GIF `{}`: {e}", out.display()))?;
        }
        Ok(())
    })
}

/// An animated PNG of `frames` at `fps` frames per second, looping forever.
pub fn apng(frames: &[PathBuf], fps: f64, out: &Path) -> Result<(), String> {
    let Some(first) = frames.first() else {
        return Err("no frames to assemble".into());
    };
    let (w, h) = read_rgb(first)?.dimensions();
    atomic(out, |file| {
        let bad = |e: png::EncodingError| format!("cannot encode APNG `{}`: {e}", out.display());
        let mut enc = png::Encoder::new(file, w, h);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        enc.set_animated(frames.len() as u32, 0).map_err(bad)?;
        // Delay as a fraction of a second: 1/fps, in whole units when possible.
        let (num, den) = if fps.fract() == 0.0 && fps <= f64::from(u16::MAX) {
            (1u16, fps as u16)
        } else {
            (
                1000u16,
                (fps * 1000.0).round().clamp(1.0, f64::from(u16::MAX)) as u16,
            )
        };
        enc.set_frame_delay(num, den).map_err(bad)?;
        let mut writer = enc.write_header().map_err(bad)?;
        for f in frames {
            let rgb = read_rgb(f)?;
            if rgb.dimensions() != (w, h) {
                return Err(format!(
                    "frame `{}` is {}x{}, the first frame {w}x{h}: an APNG needs one size",
                    f.display(),
                    rgb.width(),
                    rgb.height()
                ));
            }
            writer.write_image_data(rgb.as_raw()).map_err(bad)?;
        }
        writer.finish().map_err(bad)
    })
}

/// Whether a program is on `PATH`.
fn on_path(program: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|d| d.join(program).is_file()))
}

/// An H.264 MP4 through `ffmpeg`. `pattern` is the frame pattern with `#`s,
/// `first` the first frame number; frames must follow each other.
pub fn mp4(pattern: &str, first: i64, fps: f64, out: &Path) -> Result<(), String> {
    if !on_path("ffmpeg") {
        return Err(
            "cannot make an MP4: the `ffmpeg` program is not on PATH; install it \
             (Debian/Ubuntu: `sudo apt-get install ffmpeg`) or use --gif / --apng"
                .into(),
        );
    }
    let input = super::sequence::printf_pattern(pattern);
    let status = Command::new("ffmpeg")
        .args(["-y", "-loglevel", "error", "-framerate"])
        .arg(format!("{fps}"))
        .arg("-start_number")
        .arg(first.to_string())
        .arg("-i")
        .arg(&input)
        .args(["-c:v", "libx264", "-pix_fmt", "yuv420p", "-vf"])
        .arg("pad=ceil(iw/2)*2:ceil(ih/2)*2")
        .arg(out)
        .status()
        .map_err(|e| format!("cannot run ffmpeg: {e}"))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!(
            "ffmpeg failed ({status}) making `{}`",
            out.display()
        ))
    }
}
