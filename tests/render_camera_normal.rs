//! Camera ray perturbation (`camera { normal { … } }`) and the slope of normal
//! patterns, against numbers measured on POV-Ray 3.7.

mod render_support;

/// A backdrop at z = 10 whose red channel is (x + 20) / 40 and green (y + 20) /
/// 40: a pixel tells where its ray landed.
const BACKDROP: &str = "global_settings { assumed_gamma 1.0 }\n\
    plane { z, 10 pigment { average pigment_map {\n\
    [1 gradient x color_map { [0 rgb 0] [1 rgb <2, 0, 0>] } scale 40 translate -20*x]\n\
    [1 gradient y color_map { [0 rgb 0] [1 rgb <0, 2, 0>] } scale 40 translate -20*y] } }\n\
    finish { ambient 1 diffuse 0 } }\n";

#[test]
fn a_camera_normal_leans_every_ray_by_its_world_slope() {
    // POV-Ray 3.7 (measured, 16 × 16): `normal { gradient x 0.5 }` adds -x/15 to
    // each unit direction before normalising, under any camera orientation.
    for (name, rotate) in [("plain", ""), ("rolled", "rotate z*30")] {
        let scene = format!(
            "{BACKDROP}camera {{ direction z right x up y {rotate} normal {{ gradient x 0.5 }} }}\n"
        );
        let px = render_support::render_source("render_camera_normal", name, &scene, 16, 16);
        let roll = if rotate.is_empty() {
            0.0
        } else {
            30f64.to_radians()
        };
        for (k, p) in px.iter().enumerate() {
            let (i, j) = ((k % 16) as f64, (k / 16) as f64);
            let (sx, sy) = ((i + 0.5) / 16.0 - 0.5, 0.5 - (j + 0.5) / 16.0);
            let (c, s) = (roll.cos(), roll.sin());
            let d = glam::DVec3::new(sx * c - sy * s, sx * s + sy * c, 1.0).normalize();
            let lean = d - glam::DVec3::X / 15.0;
            let want = (lean.x / lean.z * 10.0, lean.y / lean.z * 10.0);
            let got = (p[0] * 40.0 - 20.0, p[1] * 40.0 - 20.0);
            assert!(
                (got.0 - want.0).abs() < 0.01 && (got.1 - want.1).abs() < 0.01,
                "{name} pixel {k}: landed at {got:?}, want {want:?}"
            );
        }
    }
}

#[test]
fn a_gradient_normal_tilts_a_lit_plane_by_a_fifteenth() {
    // A white plane facing the camera, lit at 45 degrees from the left:
    // POV-Ray 3.7 shows 0.75259 of the light with `normal { gradient x 0.5 }`,
    // a tilt of exactly 1/15 towards the light.
    let scene = "global_settings { assumed_gamma 1.0 }\n\
        camera { orthographic location <0, 0, -5> look_at 0 right x*2 up y*2 }\n\
        light_source { <-100, 0, -100> rgb 1 parallel point_at 0 }\n\
        plane { z, 0 pigment { rgb 1 } normal { gradient x 0.5 } finish { ambient 0 diffuse 1 } }\n";
    let px = render_support::render_source("render_camera_normal", "gradient_tilt", scene, 4, 4);
    let n = glam::DVec3::new(-1.0 / 15.0, 0.0, -1.0).normalize();
    let want = n.dot(glam::DVec3::new(-1.0, 0.0, -1.0).normalize());
    assert!((px[5][0] - want).abs() < 1e-3, "{} want {want}", px[5][0]);
}
