//! Image files read by `image_map`, `image_pattern`, `bump_map`, `material_map`
//! and `height_field`: each file decoded once (per evaluation, and from one
//! frame of an animation to the next while the file does not change) into a
//! compact [`Picture`] that every use shares, after its size was checked
//! against `--max-image-pixels`.

use super::{Evaluator, Fail};
use crate::diag::{codes, Diagnostic};
use crate::scene::{Depth, Palette, Picture, Samples, Tones, Transfer};
use crate::span::Span;
use rustc_hash::FxHashMap;
use std::io::BufReader;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::SystemTime;

/// What a decoder may allocate beyond the picture itself (metadata, row
/// buffers, an internal copy): this much plus the picture's own size.
const DECODER_SLACK: u64 = 64 << 20;

/// A picture read from a file, valid while the file's size and time are the same.
struct Entry {
    len: u64,
    modified: Option<SystemTime>,
    picture: Arc<Picture>,
    /// The evaluation that last used it.
    used: u64,
}

/// Pictures by file, kept between evaluations of the same scene.
#[derive(Default)]
pub(crate) struct ImageCache {
    files: FxHashMap<PathBuf, Entry>,
    generation: u64,
    /// Files decoded so far.
    decoded: u64,
    /// Tone tables made so far (by depth and transfer).
    tones: Vec<Arc<Tones>>,
}

impl ImageCache {
    /// Starts an evaluation.
    pub(crate) fn begin(&mut self) {
        self.generation += 1;
    }

    /// Ends an evaluation: pictures it did not use are forgotten.
    pub(crate) fn end(&mut self) {
        let g = self.generation;
        self.files.retain(|_, e| e.used == g);
    }

    /// Files decoded so far (a file read again because it changed counts again).
    pub(crate) fn decoded(&self) -> u64 {
        self.decoded
    }

    /// The shared tone table of `depth` under `transfer`.
    pub(crate) fn tones(&mut self, depth: Depth, transfer: Transfer) -> Arc<Tones> {
        if let Some(t) = self
            .tones
            .iter()
            .find(|t| t.depth() == depth && t.transfer() == transfer)
        {
            return t.clone();
        }
        let t = Arc::new(Tones::new(depth, transfer));
        self.tones.push(t.clone());
        t
    }
}

fn stat(path: &Path) -> Option<(u64, Option<SystemTime>)> {
    let m = std::fs::metadata(path).ok()?;
    Some((m.len(), m.modified().ok()))
}

/// Why an image could not be had.
pub(crate) enum ImageFail {
    /// Reported already, or a diagnostic of its own (the pixel budget).
    Fail(Fail),
    /// The file cannot be read or decoded: the reader's message, for the
    /// caller to put in its own diagnostic.
    Read(String),
}

/// Why [`decode`] failed.
enum DecodeError {
    /// The header's size is over the pixels left in the budget.
    TooLarge(u32, u32),
    /// The file cannot be read or decoded.
    Read(String),
}

fn read_error(e: impl std::fmt::Display) -> DecodeError {
    DecodeError::Read(e.to_string())
}

impl Evaluator<'_> {
    /// The picture in `path` (the file the scene calls `name`, at `span`):
    /// decoded when the cache does not hold it yet, refused when the scene's
    /// images would hold more than `--max-image-pixels` pixels.
    pub(crate) fn picture(
        &mut self,
        path: &Path,
        name: &str,
        span: Span,
    ) -> Result<Arc<Picture>, ImageFail> {
        let g = self.images.generation;
        let stamp = stat(path);
        let cached = self.images.files.get(path).and_then(|e| {
            (stamp == Some((e.len, e.modified))).then(|| (e.picture.clone(), e.used == g))
        });
        if let Some((picture, counted)) = cached {
            if !counted {
                self.charge_pixels(name, span, picture.width(), picture.height())?;
                if let Some(e) = self.images.files.get_mut(path) {
                    e.used = g;
                }
            }
            return Ok(picture);
        }
        let room = self
            .options
            .max_image_pixels
            .saturating_sub(self.image_pixels);
        let picture = match decode(path, room) {
            Ok(p) => Arc::new(p),
            Err(DecodeError::TooLarge(w, h)) => {
                return Err(ImageFail::Fail(self.too_many_pixels(name, span, w, h)))
            }
            Err(DecodeError::Read(e)) => return Err(ImageFail::Read(e)),
        };
        self.images.decoded += 1;
        self.charge_pixels(name, span, picture.width(), picture.height())?;
        if let Some((len, modified)) = stamp {
            self.images.files.insert(
                path.to_path_buf(),
                Entry {
                    len,
                    modified,
                    picture: picture.clone(),
                    used: g,
                },
            );
        }
        Ok(picture)
    }

    /// Counts a `w`×`h` picture against `--max-image-pixels`.
    fn charge_pixels(&mut self, name: &str, span: Span, w: u32, h: u32) -> Result<(), ImageFail> {
        let n = u64::from(w) * u64::from(h);
        let total = self.image_pixels.saturating_add(n);
        if total > self.options.max_image_pixels {
            return Err(ImageFail::Fail(self.too_many_pixels(name, span, w, h)));
        }
        self.image_pixels = total;
        Ok(())
    }

    /// The error for a `w`×`h` image over the pixel budget.
    fn too_many_pixels(&self, name: &str, span: Span, w: u32, h: u32) -> Fail {
        let n = u64::from(w) * u64::from(h);
        let max = self.options.max_image_pixels;
        let before = self.image_pixels;
        let message = if before == 0 {
            format!("image `{name}` is {w}×{h} = {n} pixels, more than the {max} --max-image-pixels allows")
        } else {
            format!(
                "image `{name}` is {w}×{h} = {n} pixels; with the {before} pixels of the images read before it, the scene's images hold more than the {max} --max-image-pixels allows"
            )
        };
        Diagnostic::error(codes::IMAGE_PIXELS, span, message)
            .with_label("too many pixels")
            .with_help(format!(
                "use a smaller image, or raise the limit with `--max-image-pixels {}` (each pixel takes 1 to 16 bytes, by the file's channels and depth)",
                before.saturating_add(n)
            ))
            .into()
    }
}

