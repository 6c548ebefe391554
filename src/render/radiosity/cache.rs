//! The irradiance cache: gathered values kept with their place, orientation and
//! reuse radius, found again by a hashed grid per reuse-radius scale.

use glam::DVec3;
use rustc_hash::FxHashMap;

/// One gathered value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Where it was gathered.
    pub p: DVec3,
    /// The (unit) normal it was gathered about.
    pub n: DVec3,
    /// The mean light arriving over the hemisphere (cosine-weighted).
    pub e: DVec3,
    /// Reuse radius: the harmonic mean distance of what the gathering rays
    /// met, clamped by `minimum_reuse` and `maximum_reuse`.
    pub r: f64,
    /// The radiosity bounce it serves (0: surfaces seen by camera, reflected
    /// and refracted rays).
    pub depth: u32,
}

impl Sample {
    /// Ward's blending weight of this value at `p` with normal `n` under error
    /// bound `eb`, or `None` where it may not be reused: its estimated error
    /// `|p − pᵢ| / rᵢ + √(1 − n·nᵢ)` must stay below `eb`, and `p` must not lie
    /// behind the value's tangent plane (the value would see what `p` cannot).
    /// The weight `1/error − 1/eb` falls to zero at the bound, so values fade
    /// in and out without seams.
    pub fn weight(&self, p: DVec3, n: DVec3, eb: f64) -> Option<f64> {
        let cos = n.dot(self.n);
        if cos <= 0.0 {
            return None;
        }
        let d = p - self.p;
        if d.dot(n + self.n) < -0.1 * self.r {
            return None;
        }
        let err = d.length() / self.r + (1.0 - cos).max(0.0).sqrt();
        (err < eb).then(|| 1.0 / err.max(1e-6) - 1.0 / eb)
    }
}

/// A running weighted mean of reusable values.
#[derive(Clone, Copy, Debug, Default)]
pub struct Blend {
    /// Sum of weights.
    pub weight: f64,
    /// Sum of weighted values.
    pub sum: DVec3,
    /// Values blended.
    pub count: u32,
}

impl Blend {
    /// Adds `s` if it may be reused at `p`, `n`.
    pub fn add(&mut self, s: &Sample, p: DVec3, n: DVec3, eb: f64) {
        if let Some(w) = s.weight(p, n, eb) {
            self.weight += w;
            self.sum += w * s.e;
            self.count += 1;
        }
    }

    /// The blended value (zero when empty).
    pub fn value(&self) -> DVec3 {
        if self.weight > 0.0 {
            self.sum / self.weight
        } else {
            DVec3::ZERO
        }
    }
}

/// Key of a grid cell: (bounce, scale level, cell coordinates).
type Cell = (u32, i32, [i64; 3]);

/// Every value gathered so far, indexed for lookup.
#[derive(Clone, Debug, Default)]
pub struct Cache {
    samples: Vec<Sample>,
    /// A value of reuse reach `ρ` (radius times the largest error bound) is
    /// filed in the cells of side `2^⌈log2 ρ⌉` its sphere of reach touches, so
    /// a lookup visits one cell per level.
    cells: FxHashMap<Cell, Vec<u32>>,
    /// (bounce, level) pairs in use, sorted.
    levels: Vec<(u32, i32)>,
    /// The largest error bound lookups use.
    reach: f64,
}

impl Cache {
    /// An empty cache for lookups with error bounds up to `error_bound`.
    pub fn new(error_bound: f64) -> Cache {
        Cache {
            reach: error_bound,
            ..Cache::default()
        }
    }

    /// Number of values.
    pub fn len(&self) -> usize {
        self.samples.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }

    /// The values, in the order they were added.
    pub fn into_samples(self) -> Vec<Sample> {
        self.samples
    }

