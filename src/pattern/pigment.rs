//! Pigment and normal evaluation: patterns, colour and pigment maps, image maps,
//! bump perturbation, and the textures a patterned texture chooses.

use super::normal_blend::perturb_blend;
use super::{image_map, patterns};

use crate::scene::{Colour, Mapped, Normal, Pattern, PatternKind, PatternMap, Pigment};
use glam::{DMat4, DVec2, DVec3};

/// Added to each coordinate before flooring in `checker`. POV-Ray 3.7 shows the
/// same bias: a point 3e-10 below an integer plane still takes the lower cube, one
/// 1e-10 below flips to the upper one (measured with rays hitting exact boundaries).
pub const CHECKER_OFFSET: f64 = 1e-10;

/// Which of the two `checker` pigments covers pattern-space point `p`: 0 when
/// `floor(x) + floor(y) + floor(z)` is even (after [`CHECKER_OFFSET`]), else 1.
///
/// Measured against POV-Ray 3.7: the unit cube [0,1)³ takes the first pigment,
/// a point exactly on an integer plane belongs to the cube above it.
pub fn checker_index(p: DVec3) -> usize {
    let f = (p + DVec3::splat(CHECKER_OFFSET)).floor();
    let sum = f.x + f.y + f.z;
    usize::from(sum.rem_euclid(2.0) != 0.0)
}

/// The colour of `pigment` at point `p`, given in the space the pigment's own
/// transform is relative to (the texture's space).
pub fn evaluate(pigment: &Pigment, p: DVec3) -> Colour {
    evaluate_uv(pigment, p, None)
}

/// As [`evaluate`], with the surface's uv coordinates for `uv_mapping`.
pub fn evaluate_uv(pigment: &Pigment, p: DVec3, uv: Option<DVec2>) -> Colour {
    let p = match &pigment.transform {
        Some(t) => t.inverse.transform_point3(p),
        None => p,
    };
    match &pigment.pattern {
        Pattern::Solid(c) => *c,
        Pattern::Checker(pair) => evaluate_uv(&pair[checker_index(p)], p, uv),
        Pattern::Mapped(m) => mapped(m, p, uv),
        Pattern::Image(im) => image_map::lookup(im, p, uv),
        Pattern::Uv(inner) => match uv {
            Some(uv) => evaluate_uv(inner, DVec3::new(uv.x, uv.y, 0.0), Some(uv)),
            None => evaluate_uv(inner, p, None),
        },
    }
}

fn mapped(m: &Mapped, p: DVec3, uv: Option<DVec2>) -> Colour {
    if m.kind.is_list() {
        let q = patterns::warp(p, &m.mods);
        let i = patterns::list_index(&m.kind, q);
        return match &m.map {
            PatternMap::List(l) if !l.is_empty() => evaluate_uv(&l[i.min(l.len() - 1)], p, uv),
            _ => Colour::BLACK,
        };
    }
    if m.kind == PatternKind::Average {
        return average(&m.map, p, uv);
    }
    let v = patterns::value(&m.kind, p, &m.mods);
    match &m.map {
        PatternMap::Colours(entries) => colour_at(entries, v),
        PatternMap::Pigments(entries) => {
            if entries.is_empty() {
                return Colour::BLACK;
            }
            let i = entries.partition_point(|(x, _)| *x <= v);
            if i == 0 {
                return evaluate_uv(&entries[0].1, p, uv);
            }
            if i == entries.len() {
                return evaluate_uv(&entries[i - 1].1, p, uv);
            }
            let (v0, a) = &entries[i - 1];
            let (v1, b) = &entries[i];
            let ca = evaluate_uv(a, p, uv);
            if v1 <= v0 {
                return ca;
            }
            let cb = evaluate_uv(b, p, uv);
            mix(ca, cb, (v - v0) / (v1 - v0))
        }
        PatternMap::List(l) => l
            .first()
            .map_or(Colour::BLACK, |pig| evaluate_uv(pig, p, uv)),
    }
}

