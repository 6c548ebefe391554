//! `density_file df3 "FILE"`: a grid of values filling the unit cube, read from
//! POV-Ray's DF3 format.

/// The most voxels a DF3 file may hold (1024³: 4 GiB of f32 would be too many;
/// this is 256 Mi voxels, 1 GiB).
pub const DF3_MAX_VOXELS: usize = 1 << 28;

/// A DF3 grid: `size[0]` × `size[1]` × `size[2]` values in [0, 1], x fastest,
/// over the unit cube.
#[derive(Clone, Debug, PartialEq)]
pub struct DensityGrid {
    /// Voxels along x, y and z.
    pub size: [usize; 3],
    /// The values, x fastest, then y, then z.
    pub values: Vec<f32>,
    /// `interpolate`: 0 nearest voxel, 1 trilinear, 2 tricubic (Catmull-Rom).
    pub interpolate: u8,
}

impl DensityGrid {
    /// Parses a DF3 file: three big-endian 16-bit sizes, then the voxels, big-endian,
    /// 1, 2 or 4 bytes each (as many as the file holds), scaled to [0, 1] by the
    /// largest value of their width.
    pub fn parse(bytes: &[u8], interpolate: u8) -> Result<DensityGrid, String> {
        if bytes.len() < 6 {
            return Err("the file is shorter than the 6-byte DF3 header".into());
        }
        let dim = |i: usize| usize::from(u16::from_be_bytes([bytes[2 * i], bytes[2 * i + 1]]));
        let size = [dim(0), dim(1), dim(2)];
        let count = size[0] * size[1] * size[2];
        if count == 0 {
            return Err(format!(
                "the header gives a size of {}×{}×{}",
                size[0], size[1], size[2]
            ));
        }
        if count > DF3_MAX_VOXELS {
            return Err(format!(
                "{count} voxels is more than rts reads ({DF3_MAX_VOXELS})"
            ));
        }
        let data = &bytes[6..];
        let width = data.len() / count;
        let values: Vec<f32> = match width {
            1 => data[..count].iter().map(|&b| f32::from(b) / 255.0).collect(),
            2 => data[..2 * count]
                .chunks_exact(2)
                .map(|c| f32::from(u16::from_be_bytes([c[0], c[1]])) / 65535.0)
                .collect(),
            w if w >= 4 => data[..4 * count]
                .chunks_exact(4)
                .map(|c| (f64::from(u32::from_be_bytes([c[0], c[1], c[2], c[3]])) / 4_294_967_295.0) as f32)
                .collect(),
            _ => {
                return Err(format!(
                    "the header gives {count} voxels but the file holds {} bytes of data (1, 2 or 4 per voxel)",
                    data.len()
                ))
            }
        };
        Ok(DensityGrid {
            size,
            values,
            interpolate,
        })
    }

