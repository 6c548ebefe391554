//! A large mesh's hierarchy as traversal walks it: the binary SAH tree collapsed
//! into nodes of up to four children whose boxes are tested together, one f32
//! lane each (SSE through glam's `Vec4`). The binary tree's f32 bounds are already rounded
//! outwards; the ray's f64 origin and direction are rounded so that every box
//! test errs towards a hit (see [`Lanes::new`]), never towards a miss.

use glam::Vec4;

use super::bvh::FLAT_MAX;
use super::Ray;

/// The box of an empty lane: all at +∞, so a ray enters it at +∞ or leaves it at
/// −∞, and far limits are finite (see [`far`]).
const EMPTY_LANE: [[Vec4; 3]; 2] = [[Vec4::INFINITY; 3]; 2];

/// One node of up to four children. A lane is an inner node (`count == 0`,
/// `child` its index), a leaf (`count` primitives from `child` on in
/// [`super::Bvh`]'s primitive list) or empty (bounds no ray enters).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub(super) struct Wide {
    /// Child bounds by lane: `[min, max]`, each x, y, z.
    bounds: [[Vec4; 3]; 2],
    child: [u32; 4],
    count: [u32; 4],
}

impl Wide {
    pub(super) const EMPTY: Wide = Wide {
        bounds: EMPTY_LANE,
        child: [0; 4],
        count: [0; 4],
    };

    /// Sets lane `lane` to the box `min`..`max` holding `child` / `count` (see [`Wide`]).
    pub(super) fn set(
        &mut self,
        lane: usize,
        min: [f32; 3],
        max: [f32; 3],
        child: u32,
        count: u32,
    ) {
        for a in 0..3 {
            self.bounds[0][a][lane] = min[a];
            self.bounds[1][a][lane] = max[a];
        }
        self.child[lane] = child;
        self.count[lane] = count;
    }
}

/// Slack on far distances for the rounding of the subtraction, the product and
/// the reciprocal (each within 2⁻²⁴ relative): 16 times what they can add up to.
const FAR_SLACK: f32 = 1.0 + 1.0 / (1 << 20) as f32;
/// Largest reciprocal direction used: a zero component would give ∞ and, for an
/// origin on a box face, 0 × ∞ = NaN. With the origin margin below, a ray lying in
/// a face plane still sees that slab reach past 10¹⁰.
const MAX_INV: f64 = 1e30;
/// Relative margin on the origin (and on distance limits).
const MARGIN: f32 = 1.0 / (1 << 20) as f32;

/// A ray prepared for four-lane box tests.
pub(super) struct Lanes {
    /// Per axis, whether the ray enters boxes through their max plane
    /// (negative direction): indexes [`Wide::bounds`].
    back: [bool; 3],
    /// Origin per axis as used against near planes and far planes: moved by a
    /// margin so each plane's distance comes out on the side of a hit.
    near: [Vec4; 3],
    far: [Vec4; 3],
    inv: [Vec4; 3],
}

impl Lanes {
    /// Prepares `ray`. Against the planes a ray enters by, the f32 origin is
    /// moved a margin of about `|o|·2⁻²⁰ + 10⁻²⁰` forwards, against those it
    /// leaves by as far back (16 times the rounding of the origin and of the
    /// sum, so without branches): every box is tested as if grown by that
    /// margin, and rounding can only turn misses into hits.
    pub(super) fn new(ray: &Ray) -> Lanes {
        let mut lanes = Lanes {
            back: [false; 3],
            near: [Vec4::ZERO; 3],
            far: [Vec4::ZERO; 3],
            inv: [Vec4::ZERO; 3],
        };
        for a in 0..3 {
            let o = ray.origin[a] as f32;
            let inv = (1.0 / ray.dir[a]).clamp(-MAX_INV, MAX_INV) as f32;
            let margin = (o.abs() * MARGIN + 1e-20).copysign(inv);
            lanes.back[a] = inv < 0.0;
            lanes.near[a] = Vec4::splat(o + margin);
            lanes.far[a] = Vec4::splat(o - margin);
            lanes.inv[a] = Vec4::splat(inv);
        }
        lanes
    }

