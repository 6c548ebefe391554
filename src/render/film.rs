//! The rendered image before output encoding.

use glam::{DVec3, Vec3};

/// A rendered image in the scene's working colour space (unclamped, linear in the
/// sense of `assumed_gamma`), rows top to bottom.
///
/// Colours are kept in single precision (12 bytes a pixel): every sample is
/// computed in double precision and rounded once when it is stored. That is far
/// finer than any output needs (a 16-bit file step is 1.5e-5, single precision
/// 6e-8 relative), so only a value within that of a file level's rounding
/// boundary can come out one level apart from a double-precision film.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height` colours, row-major from the top-left.
    pub pixels: Vec<Vec3>,
}

impl Film {
    /// A black `width`×`height` film.
    pub fn new(width: u32, height: u32) -> Film {
        Film {
            width,
            height,
            pixels: vec![Vec3::ZERO; width as usize * height as usize],
        }
    }

    /// A `width`×`height` film of `colours` (row-major from the top-left),
    /// each rounded to single precision.
    pub fn from_colours(width: u32, height: u32, colours: impl IntoIterator<Item = DVec3>) -> Film {
        Film {
            width,
            height,
            pixels: colours.into_iter().map(DVec3::as_vec3).collect(),
        }
    }

    /// The colour of pixel (`x`, `y`), `y = 0` at the top.
    pub fn get(&self, x: u32, y: u32) -> DVec3 {
        self.pixels[y as usize * self.width as usize + x as usize].as_dvec3()
    }

    /// Every colour in double precision, row-major from the top-left.
    pub fn colours(&self) -> impl ExactSizeIterator<Item = DVec3> + '_ {
        self.pixels.iter().map(|p| p.as_dvec3())
    }

    /// Row `y` (0 at the top).
    pub fn row(&self, y: u32) -> &[Vec3] {
        let w = self.width as usize;
        &self.pixels[y as usize * w..(y as usize + 1) * w]
    }
}
