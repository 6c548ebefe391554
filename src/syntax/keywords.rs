//! The reserved keywords of the grammar, as a sorted table.

/// Every reserved keyword of `grammar/rts.pest` (rule `keyword_word`), sorted.
pub const KEYWORDS: &[&str] = &[
    "aa_level",
    "aa_threshold",
    "absorption",
    "accuracy",
    "adaptive",
    "adc_bailout",
    "agate",
    "agate_turb",
    "all",
    "all_intersections",
    "altitude",
    "always_sample",
    "ambient",
    "ambient_light",
    "angle",
    "animation",
    "aperture",
    "arc_angle",
    "area_light",
    "assumed_gamma",
    "autostop",
    "average",
    "b_spline",
    "background",
    "bezier_spline",
    "bicubic_patch",
    "black_hole",
    "blob",
    "blur_samples",
    "bounded_by",
    "box",
    "boxed",
    "bozo",
    "brick",
    "brick_size",
    "brightness",
    "brilliance",
    "bump_map",
    "bump_size",
    "bumps",
    "camera",
    "camera_path",
    "catmull_rom",
    "caustics",
    "cells",
    "checker",
    "circular",
    "clipped_by",
    "clock_range",
    "collect",
    "color_map",
    "colour_map",
    "component",
    "cone",
    "confidence",
    "conic_sweep",
    "conserve_energy",
    "contained_by",
    "control0",
    "control1",
    "count",
    "crackle",
    "crand",
    "cube",
    "cubic",
    "cubic_spline",
    "cubic_wave",
    "cyclic",
    "cylinder",
    "cylindrical",
    "density",
    "density_file",
    "density_map",
    "dents",
    "df3",
    "difference",
    "diffuse",
    "direction",
    "disc",
    "dispersion",
    "dispersion_samples",
    "dist_exp",
    "distance",
    "double_illuminate",
    "duration",
    "ease_bezier",
    "ease_in",
    "ease_in_out",
    "ease_out",
    "eccentricity",
    "emission",
    "error_bound",
    "evaluate",
    "expand_thresholds",
    "exponent",
    "exr",
    "exterior",
    "extinction",
    "face_indices",
    "fade_color",
    "fade_colour",
    "fade_distance",
    "fade_power",
    "falloff",
    "falloff_angle",
    "filter",
    "finish",
    "firefly_clamp",
    "fisheye",
    "flatness",
    "flip",
    "focal_point",
    "fog",
    "fog_alt",
    "fog_offset",
    "fog_type",
    "form",
    "fps",
    "frames",
    "frequency",
    "fresnel",
    "function",
    "gamma",
    "gather",
    "global_lights",
    "global_settings",
    "gradient",
    "granite",
    "gray_threshold",
    "height_field",
    "hexagon",
    "hf_gray_16",
    "hierarchy",
    "hold",
    "hollow",
    "hypercomplex",
    "image_map",
    "image_pattern",
    "importance",
    "inside_vector",
    "interior",
    "interior_texture",
    "internal",
    "interpolate",
    "intersection",
    "intervals",
    "inverse",
    "ior",
    "irid",
    "isosurface",
    "jitter",
    "jpeg",
    "julia",
    "julia_fractal",
    "key",
    "keyframes",
    "lambda",
    "lathe",
    "leopard",
    "light_group",
    "light_source",
    "linear_spline",
    "linear_sweep",
    "load_file",
    "location",
    "look_along",
    "look_at",
    "looks_like",
    "loop",
    "low_error_factor",
    "magnet",
    "major_radius",
    "mandel",
    "map_type",
    "marble",
    "material",
    "material_map",
    "matrix",
    "max_depth",
    "max_gradient",
    "max_iteration",
    "max_sample",
    "max_trace",
    "max_trace_level",
    "maximum_reuse",
    "media",
    "media_attenuation",
    "media_interaction",
    "merge",
    "mesh",
    "mesh2",
    "mesh_camera",
    "metallic",
    "method",
    "metric",
    "minimum_reuse",
    "mm_per_unit",
    "mortar",
    "motion_blur",
    "natural_spline",
    "nearest_count",
    "no_image",
    "no_radiosity",
    "no_reflection",
    "no_shadow",
    "noise_generator",
    "normal",
    "normal_indices",
    "normal_map",
    "normal_vectors",
    "number_of_waves",
    "obj_file",
    "object",
    "octaves",
    "offset",
    "omega",
    "once",
    "onion",
    "open",
    "orient",
    "orientation",
    "orthographic",
    "panoramic",
    "parallel",
    "pass_through",
    "path_tracing",
    "pattern",
    "perspective",
    "phase",
    "phong",
    "phong_size",
    "photons",
    "pigment",
    "pigment_map",
    "pigment_pattern",
    "ping_pong",
    "pixel_filter",
    "planar",
    "plane",
    "ply_file",
    "png",
    "point_at",
    "poly",
    "poly_wave",
    "polygon",
    "polyhedron",
    "precision",
    "pretrace_end",
    "pretrace_start",
    "prism",
    "projected_through",
    "quadratic_spline",
    "quadric",
    "quartic",
    "quaternion",
    "quick_color",
    "quick_colour",
    "quilted",
    "radial",
    "radiosity",
    "radius",
    "rainbow",
    "ramp_wave",
    "ratio",
    "reciprocal",
    "recursion_limit",
    "reflection",
    "reflection_exponent",
    "refraction",
    "repeat",
    "right",
    "ripples",
    "roll",
    "rotate",
    "roughness",
    "samples",
    "save_file",
    "scale",
    "scallop_wave",
    "scattering",
    "seconds",
    "shadowless",
    "sine_wave",
    "sky",
    "sky_sphere",
    "slice",
    "slope",
    "slope_map",
    "smooth",
    "smooth_triangle",
    "solid",
    "sor",
    "spacing",
    "specular",
    "sphere",
    "sphere_sweep",
    "spherical",
    "spiral1",
    "spiral2",
    "spline",
    "split_union",
    "spotlight",
    "spotted",
    "sqr",
    "square",
    "step_spline",
    "strength",
    "sturm",
    "subsurface",
    "superellipsoid",
    "tangent",
    "target",
    "text",
    "texture",
    "texture_list",
    "texture_map",
    "thickness",
    "threshold",
    "tightness",
    "tile2",
    "tiles",
    "tolerance",
    "toroidal",
    "torus",
    "transform",
    "translate",
    "translucency",
    "transmit",
    "triangle",
    "triangle_wave",
    "triangular",
    "ttf",
    "turb_depth",
    "turbulence",
    "type",
    "u_steps",
    "ultra_wide_angle",
    "union",
    "up",
    "use_alpha",
    "use_color",
    "use_colour",
    "use_index",
    "uv_indices",
    "uv_mapping",
    "uv_vectors",
    "v_steps",
    "variance",
    "vertex_vectors",
    "warp",
    "water_level",
    "waves",
    "width",
    "wood",
    "wrinkles",
];

