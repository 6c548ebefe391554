//! The path tracer: the white furnace, convergence at the Monte Carlo rate,
//! determinism across threads and passes, checkpoints, the documented mapping
//! from POV-Ray finishes to scattering functions, and the command line.

use glam::DVec3;
use rts::build::{build, Ray, RayKind, World};
use rts::render::path::{self, checkpoint, Accum, Bsdf, PathOptions, PathScene};
use rts::render::{RenderOptions, Settings};
use rts::scene::{PixelFilter, Scene};
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

fn world(text: &str) -> World {
    build(&scene(text))
}

fn opts(w: u32, h: u32) -> RenderOptions {
    RenderOptions {
        width: w,
        height: h,
    }
}

#[test]
fn white_furnace_returns_the_albedo() {
    // A Lambertian sphere under a uniform white environment: every camera ray that
    // hits it returns its albedo, every other ray the environment (1).
    for (albedo, env) in [
        (0.8, "background { rgb 1 }"),
        (0.35, "sky_sphere { pigment { rgb 1 } }"),
    ] {
        let w = world(&format!(
            "global_settings {{ assumed_gamma 1 path_tracing {{ max_depth 64 }} }}
             camera {{ location <0, 0, -4> look_at 0 angle 40 }}
             {env}
             sphere {{ 0, 1 pigment {{ rgb {albedo} }} finish {{ ambient 0 diffuse 1 }} }}"
        ));
        // The box filter: each pixel averages its own samples, which all return
        // exactly the albedo or the environment.
        let box_filter = PathOptions {
            filter: PixelFilter::Box,
            ..PathOptions::default()
        };
        let r = path::render(&w, &opts(16, 16), &Settings::default(), &box_filter, 16);
        let centre = r.film.get(8, 8);
        assert!(
            (centre - DVec3::splat(albedo)).abs().max_element() < 1e-3,
            "{centre}"
        );
        // The splatted Gaussian (the default): unbiased, with the noise of the
        // weights its neighbours' samples send (about 1% at 16 samples).
        let g = path::render(
            &w,
            &opts(16, 16),
            &Settings::default(),
            &PathOptions::default(),
            64,
        );
        let centre = g.film.get(8, 8);
        assert!(
            (centre - DVec3::splat(albedo)).abs().max_element() < 1e-2,
            "{centre}"
        );
        let corner = r.film.get(0, 0);
        assert!((corner - DVec3::ONE).abs().max_element() < 1e-3, "{corner}");
        for p in r.film.colours() {
            assert!(
                p.max_element() <= 1.0 + 1e-3 && p.min_element() >= albedo - 1e-3,
                "{p}"
            );
        }
    }
}

#[test]
fn white_furnace_inside_a_closed_white_room_converges_to_the_analytic_value() {
    // Inside a sphere of albedo a that emits Le everywhere, radiance is
    // Le / (1 - a) (every bounce sees the same).
    let (a, le) = (0.5, 0.25);
    let w = world(&format!(
        "global_settings {{ assumed_gamma 1 path_tracing {{ max_depth 200 }} }}
         camera {{ location 0 look_at z angle 60 }}
         sphere {{ 0, 10 pigment {{ rgb {a} }} finish {{ ambient 0 diffuse 1 emission {} }} }}",
        le / a
    ));
    let r = path::render(
        &w,
        &opts(8, 8),
        &Settings::default(),
        &PathOptions {
            max_depth: 200,
            ..PathOptions::default()
        },
        256,
    );
    let mean = r.film.colours().sum::<DVec3>() / r.film.pixels.len() as f64;
    let want = le / (1.0 - a);
    assert!((mean.x - want).abs() < 1e-2 * want, "{mean} vs {want}");
}

const SMALL_SCENE: &str = "
    global_settings { assumed_gamma 1 path_tracing { max_depth 6 } }
    camera { location <0, 1, -4> look_at <0, 0.5, 0> angle 50 }
    plane { y, 0 pigment { rgb 0.7 } finish { ambient 0 diffuse 1 } }
    sphere { <0, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.4, 0.3> } finish { ambient 0 diffuse 0.8 reflection 0.2 } }
    sphere { <0, 3, 0>, 0.5 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 4 } }
    light_source { <3, 4, -3> rgb 0.5 }
";

fn rmse(a: &[DVec3], b: &[DVec3]) -> f64 {
    let s: f64 = a
        .iter()
        .zip(b)
        .map(|(x, y)| (*x - *y).length_squared() / 3.0)
        .sum();
    (s / a.len() as f64).sqrt()
}

