//! Render checks of warps and of the geometric and fractal patterns: a plane
//! facing an orthographic camera, lit by ambient only, shows each pattern's value
//! as grey (0 black, 1 white), so pixels can be checked against the formulas.

use std::path::PathBuf;
use std::process::Command;

/// Renders the plane z = 0 with `pigment` on an 8×8 orthographic view of
/// x, y in [-2, 2] and returns the grey value (red channel) of each pixel, row 0
/// at the top; pixel (i, j) sees x = -1.75 + 0.5 i, y = 1.75 - 0.5 j.
fn grey(name: &str, pigment: &str) -> Vec<Vec<f64>> {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("render_warps");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let src = dir.join(format!("{name}.rts"));
    let out = dir.join(format!("{name}.png"));
    let scene = format!(
        "global_settings {{ assumed_gamma 1.0 }}\n\
         camera {{ orthographic location <0, 0, -10> look_at 0 right x*4 up y*4 }}\n\
         plane {{ z, 0 pigment {{ {pigment} }} finish {{ ambient 1 diffuse 0 }} }}\n"
    );
    std::fs::write(&src, scene).expect("write scene");
    let status = Command::new(env!("CARGO_BIN_EXE_rts"))
        .arg("render")
        .arg(&src)
        .arg("-o")
        .arg(&out)
        .args(["-W", "8", "-H", "8", "-q"])
        .args(["--gamma", "1.0", "--bit-depth", "16"])
        .status()
        .expect("run rts");
    assert!(status.success(), "render {name}");
    let img = image::open(&out).expect("read png").to_rgb16();
    (0..8)
        .map(|j| {
            (0..8)
                .map(|i| f64::from(img.get_pixel(i, j)[0]) / 65535.0)
                .collect()
        })
        .collect()
}

const GREY: &str = "color_map { [0 rgb 0] [1 rgb 1] }";

fn x_of(i: usize) -> f64 {
    -1.75 + 0.5 * i as f64
}

fn y_of(j: usize) -> f64 {
    1.75 - 0.5 * j as f64
}

#[test]
fn repeat_warp_is_periodic_with_its_width() {
    // The gradient (one unit every 4) is folded into [0, 2) along x: every
    // pixel shows (x mod 2) / 4, so pixels 2 apart (4 pixels) agree exactly.
    let g = grey(
        "repeat",
        &format!("gradient x {GREY} scale 4 warp {{ repeat x*2 }}"),
    );
    for row in &g {
        for i in 0..8 {
            let want = x_of(i).rem_euclid(2.0) / 4.0;
            assert!(
                (row[i] - want).abs() < 2e-4,
                "pixel {i}: {} vs {want}",
                row[i]
            );
            if i + 4 < 8 {
                assert_eq!(row[i], row[i + 4]);
            }
        }
    }
}

#[test]
fn repeat_flip_mirrors_odd_copies() {
    let g = grey(
        "repeat_flip",
        &format!("gradient x {GREY} scale 4 warp {{ repeat x*2 flip x }}"),
    );
    for (i, &got) in g[3].iter().enumerate() {
        let x = x_of(i);
        let block = (x / 2.0).floor();
        let r = x - 2.0 * block;
        let want = if block.rem_euclid(2.0) == 1.0 {
            2.0 - r
        } else {
            r
        } / 4.0;
        assert!((got - want).abs() < 2e-4, "pixel {i}: {got} vs {want}");
    }
}

#[test]
fn planar_spherical_and_boxed_values() {
    let planar = grey("planar", &format!("planar {GREY}"));
    let spherical = grey("spherical", &format!("spherical {GREY}"));
    let boxed = grey("boxed", &format!("boxed {GREY}"));
    for j in 0..8 {
        for i in 0..8 {
            let (x, y) = (x_of(i), y_of(j));
            let p = 1.0 - y.abs().min(1.0);
            let s = 1.0 - (x * x + y * y).sqrt().min(1.0);
            let b = 1.0 - x.abs().max(y.abs()).min(1.0);
            assert!((planar[j][i] - p).abs() < 2e-4, "planar at {x}, {y}");
            assert!((spherical[j][i] - s).abs() < 2e-4, "spherical at {x}, {y}");
            assert!((boxed[j][i] - b).abs() < 2e-4, "boxed at {x}, {y}");
        }
    }
}

#[test]
fn mandel_is_the_interior_value_inside_and_the_count_outside() {
    let g = grey("mandel", &format!("mandel 20 {GREY}"));
    // (-0.25, 0.25) is inside the set: the interior value, 1 (white).
    assert!((g[3][3] - 1.0).abs() < 2e-4, "{}", g[3][3]);
    // (1.75, 1.75) escapes at the first iteration: 0.
    assert!(g[0][7] < 2e-4, "{}", g[0][7]);
    // (0.75, 0.25): z = c, then c² + c = (1.25, 0.625), then past the bailout
    // at the second iteration: count 1 of 20.
    assert!((g[3][5] - 0.05).abs() < 2e-4, "{}", g[3][5]);
}

#[test]
fn black_hole_pulls_the_pattern_in() {
    // Onion distance scaled by 4; the hole doubles distances near its centre
    // (strength 1 caps the pull at twice the distance).
    let g = grey(
        "black_hole",
        &format!("onion {GREY} scale 4 warp {{ black_hole 0, 1.5 strength 4 }}"),
    );
    let (x, y) = (x_of(4), y_of(3));
    let r = (x * x + y * y).sqrt();
    let k = (4.0 * (1.0 - r / 1.5f64).powi(2)).min(1.0);
    assert!((g[3][4] - r * (1.0 + k) / 4.0).abs() < 2e-4, "{}", g[3][4]);
    // Outside the radius nothing moves.
    let r = (x_of(0).powi(2) + y_of(0).powi(2)).sqrt();
    assert!((g[0][0] - r / 4.0).abs() < 2e-4);
}

#[test]
fn warp_after_a_transform_acts_in_the_transformed_space() {
    // `scale 4 warp { repeat x*2 }` repeats every 2 world units, while
    // `warp { repeat x*2 } scale 4` repeats every 8 (the scale moves the warp).
    let before = grey(
        "warp_then_scale",
        &format!("gradient x {GREY} warp {{ repeat x*0.5 }} scale 4"),
    );
    for i in 0..4 {
        assert_eq!(before[2][i], before[2][i + 4]);
        let want = (x_of(i) / 4.0).rem_euclid(0.5);
        assert!(
            (before[2][i] - want).abs() < 2e-4,
            "{} vs {want}",
            before[2][i]
        );
    }
}
