//! `rts render --shard I/N` of a still and `rts merge`, through the binary: the
//! merged bands are the bytes of one render (anti-aliasing, focal blur, area
//! lights, radiosity, photons, the path tracer's filter, every format), and
//! parts of another scene or options, missing, overlapping or changed parts are
//! refused with their codes.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn run(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rts"))
        .current_dir(dir)
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("run rts")
}

fn ok(dir: &Path, args: &[&str]) -> Output {
    let out = run(dir, args);
    assert!(
        out.status.success(),
        "rts {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// Runs `args`, expects it to fail, and gives its standard error.
fn refused(dir: &Path, args: &[&str]) -> String {
    let out = run(dir, args);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(!out.status.success(), "rts {args:?} succeeded: {err}");
    err
}

/// A fresh folder under target/ for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("target/still-shard-tests")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

fn example(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

/// Renders `scene` once and in `n` shards merged, `w`×`h` as `ext`, with
/// `extra` options, and asserts the two files are the same bytes.
fn merged_equals_one_run(
    name: &str,
    scene: &str,
    ext: &str,
    (w, h): (u32, u32),
    n: u32,
    extra: &[&str],
) {
    let dir = scratch(name);
    let scene = example(scene);
    let (ws, hs) = (w.to_string(), h.to_string());
    let one = format!("one.{ext}");
    let split = format!("split.{ext}");
    let mut base = vec![scene.as_str(), "-W", &ws, "-H", &hs, "-q"];
    base.extend_from_slice(extra);
    let mut a = vec!["render", "-o", &one, "--threads", "2"];
    a.extend_from_slice(&base);
    ok(&dir, &a);
    // Shards in reverse order, on one thread: nothing depends on either.
    for i in (1..=n).rev() {
        let shard = format!("{i}/{n}");
        let mut a = vec!["render", "-o", &split, "--shard", &shard];
        a.extend_from_slice(&base);
        a.extend_from_slice(&["--threads", "1"]);
        ok(&dir, &a);
    }
    ok(&dir, &["merge", "-o", &split]);
    let (x, y) = (
        std::fs::read(dir.join(&one)).unwrap(),
        std::fs::read(dir.join(&split)).unwrap(),
    );
    assert!(!x.is_empty());
    assert!(x == y, "{name}: the merged {ext} differs from one render");
}

#[test]
fn antialiased_area_light_bands_merge_to_one_render() {
    // 60 rows in 3 bands cut through the 32-row blocks anti-aliasing works in.
    merged_equals_one_run(
        "aa",
        "area_light.rts",
        "png",
        (80, 60),
        3,
        &["--antialias", "0.1"],
    );
    // 100 rows: bands of whole blocks.
    merged_equals_one_run(
        "aa_blocks",
        "area_light.rts",
        "png",
        (64, 100),
        3,
        &["--antialias", "0.1"],
    );
}

#[test]
fn focal_blur_bands_merge_to_one_render_in_16_bits() {
    merged_equals_one_run(
        "focal",
        "depth_of_field.rts",
        "png",
        (72, 54),
        4,
        &["--samples", "4", "--bit-depth", "16"],
    );
}

#[test]
fn radiosity_and_photon_bands_merge_to_one_render() {
    // The pretrace covers the whole image in every band.
    merged_equals_one_run(
        "radiosity",
        "radiosity.rts",
        "png",
        (64, 48),
        3,
        &["--antialias", "0.3"],
    );
    merged_equals_one_run("photons", "photons.rts", "ppm", (64, 48), 2, &[]);
}

#[test]
fn path_traced_bands_merge_to_one_render() {
    // The Gaussian filter spreads samples over neighbouring rows.
    merged_equals_one_run(
        "path",
        "materials_path.rts",
        "png",
        (48, 40),
        3,
        &["--spp", "2"],
    );
}

#[test]
fn float_formats_and_passes_merge_to_one_render() {
    merged_equals_one_run(
        "exr",
        "cornell_box.rts",
        "exr",
        (48, 40),
        3,
        &["--samples", "2"],
    );
    merged_equals_one_run("hdr", "glass.rts", "hdr", (48, 40), 2, &[]);
    merged_equals_one_run(
        "depth",
        "textures.rts",
        "png",
        (48, 40),
        3,
        &["--pass", "depth"],
    );
}

/// Three parts of `area_light.rts` at 48×40 in `dir` as `s.png`, with `extra`
/// options for shard 2.
fn three_parts(dir: &Path, extra2: &[&str]) {
    let scene = example("area_light.rts");
    for i in 1..=3 {
        let shard = format!("{i}/3");
        let mut a = vec![
            "render", &scene, "-o", "s.png", "-W", "48", "-H", "40", "-q", "--shard", &shard,
        ];
        if i == 2 {
            a.extend_from_slice(extra2);
        }
        ok(dir, &a);
    }
}

#[test]
fn merge_refuses_parts_of_other_options_or_scenes() {
    let dir = scratch("refuse_options");
    three_parts(&dir, &["--seed", "7"]);
    let err = refused(&dir, &["merge", "-o", "s.png"]);
    assert!(
        err.contains("error[rts::merge::different_options]"),
        "{err}"
    );
    assert!(err.contains("seed: 7"), "{err}");

    let dir = scratch("refuse_scene");
    let scene = dir.join("scene.rts");
    let text = std::fs::read_to_string(example("area_light.rts")).unwrap();
    std::fs::write(&scene, &text).unwrap();
    for i in 1..=2 {
        if i == 2 {
            std::fs::write(&scene, format!("{text}\n// changed\n")).unwrap();
        }
        let shard = format!("{i}/2");
        ok(
            &dir,
            &[
                "render",
                "scene.rts",
                "-o",
                "s.png",
                "-W",
                "48",
                "-H",
                "40",
                "-q",
                "--shard",
                &shard,
            ],
        );
    }
    let err = refused(&dir, &["merge", "-o", "s.png"]);
    assert!(err.contains("error[rts::merge::different_scene]"), "{err}");
}

#[test]
fn merge_refuses_missing_overlapping_and_changed_parts() {
    let dir = scratch("refuse_bands");
    three_parts(&dir, &[]);
    // Named parts: 1 and 3 leave rows out, and the message names shard 2.
    let err = refused(
        &dir,
        &[
            "merge",
            "s.part-1-of-3.png",
            "s.part-3-of-3.png",
            "-o",
            "s.png",
        ],
    );
    assert!(err.contains("error[rts::merge::missing_band]"), "{err}");
    assert!(err.contains("--shard 2/3"), "{err}");
    // All three merge.
    ok(&dir, &["merge", "-o", "s.png"]);
    // A part of a split in two overlaps them.
    let scene = example("area_light.rts");
    ok(
        &dir,
        &[
            "render", &scene, "-o", "s.png", "-W", "48", "-H", "40", "-q", "--shard", "1/2",
        ],
    );
    let err = refused(&dir, &["merge", "-o", "s.png"]);
    assert!(
        err.contains("error[rts::merge::overlapping_bands]"),
        "{err}"
    );
    std::fs::remove_file(dir.join("s.part-1-of-2.png.manifest.json")).unwrap();
    // A part changed after its manifest was written.
    let mut bytes = std::fs::read(dir.join("s.part-3-of-3.png")).unwrap();
    bytes.push(0);
    std::fs::write(dir.join("s.part-3-of-3.png"), bytes).unwrap();
    let err = refused(&dir, &["merge", "-o", "s.png"]);
    assert!(err.contains("error[rts::merge::bad_part]"), "{err}");
    // No parts at all.
    let err = refused(&dir, &["merge", "-o", "other.png"]);
    assert!(err.contains("error[rts::merge::missing_band]"), "{err}");
}

#[test]
fn a_complete_part_is_not_rendered_again() {
    let dir = scratch("skip");
    three_parts(&dir, &[]);
    let scene = example("area_light.rts");
    let args = [
        "render", &scene, "-o", "s.png", "-W", "48", "-H", "40", "--shard", "2/3",
    ];
    let err = String::from_utf8_lossy(&ok(&dir, &args).stderr).into_owned();
    assert!(err.contains("already complete"), "{err}");
    let mut forced = args.to_vec();
    forced.push("--force");
    let err = String::from_utf8_lossy(&ok(&dir, &forced).stderr).into_owned();
    assert!(err.contains("part 2/3: rows"), "{err}");
}

#[test]
fn options_no_band_can_reproduce_are_refused() {
    let dir = scratch("unsupported");
    let scene = example("materials_path.rts");
    for extra in [
        &["-H", "12", "--time-limit", "5s"][..],
        &["-H", "12", "--crop", "0,0,8,8"],
        &["-H", "12", "--aov", "albedo"],
        // More shards than rows.
        &["-H", "2"],
    ] {
        let mut a = vec![
            "render", &scene, "-o", "s.png", "-W", "16", "--shard", "1/3",
        ];
        a.extend_from_slice(extra);
        let err = refused(&dir, &a);
        assert!(
            err.contains("error[rts::shard::unsupported]"),
            "{extra:?}: {err}"
        );
    }
}
