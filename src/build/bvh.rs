//! A bounding volume hierarchy built with binned SAH, in parallel near the root.
//! Nodes hold f32 bounds rounded outwards (32 bytes a node), so a mesh of a
//! million triangles keeps its tree small; rays stay f64. The built binary tree
//! is then laid out for its walk: widened to f64 (the world's and small meshes',
//! [`super::binary`]) or collapsed to 4-wide nodes (large meshes', [`super::wide`]).

use super::binary::{self, Node64};
use super::wide::{self, Wide};
use super::{Aabb, Ray};
use glam::Vec3;

/// Number of SAH bins per axis.
const BINS: usize = 16;
/// Most primitives a mesh leaf holds before splitting is considered.
const MAX_LEAF: usize = 4;
/// The same for the hierarchy over a world's primitives, where a primitive test
/// (a transformed box, a torus, a CSG) costs more than a node test: leaves of one
/// primitive unless the SAH prefers more (the Cornell box's walls and boxes: 9%
/// fewer instructions per path-traced sample than with leaves of up to 4).
const MAX_WORLD_LEAF: usize = 1;
/// Meshes of at least this many triangles are walked 4-wide: on small ones the
/// ray setup of the wide walk costs more than it saves (the comparison scene of
/// a few small meshes: 0.19 s against 0.16 s with the binary walk).
const WIDE_MIN: usize = 256;
/// Most primitives [`Bvh::flat`] takes. For the path tracer's scattered rays a
/// flat list beat the world's tree at every size measured (the Cornell box with
/// 14 to 200 small spheres added: 30 to 216 primitives, 12-28% more samples per
/// second); the classic renderer's coherent rays do better with the tree.
pub const FLAT_MAX: usize = 256;
/// Cost of one node traversal relative to one primitive test.
const TRAVERSAL_COST: f32 = 1.0;
/// Depth after which nodes are halved by count, so depth stays bounded
/// (64 + log2 of the primitive count).
const MAX_SAH_DEPTH: usize = 64;
/// Subtrees with more primitives than this, near the root, are built in parallel.
const PAR_MIN: usize = 20_000;
/// Parallel build down to this depth (2^depth tasks).
const PAR_DEPTH: usize = 6;

/// An f32 box.
#[derive(Clone, Copy, Debug)]
struct Box32 {
    min: Vec3,
    max: Vec3,
}

impl Box32 {
    const EMPTY: Box32 = Box32 {
        min: Vec3::splat(f32::INFINITY),
        max: Vec3::splat(f32::NEG_INFINITY),
    };

    /// The f32 box holding `b` (rounded outwards).
    fn from_aabb(b: &Aabb) -> Box32 {
        let down = round_down;
        let up = |x: f64| {
            let f = x as f32;
            if (f as f64) < x {
                f.next_up()
            } else {
                f
            }
        };
        Box32 {
            min: Vec3::new(down(b.min.x), down(b.min.y), down(b.min.z)),
            max: Vec3::new(up(b.max.x), up(b.max.y), up(b.max.z)),
        }
    }

