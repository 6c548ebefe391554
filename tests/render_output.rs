//! Determinism across thread counts and PNG output.

mod render_support;

use glam::DVec3;
use render_support::*;
use rts::build::build;
use rts::output::{write, BitDepth, Gamma, OutputOptions};
use rts::render::{render, Film, RenderOptions};
use rts::scene::{Finish, Pattern, Pigment, Reflection, Scene, Texture};
use std::sync::Arc;

/// A small scene exercising every feature: checker floor, mirror, highlights.
fn busy_scene() -> Scene {
    let cam = rts::scene::Camera {
        location: DVec3::new(0.0, 2.0, -6.0),
        direction: DVec3::new(0.0, -0.3, 1.0).normalize() * 1.5,
        ..Default::default()
    };
    let checker = Pigment {
        pattern: Pattern::Checker(Box::new([
            solid(DVec3::ONE),
            solid(DVec3::new(0.1, 0.2, 0.6)),
        ])),
        transform: None,
    };
    let floor = with_texture(
        plane(DVec3::Y, -1.0),
        Some(Arc::new(Texture {
            pigment: checker,
            finish: Finish::default(),
            ..Texture::default()
        })),
    );
    let mirror = Finish {
        reflection: Reflection {
            min: DVec3::splat(0.4),
            max: DVec3::splat(0.9),
            ..Default::default()
        },
        phong: 0.8,
        specular: 0.3,
        metallic: 0.5,
        ..Finish::default()
    };
    let mut objs = vec![floor];
    for k in 0..12 {
        let a = k as f64 * 0.52;
        let c = DVec3::new(2.5 * a.cos(), -0.5 + 0.1 * k as f64, 3.0 + 2.5 * a.sin());
        objs.push(with_texture(
            sphere(c, 0.5),
            texture(DVec3::new(0.9, 0.5, 0.2), mirror),
        ));
    }
    objs.push(with_texture(
        cuboid(DVec3::new(-0.5, -1.0, 2.5), DVec3::new(0.5, 0.0, 3.5)),
        texture(DVec3::new(0.2, 0.8, 0.3), Finish::default()),
    ));
    let mut sc = scene(cam, objs);
    sc.lights.push(point_light(DVec3::new(-4.0, 6.0, -3.0)));
    sc.background.rgb = DVec3::new(0.3, 0.5, 0.9);
    sc
}

fn render_on(threads: usize, sc: &Scene) -> Film {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let world = build(sc);
    pool.install(|| {
        render(
            &world,
            &RenderOptions {
                width: 96,
                height: 72,
            },
        )
    })
}

#[test]
fn same_bits_on_one_and_four_threads() {
    let sc = busy_scene();
    let a = render_on(1, &sc);
    let b = render_on(4, &sc);
    assert_eq!(a.pixels.len(), 96 * 72);
    let bits = |f: &Film| {
        f.pixels
            .iter()
            .flat_map(|p| p.to_array().map(f64::to_bits))
            .collect::<Vec<_>>()
    };
    assert_eq!(bits(&a), bits(&b));
    // Something is actually visible: not all background.
    assert!(a.pixels.iter().any(|p| *p != sc.background.rgb));
}

fn tmp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("rts-render-output-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn grey_film() -> Film {
    Film {
        width: 2,
        height: 1,
        pixels: vec![DVec3::splat(0.5), DVec3::new(2.0, -1.0, 0.25)],
    }
}

#[test]
fn png_8_bit_srgb_and_linear() {
    let dir = tmp_dir("8");
    let path = dir.join("grey.png");
    write(&grey_film(), &path, &OutputOptions::default()).unwrap();
    let img = image::open(&path).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (2, 1));
    assert_eq!(img.get_pixel(0, 0).0, [188, 188, 188]);
    assert_eq!(img.get_pixel(1, 0).0, [255, 0, 137]);
    let linear = OutputOptions {
        gamma: Gamma::Power(1.0),
        ..Default::default()
    };
    write(&grey_film(), &path, &linear).unwrap();
    let img = image::open(&path).unwrap().to_rgb8();
    assert_eq!(img.get_pixel(0, 0).0, [128, 128, 128]);
    assert_eq!(img.get_pixel(1, 0).0, [255, 0, 64]);
    // No temporary file left behind.
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn png_16_bit_with_assumed_gamma() {
    let dir = tmp_dir("16");
    let path = dir.join("grey16.png");
    let opts = OutputOptions {
        bit_depth: BitDepth::Sixteen,
        ..Default::default()
    };
    write(&grey_film(), &path, &opts).unwrap();
    let img = image::open(&path).unwrap().to_rgb16();
    assert_eq!(img.get_pixel(0, 0).0, [48192, 48192, 48192]);
    let opts = OutputOptions {
        assumed_gamma: Some(2.2),
        gamma: Gamma::Power(2.2),
        ..opts
    };
    write(&grey_film(), &path, &opts).unwrap();
    let img = image::open(&path).unwrap().to_rgb16();
    assert_eq!(img.get_pixel(0, 0).0, [32768, 32768, 32768]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn write_error_names_the_path() {
    let path = std::path::Path::new("/nonexistent-rts-dir/sub/out.png");
    let err = write(&grey_film(), path, &OutputOptions::default()).unwrap_err();
    let msg = err.to_string();
    assert!(msg.contains("/nonexistent-rts-dir/sub/out.png"), "{msg}");
    assert!(std::error::Error::source(&err).is_some());
}
