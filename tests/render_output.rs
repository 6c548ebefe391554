//! Determinism across thread counts and PNG output.

mod render_support;

use glam::{DVec3, Vec3};
use render_support::*;
use rts::build::build;
use rts::output::{write, write_as, BitDepth, Format, Gamma, OutputOptions};
use rts::render::{
    render, render_with, Antialias, Crop, Film, Pass, Progress, RenderOptions, Rendered, Sampling,
    Settings,
};
use rts::scene::{Finish, Pattern, Pigment, Reflection, Scene, Texture};
use std::sync::atomic::Ordering;
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
    assert_eq!(bits(&a), bits(&b));
    // Something is actually visible: not all background.
    assert!(a
        .colours()
        .any(|p| p != sc.background.rgb.as_vec3().as_dvec3()));
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
        pixels: vec![Vec3::splat(0.5), Vec3::new(2.0, -1.0, 0.25)],
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

fn render_settings_on(threads: usize, sc: &Scene, settings: &Settings) -> Rendered {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let world = build(sc);
    pool.install(|| {
        render_with(
            &world,
            &RenderOptions {
                width: 96,
                height: 72,
            },
            settings,
            None,
        )
    })
}

fn bits(f: &Film) -> Vec<u32> {
    f.pixels
        .iter()
        .flat_map(|p| p.to_array().map(f32::to_bits))
        .collect()
}

#[test]
fn antialias_and_samples_are_the_same_on_one_and_four_threads() {
    let sc = busy_scene();
    let plain = render_on(1, &sc);
    for sampling in [
        Sampling::Adaptive(Antialias::default()),
        Sampling::Adaptive(Antialias {
            threshold: 0.0,
            depth: 2,
            jitter: 0.0,
            ..Antialias::default()
        }),
        Sampling::Fixed(5),
    ] {
        let settings = Settings {
            sampling,
            seed: 3,
            ..Settings::default()
        };
        let a = render_settings_on(1, &sc, &settings);
        let b = render_settings_on(4, &sc, &settings);
        assert_eq!(bits(&a.film), bits(&b.film), "{sampling:?}");
        assert_eq!(a.stats, b.stats, "{sampling:?}");
        assert_eq!(a.stats.pixels, 96 * 72);
        assert!(a.stats.rays.camera > 96 * 72, "{sampling:?}");
        // Anti-aliasing changes edge pixels only; the picture stays close.
        assert_ne!(bits(&a.film), bits(&plain), "{sampling:?}");
    }
    // Adaptive AA leaves pixels away from edges as the plain render has them.
    let aa = render_settings_on(
        2,
        &sc,
        &Settings {
            sampling: Sampling::Adaptive(Antialias::default()),
            ..Settings::default()
        },
    );
    let same = aa
        .film
        .pixels
        .iter()
        .zip(&plain.pixels)
        .filter(|(a, b)| a == b)
        .count();
    assert!(same > 96 * 72 / 4, "{same}");
    assert!(aa.stats.supersampled > 0 && aa.stats.supersampled < 96 * 72);
    // Another seed moves the jittered samples.
    let other = render_settings_on(
        2,
        &sc,
        &Settings {
            sampling: Sampling::Adaptive(Antialias::default()),
            seed: 99,
            ..Settings::default()
        },
    );
    assert_ne!(bits(&aa.film), bits(&other.film));
}

#[test]
fn a_crop_is_the_same_pixels_as_the_full_render() {
    let sc = busy_scene();
    for sampling in [
        Sampling::Centre,
        Sampling::Adaptive(Antialias::default()),
        Sampling::Fixed(3),
    ] {
        let full = render_settings_on(
            2,
            &sc,
            &Settings {
                sampling,
                ..Settings::default()
            },
        );
        let crop = Crop {
            x0: 30,
            y0: 20,
            x1: 71,
            y1: 55,
        };
        let part = render_settings_on(
            3,
            &sc,
            &Settings {
                sampling,
                crop: Some(crop),
                ..Settings::default()
            },
        );
        assert_eq!((part.film.width, part.film.height), (41, 35));
        assert_eq!(part.stats.pixels, 41 * 35);
        for y in 0..35 {
            for x in 0..41 {
                assert_eq!(
                    part.film.get(x, y),
                    full.film.get(x + 30, y + 20),
                    "{sampling:?} at ({x}, {y})"
                );
            }
        }
    }
}