/// The static spelling of a keyword the grammar accepted.
pub fn canonical(word: &str) -> &'static str {
    match KEYWORDS.binary_search(&word) {
        Ok(i) => KEYWORDS[i],
        Err(_) => "?",
    }
}

/// The colour keywords of the grammar's `colour_kw` rule (`rgb 1`, `color red 1`).
pub const COLOUR_WORDS: &[&str] = &[
    "color", "colour", "rgb", "rgbf", "rgbft", "rgbt", "srgb", "srgbf", "srgbft", "srgbt",
];

/// The colour component keywords of the grammar's `colour_part_kw` rule.
pub const COLOUR_PART_WORDS: &[&str] =
    &["blue", "filter", "gray", "green", "grey", "red", "transmit"];

/// A rule matching any of `words` as a whole word, written as a trie: the
/// word's letters pick the branch, so a word is matched with a handful of
/// comparisons instead of one per word, and every branch ends in
/// `!ident_char`.
fn trie(words: &[&str]) -> String {
    #[derive(Default)]
    struct Node {
        end: bool,
        children: std::collections::BTreeMap<u8, Node>,
    }
    fn insert(n: &mut Node, w: &[u8]) {
        match w.split_first() {
            None => n.end = true,
            Some((c, rest)) => insert(n.children.entry(*c).or_default(), rest),
        }
    }
    // Many alternatives are split in two by their first letter, a range test
    // choosing the half (pest tries alternatives in order: a word starting
    // with `s` would otherwise be compared with every letter before it).
    fn choice(alts: &[(u8, String)]) -> String {
        if alts.len() <= 4 {
            return alts
                .iter()
                .map(|(_, a)| a.as_str())
                .collect::<Vec<_>>()
                .join(" | ");
        }
        let (left, right) = alts.split_at(alts.len() / 2);
        let range = format!(
            "'{}'..'{}'",
            left[0].0 as char,
            left[left.len() - 1].0 as char
        );
        format!(
            "&({range}) ~ ({}) | !({range}) ~ ({})",
            choice(left),
            choice(right)
        )
    }
    // One alternative per child, each a run of letters as long as the trie
    // does not branch; the word ending here comes last.
    fn alternatives(n: &Node, out: &mut String) {
        let mut alts = Vec::new();
        for (c, child) in &n.children {
            let mut label = vec![*c];
            let mut node = child;
            while !node.end && node.children.len() == 1 {
                let (c, next) = node.children.iter().next().expect("one child");
                label.push(*c);
                node = next;
            }
            let mut alt = format!("\"{}\"", String::from_utf8_lossy(&label));
            if node.children.is_empty() {
                alt.push_str(" ~ !ident_char");
            } else {
                let mut inner = String::new();
                alternatives(node, &mut inner);
                alt.push_str(&format!(" ~ ({inner})"));
            }
            alts.push((*c, alt));
        }
        out.push_str(&choice(&alts));
        if n.end {
            out.push_str(" | !ident_char");
        }
    }
    let mut root = Node::default();
    for w in words {
        insert(&mut root, w.as_bytes());
    }
    let mut body = String::new();
    alternatives(&root, &mut body);
    format!("&ASCII_ALPHA_LOWER ~ ({body})")
}

