//! Light arriving at a surface point: direction, distance, colour after shadows,
//! spot and cylinder beams, fading and area lights, as POV-Ray 3.7 computes them.

use super::shade::TraceCtx;
use crate::build::{Ray, World};
use crate::scene::{AreaLight, Beam, LightKind};
use glam::DVec3;
use std::cell::Cell;

/// Shadow hints kept per thread: one per light (by index, modulo the count).
const HINT_SLOTS: usize = 16;

thread_local! {
    /// POV-Ray's shadow cache: per light, the primitive that last blocked one of
    /// its shadow rays on this thread, tested before the hierarchy is walked.
    /// Neighbouring points are usually shadowed by the same object, so a blocked
    /// shadow ray mostly costs one intersection test. Only ever a hint: the
    /// answer is the same whatever it holds, so pictures stay independent of
    /// threads and order.
    static SHADOW_HINTS: [Cell<u32>; HINT_SLOTS] = const { [const { Cell::new(u32::MAX) }; HINT_SLOTS] };
}

/// Light from one source reaching a point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Incident {
    /// Unit direction from the point towards the light (its centre for area lights).
    pub dir: DVec3,
    /// Distance to the light along `dir` (to the plane through `location` for
    /// parallel lights).
    pub dist: f64,
    /// The light's colour as it arrives: after shadows (for area lights multiplied by
    /// the unshadowed fraction), fading and spot or cylinder falloff.
    pub colour: DVec3,
}

/// The light `world.lights[index]` brings to point `p` with geometric normal
/// `geo_n` and shading normal `n` (facing the viewer); `None` when the point faces
/// away, lies outside the beam or is in full shadow (or there is no such light).
/// The index also picks the light's shadow hint.
pub fn incident(
    world: &World,
    index: usize,
    p: DVec3,
    geo_n: DVec3,
    n: DVec3,
    ctx: &mut TraceCtx,
) -> Option<Incident> {
    let light = world.lights.get(index)?;
    // Measured in POV-Ray 3.7: a `shadowless` spotlight or cylinder light loses its
    // beam (a cylinder light still shines along its axis).
    let kind = if light.shadowless {
        LightKind::Point
    } else {
        light.kind
    };
    // Cylinder lights shine along their axis, like parallel lights (as measured in
    // POV-Ray 3.7: the whole beam has cos = 1 on a plane across it).
    let along_axis = light.parallel || matches!(light.kind, LightKind::Cylinder(_));
    let (dir, dist) = if along_axis {
        let l = (light.location - light.point_at).normalize();
        // Only what lies before the plane through `location` casts shadows.
        (l, (light.location - p).dot(l).max(0.0))
    } else {
        let to = light.location - p;
        let dist = to.length();
        (to / dist, dist)
    };
    let cos_l = n.dot(dir);
    if cos_l.is_nan() || cos_l <= 0.0 {
        return None;
    }
    let mut colour = light.colour * fade(light.fade_distance, light.fade_power, dist);
    colour *= match kind {
        LightKind::Point => 1.0,
        LightKind::Spot(beam) => {
            let axis = (light.point_at - light.location).normalize();
            spot_attenuation(&beam, (-dir).dot(axis))
        }
        LightKind::Cylinder(beam) => {
            let axis = (light.point_at - light.location).normalize();
            cylinder_attenuation(&beam, axis, p - light.location)
        }
    };
    if colour == DVec3::ZERO || colour.is_nan() {
        return None;
    }
    // A shadowless light's `projected_through` still masks it (shadowed lights
    // test it per shadow ray, so area lights get soft edges).
    if light.shadowless && beyond_mask(world, index, p, dir, dist) == Some(None) {
        return None;
    }
    if !light.shadowless {
        let seen = match (&light.area, along_axis) {
            (Some(area), false) => {
                area_visibility(world, area, light.location, p, geo_n, index, ctx)
            }
            _ => shadow(world, p, geo_n, dir, dist, index, ctx),
        };
        colour *= seen;
        // Media in objects always dim light passing through them; atmospheric
        // media and fog only with `media_attenuation on` (as in POV-Ray 3.7).
        let atmospheric = light.media_attenuation && world.tracks_interiors;
        if (atmospheric || world.object_media) && colour != DVec3::ZERO {
            colour *= super::media::shadow_attenuation(world, p, dir, dist, atmospheric, ctx);
        }
        if colour == DVec3::ZERO {
            return None;
        }
    }
    Some(Incident { dir, dist, colour })
}

