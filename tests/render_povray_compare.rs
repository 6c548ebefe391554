//! A scene mirroring a POV-Ray 3.7 reference file, rendered on request for
//! comparison with POV-Ray (`RTS_COMPARE_OUT=out.png cargo test --release
//! --test render_povray_compare -- --ignored`); the matching `.pov` text is in
//! [`POV_SOURCE`]. Output is 16-bit linear to compare with
//! `povray -A File_Gamma=1.0 +FN16`.

mod render_support;

use glam::DVec3;
use render_support::*;
use rts::build::build;
use rts::output::{write, BitDepth, Gamma, OutputOptions};
use rts::render::{render, RenderOptions};
use rts::scene::{
    Camera, Finish, Object, Pattern, Pigment, Reflection, Scene, Shape, Texture, Transform,
};
use std::sync::Arc;

/// The POV-Ray scene this mirrors.
pub const POV_SOURCE: &str = include_str!("render_povray_compare.pov");

fn checker(a: DVec3, b: DVec3, scale: f64) -> Pigment {
    Pigment {
        pattern: Pattern::Checker(Box::new([solid(a), solid(b)])),
        transform: Some(Arc::new(Transform::scale(DVec3::splat(scale)))),
    }
}

fn tex(pigment: Pigment, finish: Finish) -> Option<Arc<Texture>> {
    Some(Arc::new(Texture {
        pigment,
        finish,
        ..Texture::default()
    }))
}

/// The scene of [`POV_SOURCE`].
pub fn compare_scene() -> Scene {
    let cam = Camera {
        location: DVec3::new(0.0, 2.0, -6.0),
        direction: DVec3::new(0.0, -0.45, 1.5),
        right: DVec3::X * 4.0 / 3.0,
        up: DVec3::Y,
        ..Camera::default()
    };
    let floor = with_texture(
        plane(DVec3::Y, -1.0),
        tex(
            checker(DVec3::ONE, DVec3::new(0.1, 0.2, 0.6), 0.75),
            matte(0.1, 0.6),
        ),
    );
    let s1 = with_texture(
        sphere(DVec3::new(-1.5, 0.0, 2.0), 1.0),
        texture(
            DVec3::new(0.9, 0.5, 0.2),
            Finish {
                phong: 0.8,
                phong_size: 30.0,
                metallic: 0.7,
                reflection: Reflection {
                    min: DVec3::splat(0.2),
                    max: DVec3::splat(0.8),
                    falloff: 2.0,
                    metallic: 1.0,
                    ..Reflection::default()
                },
                ..matte(0.1, 0.5)
            },
        ),
    );
    let s2 = with_transform(
        with_texture(
            sphere(DVec3::ZERO, 1.0),
            texture(
                DVec3::new(0.2, 0.8, 0.3),
                Finish {
                    specular: 0.6,
                    roughness: 0.02,
                    brilliance: 2.0,
                    ..Finish::default()
                },
            ),
        ),
        Transform::scale(DVec3::new(0.5, 1.0, 0.5))
            .then(&Transform::rotate(DVec3::new(0.0, 0.0, 30.0)))
            .then(&Transform::translate(DVec3::new(1.5, 0.0, 1.5))),
    );
    let bx = with_transform(
        with_texture(
            cuboid(DVec3::new(-0.5, -1.0, -0.5), DVec3::new(0.5, 0.2, 0.5)),
            texture(
                DVec3::new(0.8, 0.2, 0.2),
                Finish {
                    reflection: Reflection {
                        min: DVec3::splat(0.3),
                        max: DVec3::splat(0.3),
                        ..Reflection::default()
                    },
                    ..matte(0.2, 0.7)
                },
            ),
        ),
        Transform::rotate(DVec3::new(0.0, 35.0, 0.0))
            .then(&Transform::translate(DVec3::new(0.3, 0.0, 4.0))),
    );
    let tri = with_texture(
        triangle(
            DVec3::new(-3.0, -1.0, 5.0),
            DVec3::new(-1.0, 2.5, 6.0),
            DVec3::new(1.0, -1.0, 6.5),
        ),
        texture(DVec3::new(0.9, 0.9, 0.3), Finish::default()),
    );
    let u = Object {
        texture: tex(
            checker(DVec3::new(0.0, 1.0, 1.0), DVec3::new(1.0, 1.0, 0.0), 0.3),
            Finish::default(),
        ),
        transform: Some(Arc::new(Transform::translate(DVec3::new(-0.2, -0.6, 0.5)))),
        ..object(Shape::Union {
            children: vec![
                with_transform(
                    sphere(DVec3::ZERO, 0.4),
                    Transform::translate(DVec3::X * 0.6),
                ),
                with_texture(
                    with_transform(
                        sphere(DVec3::ZERO, 0.4),
                        Transform::translate(-DVec3::X * 0.6),
                    ),
                    texture(DVec3::new(1.0, 0.0, 1.0), Finish::default()),
                ),
            ]
            .into(),
        })
    };
    let mut ghost = with_texture(
        sphere(DVec3::new(2.5, 1.5, 3.0), 0.6),
        texture(DVec3::ONE, Finish::default()),
    );
    ghost.flags.no_shadow = true;
    let mut sc = scene(cam, vec![floor, s1, s2, bx, tri, u, ghost]);
    sc.background.rgb = DVec3::new(0.3, 0.5, 0.9);
    let mut l1 = point_light(DVec3::new(-4.0, 6.0, -3.0));
    l1.colour = DVec3::new(1.0, 0.9, 0.8);
    let mut l2 = point_light(DVec3::new(3.0, 5.0, -1.0));
    l2.colour = DVec3::splat(0.4);
    l2.parallel = true;
    sc.lights = vec![l1, l2];
    sc
}

