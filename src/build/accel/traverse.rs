//! The walks of the wide tree: nearest-first for closest hits, unordered for
//! "anything in between", and the flat list. Each is a [`pulp::WithSimd`]
//! operation, dispatched once per walk ([`super::simd::dispatch`]) so the box
//! kernel and the caller's primitive tests inline into one function compiled
//! for the SIMD level in force.

use pulp::{Simd, WithSimd};

use super::kernels::{down, far, hit8, tri_keep, RayBoxes, RayTri, TRI_CHUNK, WIDTH};
use super::wide::Wide;
use super::Ray;

/// A key for a hit lane: its entry distance's bits above (non-negative f32s
/// order as their bits do), `low` below (`node * 8 + lane`, or a primitive).
#[inline(always)]
fn key(dist: f32, low: u32) -> u64 {
    (u64::from(dist.to_bits()) << 32) | u64::from(low)
}

/// The entry distance kept in a key.
#[inline(always)]
fn key_dist(key: u64) -> f32 {
    f32::from_bits((key >> 32) as u32)
}

/// The keys of the lanes set in `mask`, sorted (nearest first), and how many.
#[inline(always)]
fn sorted(mask: u32, dist: &[f32; WIDTH], low: impl Fn(usize) -> u32) -> ([u64; WIDTH], usize) {
    let mut keys = [u64::MAX; WIDTH];
    let mut n = 0;
    let mut m = mask;
    while m != 0 {
        let lane = m.trailing_zeros() as usize;
        m &= m - 1;
        let k = key(dist[lane], low(lane));
        let mut j = n;
        while j > 0 && keys[j - 1] > k {
            keys[j] = keys[j - 1];
            j -= 1;
        }
        keys[j] = k;
        n += 1;
    }
    (keys, n)
}

/// A first look at a leaf's primitives before `visit` tests them one by one:
/// which of them (bit per primitive, at most [`TRI_CHUNK`]) may be hit.
pub(super) trait Cull {
    /// The primitives of `prims` (at most [`TRI_CHUNK`]) to test.
    fn keep<S: Simd>(&self, s: S, prims: &[u32], t_min: f64, t_max: f64) -> u32;
}

/// No first look: every primitive is tested.
pub(super) struct KeepAll;

impl Cull for KeepAll {
    #[inline(always)]
    fn keep<S: Simd>(&self, _: S, _: &[u32], _: f64, _: f64) -> u32 {
        u32::MAX
    }
}

/// A mesh's triangles, culled in f32 several at a time ([`tri_keep`]).
pub(super) struct TriCull<'a> {
    pub(super) ray: RayTri,
    pub(super) positions: &'a [[f32; 3]],
    pub(super) triangles: &'a [[u32; 3]],
}

impl Cull for TriCull<'_> {
    #[inline(always)]
    fn keep<S: Simd>(&self, s: S, prims: &[u32], t_min: f64, t_max: f64) -> u32 {
        tri_keep(
            s,
            &self.ray,
            self.positions,
            self.triangles,
            prims,
            t_min,
            t_max,
        )
    }
}

/// The nearest-first walk ([`super::Bvh::traverse`]).
pub(super) struct Closest<'a, F, C> {
    pub(super) nodes: &'a [Wide],
    pub(super) prims: &'a [u32],
    pub(super) ray: &'a Ray,
    pub(super) t_min: f64,
    pub(super) t_max: f64,
    pub(super) visit: F,
    pub(super) cull: C,
}

