//! Portability: the same picture, byte for byte, at every SIMD level the
//! traversal kernels run at (`--simd scalar`, `v3`, `v4`, `auto`, and
//! `RTS_SIMD=scalar`) and on 1 or 2 threads. Levels the processor lacks fall back
//! to the best it has, so the test runs everywhere and proves most where AVX2
//! and AVX-512 exist. The scenes cover the wide tree over a world (spheres, CSG,
//! glass with shadows), large meshes (height field, meshes), and the path
//! tracer's flat list (Cornell box).

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The PNG bytes of `scene` rendered small with `args` (and `env`).
fn render(scene: &str, args: &[&str], env: Option<(&str, &str)>, out: &Path) -> Vec<u8> {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_rts"));
    cmd.arg("render")
        .arg(root().join("examples").join(scene))
        .arg("-o")
        .arg(out)
        .args(["-W", "80", "-H", "60", "-q"])
        .args(args)
        .env_remove("RTS_SIMD");
    if let Some((k, v)) = env {
        cmd.env(k, v);
    }
    let status = cmd.status().expect("run rts");
    assert!(status.success(), "rts render {scene} {args:?} failed");
    std::fs::read(out).expect("read the picture")
}

#[test]
fn every_simd_level_and_thread_count_gives_the_same_bytes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scenes: &[(&str, &[&str])] = &[
        ("showcase.rts", &["--antialias", "0.3"]),
        ("csg.rts", &[]),
        ("glass.rts", &[]),
        ("height_field.rts", &[]),
        ("meshes.rts", &[]),
        ("cornell_box.rts", &["--integrator", "path", "--spp", "4"]),
    ];
    for (scene, extra) in scenes {
        let out = dir.path().join("x.png");
        let with = |more: &[&str], env| {
            let args: Vec<&str> = extra.iter().chain(more).copied().collect();
            render(scene, &args, env, &out)
        };
        let reference = with(&["--simd", "scalar", "--threads", "1"], None);
        for (more, env) in [
            (&["--simd", "auto", "--threads", "1"][..], None),
            (&["--simd", "auto", "--threads", "2"][..], None),
            (&["--simd", "v3", "--threads", "2"][..], None),
            (&["--simd", "v4", "--threads", "2"][..], None),
            (&["--threads", "2"][..], Some(("RTS_SIMD", "scalar"))),
        ] {
            assert!(
                with(more, env) == reference,
                "{scene} {extra:?}: {more:?} {env:?} differs from --simd scalar on 1 thread"
            );
        }
    }
}

#[test]
fn an_unknown_simd_level_is_a_usage_error() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("x.png");
    for (args, env) in [
        (&["--simd", "sse9"][..], None),
        (&[][..], Some(("RTS_SIMD", "fast"))),
    ] {
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_rts"));
        cmd.arg("render")
            .arg(root().join("examples/csg.rts"))
            .arg("-o")
            .arg(&out)
            .args(["-W", "8", "-H", "6", "-q"])
            .args(args)
            .env_remove("RTS_SIMD");
        if let Some((k, v)) = env {
            cmd.env(k, v);
        }
        let o = cmd.output().expect("run rts");
        assert_eq!(o.status.code(), Some(2), "{args:?} {env:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains("scalar"), "names the levels: {err}");
    }
}
