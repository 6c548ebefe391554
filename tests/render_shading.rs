//! Analytic checks of the shading model.

mod render_support;

use glam::DVec3;
use render_support::*;
use rts::build::build;
use rts::render::{render, RenderOptions};
use rts::scene::{Finish, Reflection, Transform};

/// Films hold single precision (rounding within 6e-8 of a value): shading is
/// checked to well within a 16-bit file step (1.5e-5) but not beyond.
const EPS: f64 = 1e-6;

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).abs().max_element() < EPS
}

#[test]
fn flat_sphere_covers_exactly_the_pixels_inside_its_silhouette() {
    // Camera at z = -10 looking at a unit sphere: a pixel is covered exactly when
    // its ray passes closer than 1 to the centre.
    let cam = square_camera(DVec3::new(0.0, 0.0, -10.0), 0.5);
    let s = with_texture(
        sphere(DVec3::ZERO, 1.0),
        texture(DVec3::splat(0.5), matte(1.0, 0.0)),
    );
    let world = build(&scene(cam, vec![s]));
    let (w, h) = (41, 41);
    let film = render(
        &world,
        &RenderOptions {
            width: w,
            height: h,
        },
    );
    for j in 0..h {
        for i in 0..w {
            // The ray direction through the pixel, and its distance from the centre.
            let u = (i as f64 + 0.5) / w as f64 - 0.5;
            let v = 0.5 - (j as f64 + 0.5) / h as f64;
            let d = DVec3::new(u * 0.5, v * 0.5, 1.0).normalize();
            let o = DVec3::new(0.0, 0.0, -10.0);
            let miss_dist = (o - d * o.dot(d)).length();
            let px = film.get(i, j);
            if miss_dist < 1.0 - 1e-9 {
                assert_eq!(px, DVec3::splat(0.5), "pixel {i},{j} inside");
            } else if miss_dist > 1.0 + 1e-9 {
                assert_eq!(px, DVec3::ZERO, "pixel {i},{j} outside");
            }
        }
    }
    assert_eq!(film.get(20, 20), DVec3::splat(0.5));
    assert_eq!(film.get(0, 0), DVec3::ZERO);
}

#[test]
fn diffuse_of_a_plane_is_n_dot_l() {
    // Floor y = 0 seen from above; light off to the side, far away.
    let cam = rts::scene::Camera {
        location: DVec3::new(0.0, 5.0, 0.0),
        direction: -DVec3::Y,
        right: DVec3::X,
        up: DVec3::Z,
        ..Default::default()
    };
    let floor = with_texture(plane(DVec3::Y, 0.0), texture(DVec3::ONE, matte(0.0, 1.0)));
    let mut sc = scene(cam, vec![floor]);
    let light = DVec3::new(3.0, 4.0, 1.0);
    sc.lights.push(point_light(light));
    let world = build(&sc);
    let film = render(
        &world,
        &RenderOptions {
            width: 9,
            height: 9,
        },
    );
    for j in 0..9 {
        for i in 0..9 {
            let mut sampler = rts::render::Sampler::new(0, 0, i, j, 0);
            let (x, y) = (f64::from(i) + 0.5, f64::from(j) + 0.5);
            let ray = rts::render::primary_ray(&world.camera, x, y, 9, 9, &mut sampler).unwrap();
            let p = ray.at(5.0 / -ray.dir.y);
            let expect = (light - p).normalize().y;
            assert!((film.get(i, j).x - expect).abs() < EPS, "{i},{j}");
        }
    }
}

#[test]
fn brilliance_and_light_colour_scale_diffuse() {
    let cam = rts::scene::Camera {
        location: DVec3::new(0.0, 1.0, 0.0),
        direction: -DVec3::Y,
        right: DVec3::X * 1e-3,
        up: DVec3::Z * 1e-3,
        ..Default::default()
    };
    let fin = Finish {
        brilliance: 3.0,
        ..matte(0.0, 0.5)
    };
    let floor = with_texture(
        plane(DVec3::Y, 0.0),
        texture(DVec3::new(1.0, 0.5, 0.25), fin),
    );
    let mut sc = scene(cam, vec![floor]);
    let mut l = point_light(DVec3::new(0.0, 1.0, 1.0));
    l.colour = DVec3::new(2.0, 1.0, 1.0);
    sc.lights.push(l);
    let film = render(
        &build(&sc),
        &RenderOptions {
            width: 1,
            height: 1,
        },
    );
    let cos = std::f64::consts::FRAC_1_SQRT_2;
    let expect = 0.5 * cos.powi(3) * DVec3::new(2.0, 0.5, 0.25);
    assert!(
        close(film.get(0, 0), expect),
        "{:?} vs {expect:?}",
        film.get(0, 0)
    );
}

