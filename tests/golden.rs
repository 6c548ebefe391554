//! Golden images: every example rendered small through the binary and compared with
//! `tests/golden/<name>.png` within a tolerance (platform float differences may move a
//! few pixels by a level or two at edges; a change in shading moves many).
//!
//! On a mismatch the test writes the new picture and an amplified difference image to
//! `target/golden/` and names them. After an intended change, regenerate with
//! `RTS_BLESS=1 cargo test --release --test golden` and look at the pictures before
//! committing them.

use image::RgbImage;
use std::path::{Path, PathBuf};
use std::process::Command;

const WIDTH: u32 = 96;
const HEIGHT: u32 = 72;
/// Largest difference of one channel, in 8-bit levels.
const MAX_LEVELS: u8 = 24;
/// Share of pixels allowed to differ by more than 2 levels.
const MAX_CHANGED: f64 = 0.01;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn render(scene: &Path, out: &Path) {
    let status = Command::new(env!("CARGO_BIN_EXE_rts"))
        .arg("render")
        .arg(scene)
        .arg("-o")
        .arg(out)
        .args(["-W", &WIDTH.to_string(), "-H", &HEIGHT.to_string(), "-q"])
        .status()
        .expect("run rts");
    assert!(status.success(), "rts render {} failed", scene.display());
}

fn load(path: &Path) -> RgbImage {
    image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .to_rgb8()
}

/// (largest channel difference, share of pixels off by more than 2 levels, diff image)
fn compare(want: &RgbImage, got: &RgbImage) -> (u8, f64, RgbImage) {
    let mut max = 0u8;
    let mut changed = 0usize;
    let mut diff = RgbImage::new(want.width(), want.height());
    for ((a, b), d) in want.pixels().zip(got.pixels()).zip(diff.pixels_mut()) {
        let mut px = 0u8;
        for c in 0..3 {
            let delta = a.0[c].abs_diff(b.0[c]);
            px = px.max(delta);
            d.0[c] = delta.saturating_mul(8);
        }
        max = max.max(px);
        if px > 2 {
            changed += 1;
        }
    }
    let share = changed as f64 / (want.width() * want.height()) as f64;
    (max, share, diff)
}

#[test]
fn examples_match_their_golden_images() {
    let bless = std::env::var_os("RTS_BLESS").is_some();
    let out_dir = root().join("target/golden");
    std::fs::create_dir_all(&out_dir).expect("target/golden");
    let mut failures = Vec::new();
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(root().join("examples"))
        .expect("examples/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "rts"))
        .collect();
    scenes.sort();
    assert!(!scenes.is_empty());
    for scene in scenes {
        let name = scene.file_stem().unwrap().to_string_lossy().to_string();
        let golden = root().join("tests/golden").join(format!("{name}.png"));
        let got_path = out_dir.join(format!("{name}.png"));
        render(&scene, &got_path);
        if bless {
            std::fs::copy(&got_path, &golden).expect("write golden");
            continue;
        }
        assert!(
            golden.exists(),
            "no golden image for {name}: run RTS_BLESS=1 cargo test --release --test golden"
        );
        let want = load(&golden);
        let got = load(&got_path);
        assert_eq!(want.dimensions(), got.dimensions(), "{name}: size");
        let (max, share, diff) = compare(&want, &got);
        if max > MAX_LEVELS || share > MAX_CHANGED {
            let diff_path = out_dir.join(format!("{name}.diff.png"));
            diff.save(&diff_path).expect("write diff");
            failures.push(format!(
                "{name}: max difference {max} levels, {:.2}% of pixels changed; see {} and {}",
                share * 100.0,
                got_path.display(),
                diff_path.display()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_comparison_catches_a_changed_picture() {
    let a = RgbImage::from_pixel(10, 10, image::Rgb([100, 100, 100]));
    let mut b = a.clone();
    assert_eq!(compare(&a, &b).0, 0);
    for x in 0..10 {
        b.put_pixel(x, 0, image::Rgb([100, 140, 100]));
    }
    let (max, share, _) = compare(&a, &b);
    assert_eq!(max, 40);
    assert!((share - 0.1).abs() < 1e-9);
    assert!(max > MAX_LEVELS && share > MAX_CHANGED);
}
