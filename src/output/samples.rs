//! The values an image file written by rts holds, read back exactly and written
//! again with rts's own encoders. `rts merge` stacks the row bands of a still
//! (`rts render --shard I/N`) this way: the stacked samples, encoded as one
//! render encodes its film, are the bytes of that render's file.

use super::encode::{self, row_bytes, EncodeResult};
use super::{BitDepth, Format, OutputError};
use crate::files;
use std::io::{BufReader, BufWriter, Read};
use std::path::Path;

/// Samples of an RGB image, row-major from the top-left.
#[derive(Clone, Debug, PartialEq)]
pub enum Samples {
    /// 8-bit file values (PNG, PPM).
    Eight(Vec<u8>),
    /// 16-bit file values, big-endian pairs (PNG, PPM).
    Sixteen(Vec<u8>),
    /// Linear light (EXR, Radiance HDR).
    Float(Vec<[f32; 3]>),
}

/// What an image file holds, as rts's encoders take it.
#[derive(Clone, Debug, PartialEq)]
pub struct StoredImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The values.
    pub samples: Samples,
}

/// A decoding failure, as text.
fn bad(path: &Path, what: impl std::fmt::Display) -> String {
    format!("cannot read `{}`: {what}", path.display())
}

impl StoredImage {
    /// Bits per channel of integer samples (`None` for float ones).
    pub fn bit_depth(&self) -> Option<BitDepth> {
        match self.samples {
            Samples::Eight(_) => Some(BitDepth::Eight),
            Samples::Sixteen(_) => Some(BitDepth::Sixteen),
            Samples::Float(_) => None,
        }
    }

    /// Reads `path`, a `format` file as rts writes them (RGB; PNG and PPM of 8
    /// or 16 bits), refusing one of more than `max_pixels` pixels before its
    /// samples are read.
    pub fn read(path: &Path, format: Format, max_pixels: u64) -> Result<StoredImage, String> {
        let file = files::open_regular(path).map_err(|e| bad(path, e))?;
        let mut input = BufReader::new(file);
        let check = |w: u32, h: u32| -> Result<(), String> {
            if w == 0 || h == 0 || u64::from(w) * u64::from(h) > max_pixels {
                Err(bad(
                    path,
                    format!("its size {w}x{h} is outside 1x1 to {max_pixels} pixels"),
                ))
            } else {
                Ok(())
            }
        };
        match format {
            Format::Png => {
                let mut d = png::Decoder::new(input);
                d.set_transformations(png::Transformations::IDENTITY);
                let mut reader = d.read_info().map_err(|e| bad(path, e))?;
                let info = reader.info();
                let (w, h) = (info.width, info.height);
                check(w, h)?;
                let depth = match (info.color_type, info.bit_depth) {
                    (png::ColorType::Rgb, png::BitDepth::Eight) => BitDepth::Eight,
                    (png::ColorType::Rgb, png::BitDepth::Sixteen) => BitDepth::Sixteen,
                    (c, b) => {
                        return Err(bad(
                            path,
                            format!("a {c:?} PNG of {b:?} bits; rts writes RGB of 8 or 16"),
                        ))
                    }
                };
                let size = reader
                    .output_buffer_size()
                    .ok_or_else(|| bad(path, "too large"))?;
                let mut buf = vec![0; size];
                let out = reader.next_frame(&mut buf).map_err(|e| bad(path, e))?;
                buf.truncate(out.buffer_size());
                if buf.len() != row_bytes(w, depth) * h as usize {
                    return Err(bad(path, "unexpected sample layout"));
                }
                Ok(StoredImage {
                    width: w,
                    height: h,
                    samples: integer(depth, buf),
                })
            }
            Format::Ppm => {
                let (w, h, depth) = ppm_header(&mut input).map_err(|e| bad(path, e))?;
                check(w, h)?;
                let n = row_bytes(w, depth) * h as usize;
                let mut buf = Vec::with_capacity(n);
                (&mut input)
                    .take(n as u64 + 1)
                    .read_to_end(&mut buf)
                    .map_err(|e| bad(path, e))?;
                if buf.len() != n {
                    return Err(bad(path, "its samples are not the size its header says"));
                }
                Ok(StoredImage {
                    width: w,
                    height: h,
                    samples: integer(depth, buf),
                })
            }
            Format::Exr | Format::Hdr => {
                use image::ImageDecoder;
                let (w, h, bytes) = if format == Format::Exr {
                    let d = image::codecs::openexr::OpenExrDecoder::new(input)
                        .map_err(|e| bad(path, e))?;
                    let (w, h) = d.dimensions();
                    check(w, h)?;
                    (w, h, float_bytes(path, d)?)
                } else {
                    let d = image::codecs::hdr::HdrDecoder::new(input).map_err(|e| bad(path, e))?;
                    let (w, h) = d.dimensions();
                    check(w, h)?;
                    (w, h, float_bytes(path, d)?)
                };
                float_image(path, w, h, bytes)
            }
        }
    }

