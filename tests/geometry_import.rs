//! Meshes read from files (OBJ, PLY, PNG height fields): contents, the read
//! sandbox and missing files.

use rts::build::{build, Ray, RayKind};
use rts::eval::{eval, EvalOptions};
use rts::scene::Shape;
use rts::source::SourceMap;
use std::path::{Path, PathBuf};

/// A fresh folder for one test.
fn folder(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("rts_geom_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Evaluates `text` as the scene file `dir/scene.rts`: scene and diagnostic codes.
fn run(dir: &Path, text: &str) -> (rts::scene::Scene, Vec<String>) {
    let path = dir.join("scene.rts");
    std::fs::write(&path, text).unwrap();
    let mut sources = SourceMap::new();
    let id = sources.add("scene.rts", Some(path), text.to_string());
    let (file, diags) = rts::syntax::parse(text, id);
    assert!(diags.is_empty(), "{diags:?}");
    let out = eval(&file, id, &mut sources, &EvalOptions::default());
    let codes = out
        .diagnostics
        .iter()
        .filter(|d| !d.code.starts_with("rts::lint"))
        .map(|d| d.code.to_string())
        .collect();
    (out.scene, codes)
}

fn triangles(s: &rts::scene::Scene, k: usize) -> usize {
    match &s.objects[k].shape {
        Shape::Mesh(m) => m.triangles.len(),
        other => panic!("not a mesh: {other:?}"),
    }
}

const CUBE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

const TET_PLY: &str =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n\
0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

#[test]
fn obj_and_ply_meshes_load_and_are_solid_with_inside_vector() {
    let d = folder("objply");
    std::fs::write(d.join("cube.obj"), CUBE_OBJ).unwrap();
    std::fs::write(d.join("tet.ply"), TET_PLY).unwrap();
    let (scene, codes) = run(
        &d,
        "mesh { obj_file \"cube.obj\" inside_vector y }\nmesh { ply_file \"tet.ply\" translate 5*x }\n",
    );
    assert!(codes.is_empty(), "{codes:?}");
    assert_eq!(triangles(&scene, 0), 12); // quads are triangulated
    assert_eq!(triangles(&scene, 1), 4);
    let w = build(&scene);
    assert!(w.inside(glam::DVec3::splat(0.5)));
    assert!(!w.inside(glam::DVec3::new(5.1, 0.1, 0.1))); // no inside_vector: not solid
    let hit = w
        .intersect(
            &Ray::new(glam::DVec3::new(0.5, 0.5, -3.0), glam::DVec3::Z),
            0.0,
            f64::INFINITY,
            RayKind::Camera,
        )
        .unwrap();
    assert!((hit.t - 3.0).abs() < 1e-6);
}

#[test]
fn files_outside_the_sandbox_or_missing_are_diagnostics() {
    let d = folder("sandbox");
    let sub = d.join("sub");
    std::fs::create_dir_all(&sub).unwrap();
    std::fs::write(d.join("cube.obj"), CUBE_OBJ).unwrap();
    let (_, codes) = run(
        &sub,
        "mesh { obj_file \"../cube.obj\" }\nmesh { ply_file \"missing.ply\" }\nheight_field { png \"none.png\" }\n",
    );
    assert_eq!(
        codes,
        vec![
            "rts::io::file_not_allowed",
            "rts::io::file_not_found",
            "rts::io::file_not_found"
        ]
    );
}

#[test]
fn height_field_spans_the_unit_square() {
    let d = folder("hf");
    // 3×2 image: heights 0, 128, 255 in the top row, 64 in the bottom row.
    let mut img = image::GrayImage::new(3, 2);
    for (i, v) in [0u8, 128, 255].into_iter().enumerate() {
        img.put_pixel(i as u32, 0, image::Luma([v]));
        img.put_pixel(i as u32, 1, image::Luma([64]));
    }
    img.save(d.join("hf.png")).unwrap();
    let (scene, codes) = run(&d, "height_field { png \"hf.png\" smooth }\n");
    assert!(codes.is_empty(), "{codes:?}");
    assert_eq!(triangles(&scene, 0), 4);
    let w = build(&scene);
    // The top image row is at z = 1; its right pixel is the highest (255/256).
    let down = |x: f64, z: f64| {
        w.intersect(
            &Ray::new(glam::DVec3::new(x, 5.0, z), -glam::DVec3::Y),
            0.0,
            f64::INFINITY,
            RayKind::Camera,
        )
        .map(|h| 5.0 - h.t)
    };
    assert!((down(1.0 - 1e-9, 1.0 - 1e-9).unwrap() - 255.0 * 257.0 / 65536.0).abs() < 1e-4);
    assert!((down(1e-9, 1e-9).unwrap() - 64.0 * 257.0 / 65536.0).abs() < 1e-4);
    assert!(down(1.5, 0.5).is_none());
    assert!(w.inside(glam::DVec3::new(0.9, 0.01, 0.5)));
    assert!(!w.inside(glam::DVec3::new(0.9, 0.99, 0.5)));
}

#[test]
fn a_declared_mesh_placed_many_times_is_stored_once() {
    let d = folder("instances");
    let (scene, codes) = run(
        &d,
        "#declare M = mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }\n\
         #for (I, 0, 9) object { M translate I*x } #end\n\
         object { M rotate 30*y pigment { rgb 1 } }\n",
    );
    assert!(codes.is_empty(), "{codes:?}");
    assert_eq!(scene.objects.len(), 11);
    let first = match &scene.objects[0].shape {
        Shape::Mesh(m) => m.clone(),
        _ => panic!("not a mesh"),
    };
    for o in &scene.objects {
        match &o.shape {
            Shape::Mesh(m) => assert!(std::sync::Arc::ptr_eq(m, &first)),
            _ => panic!("not a mesh"),
        }
    }
    let w = build(&scene);
    assert_eq!(w.primitives.len(), 11);
}
