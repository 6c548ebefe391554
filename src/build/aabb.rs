//! Axis-aligned bounding boxes.

use super::Ray;
use glam::DVec3;

/// An axis-aligned box; the empty box has `min > max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Lowest corner.
    pub min: DVec3,
    /// Highest corner.
    pub max: DVec3,
}

impl Default for Aabb {
    fn default() -> Self {
        Aabb::EMPTY
    }
}

impl Aabb {
    /// The box containing nothing.
    pub const EMPTY: Aabb = Aabb {
        min: DVec3::splat(f64::INFINITY),
        max: DVec3::splat(f64::NEG_INFINITY),
    };

    /// The smallest box holding all `points`.
    pub fn from_points(points: impl IntoIterator<Item = DVec3>) -> Aabb {
        points
            .into_iter()
            .fold(Aabb::EMPTY, |b, p| Aabb::new(b.min.min(p), b.max.max(p)))
    }

    /// A box from its corners.
    pub fn new(min: DVec3, max: DVec3) -> Aabb {
        Aabb { min, max }
    }

    /// True when the box holds no point.
    pub fn is_empty(&self) -> bool {
        self.min.cmpgt(self.max).any()
    }

    /// The smallest box holding both.
    pub fn union(&self, other: &Aabb) -> Aabb {
        Aabb::new(self.min.min(other.min), self.max.max(other.max))
    }

    /// The smallest box holding `self` and `p`.
    pub fn grow(&self, p: DVec3) -> Aabb {
        Aabb::new(self.min.min(p), self.max.max(p))
    }

    /// Centre point.
    pub fn centroid(&self) -> DVec3 {
        (self.min + self.max) * 0.5
    }

    /// The eight corners.
    pub fn corners(&self) -> [DVec3; 8] {
        let (a, b) = (self.min, self.max);
        [
            DVec3::new(a.x, a.y, a.z),
            DVec3::new(b.x, a.y, a.z),
            DVec3::new(a.x, b.y, a.z),
            DVec3::new(b.x, b.y, a.z),
            DVec3::new(a.x, a.y, b.z),
            DVec3::new(b.x, a.y, b.z),
            DVec3::new(a.x, b.y, b.z),
            DVec3::new(b.x, b.y, b.z),
        ]
    }

    /// Half the surface area (all the SAH needs); 0 for the empty box.
    pub fn half_area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let d = self.max - self.min;
        d.x * d.y + d.y * d.z + d.z * d.x
    }

    /// Entry distance of `ray` into the box when it enters within `(t_min, t_max)`.
    /// `inv_dir` is `1 / ray.dir` per component.
    #[inline]
    pub fn hit(&self, ray: &Ray, inv_dir: DVec3, t_min: f64, t_max: f64) -> Option<f64> {
        let t0 = (self.min - ray.origin) * inv_dir;
        let t1 = (self.max - ray.origin) * inv_dir;
        // `min`/`max` of glam return the non-NaN operand, so 0 * inf (a ray lying in a
        // slab plane) does not poison the interval.
        let near = t0.min(t1).max_element().max(t_min);
        let far = t0.max(t1).min_element().min(t_max);
        (near <= far).then_some(near)
    }
}