    /// The images in `parts` one under the other (all of one width and kind).
    pub fn stack(parts: Vec<StoredImage>) -> Result<StoredImage, String> {
        let Some(first) = parts.first() else {
            return Err("no parts to stack".into());
        };
        let width = first.width;
        let mut height = 0u32;
        let mut samples = match first.samples {
            Samples::Eight(_) => Samples::Eight(Vec::new()),
            Samples::Sixteen(_) => Samples::Sixteen(Vec::new()),
            Samples::Float(_) => Samples::Float(Vec::new()),
        };
        for p in parts {
            if p.width != width {
                return Err(format!(
                    "parts of different widths ({width} and {}) cannot be stacked",
                    p.width
                ));
            }
            height += p.height;
            match (&mut samples, p.samples) {
                (Samples::Eight(a), Samples::Eight(b))
                | (Samples::Sixteen(a), Samples::Sixteen(b)) => a.extend_from_slice(&b),
                (Samples::Float(a), Samples::Float(b)) => a.extend_from_slice(&b),
                _ => return Err("parts of different bit depths cannot be stacked".into()),
            }
        }
        Ok(StoredImage {
            width,
            height,
            samples,
        })
    }

    /// Encodes the image as `format` with rts's encoders.
    fn encode(
        &self,
        out: &mut (impl std::io::Write + std::io::Seek),
        format: Format,
    ) -> EncodeResult {
        let size = (self.width, self.height);
        match (&self.samples, format) {
            (Samples::Eight(b) | Samples::Sixteen(b), Format::Png | Format::Ppm) => {
                let depth = self.bit_depth().unwrap_or_default();
                let n = row_bytes(self.width, depth);
                let row = |y: usize, dst: &mut [u8]| dst.copy_from_slice(&b[y * n..(y + 1) * n]);
                if format == Format::Png {
                    encode::write_png(out, size, depth, row)
                } else {
                    encode::write_ppm(out, size, depth, row)
                }
            }
            (Samples::Float(v), Format::Exr) => encode::write_exr(out, size, |i| v[i]),
            (Samples::Float(v), Format::Hdr) => encode::write_hdr(out, size, |i| v[i]),
            _ => Err(format!("these samples cannot be written as {format:?}").into()),
        }
    }

    /// Writes the image at `path` as `format`, atomically (see
    /// [`super::write_as`]): the bytes rts writes for a film whose file values
    /// these are.
    pub fn write(&self, path: &Path, format: Format) -> Result<(), OutputError> {
        let result = (|| -> EncodeResult {
            let file = files::create(path, files::Policy::Stream)?;
            let mut out = BufWriter::new(file);
            self.encode(&mut out, format)?;
            out.into_inner().map_err(|e| e.into_error())?.commit()?;
            Ok(())
        })();
        result.map_err(|source| OutputError {
            path: path.to_path_buf(),
            source,
        })
    }
}

fn integer(depth: BitDepth, buf: Vec<u8>) -> Samples {
    match depth {
        BitDepth::Eight => Samples::Eight(buf),
        BitDepth::Sixteen => Samples::Sixteen(buf),
    }
}

/// The RGB 32-bit float samples of `d`, native-endian bytes.
fn float_bytes(path: &Path, d: impl image::ImageDecoder) -> Result<Vec<u8>, String> {
    if d.color_type() != image::ColorType::Rgb32F {
        return Err(bad(
            path,
            format!(
                "its colours are {:?}; rts writes RGB floats",
                d.color_type()
            ),
        ));
    }
    let n = usize::try_from(d.total_bytes()).map_err(|_| bad(path, "too large"))?;
    let mut buf = vec![0u8; n];
    d.read_image(&mut buf).map_err(|e| bad(path, e))?;
    Ok(buf)
}

