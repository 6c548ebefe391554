//! Which keywords each block accepts, from the same lists the evaluator checks against;
//! editors use it to complete only what is valid where the cursor is.

use super::blocks::is_evaluated_block;
use super::transforms::TRANSFORMS;
use crate::eval::materials::finish::{FINISH_ITEMS, REFLECTION_ITEMS};
use crate::eval::materials::image_map::IMAGE_MAP_ITEMS;
use crate::eval::materials::interior::INTERIOR_ITEMS;
use crate::eval::materials::normal::normal_items;
use crate::eval::materials::pigment::pigment_items;
use crate::eval::materials::texture::texture_items;
use crate::eval::objects::modifiers::OBJECT_MODIFIERS;
use crate::eval::objects::object::OBJECT_BLOCKS;
use crate::eval::settings::atmosphere::{FOG_ITEMS, SKY_ITEMS};
use crate::eval::settings::camera::{CAMERA_ITEMS, GLOBAL_ITEMS};
use crate::eval::settings::lights::LIGHT_ITEMS;

/// Blocks that stand at top level besides the objects: the camera, lights,
/// atmosphere, scene settings and the animation timeline.
const TOP_LEVEL_SETTINGS: &[&str] = &[
    "animation",
    "background",
    "camera",
    "camera_path",
    "fog",
    "global_settings",
    "light_source",
    "media",
    "rainbow",
    "sky_sphere",
];

/// Blocks that stand at top level: every object block the evaluator reads
/// ([`OBJECT_BLOCKS`]) and [`TOP_LEVEL_SETTINGS`], sorted.
pub fn top_level_keywords() -> Vec<&'static str> {
    let mut v: Vec<&'static str> = OBJECT_BLOCKS
        .iter()
        .chain(TOP_LEVEL_SETTINGS)
        .copied()
        .collect();
    v.sort_unstable();
    v.dedup();
    v
}

/// The keywords valid among the items of a `block { … }`; `None` when the block is not
/// one rts evaluates. For object blocks this includes the objects a CSG block may
/// contain; for `None`-returning blocks editors should offer everything.
pub fn block_keywords(block: &str) -> Option<Vec<&'static str>> {
    let mut out: Vec<&'static str> = match block {
        "texture" => texture_items(),
        "pigment" => pigment_items(),
        "normal" => normal_items(),
        "finish" => FINISH_ITEMS.to_vec(),
        "reflection" => REFLECTION_ITEMS.to_vec(),
        "interior" => INTERIOR_ITEMS.to_vec(),
        "image_map" => IMAGE_MAP_ITEMS.to_vec(),
        "camera" => CAMERA_ITEMS.to_vec(),
        "light_source" => LIGHT_ITEMS.to_vec(),
        "global_settings" => GLOBAL_ITEMS.to_vec(),
        "path_tracing" => crate::eval::settings::path_tracing::PATH_ITEMS.to_vec(),
        "radiosity" => crate::eval::settings::radiosity::RADIOSITY_ITEMS.to_vec(),
        "sky_sphere" => SKY_ITEMS.to_vec(),
        "fog" => FOG_ITEMS.to_vec(),
        "rainbow" => crate::eval::settings::atmosphere::RAINBOW_ITEMS.to_vec(),
        "media" => crate::eval::settings::media::MEDIA_ITEMS.to_vec(),
        "scattering" => crate::eval::settings::media::SCATTERING_ITEMS.to_vec(),
        "density" => pigment_items(),
        "transform" => TRANSFORMS.to_vec(),
        "color_map" | "colour_map" | "density_map" | "pigment_map" | "texture_map"
        | "background" => Vec::new(),
        "mesh" => vec!["triangle", "smooth_triangle", "inside_vector"],
        "mesh2" => vec![
            "vertex_vectors",
            "normal_vectors",
            "uv_vectors",
            "texture_list",
            "face_indices",
            "normal_indices",
            "uv_indices",
            "inside_vector",
        ],
        "cylinder" | "cone" => vec!["open"],
        "prism" => {
            let mut v = crate::eval::objects::shapes::PRISM_ITEMS.to_vec();
            v.push("open");
            v
        }
        "height_field" => vec!["png", "smooth", "water_level"],
        "text" => crate::eval::objects::text::TEXT_ITEMS.to_vec(),
        "bicubic_patch" => {
            let mut v = crate::eval::objects::shapes_more::PATCH_ITEMS.to_vec();
            v.push("uv_vectors");
            v
        }
        "julia_fractal" => crate::eval::objects::shapes_more::JULIA_ITEMS.to_vec(),
        "lathe" | "sor" => crate::eval::objects::revolve::LATHE_ITEMS.to_vec(),
        "isosurface" => crate::eval::objects::isosurface::ISOSURFACE_ITEMS.to_vec(),
        "blob" => vec!["threshold", "sphere", "cylinder", "hierarchy"],
        "material" => crate::eval::materials::material_block::MATERIAL_ITEMS.to_vec(),
        "subsurface" => crate::eval::materials::subsurface::SUBSURFACE_ITEMS.to_vec(),
        "image_pattern" => crate::eval::materials::pattern_blocks::IMAGE_PATTERN_ITEMS.to_vec(),
        "slope" => crate::eval::materials::pattern_blocks::SLOPE_ITEMS.to_vec(),
        "photons" => {
            use crate::eval::settings::photons;
            let mut v = photons::GLOBAL_ITEMS.to_vec();
            v.extend_from_slice(photons::OBJECT_ITEMS);
            v.extend_from_slice(photons::LIGHT_ITEMS);
            v
        }
        "animation" => crate::eval::animation::timeline::ANIMATION_ITEMS.to_vec(),
        "camera_path" => crate::eval::animation::camera_path::CAMERA_PATH_ITEMS.to_vec(),
        "keyframes" => crate::eval::animation::keyframe::KEYFRAME_ITEMS.to_vec(),
        "key" => crate::eval::animation::keyframe::KEY_ITEMS.to_vec(),
        "spline" => crate::eval::animation::spline::SPLINE_ITEMS.to_vec(),
        "sphere_sweep" => crate::eval::objects::shapes_more::SWEEP_ITEMS.to_vec(),
        "clipped_by" | "bounded_by" => OBJECT_BLOCKS.to_vec(),
        "union" | "merge" | "intersection" | "difference" => OBJECT_BLOCKS.to_vec(),
        "looks_like" | "projected_through" => OBJECT_BLOCKS.to_vec(),
        k if OBJECT_BLOCKS.contains(&k) => Vec::new(),
        k if is_evaluated_block(k) => return None,
        _ => return None,
    };
    if OBJECT_BLOCKS.contains(&block) {
        out.extend_from_slice(OBJECT_MODIFIERS);
    }
    if block == "texture" || block == "pigment" {
        out.extend_from_slice(&["color", "rgb"]);
    }
    out.sort_unstable();
    out.dedup();
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finish_takes_only_finish_keywords() {
        let f = block_keywords("finish").expect("finish");
        assert!(f.contains(&"phong") && f.contains(&"reflection"));
        assert!(!f.contains(&"sphere") && !f.contains(&"translate"));
        let s = block_keywords("sphere").expect("sphere");
        assert!(s.contains(&"pigment") && s.contains(&"translate"));
        assert!(block_keywords("no_such_block").is_none());
    }
}