    fn union(&self, o: &Box32) -> Box32 {
        Box32 {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }

    fn grow(&self, p: Vec3) -> Box32 {
        Box32 {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    fn half_area(&self) -> f32 {
        if self.min.cmpgt(self.max).any() {
            return 0.0;
        }
        let d = self.max - self.min;
        d.x * d.y + d.y * d.z + d.z * d.x
    }
}

/// One node of the binary tree as built: an interior node's children are `first` and `first + 1`; a
/// leaf holds `count` entries of [`Bvh::prims`] starting at `first`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Node {
    pub(super) min: Vec3,
    pub(super) count: u32,
    pub(super) max: Vec3,
    pub(super) first: u32,
}

impl Node {
    const EMPTY: Node = Node {
        min: Vec3::ZERO,
        count: 0,
        max: Vec3::ZERO,
        first: 0,
    };
}

/// A binned-SAH BVH over primitive indices. A world's hierarchy (small, one
/// primitive a leaf) and a small mesh's are walked as binary trees in f64; a
/// large mesh's (up to four triangles a leaf) as a 4-wide tree in f32 lanes,
/// with half the nodes and memory. Measured: the wide walk is 8-10% faster on a
/// 1M-triangle mesh, and 5-8% slower on the world trees of the sphere and CSG
/// comparison scenes. The path tracer walks small worlds with no tree at all
/// ([`Bvh::flat`]).
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    /// A mesh's tree collapsed to 4-wide nodes, root first (else empty).
    nodes: Vec<Wide>,
    /// A world's binary tree in f64, root first (else empty).
    exact: Vec<Node64>,
    /// [`Bvh::flat`]'s boxes, four a node (lane child: the primitive, count 1)
    /// (else empty).
    flat: Vec<Wide>,
    /// Primitive indices, ordered so every leaf's are contiguous.
    prims: Vec<u32>,
    /// Bounds of everything.
    root: Option<Box32>,
}

/// The build inputs shared by all tasks.
struct Input {
    boxes: Vec<Box32>,
    cents: Vec<Vec3>,
    /// Sets this small or smaller become leaves.
    max_leaf: usize,
}

impl Bvh {
    /// Builds a hierarchy over `items`: (primitive index, world bounds).
    pub fn build(items: &[(u32, Aabb)]) -> Bvh {
        let boxes = items.iter().map(|(_, b)| Box32::from_aabb(b)).collect();
        let mut bvh = Bvh::build_from(boxes, MAX_WORLD_LEAF, false);
        for p in &mut bvh.prims {
            *p = items[*p as usize].0;
        }
        bvh
    }

    /// No tree over `items` (at most [`FLAT_MAX`]; `None` for more, or none):
    /// a walk tests every item's box, four at a time in f32, and visits the
    /// ones entered nearest first ([`super::wide::traverse_flat`]). In a small
    /// scene most inner boxes of a tree hold most of it: in the Cornell box,
    /// whose walls enclose the room, a scattered ray tested about 24 of the
    /// tree's 39 boxes one at a time, where 4 tests cover its 16 primitives'.
    pub fn flat(items: &[(u32, Aabb)]) -> Option<Bvh> {
        if items.is_empty() || items.len() > FLAT_MAX {
            return None;
        }
        let mut root = Box32::EMPTY;
        let mut flat = vec![Wide::EMPTY; items.len().div_ceil(4)];
        for (k, (prim, b)) in items.iter().enumerate() {
            let b = Box32::from_aabb(b);
            root = root.union(&b);
            flat[k / 4].set(k % 4, b.min.into(), b.max.into(), *prim, 1);
        }
        Some(Bvh {
            flat,
            root: Some(root),
            ..Bvh::default()
        })
    }

    /// Builds a hierarchy over primitives `0..n` whose bounds `bounds(i)` gives.
    pub fn build_indexed(n: usize, bounds: impl Fn(usize) -> Aabb + Sync) -> Bvh {
        use rayon::prelude::*;
        let boxes = (0..n)
            .into_par_iter()
            .map(|i| Box32::from_aabb(&bounds(i)))
            .collect();
        Bvh::build_from(boxes, MAX_LEAF, n >= WIDE_MIN)
    }

    /// The tree over `boxes`, 4-wide when `wide`.
    fn build_from(boxes: Vec<Box32>, max_leaf: usize, wide: bool) -> Bvh {
        if boxes.is_empty() {
            return Bvh::default();
        }
        let cents = boxes.iter().map(|b| (b.min + b.max) * 0.5).collect();
        let input = Input {
            boxes,
            cents,
            max_leaf,
        };
        let mut order: Vec<u32> = (0..input.boxes.len() as u32).collect();
        let binary = build_sub(&mut order, 0, 0, &input);
        // The inputs (36 bytes a primitive) go before the wide nodes are made.
        drop(input);
        let root = Box32 {
            min: binary[0].min,
            max: binary[0].max,
        };
        let (nodes, exact) = if wide {
            (collapse(&binary), Vec::new())
        } else {
            (Vec::new(), binary.iter().map(Node64::new).collect())
        };
        Bvh {
            nodes,
            exact,
            flat: Vec::new(),
            prims: order,
            root: Some(root),
        }
    }

