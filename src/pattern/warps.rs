//! `warp { … }`: the point moves through each warp of a pattern, last written
//! first, before the pattern is evaluated. The formulas were fitted to POV-Ray
//! 3.7 renders of `function` patterns that show each output coordinate.

use super::noise::turbulence_vec;
use crate::scene::{MappingWarp, Warp, WarpStep};
use glam::DVec3;
use std::f64::consts::TAU;

/// The point `p` (in pattern space) after `steps`, applied from the last one
/// written to the first, each in the space its own transforms give it.
pub fn apply(steps: &[WarpStep], mut p: DVec3) -> DVec3 {
    for step in steps.iter().rev() {
        match &step.before {
            Some((m, inv)) => {
                let q = warp(&step.warp, m.transform_point3(p));
                p = inv.transform_point3(q);
            }
            None => p = warp(&step.warp, p),
        }
    }
    p
}

/// One warp of point `p`.
pub fn warp(w: &Warp, p: DVec3) -> DVec3 {
    match w {
        Warp::Turbulence {
            amount,
            octaves,
            omega,
            lambda,
        } => p + *amount * turbulence_vec(p, *octaves, *omega, *lambda),
        Warp::Repeat {
            axis,
            width,
            offset,
            flip,
        } => {
            let block = (p[*axis] / width).floor();
            let mut q = p;
            q[*axis] -= block * width;
            if block.rem_euclid(2.0) == 1.0 {
                for i in 0..3 {
                    if flip[i] != 0.0 {
                        q[i] = if i == *axis { width - q[i] } else { -q[i] };
                    }
                }
            }
            q + *offset * block
        }
        Warp::BlackHole {
            centre,
            radius,
            strength,
            falloff,
            inverse,
            repeat,
            turbulence,
        } => {
            let mut c = *centre;
            if *repeat != DVec3::ZERO {
                let mut cell = DVec3::ZERO;
                for i in 0..3 {
                    if repeat[i] != 0.0 {
                        cell[i] = ((p[i] - centre[i]) / repeat[i]).round();
                        c[i] += cell[i] * repeat[i];
                    }
                }
                if *turbulence != DVec3::ZERO {
                    c += *turbulence * (cell_jitter(cell) * 2.0 - DVec3::ONE);
                }
            }
            let d = p - c;
            let len = d.length();
            if len >= *radius || *radius <= 0.0 {
                return p;
            }
            let k = (strength * (1.0 - len / radius).powf(*falloff)).min(1.0);
            c + d * if *inverse { 1.0 - k } else { 1.0 + k }
        }
        Warp::Mapping {
            kind,
            orientation,
            dist_exp,
            major_radius,
        } => {
            let q = mapping(*kind, p, *dist_exp, *major_radius);
            orient(q, *orientation)
        }
    }
}

/// The angle of `(x, z)` around the y axis as a fraction of a turn, from +x
/// towards +z, in [0, 1).
fn turn(x: f64, z: f64) -> f64 {
    if x == 0.0 && z == 0.0 {
        return 0.0;
    }
    (z.atan2(x) / TAU).rem_euclid(1.0)
}

fn mapping(kind: MappingWarp, p: DVec3, dist_exp: f64, major: f64) -> DVec3 {
    let scale = |len: f64| {
        if dist_exp == 0.0 {
            1.0
        } else {
            len.powf(dist_exp)
        }
    };
    match kind {
        MappingWarp::Planar => DVec3::new(p.x, p.y, 0.0),
        MappingWarp::Cylindrical => {
            let len = (p.x * p.x + p.z * p.z).sqrt();
            DVec3::new(turn(p.x, p.z) * scale(len), p.y, len)
        }
        MappingWarp::Spherical => {
            let len = p.length();
            let flat = (p.x * p.x + p.z * p.z).sqrt();
            let lat = p.y.atan2(flat) / std::f64::consts::PI + 0.5;
            let s = scale(len);
            DVec3::new(turn(p.x, p.z) * s, lat * s, len)
        }
        MappingWarp::Toroidal => {
            let flat = (p.x * p.x + p.z * p.z).sqrt() - major;
            let len = (flat * flat + p.y * p.y).sqrt();
            let tube = ((p.y.atan2(flat) + std::f64::consts::PI) / TAU).rem_euclid(1.0);
            let s = scale(len);
            DVec3::new(turn(p.x, p.z) * s, tube * s, len)
        }
    }
}

/// Rotates a mapped point so the mapping's z axis lies along `orientation`'s
/// rotation onto +z (the default `<0, 0, 1>` leaves it).
fn orient(q: DVec3, orientation: DVec3) -> DVec3 {
    let o = orientation.normalize_or_zero();
    if o == DVec3::ZERO || (o - DVec3::Z).length() < 1e-12 {
        return q;
    }
    glam::DQuat::from_rotation_arc(o, DVec3::Z) * q
}

/// A fixed pseudo-random offset in [0, 1)³ for black hole cell `cell`.
fn cell_jitter(cell: DVec3) -> DVec3 {
    let mut h = (cell.x as i64 as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ (cell.y as i64 as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ (cell.z as i64 as u64).wrapping_mul(0x1656_67B1_9E37_79F9)
        ^ 0x5851_F42D_4C95_7F2D;
    let mut next = || {
        h = h.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = h;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    };
    DVec3::new(next(), next(), next())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn repeat(axis: usize, width: f64, offset: DVec3, flip: DVec3) -> Warp {
        Warp::Repeat {
            axis,
            width,
            offset,
            flip,
        }
    }

    #[test]
    fn repeat_folds_into_the_first_slab() {
        let w = repeat(0, 0.7, DVec3::ZERO, DVec3::ZERO);
        let q = warp(&w, DVec3::new(1.5, 2.0, 3.0));
        assert!((q.x - 0.1).abs() < 1e-12 && q.y == 2.0 && q.z == 3.0);
        // Flipped odd slabs mirror along the axis; offset shifts per slab.
        let w = repeat(0, 0.7, DVec3::new(0.2, 0.3, 0.0), DVec3::new(1.0, 1.0, 0.0));
        let q = warp(&w, DVec3::new(0.81, 0.5, 0.0));
        assert!((q.x - (0.7 - 0.11 + 0.2)).abs() < 1e-12);
        assert!((q.y - (-0.5 + 0.3)).abs() < 1e-12);
    }

    #[test]
    fn black_hole_pulls_within_its_radius_only() {
        let w = Warp::BlackHole {
            centre: DVec3::ZERO,
            radius: 1.5,
            strength: 1.0,
            falloff: 2.0,
            inverse: false,
            repeat: DVec3::ZERO,
            turbulence: DVec3::ZERO,
        };
        let p = DVec3::new(0.75, 0.0, 0.0);
        assert!((warp(&w, p).x - 0.75 * 1.25).abs() < 1e-12);
        let far = DVec3::new(2.0, 0.0, 0.0);
        assert_eq!(warp(&w, far), far);
    }

    #[test]
    fn cylindrical_maps_angle_height_distance() {
        let w = Warp::Mapping {
            kind: MappingWarp::Cylindrical,
            orientation: DVec3::Z,
            dist_exp: 0.0,
            major_radius: 1.0,
        };
        let q = warp(&w, DVec3::new(-2.0, 0.5, 0.0));
        assert!((q - DVec3::new(0.5, 0.5, 2.0)).length() < 1e-12);
    }
}