/// How much light passes from `p` (geometric normal `geo_n`) along unit `dir` for
/// `dist`: one for a clear path, zero when an opaque object blocks it, the product
/// of the filter/transmit colours of transparent surfaces on the way otherwise.
///
/// This is the single place shadow rays are traced, so transparent shadows can
/// replace it. `light` is the light's index in the world (it picks the shadow
/// hint the ray starts from).
pub fn shadow(
    world: &World,
    p: DVec3,
    geo_n: DVec3,
    dir: DVec3,
    dist: f64,
    light: usize,
    ctx: &mut TraceCtx,
) -> DVec3 {
    // Through a `projected_through` object only: shadows from beyond it.
    let dist = match beyond_mask(world, light, p, dir, dist) {
        None => dist,
        Some(None) => return DVec3::ZERO,
        Some(Some(rest)) => rest,
    };
    let (ray, eps) = Ray::secondary(p, geo_n, dir);
    // Measured from the ray's own origin (moved off the surface): from a floor
    // lit by a light set exactly in the ceiling's plane, the distance from `p`
    // would reach the ceiling (POV-Ray's radiosity/cornell.pov had a black
    // floor); a surface through the light itself casts no shadow.
    let dist = (p + dir * dist - ray.origin).length();
    if dist <= eps {
        return DVec3::ONE;
    }
    ctx.stats.shadow += 1;
    SHADOW_HINTS.with(|hints| {
        let cell = &hints[light % HINT_SLOTS];
        let mut hint = cell.get();
        // Filtered by transparent surfaces on the way (0 behind opaque ones).
        let photon_light = world.global.photons.is_some()
            && world
                .lights
                .get(light)
                .is_some_and(|l| l.photons.refraction);
        let seen =
            super::shade::shadow_filter(world, &ray, eps, dist - eps, &mut hint, photon_light);
        cell.set(hint);
        seen
    })
}

/// For a light with a `projected_through` object (else `None`): `Some(None)` when
/// the way from the light (at `p + dir · dist`) to `p` misses the object, else
/// `Some(Some(d))` with `d` the distance from `p` back to where that way last
/// leaves the object (0 when `p` lies inside it): only objects within `d` of `p`
/// can shadow it, as POV-Ray's manual says ("any objects between the light and
/// the projected through object will not cast shadows").
pub(crate) fn beyond_mask(
    world: &World,
    light: usize,
    p: DVec3,
    dir: DVec3,
    dist: f64,
) -> Option<Option<f64>> {
    let mask = world.light_masks.get(light)?.as_ref()?;
    /// Crossings looked at on one way (a limit, not a hang, for odd shapes).
    const MAX_CROSSINGS: usize = 64;
    // A parallel light's samples may lie at infinity: start past the mask instead.
    let dist = if dist.is_finite() {
        dist
    } else {
        let b = mask.bounds;
        let far = (b.min - p).abs().max((b.max - p).abs()).length();
        if far.is_finite() {
            far + 1.0
        } else {
            1e9
        }
    };
    let from = p + dir * dist;
    let ray = Ray::new(from, -dir);
    let mut last = None;
    let mut t0 = 0.0;
    // Stopping a little short of `p`: a point on the object's own surface is
    // not reached through that surface (POV-Ray leaves the object's lit side
    // dark), the same way on every pixel.
    let reach = dist - 2.0 * crate::build::surface_offset(p);
    for _ in 0..MAX_CROSSINGS {
        let Some(hit) = mask.intersect(&ray, t0, reach, crate::build::RayKind::Probe) else {
            break;
        };
        last = Some(hit.t);
        t0 = hit.t + crate::build::surface_offset(ray.at(hit.t));
    }
    let Some(t) = last else {
        return Some(None);
    };
    Some(Some(if mask.inside(p) {
        0.0
    } else {
        (dist - t).max(0.0)
    }))
}

/// POV-Ray's distance fading: `2 / (1 + (d / fade_distance)^fade_power)`, or 1 when
/// either parameter is zero (no fading). A light at `d = fade_distance` has its full
/// colour; nearer it is brighter, up to twice at the light.
pub fn fade(fade_distance: f64, fade_power: f64, d: f64) -> f64 {
    if fade_power <= 0.0 || fade_distance.abs() < 1e-10 {
        return 1.0;
    }
    2.0 / (1.0 + (d / fade_distance).powf(fade_power))
}

