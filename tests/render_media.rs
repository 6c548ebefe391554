//! Participating media, checked against what POV-Ray 3.7 defines: absorbing
//! media let `exp(-absorption · density · distance)` through, emitting media add
//! `emission · distance` (dimmed by their own extinction on the way), media act
//! only in hollow objects, several media add up, and pictures do not depend on
//! the number of threads.

use glam::DVec3;
use rts::build::build;
use rts::render::render_pixel;
use rts::scene::Scene;
use rts::source::SourceMap;
use std::process::Command;

fn scene(text: &str) -> Scene {
    let mut sources = SourceMap::new();
    let id = sources.add("test.rts", None, text.to_string());
    let (file, diags) = rts::syntax::parse(text, id);
    assert!(diags.is_empty(), "{diags:?}");
    let ev = rts::eval::eval(&file, id, &mut sources, &rts::eval::EvalOptions::default());
    assert!(
        ev.diagnostics
            .iter()
            .all(|d| d.severity != rts::diag::Severity::Error),
        "{:?}",
        ev.diagnostics
    );
    ev.scene
}

/// The centre pixel of `objects` seen from z = -5 looking along +z, over a
/// background of `bg`.
fn centre(bg: &str, objects: &str) -> DVec3 {
    let text =
        format!("camera {{ location <0, 0, -5> look_at 0 }}\nbackground {{ rgb {bg} }}\n{objects}");
    render_pixel(&build(&scene(&text)), 0, 0, 1, 1)
}

fn close(got: DVec3, want: DVec3, tol: f64) {
    assert!((got - want).abs().max_element() < tol, "{got} vs {want}");
}

fn exp(v: DVec3) -> DVec3 {
    DVec3::new(v.x.exp(), v.y.exp(), v.z.exp())
}

/// A transparent box one unit deep (z from -0.5 to 0.5) holding `media`.
fn slab(media: &str, hollow: bool) -> String {
    format!(
        "box {{ <-1, -1, -0.5>, <1, 1, 0.5> pigment {{ rgbt 1 }} {} interior {{ {media} }} }}",
        if hollow { "hollow" } else { "" }
    )
}

#[test]
fn absorption_lets_through_exp_of_minus_absorption_times_distance() {
    let a = DVec3::new(0.7, 1.4, 0.2);
    let got = centre("1", &slab("media { absorption <0.7, 1.4, 0.2> }", true));
    close(got, exp(-a), 1e-9);
    // Twice as deep: the square.
    let deep = "box { <-1, -1, -1>, <1, 1, 1> pigment { rgbt 1 } hollow \
                interior { media { absorption <0.7, 1.4, 0.2> } } }";
    close(centre("1", deep), exp(-2.0 * a), 1e-9);
    // A constant density scales the coefficients.
    let half = slab(
        "media { absorption <0.7, 1.4, 0.2> density { rgb 0.5 } }",
        true,
    );
    close(centre("1", &half), exp(-0.5 * a), 1e-9);
}

#[test]
fn several_media_in_one_interior_add_up() {
    let two = slab("media { absorption 0.3 } media { absorption 0.4 }", true);
    close(centre("1", &two), DVec3::splat((-0.7f64).exp()), 1e-9);
}

#[test]
fn media_needs_a_hollow_object() {
    // As in POV-Ray 3.7: in a solid object the media is not seen.
    close(
        centre("1", &slab("media { absorption 2 }", false)),
        DVec3::ONE,
        1e-12,
    );
}

#[test]
fn emission_adds_light_along_the_way() {
    // Emission only: e · d.
    let e = DVec3::new(0.3, 0.2, 0.1);
    close(
        centre("0", &slab("media { emission <0.3, 0.2, 0.1> }", true)),
        e,
        1e-9,
    );
    // With absorption a the glow is e / a · (1 - exp(-a d)), integrated by
    // method 3's samples to within a percent.
    let got = centre("0", &slab("media { emission 1 absorption 2 }", true));
    let want = (1.0 - (-2.0f64).exp()) / 2.0;
    close(got, DVec3::splat(want), 0.01 * want);
}

#[test]
fn atmospheric_media_fills_space_outside_solid_objects() {
    // A wall 5 units away lit only by its ambient 1 (its inside, z > 0, is
    // behind it: a camera inside a solid plane would see no media).
    let wall = "plane { -z, 0 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n";
    let got = centre("0", &format!("{wall}media {{ absorption 0.1 }}"));
    close(got, DVec3::splat((-0.5f64).exp()), 1e-9);
    // Inside a solid (not hollow) glass slab the atmosphere is kept out.
    let glass = "box { <-1, -1, -3>, <1, 1, -1> pigment { rgbt 1 } }\n";
    let got = centre("0", &format!("{wall}{glass}media {{ absorption 0.1 }}"));
    close(got, DVec3::splat((-0.3f64).exp()), 1e-9);
}

#[test]
fn scattering_lights_the_media_with_shadows() {
    // A beam of scattering media lit by a light above: brighter than the black
    // background; an opaque roof between the light and the media darkens it.
    let lit = "light_source { <0, 10, 0> rgb 1 }\n";
    let media = slab("media { scattering { 1, rgb 0.5 } }", true);
    let open = centre("0", &format!("{lit}{media}"));
    assert!(open.min_element() > 0.1, "{open}");
    // POV-Ray's isotropic scattering: light 1 · 0.5 per unit over one unit,
    // dimmed by the extinction on the way to the camera (0.5 per unit):
    // (1 - e^-0.5); the light itself crosses one unit of the media from the
    // box's top to the centre line: e^-0.5.
    let want = (-0.5f64).exp() * (1.0 - (-0.5f64).exp());
    close(open, DVec3::splat(want), 0.01 * want);
    let roof = "box { <-3, 3, -3>, <3, 3.1, 3> pigment { rgb 1 } }\n";
    let shut = centre("0", &format!("{lit}{roof}{media}"));
    close(shut, DVec3::ZERO, 1e-12);
    // `media_interaction off`: the light does not reach the media.
    let off = "light_source { <0, 10, 0> rgb 1 media_interaction off }\n";
    close(centre("0", &format!("{off}{media}")), DVec3::ZERO, 1e-12);
}

#[test]
fn same_picture_for_any_thread_count() {
    let dir = std::env::temp_dir().join(format!("rts_media_{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/media.rts");
    let mut bytes = Vec::new();
    for threads in ["1", "2"] {
        let out = dir.join(format!("t{threads}.png"));
        let status = Command::new(env!("CARGO_BIN_EXE_rts"))
            .args([
                "render",
                scene,
                "-W",
                "40",
                "-H",
                "30",
                "-q",
                "--threads",
                threads,
                "-o",
            ])
            .arg(&out)
            .status()
            .expect("run rts");
        assert!(status.success());
        bytes.push(std::fs::read(&out).expect("png"));
    }
    assert_eq!(bytes[0], bytes[1]);
    let _ = std::fs::remove_dir_all(&dir);
}
