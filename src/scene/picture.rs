//! Decoded image files, kept as compactly as the file stores them: 8- or 16-bit
//! samples, 32-bit floats only for floating-point files, one byte per pixel for
//! palette images. One [`Picture`] per file is shared (`Arc`) by every
//! `image_map`, `image_pattern`, `bump_map` and `material_map` that reads it;
//! lookups convert the few pixels they read, through a [`Tones`] table.

use std::fmt;

/// A palette's colours as RGBA bytes (entries the file leaves out are opaque
/// black, as PNG decoders give them).
pub type Palette = [[u8; 4]; 256];

/// The samples of a picture, row-major from the top-left.
#[derive(Clone, PartialEq)]
pub enum Samples {
    /// 8-bit samples, `channels` per pixel: 1 grey, 2 grey and alpha, 3 RGB,
    /// 4 RGBA.
    Eight {
        /// Samples per pixel.
        channels: u8,
        /// The samples.
        data: Vec<u8>,
    },
    /// 16-bit samples, laid out as [`Samples::Eight`].
    Sixteen {
        /// Samples per pixel.
        channels: u8,
        /// The samples.
        data: Vec<u16>,
    },
    /// 32-bit float samples (OpenEXR, Radiance HDR): 3 RGB or 4 RGBA per pixel.
    Float {
        /// Samples per pixel.
        channels: u8,
        /// The samples.
        data: Vec<f32>,
    },
    /// A palette image: one index per pixel.
    Indexed {
        /// The palette index of each pixel.
        indices: Vec<u8>,
        /// The palette.
        palette: Box<Palette>,
    },
}

/// How deep a picture's samples are, which chooses its [`Tones`] table. Grey
/// pictures are told apart because image decoders turn their codes into
/// floats a little differently (times 1/255 rather than divided by 255, which
/// differ in the last bit for some codes).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Depth {
    /// 8-bit colour samples (and palette colours): codes 0 to 255.
    Eight,
    /// 16-bit colour samples: codes 0 to 65535.
    Sixteen,
    /// 8-bit grey samples.
    GreyEight,
    /// 16-bit grey samples.
    GreySixteen,
    /// Floating-point samples, used as they are.
    Float,
}

/// One pixel as stored: integer colour codes of a [`Depth`], or floats; with
/// the pixel's opacity as image decoders give it (1 without an alpha channel).
/// Grey is repeated in red, green and blue.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Texel {
    /// Red, green and blue codes of an 8- or 16-bit picture, and opacity.
    Codes([u16; 3], f32),
    /// Red, green and blue of a floating-point picture, and opacity.
    Floats([f32; 3], f32),
}

/// A decoded image file.
#[derive(Clone)]
pub struct Picture {
    width: u32,
    height: u32,
    samples: Samples,
    /// The lowest opacity of any pixel (1 when there is no alpha channel).
    min_alpha: f32,
    /// For palette images, which palette entries some pixel uses.
    used: Option<Box<[bool; 256]>>,
}

/// `code / 255` as image decoders convert 8-bit colour samples to floats.
fn unit8(code: u8) -> f32 {
    (f32::from(code) / 255.0).clamp(0.0, 1.0)
}

/// `code / 65535` as image decoders convert 16-bit colour samples to floats.
fn unit16(code: u16) -> f32 {
    (f32::from(code) / 65535.0).clamp(0.0, 1.0)
}

/// `code × (1/255)` as image decoders convert 8-bit grey samples to floats.
fn grey8(code: u8) -> f32 {
    f32::from(code) * (1.0 / 255.0)
}

/// `code × (1/65535)` as image decoders convert 16-bit grey samples to floats.
fn grey16(code: u16) -> f32 {
    f32::from(code) * (1.0 / 65535.0)
}