#[test]
fn debug_passes_show_distance_normal_and_pigment() {
    // A unit sphere 5 units in front of the camera on a black background.
    let cam = rts::scene::Camera {
        location: DVec3::new(0.0, 0.0, -5.0),
        direction: DVec3::Z,
        ..Default::default()
    };
    let mut sc = scene(
        cam,
        vec![with_texture(
            sphere(DVec3::ZERO, 1.0),
            texture(DVec3::new(0.9, 0.2, 0.1), Finish::default()),
        )],
    );
    sc.background.rgb = DVec3::new(0.0, 0.0, 0.3);
    let world = build(&sc);
    let opts = RenderOptions {
        width: 33,
        height: 33,
    };
    let pass = |pass| {
        render_with(
            &world,
            &opts,
            &Settings {
                pass,
                ..Settings::default()
            },
            None,
        )
        .film
    };
    // The centre ray hits at distance 4: grey 1 - 4/8 with --depth-max 8.
    let depth = pass(Pass::Depth { max: Some(8.0) });
    assert!((depth.get(16, 16) - DVec3::splat(0.5)).abs().max_element() < 1e-9);
    assert_eq!(depth.get(0, 0), DVec3::ZERO);
    // Automatic black distance: the farthest hit, so the nearest point is the
    // brightest and still below white.
    let auto = pass(Pass::Depth { max: None });
    let c = auto.get(16, 16).x;
    assert!(c > 0.0 && c < 1.0 && auto.colours().all(|p| p.x <= c));
    // The normal facing the camera is -z: colour (0.5, 0.5, 0).
    let normal = pass(Pass::Normal);
    assert!(
        (normal.get(16, 16) - DVec3::new(0.5, 0.5, 0.0))
            .abs()
            .max_element()
            < 1e-9
    );
    assert_eq!(normal.get(0, 0), DVec3::ZERO);
    assert!(Pass::Normal.is_data() && !Pass::Albedo.is_data());
    // Albedo: the pigment, unlit; the background where nothing is hit.
    let albedo = pass(Pass::Albedo);
    // (Exactly the colours, as the film holds them: in single precision.)
    let single = |c: DVec3| c.as_vec3().as_dvec3();
    assert_eq!(albedo.get(16, 16), single(DVec3::new(0.9, 0.2, 0.1)));
    assert_eq!(albedo.get(0, 0), single(DVec3::new(0.0, 0.0, 0.3)));
}

