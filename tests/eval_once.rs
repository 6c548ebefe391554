//! Evaluating once what the clock does not touch (src/eval/core/reuse.rs): the
//! frames of an animation evaluated with one cache, reusing the top-level items
//! that read no per-frame value, give the scene and the messages a full
//! evaluation of each frame gives, for every example and fixture; and the
//! reuse does happen. The pictures through the binary are compared in
//! tests/animation.rs.

use rts::eval::{eval_cached, EvalCache, EvalOptions};
use rts::scene::Timeline;
use rts::source::SourceMap;
use std::path::{Path, PathBuf};

const FRAMES: i64 = 4;

/// The options of frame `n` of a 4-frame animation (clock 0 to 1).
fn frame(n: i64, reuse: bool) -> EvalOptions {
    let t = Timeline {
        final_frame: FRAMES,
        ..Timeline::default()
    };
    EvalOptions {
        clock: t.clock_of(n),
        clock_delta: t.clock_delta(),
        clock_on: true,
        frame_number: n as f64,
        initial_frame: 1.0,
        final_frame: FRAMES as f64,
        final_clock: 1.0,
        timeline: Some(t),
        image_width: 64.0,
        image_height: 48.0,
        reuse,
        ..EvalOptions::default()
    }
}

/// What one evaluation gives that a picture or a user sees: the scene and the
/// messages, as text.
fn shown(ev: &rts::eval::Evaluated) -> String {
    // Placement numbers differ by design (each evaluation of an item gives its
    // objects new ones); everything else must be the same.
    let mut scene = ev.scene.clone();
    scene.placed.clear();
    format!("{:?}\n{:?}", scene, ev.diagnostics)
}

/// Evaluates `path` for every frame with one cache (reuse on) and each frame
/// alone with reuse off; panics on the first difference. Returns the units
/// (replayed, evaluated) of the reusing run.
fn compare(path: &Path) -> (u64, u64) {
    // Deep recursion fixtures need the binary's big stack.
    let path = path.to_path_buf();
    std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(move || compare_here(&path))
        .unwrap()
        .join()
        .unwrap_or_else(|e| std::panic::resume_unwind(e))
}

fn compare_here(path: &Path) -> (u64, u64) {
    // (A fixture that is not UTF-8 text is refused before evaluation.)
    let Ok(text) = std::fs::read_to_string(path) else {
        return (0, 0);
    };
    let mut sources = SourceMap::new();
    let id = sources.add(
        path.display().to_string(),
        Some(path.to_path_buf()),
        text.clone(),
    );
    let (file, _) = rts::syntax::parse(&text, id);
    let mut cache = EvalCache::default();
    for n in 1..=FRAMES {
        let reused = shown(&eval_cached(
            &file,
            id,
            &mut sources,
            &frame(n, true),
            &mut cache,
        ));
        let full = shown(&eval_cached(
            &file,
            id,
            &mut sources,
            &frame(n, false),
            &mut EvalCache::default(),
        ));
        if reused != full {
            let at = reused
                .bytes()
                .zip(full.bytes())
                .position(|(a, b)| a != b)
                .unwrap_or(reused.len().min(full.len()));
            let lo = at.saturating_sub(200);
            panic!(
                "{}: frame {n} differs at byte {at}:\nreused: {}\nfull:   {}",
                path.display(),
                &reused[lo..(at + 200).min(reused.len())],
                &full[lo..(at + 200).min(full.len())]
            );
        }
    }
    cache.units()
}

fn scenes(dir: &str) -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let mut v: Vec<PathBuf> = std::fs::read_dir(&root)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "rts"))
        .collect();
    v.sort();
    v
}

#[test]
fn every_example_evaluates_the_same_with_reuse() {
    let mut replayed = 0;
    for p in scenes("examples") {
        replayed += compare(&p).0;
    }
    assert!(replayed > 0);
}

#[test]
fn every_fixture_evaluates_the_same_with_reuse() {
    for p in scenes("tests/fixtures/ok")
        .into_iter()
        .chain(scenes("tests/fixtures/err"))
    {
        compare(&p);
    }
}