impl Picture {
    /// A `width`×`height` picture of `samples`, or `None` when the size is 0 or
    /// the samples do not fill it exactly.
    pub fn new(width: u32, height: u32, samples: Samples) -> Option<Picture> {
        let n = (width as usize).checked_mul(height as usize)?;
        if n == 0 {
            return None;
        }
        let fits = |channels: u8, len: usize, allowed: &[u8]| {
            allowed.contains(&channels) && n.checked_mul(usize::from(channels)) == Some(len)
        };
        let ok = match &samples {
            Samples::Eight { channels, data } => fits(*channels, data.len(), &[1, 2, 3, 4]),
            Samples::Sixteen { channels, data } => fits(*channels, data.len(), &[1, 2, 3, 4]),
            Samples::Float { channels, data } => fits(*channels, data.len(), &[3, 4]),
            Samples::Indexed { indices, .. } => indices.len() == n,
        };
        if !ok {
            return None;
        }
        let min_alpha = match &samples {
            Samples::Eight { channels: 2, data } => {
                data.chunks_exact(2).fold(1.0f32, |m, p| m.min(grey8(p[1])))
            }
            Samples::Eight { channels: 4, data } => {
                data.chunks_exact(4).fold(1.0f32, |m, p| m.min(unit8(p[3])))
            }
            Samples::Sixteen { channels: 2, data } => data
                .chunks_exact(2)
                .fold(1.0f32, |m, p| m.min(grey16(p[1]))),
            Samples::Sixteen { channels: 4, data } => data
                .chunks_exact(4)
                .fold(1.0f32, |m, p| m.min(unit16(p[3]))),
            Samples::Float { channels: 4, data } => {
                data.chunks_exact(4).fold(1.0f32, |m, p| m.min(p[3]))
            }
            _ => 1.0,
        };
        let used = match &samples {
            Samples::Indexed { indices, palette } => {
                let mut used = Box::new([false; 256]);
                for &k in indices {
                    used[usize::from(k)] = true;
                }
                let min = (0..256)
                    .filter(|&k| used[k])
                    .fold(1.0f32, |m, k| m.min(unit8(palette[k][3])));
                return Some(Picture {
                    width,
                    height,
                    samples,
                    min_alpha: min,
                    used: Some(used),
                });
            }
            _ => None,
        };
        Some(Picture {
            width,
            height,
            samples,
            min_alpha,
            used,
        })
    }

    /// Width in pixels (at least 1).
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels (at least 1).
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Number of pixels.
    pub fn pixels(&self) -> u64 {
        u64::from(self.width) * u64::from(self.height)
    }

    /// The stored samples.
    pub fn samples(&self) -> &Samples {
        &self.samples
    }

    /// The depth of the colour samples.
    pub fn depth(&self) -> Depth {
        match self.samples {
            Samples::Eight {
                channels: 1 | 2, ..
            } => Depth::GreyEight,
            Samples::Eight { .. } | Samples::Indexed { .. } => Depth::Eight,
            Samples::Sixteen {
                channels: 1 | 2, ..
            } => Depth::GreySixteen,
            Samples::Sixteen { .. } => Depth::Sixteen,
            Samples::Float { .. } => Depth::Float,
        }
    }

    /// Whether floats are stored (OpenEXR, HDR): such pictures hold linear light.
    pub fn is_float(&self) -> bool {
        self.depth() == Depth::Float
    }

    /// Bytes the samples take.
    pub fn bytes(&self) -> usize {
        match &self.samples {
            Samples::Eight { data, .. } => data.len(),
            Samples::Sixteen { data, .. } => data.len() * 2,
            Samples::Float { data, .. } => data.len() * 4,
            Samples::Indexed { indices, .. } => indices.len() + 1024,
        }
    }

    /// The lowest opacity of any pixel (1 when the picture has no alpha).
    pub fn min_alpha(&self) -> f32 {
        self.min_alpha
    }

    /// The palette of a palette image.
    pub fn palette(&self) -> Option<&Palette> {
        match &self.samples {
            Samples::Indexed { palette, .. } => Some(palette),
            _ => None,
        }
    }

    /// Whether some pixel of a palette image uses palette entry `k`.
    pub fn uses_index(&self, k: u8) -> bool {
        self.used.as_ref().is_some_and(|u| u[usize::from(k)])
    }

