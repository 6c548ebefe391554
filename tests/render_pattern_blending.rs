//! Analytic render checks of pattern blending: `average`, `pigment_pattern`,
//! `image_pattern`, `slope`, `normal_map`, `slope_map`, `bump_map`,
//! `material_map` and `interior_texture`.

mod render_support;

use std::path::PathBuf;

fn dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("render_pattern_blending");
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// Renders `scene` at `w`×`h` with linear output and returns its pixels in 0..1.
fn render(name: &str, scene: &str, w: u32, h: u32) -> Vec<[f64; 3]> {
    render_support::render_source("render_pattern_blending", name, scene, w, h)
}

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() <= tol)
}

/// A camera looking at the unit square of the x-y plane (z = 0) from -z, and
/// a finish that shows the pigment as it is.
const CAMERA: &str = "global_settings { assumed_gamma 1.0 }\n\
    camera { orthographic location <0.5, 0.5, -5> look_at <0.5, 0.5, 0> right x up y }\n\
    #declare Flat = finish { ambient 1 diffuse 0 }\n";

/// A plane facing the camera with `pigment`.
fn plane(pigment: &str) -> String {
    format!("{CAMERA}plane {{ -z, 0 pigment {{ {pigment} }} finish {{ Flat }} }}\n")
}

#[test]
fn average_weighs_its_pigments() {
    let px = render(
        "average",
        &plane("average pigment_map { [1 rgb <1, 0, 0>] [3 rgb <0, 0, 1>] }"),
        4,
        4,
    );
    for p in &px {
        assert!(close(*p, [0.25, 0.0, 0.75], 1e-3), "{p:?}");
    }
    // A weight left out counts 1.
    let px = render(
        "average_default",
        &plane("average pigment_map { [rgb <1, 0, 0>] [rgb <0, 1, 0>] }"),
        2,
        2,
    );
    assert!(close(px[0], [0.5, 0.5, 0.0], 1e-3), "{:?}", px[0]);
}

#[test]
fn pigment_pattern_is_the_grey_value() {
    // A solid pigment is a constant pattern: its grey value picks one colour
    // of the map everywhere (0.297 red + 0.589 green + 0.114 blue).
    let px = render(
        "pigment_pattern",
        &plane("pigment_pattern { rgb <1, 0.5, 0> } color_map { [0 rgb 0] [1 rgb <1, 1, 0>] }"),
        4,
        4,
    );
    let g = 0.297 + 0.589 * 0.5;
    for p in &px {
        assert!(close(*p, [g, g, 0.0], 1e-3), "{p:?}");
    }
    // A checker of black and white gives values 0 and 1: the map's ends.
    let px = render(
        "pigment_pattern_checker",
        &plane(
            "pigment_pattern { checker rgb 0, rgb 1 scale 0.5 } color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }",
        ),
        4,
        4,
    );
    assert!(close(px[12], [1.0, 0.0, 0.0], 1e-3), "{:?}", px[12]);
    assert!(close(px[14], [0.0, 0.0, 1.0], 1e-3), "{:?}", px[14]);
}

#[test]
fn image_pattern_reads_grey_and_material_map_chooses_textures() {
    // 2×1 grey image: black on the left, grey 0.4 on the right (8 bit: 102).
    let img = image::GrayImage::from_raw(2, 1, vec![0, 102]).expect("image");
    img.save(dir().join("two.png")).expect("save");
    let px = render(
        "image_pattern",
        &plane("image_pattern { png \"two.png\" } color_map { [0 rgb 0] [1 rgb <0, 1, 1>] }"),
        4,
        2,
    );
    assert!(close(px[0], [0.0, 0.0, 0.0], 1e-3), "{:?}", px[0]);
    assert!(close(px[3], [0.0, 0.4, 0.4], 1e-3), "{:?}", px[3]);
    // Without a palette, grey × 255 is the index: 0 and 1.
    let idx = image::GrayImage::from_raw(2, 1, vec![0, 1]).expect("image");
    idx.save(dir().join("index.png")).expect("save");
    let scene = format!(
        "{CAMERA}plane {{ -z, 0 texture {{ material_map {{ png \"index.png\" \
         texture {{ pigment {{ rgb <1, 0, 0> }} finish {{ Flat }} }} \
         texture {{ pigment {{ rgb <0, 1, 0> }} finish {{ Flat }} }} }} }} }}\n"
    );
    let px = render("material_map", &scene, 4, 2);
    assert!(close(px[0], [1.0, 0.0, 0.0], 1e-3), "{:?}", px[0]);
    assert!(close(px[3], [0.0, 1.0, 0.0], 1e-3), "{:?}", px[3]);
}

