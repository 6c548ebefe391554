//! Analytic render checks of textures: transparency (filter and transmit),
//! filtered shadows, layered textures and a pattern's values across the image.

use std::path::PathBuf;
use std::process::Command;

/// Renders `scene` at `w`×`h` with linear output and returns its pixels in 0..1.
fn render(name: &str, scene: &str, w: u32, h: u32) -> (u32, Vec<[f64; 3]>) {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("render_textures");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let src = dir.join(format!("{name}.rts"));
    let out = dir.join(format!("{name}.png"));
    std::fs::write(&src, scene).expect("write scene");
    let status = Command::new(env!("CARGO_BIN_EXE_rts"))
        .arg("render")
        .arg(&src)
        .arg("-o")
        .arg(&out)
        .args(["-W", &w.to_string(), "-H", &h.to_string(), "-q"])
        .args(["--gamma", "1.0", "--bit-depth", "16"])
        .status()
        .expect("run rts");
    assert!(status.success(), "render {name}");
    let img = image::open(&out).expect("read png").to_rgb16();
    let px = img
        .pixels()
        .map(|p| [0, 1, 2].map(|i| f64::from(p[i]) / 65535.0))
        .collect();
    (w, px)
}

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() <= tol)
}

const CAMERA: &str = "global_settings { assumed_gamma 1.0 }\n\
    camera { location <0, 0, -10> direction z*10 right x*4 up y*4 }\n\
    light_source { <0, 0, -100> rgb 1 }\n";

#[test]
fn filter_and_transmit_let_light_through() {
    // A white backdrop seen through a red filtering sheet (left) and a half
    // transmitting blue sheet (right).
    let scene = format!(
        "{CAMERA}plane {{ z, 5 pigment {{ rgb 1 }} finish {{ ambient 1 diffuse 0 }} }}\n\
         box {{ <-2, -2, -1>, <0, 2, -0.9> pigment {{ rgbf <1, 0, 0, 1> }} finish {{ ambient 1 diffuse 0 }} }}\n\
         box {{ <0, -2, -1>, <2, 2, -0.9> pigment {{ rgbt <0, 0, 1, 0.5> }} finish {{ ambient 1 diffuse 0 }} }}\n"
    );
    let (w, px) = render("transparency", &scene, 8, 8);
    let at = |x: u32, y: u32| px[(y * w + x) as usize];
    // Full filter: the colour passes tinted, the surface itself adds nothing.
    assert!(close(at(1, 4), [1.0, 0.0, 0.0], 1e-3), "{:?}", at(1, 4));
    // Transmit 0.5 on both faces of the box: half the surface colour plus half
    // of (half the colour plus half the backdrop).
    assert!(close(at(6, 4), [0.25, 0.25, 1.0], 1e-3), "{:?}", at(6, 4));
}

#[test]
fn shadows_through_filtering_surfaces_are_coloured() {
    // A floor lit straight from above through a green filter sheet.
    let scene = "global_settings { assumed_gamma 1.0 }\n\
        camera { location <0, 10, 0> direction y*-10 right x*2 up z*2 }\n\
        light_source { <0, 100, 0> rgb 1 }\n\
        plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
        box { <-50, 5, -50>, <50, 5.1, 50> pigment { rgbf <0.2, 1, 0.2, 1> } finish { ambient 0 diffuse 0 } no_image }\n";
    let (w, px) = render("filtered_shadow", scene, 4, 4);
    let c = px[(2 * w + 2) as usize];
    // Light through the sheet: filter · colour = (0.2, 1, 0.2), crossed twice
    // (two faces of the box): (0.04, 1, 0.04).
    assert!(close(c, [0.04, 1.0, 0.04], 2e-3), "{c:?}");
}

#[test]
fn layered_texture_shows_the_lower_layer_through_clear_parts() {
    let scene = format!(
        "{CAMERA}plane {{ z, 0\n\
           texture {{ pigment {{ rgb <0, 0, 1> }} finish {{ ambient 1 diffuse 0 }} }}\n\
           texture {{ pigment {{ gradient x color_map {{ [0.5 rgbt <1, 0, 0, 0>] [0.5 rgbt <1, 1, 1, 1>] }} }} finish {{ ambient 1 diffuse 0 }} }}\n\
         }}\n"
    );
    let (w, px) = render("layers", &scene, 8, 8);
    // x in [0, 0.5): red top layer; x in [0.5, 1): clear, so the blue layer below.
    let red = px[(4 * w + 4) as usize]; // x ≈ 0.25
    let blue = px[(4 * w + 5) as usize]; // x ≈ 0.75
    assert!(close(red, [1.0, 0.0, 0.0], 1e-3), "{red:?}");
    assert!(close(blue, [0.0, 0.0, 1.0], 1e-3), "{blue:?}");
}

#[test]
fn gradient_values_follow_x() {
    let scene = format!(
        "{CAMERA}plane {{ z, 0 pigment {{ gradient x scale 4 translate -2*x }} finish {{ ambient 1 diffuse 0 }} }}\n"
    );
    let (w, px) = render("gradient", &scene, 16, 2);
    for i in 0..w {
        // Pixel centre x = -2 + (i + 0.5) / 4, value (x + 2) / 4.
        let want = (f64::from(i) + 0.5) / 16.0;
        assert!(
            (px[i as usize][0] - want).abs() < 1e-3,
            "{i}: {:?}",
            px[i as usize]
        );
    }
}