/// `grammar/keywords.pest`: the grammar's word rules generated from the tables
/// above as tries. `keyword_word` is [`KEYWORDS`]; `colour_kw` and
/// `colour_part_kw` are [`COLOUR_WORDS`] and [`COLOUR_PART_WORDS`];
/// `reserved_word`, every word a name may not be (those and `array`), lets
/// `ident_name` reject a reserved word with one walk down one trie.
pub fn keyword_grammar() -> String {
    let mut reserved: Vec<&str> = KEYWORDS
        .iter()
        .chain(COLOUR_WORDS)
        .chain(COLOUR_PART_WORDS)
        .copied()
        .chain(["array"])
        .collect();
    reserved.sort_unstable();
    reserved.dedup();
    format!(
        "// Generated from `src/syntax/keywords.rs` (`KEYWORDS`, `COLOUR_WORDS`,\n\
         // `COLOUR_PART_WORDS`) by `keyword_grammar()`: do not edit. After changing a\n\
         // table, run `RTS_BLESS=1 cargo test --lib keyword_grammar` to write it again.\n\n\
         /// The reserved keywords (those that are not values or functions), as a trie.\n\
         keyword_word = @{{ {} }}\n\
         /// The colour keywords (`rgb`, `color`, …).\n\
         colour_kw = @{{ {} }}\n\
         /// A colour component keyword (`red 0.5`, `filter 0.2`, …).\n\
         colour_part_kw = @{{ {} }}\n\
         /// Every word a name may not be: the keywords, the colour words and `array`.\n\
         reserved_word = _{{ {} }}\n",
        trie(KEYWORDS),
        trie(COLOUR_WORDS),
        trie(COLOUR_PART_WORDS),
        trie(&reserved),
    )
}

#[cfg(test)]
mod tests {
    use super::{keyword_grammar, COLOUR_PART_WORDS, COLOUR_WORDS, KEYWORDS};

    #[test]
    fn keyword_grammar_is_generated_from_the_table() {
        for table in [KEYWORDS, COLOUR_WORDS, COLOUR_PART_WORDS] {
            assert!(table.windows(2).all(|w| w[0] < w[1]), "sorted, no repeats");
        }
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/grammar/keywords.pest");
        let want = keyword_grammar();
        if std::env::var_os("RTS_BLESS").is_some() {
            std::fs::write(path, &want).expect("write grammar/keywords.pest");
        }
        let have = std::fs::read_to_string(path).unwrap_or_default();
        assert!(
            have == want,
            "grammar/keywords.pest is not what KEYWORDS gives: run `RTS_BLESS=1 cargo test --lib keyword_grammar`"
        );
    }
}