    /// World bounds of everything in the hierarchy.
    pub fn bounds(&self) -> Aabb {
        self.root.map_or(Aabb::EMPTY, |b| {
            Aabb::new(b.min.as_dvec3(), b.max.as_dvec3())
        })
    }

    /// Number of nodes, binary or 4-wide (for statistics and tests).
    pub fn node_count(&self) -> usize {
        self.nodes.len() + self.exact.len() + self.flat.len()
    }

    /// Bytes held by the hierarchy.
    pub fn memory(&self) -> usize {
        self.nodes.capacity() * std::mem::size_of::<Wide>()
            + self.exact.capacity() * std::mem::size_of::<Node64>()
            + self.flat.capacity() * std::mem::size_of::<Wide>()
            + self.prims.capacity() * 4
    }

    /// Visits leaves the ray may hit, nearest-first. `visit(prim, t_max)` tests one
    /// primitive and returns the new `t_max` (shrunk when it found a closer hit) or
    /// `None` to stop the traversal early.
    #[inline]
    pub fn traverse(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        visit: impl FnMut(u32, f64) -> Option<f64>,
    ) {
        if !self.exact.is_empty() {
            binary::traverse(&self.exact, &self.prims, ray, t_min, t_max, visit);
        } else if !self.flat.is_empty() {
            wide::traverse_flat(&self.flat, ray, t_min, t_max, visit);
        } else {
            wide::traverse(&self.nodes, &self.prims, ray, t_min, t_max, visit);
        }
    }
}

/// The 4-wide tree of binary tree `binary` (root first): each wide node takes the
/// children of a binary node and keeps opening its largest inner child until it
/// has four.
fn collapse(binary: &[Node]) -> Vec<Wide> {
    let mut out = Vec::with_capacity(binary.len() / 2 + 1);
    out.push(Wide::EMPTY);
    let root = &binary[0];
    if root.count > 0 {
        out[0].set(0, root.min.into(), root.max.into(), root.first, root.count);
        return out;
    }
    fill(binary, 0, 0, &mut out);
    out.shrink_to_fit();
    out
}

/// Fills wide node `slot` from binary inner node `b`, then its inner children.
fn fill(binary: &[Node], b: usize, slot: usize, out: &mut Vec<Wide>) {
    let first = binary[b].first as usize;
    let mut kids = [first, first + 1, 0, 0];
    let mut n = 2;
    while n < 4 {
        let widest = (0..n)
            .filter(|&i| binary[kids[i]].count == 0)
            .max_by(|&i, &j| area(&binary[kids[i]]).total_cmp(&area(&binary[kids[j]])));
        let Some(i) = widest else { break };
        let open = binary[kids[i]].first as usize;
        kids[i] = open;
        kids[n] = open + 1;
        n += 1;
    }
    let mut inner = [(0usize, 0usize); 4];
    let mut m = 0;
    let mut node = Wide::EMPTY;
    for (lane, &k) in kids[..n].iter().enumerate() {
        let c = &binary[k];
        if c.count > 0 {
            node.set(lane, c.min.into(), c.max.into(), c.first, c.count);
        } else {
            let at = out.len();
            out.push(Wide::EMPTY);
            node.set(lane, c.min.into(), c.max.into(), at as u32, 0);
            inner[m] = (k, at);
            m += 1;
        }
    }
    out[slot] = node;
    for &(k, at) in &inner[..m] {
        fill(binary, k, at, out);
    }
}

/// Half the surface area of a node's box.
fn area(n: &Node) -> f32 {
    Box32 {
        min: n.min,
        max: n.max,
    }
    .half_area()
}

/// `x` as an f32 no greater than it.
fn round_down(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) > x {
        f.next_down()
    } else {
        f
    }
}

