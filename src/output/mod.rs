//! Writing a [`Film`] to an image file.

mod format;
mod gamma;

pub use format::{Format, ParseFormatError};
pub use gamma::{decode_working, to_file, Gamma, ParseGammaError};

use crate::files;
use crate::render::Film;
use image::codecs::hdr::HdrEncoder;
use image::codecs::openexr::OpenExrEncoder;
use image::codecs::png::PngEncoder;
use image::{ExtendedColorType, ImageEncoder};
use std::fmt;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Bits per channel in the written file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BitDepth {
    /// 8 bits per channel (the default).
    #[default]
    Eight,
    /// 16 bits per channel.
    Sixteen,
}

/// How to encode the film.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OutputOptions {
    /// The file's transfer function (`--gamma`; sRGB by default, like POV-Ray 3.7).
    pub gamma: Gamma,
    /// Bits per channel.
    pub bit_depth: BitDepth,
    /// The scene's `assumed_gamma` (the working space the film is in); `None`
    /// behaves as 1.0.
    pub assumed_gamma: Option<f64>,
}

/// Why an image could not be written.
#[derive(Debug)]
pub struct OutputError {
    /// The file that was being written.
    pub path: PathBuf,
    /// What went wrong.
    pub source: Box<dyn std::error::Error + Send + Sync + 'static>,
}

impl fmt::Display for OutputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "cannot write image `{}`: {}",
            self.path.display(),
            self.source
        )
    }
}

impl std::error::Error for OutputError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&*self.source)
    }
}

/// The file samples of `film`, RGB interleaved, rows from the top, in [0, 1].
pub fn encode_samples(film: &Film, opts: &OutputOptions) -> Vec<f64> {
    use rayon::prelude::*;
    // Three `pow`s per pixel: in parallel, the same values in the same order.
    let per_pixel: Vec<[f64; 3]> = film
        .pixels
        .par_iter()
        .map(|c| {
            c.to_array()
                .map(|v| to_file(v, opts.assumed_gamma, opts.gamma))
        })
        .collect();
    per_pixel.into_iter().flatten().collect()
}

/// Linear light of `film` (working values decoded with `assumed_gamma`, negatives
/// 0, no upper clamp), RGB interleaved, rows from the top: what EXR and HDR hold.
pub fn linear_samples(film: &Film, opts: &OutputOptions) -> Vec<f32> {
    film.pixels
        .iter()
        .flat_map(|c| c.to_array())
        .map(|v| {
            let l = decode_working(v, opts.assumed_gamma);
            if l.is_finite() {
                l as f32
            } else {
                0.0
            }
        })
        .collect()
}

/// Writes `film` at `path` in the format its extension names (PNG when the
/// extension is not one of [`Format`]'s), atomically: the image goes to a
/// temporary file in the same directory which is then renamed over `path`. A FIFO
/// or character device is written directly, and `-` is standard output (see
/// [`crate::files::Policy::Stream`]).
pub fn write(film: &Film, path: &Path, opts: &OutputOptions) -> Result<(), OutputError> {
    let format = Format::from_path(path).unwrap_or(Format::Png);
    write_as(film, path, format, opts)
}

/// Writes `film` at `path` as `format`, atomically (or into a stream, as
/// [`write`]). PNG and PPM hold
/// gamma-encoded 8- or 16-bit values (`opts.bit_depth`, `opts.gamma`); EXR (32-bit
/// float) and Radiance HDR hold linear light, unclamped, and ignore `gamma` and
/// `bit_depth`.
pub fn write_as(
    film: &Film,
    path: &Path,
    format: Format,
    opts: &OutputOptions,
) -> Result<(), OutputError> {
    let err = |e: Box<dyn std::error::Error + Send + Sync>| OutputError {
        path: path.to_path_buf(),
        source: e,
    };
    if film.width == 0 || film.height == 0 {
        return Err(err("the image is empty".into()));
    }
    let result = (|| -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
        let file = files::create(path, files::Policy::Stream)?;
        let mut out = BufWriter::new(file);
        match format {
            Format::Png | Format::Ppm => {
                let (bytes, colour) = integer_samples(film, opts);
                if format == Format::Png {
                    PngEncoder::new(&mut out).write_image(
                        &bytes,
                        film.width,
                        film.height,
                        colour,
                    )?;
                } else {
                    write_ppm(&mut out, film, opts)?;
                }
            }
            Format::Exr => {
                let floats = linear_samples(film, opts);
                let bytes: Vec<u8> = floats.iter().flat_map(|v| v.to_ne_bytes()).collect();
                OpenExrEncoder::new(&mut out).write_image(
                    &bytes,
                    film.width,
                    film.height,
                    ExtendedColorType::Rgb32F,
                )?;
            }
            Format::Hdr => {
                let floats = linear_samples(film, opts);
                let px: Vec<image::Rgb<f32>> = floats
                    .chunks_exact(3)
                    .map(|c| image::Rgb([c[0], c[1], c[2]]))
                    .collect();
                HdrEncoder::new(&mut out).encode(&px, film.width as usize, film.height as usize)?;
            }
        }
        out.into_inner().map_err(|e| e.into_error())?.commit()?;
        Ok(())
    })();
    result.map_err(err)
}

/// A binary PPM (P6): maximum value 255 or 65535, 16-bit samples big-endian as
/// the format requires.
fn write_ppm(out: &mut impl Write, film: &Film, opts: &OutputOptions) -> std::io::Result<()> {
    let samples = encode_samples(film, opts);
    let max = match opts.bit_depth {
        BitDepth::Eight => 255,
        BitDepth::Sixteen => 65535,
    };
    write!(out, "P6\n{} {}\n{max}\n", film.width, film.height)?;
    let bytes: Vec<u8> = match opts.bit_depth {
        BitDepth::Eight => samples.iter().map(|v| (v * 255.0).round() as u8).collect(),
        BitDepth::Sixteen => samples
            .iter()
            .flat_map(|v| ((v * 65535.0).round() as u16).to_be_bytes())
            .collect(),
    };
    out.write_all(&bytes)
}

/// The 8- or 16-bit file samples (native-endian bytes for 16) and their layout.
fn integer_samples(film: &Film, opts: &OutputOptions) -> (Vec<u8>, ExtendedColorType) {
    let samples = encode_samples(film, opts);
    match opts.bit_depth {
        BitDepth::Eight => (
            samples
                .iter()
                .map(|v| (v * 255.0).round() as u8)
                .collect::<Vec<u8>>(),
            ExtendedColorType::Rgb8,
        ),
        BitDepth::Sixteen => (
            samples
                .iter()
                .flat_map(|v| ((v * 65535.0).round() as u16).to_ne_bytes())
                .collect(),
            ExtendedColorType::Rgb16,
        ),
    }
}
