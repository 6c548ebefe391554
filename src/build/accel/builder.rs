//! The binned-SAH binary build, in parallel near the root. Nodes hold f32
//! bounds rounded outwards (32 bytes a node), so a mesh of a million triangles
//! keeps its tree small; rays stay f64. The binary tree is then laid out for its
//! walk by [`super::wide`] (8-wide nodes) or [`super::binary`] (f64 nodes).

use super::Aabb;
use glam::{Vec3, Vec3A};

/// Number of SAH bins per axis.
const BINS: usize = 16;
/// Cost of one node traversal relative to one primitive test.
const TRAVERSAL_COST: f32 = 1.0;
/// Depth after which nodes are halved by count, so depth stays bounded
/// (64 + log2 of the primitive count).
const MAX_SAH_DEPTH: usize = 64;
/// Subtrees with more primitives than this, near the root, are built in parallel.
const PAR_MIN: usize = 20_000;
/// Parallel build down to this depth (2^depth tasks).
const PAR_DEPTH: usize = 6;

/// An f32 box (in SIMD-width vectors: a union is two instructions).
#[derive(Clone, Copy, Debug)]
pub(super) struct Box32 {
    pub(super) min: Vec3A,
    pub(super) max: Vec3A,
}

impl Box32 {
    pub(super) const EMPTY: Box32 = Box32 {
        min: Vec3A::splat(f32::INFINITY),
        max: Vec3A::splat(f32::NEG_INFINITY),
    };

    /// The f32 box holding `b` (rounded outwards).
    pub(super) fn from_aabb(b: &Aabb) -> Box32 {
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
            min: Vec3A::new(down(b.min.x), down(b.min.y), down(b.min.z)),
            max: Vec3A::new(up(b.max.x), up(b.max.y), up(b.max.z)),
        }
    }

    pub(super) fn union(&self, o: &Box32) -> Box32 {
        Box32 {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }

    fn grow(&self, p: Vec3A) -> Box32 {
        Box32 {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// The box's centre (where the build bins it).
    #[inline]
    fn centre(&self) -> Vec3A {
        (self.min + self.max) * 0.5
    }

    pub(super) fn half_area(&self) -> f32 {
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
    pub(super) const EMPTY: Node = Node {
        min: Vec3::ZERO,
        count: 0,
        max: Vec3::ZERO,
        first: 0,
    };
}

/// Half the surface area of a node's box.
pub(super) fn area(n: &Node) -> f32 {
    Box32 {
        min: n.min.into(),
        max: n.max.into(),
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
        return Some(median_split(order, &input.boxes, cb));
    }
    let (axis, pos) = best_split(order, input, cb)?;
    Some(
        match partition(order, |&k| input.boxes[k as usize].centre()[axis] < pos) {
            0 => median_split(order, &input.boxes, cb),
            m if m == order.len() => median_split(order, &input.boxes, cb),
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
                let k = &input.boxes[k as usize];
                (b.union(k), c.grow(k.centre()))
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
fn bin(part: &[u32], input: &Input, min: Vec3A, scale: Vec3A) -> (Bins, Box32) {
    let mut bins = [[(Box32::EMPTY, 0u32); BINS]; 3];
    let mut parent = Box32::EMPTY;
    for &k in part {
        let k = k as usize;
        let b = &input.boxes[k];
        parent = parent.union(b);
        // The bin along each axis, clamped to the bins (NaN to the first) in
        // floats, where the conversion is one instruction.
        let rel = ((b.centre() - min) * scale)
            .max(Vec3A::ZERO)
            .min(Vec3A::splat((BINS - 1) as f32))
            .to_array();
        for axis in 0..3 {
            let i = rel[axis] as i32 as usize;
            let e = &mut bins[axis][i];
            e.0 = e.0.union(b);
            e.1 += 1;
        }
    }
    (bins, parent)
}

fn leaf_or_inner(bounds: Box32, first: u32, count: u32) -> Node {
    Node {
        min: bounds.min.into(),
        max: bounds.max.into(),
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
    let scale = Vec3A::new(
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
fn median_split(order: &mut [u32], boxes: &[Box32], cb: &Box32) -> usize {
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
        let (a, b) = (&boxes[a as usize], &boxes[b as usize]);
        a.centre()[axis].total_cmp(&b.centre()[axis])
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

/// The build inputs shared by all tasks.
struct Input {
    /// The primitives' boxes (their centres are binned).
    boxes: Vec<Box32>,
    /// Sets this small or smaller become leaves.
    max_leaf: usize,
}

/// The binary tree over `boxes` (root first; interior nodes' children at
/// `first` and `first + 1`) and the primitive order its leaves index into.
/// `boxes` must not be empty.
pub(super) fn binary_tree(boxes: Vec<Box32>, max_leaf: usize) -> (Vec<Node>, Vec<u32>) {
    let input = Input { boxes, max_leaf };
    let mut order: Vec<u32> = (0..input.boxes.len() as u32).collect();
    let nodes = build_sub(&mut order, 0, 0, &input);
    (nodes, order)
}
