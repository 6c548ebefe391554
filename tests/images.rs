//! Image files read by scenes: each file decoded once and shared by every map
//! that reads it (within an evaluation and across the frames of an animation),
//! and refused over `--max-image-pixels` from its header, before decoding.

use rts::eval::{eval_cached, EvalCache, EvalOptions};
use rts::scene::{Pattern, Picture, Shape};
use rts::source::SourceMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Arc;

/// A fresh folder for one test.
fn folder(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("rts_images_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A `w`×`h` RGB picture with some variation.
fn write_png(path: &Path, w: u32, h: u32) {
    image::RgbImage::from_fn(w, h, |x, y| image::Rgb([(x * 7) as u8, (y * 5) as u8, 90]))
        .save(path)
        .unwrap();
}

/// The scene file `dir/scene.rts` parsed, ready to be evaluated.
fn parse(dir: &Path, text: &str) -> (SourceMap, rts::span::FileId, rts::syntax::ast::File) {
    let path = dir.join("scene.rts");
    std::fs::write(&path, text).unwrap();
    let mut sources = SourceMap::new();
    let id = sources.add("scene.rts", Some(path), text.to_string());
    let (file, diags) = rts::syntax::parse(text, id);
    assert!(diags.is_empty(), "{diags:?}");
    (sources, id, file)
}

/// The pictures of every image map in `scene` (top-level objects' pigments).
fn pictures(scene: &rts::scene::Scene) -> Vec<Arc<Picture>> {
    scene
        .objects
        .iter()
        .filter_map(|o| o.texture.as_ref())
        .filter_map(|t| match &t.pigment.pattern {
            Pattern::Image(im) => Some(im.picture.clone()),
            _ => None,
        })
        .collect()
}

const LOOP: &str = "#version 3.7;
global_settings { assumed_gamma 1.0 }
#for (I, 0, 49)
  box { <I, 0, 0>, <I + 1, 1, 1> pigment { image_map { png \"a.png\" interpolate 2 } } }
#end
plane { z, 0 pigment { image_pattern { png \"a.png\" } } normal { bump_map { png \"a.png\" } } }
height_field { png \"a.png\" }
";

#[test]
fn a_file_read_fifty_times_is_decoded_once_and_shared() {
    let d = folder("once");
    write_png(&d.join("a.png"), 40, 30);
    let (mut sources, id, file) = parse(&d, LOOP);
    let mut cache = EvalCache::default();
    let opts = EvalOptions::default();
    let first = eval_cached(&file, id, &mut sources, &opts, &mut cache);
    assert!(
        !rts::diag::has_errors(&first.diagnostics),
        "{:?}",
        first.diagnostics
    );
    assert_eq!(cache.images_decoded(), 1);
    let pics = pictures(&first.scene);
    assert_eq!(pics.len(), 50);
    assert!(pics.iter().all(|p| Arc::ptr_eq(p, &pics[0])));
    assert_eq!((pics[0].width(), pics[0].height()), (40, 30));
    // 8-bit RGB is kept as 3 bytes a pixel.
    assert_eq!(pics[0].bytes(), 40 * 30 * 3);
    assert!(matches!(first.scene.objects[51].shape, Shape::Mesh(_)));

    // The next frame reuses the decoded file.
    let second = eval_cached(&file, id, &mut sources, &opts, &mut cache);
    assert!(!rts::diag::has_errors(&second.diagnostics));
    assert_eq!(cache.images_decoded(), 1);
    assert!(Arc::ptr_eq(&pictures(&second.scene)[0], &pics[0]));

    // A file that changed is read again.
    write_png(&d.join("a.png"), 41, 30);
    let third = eval_cached(&file, id, &mut sources, &opts, &mut cache);
    assert!(!rts::diag::has_errors(&third.diagnostics));
    assert_eq!(cache.images_decoded(), 2);
    assert_eq!(pictures(&third.scene)[0].width(), 41);
}

#[test]
fn the_pixel_budget_counts_each_file_once_across_frames() {
    let d = folder("budget");
    write_png(&d.join("a.png"), 40, 30);
    write_png(&d.join("b.png"), 20, 10);
    let text = "plane { z, 0 pigment { image_map { png \"a.png\" } } }
plane { z, 1 pigment { image_map { png \"a.png\" } } }
plane { z, 2 pigment { image_map { png \"b.png\" } } }
";
    let (mut sources, id, file) = parse(&d, text);
    let codes = |max: u64, sources: &mut SourceMap, cache: &mut EvalCache| -> Vec<String> {
        let opts = EvalOptions {
            max_image_pixels: max,
            ..EvalOptions::default()
        };
        eval_cached(&file, id, sources, &opts, cache)
            .diagnostics
            .iter()
            .filter(|d| d.severity == rts::diag::Severity::Error)
            .map(|d| d.code.to_string())
            .collect()
    };
    // 40×30 + 20×10 = 1400 pixels: enough, in every frame.
    let mut cache = EvalCache::default();
    for _ in 0..3 {
        assert!(codes(1400, &mut sources, &mut cache).is_empty());
    }
    // One pixel fewer refuses the second file.
    let mut cache = EvalCache::default();
    assert_eq!(
        codes(1399, &mut sources, &mut cache),
        ["rts::limit::image_pixels"]
    );
    // Also when the files were decoded by an earlier frame with a larger budget.
    let mut cache = EvalCache::default();
    assert!(codes(1400, &mut sources, &mut cache).is_empty());
    assert_eq!(
        codes(1399, &mut sources, &mut cache),
        ["rts::limit::image_pixels"]
    );
}

fn rts(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rts"))
        .args(args)
        .output()
        .expect("run rts");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn an_image_over_max_image_pixels_is_refused_at_its_name() {
    let d = folder("cli");
    write_png(&d.join("a.png"), 40, 30);
    let scene = d.join("scene.pov");
    std::fs::write(
        &scene,
        "camera { location -z look_at 0 }\nplane { z, 0 pigment { image_map { png \"a.png\" } } }\n",
    )
    .unwrap();
    let s = scene.display().to_string();
    let (code, out, _) = rts(&[
        "check",
        &s,
        "--max-image-pixels",
        "1000",
        "--message-format",
        "json",
    ]);
    assert_eq!(code, 1, "{out}");
    let diag: serde_json::Value = out
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
        .find(|v| v["severity"] == "error")
        .expect("an error");
    assert_eq!(diag["code"], "rts::limit::image_pixels");
    // The span is the file name: line 2, from its opening quote.
    assert_eq!(diag["line"], 2);
    assert_eq!(diag["column"], 40);
    assert_eq!(diag["end_column"], 47);
    let message = diag["message"].as_str().unwrap();
    assert!(message.contains("40×30 = 1200 pixels"), "{message}");
    assert!(diag["help"]
        .as_str()
        .unwrap()
        .contains("--max-image-pixels 1200"));
    // Exactly enough renders.
    let out_png = d.join("out.png").display().to_string();
    let (code, _, err) = rts(&[
        "render",
        &s,
        "--max-image-pixels",
        "1200",
        "-W",
        "8",
        "-H",
        "6",
        "-o",
        &out_png,
        "-q",
    ]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn a_huge_header_is_refused_before_decoding() {
    // A PNG whose header claims 100000 × 100000 RGBA pixels (40 GB decoded)
    // over a few bytes of data: refused from the header by the default budget.
    let d = folder("huge");
    let mut png = Vec::new();
    {
        let mut e = png::Encoder::new(&mut png, 100_000, 100_000);
        e.set_color(png::ColorType::Rgba);
        // Only the header (and the IEND the writer adds when dropped): the
        // image data is missing.
        drop(e.write_header().unwrap());
    }
    std::fs::write(d.join("huge.png"), &png).unwrap();
    let scene = d.join("scene.pov");
    std::fs::write(
        &scene,
        "plane { z, 0 pigment { image_map { png \"huge.png\" } } }\n",
    )
    .unwrap();
    let (code, out, _) = rts(&[
        "check",
        &scene.display().to_string(),
        "--message-format",
        "short",
    ]);
    assert_eq!(code, 1);
    assert!(out.contains("error[rts::limit::image_pixels]"), "{out}");
    assert!(out.contains("100000×100000"), "{out}");
}