/// Hermite blend from 0 at `low` to 1 at `high`: `t²(3 - 2t)`.
fn smoothstep(low: f64, high: f64, x: f64) -> f64 {
    if x <= low {
        return 0.0;
    }
    if x >= high {
        return 1.0;
    }
    let t = (x - low) / (high - low);
    t * t * (3.0 - 2.0 * t)
}

/// A spotlight's intensity at a point seen from the light at angle θ off the axis
/// (`cos_theta = cos θ`): 0 outside `falloff`; inside it `cos θ ^ tightness` (1 for
/// tightness 0), multiplied between `radius` and `falloff` by a smooth Hermite
/// step in cos θ from 0 at the falloff cone to 1 at the radius cone. Nothing
/// behind the light's plane (θ ≥ 90°) is lit even when `falloff` is wider, as
/// measured in POV-Ray 3.7 (`falloff 100` keeps its wider step in front).
pub fn spot_attenuation(beam: &Beam, cos_theta: f64) -> f64 {
    let cos_falloff = beam.falloff.to_radians().cos();
    let cos_radius = beam.radius.to_radians().cos();
    if cos_theta <= cos_falloff || cos_theta <= 0.0 {
        return 0.0;
    }
    let mut a = if beam.tightness > 0.0 {
        cos_theta.powf(beam.tightness)
    } else {
        1.0
    };
    if cos_theta < cos_radius {
        a *= smoothstep(cos_falloff, cos_radius, cos_theta);
    }
    a
}

/// A cylinder light's intensity at offset `rel` from its location, `axis` the unit
/// beam direction: 0 behind the light or farther than `falloff` from the axis;
/// otherwise `(1 - r / falloff)^tightness` with r the distance from the axis,
/// multiplied beyond `radius` by a Hermite step from 0 at `falloff` to 1 at
/// `radius`.
pub fn cylinder_attenuation(beam: &Beam, axis: DVec3, rel: DVec3) -> f64 {
    let along = rel.dot(axis);
    if along <= 0.0 {
        return 0.0;
    }
    let r = (rel - along * axis).length();
    if r >= beam.falloff {
        return 0.0;
    }
    let x = 1.0 - r / beam.falloff;
    let mut a = if beam.tightness > 0.0 {
        x.powf(beam.tightness)
    } else {
        1.0
    };
    if beam.radius > 0.0 && r > beam.radius {
        a *= smoothstep(0.0, 1.0 - beam.radius / beam.falloff, x);
    }
    a
}

/// Fraction of an area light that `p` sees, per channel.
fn area_visibility(
    world: &World,
    area: &AreaLight,
    centre: DVec3,
    p: DVec3,
    geo_n: DVec3,
    light: usize,
    ctx: &mut TraceCtx,
) -> DVec3 {
    let (mut a1, mut a2) = (area.axis1, area.axis2);
    if area.orient {
        (a1, a2) = oriented_axes(a1, a2, (centre - p).normalize());
    }
    let mut grid = Grid {
        world,
        area,
        centre,
        a1,
        a2,
        p,
        geo_n,
        light,
        cache: vec![None; area.size1 as usize * area.size2 as usize],
    };
    let dyadic = |n: u32| n == 1 || (n - 1).is_power_of_two();
    match area.adaptive {
        Some(level) => grid.block(0, 0, area.size1 - 1, area.size2 - 1, 0, level, ctx),
        // Without `adaptive`, POV-Ray 3.7 still averages block by block down to
        // single cells, which weighs the lights unevenly; that matches it exactly for
        // 2^n + 1 lights per axis.
        None if dyadic(area.size1) && dyadic(area.size2) => {
            grid.block(0, 0, area.size1 - 1, area.size2 - 1, 0, u32::MAX, ctx)
        }
        // Other sizes: the plain mean, which is close to POV-Ray's (within 7/255 in
        // a 4 × 4 test) but not equal.
        None => {
            let mut sum = DVec3::ZERO;
            for v in 0..area.size2 {
                for u in 0..area.size1 {
                    sum += grid.sample(u, v, ctx);
                }
            }
            sum / f64::from(area.size1 * area.size2)
        }
    }
}

