//! The geometry scenes of tests/fixtures/ok/geometry_*.rts are valid POV-Ray: when
//! `povray` is installed, render each with both at 160×120 (no antialiasing)
//! and require the pictures to agree (skipped, with a note, without POV-Ray).

use std::path::{Path, PathBuf};
use std::process::Command;

fn povray_available() -> bool {
    Command::new("povray")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success() || !o.stderr.is_empty())
}

fn pixels(p: &Path) -> Vec<u8> {
    image::open(p).unwrap().to_rgb8().into_raw()
}

/// (max, mean) per-channel difference in 0..255.
fn diff(a: &Path, b: &Path) -> (u8, f64) {
    let (a, b) = (pixels(a), pixels(b));
    assert_eq!(a.len(), b.len());
    let mut max = 0u8;
    let mut sum = 0u64;
    for (x, y) in a.iter().zip(&b) {
        let d = x.abs_diff(*y);
        max = max.max(d);
        sum += d as u64;
    }
    (max, sum as f64 / a.len() as f64)
}

fn render_both(name: &str) -> Option<(u8, f64)> {
    if !povray_available() {
        eprintln!("povray not installed: skipping the comparison of {name}");
        return None;
    }
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/ok")
        .join(name);
    let dir = std::env::temp_dir().join(format!("rts_geom_pov_{}_{}", name, std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let pov_scene = dir.join("scene.pov");
    std::fs::copy(&src, &pov_scene).unwrap();
    let (ours, theirs) = (dir.join("rts.png"), dir.join("pov.png"));
    let st = Command::new(env!("CARGO_BIN_EXE_rts"))
        .args([
            "render",
            src.to_str().unwrap(),
            "-W",
            "160",
            "-H",
            "120",
            "-o",
        ])
        .arg(&ours)
        .output()
        .unwrap();
    assert!(
        st.status.success(),
        "{}",
        String::from_utf8_lossy(&st.stderr)
    );
    let st = Command::new("povray")
        .current_dir(&dir)
        .args([
            "+Iscene.pov",
            "+Opov.png",
            "+W160",
            "+H120",
            "-D",
            "-A",
            "+FN8",
        ])
        .output()
        .unwrap();
    assert!(
        st.status.success(),
        "{}",
        String::from_utf8_lossy(&st.stderr)
    );
    Some(diff(&ours, &theirs))
}

#[test]
fn shapes_and_csg_match_povray() {
    // cylinder, cone, torus, disc, open cylinder, merge, intersection, difference.
    if let Some((max, mean)) = render_both("geometry_shapes.rts") {
        eprintln!("geometry_shapes: max {max}, mean {mean:.4}");
        assert!(mean < 0.05 && max <= 8, "max {max}, mean {mean}");
    }
}

#[test]
fn meshes_and_clipping_match_povray() {
    // mesh (instanced, per-triangle texture, inside_vector), mesh2 (smooth normals,
    // texture_list), smooth_triangle, polygon with a hole, clipped_by, inverse.
    if let Some((max, mean)) = render_both("geometry_meshes.rts") {
        eprintln!("geometry_meshes: max {max}, mean {mean:.4}");
        assert!(mean < 0.05 && max <= 8, "max {max}, mean {mean}");
    }
}

#[test]
fn nested_csg_member_textures_and_clipping_match_povray() {
    // difference of an intersection and a merge with textured members, a torus
    // halved by an inverse plane, a sharp cone, a clipped union, inverse spheres.
    if let Some((max, mean)) = render_both("geometry_csg.rts") {
        eprintln!("geometry_csg: max {max}, mean {mean:.4}");
        assert!(mean < 0.05 && max <= 8, "max {max}, mean {mean}");
    }
}
