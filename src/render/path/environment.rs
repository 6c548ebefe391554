//! The environment (`sky_sphere` over `background`) as a light: a latitude-longitude
//! table of its brightness, sampled in proportion to it (piecewise constant, with a
//! floor so every direction keeps a non-zero density). Radiance itself is always
//! looked up exactly with [`crate::render::sky`]; the table only shapes the density.
//! A uniform environment is not sampled this way: cosine-weighted BSDF sampling is
//! already ideal for it.

use crate::build::World;
use crate::render::sky;
use glam::DVec3;
use std::f64::consts::PI;

/// Table size: longitude cells (latitude has half as many).
const WIDTH: usize = 128;
const HEIGHT: usize = WIDTH / 2;

/// An environment prepared for importance sampling.
#[derive(Clone, Debug)]
pub struct Environment {
    /// Cumulative row weights (latitude), normalised to end at 1.
    rows: Vec<f64>,
    /// Per row, cumulative cell weights, normalised to end at 1.
    cells: Vec<Vec<f64>>,
    /// Each cell's probability (row × cell).
    prob: Vec<f64>,
}

/// The brightness a direction is sampled by.
fn weight(c: DVec3) -> f64 {
    c.max(DVec3::ZERO).dot(DVec3::new(0.2126, 0.7152, 0.0722))
}

/// Direction of latitude-longitude point (`u`, `v`) in [0, 1)²: v = 0 is +y.
fn direction(u: f64, v: f64) -> DVec3 {
    let theta = v * PI;
    let phi = u * 2.0 * PI;
    let s = theta.sin();
    DVec3::new(s * phi.cos(), theta.cos(), s * phi.sin())
}

/// Inverse of [`direction`].
fn uv(d: DVec3) -> (f64, f64) {
    let v = d.y.clamp(-1.0, 1.0).acos() / PI;
    let mut u = d.z.atan2(d.x) / (2.0 * PI);
    if u < 0.0 {
        u += 1.0;
    }
    (u.min(1.0 - 1e-12), v.min(1.0 - 1e-12))
}

impl Environment {
    /// The table of `world`'s environment; `None` when it is black or uniform.
    pub fn new(world: &World) -> Option<Environment> {
        let mut lum = vec![0.0; WIDTH * HEIGHT];
        for j in 0..HEIGHT {
            for i in 0..WIDTH {
                // The brightest of a few points, so thin bright features are kept.
                let mut m: f64 = 0.0;
                for (a, b) in [
                    (0.25, 0.25),
                    (0.75, 0.25),
                    (0.25, 0.75),
                    (0.75, 0.75),
                    (0.5, 0.5),
                ] {
                    let d = direction(
                        (i as f64 + a) / WIDTH as f64,
                        (j as f64 + b) / HEIGHT as f64,
                    );
                    m = m.max(weight(sky(world, d)));
                }
                lum[j * WIDTH + i] = m;
            }
        }
        let (lo, hi) = lum
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
        if hi <= 0.0 || hi - lo <= 1e-6 * hi {
            return None;
        }
        let mean = lum.iter().sum::<f64>() / lum.len() as f64;
        let mut prob = vec![0.0; WIDTH * HEIGHT];
        let mut total = 0.0;
        for j in 0..HEIGHT {
            let sin = ((j as f64 + 0.5) / HEIGHT as f64 * PI).sin();
            for i in 0..WIDTH {
                let w = (lum[j * WIDTH + i] + 0.05 * mean) * sin;
                prob[j * WIDTH + i] = w;
                total += w;
            }
        }
        for p in &mut prob {
            *p /= total;
        }
        let mut rows = Vec::with_capacity(HEIGHT);
        let mut cells = Vec::with_capacity(HEIGHT);
        let mut acc = 0.0;
        for j in 0..HEIGHT {
            let row = &prob[j * WIDTH..(j + 1) * WIDTH];
            let sum: f64 = row.iter().sum();
            acc += sum;
            rows.push(acc);
            let mut c = 0.0;
            cells.push(
                row.iter()
                    .map(|p| {
                        c += p / sum;
                        c
                    })
                    .collect(),
            );
        }
        if let Some(last) = rows.last_mut() {
            *last = 1.0;
        }
        Some(Environment { rows, cells, prob })
    }

    /// A direction and its solid-angle density, from a point on the unit square.
    pub fn sample(&self, (a, b): (f64, f64)) -> (DVec3, f64) {
        let j = self.rows.partition_point(|c| *c <= a).min(HEIGHT - 1);
        let row = &self.cells[j];
        let i = row.partition_point(|c| *c <= b).min(WIDTH - 1);
        // Uniform within the cell, using what is left of the two numbers.
        let r0 = if j == 0 { 0.0 } else { self.rows[j - 1] };
        let fa = ((a - r0) / (self.rows[j] - r0).max(1e-300)).clamp(0.0, 1.0);
        let c0 = if i == 0 { 0.0 } else { row[i - 1] };
        let fb = ((b - c0) / (row[i] - c0).max(1e-300)).clamp(0.0, 1.0);
        let d = direction(
            (i as f64 + fb) / WIDTH as f64,
            (j as f64 + fa) / HEIGHT as f64,
        );
        (d, self.pdf(d))
    }

    /// Solid-angle density of [`Environment::sample`] returning unit direction `d`.
    pub fn pdf(&self, d: DVec3) -> f64 {
        let (u, v) = uv(d);
        let (i, j) = ((u * WIDTH as f64) as usize, (v * HEIGHT as f64) as usize);
        let p = self.prob[j.min(HEIGHT - 1) * WIDTH + i.min(WIDTH - 1)];
        let sin = (v * PI).sin().max(1e-12);
        // A cell spans (2π / W) × (π / H) in (φ, θ); dω = sin θ dθ dφ.
        p * (WIDTH * HEIGHT) as f64 / (2.0 * PI * PI * sin)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directions_and_coordinates_round_trip() {
        for (u, v) in [(0.1, 0.2), (0.7, 0.9), (0.5, 0.5)] {
            let (a, b) = uv(direction(u, v));
            assert!((a - u).abs() < 1e-12 && (b - v).abs() < 1e-12);
        }
    }
}