/// The area light's axes turned to lie across the direction `d` to the light,
/// keeping their lengths.
pub(super) fn oriented_axes(a1: DVec3, a2: DVec3, d: DVec3) -> (DVec3, DVec3) {
    let (l1, l2) = (a1.length(), a2.length());
    let mut u = d.cross(a2);
    if u.length_squared() < 1e-12 * l2 * l2 {
        u = d.cross(a1);
    }
    if u.length_squared() < 1e-24 {
        u = d.any_orthonormal_vector();
    }
    let u = u.normalize();
    let v = d.cross(u);
    (u * l1, v * l2)
}

/// One area light's grid of sample lights as seen from one point, with each
/// light's shadow test kept so adaptive blocks share their corners.
struct Grid<'a> {
    world: &'a World,
    area: &'a AreaLight,
    centre: DVec3,
    a1: DVec3,
    a2: DVec3,
    p: DVec3,
    geo_n: DVec3,
    /// Index of the light in the world.
    light: usize,
    cache: Vec<Option<DVec3>>,
}

impl Grid<'_> {
    /// Light arriving from grid light (u, v).
    fn sample(&mut self, u: u32, v: u32, ctx: &mut TraceCtx) -> DVec3 {
        let i = (v * self.area.size1 + u) as usize;
        if let Some(c) = self.cache[i] {
            return c;
        }
        let at = |k: u32, n: u32| {
            if n > 1 {
                f64::from(k) / f64::from(n - 1) - 0.5
            } else {
                0.0
            }
        };
        let (mut s, mut t) = (at(u, self.area.size1), at(v, self.area.size2));
        if self.area.jitter {
            let (j1, j2) = ctx.sampler.next_2d();
            if self.area.size1 > 1 {
                s += (j1 - 0.5) / f64::from(self.area.size1 - 1);
            }
            if self.area.size2 > 1 {
                t += (j2 - 0.5) / f64::from(self.area.size2 - 1);
            }
        }
        if self.area.circular {
            (s, t) = square_to_disc(s, t);
        }
        let pos = self.centre + s * self.a1 + t * self.a2;
        let to = pos - self.p;
        let dist = to.length();
        let c = if dist > 0.0 {
            shadow(
                self.world,
                self.p,
                self.geo_n,
                to / dist,
                dist,
                self.light,
                ctx,
            )
        } else {
            DVec3::ONE
        };
        self.cache[i] = Some(c);
        c
    }

    /// POV-Ray's adaptive area light: the four corners of the block of grid lights
    /// [u1, u2] × [v1, v2]; the block splits in four (or two) while it is wider
    /// than one cell and either `level < min_level` or its corners differ.
    #[allow(clippy::too_many_arguments)]
    fn block(
        &mut self,
        u1: u32,
        v1: u32,
        u2: u32,
        v2: u32,
        level: u32,
        min_level: u32,
        ctx: &mut TraceCtx,
    ) -> DVec3 {
        let c = [
            self.sample(u1, v1, ctx),
            self.sample(u2, v1, ctx),
            self.sample(u1, v2, ctx),
            self.sample(u2, v2, ctx),
        ];
        let splittable = u2 - u1 > 1 || v2 - v1 > 1;
        let differ = c.iter().any(|x| (*x - c[0]).abs().element_sum() > 0.1);
        if !(splittable && (level < min_level || differ)) {
            return (c[0] + c[1] + c[2] + c[3]) / 4.0;
        }
        // Both ranges split at their (rounded down) middle even when one is a
        // single cell wide, which then gives a degenerate half: POV-Ray's weights
        // for grids that are not 2^n + 1 wide depend on this.
        let (um, vm) = ((u1 + u2) / 2, (v1 + v2) / 2);
        let mut sum = DVec3::ZERO;
        for (a, b) in [(v1, vm), (vm, v2)] {
            for (l, r) in [(u1, um), (um, u2)] {
                sum += self.block(l, a, r, b, level + 1, min_level, ctx);
            }
        }
        sum / 4.0
    }
}