/// Limits for an image decoder: `width`×`height` at most (when known) and
/// `alloc` bytes of its own allocations.
fn limits(size: Option<(u32, u32)>, alloc: u64) -> image::Limits {
    let mut l = image::Limits::default();
    l.max_image_width = size.map(|s| s.0);
    l.max_image_height = size.map(|s| s.1);
    l.max_alloc = Some(alloc);
    l
}

/// Decodes the image at `path` (format from its content, else its extension)
/// if it has at most `room` pixels: 8- and 16-bit samples as stored, floats
/// for floating-point files, palette PNGs as indices and their palette.
fn decode(path: &Path, room: u64) -> Result<Picture, DecodeError> {
    let check = |w: u32, h: u32| {
        if u64::from(w) * u64::from(h) > room {
            Err(DecodeError::TooLarge(w, h))
        } else {
            Ok(())
        }
    };
    let mut reader = image::ImageReader::open(path)
        .map_err(read_error)?
        .with_guessed_format()
        .map_err(read_error)?;
    if reader.format() == Some(image::ImageFormat::Png) {
        let (colour, w, h) = png_header(path)?;
        check(w, h)?;
        if colour == png::ColorType::Indexed {
            return decode_indexed(path);
        }
    }
    reader.limits(limits(None, DECODER_SLACK));
    let mut decoder = reader.into_decoder().map_err(read_error)?;
    let (w, h) = image::ImageDecoder::dimensions(&decoder);
    check(w, h)?;
    let bytes = image::ImageDecoder::total_bytes(&decoder);
    image::ImageDecoder::set_limits(
        &mut decoder,
        limits(Some((w, h)), bytes.saturating_add(DECODER_SLACK)),
    )
    .map_err(read_error)?;
    let img = image::DynamicImage::from_decoder(decoder).map_err(read_error)?;
    from_dynamic(img)
}

/// The colour type and size in a PNG file's header.
fn png_header(path: &Path) -> Result<(png::ColorType, u32, u32), DecodeError> {
    let file = std::fs::File::open(path).map_err(read_error)?;
    let mut d = png::Decoder::new_with_limits(
        BufReader::new(file),
        png::Limits {
            bytes: DECODER_SLACK as usize,
        },
    );
    let info = d.read_header_info().map_err(read_error)?;
    Ok((info.color_type, info.width, info.height))
}

/// A palette PNG as its indices and palette (one byte per pixel; the colours
/// are those image decoders expand it to).
fn decode_indexed(path: &Path) -> Result<Picture, DecodeError> {
    let file = std::fs::File::open(path).map_err(read_error)?;
    let mut d = png::Decoder::new_with_limits(
        BufReader::new(file),
        png::Limits {
            bytes: DECODER_SLACK as usize,
        },
    );
    d.set_transformations(png::Transformations::IDENTITY);
    let mut reader = d.read_info().map_err(read_error)?;
    let palette = {
        let info = reader.info();
        let Some(plte) = info.palette.as_deref() else {
            return Err(DecodeError::Read(
                "a palette image without a palette".into(),
            ));
        };
        rgba_palette(plte, info.trns.as_deref().unwrap_or(&[]))
    };
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| DecodeError::Read("the image is too large".into()))?;
    let mut buf = vec![0; size];
    let out = reader.next_frame(&mut buf).map_err(read_error)?;
    let bits = out.bit_depth as usize;
    let (w, h) = (out.width as usize, out.height as usize);
    let indices = if bits == 8 && out.line_size == w {
        buf.truncate(w * h);
        buf
    } else {
        let mut idx = Vec::with_capacity(w * h);
        let mask = ((1u16 << bits) - 1) as u8;
        for row in buf.chunks(out.line_size).take(h) {
            for x in 0..w {
                let bit = x * bits;
                let byte = row.get(bit / 8).copied().unwrap_or(0);
                idx.push((byte >> (8 - bits - bit % 8)) & mask);
            }
        }
        idx
    };
    Picture::new(
        out.width,
        out.height,
        Samples::Indexed {
            indices,
            palette: Box::new(palette),
        },
    )
    .ok_or_else(|| DecodeError::Read("the image has no pixels".into()))
}