/// Pixels of POV-Ray 3.7's render of [`POV_SOURCE`] at 320×240
/// (`povray -A File_Gamma=1.0 +FN16`): (x, y, 16-bit linear RGB).
const POVRAY_SAMPLES: &[(u32, u32, [u16; 3])] = &[
    (7, 5, [19661, 32768, 58982]),
    (42, 5, [19661, 32768, 58982]),
    (77, 5, [19661, 32768, 58982]),
    (112, 5, [19661, 32768, 58982]),
    (147, 5, [19661, 32768, 58982]),
    (182, 5, [19661, 32768, 58982]),
    (217, 5, [19661, 32768, 58982]),
    (252, 5, [19661, 32768, 58982]),
    (287, 5, [19661, 32768, 58982]),
    (7, 31, [2473, 4849, 14254]),
    (42, 31, [24879, 24376, 23873]),
    (77, 31, [24985, 24472, 23958]),
    (112, 31, [37859, 35217, 10859]),
    (147, 31, [36183, 33709, 10412]),
    (182, 31, [2500, 4898, 14383]),
    (217, 31, [24907, 24401, 23895]),
    (252, 31, [40939, 37500, 34062]),
    (287, 31, [2460, 4825, 14190]),
    (7, 57, [3197, 6151, 17726]),
    (42, 57, [32242, 31003, 29763]),
    (77, 57, [3240, 6228, 17932]),
    (112, 57, [36948, 34397, 10616]),
    (147, 57, [35408, 33012, 10205]),
    (182, 57, [32046, 30826, 29606]),
    (217, 57, [31695, 30510, 29325]),
    (252, 57, [3127, 6025, 17389]),
    (287, 57, [30787, 29693, 28599]),
    (7, 83, [3925, 7461, 21220]),
    (42, 83, [3949, 7505, 21335]),
    (77, 83, [65535, 38712, 19052]),
    (112, 83, [41308, 24360, 11776]),
    (147, 83, [54694, 23495, 21837]),
    (182, 83, [29527, 15465, 14909]),
    (217, 83, [18356, 35463, 17881]),
    (252, 83, [3699, 7056, 20139]),
    (287, 83, [3621, 6915, 19762]),
    (7, 109, [4555, 8595, 24243]),
    (42, 109, [4558, 8602, 24261]),
    (77, 109, [27855, 14792, 6080]),
    (112, 109, [20208, 11206, 4983]),
    (147, 109, [11081, 3812, 6194]),
    (182, 109, [19309, 6966, 11469]),
    (217, 109, [3982, 14859, 5171]),
    (252, 109, [2856, 11352, 4232]),
    (287, 109, [4053, 7693, 21838]),
    (7, 135, [50225, 47188, 44150]),
    (42, 135, [3671, 6739, 18406]),
    (77, 135, [23048, 12317, 4894]),
    (112, 135, [54539, 0, 47434]),
    (147, 135, [19846, 19846, 19846]),
    (182, 135, [0, 48492, 45342]),
    (217, 135, [45957, 43345, 40734]),
    (252, 135, [1466, 5825, 2170]),
    (287, 135, [1985, 3969, 11908]),
    (7, 161, [53292, 49948, 46603]),
    (42, 161, [5285, 9911, 27751]),
    (77, 161, [38915, 35679, 32443]),
    (112, 161, [31915, 0, 27775]),
    (147, 161, [50448, 47388, 44328]),
    (182, 161, [31014, 29007, 0]),
    (217, 161, [35033, 32185, 29337]),
    (252, 161, [4722, 8896, 25045]),
    (287, 161, [46107, 43481, 40855]),
    (7, 187, [55121, 51593, 48066]),
    (42, 187, [5455, 10216, 28565]),
    (77, 187, [53816, 50419, 47022]),
    (112, 187, [52956, 49645, 46334]),
    (147, 187, [5200, 9757, 27341]),
    (182, 187, [50978, 47865, 44752]),
    (217, 187, [4992, 9382, 26342]),
    (252, 187, [48844, 45945, 43045]),
    (287, 187, [47774, 44982, 42189]),
    (7, 213, [5613, 10500, 29322]),
    (42, 213, [55490, 51925, 48361]),
    (77, 213, [5473, 10249, 28653]),
    (112, 213, [53879, 50476, 47073]),
    (147, 213, [52955, 49644, 46333]),
    (182, 213, [5198, 9754, 27333]),
    (217, 213, [50982, 47868, 44755]),
    (252, 213, [49971, 46959, 43946]),
    (287, 213, [4896, 9210, 25884]),
    (7, 239, [5662, 10589, 29562]),
    (42, 239, [5597, 10472, 29247]),
    (77, 239, [55224, 51686, 48148]),
    (112, 239, [5441, 10190, 28496]),
    (147, 239, [5353, 10033, 28078]),
    (182, 239, [52624, 49347, 46069]),
    (217, 239, [5169, 9702, 27195]),
    (252, 239, [5076, 9533, 26744]),
    (287, 239, [49819, 46822, 43825]),
];