#[test]
fn error_falls_at_least_like_one_over_sqrt_spp() {
    // Without mirrors (caustics from a small emitter make rare, huge samples).
    let w = world(&SMALL_SCENE.replace("reflection 0.2", ""));
    let o = opts(12, 9);
    let settings = Settings::default();
    let po = PathOptions::default();
    let reference = path::render(
        &w,
        &o,
        &Settings {
            seed: 99,
            ..settings
        },
        &po,
        4096,
    )
    .film;
    let spps = [4u32, 16, 64, 256];
    let errors: Vec<f64> = spps
        .iter()
        .map(|&n| {
            rmse(
                &path::render(&w, &o, &settings, &po, n)
                    .film
                    .colours()
                    .collect::<Vec<_>>(),
                &reference.colours().collect::<Vec<_>>(),
            )
        })
        .collect();
    // Least-squares slope of log(error) against log(spp).
    let xs: Vec<f64> = spps.iter().map(|&n| f64::from(n).ln()).collect();
    let ys: Vec<f64> = errors.iter().map(|e| e.ln()).collect();
    let k = xs.len() as f64;
    let (mx, my) = (xs.iter().sum::<f64>() / k, ys.iter().sum::<f64>() / k);
    let slope = xs
        .iter()
        .zip(&ys)
        .map(|(x, y)| (x - mx) * (y - my))
        .sum::<f64>()
        / xs.iter().map(|x| (x - mx) * (x - mx)).sum::<f64>();
    eprintln!("RMSE {errors:?} at spp {spps:?}: slope {slope:.3}");
    // Monte Carlo gives -0.5; scrambled Sobol points may do better.
    assert!(
        (-1.2..=-0.4).contains(&slope),
        "slope {slope}, errors {errors:?}"
    );
    assert!(errors.windows(2).all(|e| e[1] < e[0]), "{errors:?}");
}

#[test]
fn same_picture_for_any_thread_count_and_any_split_into_passes() {
    let w = world(SMALL_SCENE);
    let o = opts(10, 8);
    let s = Settings::default();
    let po = PathOptions::default();
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(|| path::render(&w, &o, &s, &po, 8));
    let two = rayon::ThreadPoolBuilder::new()
        .num_threads(3)
        .build()
        .unwrap()
        .install(|| path::render(&w, &o, &s, &po, 8));
    assert_eq!(one.film, two.film);
    // 3 + 5 samples, through a checkpoint file, equal 8 at once.
    let sc = PathScene::new(&w, po.max_depth);
    let crop = path::resolve_crop(&s, o.width, o.height);
    let mut acc = Accum::new(crop);
    path::render_samples(&sc, &o, &s, &po, &mut acc, 3, None);
    let key = checkpoint::Key::new(&o, &s, crop, &po, 7);
    let file = std::env::temp_dir().join(format!("rts_path_test_{}.ckpt", std::process::id()));
    checkpoint::save(&file, &key, &acc).unwrap();
    let mut resumed = checkpoint::load(&file, &key).unwrap();
    std::fs::remove_file(&file).unwrap();
    path::render_samples(&sc, &o, &s, &po, &mut resumed, 5, None);
    assert_eq!(resumed.samples, 8);
    assert_eq!(resumed.film(), one.film);
    // Another frame or seed gives other samples.
    let other = path::render(&w, &o, &Settings { frame: 1, ..s }, &po, 8);
    assert_ne!(other.film, one.film);
}

/// The scattering function at the first surface a ray from `from` to `at` meets.
fn bsdf_at(w: &World, from: DVec3, at: DVec3) -> Bsdf {
    let ray = Ray::new(from, (at - from).normalize());
    let hit = w
        .intersect(&ray, 0.0, f64::INFINITY, RayKind::Camera)
        .expect("hit");
    let s = w.surface(&ray, &hit);
    Bsdf::at(&s, -ray.dir)
}

