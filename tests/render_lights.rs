//! Analytic checks of light sources: one ray straight down onto a white matte floor
//! (`diffuse 1`, no ambient) under one light, so the pixel is the light arriving.

mod render_support;

use glam::DVec3;
use render_support::*;
use rts::build::build;
use rts::render::{render_pixel, spot_attenuation};
use rts::scene::{AreaLight, Beam, Camera, Light, LightKind, Object};

/// The floor's brightness at the origin under `light`, with extra `objects`.
fn floor_under(light: Light, objects: Vec<Object>) -> DVec3 {
    let cam = Camera {
        location: DVec3::new(0.0, 10.0, 0.0),
        direction: -DVec3::Y,
        right: DVec3::X * 0.01,
        up: DVec3::Z * 0.01,
        ..Camera::default()
    };
    let floor = with_texture(plane(DVec3::Y, 0.0), texture(DVec3::ONE, matte(0.0, 1.0)));
    let mut all = vec![floor];
    all.extend(objects);
    let mut sc = scene(cam, all);
    sc.lights.push(light);
    render_pixel(&build(&sc), 0, 0, 1, 1)
}

fn assert_close(got: DVec3, want: f64) {
    assert!(
        (got - DVec3::splat(want)).abs().max_element() < 1e-9,
        "{got} vs {want}"
    );
}

#[test]
fn point_lights_do_not_fall_off_with_distance() {
    // POV-Ray's point light has no inverse-square law: near and far lights give the
    // same light to a surface facing them.
    assert_close(
        floor_under(point_light(DVec3::new(0.0, 2.0, 0.0)), vec![]),
        1.0,
    );
    assert_close(
        floor_under(point_light(DVec3::new(0.0, 200.0, 0.0)), vec![]),
        1.0,
    );
}

#[test]
fn fade_distance_and_power() {
    let light = Light {
        fade_distance: 2.0,
        fade_power: 2.0,
        ..point_light(DVec3::new(0.0, 4.0, 0.0))
    };
    // 2 / (1 + (4 / 2)²) = 0.4.
    assert_close(floor_under(light, vec![]), 0.4);
}

#[test]
fn spotlight_between_radius_and_falloff() {
    // The axis aims 35° away from the lit point: between radius 30 and falloff 45.
    let aim = DVec3::new(4.0 * 35f64.to_radians().tan(), 0.0, 0.0);
    let light = Light {
        kind: LightKind::Spot(Beam::SPOT),
        point_at: aim,
        ..point_light(DVec3::new(0.0, 4.0, 0.0))
    };
    let want = spot_attenuation(&Beam::SPOT, 35f64.to_radians().cos());
    assert!(want > 0.1 && want < 0.9);
    assert_close(floor_under(light.clone(), vec![]), want);
    // Outside the falloff cone: dark.
    let far = Light {
        point_at: DVec3::new(8.0, 0.0, 0.0),
        ..light
    };
    assert_close(floor_under(far, vec![]), 0.0);
}

#[test]
fn area_light_weights_its_lights_block_by_block() {
    // Three lights at x = -1, 0, 1 (height 4); a slab at height 2 hides the left one
    // only. POV-Ray averages blocks [0,1] and [1,2]: (0.5 + 1) / 2 = 0.75, not 2/3.
    let light = Light {
        area: Some(AreaLight {
            axis1: DVec3::new(2.0, 0.0, 0.0),
            axis2: DVec3::new(0.0, 0.0, 1.0),
            size1: 3,
            size2: 1,
            jitter: false,
            adaptive: None,
            circular: false,
            orient: false,
        }),
        ..point_light(DVec3::new(0.0, 4.0, 0.0))
    };
    let slab = cuboid(DVec3::new(-10.0, 1.9, -10.0), DVec3::new(-0.2, 2.1, 10.0));
    assert_close(floor_under(light.clone(), vec![slab]), 0.75);
    assert_close(floor_under(light, vec![]), 1.0);
}

/// As in POV-Ray, a light source written among a CSG object's members moves with
/// the object's transforms, nested ones included (checked pixel for pixel against
/// POV-Ray 3.7 on a lit floor).
#[test]
fn lights_inside_unions_move_with_them() {
    let text = "#declare U = union { light_source { <0, 0, -3> rgb <1, 0.5, 0.2> } \
                sphere { <0, 1, 0>, 0.7 } rotate 90*y translate <1, 2, 0> }\n\
                object { U translate z }\n\
                union { union { light_source { 0 rgb 0.5 } translate x*3 } translate y*2 }\n";
    let mut sources = rts::source::SourceMap::new();
    let id = sources.add("test.rts", None, text.to_string());
    let (file, diags) = rts::syntax::parse(text, id);
    assert!(diags.is_empty(), "{diags:?}");
    let ev = rts::eval::eval(&file, id, &mut sources, &rts::eval::EvalOptions::default());
    let lights = &ev.scene.lights;
    assert_eq!(lights.len(), 2, "{:?}", ev.diagnostics);
    // <0,0,-3> turned 90° about y is <-3,0,0>; then the union's and object's moves.
    assert!((lights[0].location - DVec3::new(-2.0, 2.0, 1.0)).length() < 1e-9);
    assert!((lights[0].colour - DVec3::new(1.0, 0.5, 0.2)).length() < 1e-12);
    assert!((lights[1].location - DVec3::new(3.0, 2.0, 0.0)).length() < 1e-9);
    // The lights are taken out: the objects no longer hold them.
    assert!(ev.scene.objects.iter().all(|o| o.lights.is_empty()));
}

