//! `image_map` lookups: planar, spherical and cylindrical projections, or the
//! surface's uv coordinates.

use crate::scene::{Colour, ImageMap};
use glam::{DVec2, DVec3};
use std::f64::consts::{PI, TAU};

/// The colour of image map `im` at pattern-space point `p` (surface coordinates
/// `uv` when the map uses `uv_mapping`).
pub fn lookup(im: &ImageMap, p: DVec3, uv: Option<DVec2>) -> Colour {
    let p = match &im.mods {
        Some(m) => super::patterns::warp(p, m),
        None => p,
    };
    let (u, v) = if im.uv_mapping {
        match uv {
            Some(uv) => (uv.x, uv.y),
            None => (p.x, p.y),
        }
    } else {
        match im.map_type {
            1 => {
                let len = p.length();
                if len == 0.0 {
                    (0.0, 0.5)
                } else {
                    // Longitude from +x, growing towards +z (measured on POV-Ray 3.7).
                    let u = (p.z.atan2(p.x) / TAU).rem_euclid(1.0);
                    (u, 0.5 + (p.y / len).clamp(-1.0, 1.0).asin() / PI)
                }
            }
            2 => ((p.z.atan2(p.x) / TAU).rem_euclid(1.0), p.y),
            _ => (p.x, p.y),
        }
    };
    if im.once && !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
        return Colour {
            rgb: DVec3::ZERO,
            filter: 0.0,
            transmit: 1.0,
        };
    }
    let (u, v) = (u.rem_euclid(1.0), v.rem_euclid(1.0));
    let (w, h) = (im.width as f64, im.height as f64);
    let x = u * w;
    let y = (1.0 - v) * h;
    if !im.interpolate {
        return pixel(im, x.floor() as i64, y.floor() as i64);
    }
    let (fx, fy) = (x - 0.5, y - 0.5);
    let (x0, y0) = (fx.floor(), fy.floor());
    let (tx, ty) = (fx - x0, fy - y0);
    let (x0, y0) = (x0 as i64, y0 as i64);
    let c00 = pixel(im, x0, y0);
    let c10 = pixel(im, x0 + 1, y0);
    let c01 = pixel(im, x0, y0 + 1);
    let c11 = pixel(im, x0 + 1, y0 + 1);
    let lerp = |a: Colour, b: Colour, t: f64| Colour {
        rgb: a.rgb + (b.rgb - a.rgb) * t,
        filter: a.filter + (b.filter - a.filter) * t,
        transmit: a.transmit + (b.transmit - a.transmit) * t,
    };
    lerp(lerp(c00, c10, tx), lerp(c01, c11, tx), ty)
}

/// Pixel (x, y), wrapping around the edges.
fn pixel(im: &ImageMap, x: i64, y: i64) -> Colour {
    let x = x.rem_euclid(im.width as i64) as usize;
    let y = y.rem_euclid(im.height as i64) as usize;
    im.pixels[y * im.width as usize + x]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_by_two() -> ImageMap {
        ImageMap {
            width: 2,
            height: 2,
            pixels: vec![
                Colour::rgb(1.0, 0.0, 0.0),
                Colour::rgb(0.0, 1.0, 0.0),
                Colour::rgb(0.0, 0.0, 1.0),
                Colour::rgb(1.0, 1.0, 1.0),
            ],
            map_type: 0,
            interpolate: false,
            once: false,
            uv_mapping: false,
            see_through: false,
            mods: None,
        }
    }

    #[test]
    fn planar_top_row_is_high_y() {
        let im = two_by_two();
        assert_eq!(lookup(&im, DVec3::new(0.25, 0.75, 0.0), None).rgb, DVec3::X);
        assert_eq!(lookup(&im, DVec3::new(0.25, 0.25, 0.0), None).rgb, DVec3::Z);
        assert_eq!(
            lookup(&im, DVec3::new(1.75, 2.25, 0.0), None).rgb,
            DVec3::ONE
        );
    }

    #[test]
    fn once_is_clear_outside() {
        let im = ImageMap {
            once: true,
            see_through: true,
            ..two_by_two()
        };
        assert_eq!(lookup(&im, DVec3::new(1.5, 0.5, 0.0), None).transmit, 1.0);
    }

    #[test]
    fn uv_mapping_uses_uv() {
        let im = ImageMap {
            uv_mapping: true,
            ..two_by_two()
        };
        let c = lookup(&im, DVec3::new(9.0, 9.0, 9.0), Some(DVec2::new(0.75, 0.75)));
        assert_eq!(c.rgb, DVec3::Y);
    }
}