#[test]
fn classic_terms_map_to_the_documented_scattering_functions() {
    let eye = DVec3::new(0.0, 0.0, -5.0);
    let w = world("sphere { 0, 1 pigment { rgb <0.8, 0.4, 0.2> } finish { diffuse 0.5 } }");
    let b = bsdf_at(&w, eye, DVec3::ZERO);
    // pigment × diffuse → Lambertian albedo; nothing else.
    assert!((b.diffuse - DVec3::new(0.4, 0.2, 0.1)).length() < 1e-12);
    assert_eq!(
        (b.spec, b.gloss, b.trans, b.emission),
        (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO, DVec3::ZERO)
    );

    // reflection + metallic → a conductor tinted by the pigment, mirror-smooth at
    // POV-Ray's default roughness, GGX with roughness as alpha otherwise; the
    // diffuse part keeps what the reflection leaves.
    let w = world(
        "sphere { 0, 1 pigment { rgb <1, 0.5, 0.25> } finish { diffuse 1 reflection { 0.8 metallic } } }
         sphere { <3, 0, 0>, 1 pigment { rgb 1 } finish { diffuse 0 reflection 1 roughness 0.2 } }",
    );
    let b = bsdf_at(&w, eye, DVec3::ZERO);
    assert!((b.spec - DVec3::new(0.8, 0.4, 0.2)).length() < 1e-12);
    assert_eq!(b.spec_alpha, 0.0);
    assert!((b.diffuse - DVec3::new(0.2, 0.1, 0.05)).length() < 1e-12);
    let b = bsdf_at(&w, DVec3::new(3.0, 0.0, -5.0), DVec3::new(3.0, 0.0, 0.0));
    assert_eq!(b.spec_alpha, 0.2);
    assert_eq!(b.spec, DVec3::ONE);

    // filter/transmit with an interior ior → a dielectric (eta seen from outside);
    // without ior → straight through.
    let w = world(
        "sphere { 0, 1 pigment { rgbf <0.9, 1, 0.9, 1> } interior { ior 1.5 } }
         sphere { <3, 0, 0>, 1 pigment { rgbt <1, 0, 0, 0.75> } }",
    );
    let b = bsdf_at(&w, eye, DVec3::ZERO);
    assert_eq!(b.eta, 1.5);
    assert!((b.trans - DVec3::new(0.9, 1.0, 0.9)).length() < 1e-12);
    assert_eq!(b.diffuse, DVec3::ZERO);
    let b = bsdf_at(&w, DVec3::new(3.0, 0.0, -5.0), DVec3::new(3.0, 0.0, 0.0));
    assert_eq!(b.eta, 1.0);
    assert!((b.trans - DVec3::splat(0.75)).length() < 1e-12);
    assert!((b.diffuse - DVec3::new(0.25 * 0.6, 0.0, 0.0)).length() < 1e-12);

    // emission × pigment → emitted radiance; ambient has no effect.
    let w = world("sphere { 0, 1 pigment { rgb <1, 0.5, 0> } finish { ambient 1 emission 3 } }");
    let b = bsdf_at(&w, eye, DVec3::ZERO);
    assert!((b.emission - DVec3::new(3.0, 1.5, 0.0)).length() < 1e-12);
}

#[test]
fn a_point_light_lights_a_lambertian_surface_as_the_classic_renderer_does() {
    let text = "
        global_settings { assumed_gamma 1 }
        camera { orthographic location <0, 5, 0> look_at 0 right x*2 up z*2 }
        plane { y, 0 pigment { rgb <0.6, 0.5, 0.4> } finish { ambient 0 diffuse 0.7 } }
        light_source { <0, 1000, 0> rgb <1, 0.8, 0.5> parallel point_at 0 }
        light_source { <1, 3, 1> rgb 0.3 fade_distance 2 fade_power 2 }";
    let w = world(text);
    let o = opts(9, 9);
    let classic = rts::render::render(&w, &o);
    let po = PathOptions {
        filter: PixelFilter::Box,
        max_depth: 2,
        ..PathOptions::default()
    };
    let pt = path::render(&w, &o, &Settings::default(), &po, 64).film;
    // Pixels differ only by where in the pixel the samples fall (the fading
    // light varies across a pixel).
    for (a, b) in classic.colours().zip(pt.colours()) {
        assert!(
            (a - b).abs().max_element() < 2e-3 * a.max_element().max(1.0),
            "{a} vs {b}"
        );
    }
}

