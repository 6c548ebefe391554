//! Photons: caustic brightness measured on POV-Ray 3.7 (a flat mirror sends
//! the light's colour on at any distance; at 45° the cosine), a glass lens
//! focuses light into its shadow, the switches that turn photons off, `count`,
//! and the same bytes for any number of threads.

mod render_support;

use render_support::render_source;

/// A floor at height `floor` lit by a light of colour 0.5 at <-10, 2, 0>; a
/// square mirror at height 2 turned `tilt` degrees reflects the light down
/// onto it; the camera looks at `look` (the middle of the reflected spot).
fn mirror_scene(floor: f64, tilt: f64, look: [f64; 3], extra: &str) -> String {
    let [x, y, z] = look;
    format!(
        "#version 3.7;
global_settings {{ assumed_gamma 1.0 photons {{ spacing 0.005 }} }}
camera {{ location <{x}, {}, {}> look_at <{x}, {y}, {z}> angle 30 }}
light_source {{ <-10, 2, 0> color rgb 0.5 }}
plane {{ y, {floor} pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} {extra} }}
box {{ <-0.5, -0.01, -0.5>, <0.5, 0, 0.5> rotate z*-{tilt} translate y*2
  pigment {{ rgb 0 }} finish {{ ambient 0 diffuse 0 reflection 1 }}
  photons {{ target reflection on collect off }} }}",
        y + 6.0,
        z - 8.0
    )
}

fn middle(px: &[[f64; 3]], w: usize, h: usize) -> f64 {
    px[(h / 2) * w + w / 2][0]
}

#[test]
fn a_flat_mirror_sends_on_the_lights_colour_at_any_distance() {
    // POV-Ray 3.7 (200x200, same scene): 0.596 to 0.61 at the spot on the near
    // floor, 0.885 on the far one; direct light alone 0.098 and 0.384.
    for (floor, want) in [(0.0, 0.598), (-10.0, 0.884)] {
        let px = render_source(
            "photons",
            &format!("mirror{floor}"),
            &mirror_scene(floor, 45.0, [0.0, floor, 0.0], ""),
            60,
            60,
        );
        let got = middle(&px, 60, 60);
        assert!((got - want).abs() < 0.03, "floor {floor}: {got} vs {want}");
    }
}

#[test]
fn light_reflected_at_45_degrees_adds_its_colour_times_the_cosine() {
    // POV-Ray 3.7: 0.431 to 0.443 (direct 0.082 + 0.5 · cos 45°).
    let px = render_source(
        "photons",
        "mirror45",
        &mirror_scene(0.0, 22.5, [2.0, 0.0, 0.0], ""),
        60,
        60,
    );
    let got = middle(&px, 60, 60);
    assert!((got - 0.436).abs() < 0.03, "{got}");
}

#[test]
fn collect_off_keeps_the_floor_free_of_photons() {
    let px = render_source(
        "photons",
        "nocollect",
        &mirror_scene(0.0, 45.0, [0.0, 0.0, 0.0], "photons { collect off }"),
        60,
        60,
    );
    let got = middle(&px, 60, 60);
    assert!((got - 0.098).abs() < 0.01, "{got}");
}

