//! Writing a [`Film`] to an image file.

mod encode;
mod format;
mod gamma;
mod samples;

pub use format::{Format, ParseFormatError};
pub use gamma::{decode_working, to_file, Gamma, ParseGammaError};
pub use samples::{Samples, StoredImage};

use crate::files;
use crate::render::Film;
use std::fmt;
use std::io::BufWriter;
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
        encode::encode(&mut out, film, format, opts)?;
        out.into_inner().map_err(|e| e.into_error())?.commit()?;
        Ok(())
    })();
    result.map_err(err)
}