/// Floor under a blocker, light above: the point under the blocker is lit only by
/// ambient; with `no_shadow` or a `shadowless` light it is lit fully.
fn shadow_scene(no_shadow: bool, shadowless: bool, blocker_y: f64, parallel: bool) -> DVec3 {
    let cam = rts::scene::Camera {
        location: DVec3::new(0.0, 0.5, 0.0),
        direction: -DVec3::Y,
        right: DVec3::X * 1e-3,
        up: DVec3::Z * 1e-3,
        ..Default::default()
    };
    let floor = with_texture(plane(DVec3::Y, 0.0), texture(DVec3::ONE, matte(0.2, 0.7)));
    let mut blocker = sphere(DVec3::new(0.0, blocker_y, 0.0), 0.25);
    blocker.flags.no_shadow = no_shadow;
    blocker.flags.no_image = true;
    let mut sc = scene(cam, vec![floor, blocker]);
    let mut l = point_light(DVec3::new(0.0, 10.0, 0.0));
    l.shadowless = shadowless;
    if parallel {
        l.parallel = true;
    }
    sc.lights.push(l);
    render(
        &build(&sc),
        &RenderOptions {
            width: 1,
            height: 1,
        },
    )
    .get(0, 0)
}

#[test]
fn shadows() {
    assert!(close(
        shadow_scene(false, false, 2.0, false),
        DVec3::splat(0.2)
    ));
    assert!(close(
        shadow_scene(true, false, 2.0, false),
        DVec3::splat(0.9)
    ));
    assert!(close(
        shadow_scene(false, true, 2.0, false),
        DVec3::splat(0.9)
    ));
    // A blocker beyond a point light does not shadow.
    assert!(close(
        shadow_scene(false, false, 12.0, false),
        DVec3::splat(0.9)
    ));
}

#[test]
fn parallel_light_shadows_only_from_before_its_plane() {
    // POV-Ray 3.7: with the light at y = 10 pointing down, a blocker at 9.95 casts
    // a shadow, one at 10.05 does not.
    assert!(close(
        shadow_scene(false, false, 2.0, true),
        DVec3::splat(0.2)
    ));
    assert!(close(
        shadow_scene(false, false, 9.8, true),
        DVec3::splat(0.2)
    ));
    assert!(close(
        shadow_scene(false, false, 10.3, true),
        DVec3::splat(0.9)
    ));
}

#[test]
fn parallel_light_direction_is_the_same_everywhere() {
    // A floor lit by a parallel light at 45°: every pixel gets diffuse cos 45°.
    let cam = rts::scene::Camera {
        location: DVec3::new(0.0, 1.0, 0.0),
        direction: -DVec3::Y,
        right: DVec3::X * 4.0,
        up: DVec3::Z * 4.0,
        ..Default::default()
    };
    let floor = with_texture(plane(DVec3::Y, 0.0), texture(DVec3::ONE, matte(0.0, 1.0)));
    let mut sc = scene(cam, vec![floor]);
    let mut l = point_light(DVec3::new(1.0, 1.0, 0.0));
    l.parallel = true;
    sc.lights.push(l);
    let film = render(
        &build(&sc),
        &RenderOptions {
            width: 5,
            height: 5,
        },
    );
    for px in film.colours() {
        assert!((px.x - std::f64::consts::FRAC_1_SQRT_2).abs() < EPS);
    }
}

#[test]
fn mirror_reflects_the_background() {
    let cam = square_camera(DVec3::new(0.0, 0.0, -3.0), 0.1);
    let fin = Finish {
        reflection: Reflection {
            min: DVec3::ONE,
            max: DVec3::ONE,
            ..Reflection::default()
        },
        ..matte(0.0, 0.0)
    };
    let mirror = with_texture(plane(-DVec3::Z, 0.0), texture(DVec3::ONE, fin));
    let mut sc = scene(cam, vec![mirror]);
    sc.background.rgb = DVec3::new(0.2, 0.4, 0.8);
    let film = render(
        &build(&sc),
        &RenderOptions {
            width: 3,
            height: 3,
        },
    );
    for px in film.colours() {
        assert!(close(px, DVec3::new(0.2, 0.4, 0.8)), "{px:?}");
    }
}

#[test]
fn facing_mirrors_follow_max_trace_level_and_adc_bailout() {
    // POV-Ray 3.7, two facing mirrors (ambient 0.5 red, reflection 0.5), camera
    // between them: level n gives sum of 0.5^k for k = 1..n; adc 0.1 stops after 4.
    let run = |mtl: u32, adc: f64| {
        let cam = square_camera(DVec3::ZERO, 1e-3);
        let fin = Finish {
            reflection: Reflection {
                min: DVec3::splat(0.5),
                max: DVec3::splat(0.5),
                ..Reflection::default()
            },
            ..matte(0.5, 0.0)
        };
        let tex = texture(DVec3::X, fin);
        let a = with_texture(plane(DVec3::Z, 1.0), tex.clone());
        let b = with_texture(plane(DVec3::Z, -1.0), tex);
        let mut sc = scene(cam, vec![a, b]);
        sc.background.rgb = DVec3::Z;
        sc.global.max_trace_level = mtl;
        sc.global.adc_bailout = adc;
        render(
            &build(&sc),
            &RenderOptions {
                width: 1,
                height: 1,
            },
        )
        .get(0, 0)
    };
    assert!(close(run(1, 0.0), DVec3::new(0.5, 0.0, 0.0)));
    assert!(close(run(2, 0.0), DVec3::new(0.75, 0.0, 0.0)));
    assert!(close(run(5, 0.0), DVec3::new(0.96875, 0.0, 0.0)));
    assert!(close(run(10, 0.1), DVec3::new(0.9375, 0.0, 0.0)));
    assert!(close(run(10, 0.2), DVec3::new(0.875, 0.0, 0.0)));
}

