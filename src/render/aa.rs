//! How pixels are sampled: one ray, POV-Ray's adaptive anti-aliasing, or a fixed
//! number of jittered samples.

use glam::DVec3;

/// POV-Ray 3.7's non-recursive adaptive anti-aliasing (`Sampling_Method=1`,
/// `+A0.3 +R3 +J1.0`), measured against `povray`:
///
/// * the image is cut into blocks of [`BLOCK`]×[`BLOCK`] pixels from the top-left
///   (POV-Ray's `Render_Block_Size`), each done on its own;
/// * every pixel of a block, and the row above and the column left of the block,
///   first gets one ray through its centre;
/// * then, in reading order, each pixel is compared with its left and upper
///   neighbours as they are *now* (a neighbour inside the block may already be
///   supersampled; one outside keeps its centre colour); when they differ by at
///   least `threshold`, the pixel is supersampled, and so is the neighbour if it
///   is in the block and was not yet. The difference is
///   `|r1-r2| + |g1-g2| + |b1-b2|` of the colours clipped to [0, 1] and raised to
///   `1/gamma` (POV-Ray's `Antialias_Gamma`, 2.5);
/// * a supersampled pixel takes `depth × depth` more rays on a regular grid of
///   sub-cells (centres at `(k + 0.5) / depth`), each moved within its sub-cell by
///   up to `jitter` of the sub-cell (POV-Ray's `+J`, on with 1.0 by default), and
///   its colour is the plain mean of the centre ray and the grid rays
///   (`depth² + 1` rays).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Antialias {
    /// Colour difference that triggers supersampling (`+A0.3`).
    pub threshold: f64,
    /// Grid size per side (`+R3`), 1 to 9.
    pub depth: u32,
    /// Jitter amount in sub-cells, 0 (regular grid) to 1 (`+J1.0`).
    pub jitter: f64,
    /// The gamma colours are raised to before comparing (`Antialias_Gamma`).
    pub gamma: f64,
}

impl Default for Antialias {
    /// POV-Ray's defaults: `+A0.3 +R3 +J1.0`, `Antialias_Gamma=2.5`.
    fn default() -> Self {
        Antialias {
            threshold: 0.3,
            depth: 3,
            jitter: 1.0,
            gamma: 2.5,
        }
    }
}

impl Antialias {
    /// Whether pixels with centre colours `a` and `b` are different enough to be
    /// supersampled.
    pub fn differ(&self, a: DVec3, b: DVec3) -> bool {
        self.differ_mapped(self.map(a), self.map(b))
    }

    /// Colour `c` as [`Antialias::differ`] compares it: clipped to [0, 1] and
    /// raised to `1 / gamma`. Computed once per pixel value (three `pow`s), not
    /// once per comparison.
    pub fn map(&self, c: DVec3) -> DVec3 {
        let c = c.clamp(DVec3::ZERO, DVec3::ONE);
        if self.gamma == 1.0 {
            c
        } else {
            // Single precision is ample for a comparison against a threshold
            // (relative error ~1e-7) and costs a fraction of a double `pow`.
            let e = (1.0 / self.gamma) as f32;
            let p = |v: f64| f64::from((v as f32).powf(e));
            DVec3::new(p(c.x), p(c.y), p(c.z))
        }
    }

    /// [`Antialias::differ`] on colours already passed through [`Antialias::map`].
    pub fn differ_mapped(&self, a: DVec3, b: DVec3) -> bool {
        let d = (a - b).abs();
        d.x + d.y + d.z >= self.threshold
    }

    /// The image-plane offset within the pixel (each in [0, 1]) of grid sample `k`
    /// (`0 ≤ k < depth²`, row-major), moved by the jitter values `(u, v)` in [0, 1).
    pub fn grid_offset(&self, k: u32, (u, v): (f64, f64)) -> (f64, f64) {
        let n = f64::from(self.depth);
        let (col, row) = (f64::from(k % self.depth), f64::from(k / self.depth));
        (
            (col + 0.5 + self.jitter * (u - 0.5)) / n,
            (row + 0.5 + self.jitter * (v - 0.5)) / n,
        )
    }
}

/// POV-Ray's render block size, which anti-aliasing depends on.
pub const BLOCK: u32 = 32;

/// A block of pixels: columns `x0..x1`, rows `y0..y1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Block {
    /// First column.
    pub x0: u32,
    /// First row.
    pub y0: u32,
    /// One past the last column.
    pub x1: u32,
    /// One past the last row.
    pub y1: u32,
}