/// A fresh folder for one test.
fn folder(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("rts_eval_once_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// What moves and what does not, side by side: a moving declaration read by a
/// later item, a conditional declaration, random streams drawn from by static
/// and moving items, macros that read the clock, a local of an include file
/// read through a deferred pigment, library colours first used by a moving item.
const TRICKY: &str = r#"#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "part.inc"
camera { location <0, 2, -5 + clock> look_at 0 }
light_source { <3, 5, -4>, White }
#declare S = seed(7);
#declare R0 = rand(S);
#declare X = 0;
#if (clock > 0.5) #declare X = 1; #end
sphere { <X, 0.5, 0>, 0.3 pigment { Red } }
#if (clock > 0.2) sphere { 0, 1 pigment { Orange } } #else sphere { 0, 1 pigment { Violet } } #end
sphere { 1, 1 pigment { Orange } }
sphere { 2, 1 pigment { Violet } }
#declare J = rand(S) * (1 + 0 * clock);
sphere { <-1, J, 0>, 0.2 pigment { Blue } }
#if (clock > 0.5) #declare Extra = rand(S); #end
#declare K = rand(S);
sphere { <1, K, 0>, 0.2 pigment { Green } }
#macro M(A) sphere { <A, clock, 1>, 0.1 pigment { Yellow } } #end
M(0.5)
#macro N(A) sphere { <A, 1, 1>, 0.1 pigment { Cyan } } #end
N(-0.5)
object { Tri translate y * -0.5 }
#declare I = 0;
#while (I < 5) sphere { <I / 5, -0.3, -1>, 0.05 pigment { rgb <I / 5, 0.2, Moving> } } #declare I = I + 1; #end
#ifdef (Late) sphere { 2, 0.1 } #end
#if (frame_number = 3) #declare Late = 1; #end
#ifdef (Late) sphere { -2, 0.1 } #end
#debug concat("R0=", str(R0, 0, 4), " J=", str(J, 0, 4), "\n")
#declare Unused_Static = 1;
"#;

const PART: &str = "#local Half = 0.5;
#declare Tri = mesh2 {
  vertex_vectors { 4, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  pigment { rgb Half }
}
#local Half = clock;
#declare Moving = Half;
#declare Tri2 = mesh2 {
  vertex_vectors { 3, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1> }
  face_indices { 1, <0, 1, 2> }
  pigment { rgb Half }
}
";

#[test]
fn moving_values_reach_what_reads_them() {
    let dir = folder("tricky");
    std::fs::write(dir.join("part.inc"), PART).unwrap();
    std::fs::write(dir.join("scene.rts"), TRICKY).unwrap();
    let (replayed, evaluated) = compare(&dir.join("scene.rts"));
    // The static items of frames 2-4 are replayed.
    assert!(
        replayed >= 3 * 8,
        "replayed {replayed}, evaluated {evaluated}"
    );
}

/// Runs the binary in `dir`; panics when it fails.
fn rts(dir: &Path, args: &[&str]) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rts"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("run rts");
    assert!(
        out.status.success(),
        "rts {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Frames 1-3 of `scene` (in `dir`) through the binary, written under `out`:
/// with reuse, with `--no-eval-cache`, and frame 2 as a `--frame` still, all
/// the same bytes.
fn same_pictures(dir: &Path, scene: &str, out: &Path) {
    let size = ["-W", "16", "-H", "12", "--samples", "1", "-q"];
    let run = |sub: &str, extra: &[&str]| {
        let pattern = out.join(sub).join("o_####.png");
        let pattern = pattern.to_str().unwrap();
        let mut a = vec!["render", scene, "-o", pattern, "--frames", "1..3"];
        a.extend_from_slice(&size);
        a.extend_from_slice(extra);
        rts(dir, &a);
    };
    run("reuse", &[]);
    run("full", &["--no-eval-cache"]);
    let still = out.join("still.png");
    let mut a = vec!["render", scene, "-o", still.to_str().unwrap()];
    a.extend_from_slice(&["--frames", "1..3", "--frame", "2"]);
    a.extend_from_slice(&size);
    rts(dir, &a);
    for k in 1..=3 {
        let name = format!("o_{k:04}.png");
        let reused = std::fs::read(out.join("reuse").join(&name)).unwrap();
        let full = std::fs::read(out.join("full").join(&name)).unwrap();
        assert!(reused == full, "{scene}: frame {k} differs with reuse");
        if k == 2 {
            assert!(
                std::fs::read(&still).unwrap() == reused,
                "{scene}: frame 2 differs from the --frame 2 still"
            );
        }
    }
}

/// Many objects standing still and one moving: from the second frame the
/// world's tree comes in two levels (the still ones' tree kept). Every sphere
/// is there twice, red then blue, so every hit is a tie the tree must not
/// decide: the still (one tree, built whole) must show the same red.
const TWO_LEVELS: &str = r#"
#version 3.7;
animation { frames 3 }
camera { location <0, 6, -14> look_at <0, 0, 0> }
light_source { <5, 10, -5>, rgb 1 }
#for (I, 0, 119)
  #local P = <mod(I, 12) - 5.5, 0, div(I, 12) - 4.5>;
  sphere { P, 0.45 pigment { rgb <1, 0, 0> } }
  sphere { P, 0.45 pigment { rgb <0, 0, 1> } }
#end
sphere { <-6 + 12 * clock, 1, 0>, 0.8 pigment { rgb 1 } }
"#;

#[test]
fn animation_frames_are_the_same_bytes_with_reuse() {
    let out = folder("pictures");
    let tricky = folder("tricky_pictures");
    std::fs::write(tricky.join("part.inc"), PART).unwrap();
    std::fs::write(tricky.join("scene.rts"), TRICKY).unwrap();
    same_pictures(&tricky, "scene.rts", &out.join("tricky"));
    std::fs::write(tricky.join("two_levels.rts"), TWO_LEVELS).unwrap();
    same_pictures(&tricky, "two_levels.rts", &out.join("two_levels"));
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let animated = |p: &PathBuf| {
        std::fs::read_to_string(p).is_ok_and(|t| {
            ["clock", "frame_number", "keyframes", "camera_path", "seed("]
                .iter()
                .any(|w| t.contains(w))
        })
    };
    for dir in ["examples", "tests/fixtures/ok"] {
        for p in scenes(dir).into_iter().filter(animated) {
            let name = p.file_name().unwrap().to_str().unwrap();
            same_pictures(&root.join(dir), name, &out.join(name));
        }
    }
}