#[test]
fn projected_through_masks_both_renderers_alike() {
    // A ring as the mask: a lit ring on the floor, dark inside and outside it;
    // a ball between the light and the ring casts no shadow.
    let text = "
        global_settings { assumed_gamma 1 }
        camera { orthographic location <0, 5, 0> look_at 0 right x*4 up z*4 }
        plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
        sphere { <0.75, 4, 0>, 0.2 pigment { rgb 1 } no_image }
        light_source { <0, 1000, 0> rgb 1 parallel point_at 0
          projected_through { difference { cylinder { <0, 2.9, 0>, <0, 3.1, 0>, 1 }
                                           cylinder { <0, 2, 0>, <0, 4, 0>, 0.5 } } } }";
    let w = world(text);
    let o = opts(16, 16);
    let classic = rts::render::render(&w, &o);
    let po = PathOptions {
        filter: PixelFilter::Box,
        max_depth: 2,
        ..PathOptions::default()
    };
    let pt = path::render(&w, &o, &Settings::default(), &po, 16).film;
    for film in [&classic, &pt] {
        // Pixels a quarter unit wide: whole pixels inside the hole, on the
        // ring (the ball's would-be shadow falls on one of the first two) and
        // outside it.
        let at = |x: usize, y: usize| film.pixels[y * 16 + x].x;
        assert!(at(7, 7) < 1e-6, "inside the ring's hole: {}", at(7, 7));
        for (x, y) in [(10, 8), (5, 8), (8, 5)] {
            assert!(at(x, y) > 0.5, "under the ring at ({x}, {y}): {}", at(x, y));
        }
        assert!(at(0, 0) < 1e-6, "outside the ring: {}", at(0, 0));
    }
}

#[test]
fn scene_settings_select_the_path_tracer_and_are_checked() {
    let s = scene("global_settings { path_tracing { samples 5 max_depth 3 firefly_clamp 10 pixel_filter \"box\" } }");
    let p = s.global.path_tracing.expect("set");
    assert_eq!(
        (p.samples, p.max_depth, p.firefly_clamp, p.filter),
        (5, 3, 10.0, PixelFilter::Box)
    );
    assert!(scene("global_settings { assumed_gamma 1 }")
        .global
        .path_tracing
        .is_none());
    for (bad, code) in [
        (
            "global_settings { path_tracing { samples 0 } }",
            "rts::eval::out_of_range",
        ),
        (
            "global_settings { path_tracing { pixel_filter \"tent\" } }",
            "rts::eval::out_of_range",
        ),
        ("global_settings { path_tracing { max_dept 3 } }", ""),
    ] {
        let mut sources = SourceMap::new();
        let id = sources.add("t.rts", None, bad.to_string());
        let (file, pd) = rts::syntax::parse(bad, id);
        let ev = rts::eval::eval(&file, id, &mut sources, &rts::eval::EvalOptions::default());
        let all: Vec<_> = pd.iter().chain(&ev.diagnostics).collect();
        assert!(
            all.iter()
                .any(|d| d.severity == rts::diag::Severity::Error && d.code.contains(code)),
            "{bad}: {all:?}"
        );
    }
}

fn rts() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rts"))
}