fn float_image(path: &Path, w: u32, h: u32, bytes: Vec<u8>) -> Result<StoredImage, String> {
    if bytes.len() != w as usize * h as usize * 12 {
        return Err(bad(path, "unexpected sample layout"));
    }
    let f = |b: &[u8]| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
    Ok(StoredImage {
        width: w,
        height: h,
        samples: Samples::Float(
            bytes
                .chunks_exact(12)
                .map(|c| [f(&c[0..4]), f(&c[4..8]), f(&c[8..12])])
                .collect(),
        ),
    })
}

/// The width, height and depth in a binary PPM's header (`P6 W H MAX` and one
/// whitespace byte), comments allowed.
fn ppm_header(input: &mut impl Read) -> Result<(u32, u32, BitDepth), String> {
    let mut fields: Vec<String> = Vec::new();
    let mut cur = String::new();
    let mut byte = [0u8; 1];
    let mut comment = false;
    while fields.len() < 4 {
        if input.read(&mut byte).map_err(|e| e.to_string())? == 0 {
            return Err("the PPM header ends early".into());
        }
        let c = byte[0] as char;
        if comment {
            comment = c != '\n';
            continue;
        }
        if c == '#' && cur.is_empty() {
            comment = true;
        } else if c.is_ascii_whitespace() {
            if !cur.is_empty() {
                fields.push(std::mem::take(&mut cur));
            }
        } else if cur.len() < 16 {
            cur.push(c);
        } else {
            return Err("not a PPM header".into());
        }
    }
    if fields[0] != "P6" {
        return Err("not a binary PPM (P6)".into());
    }
    let num = |s: &str| {
        s.parse::<u32>()
            .map_err(|_| format!("`{s}` in the PPM header"))
    };
    let (w, h) = (num(&fields[1])?, num(&fields[2])?);
    let depth = match num(&fields[3])? {
        255 => BitDepth::Eight,
        65535 => BitDepth::Sixteen,
        m => return Err(format!("maximum value {m}; rts writes 255 or 65535")),
    };
    Ok((w, h, depth))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::{write_as, Gamma, OutputOptions};
    use crate::render::Film;
    use glam::Vec3;

    #[test]
    fn bands_stacked_are_the_bytes_of_the_whole() {
        let (w, h) = (13u32, 150u32);
        let pixels: Vec<Vec3> = (0..w * h)
            .map(|i| {
                let t = i as f32 / (w * h) as f32;
                Vec3::new(t * 3.0, (t * 37.0).fract(), 1e-3 + t * t * 40.0)
            })
            .collect();
        let film = Film {
            width: w,
            height: h,
            pixels,
        };
        let dir = std::env::temp_dir().join(format!("rts-samples-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for format in Format::ALL {
            for bit_depth in [BitDepth::Eight, BitDepth::Sixteen] {
                let opts = OutputOptions {
                    gamma: Gamma::Srgb,
                    bit_depth,
                    assumed_gamma: Some(2.2),
                };
                let ext = format.extension();
                let whole = dir.join(format!("whole.{ext}"));
                write_as(&film, &whole, format, &opts).unwrap();
                let mut parts = Vec::new();
                for (k, (y0, y1)) in [(0, 70), (70, 71), (71, 150)].into_iter().enumerate() {
                    let band = Film {
                        width: w,
                        height: y1 - y0,
                        pixels: film.pixels[(y0 * w) as usize..(y1 * w) as usize].to_vec(),
                    };
                    let p = dir.join(format!("part{k}.{ext}"));
                    write_as(&band, &p, format, &opts).unwrap();
                    parts.push(StoredImage::read(&p, format, 1 << 26).unwrap());
                }
                let merged = dir.join(format!("merged.{ext}"));
                StoredImage::stack(parts)
                    .unwrap()
                    .write(&merged, format)
                    .unwrap();
                assert!(
                    std::fs::read(&whole).unwrap() == std::fs::read(&merged).unwrap(),
                    "{format:?} {bit_depth:?}"
                );
            }
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
