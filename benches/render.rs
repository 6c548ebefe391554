#![allow(missing_docs)] // criterion_group! generates an undocumented function
//! Render speed: scenes of the POV-Ray comparison (`tests/compare/scenes`) at 160×120, through
//! the library API (parse → eval → build → render). The scene is read and evaluated once; each
//! iteration builds the world and renders it. A scene that this build cannot read yet (a
//! feature not implemented: `rts::eval::unsupported`) is skipped with a note on stderr.
//! How this compares with POV-Ray is measured by `tests/compare/compare.py` (its rts/POV column).
//! Run with `cargo bench --bench render`.

use criterion::{criterion_group, criterion_main, Criterion};
use rts::eval::{eval, load_file, EvalOptions};
use rts::render::{render, RenderOptions};
use rts::scene::Scene;
use rts::source::{FileAccess, SourceMap};
use std::path::{Path, PathBuf};

/// The scenes measured: the basics, 900 reflective spheres, CSG, glass, patterns, lights, the
/// standard includes.
const SCENES: &[&str] = &[
    "basic_shapes",
    "speed_spheres",
    "csg",
    "glass",
    "patterns_regular",
    "lights",
    "includes",
];
const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;

fn compare_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/compare")
}

/// The evaluated scene, or the first error's message when this build cannot read it.
fn load(name: &str) -> Result<Scene, String> {
    let path = compare_dir().join("scenes").join(format!("{name}.pov"));
    let mut sources = SourceMap::new();
    let id = load_file(&mut sources, &path, path.display().to_string())
        .map_err(|_| format!("cannot read {}", path.display()))?;
    let text = sources.get(id).text.clone();
    let (file, mut diags) = rts::syntax::parse(&text, id);
    let options = EvalOptions {
        access: FileAccess {
            allowed: vec![compare_dir().join("assets")],
            ..FileAccess::default()
        },
        image_width: f64::from(WIDTH),
        image_height: f64::from(HEIGHT),
        ..EvalOptions::default()
    };
    if !rts::diag::has_errors(&diags) {
        let evaluated = eval(&file, id, &mut sources, &options);
        diags.extend(evaluated.diagnostics);
        if !rts::diag::has_errors(&diags) {
            return Ok(evaluated.scene);
        }
    }
    let first = diags.iter().find(|d| d.is_error()).expect("an error");
    Err(format!("[{}] {}", first.code, first.message))
}

fn scenes(c: &mut Criterion) {
    let mut g = c.benchmark_group("render 160x120");
    g.sample_size(10);
    for name in SCENES {
        let scene = match load(name) {
            Ok(s) => s,
            Err(e) => {
                eprintln!("skipping {name}: {e}");
                continue;
            }
        };
        let opts = RenderOptions {
            width: WIDTH,
            height: HEIGHT,
        };
        g.bench_function(*name, |b| {
            b.iter(|| render(&rts::build::build(&scene), &opts))
        });
    }
    g.finish();
}

criterion_group!(benches, scenes);
criterion_main!(benches);
