//! Pictures rendered by POV-Ray 3.7 (`povray +W80 +H60 -D -A`, committed next to
//! their scenes in `tests/reference/povray/`) against rts rendering the same text:
//! lights, cameras, fog and sky sphere. Regenerate a reference with
//! `povray +Iname.pov +Oname.png +W80 +H60 -D -A` in that folder.

use image::RgbImage;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Scenes rts matches only closely, with the largest allowed difference in 8-bit
/// levels and the share of pixels allowed to differ by more than one level.
const CLOSE: &[(&str, u8, f64)] = &[
    // The circular mapping and orient match; a few shadow-edge pixels differ.
    ("area_light_circular_orient", 64, 0.01),
    // POV-Ray speckles a few pixels on the rims where a quadric meets its cutting
    // plane (its polynomial solver near tangency); the surfaces match elsewhere.
    ("quadric_shapes", 128, 0.005),
    // One pixel 2 levels off where a camera ray grazes the see-through blob.
    ("blob_filter_shadow", 2, 0.001),
];

fn folder() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/reference/povray")
}

fn load(path: &Path) -> RgbImage {
    image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .to_rgb8()
}

#[test]
fn rts_matches_povray_pictures() {
    let out_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/povray_reference");
    std::fs::create_dir_all(&out_dir).unwrap();
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(folder())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "pov"))
        .collect();
    scenes.sort();
    assert!(scenes.len() >= 10);
    let mut failures = Vec::new();
    for scene in &scenes {
        let name = scene.file_stem().unwrap().to_str().unwrap().to_string();
        let out = out_dir.join(format!("{name}.png"));
        let status = Command::new(env!("CARGO_BIN_EXE_rts"))
            .arg("render")
            .arg(scene)
            .arg("-o")
            .arg(&out)
            .args(["-W", "80", "-H", "60", "-q"])
            .status()
            .expect("run rts");
        assert!(status.success(), "rts render {name} failed");
        let (a, b) = (load(&scene.with_extension("png")), load(&out));
        assert_eq!(a.dimensions(), b.dimensions());
        let (mut worst, mut off) = (0u8, 0usize);
        for (p, q) in a.pixels().zip(b.pixels()) {
            let d = (0..3).map(|i| p[i].abs_diff(q[i])).max().unwrap();
            worst = worst.max(d);
            off += usize::from(d > 1);
        }
        let share = off as f64 / (a.width() * a.height()) as f64;
        let (max, max_share) = CLOSE
            .iter()
            .find(|c| c.0 == name)
            .map_or((1, 0.0), |c| (c.1, c.2));
        if worst > max || share > max_share {
            failures.push(format!(
                "{name}: max {worst} levels, {:.2}% pixels off by more than 1 (new picture: {})",
                share * 100.0,
                out.display()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
