//! Normals made of other normals or shaped heights: `normal_map`, `average`,
//! the normals of a list pattern, `slope_map` and `bump_map`.

use super::{patterns, perturb, texture_map::map_lookup};
use crate::scene::{ImageUse, Normal, NormalBlend, PatternKind};
use glam::{DMat4, DVec2, DVec3};

/// How strongly the slope of a `slope_map` height tilts the normal per unit of
/// `bump_size` (fitted to POV-Ray 3.7: a lit plane with `gradient x` shaped by
/// a slope map shades alike at its steepest rises and falls).
const SLOPE_MAP_GAIN: f64 = 0.164;

/// How strongly a `bump_map` tilts the normal per unit of `bump_size` and of
/// height change from one pixel to the next.
const BUMP_MAP_GAIN: f64 = 1.0;

/// The map from world space into `normal`'s pattern space, given the one into
/// its texture's space.
fn pattern_from_world(normal: &Normal, texture_from_world: Option<&DMat4>) -> Option<DMat4> {
    match (&normal.transform, texture_from_world) {
        (Some(x), Some(m)) => Some(x.inverse * *m),
        (Some(x), None) => Some(x.inverse),
        (None, Some(m)) => Some(*m),
        (None, None) => None,
    }
}

/// `n` perturbed by a normal whose pattern blends or shapes: see [`NormalBlend`].
/// The entries of a map or list live in the blending normal's space (its
/// transforms move them too, as in POV-Ray).
pub(super) fn perturb_blend(
    normal: &Normal,
    blend: &NormalBlend,
    n: DVec3,
    p: DVec3,
    texture_from_world: Option<&DMat4>,
) -> DVec3 {
    let space = pattern_from_world(normal, texture_from_world);
    let q = space.map_or(p, |m| m.transform_point3(p));
    let entry = |e: &Normal| perturb(e, n, p, space.as_ref());
    let out = match blend {
        NormalBlend::Map(entries) if normal.kind == PatternKind::Average => {
            let mut sum = DVec3::ZERO;
            for (w, e) in entries {
                sum += *w * entry(e);
            }
            sum
        }
        NormalBlend::Map(entries) => {
            if entries.is_empty() {
                return n;
            }
            let v = patterns::value(&normal.kind, q, &normal.mods);
            let (i, j, t) = map_lookup(entries, v);
            if i == j || t <= 0.0 {
                entry(&entries[i].1)
            } else {
                entry(&entries[i].1) * (1.0 - t) + entry(&entries[j].1) * t
            }
        }
        NormalBlend::List(list) => {
            if list.is_empty() {
                return n;
            }
            let i = patterns::list_index(&normal.kind, patterns::warp(q, &normal.mods));
            entry(&list[i.min(list.len() - 1)])
        }
        NormalBlend::Slopes(map) => {
            let h = |x: DVec3| slope_height(map, patterns::value(&normal.kind, x, &normal.mods));
            tilt(n, p, space.as_ref(), h, normal.bump_size * SLOPE_MAP_GAIN)
        }
        NormalBlend::BumpMap => {
            let PatternKind::ImagePattern(ip) = &normal.kind else {
                return n;
            };
            // Heights per pixel: the slope in image units over the pixel size
            // (measured on POV-Ray 3.7: `bump_size 3` of a smooth grey ramp
            // barely tilts, a one-pixel step of 0.5 tilts by about 1.5).
            // `use_index` heights are the palette indices themselves (0 to
            // 255; measured: 255 times as steep as the same image's grey).
            let unit = if ip.source == ImageUse::Index {
                255.0
            } else {
                1.0
            };
            let per_pixel = DVec3::new(
                unit / f64::from(ip.image.width().max(1)),
                unit / f64::from(ip.image.height().max(1)),
                0.0,
            );
            let h = |x: DVec3| patterns::value(&normal.kind, x, &normal.mods);
            let step = 1e-4;
            let mut g = DVec3::ZERO;
            for (i, axis) in [DVec3::X, DVec3::Y].into_iter().enumerate() {
                g[i] = (h(q + axis * step) - h(q - axis * step)) / (2.0 * step) * per_pixel[i];
            }
            // Back to world directions (the transposed linear part of the
            // world → pattern map), keeping the pattern's units.
            let (g, scale) = match &space {
                Some(m) => (
                    m.transpose().transform_vector3(g),
                    m.transform_vector3(DVec3::ONE).length() / 3f64.sqrt(),
                ),
                None => (g, 1.0),
            };
            let g = g / scale.max(1e-12);
            n - normal.bump_size * BUMP_MAP_GAIN * (g - g.dot(n) * n)
        }
    };
    let len = out.length();
    if len > 0.0 && len.is_finite() {
        out / len
    } else {
        n
    }
}

/// `n` tilted against the slope of height `h` (a function of pattern-space
/// points) by `gain`, the slope taken in the pattern's own units by central
/// differences around world point `p`.
fn tilt(n: DVec3, p: DVec3, space: Option<&DMat4>, h: impl Fn(DVec3) -> f64, gain: f64) -> DVec3 {
    if gain == 0.0 {
        return n;
    }
    let to = |x: DVec3| space.map_or(x, |m| m.transform_point3(x));
    // The pattern's scale, so the step and the slope are in its own units.
    let scale = space
        .map(|m| m.transform_vector3(DVec3::ONE).length() / 3f64.sqrt())
        .unwrap_or(1.0)
        .max(1e-12);
    let step = 1e-4 / scale;
    let mut g = DVec3::ZERO;
    for (i, axis) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
        g[i] = (h(to(p + axis * step)) - h(to(p - axis * step))) / (2.0 * step);
    }
    let g = g / scale;
    let tangential = g - g.dot(n) * n;
    let out = n - gain * tangential;
    let len = out.length();
    if len > 0.0 && len.is_finite() {
        out / len
    } else {
        n
    }
}

/// The height a `slope_map` gives pattern value `v`: between two entries a
/// cubic (Hermite) curve through their heights with their slopes (the slope of
/// the height per unit of pattern value); before the first entry its height,
/// past the last the last's.
pub fn slope_height(map: &[(f64, DVec2)], v: f64) -> f64 {
    let Some(first) = map.first() else {
        return 0.0;
    };
    let (i, j, t) = map_lookup(map, v);
    if i == j {
        return if v <= first.0 { first.1.x } else { map[i].1.x };
    }
    let (v0, a) = map[i];
    let (v1, b) = map[j];
    let w = v1 - v0;
    let (t2, t3) = (t * t, t * t * t);
    let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
    let h10 = t3 - 2.0 * t2 + t;
    let h01 = -2.0 * t3 + 3.0 * t2;
    let h11 = t3 - t2;
    h00 * a.x + h10 * w * a.y + h01 * b.x + h11 * w * b.y
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slope_map_passes_its_points_with_its_slopes() {
        let map = vec![(0.0, DVec2::new(0.0, 1.0)), (0.5, DVec2::new(1.0, 0.0))];
        assert!(slope_height(&map, 0.0).abs() < 1e-12);
        assert!((slope_height(&map, 0.5) - 1.0).abs() < 1e-12);
        assert!((slope_height(&map, 0.9) - 1.0).abs() < 1e-12);
        let d = (slope_height(&map, 1e-6) - slope_height(&map, 0.0)) / 1e-6;
        assert!((d - 1.0).abs() < 1e-3, "{d}");
        let d = (slope_height(&map, 0.5) - slope_height(&map, 0.5 - 1e-6)) / 1e-6;
        assert!(d.abs() < 1e-3, "{d}");
    }
}