#[test]
fn transformed_sphere_equals_moved_sphere() {
    let cam = square_camera(DVec3::new(0.0, 0.0, -6.0), 0.8);
    let tex = texture(
        DVec3::new(0.9, 0.6, 0.3),
        Finish {
            phong: 0.7,
            ..matte(0.1, 0.6)
        },
    );
    let offset = DVec3::new(0.5, -0.25, 1.0);
    let moved = with_texture(sphere(offset, 1.0), tex.clone());
    let transformed = with_transform(
        with_texture(sphere(DVec3::ZERO, 1.0), tex),
        Transform::translate(offset),
    );
    let render_one = |obj| {
        let mut sc = scene(cam.clone(), vec![obj]);
        sc.lights.push(point_light(DVec3::new(-5.0, 5.0, -5.0)));
        render(
            &build(&sc),
            &RenderOptions {
                width: 32,
                height: 32,
            },
        )
    };
    let (a, b) = (render_one(moved), render_one(transformed));
    for (p, q) in a.colours().zip(b.colours()) {
        assert!((p - q).abs().max_element() < EPS, "{p:?} vs {q:?}");
    }
}

/// A closed glass cube as a `mesh` of twelve triangles, each wound so that
/// `(b - a) × (c - a)` points out, or each reversed.
fn glass_mesh_cube(reversed: bool) -> String {
    let v = |i: usize| [(i >> 2) & 1, (i >> 1) & 1, i & 1].map(|b| if b == 1 { 1 } else { -1 });
    // Faces as corner indices in outward order.
    let faces = [
        [0, 1, 3, 2],
        [4, 6, 7, 5],
        [0, 4, 5, 1],
        [2, 3, 7, 6],
        [0, 2, 6, 4],
        [1, 5, 7, 3],
    ];
    let mut s = String::from("mesh {\n");
    for [a, b, c, d] in faces {
        for mut t in [[a, b, c], [a, c, d]] {
            if reversed {
                t.reverse();
            }
            let p = t.map(|i| {
                let [x, y, z] = v(i);
                format!("<{x},{y},{z}>")
            });
            s += &format!("  triangle {{ {}, {}, {} }}\n", p[0], p[1], p[2]);
        }
    }
    s + "  pigment { rgbf <1,1,1,0.9> } interior { ior 1.5 } rotate y*30 }\n"
}

#[test]
fn glass_meshes_refract_the_same_whichever_way_their_triangles_wind() {
    // POV-Ray tells entering from leaving by the objects a ray is in, so the
    // order of a triangle's corners does not matter (measured: the same
    // picture both ways); an outward-wound cube is checked to bend light.
    let scene = |mesh: String| {
        format!(
            "global_settings {{ assumed_gamma 1 }}\n\
             camera {{ location <0,3,-6> look_at 0 angle 40 }}\n\
             light_source {{ <5,10,-5> rgb 1 }}\n\
             plane {{ z, 4 pigment {{ checker rgb <1,0,0> rgb <0,0,1> scale 0.5 }} }}\n\
             {mesh}"
        )
    };
    let out = render_source(
        "shading",
        "glass_out",
        &scene(glass_mesh_cube(false)),
        48,
        36,
    );
    let rev = render_source(
        "shading",
        "glass_rev",
        &scene(glass_mesh_cube(true)),
        48,
        36,
    );
    assert_eq!(out, rev);
    let flat = render_source(
        "shading",
        "glass_ior1",
        &scene(glass_mesh_cube(false).replace("ior 1.5", "ior 1")),
        48,
        36,
    );
    assert_ne!(out, flat, "the glass should bend the checker behind it");
}

#[test]
fn slope_sees_the_side_of_the_surface_the_ray_meets() {
    // Looking down onto triangles of either winding, a disc facing down and
    // the inside of a sphere: `slope y` is 1 on all of them, as in POV-Ray.
    for (i, obj) in [
        "triangle { <-1,0,-1>, <1,0,-1>, <0,0,1> }",
        "triangle { <-1,0,-1>, <0,0,1>, <1,0,-1> }",
        "disc { 0, -y, 2 }",
        "sphere { <0,0.9,0>, 1 }",
    ]
    .iter()
    .enumerate()
    {
        let scene = format!(
            "global_settings {{ assumed_gamma 1 }}\n\
             camera {{ location <0,1,0.01> look_at 0 }}\n\
             object {{ {obj} pigment {{ slope y color_map {{ [0 rgb x] [1 rgb y] }} }}\n\
               finish {{ ambient 1 diffuse 0 }} }}\n"
        );
        let px = render_source("shading", &format!("slope_side_{i}"), &scene, 9, 9);
        let [r, g, _] = px[4 * 9 + 4];
        assert!(g > 0.99 && r < 0.01, "{obj}: {r} {g}");
    }
}
