//! Which interiors a ray is inside, for the indices of refraction on either
//! side of the surfaces it meets. POV-Ray 3.7's rule (measured: a sphere of
//! `ior 1.5` inside a box of `ior 1.5` is invisible; a liquid in a glass bends
//! light by the ratio of the two; of two overlapping slabs, the one entered
//! last sets the index until it is left): entering an object goes from the
//! ior the ray is in (its innermost interior's) to the object's; leaving it,
//! from the ior the ray is in to that of the innermost object still around it
//! (1 outside everything). A ray that leaves an object it was not seen to
//! enter goes from the object's index to the one it travels in.

use crate::build::{SurfaceHit, World};

/// Interiors kept: deeper nesting is treated as not entered (its surfaces
/// bend as against the last one kept).
const DEPTH: usize = 8;

/// The interiors a ray is in, innermost last: a small copyable stack, saved
/// and restored round each refracted ray.
#[derive(Clone, Copy, Debug, Default)]
pub struct IorStack {
    keys: [usize; DEPTH],
    iors: [f64; DEPTH],
    len: usize,
}

/// What identifies the inside of the surface at `s`: its interior when it
/// has one (the parts of a CSG object or mesh share it), else its primitive.
pub fn key(s: &SurfaceHit) -> usize {
    match s.interior {
        Some(i) => std::sync::Arc::as_ptr(i) as usize,
        None => usize::MAX - s.prim as usize,
    }
}

impl IorStack {
    /// The interiors around the camera of `world`.
    pub fn at_camera(world: &World) -> IorStack {
        let mut stack = IorStack::default();
        for &i in &world.camera_inside {
            let prim = &world.primitives[i as usize];
            let key = match &prim.interior {
                Some(int) => std::sync::Arc::as_ptr(int) as usize,
                None => usize::MAX - i as usize,
            };
            stack.enter(key, prim.interior.as_ref().map_or(1.0, |int| int.ior));
        }
        stack
    }

    /// The ior the ray travels in.
    pub fn current(&self) -> f64 {
        if self.len == 0 {
            1.0
        } else {
            self.iors[self.len - 1]
        }
    }

    /// The ior the ray travels in once it has left the interior `key`.
    pub fn outside(&self, key: usize) -> f64 {
        let mut it = self.keys[..self.len].iter().rposition(|&k| k == key);
        (0..self.len)
            .rev()
            .find(|&i| {
                if Some(i) == it {
                    it = None;
                    false
                } else {
                    true
                }
            })
            .map_or(1.0, |i| self.iors[i])
    }

    /// Whether the ray is in interior `key`, by what it was seen to enter.
    pub fn holds(&self, key: usize) -> bool {
        self.keys[..self.len].contains(&key)
    }

    /// Whether a ray meeting the surface at `s` along `dir` enters its object:
    /// when the ray is not already in it, for surfaces whose normal's side is
    /// only their winding (see `PrimShape::sided_by_winding`), else when it
    /// meets the outside of the geometric normal.
    pub fn entering(&self, world: &World, s: &SurfaceHit, dir: glam::DVec3) -> bool {
        let by_winding = world
            .primitives
            .get(s.prim as usize)
            .is_some_and(|p| p.shape.sided_by_winding());
        if by_winding && self.len < DEPTH {
            !self.holds(key(s))
        } else {
            dir.dot(s.geo_normal) < 0.0
        }
    }

    /// The ray enters interior `key` of index `ior`.
    pub fn enter(&mut self, key: usize, ior: f64) {
        if self.len < DEPTH {
            self.keys[self.len] = key;
            self.iors[self.len] = ior;
            self.len += 1;
        }
    }

    /// The ray leaves interior `key` (nothing happens when it was not in it).
    pub fn leave(&mut self, key: usize) {
        if let Some(i) = self.keys[..self.len].iter().rposition(|&k| k == key) {
            self.keys.copy_within(i + 1..self.len, i);
            self.iors.copy_within(i + 1..self.len, i);
            self.len -= 1;
        }
    }

    /// The indices of refraction on the near and far side of a surface with
    /// interior `key` of index `ior`, met `entering` it (see the module).
    pub fn sides(&self, key: usize, ior: f64, entering: bool) -> (f64, f64) {
        if entering {
            (self.current(), ior)
        } else if self.holds(key) {
            (self.current(), self.outside(key))
        } else {
            // Leaving what it was not seen to enter (it started inside, or
            // rounding hid the way in): out of the object into the ray's medium.
            (ior, self.current())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nested_interiors_give_the_ratio_of_their_indices() {
        let mut s = IorStack::default();
        assert_eq!(s.sides(1, 1.5, true), (1.0, 1.5));
        s.enter(1, 1.5);
        // Into a liquid inside the glass.
        assert_eq!(s.sides(2, 1.2, true), (1.5, 1.2));
        s.enter(2, 1.2);
        // Out of the glass's inner wall while in the liquid: the liquid's
        // index on both sides, no bend.
        assert_eq!(s.sides(1, 1.5, false), (1.2, 1.2));
        s.leave(1);
        assert_eq!(s.current(), 1.2);
        assert_eq!(s.sides(2, 1.2, false), (1.2, 1.0));
        s.leave(2);
        assert_eq!((s.len, s.current()), (0, 1.0));
        // Leaving what it was not seen to enter: out into the air.
        assert_eq!(s.sides(3, 1.3, false), (1.3, 1.0));
    }
}
