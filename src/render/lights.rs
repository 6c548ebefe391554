//! Light arriving at a surface point: direction, distance, colour after shadows.

use super::shade::TraceCtx;
use crate::build::{Ray, World};
use crate::scene::{Light, LightKind};
use glam::DVec3;

/// Light from one source reaching a point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Incident {
    /// Unit direction from the point towards the light.
    pub dir: DVec3,
    /// Distance to the light along `dir` (to the plane through `location` for
    /// parallel lights).
    pub dist: f64,
    /// The light's colour as it arrives: after shadows (and, for lights that have
    /// them, fading and spot falloff).
    pub colour: DVec3,
}

/// The light `light` brings to point `p` with geometric normal `geo_n` and shading
/// normal `n` (facing the viewer); `None` when the point faces away or is in full
/// shadow.
pub fn incident(
    world: &World,
    light: &Light,
    p: DVec3,
    geo_n: DVec3,
    n: DVec3,
    ctx: &mut TraceCtx,
) -> Option<Incident> {
    let (dir, dist) = match light.kind {
        LightKind::Point => {
            let to = light.location - p;
            let dist = to.length();
            (to / dist, dist)
        }
        LightKind::Parallel { point_at } => {
            let l = (light.location - point_at).normalize();
            // Only what lies before the plane through `location` casts shadows.
            (l, (light.location - p).dot(l).max(0.0))
        }
    };
    let cos_l = n.dot(dir);
    if cos_l.is_nan() || cos_l <= 0.0 {
        return None;
    }
    let mut colour = light.colour;
    if !light.shadowless {
        let (shadow_ray, eps) = Ray::secondary(p, geo_n, dir);
        if dist > eps {
            ctx.stats.shadow += 1;
            // Filtered by transparent surfaces on the way (0 behind opaque ones).
            colour *= super::shade::shadow_filter(world, &shadow_ray, eps, dist - eps);
            if colour == DVec3::ZERO {
                return None;
            }
        }
    }
    Some(Incident { dir, dist, colour })
}