    /// Adds a value.
    pub fn push(&mut self, s: Sample) {
        let reach = (s.r * self.reach).max(1e-12);
        // Up to 2^1023, the largest finite power of two, so a cell is never
        // smaller than the reach (a cap of 2^60 once filed a value of reach
        // 1e30, seen from a camera that far out, in 1e12³ cells).
        let level = (reach.log2().ceil() as i32).clamp(-60, 1023);
        let size = 2f64.powi(level);
        let lo = ((s.p - DVec3::splat(reach)) / size).floor();
        let hi = ((s.p + DVec3::splat(reach)) / size).floor();
        // The sphere of reach spans at most 3 cells along an axis; more only
        // where `p ± reach` overflowed to infinity near f64's end.
        let span = |lo: f64, hi: f64| {
            let lo = lo as i64;
            lo..=(hi as i64).clamp(lo, lo.saturating_add(2))
        };
        let index = self.samples.len() as u32;
        self.samples.push(s);
        for x in span(lo.x, hi.x) {
            for y in span(lo.y, hi.y) {
                for z in span(lo.z, hi.z) {
                    self.cells
                        .entry((s.depth, level, [x, y, z]))
                        .or_default()
                        .push(index);
                }
            }
        }
        if let Err(at) = self.levels.binary_search(&(s.depth, level)) {
            self.levels.insert(at, (s.depth, level));
        }
    }

    /// Adds to `blend` the values of bounce `depth` reusable at `p`, `n`.
    pub fn blend(&self, p: DVec3, n: DVec3, depth: u32, eb: f64, blend: &mut Blend) {
        let from = self.levels.partition_point(|&(d, _)| d < depth);
        for &(d, level) in &self.levels[from..] {
            if d != depth {
                break;
            }
            let c = (p / 2f64.powi(level)).floor();
            let key = (depth, level, [c.x as i64, c.y as i64, c.z as i64]);
            if let Some(list) = self.cells.get(&key) {
                for &i in list {
                    blend.add(&self.samples[i as usize], p, n, eb);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(p: DVec3, r: f64) -> Sample {
        Sample {
            p,
            n: DVec3::Y,
            e: DVec3::splat(p.x),
            r,
            depth: 0,
        }
    }

    #[test]
    fn lookup_finds_what_a_scan_finds() {
        let mut cache = Cache::new(1.8);
        let mut all = Vec::new();
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..500 {
            let s = sample(
                DVec3::new(next() * 10.0, 0.0, next() * 10.0),
                0.05 + next() * next() * 3.0,
            );
            cache.push(s);
            all.push(s);
        }
        for _ in 0..200 {
            let p = DVec3::new(next() * 10.0, 0.0, next() * 10.0);
            for eb in [0.5, 1.8] {
                let mut fast = Blend::default();
                cache.blend(p, DVec3::Y, 0, eb, &mut fast);
                let mut slow = Blend::default();
                for s in &all {
                    slow.add(s, p, DVec3::Y, eb);
                }
                assert_eq!(fast.count, slow.count);
                assert!((fast.value() - slow.value()).length() < 1e-9);
            }
        }
    }

    #[test]
    fn weights_fall_to_zero_at_the_bound_and_refuse_facing_away() {
        let s = sample(DVec3::ZERO, 1.0);
        assert!(s.weight(DVec3::new(0.5, 0.0, 0.0), DVec3::Y, 1.0).unwrap() > 0.0);
        assert!(
            s.weight(DVec3::new(0.999, 0.0, 0.0), DVec3::Y, 1.0)
                .unwrap()
                < 0.01
        );
        assert!(s
            .weight(DVec3::new(1.01, 0.0, 0.0), DVec3::Y, 1.0)
            .is_none());
        assert!(s.weight(DVec3::ZERO, -DVec3::Y, 1.8).is_none());
        // Below the value's tangent plane (a step down): not reused.
        assert!(s
            .weight(DVec3::new(0.0, -0.5, 0.0), DVec3::Y, 1.8)
            .is_none());
    }
}