#[test]
fn matches_povray_samples() {
    let world = build(&compare_scene());
    let mut worst = 0.0f64;
    for &(x, y, rgb) in POVRAY_SAMPLES {
        let ours = rts::render::render_pixel(&world, x, y, 320, 240);
        for (c, &v) in ours.to_array().iter().zip(&rgb) {
            let q = (c.clamp(0.0, 1.0) * 65535.0).round();
            worst = worst.max((q - f64::from(v)).abs());
        }
    }
    // POV-Ray computes in single precision in places: allow 2/65535.
    assert!(worst <= 2.0, "worst difference {worst}/65535");
}

#[test]
fn compare_scene_renders() {
    let film = render(
        &build(&compare_scene()),
        &RenderOptions {
            width: 40,
            height: 30,
        },
    );
    assert!(film.pixels.iter().all(|p| p.is_finite()));
    assert!(POV_SOURCE.contains("light_source"));
}

#[test]
#[ignore = "writes an image for manual comparison with POV-Ray"]
fn write_compare_image() {
    let out = std::env::var("RTS_COMPARE_OUT").unwrap_or_else(|_| "/tmp/rts_compare.png".into());
    let film = render(
        &build(&compare_scene()),
        &RenderOptions {
            width: 320,
            height: 240,
        },
    );
    let opts = OutputOptions {
        gamma: Gamma::Power(1.0),
        bit_depth: BitDepth::Sixteen,
        assumed_gamma: Some(1.0),
    };
    write(&film, std::path::Path::new(&out), &opts).unwrap();
}