    /// The palette index of pixel `i` (row-major from the top-left), for palette
    /// images.
    pub fn index(&self, i: usize) -> Option<u8> {
        match &self.samples {
            Samples::Indexed { indices, .. } => Some(indices[i]),
            _ => None,
        }
    }

    /// Pixel `i` (row-major from the top-left) as stored. Grey is repeated in
    /// red, green and blue; a palette pixel is its palette colour.
    pub fn texel(&self, i: usize) -> Texel {
        match &self.samples {
            Samples::Eight { channels, data } => {
                let c = usize::from(*channels);
                let p = &data[i * c..i * c + c];
                let (rgb, a) = match c {
                    1 => ([p[0]; 3], 1.0),
                    2 => ([p[0]; 3], grey8(p[1])),
                    3 => ([p[0], p[1], p[2]], 1.0),
                    _ => ([p[0], p[1], p[2]], unit8(p[3])),
                };
                Texel::Codes(rgb.map(u16::from), a)
            }
            Samples::Sixteen { channels, data } => {
                let c = usize::from(*channels);
                let p = &data[i * c..i * c + c];
                match c {
                    1 => Texel::Codes([p[0]; 3], 1.0),
                    2 => Texel::Codes([p[0]; 3], grey16(p[1])),
                    3 => Texel::Codes([p[0], p[1], p[2]], 1.0),
                    _ => Texel::Codes([p[0], p[1], p[2]], unit16(p[3])),
                }
            }
            Samples::Float { channels, data } => {
                let c = usize::from(*channels);
                let p = &data[i * c..i * c + c];
                let a = if c == 4 { p[3] } else { 1.0 };
                Texel::Floats([p[0], p[1], p[2]], a)
            }
            Samples::Indexed { indices, palette } => {
                let p = palette[usize::from(indices[i])];
                Texel::Codes([p[0], p[1], p[2]].map(u16::from), unit8(p[3]))
            }
        }
    }
}

impl fmt::Debug for Picture {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = match &self.samples {
            Samples::Eight { channels, .. } => format!("8-bit × {channels}"),
            Samples::Sixteen { channels, .. } => format!("16-bit × {channels}"),
            Samples::Float { channels, .. } => format!("float × {channels}"),
            Samples::Indexed { .. } => "palette".to_string(),
        };
        write!(f, "Picture({}×{}, {kind})", self.width, self.height)
    }
}

impl PartialEq for Picture {
    fn eq(&self, other: &Picture) -> bool {
        std::ptr::eq(self, other)
            || (self.width == other.width
                && self.height == other.height
                && self.samples == other.samples)
    }
}

/// How an image's stored values become the scene's colours.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Transfer {
    /// The values as stored (in [0, 1] for 8- and 16-bit files).
    AsStored,
    /// The sRGB curve decoded (POV-Ray 3.7 reads 8- and 16-bit pictures so).
    Srgb,
    /// `gamma G`: the stored value to the power G.
    Power(f64),
}

impl Transfer {
    /// The colour value of stored value `v`.
    pub fn apply(self, v: f64) -> f64 {
        match self {
            Transfer::AsStored => v,
            Transfer::Srgb => srgb_to_linear(v),
            Transfer::Power(g) => v.max(0.0).powf(g),
        }
    }
}

/// The sRGB transfer function decoded: a stored value in [0, 1] to linear light.
pub fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The colour value of every code of a [`Depth`] under a [`Transfer`]: 256
/// entries for 8-bit pictures, 65536 for 16-bit ones, none for floats (which
/// are converted as they are read).
#[derive(Clone, PartialEq)]
pub struct Tones {
    transfer: Transfer,
    depth: Depth,
    table: Vec<f64>,
}