/// Where to split `order` whose centroids span `cb`, or `None` for a leaf.
fn choose_split(order: &mut [u32], depth: usize, input: &Input, cb: &Box32) -> Option<usize> {
    if order.len() <= input.max_leaf {
        return None;
    }
    if depth >= MAX_SAH_DEPTH {
        // Deep, lopsided trees could overflow the traversal stack: halve by count.
        return Some(median_split(order, &input.cents, cb));
    }
    let (axis, pos) = best_split(order, input, cb)?;
    Some(
        match partition(order, |&k| input.cents[k as usize][axis] < pos) {
            0 => median_split(order, &input.cents, cb),
            m if m == order.len() => median_split(order, &input.cents, cb),
            m => m,
        },
    )
}

/// Sets of at least this many primitives are bounded and binned in parallel
/// chunks: near the root these passes are the build's critical path. The
/// merges are exact (min, max, counts), so the tree does not depend on threads.
const PAR_PASS: usize = 1 << 16;
/// Chunk size of the parallel passes.
const PAR_CHUNK: usize = 1 << 14;

/// Bounds of the boxes and of the centroids of `order`, in one pass.
fn spans(order: &[u32], input: &Input) -> (Box32, Box32) {
    use rayon::prelude::*;
    let seq = |part: &[u32]| {
        part.iter()
            .fold((Box32::EMPTY, Box32::EMPTY), |(b, c), &k| {
                let k = k as usize;
                (b.union(&input.boxes[k]), c.grow(input.cents[k]))
            })
    };
    if order.len() < PAR_PASS {
        return seq(order);
    }
    order.par_chunks(PAR_CHUNK).map(seq).reduce(
        || (Box32::EMPTY, Box32::EMPTY),
        |a, b| (a.0.union(&b.0), a.1.union(&b.1)),
    )
}

/// Per axis, per bin: the bounds and count of the primitives whose centroids fall in it.
type Bins = [[(Box32, u32); BINS]; 3];

/// Bins `part` (centroid bin = (centroid - `min`) × `scale`, clamped), with the
/// bounds of all its boxes.
fn bin(part: &[u32], input: &Input, min: Vec3, scale: Vec3) -> (Bins, Box32) {
    let mut bins = [[(Box32::EMPTY, 0u32); BINS]; 3];
    let mut parent = Box32::EMPTY;
    for &k in part {
        let k = k as usize;
        let b = &input.boxes[k];
        parent = parent.union(b);
        let rel = (input.cents[k] - min) * scale;
        for axis in 0..3 {
            let i = (rel[axis] as usize).min(BINS - 1);
            let e = &mut bins[axis][i];
            e.0 = e.0.union(b);
            e.1 += 1;
        }
    }
    (bins, parent)
}

fn leaf_or_inner(bounds: Box32, first: u32, count: u32) -> Node {
    Node {
        min: bounds.min,
        max: bounds.max,
        first,
        count,
    }
}

/// The nodes of the subtree over `order` (at `start` in the final order), its root
/// first; interior nodes' `first` index into the returned vector.
fn build_sub(order: &mut [u32], start: usize, depth: usize, input: &Input) -> Vec<Node> {
    if depth >= PAR_DEPTH || order.len() < PAR_MIN {
        let mut nodes = vec![Node::EMPTY];
        split_seq(&mut nodes, 0, order, start, depth, input);
        return nodes;
    }
    let (bounds, cb) = spans(order, input);
    let Some(mid) = choose_split(order, depth, input, &cb) else {
        return vec![leaf_or_inner(bounds, start as u32, order.len() as u32)];
    };
    let (lo, hi) = order.split_at_mut(mid);
    let (l, r) = rayon::join(
        || build_sub(lo, start, depth + 1, input),
        || build_sub(hi, start + mid, depth + 1, input),
    );
    // Layout: [root, l root, r root, l rest…, r rest…].
    let mut nodes = Vec::with_capacity(1 + l.len() + r.len());
    nodes.push(leaf_or_inner(bounds, 1, 0));
    let shift = |mut n: Node, by: usize| {
        if n.count == 0 {
            n.first += by as u32;
        }
        n
    };
    let (l_by, r_by) = (2, l.len() + 1);
    nodes.push(shift(l[0], l_by));
    nodes.push(shift(r[0], r_by));
    nodes.extend(l[1..].iter().map(|&n| shift(n, l_by)));
    nodes.extend(r[1..].iter().map(|&n| shift(n, r_by)));
    nodes
}

