//! The stored photons and the estimate of the light they bring to a point: a
//! kd-tree (balanced, laid out in the photon array itself) searched for the
//! nearest photons.

use glam::{DVec3, Vec3};
use std::cell::Cell;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// One stored photon: where it landed, the unit direction it travelled and
/// the light it carries (see [`super::shoot`] for its units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Photon {
    /// Where it landed.
    pub p: Vec3,
    /// The unit direction it arrived along.
    pub dir: Vec3,
    /// Its light: the irradiance it adds spread over unit area.
    pub power: Vec3,
}

/// The photons of one render, ready for estimates.
#[derive(Clone, Debug, Default)]
pub struct PhotonMap {
    /// The photons in kd-tree order: the median of a range is its node, the
    /// halves before and after it its subtrees.
    photons: Vec<Photon>,
    /// Split axis of each node (index as `photons`).
    axis: Vec<u8>,
    /// Each photon's position (index as `photons`): what the search reads,
    /// packed so more of it stays in cache.
    pos: Vec<Vec3>,
    /// Bounds of all photons (estimates far from them stop at once).
    min: Vec3,
    max: Vec3,
    /// Radius searched first.
    radius: f64,
    /// Fewest photons an estimate wants (the radius doubles, twice at most,
    /// until it has them) and most it uses.
    gather: (usize, usize),
}

thread_local! {
    /// The radius (0: r, 1: 2r, 2: 4r) the last estimate on this thread
    /// used: where the next search starts (it changes the time, not the answer).
    static LAST_LEVEL: Cell<u32> = const { Cell::new(0) };
}

/// A candidate in the search: distance² and index, largest first in the heap.
#[derive(Clone, Copy, PartialEq)]
struct Near(f32, u32);

impl Eq for Near {}

impl PartialOrd for Near {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Near {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0).then(self.1.cmp(&other.1))
    }
}

impl PhotonMap {
    /// The map of `photons`, searched within `radius` first for at least
    /// `gather.0` and at most `gather.1` photons.
    pub fn new(mut photons: Vec<Photon>, radius: f64, gather: (u32, u32)) -> PhotonMap {
        let mut axis = vec![0u8; photons.len()];
        let (mut min, mut max) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
        for ph in &photons {
            min = min.min(ph.p);
            max = max.max(ph.p);
        }
        build(&mut photons, &mut axis);
        let pos = photons.iter().map(|ph| ph.p).collect();
        PhotonMap {
            photons,
            axis,
            pos,
            min,
            max,
            radius,
            gather: (
                gather.0.max(1) as usize,
                gather.1.max(gather.0).max(1) as usize,
            ),
        }
    }

    /// Number of photons stored.
    pub fn len(&self) -> usize {
        self.photons.len()
    }

    /// Whether no photon was stored.
    pub fn is_empty(&self) -> bool {
        self.photons.is_empty()
    }

    /// The irradiance the photons bring to point `p` of a surface whose
    /// normal on the side being lit is `n`: the light of the nearest photons
    /// (at most `gather.1`, within the search radius) that arrived from that
    /// side, over the area of the disc that holds them. Fewer than `gather.0`
    /// within the radius: the radius doubles, at most twice.
    pub fn irradiance(&self, p: DVec3, n: DVec3) -> DVec3 {
        if self.photons.is_empty() {
            return DVec3::ZERO;
        }
        let q = p.as_vec3();
        let radius = self.radius as f32;
        // How far the photons' bounds are: beyond the largest radius, no light.
        let outside = (self.min - q).max(q - self.max).max(Vec3::ZERO).length();
        if outside >= 4.0 * radius {
            return DVec3::ZERO;
        }
        // The adaptive rule: the first of the radii r, 2r, 4r within which
        // `gather.0` photons lie (else 4r). A search at a larger radius finds
        // every photon a smaller one keeps (its nearest `gather.1` include
        // them), so the search may start at the radius the last estimate on
        // this thread ended with: the same answer, found with one search
        // where photons are sparse instead of three.
        let mut heap = BinaryHeap::with_capacity(self.gather.1 + 1);
        let mut level = LAST_LEVEL.with(Cell::get);
        let (found, level) = loop {
            heap.clear();
            let r = radius * (1 << level) as f32;
            if outside < r {
                self.nearest(0, self.photons.len(), q, r * r, &mut heap);
            }
            let found = std::mem::take(&mut heap).into_sorted_vec();
            let within = |l: u32| {
                let r = radius * (1 << l) as f32;
                found.partition_point(|c| c.0 < r * r)
            };
            let chosen = (0..=level).find(|&l| within(l) >= self.gather.0);
            match chosen {
                Some(l) => {
                    let n = within(l);
                    let mut found = found;
                    found.truncate(n);
                    break (found, l);
                }
                None if level == 2 => break (found, 2),
                None => level += 1,
            }
        };
        LAST_LEVEL.with(|c| c.set(level));
        if found.is_empty() {
            return DVec3::ZERO;
        }
        let r2 = if found.len() == self.gather.1 {
            f64::from(found[found.len() - 1].0)
        } else {
            let r = radius * (1 << level) as f32;
            f64::from(r * r)
        };
        if r2 <= 0.0 {
            return DVec3::ZERO;
        }
        let n32 = n.as_vec3();
        let mut sum = DVec3::ZERO;
        for c in &found {
            let ph = &self.photons[c.1 as usize];
            // Only photons that arrived from the lit side.
            if ph.dir.dot(n32) < 0.0 {
                sum += ph.power.as_dvec3();
            }
        }
        sum / (std::f64::consts::PI * r2)
    }

