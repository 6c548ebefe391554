//! What the fuzz targets, `tests/fuzz_findings.rs` and `tests/no_panic.rs` share:
//! the asset folder scenes are read "from", the small evaluation budgets, the
//! bounds on what a scene may ask of a tiny render, and a one-thread pool with a
//! big stack that every run uses (as the CLI runs scenes on big stacks).
#![allow(dead_code)]

use rts::eval::{eval, EvalOptions, Evaluated};
use rts::render::{Antialias, Pass, RenderOptions, Sampling, Settings};
use rts::scene::{PhotonDensity, Scene};
use rts::source::SourceMap;
use std::path::PathBuf;
use std::sync::OnceLock;

/// `fuzz/assets/`: a tiny PNG, OBJ, PLY, TTF, include file and data file.
pub fn assets() -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    // The fuzz crate's manifest is in fuzz/, the tests' in the repository.
    if root.join("assets").is_dir() {
        root.join("assets")
    } else {
        root.join("fuzz/assets")
    }
}

/// The scene is evaluated as `fuzz/assets/fuzz.rts` (a file that does not
/// exist), so `#include "tiny.inc"`, `png "tiny.png"`, `obj_file "tiny.obj"`,
/// `ply_file "tiny.ply"`, `ttf "tiny.ttf"` and `#fopen F "tiny.txt" read`
/// find them; `#write` never reaches the disk (`write_files` is off).
pub fn scene_path() -> PathBuf {
    assets().join("fuzz.rts")
}

/// Budgets small enough that one run stays well under a second.
pub fn options() -> EvalOptions {
    EvalOptions {
        image_width: 8.0,
        image_height: 6.0,
        max_loop_iterations: 100_000,
        max_macro_depth: 100,
        max_macro_calls: 100_000,
        max_include_depth: 16,
        max_array_size: 1 << 14,
        max_object_depth: 200,
        max_memory: 256 << 20,
        max_string_length: 1 << 20,
        max_errors: 20,
        max_write: 1 << 20,
        max_source_size: 1 << 20,
        write_files: false,
        ..EvalOptions::default()
    }
}

/// The stack of the thread every run uses (the CLI's is 512 MiB; the budgets
/// above recurse far less deep).
const STACK_SIZE: usize = 256 << 20;

/// Runs `f` on the one worker of a one-thread rayon pool, so that rendering's
/// parallel loops run on the same big-stack thread, in order. A panic in `f`
/// reaches the caller.
pub fn on_big_stack<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    static POOL: OnceLock<rayon::ThreadPool> = OnceLock::new();
    POOL.get_or_init(|| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .stack_size(STACK_SIZE)
            .build()
            .expect("one fuzzing thread")
    })
    .install(f)
}

/// Whether `RTS_FUZZ_SHOW` is set: then diagnostics are printed (to see what an
/// input does when run by hand, `fuzz/target/…/render FILE`).
fn show() -> bool {
    static SHOW: OnceLock<bool> = OnceLock::new();
    *SHOW.get_or_init(|| std::env::var_os("RTS_FUZZ_SHOW").is_some())
}

/// Parses and, when the text parses, evaluates `text` as the asset folder's
/// scene; renders every diagnostic as a user would see it. `None` when the text
/// does not parse. Inputs of odd length are read as `rts render` reads them
/// (long branch bodies read when taken), the others as `rts check` does.
pub fn parse_eval(text: &str) -> Option<Evaluated> {
    let mut sources = SourceMap::new();
    let id = sources.add("fuzz.rts", Some(scene_path()), text.to_string());
    let render = text.len() % 2 == 1;
    let (file, diags) = rts::syntax::parse_with(text, id, 0, render);
    if rts::diag::has_errors(&diags) {
        for d in &diags {
            let line = rts::diag::render::short(d, &sources);
            if show() {
                eprintln!("{line}");
            }
        }
        return None;
    }
    let options = EvalOptions {
        defer_branches: render,
        describe_globals: !render,
        ..options()
    };
    let out = eval(&file, id, &mut sources, &options);
    for d in &out.diagnostics {
        let line = rts::diag::render::short(d, &sources);
        if show() {
            eprintln!("{line}");
        }
    }
    Some(out)
}

/// The picture: small, so one run stays near a millisecond or two.
pub const SIZE: RenderOptions = RenderOptions {
    width: 8,
    height: 6,
};

/// Holds settings that multiply the work of every pixel to what a tiny
/// picture needs (the scene asked for them; the fuzzer looks for crashes and
/// hangs, not for long renders the user chose).
pub fn bound(scene: &mut Scene) {
    let g = &mut scene.global;
    g.max_trace_level = g.max_trace_level.min(5);
    if let Some(p) = &mut g.photons {
        p.density = match p.density {
            PhotonDensity::Count(n) => PhotonDensity::Count(n.min(300)),
            PhotonDensity::Spacing(_) => PhotonDensity::Count(300),
        };
        p.gather_max = p.gather_max.min(50);
        p.gather_min = p.gather_min.min(p.gather_max);
        p.max_trace_level = p.max_trace_level.map(|m| m.min(5));
    }
    if let Some(r) = &mut g.radiosity {
        r.count = r.count.min(16);
        r.count_pool = r.count_pool.clamp(r.count, 64);
        r.recursion_limit = r.recursion_limit.min(2);
    }
    if let Some(p) = &mut g.path_tracing {
        p.max_depth = p.max_depth.min(4);
    }
    let cam = &mut scene.camera;
    cam.blur_samples = cam.blur_samples.min(4);
    cam.blur_min_samples = cam.blur_min_samples.min(cam.blur_samples);
    for light in &mut scene.lights {
        if let Some(a) = &mut light.area {
            a.size1 = a.size1.min(4);
            a.size2 = a.size2.min(4);
            a.adaptive = a.adaptive.map(|n| n.min(1));
        }
    }
}

/// Builds `scene` (after [`bound`]) and renders it at [`SIZE`]: the classic
/// renderer with adaptive anti-aliasing and `pass`, then the path tracer at
/// one sample per pixel.
pub fn build_render(mut scene: Scene, pass: Pass) {
    bound(&mut scene);
    let world = rts::build::build(&scene);
    let settings = Settings {
        sampling: Sampling::Adaptive(Antialias {
            threshold: 0.3,
            depth: 2,
            jitter: 1.0,
            gamma: 2.5,
        }),
        pass,
        ..Settings::default()
    };
    let _ = rts::render::render_with(&world, &SIZE, &settings, None);
    let popts = rts::render::path::PathOptions {
        max_depth: 4,
        ..rts::render::path::PathOptions::default()
    };
    let _ = rts::render::path::render(&world, &SIZE, &Settings::default(), &popts, 1);
}

/// The whole pipeline on `text`: parse, evaluate, and when the scene has no
/// errors, [`build_render`] with a pass chosen by `choice` (mostly the shaded
/// picture). Whether it got as far as rendering.
pub fn pipeline(text: &str, choice: usize) -> bool {
    let Some(out) = parse_eval(text) else {
        return false;
    };
    if rts::diag::has_errors(&out.diagnostics) {
        return false;
    }
    let pass = match choice % 8 {
        0 => Pass::Depth { max: None },
        1 => Pass::Normal,
        2 => Pass::Albedo,
        _ => Pass::Beauty,
    };
    build_render(out.scene, pass);
    true
}