/// The RGBA colours of palette `plte` (RGB triples) with alphas `trns`, as
/// PNG decoders expand palette images: entries not in the palette are opaque
/// black, entries without an alpha opaque, and a `tRNS` longer than the
/// palette is ignored.
fn rgba_palette(plte: &[u8], trns: &[u8]) -> Palette {
    let entries = (plte.len() / 3).min(256);
    let trns = if trns.len() <= entries { trns } else { &[] };
    let mut out = [[0, 0, 0, 255]; 256];
    for (k, rgb) in plte.chunks_exact(3).take(256).enumerate() {
        out[k] = [rgb[0], rgb[1], rgb[2], trns.get(k).copied().unwrap_or(255)];
    }
    out
}

/// A decoded image kept as it is stored (its buffer moved, not copied).
fn from_dynamic(img: image::DynamicImage) -> Result<Picture, DecodeError> {
    use image::DynamicImage as D;
    let (w, h) = (img.width(), img.height());
    let samples = match img {
        D::ImageLuma8(b) => Samples::Eight {
            channels: 1,
            data: b.into_raw(),
        },
        D::ImageLumaA8(b) => Samples::Eight {
            channels: 2,
            data: b.into_raw(),
        },
        D::ImageRgb8(b) => Samples::Eight {
            channels: 3,
            data: b.into_raw(),
        },
        D::ImageRgba8(b) => Samples::Eight {
            channels: 4,
            data: b.into_raw(),
        },
        D::ImageLuma16(b) => Samples::Sixteen {
            channels: 1,
            data: b.into_raw(),
        },
        D::ImageLumaA16(b) => Samples::Sixteen {
            channels: 2,
            data: b.into_raw(),
        },
        D::ImageRgb16(b) => Samples::Sixteen {
            channels: 3,
            data: b.into_raw(),
        },
        D::ImageRgba16(b) => Samples::Sixteen {
            channels: 4,
            data: b.into_raw(),
        },
        D::ImageRgb32F(b) => Samples::Float {
            channels: 3,
            data: b.into_raw(),
        },
        D::ImageRgba32F(b) => Samples::Float {
            channels: 4,
            data: b.into_raw(),
        },
        other => Samples::Float {
            channels: 4,
            data: other.into_rgba32f().into_raw(),
        },
    };
    Picture::new(w, h, samples).ok_or_else(|| DecodeError::Read("the image has no pixels".into()))
}

/// `picture` as an `image` buffer (a copy; palette images expanded to their
/// colours), for readers that want the decoder's own conversions.
pub(crate) fn to_dynamic(picture: &Picture) -> image::DynamicImage {
    use image::{DynamicImage as D, ImageBuffer};
    let (w, h) = (picture.width(), picture.height());
    let made = match picture.samples() {
        Samples::Eight { channels, data } => match channels {
            1 => ImageBuffer::from_raw(w, h, data.clone()).map(D::ImageLuma8),
            2 => ImageBuffer::from_raw(w, h, data.clone()).map(D::ImageLumaA8),
            3 => ImageBuffer::from_raw(w, h, data.clone()).map(D::ImageRgb8),
            _ => ImageBuffer::from_raw(w, h, data.clone()).map(D::ImageRgba8),
        },
        Samples::Sixteen { channels, data } => match channels {
            1 => ImageBuffer::from_raw(w, h, data.clone()).map(D::ImageLuma16),
            2 => ImageBuffer::from_raw(w, h, data.clone()).map(D::ImageLumaA16),
            3 => ImageBuffer::from_raw(w, h, data.clone()).map(D::ImageRgb16),
            _ => ImageBuffer::from_raw(w, h, data.clone()).map(D::ImageRgba16),
        },
        Samples::Float { channels, data } => match channels {
            3 => ImageBuffer::from_raw(w, h, data.clone()).map(D::ImageRgb32F),
            _ => ImageBuffer::from_raw(w, h, data.clone()).map(D::ImageRgba32F),
        },
        Samples::Indexed { indices, palette } => {
            let data = indices
                .iter()
                .flat_map(|&k| palette[usize::from(k)])
                .collect();
            ImageBuffer::from_raw(w, h, data).map(D::ImageRgba8)
        }
    };
    // Picture::new checked that the samples fill the size.
    made.unwrap_or_else(|| D::new_rgba8(w, h))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn palettes_expand_as_png_decoders_do() {
        let p = rgba_palette(&[1, 2, 3, 4, 5, 6], &[7]);
        assert_eq!(p[0], [1, 2, 3, 7]);
        assert_eq!(p[1], [4, 5, 6, 255]);
        assert_eq!(p[2], [0, 0, 0, 255]);
        // A tRNS longer than the palette is ignored.
        let q = rgba_palette(&[1, 2, 3], &[0, 0]);
        assert_eq!(q[0], [1, 2, 3, 255]);
    }
}