    /// Which lanes of `node` the ray enters within `near`..`far` (bit per lane),
    /// and the entry distances.
    #[inline(always)]
    pub(super) fn hit(&self, node: &Wide, near: Vec4, far: Vec4) -> (u32, Vec4) {
        let b = &node.bounds;
        let side = |a: usize, leave: bool| b[usize::from(self.back[a] ^ leave)][a];
        let t = |a: usize, leave: bool| {
            let o = if leave { self.far[a] } else { self.near[a] };
            (side(a, leave) - o) * self.inv[a]
        };
        let enter = t(0, false).max(t(1, false)).max(t(2, false).max(near));
        let leave = (t(0, true).min(t(1, true)).min(t(2, true)) * FAR_SLACK).min(far);
        (enter.cmple(leave).bitmask(), enter)
    }
}

/// `x` in f32, a little below it (for near limits).
#[inline(always)]
pub(super) fn down(x: f64) -> f32 {
    let f = x as f32;
    f - f.abs() * MARGIN
}

/// `x` in f32, a little above it and at most `f32::MAX` (for far limits: empty
/// lanes are entered at +∞).
#[inline(always)]
pub(super) fn far(x: f64) -> f32 {
    let f = x as f32;
    (f + f.abs() * MARGIN).min(f32::MAX)
}

/// Visits leaves of the tree `nodes` (root first, over `prims`) that `ray` may
/// hit, nearest first: see [`super::Bvh::traverse`].
#[inline(always)]
pub(super) fn traverse(
    nodes: &[Wide],
    prims: &[u32],
    ray: &Ray,
    t_min: f64,
    mut t_max: f64,
    mut visit: impl FnMut(u32, f64) -> Option<f64>,
) {
    if nodes.is_empty() {
        return;
    }
    let lanes = Lanes::new(ray);
    let near = Vec4::splat(down(t_min));
    let mut far32 = far(t_max);
    let mut stack = Stack::new();
    let mut node = 0usize;
    loop {
        let n = &nodes[node];
        let (mask, dist) = lanes.hit(n, near, Vec4::splat(far32));
        let mut next = None;
        if mask & mask.wrapping_sub(1) == 0 {
            // One lane or none: no ordering; an inner node is entered at once.
            if mask != 0 {
                let lane = mask.trailing_zeros() as usize;
                if n.count[lane] == 0 {
                    node = n.child[lane] as usize;
                    continue;
                }
                next = Some(((node as u64) << 2) | lane as u64);
            }
        } else {
            // Push all but the nearest, farthest first.
            let keys = ordered(node, mask, dist);
            for &key in keys[1..].iter().rev() {
                if key != u64::MAX {
                    stack.push(key);
                }
            }
            next = Some(keys[0]);
        }
        loop {
            let key = match next.take() {
                Some(key) => key,
                None => {
                    // Pop, skipping boxes entered beyond a nearer hit.
                    let Some(key) = stack.pop() else {
                        return;
                    };
                    if key_dist(key) > far32 {
                        continue;
                    }
                    key
                }
            };
            let (at, lane) = key_lane(key);
            let (child, count) = nodes[at].lane(lane);
            if count == 0 {
                node = child as usize;
                break;
            }
            for &p in &prims[child as usize..(child + count) as usize] {
                match visit(p, t_max) {
                    Some(t) if t < t_max => {
                        t_max = t;
                        far32 = far(t);
                    }
                    Some(_) => {}
                    None => return,
                }
            }
        }
    }
}

/// Visits the primitives of the flat list `chunks` (see [`super::Bvh::flat`]:
/// each lane's child a primitive) whose boxes `ray` enters within
/// `t_min..t_max`, nearest entry first, as [`traverse`] does. (A ray leaving a
/// flat surface enters that surface's own thin box by the test's rounding
/// margin, so its primitive is tested too and rejects the ray: testing such
/// boxes again in f64 first measured slower.)
#[inline(always)]
pub(super) fn traverse_flat(
    chunks: &[Wide],
    ray: &Ray,
    t_min: f64,
    t_max: f64,
    visit: impl FnMut(u32, f64) -> Option<f64>,
) {
    // Room for every lane's key without a heap: small lists (the usual case)
    // set up a small array.
    if chunks.len() * 4 <= FLAT_SMALL {
        walk_flat::<FLAT_SMALL>(chunks, ray, t_min, t_max, visit);
    } else {
        walk_flat::<FLAT_MAX>(chunks, ray, t_min, t_max, visit);
    }
}

/// Lists of up to this many boxes keep their keys in a small array.
const FLAT_SMALL: usize = 32;