    /// Keeps `cand` in `heap` when nearer than `r2`, at most `gather.1` kept;
    /// once full, `r2` shrinks to the farthest kept.
    #[inline(always)]
    fn offer(&self, heap: &mut BinaryHeap<Near>, cand: Near, r2: &mut f32) {
        if cand.0 < *r2 {
            heap.push(cand);
            if heap.len() > self.gather.1 {
                heap.pop();
            }
            if heap.len() == self.gather.1 {
                *r2 = heap.peek().map_or(*r2, |c| c.0);
            }
        }
    }

    /// Adds to `heap` the photons of range `lo..hi` nearer `q` than `r2`
    /// (squared), keeping the nearest `gather.1`.
    fn nearest(&self, lo: usize, hi: usize, q: Vec3, mut r2: f32, heap: &mut BinaryHeap<Near>) {
        if hi - lo <= LEAF {
            for (i, p) in self.pos[lo..hi].iter().enumerate() {
                self.offer(
                    heap,
                    Near((*p - q).length_squared(), (lo + i) as u32),
                    &mut r2,
                );
            }
            return;
        }
        let mid = (lo + hi) / 2;
        let p = self.pos[mid];
        let a = usize::from(self.axis[mid]);
        let delta = q[a] - p[a];
        let (first, second) = if delta < 0.0 {
            ((lo, mid), (mid + 1, hi))
        } else {
            ((mid + 1, hi), (lo, mid))
        };
        self.nearest(first.0, first.1, q, r2, heap);
        if heap.len() == self.gather.1 {
            r2 = heap.peek().map_or(r2, |c| c.0);
        }
        self.offer(heap, Near((p - q).length_squared(), mid as u32), &mut r2);
        if delta * delta < r2 {
            self.nearest(second.0, second.1, q, r2, heap);
        }
    }
}

/// Ranges of at most this many photons are leaves, searched one by one.
const LEAF: usize = 16;

/// Orders `photons` as a balanced kd-tree (each range's median is its node,
/// split across the range's longest side), recording the split axes.
fn build(photons: &mut [Photon], axis: &mut [u8]) {
    if photons.len() <= LEAF {
        return;
    }
    let (mut min, mut max) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for ph in photons.iter() {
        min = min.min(ph.p);
        max = max.max(ph.p);
    }
    let ext = max - min;
    let a = if ext.x >= ext.y && ext.x >= ext.z {
        0
    } else if ext.y >= ext.z {
        1
    } else {
        2
    };
    let mid = photons.len() / 2;
    photons.select_nth_unstable_by(mid, |p, q| p.p[a].total_cmp(&q.p[a]));
    axis[mid] = a as u8;
    let (lo, rest) = photons.split_at_mut(mid);
    let (alo, arest) = axis.split_at_mut(mid);
    build(lo, alo);
    build(&mut rest[1..], &mut arest[1..]);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn photon(x: f32, y: f32, z: f32) -> Photon {
        Photon {
            p: Vec3::new(x, y, z),
            dir: Vec3::NEG_Y,
            power: Vec3::ONE,
        }
    }

    #[test]
    fn nearest_matches_brute_force() {
        let mut s = 12345u64;
        let mut rnd = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 40) as f32) / (1u64 << 24) as f32
        };
        let photons: Vec<Photon> = (0..2000).map(|_| photon(rnd(), 0.0, rnd())).collect();
        let map = PhotonMap::new(photons.clone(), 0.1, (5, 30));
        for _ in 0..50 {
            let q = Vec3::new(rnd(), 0.0, rnd());
            let mut heap = BinaryHeap::new();
            map.nearest(0, map.len(), q, 0.01, &mut heap);
            let mut got: Vec<f32> = heap.into_iter().map(|c| c.0).collect();
            got.sort_by(f32::total_cmp);
            let mut want: Vec<f32> = photons
                .iter()
                .map(|p| (p.p - q).length_squared())
                .filter(|&d| d < 0.01)
                .collect();
            want.sort_by(f32::total_cmp);
            want.truncate(30);
            assert_eq!(got, want);
        }
    }

    #[test]
    fn a_uniform_grid_estimates_its_density() {
        // Photons 0.01 apart, each of power 1e-4: irradiance 1 everywhere.
        let mut photons = Vec::new();
        for i in 0..200 {
            for j in 0..200 {
                let mut p = photon(i as f32 * 0.01, 0.0, j as f32 * 0.01);
                p.power = Vec3::splat(1e-4);
                photons.push(p);
            }
        }
        let map = PhotonMap::new(photons, 0.06, (20, 100));
        let e = map.irradiance(DVec3::new(1.0, 0.0, 1.0), DVec3::Y);
        assert!((e.x - 1.0).abs() < 0.1, "{e}");
        // Seen from below, photons that came down light nothing.
        assert_eq!(
            map.irradiance(DVec3::new(1.0, 0.0, 1.0), DVec3::NEG_Y),
            DVec3::ZERO
        );
        // Far away: nothing.
        assert_eq!(
            map.irradiance(DVec3::new(9.0, 0.0, 9.0), DVec3::Y),
            DVec3::ZERO
        );
    }
}
