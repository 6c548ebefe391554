//! The `slope` pattern: its value depends on the surface normal at the point
//! being shaded, which the renderer sets with [`set_surface_normal`] before it
//! evaluates the textures of a hit (a per-thread value, so pattern functions
//! keep their point-only signature; rendering stays deterministic since each
//! hit sets it before use).

use crate::scene::SlopeSpec;
use glam::DVec3;
use std::cell::Cell;

thread_local! {
    /// The unit surface normal of the hit being shaded on this thread.
    static NORMAL: Cell<DVec3> = const { Cell::new(DVec3::Y) };
}

/// Sets the surface normal the `slope` pattern sees (unit, pattern-independent
/// world space) for the hit about to be shaded on this thread.
pub fn set_surface_normal(n: DVec3) {
    NORMAL.with(|c| c.set(n));
}

/// [`set_surface_normal`] with `n` turned to face against `dir`, the ray that
/// found the hit: POV-Ray's `slope` sees the side of the surface the ray
/// meets (measured on POV-Ray 3.7: a triangle, a `disc` facing down and a
/// sphere seen from inside all show `slope y` at 1 where the ray comes down
/// onto them).
pub fn set_surface_normal_facing(n: DVec3, dir: DVec3) {
    set_surface_normal(if n.dot(dir) > 0.0 { -n } else { n });
}

/// The surface normal set by [`set_surface_normal`].
pub fn surface_normal() -> DVec3 {
    NORMAL.with(Cell::get)
}

/// The value of `slope` at pattern-space point `p` for the current surface
/// normal: `1 - θ / π` for θ the angle between the normal and the direction
/// (0 facing away, 0.5 across, 1 facing it; linear in the angle, as measured
/// on POV-Ray 3.7, and in world space: the pattern's transforms do not turn
/// it), rescaled from
/// `[lo, hi]` to [0, 1]; with `altitude`, the point's height along the altitude
/// direction rescaled alike, the two weighed by the lengths of their
/// directions.
pub fn value(s: &SlopeSpec, p: DVec3) -> f64 {
    let n = surface_normal();
    let rescale = |v: f64, (lo, hi): (f64, f64)| {
        if hi != lo {
            (v - lo) / (hi - lo)
        } else {
            v
        }
    };
    let len = s.direction.length();
    let dir = if len > 0.0 {
        s.direction / len
    } else {
        DVec3::Y
    };
    let slope = rescale(
        0.5 + n.dot(dir).clamp(-1.0, 1.0).asin() / std::f64::consts::PI,
        s.slope_range,
    );
    let v = match s.altitude {
        None => slope,
        Some(a) => {
            let alen = a.length();
            let adir = if alen > 0.0 { a / alen } else { DVec3::Y };
            let alt = rescale(p.dot(adir), s.altitude_range);
            let total = len + alen;
            if total > 0.0 {
                (len * slope + alen * alt) / total
            } else {
                slope
            }
        }
    };
    // Past [0, 1] the value wraps, as POV-Ray 3.7 shows (a value of 1.08
    // shows as 0.08), while 1 itself stays 1.
    if v > 1.0 {
        v % 1.00001
    } else if v < 0.0 {
        v.rem_euclid(1.0)
    } else {
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(d: DVec3) -> SlopeSpec {
        SlopeSpec {
            direction: d,
            slope_range: (0.0, 1.0),
            altitude: None,
            altitude_range: (0.0, 1.0),
        }
    }

    #[test]
    fn facing_across_and_away() {
        set_surface_normal(DVec3::Y);
        assert!((value(&spec(DVec3::Y), DVec3::ZERO) - 1.0).abs() < 1e-12);
        set_surface_normal(DVec3::X);
        assert!((value(&spec(DVec3::Y), DVec3::ZERO) - 0.5).abs() < 1e-12);
        set_surface_normal(-DVec3::Y);
        assert!(value(&spec(DVec3::Y), DVec3::ZERO).abs() < 1e-12);
    }
}