/// `average`: the entries of a pigment map (or colour map) averaged, each
/// weighed by its map value (POV-Ray's weights).
fn average(map: &PatternMap, p: DVec3, uv: Option<DVec2>) -> Colour {
    let mut sum = Colour::BLACK;
    let mut total = 0.0;
    let mut add = |w: f64, c: Colour| {
        sum.rgb += c.rgb * w;
        sum.filter += c.filter * w;
        sum.transmit += c.transmit * w;
        total += w;
    };
    match map {
        PatternMap::Pigments(entries) => {
            for (w, pig) in entries.iter() {
                add(*w, evaluate_uv(pig, p, uv));
            }
        }
        PatternMap::Colours(entries) => {
            for (w, c) in entries.iter() {
                add(*w, *c);
            }
        }
        PatternMap::List(l) => {
            for pig in l {
                add(1.0, evaluate_uv(pig, p, uv));
            }
        }
    }
    if total == 0.0 {
        return Colour::BLACK;
    }
    Colour {
        rgb: sum.rgb / total,
        filter: sum.filter / total,
        transmit: sum.transmit / total,
    }
}

fn mix(a: Colour, b: Colour, t: f64) -> Colour {
    Colour {
        rgb: a.rgb + (b.rgb - a.rgb) * t,
        filter: a.filter + (b.filter - a.filter) * t,
        transmit: a.transmit + (b.transmit - a.transmit) * t,
    }
}

/// The colour a sorted `color_map` gives value `v`: the first entry below the
/// first value, the last above the last, linear blends between.
pub fn colour_at(entries: &[(f64, Colour)], v: f64) -> Colour {
    if entries.is_empty() {
        return Colour::BLACK;
    }
    let i = entries.partition_point(|(x, _)| *x <= v);
    if i == 0 {
        return entries[0].1;
    }
    if i == entries.len() {
        return entries[i - 1].1;
    }
    let (v0, a) = entries[i - 1];
    let (v1, b) = entries[i];
    if v1 <= v0 {
        return a;
    }
    mix(a, b, (v - v0) / (v1 - v0))
}

/// How far a `bumps` normal leans per unit of its vector noise and `bump_size`
/// (fitted to POV-Ray 3.7's bumps on a lit plane: same shading contrast, and the
/// same mean spatial frequency within 13%).
const LEAN_BUMPS: f64 = 1.15;

/// The same for `wrinkles` (fitted to POV-Ray's contrast and mean darkening on a
/// lit plane, both within 2%).
const LEAN_WRINKLES: f64 = 0.75;

/// How strongly the slope of a normal pattern tilts the normal per unit of
/// `bump_size`. Fitted so each pattern's shading contrast (standard deviation of a
/// lit plane) matches POV-Ray 3.7; for `gradient x 0.5` POV-Ray tilts the normal
/// by 1/15 (measured on a plane lit at 45 degrees: 0.75259 of the light, which
/// is exactly a tilt of 0.0667; onion, spherical, wood and marble tilt alike),
/// which gives the generic value 2/15.
fn bump_gain(kind: &crate::scene::PatternKind) -> f64 {
    use crate::scene::PatternKind as K;
    match kind {
        K::Bumps => LEAN_BUMPS,
        // bozo/spotted: POV-Ray's bozo normal is faint, 0.013 standard deviation
        // of a plane lit at 45° for `bozo 0.5` (granite and agate: 0.15, 0.16).
        K::Bozo => 0.105,
        K::Granite => 0.063,
        K::Agate => 0.13,
        K::Dents => 0.2,
        K::Wrinkles => LEAN_WRINKLES,
        // POV-Ray's quilted, ripples and waves normals add their vectors
        // themselves.
        K::Quilted { .. } | K::Ripples | K::Waves => 1.0,
        _ => 2.0 / 15.0,
    }
}

/// The shading normal `n` (unit, world space, facing the viewer) perturbed by
/// `normal` at world point `p`; `texture_from_world` maps world points into the
/// texture's space. As in POV-Ray the normal leans against the pattern's slope on
/// the side the surface is seen from.
pub fn perturb(normal: &Normal, n: DVec3, p: DVec3, texture_from_world: Option<&DMat4>) -> DVec3 {
    if let Some(b) = &normal.blend {
        return perturb_blend(normal, b, n, p, texture_from_world);
    }
    if normal.bump_size == 0.0 {
        return n;
    }
    let out = if leans_whole(&normal.kind) {
        whole(normal, n, p, texture_from_world)
    } else {
        let lean = lean(normal, p, texture_from_world);
        n - (lean - lean.dot(n) * n)
    };
    let len = out.length();
    if len > 0.0 && len.is_finite() {
        out / len
    } else {
        n
    }
}

