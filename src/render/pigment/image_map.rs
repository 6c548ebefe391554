//! `image_map` lookups: planar, spherical and cylindrical projections, or the
//! surface's uv coordinates.

use crate::scene::{Colour, ImageMap, ImagePattern, ImageUse};
use glam::{DVec2, DVec3};
use std::f64::consts::{PI, TAU};

/// The colour of image map `im` at pattern-space point `p` (surface coordinates
/// `uv` when the map uses `uv_mapping`).
pub fn lookup(im: &ImageMap, p: DVec3, uv: Option<DVec2>) -> Colour {
    let p = match &im.mods {
        Some(m) => super::patterns::warp(p, m),
        None => p,
    };
    let (u, v) = image_uv(im, p, uv);
    if im.once && !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
        return Colour {
            rgb: DVec3::ZERO,
            filter: 0.0,
            transmit: 1.0,
        };
    }
    let lerp = |a: Colour, b: Colour, t: f64| Colour {
        rgb: a.rgb + (b.rgb - a.rgb) * t,
        filter: a.filter + (b.filter - a.filter) * t,
        transmit: a.transmit + (b.transmit - a.transmit) * t,
    };
    sample(im, u, v, |x, y| pixel(im, x, y), lerp)
}

/// The image coordinates (u, v) of pattern-space point `p`: by the map's
/// projection, or the surface's `uv` with `uv_mapping`.
fn image_uv(im: &ImageMap, p: DVec3, uv: Option<DVec2>) -> (f64, f64) {
    if im.uv_mapping {
        return match uv {
            Some(uv) => (uv.x, uv.y),
            None => (p.x, p.y),
        };
    }
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
}

/// The image sampled at (u, v) (tiled): the nearest pixel, or with
/// `interpolate 2` the bilinear blend of the four nearest (`at` gives a pixel's
/// value, `lerp` blends two).
fn sample<T: Copy>(
    im: &ImageMap,
    u: f64,
    v: f64,
    at: impl Fn(i64, i64) -> T,
    lerp: impl Fn(T, T, f64) -> T,
) -> T {
    let (u, v) = (u.rem_euclid(1.0), v.rem_euclid(1.0));
    let (w, h) = (im.width as f64, im.height as f64);
    let x = u * w;
    let y = (1.0 - v) * h;
    if !im.interpolate {
        return at(x.floor() as i64, y.floor() as i64);
    }
    let (fx, fy) = (x - 0.5, y - 0.5);
    let (x0, y0) = (fx.floor(), fy.floor());
    let (tx, ty) = (fx - x0, fy - y0);
    let (x0, y0) = (x0 as i64, y0 as i64);
    let c00 = at(x0, y0);
    let c10 = at(x0 + 1, y0);
    let c01 = at(x0, y0 + 1);
    let c11 = at(x0 + 1, y0 + 1);
    lerp(lerp(c00, c10, tx), lerp(c01, c11, tx), ty)
}

/// Index of pixel (x, y) in the pixel array, wrapping around the edges.
fn wrap(im: &ImageMap, x: i64, y: i64) -> usize {
    let x = x.rem_euclid(im.width as i64) as usize;
    let y = y.rem_euclid(im.height as i64) as usize;
    y * im.width as usize + x
}

/// The value in [0, 1] an `image_pattern` (or `bump_map`) reads at
/// pattern-space point `p`: the pixel's grey value, palette index / 255 or
/// opacity (0 outside the image with `once`).
pub fn value_at(ip: &ImagePattern, p: DVec3) -> f64 {
    let im = &*ip.image;
    let (u, v) = image_uv(im, p, None);
    if im.once && !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
        return 0.0;
    }
    let at = |x: i64, y: i64| -> f64 {
        let i = wrap(im, x, y);
        match (ip.source, &ip.indices) {
            (ImageUse::Index, Some(idx)) => f64::from(idx[i]) / 255.0,
            (ImageUse::Alpha, _) => 1.0 - im.pixels[i].transmit,
            _ => super::patterns::grey(im.pixels[i]),
        }
    };
    sample(im, u, v, at, |a, b, t| a + (b - a) * t)
}

/// The entry a `material_map` chooses at pattern-space point `p`: the nearest
/// pixel's palette index (for images without a palette, its grey value × 255).
/// Outside the image with `once`, the first entry.
pub fn index_at(ip: &ImagePattern, p: DVec3) -> usize {
    let im = &*ip.image;
    let (u, v) = image_uv(im, p, None);
    if im.once && !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
        return 0;
    }
    let at = |x: i64, y: i64| -> usize {
        let i = wrap(im, x, y);
        match &ip.indices {
            Some(idx) => usize::from(idx[i]),
            None => (super::patterns::grey(im.pixels[i]) * 255.0).round() as usize,
        }
    };
    let (u, v) = (u.rem_euclid(1.0), v.rem_euclid(1.0));
    let x = (u * im.width as f64).floor() as i64;
    let y = ((1.0 - v) * im.height as f64).floor() as i64;
    at(x, y)
}

/// Pixel (x, y), wrapping around the edges.
fn pixel(im: &ImageMap, x: i64, y: i64) -> Colour {
    im.pixels[wrap(im, x, y)]
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