#[test]
fn slope_is_linear_in_the_angle_and_mixes_altitude() {
    // The plane faces -z: 1 for `slope { -z }`, 0.5 for `slope { y }`.
    let map = "color_map { [0 rgb 0] [1 rgb 1] }";
    let px = render(
        "slope_facing",
        &plane(&format!("slope {{ -z }} {map}")),
        2,
        2,
    );
    assert!(close(px[0], [1.0; 3], 1e-3), "{:?}", px[0]);
    let px = render(
        "slope_across",
        &plane(&format!("slope {{ y }} {map}")),
        2,
        2,
    );
    assert!(close(px[0], [0.5; 3], 1e-3), "{:?}", px[0]);
    // Equal weights: half the slope (0.5) and half the height along y.
    let px = render(
        "slope_altitude",
        &plane(&format!("slope {{ y altitude y }} {map}")),
        1,
        4,
    );
    let top = 0.5 * 0.5 + 0.5 * 0.875;
    assert!(close(px[0], [top; 3], 1e-3), "{:?}", px[0]);
}

#[test]
fn flat_normal_blends_leave_the_surface_flat() {
    // Lit head-on, a flat plane shows its diffuse colour; normals that average
    // or blend flat entries, and a slope map of constant height, keep it so.
    let lit = "global_settings { assumed_gamma 1.0 }\n\
        camera { orthographic location <0.5, 0.5, -5> look_at <0.5, 0.5, 0> right x up y }\n\
        light_source { <0.5, 0.5, -1000> rgb 1 }\n";
    let flat = render(
        "normal_none",
        &format!("{lit}plane {{ -z, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}\n"),
        4,
        4,
    );
    for (name, normal) in [
        (
            "normal_average",
            "average normal_map { [1 gradient x 0] [2 bumps 0] }",
        ),
        (
            "normal_map",
            "gradient x normal_map { [0 bumps 0] [1 dents 0] }",
        ),
        (
            "slope_map",
            "gradient x 1 slope_map { [0 <0.5, 0>] [1 <0.5, 0>] }",
        ),
        (
            "normal_list",
            "checker normal { bumps 0 } normal { dents 0 }",
        ),
    ] {
        let px = render(
            name,
            &format!(
                "{lit}plane {{ -z, 0 pigment {{ rgb 1 }} normal {{ {normal} }} finish {{ ambient 0 diffuse 1 }} }}\n"
            ),
            4,
            4,
        );
        for (a, b) in px.iter().zip(&flat) {
            assert!(close(*a, *b, 1e-3), "{name}: {a:?} vs {b:?}");
        }
    }
    // A slope map that rises tilts the normal: the plane darkens.
    let px = render(
        "slope_map_tilts",
        &format!(
            "{lit}plane {{ -z, 0 pigment {{ rgb 1 }} normal {{ gradient x 1 slope_map {{ [0 <0, 1>] [1 <1, 1>] }} }} finish {{ ambient 0 diffuse 1 }} }}\n"
        ),
        4,
        4,
    );
    assert!(
        px[5][0] < flat[5][0] - 0.005,
        "{:?} vs {:?}",
        px[5],
        flat[5]
    );
}

#[test]
fn bump_map_outlines_steps() {
    // A 4×1 image with one step: the pixels on the step lean, the flat ones do not.
    let img = image::GrayImage::from_raw(4, 1, vec![0, 0, 255, 255]).expect("image");
    img.save(dir().join("step.png")).expect("save");
    let lit = "global_settings { assumed_gamma 1.0 }\n\
        camera { orthographic location <0.5, 0.5, -5> look_at <0.5, 0.5, 0> right x up y }\n\
        light_source { <0.5, 0.5, -1000> rgb 1 }\n";
    let px = render(
        "bump_map",
        &format!(
            "{lit}plane {{ -z, 0 pigment {{ rgb 1 }} normal {{ bump_map {{ png \"step.png\" bump_size 2 }} }} finish {{ ambient 0 diffuse 1 }} }}\n"
        ),
        16,
        1,
    );
    // Nearest pixels: flat inside each half.
    assert!(close(px[2], [1.0; 3], 1e-3), "{:?}", px[2]);
    assert!(close(px[13], [1.0; 3], 1e-3), "{:?}", px[13]);
}

#[test]
fn interior_texture_shows_from_inside() {
    // The camera inside a sphere sees its interior texture; one outside sees
    // the outer texture.
    let sphere =
        "sphere { 0, 1 texture { pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } } \
        interior_texture { pigment { rgb <0, 1, 0> } finish { ambient 1 diffuse 0 } } }\n";
    let inside = render(
        "interior_inside",
        &format!(
            "global_settings {{ assumed_gamma 1.0 }}\ncamera {{ location 0 look_at z }}\n{sphere}"
        ),
        2,
        2,
    );
    assert!(close(inside[0], [0.0, 1.0, 0.0], 1e-3), "{:?}", inside[0]);
    let outside = render(
        "interior_outside",
        &format!(
            "global_settings {{ assumed_gamma 1.0 }}\ncamera {{ location -5*z look_at 0 angle 5 }}\n{sphere}"
        ),
        2,
        2,
    );
    assert!(close(outside[0], [1.0, 0.0, 0.0], 1e-3), "{:?}", outside[0]);
}
