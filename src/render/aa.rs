//! How pixels are sampled: one ray, POV-Ray's adaptive anti-aliasing, or a fixed
//! number of jittered samples.

use glam::DVec3;

/// POV-Ray 3.7's non-recursive adaptive anti-aliasing (`Sampling_Method=1`,
/// `+A0.3 +R3 +J1.0`), measured against `povray`:
///
/// * every pixel first gets one ray through its centre;
/// * a pixel is supersampled when its centre colour differs from that of a
///   neighbour (left, above, right or below: a difference found between two
///   pixels supersamples both) by at least `threshold`, the difference being
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
        let g = |c: DVec3| c.clamp(DVec3::ZERO, DVec3::ONE).powf(1.0 / self.gamma);
        let d = (g(a) - g(b)).abs();
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
}