impl<F: FnMut(u32, f64) -> Option<f64>, C: Cull> WithSimd for Closest<'_, F, C> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let Closest {
            nodes,
            prims,
            ray,
            t_min,
            mut t_max,
            mut visit,
            cull,
        } = self;
        if nodes.is_empty() {
            return;
        }
        let r = RayBoxes::new(ray);
        let near = down(t_min);
        let mut far32 = far(t_max);
        let mut stack = Stack::new();
        let mut dist = [0.0f32; WIDTH];
        let mut node = 0usize;
        loop {
            let n = &nodes[node];
            let mask = hit8(s, &r, &n.boxes, near, far32, &mut dist);
            let mut next = None;
            if mask & mask.wrapping_sub(1) == 0 {
                // One lane or none: no ordering; an inner node is entered at once.
                if mask != 0 {
                    let lane = mask.trailing_zeros() as usize;
                    if n.count[lane] == 0 {
                        node = n.child[lane] as usize;
                        continue;
                    }
                    next = Some(key(dist[lane], (node * WIDTH + lane) as u32));
                }
            } else {
                // Push all but the nearest, farthest first.
                let (keys, k) = sorted(mask, &dist, |lane| (node * WIDTH + lane) as u32);
                for &key in keys[1..k].iter().rev() {
                    stack.push(key);
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
                let (at, lane) = ((key as u32) as usize / WIDTH, key as usize % WIDTH);
                let (child, count) = (nodes[at].child[lane], nodes[at].count[lane]);
                if count == 0 {
                    node = child as usize;
                    break;
                }
                let leaf = &prims[child as usize..(child + count) as usize];
                for chunk in leaf.chunks(TRI_CHUNK) {
                    let keep = cull.keep(s, chunk, t_min, t_max);
                    for (i, &p) in chunk.iter().enumerate() {
                        if keep & (1 << i) == 0 {
                            continue;
                        }
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
    }
}

/// The unordered walk ([`super::Bvh::any`]): leaves are visited as their
/// boxes are entered, inner nodes in lane order, no sorting.
pub(super) struct Any<'a, F> {
    pub(super) nodes: &'a [Wide],
    pub(super) prims: &'a [u32],
    pub(super) ray: &'a Ray,
    pub(super) t_min: f64,
    pub(super) t_max: f64,
    pub(super) visit: F,
}

impl<F: FnMut(u32) -> bool> WithSimd for Any<'_, F> {
    type Output = bool;

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) -> bool {
        let Any {
            nodes,
            prims,
            ray,
            t_min,
            t_max,
            mut visit,
        } = self;
        if nodes.is_empty() {
            return false;
        }
        let r = RayBoxes::new(ray);
        let (near, far32) = (down(t_min), far(t_max));
        let mut stack = Stack::new();
        let mut dist = [0.0f32; WIDTH];
        let mut node = 0usize;
        loop {
            let n = &nodes[node];
            let mut mask = hit8(s, &r, &n.boxes, near, far32, &mut dist);
            let mut next = None;
            while mask != 0 {
                let lane = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                let (child, count) = (n.child[lane], n.count[lane]);
                if count == 0 {
                    if let Some(other) = next.replace(child) {
                        stack.push(u64::from(other));
                    }
                } else {
                    for &p in &prims[child as usize..(child + count) as usize] {
                        if visit(p) {
                            return true;
                        }
                    }
                }
            }
            node = match next.or_else(|| stack.pop().map(|k| k as u32)) {
                Some(c) => c as usize,
                None => return false,
            };
        }
    }
}

/// The flat list's walk ([`super::Bvh::flat`]): every box tested, the entered
/// ones visited nearest first (`N`: room for that many entered boxes).
pub(super) struct Flat<'a, F, const N: usize> {
    pub(super) chunks: &'a [Wide],
    pub(super) ray: &'a Ray,
    pub(super) t_min: f64,
    pub(super) t_max: f64,
    pub(super) visit: F,
}

impl<F: FnMut(u32, f64) -> Option<f64>, const N: usize> WithSimd for Flat<'_, F, N> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let Flat {
            chunks,
            ray,
            t_min,
            mut t_max,
            mut visit,
        } = self;
        let r = RayBoxes::new(ray);
        let near = down(t_min);
        let limit = far(t_max);
        // The entered lanes as keys (entry distance above the primitive), kept
        // sorted by insertion: a ray enters few of the boxes.
        let mut keys = [0u64; N];
        let mut n = 0;
        let mut dist = [0.0f32; WIDTH];
        for c in chunks {
            let mut mask = hit8(s, &r, &c.boxes, near, limit, &mut dist);
            while mask != 0 {
                let lane = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                let k = key(dist[lane], c.child[lane]);
                let mut j = n;
                while j > 0 && keys[j - 1] > k {
                    keys[j] = keys[j - 1];
                    j -= 1;
                }
                keys[j] = k;
                n += 1;
            }
        }
        let mut far32 = limit;
        for &k in &keys[..n] {
            if key_dist(k) > far32 {
                return;
            }
            match visit(k as u32, t_max) {
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

/// Traversal stack entries kept in a fixed array (deeper ones spill to the heap):
/// small enough that setting it up costs a few stores, not a `memset` call.
const STACK: usize = 32;

/// The traversal stack of keys.
struct Stack {
    fixed: [u64; STACK],
    len: usize,
    spill: Vec<u64>,
}

impl Stack {
    #[inline(always)]
    fn new() -> Stack {
        Stack {
            fixed: [0; STACK],
            len: 0,
            spill: Vec::new(),
        }
    }

    #[inline(always)]
    fn push(&mut self, key: u64) {
        if self.len < STACK {
            self.fixed[self.len] = key;
            self.len += 1;
        } else {
            self.spill.push(key);
        }
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<u64> {
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