#[test]
fn exr_hdr_and_ppm_read_back() {
    let dir = tmp_dir("formats");
    let film = grey_film();
    // EXR: linear 32-bit float, unclamped; assumed_gamma 2.2 decodes 0.5 to 0.2176.
    let exr = dir.join("a.exr");
    let opts = OutputOptions {
        assumed_gamma: Some(2.2),
        ..OutputOptions::default()
    };
    write(&film, &exr, &opts).unwrap();
    let img = image::open(&exr).unwrap().to_rgb32f();
    assert_eq!(img.dimensions(), (2, 1));
    assert!((img.get_pixel(0, 0).0[0] - 0.5f32.powf(2.2)).abs() < 1e-6);
    assert!((img.get_pixel(1, 0).0[0] - 2.0f32.powf(2.2)).abs() < 1e-5);
    assert_eq!(img.get_pixel(1, 0).0[1], 0.0);
    // HDR: RGBE keeps about 1% precision, and values above 1.
    let hdr = dir.join("a.hdr");
    write(&film, &hdr, &OutputOptions::default()).unwrap();
    let img = image::open(&hdr).unwrap().to_rgb32f();
    let p = img.get_pixel(1, 0).0;
    assert!(
        (p[0] - 2.0).abs() < 0.02 && p[1] == 0.0 && (p[2] - 0.25).abs() < 0.01,
        "{p:?}"
    );
    assert!((img.get_pixel(0, 0).0[0] - 0.5).abs() < 0.01);
    // PPM: the same 8- and 16-bit values as PNG.
    let ppm = dir.join("a.ppm");
    write(&film, &ppm, &OutputOptions::default()).unwrap();
    assert!(std::fs::read(&ppm).unwrap().starts_with(b"P6"));
    let img = image::open(&ppm).unwrap().to_rgb8();
    assert_eq!(img.get_pixel(0, 0).0, [188, 188, 188]);
    assert_eq!(img.get_pixel(1, 0).0, [255, 0, 137]);
    let opts16 = OutputOptions {
        bit_depth: BitDepth::Sixteen,
        ..OutputOptions::default()
    };
    // --format wins over the extension.
    let odd = dir.join("b.img");
    write_as(&film, &odd, Format::Ppm, &opts16).unwrap();
    let img = image::ImageReader::with_format(
        std::io::BufReader::new(std::fs::File::open(&odd).unwrap()),
        image::ImageFormat::Pnm,
    )
    .decode()
    .unwrap()
    .to_rgb16();
    assert_eq!(img.get_pixel(0, 0).0, [48192, 48192, 48192]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A white box (ambient 1) whose right edge cuts pixel column 16 of a 32 × 24
/// image at fraction `f` of the pixel, on black: pixel 16 is black at its centre.
fn edge_world(f: f64) -> rts::build::World {
    let cam = rts::scene::Camera {
        location: DVec3::new(0.0, 0.0, -5.0),
        direction: DVec3::Z,
        right: DVec3::X * (4.0 / 3.0),
        up: DVec3::Y,
        ..Default::default()
    };
    let x = 5.0 * f / 24.0;
    build(&scene(
        cam,
        vec![with_texture(
            cuboid(DVec3::new(-10.0, -10.0, 0.0), DVec3::new(x, 10.0, 1.0)),
            texture(DVec3::ONE, matte(1.0, 0.0)),
        )],
    ))
}

#[test]
fn antialiased_edge_pixels_match_povray_without_jitter() {
    // `povray +A0.3 -J +W32 +H24 File_Gamma=1.0` on the same scene gives pixel 16
    // these values (in tenths: centre ray + 3×3 grid at sub-cell centres 1/6, 1/2,
    // 5/6, plain mean); pixels 15 and 17 stay white and black.
    let aa = Settings {
        sampling: Sampling::Adaptive(Antialias {
            jitter: 0.0,
            ..Antialias::default()
        }),
        ..Settings::default()
    };
    let opts = RenderOptions {
        width: 32,
        height: 24,
    };
    for (f, want) in [(0.1, 0.0), (0.2, 0.3), (0.45, 0.3), (0.55, 0.7), (0.9, 1.0)] {
        let film = render_with(&edge_world(f), &opts, &aa, None).film;
        for y in [5, 12] {
            // Within the film's single precision.
            assert!(
                (film.get(16, y).x - want).abs() < 1e-7,
                "f = {f}: {}",
                film.get(16, y)
            );
            assert_eq!(film.get(15, y), DVec3::ONE);
            assert_eq!(film.get(17, y), DVec3::ZERO);
        }
    }
    // --aa-depth 4: 4 of 17 rays white at f = 0.3 (POV-Ray +R4: 60/255).
    let r4 = Settings {
        sampling: Sampling::Adaptive(Antialias {
            depth: 4,
            jitter: 0.0,
            ..Antialias::default()
        }),
        ..Settings::default()
    };
    let film = render_with(&edge_world(0.3), &opts, &r4, None).film;
    assert!((film.get(16, 5).x - 4.0 / 17.0).abs() < 1e-7);
    // With jitter the count varies per row but stays within the column's cells.
    let jittered = render_with(
        &edge_world(0.45),
        &opts,
        &Settings {
            sampling: Sampling::Adaptive(Antialias::default()),
            ..Settings::default()
        },
        None,
    )
    .film;
    for y in 0..24 {
        let v = jittered.get(16, y).x;
        assert!((0.3 - 1e-7..=0.6 + 1e-7).contains(&v), "row {y}: {v}");
    }
}

#[test]
fn progress_reaches_its_total() {
    let world = build(&busy_scene());
    let opts = RenderOptions {
        width: 70,
        height: 40,
    };
    for sampling in [Sampling::Centre, Sampling::Adaptive(Antialias::default())] {
        let progress = Progress::default();
        let settings = Settings {
            sampling,
            ..Settings::default()
        };
        render_with(&world, &opts, &settings, Some(&progress));
        let total = progress.total.load(Ordering::Relaxed);
        // Rows, or 32-pixel blocks (3 × 2) for anti-aliasing.
        let want = if sampling == Sampling::Centre { 40 } else { 6 };
        assert_eq!(total, want);
        assert_eq!(progress.done.load(Ordering::Relaxed), total);
    }
}
