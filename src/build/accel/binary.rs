//! The world's hierarchy (and a small mesh's) as traversal walks it: the binary
//! SAH tree with its (f32, outward-rounded) bounds widened to f64, tested one box
//! at a time in the ray's own precision. World trees are small (one primitive a
//! leaf), so they stay in cache; here the two-child walk, whose branches let the
//! processor run ahead, measured faster than the 4-wide one large meshes use (see
//! [`super::wide`]).

use super::builder::Node;
use super::Ray;
use glam::DVec3;

/// Traversal stack entries kept in a fixed array (deeper ones spill to the heap):
/// small enough that setting it up costs a few stores, not a `memset` call
/// (2.5% of a sphere scene's instructions with 128).
const STACK: usize = 32;

/// A [`Node`] with its (f32) bounds widened to f64 ahead of time: the same
/// numbers, so the same traversal, without six conversions per box test. The
/// world's hierarchy (small: one leaf per primitive) keeps these.
#[derive(Clone, Copy, Debug)]
pub(super) struct Node64 {
    min: DVec3,
    max: DVec3,
    count: u32,
    first: u32,
}

impl Node64 {
    /// Entry distance of `ray` within `(t_min, t_max)`. `FINITE` says every
    /// component of `inv` is finite: then no slab distance can be NaN (0 × ∞)
    /// and plain comparisons (one `minsd`/`maxsd` each) replace the NaN-aware
    /// `min`/`max`, which cost about a third of mesh traversal in `perf`.
    #[inline(always)]
    fn hit<const FINITE: bool>(
        &self,
        ray: &Ray,
        inv: DVec3,
        t_min: f64,
        t_max: f64,
    ) -> Option<f64> {
        let (min, max) = (self.min, self.max);
        if FINITE {
            let o = ray.origin;
            let lt = |a: f64, b: f64| if a < b { a } else { b };
            let gt = |a: f64, b: f64| if a > b { a } else { b };
            let (x0, x1) = ((min.x - o.x) * inv.x, (max.x - o.x) * inv.x);
            let (y0, y1) = ((min.y - o.y) * inv.y, (max.y - o.y) * inv.y);
            let (z0, z1) = ((min.z - o.z) * inv.z, (max.z - o.z) * inv.z);
            let near = gt(gt(lt(x0, x1), lt(y0, y1)), gt(lt(z0, z1), t_min));
            let far = lt(lt(gt(x0, x1), gt(y0, y1)), lt(gt(z0, z1), t_max));
            return (near <= far).then_some(near);
        }
        // An axis the ray runs along (inv ±∞) bounds nothing when the origin is
        // within the slab, faces included, and everything when it is not (its
        // distances would be ±∞, or NaN for an origin on a face).
        let (mut near, mut far) = (t_min, t_max);
        for a in 0..3 {
            let o = ray.origin[a];
            if inv[a].is_finite() {
                let (t0, t1) = ((min[a] - o) * inv[a], (max[a] - o) * inv[a]);
                near = near.max(t0.min(t1));
                far = far.min(t0.max(t1));
            } else if o < min[a] || o > max[a] {
                return None;
            }
        }
        (near <= far).then_some(near)
    }

    /// `n` widened.
    pub(super) fn new(n: &Node) -> Node64 {
        Node64 {
            min: n.min.as_dvec3(),
            max: n.max.as_dvec3(),
            count: n.count,
            first: n.first,
        }
    }
}

/// The binary trees `a` (over `a_prims`) and `b` under one new root, `b`'s
/// leaves pointing past `a_prims` (whose length is `a_prims`): `[root, a's
/// root, b's root, a's other nodes, b's other nodes]`, every pair of children
/// still side by side. Linear in the nodes, where building again is not.
pub(super) fn join(a: &[Node64], b: &[Node64], a_prims: u32) -> Vec<Node64> {
    let (n, m) = (a.len() as u32, b.len() as u32);
    // Where node i of each tree goes.
    let in_a = |i: u32| if i == 0 { 1 } else { i + 2 };
    let in_b = |i: u32| if i == 0 { 2 } else { n + 1 + i };
    let mut out = Vec::with_capacity((n + m + 1) as usize);
    out.push(Node64 {
        min: a[0].min.min(b[0].min),
        max: a[0].max.max(b[0].max),
        count: 0,
        first: 1,
    });
    let moved = |node: &Node64, to: &dyn Fn(u32) -> u32, prims: u32| Node64 {
        first: if node.count > 0 {
            node.first + prims
        } else {
            to(node.first)
        },
        ..*node
    };
    out.push(moved(&a[0], &in_a, 0));
    out.push(moved(&b[0], &in_b, a_prims));
    out.extend(a[1..].iter().map(|x| moved(x, &in_a, 0)));
    out.extend(b[1..].iter().map(|x| moved(x, &in_b, a_prims)));
    out
}

/// Visits leaves of the tree `nodes` (root first, over `prims`) that `ray` may
/// hit, nearest first: see [`super::Bvh::traverse`].
#[inline(always)]
pub(super) fn traverse(
    nodes: &[Node64],
    prims: &[u32],
    ray: &Ray,
    t_min: f64,
    t_max: f64,
    mut visit: impl FnMut(u32, f64) -> Option<f64>,
) {
    if nodes.is_empty() {
        return;
    }
    let inv = ray.dir.recip();
    if inv.is_finite() {
        walk::<true>(prims, nodes, ray, inv, t_min, t_max, &mut visit);
    } else {
        walk::<false>(prims, nodes, ray, inv, t_min, t_max, &mut visit);
    }
}

/// [`traverse`] with `inv = 1 / ray.dir`; see [`Node64::hit`] for `FINITE`.
#[inline(always)]
fn walk<const FINITE: bool>(
    prims: &[u32],
    nodes: &[Node64],
    ray: &Ray,
    inv: DVec3,
    t_min: f64,
    mut t_max: f64,
    visit: &mut impl FnMut(u32, f64) -> Option<f64>,
) {
    // (Keeping each far child's entry distance to skip the box test on pop
    // measured 11% slower on the 1M-triangle mesh and no faster on spheres.)
    let mut stack = [0u32; STACK];
    let mut spill: Vec<u32> = Vec::new();
    let mut sp = 0usize;
    let mut node = 0usize;
    if nodes[0].hit::<FINITE>(ray, inv, t_min, t_max).is_none() {
        return;
    }
    loop {
        let n = nodes[node];
        if n.count > 0 {
            for &p in &prims[n.first as usize..(n.first + n.count) as usize] {
                match visit(p, t_max) {
                    Some(t) => t_max = t,
                    None => return,
                }
            }
        } else {
            let (a, b) = (n.first as usize, n.first as usize + 1);
            let [na, nb] = &nodes[a..a + 2] else {
                unreachable!("interior nodes have two children");
            };
            let ta = na.hit::<FINITE>(ray, inv, t_min, t_max);
            let tb = nb.hit::<FINITE>(ray, inv, t_min, t_max);
            match (ta, tb) {
                (Some(x), Some(y)) => {
                    let (near, far) = if x <= y { (a, b) } else { (b, a) };
                    if sp < STACK {
                        stack[sp] = far as u32;
                        sp += 1;
                    } else {
                        spill.push(far as u32);
                    }
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
            let cand = if let Some(c) = spill.pop() {
                c as usize
            } else if sp > 0 {
                sp -= 1;
                stack[sp] as usize
            } else {
                return;
            };
            if nodes[cand].hit::<FINITE>(ray, inv, t_min, t_max).is_some() {
                node = cand;
                break;
            }
        }
    }
}
