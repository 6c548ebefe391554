//! `isosurface { function { … } contained_by { … } … }`: the surface where a
//! function equals its threshold inside a container, as written.

use super::Function;
use glam::DVec3;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// The region an isosurface is searched in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Container {
    /// `contained_by { box { MIN, MAX } }` (corners sorted).
    Box {
        /// Lowest corner.
        min: DVec3,
        /// Highest corner.
        max: DVec3,
    },
    /// `contained_by { sphere { CENTER, RADIUS } }`.
    Sphere {
        /// Centre.
        center: DVec3,
        /// Radius.
        radius: f64,
    },
}

/// `isosurface { … }` as written (intersected by
/// `crate::build::shapes::isosurface`).
#[derive(Clone, Debug, PartialEq)]
pub struct Isosurface {
    /// The function of x, y, z.
    pub function: Arc<Function>,
    /// Where the surface is searched.
    pub container: Container,
    /// The surface is where the function equals this (default 0).
    pub threshold: f64,
    /// How closely roots are found (default 0.001).
    pub accuracy: f64,
    /// The bound on the function's slope used to step (default 1.1).
    pub max_gradient: f64,
    /// `open`: the container's surface never shows.
    pub open: bool,
    /// `max_trace N`: how many crossings a ray reports (default 1, as in POV-Ray;
    /// 0 for `all_intersections`). In CSG fewer crossings than the surface has
    /// leave the same see-through gaps POV-Ray shows.
    pub max_trace: u32,
    /// The steepest slope the renderer met between the points it evaluated,
    /// for POV-Ray's warning after a render (shared by the copies of one
    /// isosurface).
    pub steepest: SlopeMeter,
}

/// The largest function slope seen along rays through one isosurface, kept by
/// every thread that renders it. A measurement, not part of what was
/// written: any two meters compare equal.
#[derive(Clone, Debug, Default)]
pub struct SlopeMeter(Arc<AtomicU64>);

impl SlopeMeter {
    /// Notes a slope (positive and finite; others are ignored). Cheap when it is
    /// not a new maximum: one relaxed load.
    pub fn observe(&self, slope: f64) {
        if !(slope.is_finite() && slope > 0.0) {
            return;
        }
        // Positive floats order as their bit patterns do.
        let bits = slope.to_bits();
        if bits > self.0.load(Ordering::Relaxed) {
            self.0.fetch_max(bits, Ordering::Relaxed);
        }
    }

    /// The steepest slope noted so far (0 when none).
    pub fn steepest(&self) -> f64 {
        f64::from_bits(self.0.load(Ordering::Relaxed))
    }
}

impl PartialEq for SlopeMeter {
    fn eq(&self, _: &SlopeMeter) -> bool {
        true
    }
}