/// A clear glass ball above a white floor, lit from straight above.
fn lens_scene(light: &str, global: &str) -> String {
    format!(
        "#version 3.7;
global_settings {{ assumed_gamma 1.0 {global} }}
camera {{ location <0, 3, -8> look_at <0, 0, 0> angle 40 }}
light_source {{ <0, 10, 0> color rgb 0.5 {light} }}
plane {{ y, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}
sphere {{ <0, 2, 0>, 1 pigment {{ rgbf 1 }} finish {{ ambient 0 diffuse 0 }}
  interior {{ ior 1.5 }}
  photons {{ target refraction on reflection on collect off }} }}"
    )
}

#[test]
fn a_glass_ball_focuses_light_into_its_shadow() {
    let (w, h) = (60u32, 60u32);
    let at = |px: &[[f64; 3]], dx: u32| px[((h / 2) * w + w / 2 + dx) as usize][0];
    let lens = render_source(
        "photons",
        "lens",
        &lens_scene("", "photons { spacing 0.01 }"),
        w,
        h,
    );
    // A light whose photons do not refract: no caustic, and the clear ball
    // lets the light through as a filtered shadow.
    let plain = render_source(
        "photons",
        "lens_off",
        &lens_scene("photons { refraction off }", "photons { spacing 0.01 }"),
        w,
        h,
    );
    // Under the ball the focused light is several times the direct light; at
    // the rim of its shadow (0.8 units out) darker than it (the light through
    // the ball's edge is bent inwards); far from the ball the same.
    assert!(at(&plain, 0) > 0.45, "direct {}", at(&plain, 0));
    assert!(
        at(&lens, 0) > 2.0 * at(&plain, 0),
        "caustic {}",
        at(&lens, 0)
    );
    assert!(
        at(&lens, 8) < 0.5 * at(&plain, 8),
        "shadow rim {}",
        at(&lens, 8)
    );
    assert!((at(&lens, 28) - at(&plain, 28)).abs() < 0.01);
    // Without photons at all, likewise.
    let none = render_source("photons", "lens_none", &lens_scene("", ""), w, h);
    assert_eq!(plain, none);
}

#[test]
fn photons_are_the_same_for_any_number_of_threads_and_count_sets_their_number() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("photons");
    std::fs::create_dir_all(&dir).unwrap();
    let src = dir.join("threads.rts");
    std::fs::write(&src, lens_scene("", "photons { count 30000 }")).unwrap();
    let render = |threads: &str| {
        let out = dir.join(format!("threads_{threads}.png"));
        let stats = dir.join(format!("threads_{threads}.json"));
        let status = std::process::Command::new(env!("CARGO_BIN_EXE_rts"))
            .arg("render")
            .arg(&src)
            .arg("-o")
            .arg(&out)
            .args(["-W", "40", "-H", "40", "-q", "--threads", threads])
            .arg("--stats-json")
            .arg(&stats)
            .status()
            .unwrap();
        assert!(status.success());
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
        (std::fs::read(&out).unwrap(), json["photons"].clone())
    };
    let (one, photons) = render("1");
    let (two, photons2) = render("2");
    assert_eq!(one, two, "same bytes on 1 and 2 threads");
    assert_eq!(photons, photons2);
    let shot = photons["shot"].as_u64().unwrap();
    assert!((30_000..=30_500).contains(&shot), "{shot} shot");
    assert!(photons["stored"].as_u64().unwrap() > 5_000, "{photons}");
}

#[test]
fn a_photons_block_without_spacing_or_count_warns_and_shoots_nothing() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("photons");
    std::fs::create_dir_all(&dir).unwrap();
    let src = dir.join("empty.rts");
    std::fs::write(&src, lens_scene("", "photons { }")).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rts"))
        .arg("check")
        .arg(&src)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stderr);
    assert!(text.contains("neither `spacing` nor `count`"), "{text}");
    // The ball still shadows the light fully (its light would be photons).
    let px = render_source("photons", "empty", &lens_scene("", "photons { }"), 60, 60);
    assert!(middle(&px, 60, 60) < 0.05, "{}", middle(&px, 60, 60));
}

#[test]
fn glass_that_reflects_and_passes_all_light_still_finishes() {
    // Without conserve_energy a Fresnel glass reflects up to all the light
    // and passes all of it too: every photon would split without end over
    // 25 levels; the walk per photon is bounded, with conserve_energy the
    // split light decays.
    for conserve in ["", "conserve_energy"] {
        let scene = format!(
            "#version 3.7;
global_settings {{ assumed_gamma 1.0 max_trace_level 25 photons {{ count 3000 }} }}
camera {{ location <0, 3, -6> look_at <0, 1, 0> }}
light_source {{ <-5, 8, -3> rgb 1 }}
plane {{ y, 0 pigment {{ rgb 1 }} }}
cylinder {{ <0, 0.01, 0>, <0, 2.5, 0>, 1 pigment {{ rgbt 1 }}
  finish {{ diffuse 0.05 reflection {{ 0.1, 1.0 fresnel on }} {conserve} }}
  interior {{ ior 1.5 }} photons {{ target refraction on reflection on }} }}"
        );
        let px = render_source("photons", "fresnel_glass", &scene, 30, 20);
        assert!(px.iter().all(|p| p.iter().all(|c| c.is_finite())));
    }
}
