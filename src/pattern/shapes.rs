//! The geometric patterns `planar`, `spherical`, `cylindrical`, `boxed`,
//! `quilted`, `spiral1`, `spiral2` and the fractals: their raw values, checked
//! pixel by pixel against POV-Ray 3.7 renders of grey-mapped planes.

use super::fractals;
use super::patterns;
use crate::scene::{PatternKind, Wave};
use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, TAU};

/// Whether `kind` is one of this module's patterns.
pub fn is_shape(kind: &PatternKind) -> bool {
    matches!(
        kind,
        PatternKind::Planar
            | PatternKind::Spherical
            | PatternKind::Cylindrical
            | PatternKind::Boxed
            | PatternKind::Quilted { .. }
            | PatternKind::Spiral1(_)
            | PatternKind::Spiral2(_)
            | PatternKind::Fractal(_)
    )
}

/// The wave form for these patterns: as [`patterns::wave`], except that the ramp
/// keeps a value of exactly 1 (POV-Ray wraps by 1.00001, so `planar` is 1 on its
/// plane and a fractal's interior value 1 stays white).
pub fn wave(w: Wave, v: f64) -> f64 {
    if w == Wave::Ramp {
        const M: f64 = 1.00001;
        let r = v % M;
        return if r < 0.0 { r + M } else { r };
    }
    patterns::wave(w, v)
}

/// The angle of `(x, y)` around the z axis, from -y through +x (POV-Ray's
/// spiral angle), in [0, 2π).
fn spiral_angle(x: f64, y: f64) -> f64 {
    let rad = (x * x + y * y).sqrt();
    if rad == 0.0 {
        return 0.0;
    }
    let s = (y / rad).clamp(-1.0, 1.0).asin();
    if x < 0.0 {
        3.0 * FRAC_PI_2 - s
    } else {
        FRAC_PI_2 + s
    }
}

/// The vector of a `quilted` cushion at `p`: from the cell's centre, scaled by
/// the control cubic. POV-Ray's quilted normal leans the surface normal by it.
pub fn quilt_vector(kind: &PatternKind, p: DVec3) -> DVec3 {
    let PatternKind::Quilted { control0, control1 } = kind else {
        return DVec3::ZERO;
    };
    let v = p - p.floor() - DVec3::splat(0.5);
    let t = v.length();
    let it = 1.0 - t;
    v * (t * t * t + 3.0 * t * it * (control0 * it + control1 * t))
}

/// The raw value of one of this module's patterns at `p`.
pub fn raw(kind: &PatternKind, p: DVec3) -> f64 {
    match kind {
        PatternKind::Planar => 1.0 - p.y.abs().min(1.0),
        PatternKind::Spherical => 1.0 - p.length().min(1.0),
        PatternKind::Cylindrical => 1.0 - (p.x * p.x + p.z * p.z).sqrt().min(1.0),
        PatternKind::Boxed => 1.0 - p.abs().max_element().min(1.0),
        PatternKind::Quilted { .. } => {
            let w = quilt_vector(kind, p);
            // Normalised so a cushion's corner reaches 1 (measured: 2/√3 times
            // the mean of the components).
            (w.x.abs() + w.y.abs() + w.z.abs()) / 3.0 * 2.0 / 3f64.sqrt()
        }
        PatternKind::Spiral1(arms) => {
            let rad = (p.x * p.x + p.y * p.y).sqrt();
            p.z + rad + arms * spiral_angle(p.x, p.y) / TAU
        }
        PatternKind::Spiral2(arms) => {
            // Measured on POV-Ray 3.7 (the raw value at 1100 points, read through
            // `ramp_wave` with frequency 1 and 0.25, agrees to 4e-5): spiral1's
            // value and the rings of the radius, each as a triangle wave, added.
            let rad = (p.x * p.x + p.y * p.y).sqrt();
            let a = arms * spiral_angle(p.x, p.y) / TAU;
            let tri = |v: f64| patterns::wave(Wave::Triangle, v);
            tri(p.z + rad + a) + tri(rad)
        }
        PatternKind::Fractal(f) => fractals::value(f, p),
        _ => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn planar_spherical_cylindrical_boxed_values() {
        let p = DVec3::new(0.3, 0.4, 0.0);
        assert!((raw(&PatternKind::Planar, p) - 0.6).abs() < 1e-12);
        assert!((raw(&PatternKind::Spherical, p) - 0.5).abs() < 1e-12);
        assert!((raw(&PatternKind::Cylindrical, p) - 0.7).abs() < 1e-12);
        assert!((raw(&PatternKind::Boxed, p) - 0.6).abs() < 1e-12);
        assert_eq!(raw(&PatternKind::Planar, DVec3::new(0.0, 3.0, 0.0)), 0.0);
        // On the plane the value is 1, and the ramp keeps it.
        assert_eq!(wave(Wave::Ramp, raw(&PatternKind::Planar, DVec3::X)), 1.0);
    }
}
