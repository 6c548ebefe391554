//! `sphere_sweep { SPLINE N, <p>, r … [tolerance T] }` as written: the build
//! turns it into pieces ready to intersect (`crate::build::shapes::sweep`).

use glam::DVec3;

/// The spline a sweep follows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepSpline {
    /// `linear_spline`: straight between the points (at least 2).
    Linear,
    /// `b_spline`: a uniform cubic B-spline (at least 4 points; it passes
    /// near, not through, them).
    BSpline,
    /// `cubic_spline`: a Catmull-Rom spline through all points but the first
    /// and last (at least 4).
    Cubic,
}

impl SweepSpline {
    /// The fewest points the spline needs.
    pub fn min_points(self) -> usize {
        match self {
            SweepSpline::Linear => 2,
            _ => 4,
        }
    }
}

/// A `sphere_sweep`: the volume a sphere of varying radius fills as it moves
/// along a spline through the points.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepData {
    /// The spline the centres follow.
    pub spline: SweepSpline,
    /// The spheres `(centre, radius)` as written (at least
    /// [`SweepSpline::min_points`]).
    pub points: Vec<(DVec3, f64)>,
    /// `tolerance` (POV-Ray's, default 1e-6): how closely crossings are found,
    /// relative to the sweep's size.
    pub tolerance: f64,
}
