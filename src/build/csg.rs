//! Constructive solid geometry: `merge`, `intersection`, `difference`, and
//! `clipped_by`, as a tree over leaves that each keep their own world
//! transform, texture and interior.
//!
//! A ray collects every crossing of every visible leaf, sorted by distance;
//! the first one that lies on the surface of the whole tree wins. A crossing of
//! leaf L at point p is on the surface when, at every node above L, the siblings
//! agree: for `merge`, p is inside none of them; for `intersection`, inside all
//! of them; for a clip, inside all the clipping objects. `difference { A B C }`
//! is `intersection { A, inverse B, inverse C }`, as in POV-Ray.

use super::shape::{PrimShape, ShapeHit};
use super::{Aabb, Ray};
use crate::scene::{Interior, Texture, Transform};
use glam::{DMat4, DVec3};
use std::sync::Arc;

/// One leaf shape of a CSG tree.
#[derive(Clone, Debug)]
pub struct CsgLeaf {
    /// The geometry.
    pub shape: PrimShape,
    /// `world_from_leaf`; `None` for the identity.
    pub transform: Option<Transform>,
    /// The texture in force on this leaf.
    pub texture: Arc<Texture>,
    /// Maps world points into the texture's space.
    pub texture_from_world: Option<DMat4>,
    /// The interior in force.
    pub interior: Option<Arc<Interior>>,
    /// The leaf's own `inverse` (and inversion by a `difference`).
    pub inverse: bool,
    /// Whether its normal must be flipped to point out of the whole solid (an odd
    /// number of inversions on the way from the root).
    pub flip: bool,
    /// False for the leaves of clipping objects: they cut, but add no surface.
    pub surface: bool,
    /// World-space bounds; `None` when unbounded.
    pub bounds: Option<Aabb>,
}

/// How a group combines its children.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GroupKind {
    /// `union`: every child surface is kept.
    Union,
    /// `merge`: surfaces inside another child are removed.
    Merge,
    /// `intersection` (and `difference`, with inverted operands).
    Intersection,
}

/// A node of the tree.
#[derive(Clone, Debug)]
pub enum CsgNode {
    /// A leaf, by index into [`Csg::leaves`].
    Leaf(u32),
    /// A group.
    Group {
        /// How the children combine.
        kind: GroupKind,
        /// The children.
        children: Vec<CsgNode>,
        /// Inside and outside swapped.
        inverse: bool,
    },
    /// An object with `clipped_by`.
    Clip {
        /// What is clipped.
        object: Box<CsgNode>,
        /// The clipping objects: only what is inside all of them remains.
        clips: Vec<CsgNode>,
        /// Inside and outside swapped.
        inverse: bool,
    },
}

/// A CSG tree and its leaves.
#[derive(Clone, Debug)]
pub struct Csg {
    /// Every leaf.
    pub leaves: Vec<CsgLeaf>,
    /// The root.
    pub root: CsgNode,
}

impl CsgLeaf {
    fn local(&self, p: DVec3) -> DVec3 {
        match &self.transform {
            None => p,
            Some(t) => t.inverse.transform_point3(p),
        }
    }

    /// Inside this leaf (with its `inverse`), world point.
    pub fn inside(&self, p: DVec3) -> bool {
        self.shape.inside(self.local(p)) != self.inverse
    }

    /// The unit world normal at `p`, out of the whole solid.
    pub fn normal(&self, p: DVec3, sub: u32) -> DVec3 {
        let n = match &self.transform {
            None => self.shape.normal(p, sub),
            Some(t) => t.normal(self.shape.normal(self.local(p), sub)),
        }
        .normalize();
        if self.flip {
            -n
        } else {
            n
        }
    }
}

impl CsgNode {
    /// Toggles the node's `inverse`.
    pub fn invert(&mut self, leaves: &mut [CsgLeaf]) {
        match self {
            CsgNode::Leaf(i) => leaves[*i as usize].inverse ^= true,
            CsgNode::Group { inverse, .. } | CsgNode::Clip { inverse, .. } => *inverse ^= true,
        }
    }
}

impl Csg {
    /// A tree; sets each leaf's normal flip and surface flag from its path.
    pub fn new(mut leaves: Vec<CsgLeaf>, root: CsgNode) -> Csg {
        fn walk(n: &CsgNode, parity: bool, surface: bool, leaves: &mut [CsgLeaf]) {
            match n {
                CsgNode::Leaf(i) => {
                    let l = &mut leaves[*i as usize];
                    l.flip = parity != l.inverse;
                    l.surface = surface;
                }
                CsgNode::Group {
                    children, inverse, ..
                } => {
                    for c in children {
                        walk(c, parity != *inverse, surface, leaves);
                    }
                }
                CsgNode::Clip {
                    object,
                    clips,
                    inverse,
                } => {
                    walk(object, parity != *inverse, surface, leaves);
                    for c in clips {
                        walk(c, parity != *inverse, false, leaves);
                    }
                }
            }
        }
        walk(&root, false, true, &mut leaves);
        Csg { leaves, root }
    }

    /// Whether world point `p` is inside the solid.
    pub fn inside(&self, p: DVec3) -> bool {
        self.inside_node(&self.root, p)
    }