/// Fills node `node` of `nodes` with `order`, recursing sequentially.
fn split_seq(
    nodes: &mut Vec<Node>,
    node: usize,
    order: &mut [u32],
    start: usize,
    depth: usize,
    input: &Input,
) {
    let (bounds, cb) = spans(order, input);
    let Some(mid) = choose_split(order, depth, input, &cb) else {
        nodes[node] = leaf_or_inner(bounds, start as u32, order.len() as u32);
        return;
    };
    let left = nodes.len();
    nodes.push(Node::EMPTY);
    nodes.push(Node::EMPTY);
    nodes[node] = leaf_or_inner(bounds, left as u32, 0);
    let (lo, hi) = order.split_at_mut(mid);
    split_seq(nodes, left, lo, start, depth + 1, input);
    split_seq(nodes, left + 1, hi, start + mid, depth + 1, input);
}

/// The SAH-best (axis, plane position) over binned centroids, or `None` when no
/// split beats a leaf. All three axes are binned in one pass over the primitives.
fn best_split(order: &[u32], input: &Input, cb: &Box32) -> Option<(usize, f32)> {
    let ext = cb.max - cb.min;
    let usable = [0, 1, 2].map(|a| ext[a] > 0.0 && ext[a].is_finite());
    if !usable.iter().any(|&u| u) {
        return None;
    }
    let scale = Vec3::new(
        if usable[0] { BINS as f32 / ext.x } else { 0.0 },
        if usable[1] { BINS as f32 / ext.y } else { 0.0 },
        if usable[2] { BINS as f32 / ext.z } else { 0.0 },
    );
    let (bins, parent) = if order.len() < PAR_PASS {
        bin(order, input, cb.min, scale)
    } else {
        use rayon::prelude::*;
        order
            .par_chunks(PAR_CHUNK)
            .map(|part| bin(part, input, cb.min, scale))
            .reduce(
                || ([[(Box32::EMPTY, 0u32); BINS]; 3], Box32::EMPTY),
                |(mut a, pa), (b, pb)| {
                    for axis in 0..3 {
                        for i in 0..BINS {
                            a[axis][i] = (
                                a[axis][i].0.union(&b[axis][i].0),
                                a[axis][i].1 + b[axis][i].1,
                            );
                        }
                    }
                    (a, pa.union(&pb))
                },
            )
    };
    let mut best: Option<(f32, usize, f32)> = None;
    for axis in (0..3).filter(|&a| usable[a]) {
        let bins = &bins[axis];
        // Sweep from the right to get suffix areas and counts.
        let mut right = [(0.0, 0u32); BINS];
        let mut acc = (Box32::EMPTY, 0u32);
        for i in (1..BINS).rev() {
            acc = (acc.0.union(&bins[i].0), acc.1 + bins[i].1);
            right[i] = (acc.0.half_area(), acc.1);
        }
        let mut left = (Box32::EMPTY, 0u32);
        for i in 0..BINS - 1 {
            left = (left.0.union(&bins[i].0), left.1 + bins[i].1);
            let (ra, rn) = right[i + 1];
            if left.1 == 0 || rn == 0 {
                continue;
            }
            let cost = left.0.half_area() * left.1 as f32 + ra * rn as f32;
            if best.is_none_or(|(c, _, _)| cost < c) {
                best = Some((cost, axis, cb.min[axis] + (i + 1) as f32 / scale[axis]));
            }
        }
    }
    let (cost, axis, pos) = best?;
    let split_cost = TRAVERSAL_COST + cost / parent.half_area().max(f32::MIN_POSITIVE);
    (split_cost < order.len() as f32 || order.len() > 4 * input.max_leaf).then_some((axis, pos))
}