/// The blocks of a `width`×`height` image that meet `crop`, in reading order.
/// Blocks are whole blocks of the full image (cut only by its edges), so a
/// cropped render matches a full one pixel for pixel.
pub fn blocks(crop: &super::Crop, width: u32, height: u32) -> Vec<Block> {
    let mut out = Vec::new();
    if crop.x0 >= crop.x1 || crop.y0 >= crop.y1 {
        return out;
    }
    let (bx0, by0) = (crop.x0 / BLOCK, crop.y0 / BLOCK);
    let (bx1, by1) = ((crop.x1 - 1) / BLOCK, (crop.y1 - 1) / BLOCK);
    for by in by0..=by1 {
        for bx in bx0..=bx1 {
            out.push(Block {
                x0: bx * BLOCK,
                y0: by * BLOCK,
                x1: ((bx + 1) * BLOCK).min(width),
                y1: ((by + 1) * BLOCK).min(height),
            });
        }
    }
    out
}

/// The colours of `block` (row-major) under adaptive anti-aliasing;
/// `centre(x, y)` traces a pixel's centre ray, `supersample(x, y, c)` the
/// supersampled colour of a pixel whose centre colour is `c`.
pub fn render_block<S>(
    block: &Block,
    aa: &Antialias,
    centre: impl Fn(u32, u32, &mut S) -> DVec3,
    supersample: impl Fn(u32, u32, DVec3, &mut S) -> DVec3,
    st: &mut S,
) -> Vec<DVec3>
where
    S: SupersampleCount,
{
    let bw = (block.x1 - block.x0) as usize;
    let idx = |x: u32, y: u32| (y - block.y0) as usize * bw + (x - block.x0) as usize;
    let mut values = Vec::with_capacity(bw * (block.y1 - block.y0) as usize);
    for y in block.y0..block.y1 {
        for x in block.x0..block.x1 {
            values.push(centre(x, y, st));
        }
    }
    let top: Vec<DVec3> = if block.y0 > 0 {
        (block.x0..block.x1)
            .map(|x| centre(x, block.y0 - 1, st))
            .collect()
    } else {
        Vec::new()
    };
    let left: Vec<DVec3> = if block.x0 > 0 {
        (block.y0..block.y1)
            .map(|y| centre(block.x0 - 1, y, st))
            .collect()
    } else {
        Vec::new()
    };
    let mut done = vec![false; values.len()];
    let centres = values.clone();
    // Compared colours, mapped once (see `Antialias::map`).
    let mapped_centres: Vec<DVec3> = values.iter().map(|&c| aa.map(c)).collect();
    let mut mapped = mapped_centres.clone();
    let top: Vec<DVec3> = top.into_iter().map(|c| aa.map(c)).collect();
    let left: Vec<DVec3> = left.into_iter().map(|c| aa.map(c)).collect();
    for y in block.y0..block.y1 {
        for x in block.x0..block.x1 {
            let c = centres[idx(x, y)];
            let mc = mapped_centres[idx(x, y)];
            let mut hit = false;
            // Left neighbour, then upper neighbour.
            let neighbours = [
                if x > block.x0 {
                    Some((Some(idx(x - 1, y)), mapped[idx(x - 1, y)]))
                } else if x > 0 {
                    Some((None, left[(y - block.y0) as usize]))
                } else {
                    None
                },
                if y > block.y0 {
                    Some((Some(idx(x, y - 1)), mapped[idx(x, y - 1)]))
                } else if y > 0 {
                    Some((None, top[(x - block.x0) as usize]))
                } else {
                    None
                },
            ];
            for (inside, v) in neighbours.into_iter().flatten() {
                if aa.threshold <= 0.0 || aa.differ_mapped(mc, v) {
                    hit = true;
                    if let Some(i) = inside {
                        if !done[i] {
                            done[i] = true;
                            let (nx, ny) = (block.x0 + (i % bw) as u32, block.y0 + (i / bw) as u32);
                            values[i] = supersample(nx, ny, centres[i], st);
                            mapped[i] = aa.map(values[i]);
                            st.count_supersampled();
                        }
                    }
                }
            }
            if (hit || aa.threshold <= 0.0) && !done[idx(x, y)] {
                let i = idx(x, y);
                done[i] = true;
                values[i] = supersample(x, y, c, st);
                mapped[i] = aa.map(values[i]);
                st.count_supersampled();
            }
        }
    }
    values
}

/// Something that counts supersampled pixels.
pub trait SupersampleCount {
    /// One more pixel was supersampled.
    fn count_supersampled(&mut self);
}

impl SupersampleCount for super::RenderStats {
    fn count_supersampled(&mut self) {
        self.supersampled += 1;
    }
}