    fn inside_node(&self, n: &CsgNode, p: DVec3) -> bool {
        match n {
            CsgNode::Leaf(i) => self.leaves[*i as usize].inside(p),
            CsgNode::Group {
                kind,
                children,
                inverse,
            } => {
                let v = match kind {
                    GroupKind::Union | GroupKind::Merge => {
                        children.iter().any(|c| self.inside_node(c, p))
                    }
                    GroupKind::Intersection => children.iter().all(|c| self.inside_node(c, p)),
                };
                v != *inverse
            }
            CsgNode::Clip {
                object,
                clips,
                inverse,
            } => {
                let v = self.inside_node(object, p) && clips.iter().all(|c| self.inside_node(c, p));
                v != *inverse
            }
        }
    }

    /// Whether a crossing of `leaf` at `p` lies on the surface of node `n`:
    /// `None` when the leaf is not under `n`.
    fn keeps(&self, n: &CsgNode, leaf: u32, p: DVec3) -> Option<bool> {
        match n {
            CsgNode::Leaf(i) => (*i == leaf).then_some(true),
            CsgNode::Group { kind, children, .. } => {
                let (k, on) = children
                    .iter()
                    .enumerate()
                    .find_map(|(k, c)| self.keeps(c, leaf, p).map(|on| (k, on)))?;
                if !on {
                    return Some(false);
                }
                let others = children.iter().enumerate().filter(|(j, _)| *j != k);
                Some(match kind {
                    GroupKind::Union => true,
                    GroupKind::Merge => others.into_iter().all(|(_, c)| !self.inside_node(c, p)),
                    GroupKind::Intersection => {
                        others.into_iter().all(|(_, c)| self.inside_node(c, p))
                    }
                })
            }
            CsgNode::Clip { object, clips, .. } => {
                let on = self.keeps(object, leaf, p)?;
                Some(on && clips.iter().all(|c| self.inside_node(c, p)))
            }
        }
    }

    /// The nearest surface crossing in `(t_min, t_max)`: distance, leaf, part.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<ShapeHit> {
        let inv = ray.dir.recip();
        let mut all = Crossings::default();
        for (i, l) in self.leaves.iter().enumerate() {
            if !l.surface {
                continue;
            }
            if let Some(b) = &l.bounds {
                if b.hit(ray, inv, t_min, t_max).is_none() {
                    continue;
                }
            }
            let local = match &l.transform {
                None => *ray,
                Some(t) => ray.transformed(&t.inverse),
            };
            l.shape.hits(&local, t_min, t_max, &mut |t, sub| {
                all.push((t, i as u32, sub))
            });
        }
        let all = all.as_mut_slice();
        all.sort_by(|a, b| a.0.total_cmp(&b.0));
        all.iter()
            .copied()
            .find(|&(t, leaf, _)| self.keeps(&self.root, leaf, ray.at(t)) == Some(true))
    }

    /// World bounds; `None` when unbounded.
    pub fn bounds(&self) -> Option<Aabb> {
        self.node_bounds(&self.root)
    }

    fn node_bounds(&self, n: &CsgNode) -> Option<Aabb> {
        match n {
            CsgNode::Leaf(i) => {
                let l = &self.leaves[*i as usize];
                if l.inverse {
                    None
                } else {
                    l.bounds
                }
            }
            CsgNode::Group { inverse: true, .. } | CsgNode::Clip { inverse: true, .. } => None,
            CsgNode::Group { kind, children, .. } => {
                let bs = children.iter().map(|c| self.node_bounds(c));
                match kind {
                    GroupKind::Union | GroupKind::Merge => bs
                        .into_iter()
                        .try_fold(Aabb::EMPTY, |a, b| Some(a.union(&b?))),
                    GroupKind::Intersection => bs.fold(None, meet),
                }
            }
            CsgNode::Clip { object, clips, .. } => clips
                .iter()
                .map(|c| self.node_bounds(c))
                .fold(self.node_bounds(object), meet),
        }
    }
}

/// The crossings of one ray with the leaves: on the stack for the usual few,
/// spilled to the heap past [`Crossings::INLINE`].
struct Crossings {
    inline: [ShapeHit; Crossings::INLINE],
    len: usize,
    spilled: Vec<ShapeHit>,
}

impl Default for Crossings {
    fn default() -> Self {
        Crossings {
            inline: [(0.0, 0, 0); Crossings::INLINE],
            len: 0,
            spilled: Vec::new(),
        }
    }
}

impl Crossings {
    const INLINE: usize = 16;

    fn push(&mut self, h: ShapeHit) {
        if self.len < Self::INLINE {
            self.inline[self.len] = h;
            self.len += 1;
        } else {
            if self.spilled.is_empty() {
                self.spilled.extend_from_slice(&self.inline);
            }
            self.spilled.push(h);
        }
    }

    fn as_mut_slice(&mut self) -> &mut [ShapeHit] {
        if self.spilled.is_empty() {
            &mut self.inline[..self.len]
        } else {
            &mut self.spilled
        }
    }
}

/// Intersection of bounds where `None` is everything.
fn meet(a: Option<Aabb>, b: Option<Aabb>) -> Option<Aabb> {
    match (a, b) {
        (Some(a), Some(b)) => Some(Aabb::new(a.min.max(b.min), a.max.min(b.max))),
        (x, None) | (None, x) => x,
    }
}
