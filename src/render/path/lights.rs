//! POV-Ray light sources for the path tracer, keeping their classic meaning: a
//! light of colour C lights a white Lambertian surface facing it exactly as the
//! classic renderer's `diffuse 1` does (irradiance π C, no fall-off with distance
//! unless `fade_distance`/`fade_power` say so; spot and cylinder beams as in
//! POV-Ray). Area lights are sampled as the continuous rectangle (or disc, with
//! `circular`) their grid spans. Light sources are never hit by rays.

use super::super::lights::{cylinder_attenuation, fade, oriented_axes, spot_attenuation};
use super::super::sampler::concentric_disc;
use super::integrator::PathScene;
use crate::build::{surface_offset, Ray, RayKind};
use crate::scene::{Light, LightKind};
use glam::DVec3;
use std::f64::consts::PI;

/// Light from one source reaching a point, before visibility.
#[derive(Clone, Copy, Debug)]
pub struct LightSample {
    /// Unit direction towards the light.
    pub wi: DVec3,
    /// Distance to the light along `wi` (finite; for parallel lights, to the plane
    /// through its location).
    pub dist: f64,
    /// What `f · cos` is multiplied by: π × colour × fading × beam.
    pub li: DVec3,
}

/// Light `light` at point `p`, with the point on an area light chosen by `u`.
pub fn sample(light: &Light, p: DVec3, u: (f64, f64)) -> Option<LightSample> {
    let kind = if light.shadowless {
        LightKind::Point
    } else {
        light.kind
    };
    let along_axis = light.parallel || matches!(light.kind, LightKind::Cylinder(_));
    let (wi, dist) = if along_axis {
        let l = (light.location - light.point_at).normalize();
        (l, (light.location - p).dot(l).max(0.0))
    } else {
        let mut at = light.location;
        if let Some(area) = &light.area {
            let (mut a1, mut a2) = (area.axis1, area.axis2);
            if area.orient {
                (a1, a2) = oriented_axes(a1, a2, (light.location - p).normalize_or_zero());
            }
            let (x, y) = if area.circular {
                let (x, y) = concentric_disc(u.0, u.1);
                (0.5 * x, 0.5 * y)
            } else {
                (u.0 - 0.5, u.1 - 0.5)
            };
            // A 1-light axis has no extent in POV-Ray's grid.
            let s1 = if area.size1 > 1 { x } else { 0.0 };
            let s2 = if area.size2 > 1 { y } else { 0.0 };
            at += s1 * a1 + s2 * a2;
        }
        let to = at - p;
        let d = to.length();
        (to / d, d)
    };
    if !wi.is_finite() {
        return None;
    }
    // Beam and fading are measured from the light's centre, as in the classic
    // renderer.
    let centre_dist = if along_axis {
        dist
    } else {
        (light.location - p).length()
    };
    let mut c = light.colour * fade(light.fade_distance, light.fade_power, centre_dist);
    c *= match kind {
        LightKind::Point => 1.0,
        LightKind::Spot(beam) => {
            let axis = (light.point_at - light.location).normalize();
            spot_attenuation(&beam, (p - light.location).normalize().dot(axis))
        }
        LightKind::Cylinder(beam) => {
            let axis = (light.point_at - light.location).normalize();
            cylinder_attenuation(&beam, axis, p - light.location)
        }
    };
    if c.max_element() <= 0.0 || !c.is_finite() {
        return None;
    }
    Some(LightSample {
        wi,
        dist,
        li: PI * c,
    })
}

/// How much light passes from `p` (geometric normal `geo_n`) along unit `wi` for
/// `dist`: 1 on a clear path, 0 behind an opaque or refracting surface, and the
/// product of `filter · colour + transmit` of the `ior 1` transparent surfaces
/// crossed (those the path tracer also passes straight through; looked for only
/// when the world has any such surface, [`crate::build::World::transparent`]).
/// `shadow_rays` counts the rays traced.
pub fn transmittance(
    sc: &PathScene,
    p: DVec3,
    geo_n: DVec3,
    wi: DVec3,
    dist: f64,
    shadow_rays: &mut u64,
) -> DVec3 {
    let (ray, eps) = Ray::secondary(p, geo_n, wi);
    let t_max = dist - eps;
    if t_max <= eps {
        return DVec3::ONE;
    }
    *shadow_rays += 1;
    if !sc.occluded(&ray, eps, t_max) {
        return DVec3::ONE;
    }
    let world = sc.world;
    if !sc.clear {
        return DVec3::ZERO;
    }
    let mut through = DVec3::ONE;
    let mut t0 = eps;
    for _ in 0..64 {
        let Some(hit) = sc.intersect(&ray, t0, t_max, RayKind::Shadow) else {
            return through;
        };
        let s = world.surface(&ray, &hit);
        let ior = s.interior.map_or(1.0, |i| i.ior);
        if (ior - 1.0).abs() > 1e-9 {
            return DVec3::ZERO;
        }
        let tp = s
            .texture_from_world
            .map_or(s.p, |m| m.transform_point3(s.p));
        let pass = |t: &crate::scene::Texture| {
            let c = crate::pattern::evaluate_uv(&t.pigment, tp, s.uv);
            (c.filter * c.rgb + DVec3::splat(c.transmit)).clamp(DVec3::ZERO, DVec3::ONE)
        };
        through *= if s.texture.patterned.is_some() {
            // A patterned texture: the textures it shows here, averaged by weight.
            let mut sum = DVec3::ZERO;
            crate::pattern::for_each_plain(s.texture, tp, 1.0, &mut |t, w| sum += w * pass(t));
            sum
        } else {
            pass(s.texture)
        };
        if through.max_element() <= 0.0 {
            return DVec3::ZERO;
        }
        t0 = hit.t + surface_offset(s.p);
    }
    DVec3::ZERO
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::AreaLight;

    #[test]
    fn point_light_keeps_povray_brightness_at_any_distance() {
        let l = Light {
            location: DVec3::new(0.0, 10.0, 0.0),
            colour: DVec3::splat(0.5),
            ..Light::default()
        };
        for y in [0.0, 5.0, 9.0] {
            let s = sample(&l, DVec3::new(0.0, y, 0.0), (0.5, 0.5)).unwrap();
            assert!((s.li - DVec3::splat(0.5 * PI)).length() < 1e-12);
            assert!((s.dist - (10.0 - y)).abs() < 1e-12);
            assert!((s.wi - DVec3::Y).length() < 1e-12);
        }
    }

    #[test]
    fn area_light_points_span_the_grid() {
        let l = Light {
            location: DVec3::new(0.0, 10.0, 0.0),
            area: Some(AreaLight {
                axis1: DVec3::new(4.0, 0.0, 0.0),
                axis2: DVec3::new(0.0, 0.0, 2.0),
                size1: 5,
                size2: 5,
                jitter: false,
                adaptive: None,
                circular: false,
                orient: false,
            }),
            ..Light::default()
        };
        let s = sample(&l, DVec3::ZERO, (0.0, 1.0)).unwrap();
        let at = s.wi * s.dist;
        assert!((at - DVec3::new(-2.0, 10.0, 1.0)).length() < 1e-9, "{at}");
    }

    #[test]
    fn concentric_maps_into_the_disc() {
        for i in 0..=10 {
            for j in 0..=10 {
                let (x, y) = concentric_disc(f64::from(i) / 10.0, f64::from(j) / 10.0);
                assert!(x * x + y * y <= 1.0 + 1e-12);
            }
        }
    }
}