impl Tones {
    /// The table of `depth` codes under `transfer`.
    pub fn new(depth: Depth, transfer: Transfer) -> Tones {
        let table = match depth {
            Depth::Eight => (0..=255u8)
                .map(|c| transfer.apply(f64::from(unit8(c))))
                .collect(),
            Depth::Sixteen => (0..=u16::MAX)
                .map(|c| transfer.apply(f64::from(unit16(c))))
                .collect(),
            Depth::GreyEight => (0..=255u8)
                .map(|c| transfer.apply(f64::from(grey8(c))))
                .collect(),
            Depth::GreySixteen => (0..=u16::MAX)
                .map(|c| transfer.apply(f64::from(grey16(c))))
                .collect(),
            Depth::Float => Vec::new(),
        };
        Tones {
            transfer,
            depth,
            table,
        }
    }

    /// The transfer function.
    pub fn transfer(&self) -> Transfer {
        self.transfer
    }

    /// The depth the table is for.
    pub fn depth(&self) -> Depth {
        self.depth
    }

    /// Red, green and blue of `texel`, and its opacity.
    #[inline]
    pub fn colour(&self, texel: Texel) -> ([f64; 3], f32) {
        match texel {
            Texel::Codes(c, a) => (c.map(|c| self.table[usize::from(c)]), a),
            Texel::Floats(v, a) => (v.map(|v| self.transfer.apply(f64::from(v))), a),
        }
    }
}

impl fmt::Debug for Tones {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Tones({:?}, {:?})", self.depth, self.transfer)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_must_match_the_samples() {
        let s = |n| Samples::Eight {
            channels: 3,
            data: vec![0; n],
        };
        assert!(Picture::new(2, 2, s(12)).is_some());
        assert!(Picture::new(2, 2, s(11)).is_none());
        assert!(Picture::new(0, 2, s(0)).is_none());
        let f = Samples::Float {
            channels: 2,
            data: vec![0.0; 8],
        };
        assert!(Picture::new(2, 2, f).is_none());
    }

    #[test]
    fn grey_and_colour_codes_convert_as_decoders_do() {
        // 3 × (1/255) and 3 / 255 differ in the last bit.
        assert_ne!(grey8(3), unit8(3));
        assert_eq!(grey8(255), 1.0);
        let g = Tones::new(Depth::GreyEight, Transfer::AsStored);
        assert_eq!(
            g.colour(Texel::Codes([3; 3], 1.0)).0[0],
            f64::from(grey8(3))
        );
    }

    #[test]
    fn texels_repeat_grey_and_read_alpha() {
        let p = Picture::new(
            2,
            1,
            Samples::Eight {
                channels: 2,
                data: vec![10, 255, 20, 51],
            },
        )
        .unwrap();
        assert_eq!(p.texel(0), Texel::Codes([10; 3], 1.0));
        assert_eq!(p.texel(1), Texel::Codes([20; 3], grey8(51)));
        assert_eq!(p.min_alpha(), grey8(51));
        assert_eq!(p.depth(), Depth::GreyEight);
    }

    #[test]
    fn palette_pixels_are_their_entries() {
        let mut palette = Box::new([[0, 0, 0, 255]; 256]);
        palette[3] = [1, 2, 3, 0];
        let p = Picture::new(
            2,
            1,
            Samples::Indexed {
                indices: vec![3, 0],
                palette,
            },
        )
        .unwrap();
        assert_eq!(p.texel(0), Texel::Codes([1, 2, 3], 0.0));
        assert_eq!(p.index(1), Some(0));
        assert!(p.uses_index(3) && !p.uses_index(4));
        assert_eq!(p.min_alpha(), 0.0);
    }

    #[test]
    fn tones_decode_codes_like_the_transfer() {
        let t = Tones::new(Depth::Eight, Transfer::Srgb);
        let (rgb, _) = t.colour(Texel::Codes([255, 0, 128], 1.0));
        assert_eq!(rgb[0], 1.0);
        assert_eq!(rgb[1], 0.0);
        assert_eq!(rgb[2], srgb_to_linear(f64::from(128.0f32 / 255.0)));
        let f = Tones::new(Depth::Float, Transfer::Power(2.0));
        assert_eq!(
            f.colour(Texel::Floats([3.0, -1.0, 0.5], 1.0)).0,
            [9.0, 0.0, 0.25]
        );
    }
}
