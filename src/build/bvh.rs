//! A bounding volume hierarchy over the bounded primitives, built with binned SAH.

use super::{Aabb, Ray};
use glam::DVec3;

/// Number of SAH bins per axis.
const BINS: usize = 16;
/// Most primitives a leaf holds before splitting is considered.
const MAX_LEAF: usize = 4;
/// Cost of one node traversal relative to one primitive test.
const TRAVERSAL_COST: f64 = 1.0;
/// Depth after which nodes are halved by count, so depth stays below [`STACK`]
/// (64 + log2 of the primitive count).
const MAX_SAH_DEPTH: usize = 64;
/// Traversal stack size.
const STACK: usize = 128;

/// One flattened node: an interior node's children are `first` and `first + 1`; a
/// leaf holds `count` entries of [`Bvh::prims`] starting at `first`.
#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    first: u32,
    count: u32,
}

/// A binned-SAH BVH over primitive indices.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    /// Primitive indices, ordered so every leaf's are contiguous.
    prims: Vec<u32>,
}

impl Bvh {
    /// Builds a hierarchy over `items`: (primitive index, world bounds).
    pub fn build(items: &[(u32, Aabb)]) -> Bvh {
        let mut bvh = Bvh {
            nodes: Vec::with_capacity(2 * items.len().max(1)),
            prims: items.iter().map(|&(i, _)| i).collect(),
        };
        if items.is_empty() {
            return bvh;
        }
        let boxes: Vec<Aabb> = items.iter().map(|&(_, b)| b).collect();
        let centroids: Vec<DVec3> = boxes.iter().map(Aabb::centroid).collect();
        let mut order: Vec<usize> = (0..items.len()).collect();
        bvh.nodes.push(Node {
            bounds: Aabb::EMPTY,
            first: 0,
            count: 0,
        });
        bvh.split(0, &mut order, 0, 0, &boxes, &centroids);
        bvh.prims = order.iter().map(|&k| items[k].0).collect();
        bvh
    }

    /// Fills node `node` with `order`, which sits at `start` in the final order,
    /// recursing; `depth` bounds the traversal stack.
    fn split(
        &mut self,
        node: usize,
        order: &mut [usize],
        start: usize,
        depth: usize,
        boxes: &[Aabb],
        cents: &[DVec3],
    ) {
        let bounds = order.iter().fold(Aabb::EMPTY, |b, &k| b.union(&boxes[k]));
        self.nodes[node] = Node {
            bounds,
            first: start as u32,
            count: order.len() as u32,
        };
        if order.len() <= MAX_LEAF {
            return;
        }
        let cb = order.iter().fold(Aabb::EMPTY, |b, &k| b.grow(cents[k]));
        let mid = if depth >= MAX_SAH_DEPTH {
            // Deep, lopsided trees could overflow the traversal stack: halve by count.
            median_split(order, cents, &cb)
        } else {
            let Some((axis, pos)) = best_split(order, boxes, cents, &cb) else {
                return;
            };
            match partition(order, |&k| cents[k][axis] < pos) {
                0 => median_split(order, cents, &cb),
                m if m == order.len() => median_split(order, cents, &cb),
                m => m,
            }
        };
        let left = self.nodes.len();
        self.nodes.push(Node {
            bounds: Aabb::EMPTY,
            first: 0,
            count: 0,
        });
        self.nodes.push(Node {
            bounds: Aabb::EMPTY,
            first: 0,
            count: 0,
        });
        self.nodes[node] = Node {
            bounds,
            first: left as u32,
            count: 0,
        };
        let (lo, hi) = order.split_at_mut(mid);
        self.split(left, lo, start, depth + 1, boxes, cents);
        self.split(left + 1, hi, start + mid, depth + 1, boxes, cents);
    }

    /// World bounds of everything in the hierarchy.
    pub fn bounds(&self) -> Aabb {
        self.nodes.first().map_or(Aabb::EMPTY, |n| n.bounds)
    }

