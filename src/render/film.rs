//! The rendered image before output encoding.

use glam::DVec3;

/// A rendered image in the scene's working colour space (unclamped, linear in the
/// sense of `assumed_gamma`), rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height` colours, row-major from the top-left.
    pub pixels: Vec<DVec3>,
}

impl Film {
    /// The colour of pixel (`x`, `y`), `y = 0` at the top.
    pub fn get(&self, x: u32, y: u32) -> DVec3 {
        self.pixels[y as usize * self.width as usize + x as usize]
    }
}