/// A light set exactly in a ceiling's plane lights the floor below (POV-Ray's
/// radiosity/cornell.pov: its lights sit in the ceiling), and a declared light
/// placed with `light_source { NAME translate … }` is moved like `object { }`.
#[test]
fn a_light_in_the_ceiling_plane_and_a_declared_light_placed_again() {
    let scene = |light: &str| {
        format!(
            "#version 3.7;
global_settings {{ assumed_gamma 1 }}
camera {{ location <0, 1, -3> look_at <0, 0, 0> }}
{light}
plane {{ y, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}
plane {{ y, 2 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}"
        )
    };
    let direct = render_source(
        "lights",
        "ceiling_light",
        &scene("light_source { <0, 2, 0> rgb 1 }"),
        16,
        12,
    );
    let floor = direct[11 * 16 + 8];
    assert!(floor[1] > 0.1, "the floor is lit: {floor:?}");
    let placed = render_source(
        "lights",
        "declared_light",
        &scene("#declare L = light_source { <3, 2, 0> rgb 1 }\nlight_source { L translate <-3, 0, 0> }"),
        16,
        12,
    );
    assert_eq!(direct, placed);
}

/// `light_group`: a group's lights light only its objects (and those of groups
/// nested in it); the scene's lights light a group's objects only with
/// `global_lights on` (the picture is identical to POV-Ray 3.7's).
#[test]
fn light_groups_light_only_their_own_objects() {
    let scene = "#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -6> look_at <0, 0.5, 0> }
light_source { <0, 10, -10> rgb 0.8 }
#declare RedLight = light_source { <-5, 5, -5> rgb <1, 0, 0> }
light_group {
  light_source { RedLight }
  sphere { <-1.5, 0.5, 0>, 0.8 pigment { rgb 1 } finish { ambient 0 } }
  global_lights off
}
light_group {
  light_source { <5, 5, -5> rgb <0, 0, 1> }
  sphere { <1.5, 0.5, 0>, 0.8 pigment { rgb 1 } finish { ambient 0 } }
  global_lights on
}
#declare L1 = light_group {
  light_source { <0, 5, -5> rgb <0, 1, 0> }
  sphere { <0, 1.8, 0>, 0.5 pigment { rgb 1 } finish { ambient 0 } }
}
light_group { light_source { <0, 1.8, -5> rgb 0.5 } light_group { L1 } }
plane { y, -0.3 pigment { rgb 1 } finish { ambient 0 } }";
    let px = render_source("lights", "light_group", scene, 40, 30);
    let at = |x: usize, y: usize| px[y * 40 + x];
    // Left: the red group light only.
    let left = at(11, 17);
    assert!(
        left[0] > 0.01 && left[1] == 0.0 && left[2] == 0.0,
        "{left:?}"
    );
    // Right: its blue light and the scene's white one.
    let right = at(28, 17);
    assert!(right[2] > right[0] && right[0] > 0.01, "{right:?}");
    // Top: the nested group's green light and the outer group's white one.
    let top = at(20, 9);
    assert!(
        top[1] > top[0] && top[0] > 0.01 && (top[0] - top[2]).abs() < 1e-6,
        "{top:?}"
    );
    // The floor: the scene's light only.
    let floor = at(20, 26);
    assert!(
        floor[0] > 0.1 && floor[0] == floor[1] && floor[1] == floor[2],
        "{floor:?}"
    );
}

#[test]
fn simulated_caustics_brighten_shadows_as_povray_does() {
    // A clear disc tilted by `tilt` degrees between a parallel light and a
    // white floor; the gain `1 + cos^(45 C)` measured on POV-Ray 3.7 (2 at
    // normal incidence, 1.502 at 10° for C = 1, 1.2521 for C = 2).
    let floor_ratio = |caustics: f64, tilt: f64| {
        let scene = format!(
            "global_settings {{ assumed_gamma 1.0 }}\n\
             camera {{ orthographic location <0,10,0> look_at 0 sky z right x*4 up z*4 }}\n\
             light_source {{ <0,100,0> rgb 0.1 parallel point_at 0 }}\n\
             plane {{ y, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}\n\
             disc {{ <0,1.5,0>, <sin(radians({tilt})), cos(radians({tilt})), 0>, 1\n\
               pigment {{ rgbf <1,1,1,1> }} finish {{ ambient 0 diffuse 0 }}\n\
               interior {{ caustics {caustics} }} no_image }}\n"
        );
        let name = format!("caustics_{caustics}_{tilt}");
        let px = render_source("lights", &name, &scene, 20, 20);
        // Centre: under the disc; corner: open floor.
        px[10 * 20 + 10][0] / px[0][0]
    };
    for (c, tilt, want) in [
        (0.0, 0.0, 1.0),
        (1.0, 0.0, 2.0),
        (1.0, 10.0, 1.502),
        (1.0, 170.0, 1.502),
        (2.0, 10.0, 1.2521),
        (0.5, 20.0, 1.2466),
    ] {
        let got = floor_ratio(c, tilt);
        assert!(
            (got - want).abs() < 2e-3,
            "caustics {c} tilt {tilt}: {got} vs {want}"
        );
    }
}
