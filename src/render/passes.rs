//! Debug passes: what the first camera-ray hit looks like without shading.
//!
//! Each pass turns one camera ray into a colour that is written as is (the data
//! passes `depth` and `normal` go to the file without gamma encoding; `albedo` is a
//! colour in the scene's working space like the full picture).

use crate::build::{Ray, RayKind, World};
use crate::pattern;
use glam::DVec3;

/// Which picture [`super::render_with`] makes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Pass {
    /// The shaded picture.
    #[default]
    Beauty,
    /// Distance to the first hit as grey: white at distance 0, black at `max` and
    /// beyond and where nothing is hit. `max: None` takes the farthest hit on a
    /// bounded object seen by the pixel-centre rays of the rendered region (on
    /// any object when only unbounded ones such as planes are seen), so an
    /// endless floor does not wash the picture out.
    Depth {
        /// The distance drawn black.
        max: Option<f64>,
    },
    /// The unit shading normal `n` at the first hit as the colour `n * 0.5 + 0.5`
    /// (x → red, y → green, z → blue; outward for closed shapes, not turned to face
    /// the camera); black where nothing is hit.
    Normal,
    /// The pigment colour at the first hit (before lighting); the background colour
    /// where nothing is hit.
    Albedo,
}

impl Pass {
    /// Whether the pass holds data to be written without gamma encoding.
    pub fn is_data(self) -> bool {
        matches!(self, Pass::Depth { .. } | Pass::Normal)
    }
}

/// Distance along `ray` to the first surface a camera ray sees, and whether that
/// surface is bounded (not an infinite plane or the like).
pub fn first_hit_distance(world: &World, ray: &Ray) -> Option<(f64, bool)> {
    world
        .intersect(ray, 0.0, f64::INFINITY, RayKind::Camera)
        .map(|h| (h.t, !world.unbounded.contains(&h.prim)))
}

/// The value of `pass` (not [`Pass::Beauty`]) along `ray`; `max_depth` is the
/// resolved black distance for [`Pass::Depth`].
pub fn sample(world: &World, ray: &Ray, pass: Pass, max_depth: f64) -> DVec3 {
    let hit = world.intersect(ray, 0.0, f64::INFINITY, RayKind::Camera);
    match (pass, hit) {
        (Pass::Depth { .. }, Some(h)) if max_depth > 0.0 => {
            DVec3::splat(1.0 - (h.t / max_depth).min(1.0))
        }
        (Pass::Normal, Some(h)) => world.surface(ray, &h).normal * 0.5 + DVec3::splat(0.5),
        (Pass::Albedo, Some(h)) => {
            let s = world.surface(ray, &h);
            let tp = s
                .texture_from_world
                .map_or(s.p, |m| m.transform_point3(s.p));
            if s.texture.patterned.is_none() {
                return pattern::evaluate(&s.texture.pigment, tp).rgb;
            }
            // A patterned texture: its textures' pigments, averaged by weight.
            let mut albedo = DVec3::ZERO;
            pattern::slope::set_surface_normal_facing(s.normal, ray.dir);
            pattern::for_each_plain(s.texture, tp, 1.0, &mut |t, w| {
                albedo += w * pattern::evaluate(&t.pigment, tp).rgb
            });
            albedo
        }
        (Pass::Albedo, None) => world.background,
        _ => DVec3::ZERO,
    }
}
