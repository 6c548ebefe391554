//! The acceleration structure and its kernels: a binned-SAH binary build
//! ([`builder`]) collapsed into 8-wide nodes of f32 boxes ([`wide`]), walked
//! ([`traverse`]) with one ray against eight boxes per step ([`kernels`]) at
//! the SIMD level in force ([`simd`]). The rest of `build` asks only two
//! questions of a [`Bvh`]: the nearest hit ([`Bvh::traverse`], nearest first)
//! and whether anything lies in between ([`Bvh::any`], no ordering).
//!
//! f32 for culling, f64 for answers: child boxes are rounded outwards and the
//! ray's f32 copy is padded so a box test can give a false hit but never a
//! false miss; primitive tests stay in f64 with the caller.

mod binary;
mod builder;
mod kernels;
mod simd;
mod traverse;
mod wide;

pub use simd::{set_simd_level, simd_level, SimdLevel, SIMD_ENV};

use super::{Aabb, Ray};
use binary::Node64;
use builder::Box32;
use wide::Wide;

/// Most primitives a mesh leaf holds before splitting is considered.
const MAX_LEAF: usize = 4;
/// The same for the hierarchy over a world's primitives, where a primitive test
/// (a transformed box, a torus, a CSG) costs more than a node test: leaves of one
/// primitive unless the SAH prefers more (the Cornell box's walls and boxes: 9%
/// fewer instructions per path-traced sample than with leaves of up to 4).
const MAX_WORLD_LEAF: usize = 1;
/// Meshes of at least this many triangles are walked 8-wide: on small ones the
/// ray setup of the wide walk costs more than it saves.
const WIDE_MIN: usize = 256;
/// Whether the world's hierarchy is walked 8-wide (else as a binary tree in f64).
const WORLD_WIDE: bool = false;
/// Most primitives [`Bvh::flat`] takes. For the path tracer's scattered rays a
/// flat list beat the world's tree at every size measured (the Cornell box with
/// 14 to 200 small spheres added: 30 to 216 primitives, 12-28% more samples per
/// second); the classic renderer's coherent rays do better with the tree.
pub const FLAT_MAX: usize = 256;
/// Flat lists of up to this many boxes keep their walk's keys in a small array.
const FLAT_SMALL: usize = 32;

/// Whether mesh leaves are culled in f32 before the f64 triangle tests
/// ([`Bvh::traverse_triangles`]). Off: measured slower on the 1M-triangle mesh
/// (`cargo bench --bench mesh`, Mrays per CPU second at AVX2): 3.28 without,
/// 2.7-2.8 with leaves of up to 4 triangles, 2.5 with up to 8 (the corners are
/// gathered through the index list for each leaf; the f64 test rejects most
/// triangles at its first comparison anyway). Kept, and tested, for layouts
/// that store leaf triangles side by side.
const TRI_CULL: bool = false;

/// A mesh's triangles as [`Bvh::traverse_triangles`] reads them.
#[derive(Clone, Copy, Debug)]
pub struct Triangles<'a> {
    /// Vertex positions.
    pub positions: &'a [[f32; 3]],
    /// Corner indices into `positions`, per triangle.
    pub triangles: &'a [[u32; 3]],
}

/// A binned-SAH BVH over primitive indices, walked 8-wide in f32 lanes (or, for
/// small meshes, as a binary tree in f64). The path tracer walks small worlds
/// with no tree at all ([`Bvh::flat`]).
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    /// The tree collapsed to 8-wide nodes, root first (else empty).
    nodes: Vec<Wide>,
    /// The binary tree in f64, root first (else empty).
    exact: Vec<Node64>,
    /// [`Bvh::flat`]'s boxes, eight a node (lane child: the primitive, count 1)
    /// (else empty).
    flat: Vec<Wide>,
    /// Primitive indices, ordered so every leaf's are contiguous.
    prims: Vec<u32>,
    /// Bounds of everything.
    root: Option<Box32>,
}

impl Bvh {
    /// Builds a hierarchy over `items`: (primitive index, world bounds).
    pub fn build(items: &[(u32, Aabb)]) -> Bvh {
        let boxes = items.iter().map(|(_, b)| Box32::from_aabb(b)).collect();
        let mut bvh = Bvh::build_from(boxes, MAX_WORLD_LEAF, WORLD_WIDE);
        for p in &mut bvh.prims {
            *p = items[*p as usize].0;
        }
        bvh
    }