/// Splits `order` in two equal halves along the widest centroid axis.
fn median_split(order: &mut [u32], cents: &[Vec3], cb: &Box32) -> usize {
    let ext = cb.max - cb.min;
    let axis = if ext.x >= ext.y && ext.x >= ext.z {
        0
    } else if ext.y >= ext.z {
        1
    } else {
        2
    };
    let mid = order.len() / 2;
    order.select_nth_unstable_by(mid, |&a, &b| {
        cents[a as usize][axis].total_cmp(&cents[b as usize][axis])
    });
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

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn parallel_and_sequential_builds_find_the_same_leaves() {
        // Enough boxes to take the parallel path; every box is found by a ray
        // straight through its centre.
        let n = 50_000;
        let bvh = Bvh::build_indexed(n, |i| {
            let c = DVec3::new((i % 250) as f64, (i / 250) as f64, 0.0);
            Aabb::new(c - DVec3::splat(0.3), c + DVec3::splat(0.3))
        });
        let mut seen = vec![false; n];
        for &p in &bvh.prims {
            seen[p as usize] = true;
        }
        assert!(seen.iter().all(|&s| s));
        for i in (0..n).step_by(997) {
            let c = DVec3::new((i % 250) as f64, (i / 250) as f64, -5.0);
            let mut found = false;
            bvh.traverse(&Ray::new(c, DVec3::Z), 0.0, f64::INFINITY, |p, t| {
                found |= p as usize == i;
                Some(t)
            });
            assert!(found, "box {i} not reached");
        }
        let b = bvh.bounds();
        assert!(b.min.x <= -0.3 && b.max.x >= 249.3);
    }

    #[test]
    fn deep_trees_spill_the_stack_and_still_find_everything() {
        // Exponentially spaced boxes make SAH peel one box off per level: a tree
        // far deeper than the fixed stack. A ray along them meets every box.
        let n = 400;
        let bvh = Bvh::build_indexed(n, |i| {
            let x = 1.08f64.powi(i as i32);
            Aabb::new(DVec3::new(x, -0.5, -0.5), DVec3::new(x * 1.01, 0.5, 0.5))
        });
        let mut seen = vec![false; n];
        bvh.traverse(
            &Ray::new(DVec3::ZERO, DVec3::X),
            0.0,
            f64::INFINITY,
            |p, t| {
                seen[p as usize] = true;
                Some(t)
            },
        );
        assert!(seen.iter().all(|&s| s));
    }

    /// The tree over `bounds(0..n)`, binary (f64) and 4-wide (f32 lanes), with
    /// one box a leaf so every box is tested on its own.
    fn both_layouts(n: usize, bounds: impl Fn(usize) -> Aabb) -> [Bvh; 2] {
        [false, true].map(|wide| {
            let boxes = (0..n).map(|i| Box32::from_aabb(&bounds(i))).collect();
            let bvh = Bvh::build_from(boxes, 1, wide);
            assert_eq!(bvh.nodes.is_empty(), !wide);
            bvh
        })
    }

    #[test]
    fn rays_in_a_face_plane_reach_the_boxes_on_both_sides() {
        // Boxes that meet at x = 0; rays with dir.x = ±0 starting at x = 0 lie in
        // both boxes' face planes (0 × ∞ = NaN in the slab test).
        let n = 64;
        for bvh in both_layouts(n, |i| {
            let z = (i / 2) as f64;
            let x = if i % 2 == 0 { -1.0 } else { 0.0 };
            Aabb::new(DVec3::new(x, 0.0, z), DVec3::new(x + 1.0, 1.0, z + 1.0))
        }) {
            for dir in [
                DVec3::Z,
                DVec3::new(-0.0, 0.0, 1.0),
                DVec3::new(0.0, 0.3, 1.0),
            ] {
                let mut seen = vec![false; n];
                bvh.traverse(
                    &Ray::new(DVec3::new(0.0, 0.5, -1.0), dir),
                    0.0,
                    f64::INFINITY,
                    |p, t| {
                        seen[p as usize] = true;
                        Some(t)
                    },
                );
                let expected = if dir.y == 0.0 { n } else { 2 };
                let wide = !bvh.nodes.is_empty();
                assert!(
                    seen.iter().filter(|&&s| s).count() >= expected,
                    "{dir} wide {wide}"
                );
            }
        }
    }

    /// Whether `ray` meets box `b` within `[t_min, t_max]`, exactly as far as f64
    /// goes (an axis the ray runs along counts when the origin is in the slab).
    fn meets(b: &Aabb, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let (mut near, mut far) = (t_min, t_max);
        for a in 0..3 {
            let (o, d) = (ray.origin[a], ray.dir[a]);
            if d == 0.0 {
                if o < b.min[a] || o > b.max[a] {
                    return false;
                }
                continue;
            }
            let (t0, t1) = ((b.min[a] - o) / d, (b.max[a] - o) / d);
            near = near.max(t0.min(t1));
            far = far.min(t0.max(t1));
        }
        near <= far
    }

    #[test]
    fn both_layouts_visit_every_box_a_ray_meets() {
        // Random boxes, some sharing faces on a grid; rays from random points and
        // from box corners and faces, some along axes, some with a finite t_max.
        // Rounding to f32 may add boxes, never lose one.
        use rand_core::{RngCore, SeedableRng};
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(7);
        let mut unit = move || (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        let n = 3000;
        let boxes: Vec<Aabb> = (0..n)
            .map(|i| {
                if i % 3 == 0 {
                    let c = DVec3::new((i % 17) as f64, ((i / 17) % 13) as f64, (i / 221) as f64);
                    Aabb::new(c, c + DVec3::ONE)
                } else {
                    let c = DVec3::new(unit(), unit(), unit()) * 20.0 - 2.0;
                    let h = DVec3::new(unit(), unit(), unit()) * 0.7 + 1e-3;
                    Aabb::new(c - h, c + h)
                }
            })
            .collect();
        let layouts = both_layouts(n, |i| boxes[i]);
        for k in 0..4000 {
            let origin = match k % 3 {
                0 => DVec3::new(unit(), unit(), unit()) * 24.0 - 4.0,
                1 => boxes[k % n].min,
                _ => DVec3::new(boxes[k % n].max.x, unit() * 16.0, boxes[k % n].min.z),
            };
            let mut dir = DVec3::new(unit(), unit(), unit()) * 2.0 - 1.0;
            if k % 5 == 0 {
                dir[k % 3] = 0.0;
            }
            if k % 7 == 0 {
                dir = DVec3::ZERO;
                dir[k % 3] = if k % 2 == 0 { 1.0 } else { -1.0 };
            }
            let ray = Ray::new(origin, dir);
            let t_max = if k % 4 == 0 {
                unit() * 10.0
            } else {
                f64::INFINITY
            };
            for bvh in &layouts {
                let mut seen = vec![false; n];
                bvh.traverse(&ray, 0.0, t_max, |p, t| {
                    seen[p as usize] = true;
                    Some(t)
                });
                for (i, b) in boxes.iter().enumerate() {
                    assert!(
                        seen[i] || !meets(b, &ray, 0.0, t_max),
                        "ray {k} {ray:?} to {t_max} misses box {i} {b:?} (wide: {})",
                        !bvh.nodes.is_empty()
                    );
                }
            }
        }
    }
}