    /// The value at point `p`: 0 outside the unit cube. As POV-Ray 3.7 reads it
    /// (measured): voxel `i` of `n` covers `[i/n, (i+1)/n)` without
    /// interpolation; trilinear and tricubic interpolation put voxel `i` at
    /// `i/n` and wrap round from the last voxel to the first (tricubic's voxel
    /// before the first is a quirk: see below); tricubic is
    /// Catmull-Rom, so it may overshoot 1 (undershoots read as 0).
    pub fn value(&self, p: glam::DVec3) -> f64 {
        if !(0.0..1.0).contains(&p.x) || !(0.0..1.0).contains(&p.y) || !(0.0..1.0).contains(&p.z) {
            return 0.0;
        }
        let [nx, ny, nz] = self.size;
        let at = |i: usize, j: usize, k: usize| f64::from(self.values[(k * ny + j) * nx + i]);
        let u = [p.x * nx as f64, p.y * ny as f64, p.z * nz as f64];
        match self.interpolate {
            0 => {
                let idx = |t: f64, n: usize| (t as usize).min(n - 1);
                at(idx(u[0], nx), idx(u[1], ny), idx(u[2], nz))
            }
            1 => {
                let split = |t: f64, n: usize| {
                    let i = (t as usize).min(n - 1);
                    (i, (i + 1) % n, t - i as f64)
                };
                let (x0, x1, fx) = split(u[0], nx);
                let (y0, y1, fy) = split(u[1], ny);
                let (z0, z1, fz) = split(u[2], nz);
                let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
                let plane = |k: usize| {
                    lerp(
                        lerp(at(x0, y0, k), at(x1, y0, k), fx),
                        lerp(at(x0, y1, k), at(x1, y1, k), fx),
                        fy,
                    )
                };
                lerp(plane(z0), plane(z1), fz)
            }
            _ => {
                // Catmull-Rom weights of the four voxels around each axis.
                let taps = |t: f64, n: usize| {
                    let i = (t as usize).min(n - 1);
                    let f = t - i as f64;
                    let w = [
                        0.5 * (-f + 2.0 * f * f - f * f * f),
                        0.5 * (2.0 - 5.0 * f * f + 3.0 * f * f * f),
                        0.5 * (f + 4.0 * f * f - 3.0 * f * f * f),
                        0.5 * (-f * f + f * f * f),
                    ];
                    // The voxel before the first is voxel (2⁶⁴ − 1) mod n, as
                    // POV-Ray reads it (measured: the last of 2 or 4 voxels, the
                    // first of 5, the second of 7).
                    let before = if i == 0 {
                        (u64::MAX % n as u64) as usize
                    } else {
                        i - 1
                    };
                    let idx = [before, i, (i + 1) % n, (i + 2) % n];
                    (idx, w)
                };
                let (xi, xw) = taps(u[0], nx);
                let (yi, yw) = taps(u[1], ny);
                let (zi, zw) = taps(u[2], nz);
                let mut sum = 0.0;
                for c in 0..4 {
                    for b in 0..4 {
                        for a in 0..4 {
                            sum += xw[a] * yw[b] * zw[c] * at(xi[a], yi[b], zi[c]);
                        }
                    }
                }
                // Undershoots read as 0, overshoots above 1 are kept (a colour
                // map then wraps them), as in POV-Ray.
                sum.max(0.0)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn grid(values: &[u8], interpolate: u8) -> DensityGrid {
        let mut bytes = vec![0, values.len() as u8, 0, 1, 0, 1];
        bytes.extend_from_slice(values);
        DensityGrid::parse(&bytes, interpolate).expect("parse")
    }

    #[test]
    fn reads_the_three_widths_and_rejects_short_files() {
        let g = DensityGrid::parse(&[0, 2, 0, 1, 0, 1, 0, 0, 255, 255], 0).unwrap();
        assert_eq!(g.values, vec![0.0, 1.0]);
        let g = DensityGrid::parse(&[0, 1, 0, 1, 0, 1, 255, 255, 255, 255], 0).unwrap();
        assert_eq!(g.values, vec![1.0]);
        assert!(DensityGrid::parse(&[0, 2, 0, 1, 0, 1, 7], 0).is_err());
        assert!(DensityGrid::parse(&[0, 0, 0, 1, 0, 1], 0).is_err());
        assert!(DensityGrid::parse(&[0, 2], 0).is_err());
    }

    #[test]
    fn samples_as_povray_does() {
        // POV-Ray 3.7 with [0, 85, 170, 255] along x (measured at x = 0.025 +
        // 0.05 k): nearest 0 up to x = 0.25; trilinear 0.9 at 0.775 (wrapping
        // to the first voxel); tricubic 0.0833 at 0.125 and 1.0206 at 0.725.
        let v = |g: &DensityGrid, x: f64| g.value(DVec3::new(x, 0.5, 0.5));
        let g = grid(&[0, 85, 170, 255], 0);
        assert_eq!(v(&g, 0.225), 0.0);
        assert!((v(&g, 0.275) - 1.0 / 3.0).abs() < 1e-6);
        assert_eq!(v(&g, -0.01), 0.0);
        assert_eq!(v(&g, 1.01), 0.0);
        let g = grid(&[0, 85, 170, 255], 1);
        assert!((v(&g, 0.775) - 0.9).abs() < 1e-6);
        assert!((v(&g, 0.025) - 1.0 / 30.0).abs() < 1e-6);
        let g = grid(&[0, 85, 170, 255], 2);
        assert!((v(&g, 0.125) - 1.0 / 12.0).abs() < 1e-6);
        assert!((v(&g, 0.725) - 1.0206).abs() < 1e-3);
        // With 5 voxels [200, 10, 90, 30, 250] POV-Ray shows 0.720 at x = 0.025:
        // the voxel before the first is the first itself there.
        let g = grid(&[200, 10, 90, 30, 250], 2);
        assert!((v(&g, 0.025) - 0.7194).abs() < 1e-3, "{}", v(&g, 0.025));
    }
}