    /// No tree over `items` (at most [`FLAT_MAX`]; `None` for more, or none):
    /// a walk tests every item's box, eight at a time in f32, and visits the
    /// ones entered nearest first. In a small scene most inner boxes of a tree
    /// hold most of it: in the Cornell box, whose walls enclose the room, a
    /// scattered ray tested about 24 of the tree's 39 boxes one at a time,
    /// where 2 tests cover its 16 primitives'.
    pub fn flat(items: &[(u32, Aabb)]) -> Option<Bvh> {
        if items.is_empty() || items.len() > FLAT_MAX {
            return None;
        }
        let mut root = Box32::EMPTY;
        let mut flat = vec![Wide::EMPTY; items.len().div_ceil(kernels::WIDTH)];
        for (k, (prim, b)) in items.iter().enumerate() {
            let b = Box32::from_aabb(b);
            root = root.union(&b);
            flat[k / kernels::WIDTH].set(k % kernels::WIDTH, b.min.into(), b.max.into(), *prim, 1);
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

    /// The tree over `boxes`, 8-wide when `wide`.
    fn build_from(boxes: Vec<Box32>, max_leaf: usize, wide: bool) -> Bvh {
        if boxes.is_empty() {
            return Bvh::default();
        }
        // The inputs (36 bytes a primitive) are gone before the wide nodes are made.
        let (binary, order) = builder::binary_tree(boxes, max_leaf);
        let root = Box32 {
            min: binary[0].min.into(),
            max: binary[0].max.into(),
        };
        let (nodes, exact) = if wide {
            (wide::collapse(&binary), Vec::new())
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

    /// One hierarchy over `self`'s and `other`'s primitives, their trees kept
    /// whole under a new root (the two levels of an animation's world: what
    /// stands still, built once, and what moves, built every frame). `None`
    /// unless both are binary trees (the world's kind).
    pub fn join(&self, other: &Bvh) -> Option<Bvh> {
        if self.exact.is_empty() || other.exact.is_empty() {
            return None;
        }
        let exact = binary::join(&self.exact, &other.exact, self.prims.len() as u32);
        let mut prims = Vec::with_capacity(self.prims.len() + other.prims.len());
        prims.extend_from_slice(&self.prims);
        prims.extend_from_slice(&other.prims);
        let root = match (self.root, other.root) {
            (Some(a), Some(b)) => Some(a.union(&b)),
            (a, b) => a.or(b),
        };
        Some(Bvh {
            exact,
            prims,
            root,
            ..Bvh::default()
        })
    }

    /// World bounds of everything in the hierarchy.
    pub fn bounds(&self) -> Aabb {
        self.root.map_or(Aabb::EMPTY, |b| {
            Aabb::new(b.min.as_dvec3(), b.max.as_dvec3())
        })
    }

    /// Number of nodes, binary or 8-wide (for statistics and tests).
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
            if self.flat.len() * kernels::WIDTH <= FLAT_SMALL {
                simd::dispatch(traverse::Flat::<_, FLAT_SMALL> {
                    chunks: &self.flat,
                    ray,
                    t_min,
                    t_max,
                    visit,
                });
            } else {
                simd::dispatch(traverse::Flat::<_, FLAT_MAX> {
                    chunks: &self.flat,
                    ray,
                    t_min,
                    t_max,
                    visit,
                });
            }
        } else {
            simd::dispatch(traverse::Closest {
                nodes: &self.nodes,
                prims: &self.prims,
                ray,
                t_min,
                t_max,
                visit,
                cull: traverse::KeepAll,
            });
        }
    }

    /// [`Bvh::traverse`] over a tree of triangles (`triangles`, indexing
    /// `positions`): each leaf's triangles are first tested together in f32,
    /// several to a register, and only those that may be hit go to `visit` for
    /// the f64 test. The f32 test errs towards a hit, never a miss, so the
    /// answers are the f64 test's.
    #[inline]
    pub fn traverse_triangles(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        triangles: Triangles<'_>,
        visit: impl FnMut(u32, f64) -> Option<f64>,
    ) {
        if self.nodes.is_empty() || !TRI_CULL {
            return self.traverse(ray, t_min, t_max, visit);
        }
        self.traverse_culled(ray, t_min, t_max, triangles, visit);
    }

    /// [`Bvh::traverse_triangles`] with the f32 cull whatever [`TRI_CULL`] says
    /// (8-wide trees only).
    #[inline]
    pub(crate) fn traverse_culled(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        triangles: Triangles<'_>,
        visit: impl FnMut(u32, f64) -> Option<f64>,
    ) {
        simd::dispatch(traverse::Closest {
            nodes: &self.nodes,
            prims: &self.prims,
            ray,
            t_min,
            t_max,
            visit,
            cull: traverse::TriCull {
                ray: kernels::RayTri::new(ray),
                positions: triangles.positions,
                triangles: triangles.triangles,
            },
        });
    }

    /// Whether `found(prim)` holds for a primitive whose box the ray enters
    /// within `t_min..t_max`: the walk for shadow rays, which only need a yes.
    /// Leaves are tried in no particular order (but the same on every run and
    /// SIMD level); the walk ends at the first `true`.
    #[inline]
    pub fn any(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        mut found: impl FnMut(u32) -> bool,
    ) -> bool {
        if self.nodes.is_empty() {
            let mut yes = false;
            self.traverse(ray, t_min, t_max, |i, t| {
                yes = found(i);
                (!yes).then_some(t)
            });
            return yes;
        }
        simd::dispatch(traverse::Any {
            nodes: &self.nodes,
            prims: &self.prims,
            ray,
            t_min,
            t_max,
            visit: found,
        })
    }
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

    /// The tree over `bounds(0..n)`, binary (f64) and 8-wide (f32 lanes), with
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

#[cfg(test)]
mod cull_tests {
    use super::kernels::{tri_keep, RayTri, TRI_CHUNK};
    use super::Ray;
    use crate::build::shapes::flat::triangle;
    use glam::DVec3;
    use pulp::{Simd, WithSimd};
    use rand_core::{RngCore, SeedableRng};

    /// [`tri_keep`] at the level in force.
    struct Keep<'a> {
        ray: &'a RayTri,
        positions: &'a [[f32; 3]],
        triangles: &'a [[u32; 3]],
        prims: &'a [u32],
        t_max: f64,
    }

    impl WithSimd for Keep<'_> {
        type Output = u32;
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) -> u32 {
            tri_keep(
                s,
                self.ray,
                self.positions,
                self.triangles,
                self.prims,
                0.0,
                self.t_max,
            )
        }
    }