/// Whether a normal pattern's vector is added whole to the surface normal, its
/// part along the normal included (POV-Ray's `ripples` and `waves`: measured,
/// a centre above a lit plane deepens the waves on one side of it), rather than
/// only tilting it.
fn leans_whole(kind: &PatternKind) -> bool {
    matches!(kind, PatternKind::Ripples | PatternKind::Waves)
}

/// `n` (world space) with a [`leans_whole`] pattern's vector added, unnormalised:
/// as POV-Ray does it (measured on planes and spheres, uniformly and unevenly
/// scaled), the normal is carried into pattern space and made unit there, the
/// vector times `bump_size` added, and the sum carried back.
fn whole(normal: &Normal, n: DVec3, p: DVec3, texture_from_world: Option<&DMat4>) -> DVec3 {
    let (q, to_pattern) = pattern_frame(normal, p, texture_from_world);
    let Some(v) = patterns::lean_vector(&normal.kind, q, &normal.mods) else {
        return n;
    };
    // (lean_vector's vectors are what the normal leans against.)
    let v = -normal.bump_size * v;
    match to_pattern {
        None => n + v,
        Some(m) => {
            // Normals go from world to pattern space by the inverse of the
            // transposed world-to-pattern map, and back by the transpose.
            let back = glam::DMat3::from_mat4(m).transpose();
            let np = back.inverse() * n;
            back * (np.normalize_or_zero() + v)
        }
    }
}

/// A camera ray's unit direction `d` perturbed by the camera's `normal` (POV-Ray
/// 3.7's camera ray perturbation): the pattern is read at the ray's screen point
/// (`sx`, `sy`, 0), `sx` and `sy` in [-0.5, 0.5] whatever the camera's vectors,
/// and the direction leans against its world-space slope as a surface normal
/// would, without dropping the part along the ray (measured: `gradient x 0.5`
/// adds -x/15 to every unit direction, before normalising, under any camera
/// orientation, and a pattern's seams fall at the same pixels for any `right`,
/// `direction` or `location`).
pub fn perturb_camera_ray(normal: &Normal, d: DVec3, sx: f64, sy: f64) -> DVec3 {
    if normal.blend.is_some() {
        return perturb(normal, d, DVec3::new(sx, sy, 0.0), None);
    }
    let out = d - lean(normal, DVec3::new(sx, sy, 0.0), None);
    let len = out.length();
    if len > 0.0 && len.is_finite() {
        out / len
    } else {
        d
    }
}

/// The vector a normal leans against at world point `p`: its slope there times
/// `bump_size` and the pattern's gain.
fn lean(normal: &Normal, p: DVec3, texture_from_world: Option<&DMat4>) -> DVec3 {
    let f = |q: DVec3| {
        let t = texture_from_world.map_or(q, |m| m.transform_point3(q));
        let t = match &normal.transform {
            Some(x) => x.inverse.transform_point3(t),
            None => t,
        };
        if normal.kind.is_list() {
            patterns::list_index(&normal.kind, patterns::warp(t, &normal.mods)) as f64
        } else {
            patterns::value(&normal.kind, t, &normal.mods)
        }
    };
    // Central differences in world space, with a step relative to the pattern's
    // scale so tiny and huge patterns both resolve.
    let scale = texture_from_world
        .map(|m| m.transform_vector3(DVec3::ONE).length() / 3f64.sqrt())
        .unwrap_or(1.0)
        * normal
            .transform
            .as_ref()
            .map(|x| x.inverse.transform_vector3(DVec3::ONE).length() / 3f64.sqrt())
            .unwrap_or(1.0);
    // (Ripples and waves have their own normals, whatever the accuracy.)
    let analytic = if normal.accuracy.is_some() && !leans_whole(&normal.kind) {
        None
    } else {
        analytic_slope(normal, p, texture_from_world)
    };
    let g = match analytic {
        Some(g) => g,
        None => {
            // Patterns of steps (list patterns, a pigment's or an image's
            // values) are differenced over POV-Ray's default `accuracy` of
            // 0.02, so their edges show as bevels as in POV-Ray; smooth ones
            // over a tiny step; `accuracy` sets the step.
            let step = if let Some(a) = normal.accuracy {
                a
            } else if normal.kind.is_list()
                || matches!(
                    normal.kind,
                    PatternKind::PigmentPattern(_) | PatternKind::ImagePattern(_)
                )
            {
                0.02
            } else {
                1e-4
            };
            let h = step / scale.max(1e-12);
            let mut g = DVec3::ZERO;
            for (i, axis) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
                g[i] = (f(p + axis * h) - f(p - axis * h)) / (2.0 * h);
            }
            g
        }
    };
    // The slope in the pattern's own units.
    let g = g / scale.max(1e-12);
    normal.bump_size * bump_gain(&normal.kind) * g
}

