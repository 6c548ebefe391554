//! The wide tree as traversal walks it: the binary SAH tree collapsed into
//! nodes of up to eight children whose f32 boxes sit as structure of arrays,
//! tested together by [`super::kernels::hit8`].

use super::builder::{area, Node};
use super::kernels::{Boxes8, EMPTY_BOXES, WIDTH};

/// One node of up to eight children. A lane is an inner node (`count == 0`,
/// `child` its index), a leaf (`count` primitives from `child` on in
/// [`super::Bvh`]'s primitive list) or empty (a box no ray enters). A flat
/// list's lanes are primitives (`child` the primitive, `count` 1).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub(super) struct Wide {
    /// Child boxes by lane.
    pub(super) boxes: Boxes8,
    pub(super) child: [u32; WIDTH],
    pub(super) count: [u32; WIDTH],
}

impl Wide {
    pub(super) const EMPTY: Wide = Wide {
        boxes: EMPTY_BOXES,
        child: [0; WIDTH],
        count: [0; WIDTH],
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
            self.boxes[0][a][lane] = min[a];
            self.boxes[1][a][lane] = max[a];
        }
        self.child[lane] = child;
        self.count[lane] = count;
    }
}

/// The wide tree of binary tree `binary` (root first): each wide node takes the
/// children of a binary node and keeps opening its largest inner child until it
/// has eight (fewer where the tree runs out of inner nodes).
pub(super) fn collapse(binary: &[Node]) -> Vec<Wide> {
    let mut out = Vec::with_capacity(binary.len() / 4 + 1);
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
    let mut kids = [0usize; WIDTH];
    kids[0] = first;
    kids[1] = first + 1;
    let mut n = 2;
    while n < WIDTH {
        let widest = (0..n)
            .filter(|&i| binary[kids[i]].count == 0)
            .max_by(|&i, &j| area(&binary[kids[i]]).total_cmp(&area(&binary[kids[j]])));
        let Some(i) = widest else { break };
        let open = binary[kids[i]].first as usize;
        kids[i] = open;
        kids[n] = open + 1;
        n += 1;
    }
    let mut inner = [(0usize, 0usize); WIDTH];
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