/// How each pixel is sampled.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Sampling {
    /// One ray through the pixel centre (POV-Ray's `-A`).
    #[default]
    Centre,
    /// POV-Ray's adaptive supersampling.
    Adaptive(Antialias),
    /// This many rays per pixel at stratified (Owen-scrambled Sobol) positions,
    /// averaged with equal weights (a box filter).
    Fixed(u32),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_without_jitter_is_at_sub_cell_centres() {
        let aa = Antialias {
            jitter: 0.0,
            ..Antialias::default()
        };
        let xs: Vec<f64> = (0..3).map(|k| aa.grid_offset(k, (0.9, 0.1)).0).collect();
        assert_eq!(xs, vec![1.0 / 6.0, 0.5, 5.0 / 6.0]);
        assert_eq!(aa.grid_offset(3, (0.2, 0.7)).1, 0.5);
    }

    #[test]
    fn jitter_stays_inside_the_sub_cell() {
        let aa = Antialias::default();
        let (x, y) = aa.grid_offset(4, (0.0, 0.999));
        assert!((1.0 / 3.0..=2.0 / 3.0).contains(&x));
        assert!((1.0 / 3.0..=2.0 / 3.0).contains(&y));
    }

    #[test]
    fn difference_is_taken_after_antialias_gamma() {
        // Measured with povray +A0.3: white next to 0.8 grey is not supersampled
        // (0.256 after gamma 2.5) though the linear difference is 0.6; 0.05 grey
        // next to black is (0.906).
        let aa = Antialias::default();
        assert!(!aa.differ(DVec3::ONE, DVec3::splat(0.8)));
        assert!(aa.differ(DVec3::ONE, DVec3::splat(0.7)));
        assert!(aa.differ(DVec3::ZERO, DVec3::splat(0.05)));
        assert!(!aa.differ(DVec3::ZERO, DVec3::splat(0.002)));
        let all = Antialias {
            threshold: 0.0,
            ..aa
        };
        assert!(all.differ(DVec3::ONE, DVec3::ONE));
    }

    #[derive(Default)]
    struct Count(u64);
    impl SupersampleCount for Count {
        fn count_supersampled(&mut self) {
            self.0 += 1;
        }
    }

    #[test]
    fn a_pixel_compares_with_its_upper_neighbour_as_supersampled() {
        // One column: white, black, 0.3 grey. Black differs from white, so both
        // are supersampled (to 0.25 here); the grey pixel then compares with 0.25,
        // not with black, and stays one ray (POV-Ray does the same at the horizon
        // of a checkered floor).
        let centres = [1.0, 0.0, 0.3];
        let block = Block {
            x0: 0,
            y0: 0,
            x1: 1,
            y1: 3,
        };
        let mut n = Count::default();
        let v = render_block(
            &block,
            &Antialias::default(),
            |_, y, _: &mut Count| DVec3::splat(centres[y as usize]),
            |_, y, c, _: &mut Count| if y == 1 { DVec3::splat(0.25) } else { c * 0.9 },
            &mut n,
        );
        assert_eq!(n.0, 2);
        assert_eq!(
            v,
            vec![DVec3::splat(0.9), DVec3::splat(0.25), DVec3::splat(0.3)]
        );
    }

    #[test]
    fn block_borders_use_centre_colours_and_are_not_supersampled() {
        // Block starting at row 32: its first row compares with the centre of row
        // 31, which belongs to another block and is never changed here.
        let block = Block {
            x0: 0,
            y0: 32,
            x1: 2,
            y1: 33,
        };
        let mut n = Count::default();
        let v = render_block(
            &block,
            &Antialias::default(),
            |_, y, _: &mut Count| DVec3::splat(if y == 31 { 1.0 } else { 0.0 }),
            |_, _, _, _: &mut Count| DVec3::splat(0.5),
            &mut n,
        );
        assert_eq!(n.0, 2);
        assert_eq!(v, vec![DVec3::splat(0.5); 2]);
    }

    #[test]
    fn blocks_cover_the_crop_with_whole_image_blocks() {
        let crop = super::super::Crop {
            x0: 40,
            y0: 0,
            x1: 70,
            y1: 10,
        };
        let b = blocks(&crop, 80, 50);
        assert_eq!(
            b,
            vec![
                Block {
                    x0: 32,
                    y0: 0,
                    x1: 64,
                    y1: 32
                },
                Block {
                    x0: 64,
                    y0: 0,
                    x1: 80,
                    y1: 32
                },
            ]
        );
    }
}