/// The world-space vector `normal` leans against at world point `p`, when the
/// pattern gives one directly: its lean vector ([`patterns::lean_vector`]) or
/// its analytic slope ([`patterns::value_gradient`]), carried back from pattern
/// space through the transposed linear part of the world → pattern map.
fn analytic_slope(normal: &Normal, p: DVec3, texture_from_world: Option<&DMat4>) -> Option<DVec3> {
    if normal.kind.is_list() {
        return None;
    }
    let (q, to_pattern) = pattern_frame(normal, p, texture_from_world);
    let g = patterns::lean_vector(&normal.kind, q, &normal.mods)
        .or_else(|| patterns::value_gradient(&normal.kind, q, &normal.mods))?;
    Some(match to_pattern {
        Some(m) => m.transpose().transform_vector3(g),
        None => g,
    })
}

/// World point `p` in `normal`'s pattern space, with the world → pattern map
/// (`None`: the identity).
fn pattern_frame(
    normal: &Normal,
    p: DVec3,
    texture_from_world: Option<&DMat4>,
) -> (DVec3, Option<DMat4>) {
    let mut q = p;
    let mut to_pattern: Option<DMat4> = None;
    if let Some(m) = texture_from_world {
        q = m.transform_point3(q);
        to_pattern = Some(*m);
    }
    if let Some(x) = &normal.transform {
        q = x.inverse.transform_point3(q);
        to_pattern = Some(match to_pattern {
            Some(m) => x.inverse * m,
            None => x.inverse,
        });
    }
    (q, to_pattern)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{PatternKind, PatternMods, Transform};
    use std::sync::Arc;

    fn solid(r: f64, g: f64, b: f64) -> Pigment {
        Pigment {
            pattern: Pattern::Solid(Colour::rgb(r, g, b)),
            transform: None,
        }
    }

    #[test]
    fn checker_parity_and_boundaries() {
        assert_eq!(checker_index(DVec3::splat(0.5)), 0);
        assert_eq!(checker_index(DVec3::new(1.5, 0.5, 0.5)), 1);
        assert_eq!(checker_index(DVec3::new(-0.5, 0.5, 0.5)), 1);
        assert_eq!(checker_index(DVec3::new(-0.5, -0.5, 0.5)), 0);
        // Exactly on a plane: the cube above.
        assert_eq!(checker_index(DVec3::new(1.0, 0.5, 0.5)), 1);
        assert_eq!(checker_index(DVec3::new(-1.0, 2.0, 0.5)), 1);
        assert_eq!(checker_index(DVec3::new(0.0, 2.0, 0.5)), 0);
        // Within the offset below a plane: still the cube above.
        assert_eq!(checker_index(DVec3::new(1.0 - 1e-11, 0.5, 0.5)), 1);
        assert_eq!(checker_index(DVec3::new(1.0 - 1e-9, 0.5, 0.5)), 0);
    }

    #[test]
    fn checker_uses_pigment_transform() {
        let pig = Pigment {
            pattern: Pattern::Checker(Box::new([solid(1.0, 0.0, 0.0), solid(0.0, 1.0, 0.0)])),
            transform: Some(Arc::new(Transform::scale(DVec3::splat(2.0)))),
        };
        assert_eq!(evaluate(&pig, DVec3::new(1.5, 0.5, 0.5)).rgb, DVec3::X);
        assert_eq!(evaluate(&pig, DVec3::new(2.5, 0.5, 0.5)).rgb, DVec3::Y);
    }

    #[test]
    fn colour_map_blends_and_clamps() {
        let e = vec![
            (0.2, Colour::rgb(0.0, 0.0, 0.0)),
            (0.6, Colour::rgb(1.0, 0.5, 0.0)),
        ];
        assert_eq!(colour_at(&e, 0.0).rgb, DVec3::ZERO);
        assert_eq!(colour_at(&e, 0.9).rgb, DVec3::new(1.0, 0.5, 0.0));
        assert!((colour_at(&e, 0.4).rgb - DVec3::new(0.5, 0.25, 0.0)).length() < 1e-12);
    }

    #[test]
    fn gradient_pigment_with_map() {
        let pig = Pigment {
            pattern: Pattern::Mapped(Box::new(Mapped {
                kind: PatternKind::Gradient(DVec3::X),
                mods: PatternMods::default(),
                map: PatternMap::Colours(Arc::new(vec![
                    (0.0, Colour::rgb(0.0, 0.0, 0.0)),
                    (1.0, Colour::rgb(1.0, 1.0, 1.0)),
                ])),
            })),
            transform: None,
        };
        assert!((evaluate(&pig, DVec3::new(2.3, 0.0, 0.0)).rgb.x - 0.3).abs() < 1e-9);
    }

    #[test]
    fn analytic_slopes_equal_differences() {
        let tr = Transform::scale(DVec3::new(0.3, 0.7, 0.2))
            .then(&Transform::rotate(DVec3::new(20.0, 35.0, -10.0)))
            .then(&Transform::translate(DVec3::new(0.4, -1.0, 2.0)));
        let tex = Transform::rotate(DVec3::new(0.0, 60.0, 15.0))
            .then(&Transform::scale(DVec3::splat(1.7)));
        let kinds = [
            PatternKind::Bozo,
            PatternKind::Dents,
            PatternKind::Gradient(DVec3::new(0.2, 1.0, 0.5)),
        ];
        for kind in kinds {
            for freq in [1.0, 3.0] {
                let nrm = Normal {
                    kind: kind.clone(),
                    mods: PatternMods {
                        frequency: freq,
                        ..PatternMods::default()
                    },
                    bump_size: 1.0,
                    transform: Some(Arc::new(tr)),
                    accuracy: None,
                    blend: None,
                };
                for i in 0..50 {
                    let p = DVec3::new(
                        i as f64 * 0.137 - 3.0,
                        (i % 5) as f64 * 0.29,
                        (i % 11) as f64 * -0.31,
                    );
                    let Some(g) = analytic_slope(&nrm, p, Some(&tex.inverse)) else {
                        // Noise patterns with a frequency go by differences.
                        assert!(
                            freq != 1.0 && matches!(kind, PatternKind::Bozo | PatternKind::Dents)
                        );
                        continue;
                    };
                    let f = |q: DVec3| {
                        patterns::value(
                            &nrm.kind,
                            tr.inverse.transform_point3(tex.inverse.transform_point3(q)),
                            &nrm.mods,
                        )
                    };
                    let h = 1e-6;
                    for (k, axis) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
                        let fd = (f(p + axis * h) - f(p - axis * h)) / (2.0 * h);
                        assert!(
                            (fd - g[k]).abs() < 1e-4 * (1.0 + fd.abs()),
                            "{kind:?} freq {freq} at {p}: axis {k} {fd} vs {}",
                            g[k]
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn wrinkles_lean_one_way_and_bumps_do_not() {
        let mut bumps = DVec3::ZERO;
        let mut wrinkles = DVec3::ZERO;
        let m = PatternMods::default();
        for i in 0..2000 {
            let p = DVec3::new(
                i as f64 * 0.731,
                (i % 37) as f64 * 0.53,
                (i % 11) as f64 * 1.7,
            );
            bumps += patterns::lean_vector(&PatternKind::Bumps, p, &m).unwrap();
            wrinkles += patterns::lean_vector(&PatternKind::Wrinkles, p, &m).unwrap();
        }
        let (bumps, wrinkles) = (bumps / 2000.0, wrinkles / 2000.0);
        assert!(bumps.abs().max_element() < 0.05, "{bumps}");
        assert!(wrinkles.max_element() < -0.2, "{wrinkles}");
    }

    #[test]
    fn flat_pattern_keeps_normal_and_slope_tilts_it() {
        let nrm = Normal {
            kind: PatternKind::Gradient(DVec3::X),
            mods: PatternMods::default(),
            bump_size: 1.0,
            transform: None,
            accuracy: None,
            blend: None,
        };
        let n = perturb(&nrm, DVec3::Y, DVec3::new(0.3, 0.0, 0.0), None);
        assert!(n.x < 0.0 && (n.length() - 1.0).abs() < 1e-9);
        let mut flat = nrm.clone();
        flat.bump_size = 0.0;
        assert_eq!(perturb(&flat, DVec3::Y, DVec3::ZERO, None), DVec3::Y);
    }
}