#[test]
fn command_line_resume_equals_an_uninterrupted_render_and_writes_aovs() {
    let dir = std::env::temp_dir().join(format!("rts_path_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene_path = dir.join("s.rts");
    std::fs::write(&scene_path, SMALL_SCENE).unwrap();
    let run = |out: &str, extra: &[&str]| {
        let st = rts()
            .arg("render")
            .arg(&scene_path)
            .arg("-o")
            .arg(dir.join(out))
            .args(["-W", "12", "-H", "9", "-q"])
            .args(extra)
            .status()
            .unwrap();
        assert!(st.success(), "{out} {extra:?}");
    };
    run("full.exr", &["--spp", "6"]);
    run(
        "part.exr",
        &[
            "--spp",
            "2",
            "--checkpoint",
            dir.join("p.ckpt").to_str().unwrap(),
        ],
    );
    run(
        "part.exr",
        &[
            "--spp",
            "6",
            "--resume",
            "--checkpoint",
            dir.join("p.ckpt").to_str().unwrap(),
            "--aov",
            "albedo,normal",
        ],
    );
    let full = std::fs::read(dir.join("full.exr")).unwrap();
    let part = std::fs::read(dir.join("part.exr")).unwrap();
    assert_eq!(full, part);
    assert!(dir.join("part.albedo.exr").exists() && dir.join("part.normal.exr").exists());
    // A checkpoint of other settings is refused.
    let st = rts()
        .arg("render")
        .arg(&scene_path)
        .arg("-o")
        .arg(dir.join("x.exr"))
        .args([
            "-W",
            "13",
            "-H",
            "9",
            "-q",
            "--spp",
            "4",
            "--resume",
            "--checkpoint",
        ])
        .arg(dir.join("p.ckpt"))
        .output()
        .unwrap();
    assert_eq!(st.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&st.stderr).contains("another scene"));
    // The classic renderer can still be chosen for a path traced scene.
    run("classic.png", &["--integrator", "classic"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn looks_like_objects_show_the_light_and_the_light_does_the_lighting() {
    let w = world(
        "global_settings { assumed_gamma 1 }
         camera { location <0, 1, -4> look_at <0, 1, 0> angle 30 }
         plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
         light_source { <0, 1, 0> rgb 0.5
           looks_like { sphere { 0, 0.3 pigment { rgb <1, 0.9, 0.8> } finish { ambient 1 diffuse 0 } } } }",
    );
    let po = PathOptions {
        filter: PixelFilter::Box,
        ..PathOptions::default()
    };
    let f = path::render(&w, &opts(15, 15), &Settings::default(), &po, 4).film;
    // The stand-in shows its classic colour (to the film's single precision)…
    assert!(
        (f.get(7, 7) - DVec3::new(1.0, 0.9, 0.8)).length() < 1e-6,
        "{}",
        f.get(7, 7)
    );
    // …and the floor below is lit by the point light, not by the sphere.
    assert!(f.get(7, 14).x > 0.0);
}

#[test]
fn command_line_time_limit_writes_a_checkpoint_and_denoise_needs_the_feature() {
    let dir = std::env::temp_dir().join(format!("rts_path_tl_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene_path = dir.join("s.rts");
    std::fs::write(&scene_path, SMALL_SCENE).unwrap();
    let out = rts()
        .arg("render")
        .arg(&scene_path)
        .arg("-o")
        .arg(dir.join("t.png"))
        .args([
            "-W",
            "8",
            "-H",
            "6",
            "--time-limit",
            "0.3s",
            "--stats-json",
            "-",
            "-q",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(dir.join("t.png").exists() && dir.join("t.png.ckpt").exists());
    let stats: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(stats["integrator"], "path");
    assert!(stats["sampling"]["samples"].as_u64().unwrap() >= 1);
    if !cfg!(feature = "oidn") {
        let st = rts()
            .arg("render")
            .arg(&scene_path)
            .arg("-o")
            .arg(dir.join("d.png"))
            .args(["-W", "8", "-H", "6", "--spp", "1", "--denoise", "-q"])
            .output()
            .unwrap();
        assert_eq!(st.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&st.stderr).contains("--features oidn"));
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn environment_sampling_is_unbiased_and_lowers_noise() {
    // A bright band in the sky lights a diffuse ball and floor: the same picture on
    // average with and without sampling the environment as a light, less noise with.
    let w = world(
        "global_settings { assumed_gamma 1 path_tracing { max_depth 4 } }
         camera { location <0, 1.5, -4> look_at <0, 0.5, 0> angle 50 }
         sky_sphere { pigment { gradient y color_map { [0 rgb 0.05] [0.8 rgb 0.05] [0.85 rgb 20] [0.9 rgb 0.05] [1 rgb 0.05] } } }
         plane { y, 0 pigment { rgb 0.6 } finish { ambient 0 diffuse 1 } }
         sphere { <0, 0.7, 0>, 0.7 pigment { rgb <0.8, 0.5, 0.3> } finish { ambient 0 diffuse 1 } }",
    );
    let o = opts(10, 8);
    let s = Settings::default();
    let po = PathOptions::default();
    let with = PathScene::new(&w, po.max_depth);
    assert!(with.env.is_some());
    let mut without = PathScene::new(&w, po.max_depth);
    without.env = None;
    let crop = path::resolve_crop(&s, o.width, o.height);
    let run = |sc: &PathScene, n: u32, seed: u64| {
        let mut a = Accum::new(crop);
        path::render_samples(sc, &o, &Settings { seed, ..s }, &po, &mut a, n, None);
        a.film().colours().collect::<Vec<_>>()
    };
    let reference = run(&with, 2048, 7);
    let mean = |v: &[DVec3]| v.iter().sum::<DVec3>() / v.len() as f64;
    let (a, b) = (mean(&reference), mean(&run(&without, 2048, 8)));
    assert!(
        (a - b).abs().max_element() < 0.02 * a.max_element(),
        "{a} vs {b}"
    );
    let e_with = rmse(&run(&with, 16, 1), &reference);
    let e_without = rmse(&run(&without, 16, 1), &reference);
    eprintln!("16 spp RMSE: {e_with} with environment sampling, {e_without} without");
    assert!(e_with < e_without);
}
