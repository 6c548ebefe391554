//! Radiosity in the classic renderer: analytic levels measured on POV-Ray 3.7,
//! `no_radiosity`, and the same bytes for any number of threads.

mod render_support;

use render_support::render_source;

/// A grey plane seen from above under a white background, no lights: with
/// radiosity the plane shows `diffuse · colour` times the mean light of its
/// hemisphere (1), whatever `ambient` says in a 3.7 scene (measured on
/// POV-Ray 3.7: 0.3515 for diffuse 0.7, rgb 0.5, ambient 0.3).
fn plane_scene(version: &str, finish: &str, extra: &str) -> String {
    format!(
        "#version {version};
global_settings {{ assumed_gamma 1 radiosity {{ count 100 recursion_limit 1 }} }}
camera {{ location <0, 3, -5> look_at <0, 0, 0> }}
background {{ rgb 1 }}
plane {{ y, 0 pigment {{ rgb 0.5 }} finish {{ {finish} }} }}
{extra}"
    )
}

fn centre(px: &[[f64; 3]], w: usize, h: usize) -> f64 {
    px[(h * 5 / 6) * w + w / 2][1]
}

#[test]
fn a_plane_under_a_white_sky_shows_diffuse_times_colour() {
    let px = render_source(
        "radiosity",
        "plane37",
        &plane_scene("3.7", "ambient 0.3 diffuse 0.7", ""),
        40,
        30,
    );
    assert!(
        (centre(&px, 40, 30) - 0.35).abs() < 0.002,
        "{}",
        centre(&px, 40, 30)
    );
    // Emission still adds (0.2 · 0.5); in a 3.6 scene ambient does too.
    let px = render_source(
        "radiosity",
        "emission",
        &plane_scene("3.7", "ambient 0 diffuse 0.7 emission 0.2", ""),
        40,
        30,
    );
    assert!(
        (centre(&px, 40, 30) - 0.45).abs() < 0.002,
        "{}",
        centre(&px, 40, 30)
    );
    let px = render_source(
        "radiosity",
        "plane36",
        &plane_scene("3.6", "ambient 0.3 diffuse 0.7", ""),
        40,
        30,
    );
    assert!(
        (centre(&px, 40, 30) - 0.50).abs() < 0.002,
        "{}",
        centre(&px, 40, 30)
    );
}

#[test]
fn a_black_ceiling_darkens_unless_no_radiosity() {
    let ceiling = "box { <-100, 2, -100>, <100, 2.1, 100> pigment { rgb 0 } no_image";
    let dark = render_source(
        "radiosity",
        "ceiling",
        &plane_scene("3.7", "diffuse 0.7", &format!("{ceiling} }}")),
        40,
        30,
    );
    assert!(centre(&dark, 40, 30) < 0.05, "{}", centre(&dark, 40, 30));
    let open = render_source(
        "radiosity",
        "no_radiosity",
        &plane_scene("3.7", "diffuse 0.7", &format!("{ceiling} no_radiosity }}")),
        40,
        30,
    );
    assert!((centre(&open, 40, 30) - 0.35).abs() < 0.002);
}

#[test]
fn interreflection_lights_what_the_light_cannot_reach_and_is_thread_independent() {
    // A closed white room lit by one point light; a box hides part of the
    // floor from it. Without radiosity (ambient 0) that shadow is black.
    let scene = |rad: &str| {
        format!(
            "#version 3.7;
global_settings {{ assumed_gamma 1 {rad} }}
camera {{ location <0, 1.5, -2.9> look_at <0, 0.6, 0> angle 80 }}
light_source {{ <0, 2.8, 0> rgb 1 }}
#default {{ finish {{ ambient 0 diffuse 0.7 }} }}
box {{ <-3, 0, -3>, <3, 3, 3> pigment {{ rgb 0.8 }} hollow }}
box {{ <-1, 0, -1>, <1, 2.5, 1> pigment {{ rgb <0.8, 0.2, 0.2> }} translate <1.6, 0, 1> }}"
        )
    };
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("radiosity");
    std::fs::create_dir_all(&dir).unwrap();
    let src = dir.join("room.rts");
    std::fs::write(
        &src,
        scene("radiosity { count 50 pretrace_end 0.02 recursion_limit 2 }"),
    )
    .unwrap();
    let render = |threads: &str| {
        let out = dir.join(format!("room_{threads}.png"));
        let status = std::process::Command::new(env!("CARGO_BIN_EXE_rts"))
            .arg("render")
            .arg(&src)
            .arg("-o")
            .arg(&out)
            .args(["-W", "48", "-H", "36", "-q", "--threads", threads])
            .status()
            .unwrap();
        assert!(status.success());
        std::fs::read(&out).unwrap()
    };
    assert_eq!(render("1"), render("2"), "same bytes on 1 and 2 threads");
    let lit = render_source(
        "radiosity",
        "room_lit",
        &scene("radiosity { count 50 pretrace_end 0.02 recursion_limit 2 }"),
        48,
        36,
    );
    let plain = render_source("radiosity", "room_plain", &scene(""), 48, 36);
    let mean =
        |px: &[[f64; 3]]| px.iter().map(|p| p[0] + p[1] + p[2]).sum::<f64>() / px.len() as f64;
    assert!(
        mean(&lit) > mean(&plain) * 1.2,
        "{} vs {}",
        mean(&lit),
        mean(&plain)
    );
    let black = plain.iter().filter(|p| p[1] < 1e-4).count();
    let black_lit = lit.iter().filter(|p| p[1] < 1e-4).count();
    assert!(
        black > 0 && black_lit == 0,
        "{black} black pixels without radiosity, {black_lit} with"
    );
}

#[test]
fn rad_def_presets_expand_inside_the_radiosity_block() {
    let scene = |preset: &str| {
        format!(
            "#version 3.7;
#include \"rad_def.inc\"
global_settings {{ assumed_gamma 1 radiosity {{ Rad_Settings({preset}, off, off) }} }}
camera {{ location <0, 3, -5> look_at <0, 0, 0> }}
background {{ rgb 1 }}
plane {{ y, 0 pigment {{ rgb 0.5 }} finish {{ diffuse 0.7 }} }}"
        )
    };
    for preset in ["Radiosity_Default", "Radiosity_Debug", "Radiosity_IndoorHQ"] {
        let px = render_source("radiosity", preset, &scene(preset), 24, 18);
        let v = px[15 * 24 + 12][1];
        assert!((v - 0.35).abs() < 0.003, "{preset}: {v}");
    }
}
