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
    sample(im, u, v, |x, y| im.pixel(wrap(im, x, y)), lerp)
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
    let (w, h) = (f64::from(im.width()), f64::from(im.height()));
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
    let x = x.rem_euclid(i64::from(im.width())) as usize;
    let y = y.rem_euclid(i64::from(im.height())) as usize;
    y * im.width() as usize + x
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
        match (ip.source, im.picture.index(i)) {
            (ImageUse::Index, Some(k)) => f64::from(k) / 255.0,
            (ImageUse::Alpha, _) => 1.0 - im.pixel(i).transmit,
            _ => super::patterns::grey(im.pixel(i)),
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
        match im.picture.index(i) {
            Some(k) => usize::from(k),
            None => (super::patterns::grey(im.pixel(i)) * 255.0).round() as usize,
        }
    };
    let (u, v) = (u.rem_euclid(1.0), v.rem_euclid(1.0));
    let x = (u * f64::from(im.width())).floor() as i64;
    let y = ((1.0 - v) * f64::from(im.height())).floor() as i64;
    at(x, y)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Depth, Picture, Samples, Tones, Transfer};
    use std::sync::Arc;

    fn two_by_two() -> ImageMap {
        let picture = Picture::new(
            2,
            2,
            Samples::Eight {
                channels: 3,
                data: vec![255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255],
            },
        )
        .unwrap();
        ImageMap::new(
            Arc::new(picture),
            Arc::new(Tones::new(Depth::Eight, Transfer::AsStored)),
        )
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

    /// [`ImageMap::find_see_through`] agrees with looking at every pixel.
    #[test]
    fn see_through_is_found_without_reading_every_pixel() {
        use crate::scene::IndexClear;
        let rgba = Picture::new(
            2,
            1,
            Samples::Eight {
                channels: 4,
                data: vec![9, 9, 9, 255, 9, 9, 9, 200],
            },
        )
        .unwrap();
        let mut palette = Box::new([[0, 0, 0, 255]; 256]);
        palette[1] = [5, 5, 5, 100];
        let indexed = Picture::new(
            3,
            1,
            Samples::Indexed {
                indices: vec![0, 1, 0],
                palette,
            },
        )
        .unwrap();
        let opaque = two_by_two().picture;
        let mut table = [IndexClear::default(); 256];
        table[1].transmit = Some(0.0);
        table[0].filter = Some(0.25);
        let tables = [None, Some(Arc::new(table))];
        for picture in [rgba, indexed].map(Arc::new).into_iter().chain([opaque]) {
            for filter_all in [None, Some(0.0), Some(-0.5), Some(0.5)] {
                for transmit_all in [None, Some(0.0), Some(-0.1)] {
                    for by_index in &tables {
                        let im = ImageMap {
                            filter_all,
                            transmit_all,
                            by_index: by_index.clone().filter(|_| picture.palette().is_some()),
                            ..ImageMap::new(
                                picture.clone(),
                                Arc::new(Tones::new(picture.depth(), Transfer::AsStored)),
                            )
                        };
                        let n = picture.pixels() as usize;
                        let scan = (0..n).any(|i| {
                            let c = im.pixel(i);
                            c.filter + c.transmit > 0.0
                        });
                        assert_eq!(
                            im.find_see_through(),
                            scan,
                            "{picture:?} {filter_all:?} {transmit_all:?} {:?}",
                            im.by_index.is_some()
                        );
                    }
                }
            }
        }
    }
}