    /// Number of nodes (for statistics and tests).
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Visits leaves the ray may hit, nearest-first. `visit(prim, t_max)` tests one
    /// primitive and returns the new `t_max` (shrunk when it found a closer hit) or
    /// `None` to stop the traversal early.
    #[inline]
    pub fn traverse(
        &self,
        ray: &Ray,
        t_min: f64,
        mut t_max: f64,
        mut visit: impl FnMut(u32, f64) -> Option<f64>,
    ) {
        if self.nodes.is_empty() {
            return;
        }
        let inv = ray.dir.recip();
        let mut stack = [0u32; STACK];
        let mut sp = 0usize;
        let mut node = 0usize;
        if self.nodes[0].bounds.hit(ray, inv, t_min, t_max).is_none() {
            return;
        }
        loop {
            let n = self.nodes[node];
            if n.count > 0 {
                for &p in &self.prims[n.first as usize..(n.first + n.count) as usize] {
                    match visit(p, t_max) {
                        Some(t) => t_max = t,
                        None => return,
                    }
                }
            } else {
                let (a, b) = (n.first as usize, n.first as usize + 1);
                let ta = self.nodes[a].bounds.hit(ray, inv, t_min, t_max);
                let tb = self.nodes[b].bounds.hit(ray, inv, t_min, t_max);
                match (ta, tb) {
                    (Some(x), Some(y)) => {
                        let (near, far) = if x <= y { (a, b) } else { (b, a) };
                        stack[sp] = far as u32;
                        sp += 1;
                        node = near;
                        continue;
                    }
                    (Some(_), None) => {
                        node = a;
                        continue;
                    }
                    (None, Some(_)) => {
                        node = b;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            // Pop, skipping nodes the shrunk interval no longer reaches.
            loop {
                if sp == 0 {
                    return;
                }
                sp -= 1;
                let cand = stack[sp] as usize;
                if self.nodes[cand]
                    .bounds
                    .hit(ray, inv, t_min, t_max)
                    .is_some()
                {
                    node = cand;
                    break;
                }
            }
        }
    }
}

/// The SAH-best (axis, plane position) over binned centroids, or `None` when no
/// split beats a leaf.
fn best_split(order: &[usize], boxes: &[Aabb], cents: &[DVec3], cb: &Aabb) -> Option<(usize, f64)> {
    let mut best: Option<(f64, usize, f64)> = None;
    for axis in 0..3 {
        let (lo, hi) = (cb.min[axis], cb.max[axis]);
        if hi - lo <= 0.0 || !(hi - lo).is_finite() {
            continue;
        }
        let scale = BINS as f64 / (hi - lo);
        let bin_of = |c: f64| (((c - lo) * scale) as usize).min(BINS - 1);
        let mut bins = [(Aabb::EMPTY, 0usize); BINS];
        for &k in order {
            let b = &mut bins[bin_of(cents[k][axis])];
            b.0 = b.0.union(&boxes[k]);
            b.1 += 1;
        }
        // Sweep from the right to get suffix areas and counts.
        let mut right = [(0.0, 0usize); BINS];
        let mut acc = (Aabb::EMPTY, 0usize);
        for i in (1..BINS).rev() {
            acc = (acc.0.union(&bins[i].0), acc.1 + bins[i].1);
            right[i] = (acc.0.half_area(), acc.1);
        }
        let mut left = (Aabb::EMPTY, 0usize);
        for i in 0..BINS - 1 {
            left = (left.0.union(&bins[i].0), left.1 + bins[i].1);
            let (ra, rn) = right[i + 1];
            if left.1 == 0 || rn == 0 {
                continue;
            }
            let cost = left.0.half_area() * left.1 as f64 + ra * rn as f64;
            if best.is_none_or(|(c, _, _)| cost < c) {
                best = Some((cost, axis, lo + (i + 1) as f64 / scale));
            }
        }
    }
    let parent_area = order
        .iter()
        .fold(Aabb::EMPTY, |b, &k| b.union(&boxes[k]))
        .half_area();
    let (cost, axis, pos) = best?;
    let split_cost = TRAVERSAL_COST + cost / parent_area.max(f64::MIN_POSITIVE);
    (split_cost < order.len() as f64 || order.len() > 4 * MAX_LEAF).then_some((axis, pos))
}

/// Splits `order` in two equal halves along the widest centroid axis.
fn median_split(order: &mut [usize], cents: &[DVec3], cb: &Aabb) -> usize {
    let ext = cb.max - cb.min;
    let axis = if ext.x >= ext.y && ext.x >= ext.z {
        0
    } else if ext.y >= ext.z {
        1
    } else {
        2
    };
    let mid = order.len() / 2;
    order.select_nth_unstable_by(mid, |&a, &b| cents[a][axis].total_cmp(&cents[b][axis]));
    mid
}

/// Moves the elements satisfying `pred` to the front; returns how many there are.
fn partition<T>(v: &mut [T], pred: impl Fn(&T) -> bool) -> usize {
    let mut i = 0;
    for j in 0..v.len() {
        if pred(&v[j]) {
            v.swap(i, j);
            i += 1;
        }
    }
    i
}