    #[test]
    fn the_triangle_cull_keeps_every_triangle_the_f64_test_hits() {
        // Rays aimed at the edges and corners of random triangles of many sizes
        // and places, where the f64 test's answer hangs on its last bits; the
        // cull must keep every triangle that test hits, and give the same bits
        // at the scalar level as at the processor's best.
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(5);
        let mut unit = move || (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        let prims: Vec<u32> = (0..TRI_CHUNK as u32).collect();
        let triangles: Vec<[u32; 3]> = (0..TRI_CHUNK as u32)
            .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
            .collect();
        let mut kept_hits = 0;
        for k in 0..20_000 {
            let scale = [1.0, 1e-3, 100.0, 1e4][k % 4];
            let off = if k % 5 == 0 { 1e3 } else { 0.0 };
            let positions: Vec<[f32; 3]> = (0..3 * TRI_CHUNK)
                .map(|_| [0; 3].map(|_| (off + (unit() - 0.5) * scale) as f32))
                .collect();
            let corners = |j: usize| {
                triangles[j].map(|i| {
                    let p = positions[i as usize];
                    DVec3::new(p[0] as f64, p[1] as f64, p[2] as f64)
                })
            };
            let [a, b, c] = corners(k % TRI_CHUNK);
            let (u, v) = match k % 4 {
                0 => (0.0, unit()),
                1 => (unit(), 0.0),
                2 => {
                    let u = unit();
                    (u, 1.0 - u)
                }
                _ => ((k % 2) as f64, 0.0),
            };
            let target = a + (b - a) * u + (c - a) * v;
            let origin = target
                + DVec3::new(unit() - 0.5, unit() - 0.5, unit() - 0.5)
                    * scale
                    * [1.0, 10.0, 1e3][k % 3];
            let ray = Ray::new(origin, target - origin);
            let t_max = if k % 3 == 0 {
                1.0 + 1e-9
            } else {
                f64::INFINITY
            };
            let r = RayTri::new(&ray);
            let keep = tri_keep(
                pulp::Scalar::new(),
                &r,
                &positions,
                &triangles,
                &prims,
                0.0,
                t_max,
            );
            let best = super::simd::dispatch(Keep {
                ray: &r,
                positions: &positions,
                triangles: &triangles,
                prims: &prims,
                t_max,
            });
            assert_eq!(keep, best, "ray {k}: scalar and SIMD levels differ");
            for j in 0..TRI_CHUNK {
                let [a, b, c] = corners(j);
                if let Some((t, _, _)) = triangle(a, b - a, c - a, &ray) {
                    if t > 0.0 && t < t_max {
                        kept_hits += 1;
                        assert!(
                            keep & (1 << j) != 0,
                            "ray {k} {ray:?}: triangle {j} hit at {t} but culled"
                        );
                    }
                }
            }
        }
        assert!(
            kept_hits > 5_000,
            "only {kept_hits} hits: the test aims badly"
        );
    }
}