/// Maps a point of the square [-0.5, 0.5]² onto the disc of radius 0.5 as POV-Ray
/// 3.7 does (measured through a pinhole): each point moves along its radius so that
/// the square rings of the grid become circles, `p · max(|x|, |y|) / |p|`.
fn square_to_disc(s: f64, t: f64) -> (f64, f64) {
    let len = (s * s + t * t).sqrt();
    if len == 0.0 {
        return (0.0, 0.0);
    }
    let k = s.abs().max(t.abs()) / len;
    (s * k, t * k)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fade_formula() {
        assert_eq!(fade(0.0, 2.0, 5.0), 1.0);
        assert_eq!(fade(3.0, 0.0, 5.0), 1.0);
        assert!((fade(3.0, 2.0, 3.0) - 1.0).abs() < 1e-12);
        assert!((fade(3.0, 2.0, 0.0) - 2.0).abs() < 1e-12);
        // d = 2 fade_distance, power 2: 2 / (1 + 4).
        assert!((fade(3.0, 2.0, 6.0) - 0.4).abs() < 1e-12);
        assert!((fade(2.0, 1.0, 6.0) - 0.5).abs() < 1e-12);
    }

    #[test]
    fn spot_falloff_values() {
        let b = Beam::SPOT;
        assert_eq!(spot_attenuation(&b, 1.0), 1.0);
        assert_eq!(spot_attenuation(&b, 29f64.to_radians().cos()), 1.0);
        assert_eq!(spot_attenuation(&b, 46f64.to_radians().cos()), 0.0);
        let (cf, cr) = (45f64.to_radians().cos(), 30f64.to_radians().cos());
        let mid = spot_attenuation(&b, 0.5 * (cf + cr));
        assert!((mid - 0.5).abs() < 1e-12);
        let t = Beam {
            tightness: 10.0,
            ..b
        };
        let c = 10f64.to_radians().cos();
        assert!((spot_attenuation(&t, c) - c.powf(10.0)).abs() < 1e-12);
    }
    #[test]
    fn spot_falloff_past_ninety_degrees_stops_at_the_lights_plane() {
        let b = Beam {
            radius: 50.0,
            falloff: 100.0,
            ..Beam::SPOT
        };
        // Between radius and falloff the step runs on in cos θ (80° is lit)...
        let a80 = spot_attenuation(&b, 80f64.to_radians().cos());
        assert!(a80 > 0.0 && a80 < 1.0);
        // ...but nothing at or behind 90°.
        assert_eq!(spot_attenuation(&b, 95f64.to_radians().cos()), 0.0);
    }

    #[test]
    fn cylinder_falloff_values() {
        let b = Beam::CYLINDER;
        let ax = DVec3::Z;
        assert_eq!(cylinder_attenuation(&b, ax, DVec3::new(0.5, 0.0, 3.0)), 1.0);
        assert_eq!(
            cylinder_attenuation(&b, ax, DVec3::new(0.5, 0.0, -3.0)),
            0.0
        );
        assert_eq!(cylinder_attenuation(&b, ax, DVec3::new(1.1, 0.0, 3.0)), 0.0);
        let mid = cylinder_attenuation(&b, ax, DVec3::new(0.875, 0.0, 3.0));
        assert!((mid - 0.5).abs() < 1e-12);
    }

    #[test]
    fn disc_mapping_stays_in_the_disc() {
        for i in 0..=10 {
            for j in 0..=10 {
                let (x, y) = square_to_disc(i as f64 / 10.0 - 0.5, j as f64 / 10.0 - 0.5);
                assert!(x * x + y * y <= 0.25 + 1e-12);
            }
        }
        let (x, y) = square_to_disc(0.5, 0.0);
        assert!((x - 0.5).abs() < 1e-12 && y.abs() < 1e-12);
        // Measured in POV-Ray: grid point (1, 0.5) of [-1, 1]² lands at (0.894, 0.447).
        let (x, y) = square_to_disc(0.5, 0.25);
        assert!((x - 0.4472).abs() < 1e-4 && (y - 0.2236).abs() < 1e-4);
    }

    #[test]
    fn oriented_axes_face_the_light() {
        let d = DVec3::new(1.0, 1.0, 0.0).normalize();
        let (a, b) = oriented_axes(DVec3::X * 2.0, DVec3::Z * 3.0, d);
        assert!(a.dot(d).abs() < 1e-12 && b.dot(d).abs() < 1e-12);
        assert!((a.length() - 2.0).abs() < 1e-12 && (b.length() - 3.0).abs() < 1e-12);
    }
}