/// [`traverse_flat`] for lists of at most `N` boxes.
#[inline(always)]
fn walk_flat<const N: usize>(
    chunks: &[Wide],
    ray: &Ray,
    t_min: f64,
    t_max: f64,
    visit: impl FnMut(u32, f64) -> Option<f64>,
) {
    let lanes = Lanes::new(ray);
    let near = Vec4::splat(down(t_min));
    let limit = Vec4::splat(far(t_max));
    // The entered lanes as keys (entry distance's bits above the primitive),
    // kept sorted by insertion: a ray enters few of the boxes.
    let mut keys = [0u64; N];
    let mut n = 0;
    for c in chunks {
        let (mask, dist) = lanes.hit(c, near, limit);
        if mask == 0 {
            continue;
        }
        let d = dist.to_array();
        for (lane, d) in d.iter().enumerate() {
            if mask & (1 << lane) != 0 {
                let key = (u64::from(d.to_bits()) << 32) | u64::from(c.child[lane]);
                let mut j = n;
                while j > 0 && keys[j - 1] > key {
                    keys[j] = keys[j - 1];
                    j -= 1;
                }
                keys[j] = key;
                n += 1;
            }
        }
    }
    visit_sorted(&keys[..n], t_max, visit);
}

/// Visits the primitives of sorted `keys` (see [`traverse_flat`]) while their
/// boxes are entered before the nearest hit so far.
#[inline(always)]
fn visit_sorted(keys: &[u64], mut t_max: f64, mut visit: impl FnMut(u32, f64) -> Option<f64>) {
    let mut far32 = far(t_max);
    for &key in keys {
        if key_dist(key) > far32 {
            return;
        }
        match visit(key as u32, t_max) {
            Some(t) if t < t_max => {
                t_max = t;
                far32 = far(t);
            }
            Some(_) => {}
            None => return,
        }
    }
}

/// The hit lanes (bits of `mask`) of node `at`, nearest first, each as one
/// sortable number: its entry distance's bits above (non-negative f32s order as
/// their bits do), `at * 4 + lane` below. Missed lanes are `u64::MAX`, last.
/// One number per lane, so the sort is a few branch-free min/max steps.
#[inline(always)]
pub(super) fn ordered(at: usize, mask: u32, dist: Vec4) -> [u64; 4] {
    // (Indexing the `Vec4` itself is a `match`: a mispredicted jump per lane.)
    let d = dist.to_array();
    let base = at as u64 * 4;
    let key = |l: usize| {
        if mask & (1 << l) != 0 {
            (u64::from(d[l].to_bits()) << 32) | (base + l as u64)
        } else {
            u64::MAX
        }
    };
    let mut k = [key(0), key(1), key(2), key(3)];
    // A sorting network of five compare-exchanges (branch-free min/max).
    for (i, j) in [(0, 1), (2, 3), (0, 2), (1, 3), (1, 2)] {
        let (a, b) = (k[i].min(k[j]), k[i].max(k[j]));
        k[i] = a;
        k[j] = b;
    }
    k
}

/// The entry distance kept in a key of [`ordered`].
#[inline(always)]
pub(super) fn key_dist(key: u64) -> f32 {
    f32::from_bits((key >> 32) as u32)
}

/// The node and lane a key of [`ordered`] names.
#[inline(always)]
pub(super) fn key_lane(key: u64) -> (usize, usize) {
    ((key as u32 >> 2) as usize, (key & 3) as usize)
}

impl Wide {
    /// Lane `lane`'s child index and primitive count (see [`Wide`]).
    #[inline(always)]
    pub(super) fn lane(&self, lane: usize) -> (u32, u32) {
        (self.child[lane], self.count[lane])
    }
}

/// Traversal stack entries kept in a fixed array (deeper ones spill to the heap):
/// small enough that setting it up costs a few stores, not a `memset` call.
const STACK: usize = 16;

/// The traversal stack of keys (see [`ordered`]).
pub(super) struct Stack {
    fixed: [u64; STACK],
    len: usize,
    spill: Vec<u64>,
}

impl Stack {
    #[inline(always)]
    pub(super) fn new() -> Stack {
        Stack {
            fixed: [0; STACK],
            len: 0,
            spill: Vec::new(),
        }
    }

    #[inline(always)]
    pub(super) fn push(&mut self, key: u64) {
        if self.len < STACK {
            self.fixed[self.len] = key;
            self.len += 1;
        } else {
            self.spill.push(key);
        }
    }

    #[inline(always)]
    pub(super) fn pop(&mut self) -> Option<u64> {
        if let Some(key) = self.spill.pop() {
            Some(key)
        } else if self.len > 0 {
            self.len -= 1;
            Some(self.fixed[self.len])
        } else {
            None
        }
    }
}
