//! Animation through the binary, on tiny sequences: frames equal stills at the same
//! clock, keys are hit at their times, an interrupted run finishes with the same
//! bytes, shards add up to one run, changed scenes invalidate old frames, and the
//! sequence assembles into GIF and APNG.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn rts(dir: &Path, args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_rts"))
        .current_dir(dir)
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("run rts");
    assert!(
        out.status.success(),
        "rts {args:?} failed: {}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A fresh folder under target/ for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("target/animation-tests")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

/// A keyed camera over a moving sphere, 6 frames.
const ORBIT: &str = r#"
#version 3.7;
global_settings { assumed_gamma 1.0 }
animation { frames 6  fps 6 }
camera_path {
  location keyframes { catmull_rom key 0, <0, 1, -5>  key 0.5, <3, 2, -3>  key 1, <4, 4, 0> }
  look_at <0, 0, 0>
  angle keyframes { key 0, 50 ease_in_out  key 1, 35 }
}
light_source { <3, 5, -4>, rgb 1 }
plane { y, -1 pigment { checker rgb 1, rgb 0.3 } }
sphere { keyframes { key 0, <-1, 0, 0>  key 1, <1, 0.5, 0> }, 0.7 pigment { rgb <1, 0.4, 0.2> } }
"#;

fn frames_in(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .expect("read dir")
        .flatten()
        .filter(|e| e.file_name().to_string_lossy().ends_with(".png"))
        .map(|e| {
            (
                e.file_name().to_string_lossy().into_owned(),
                std::fs::read(e.path()).expect("read frame"),
            )
        })
        .collect();
    v.sort();
    v
}

#[test]
fn frame_k_equals_a_still_at_its_clock() {
    let dir = scratch("still");
    std::fs::write(dir.join("orbit.rts"), ORBIT).unwrap();
    rts(
        &dir,
        &[
            "render",
            "orbit.rts",
            "-o",
            "f/o_##.png",
            "-W",
            "16",
            "-H",
            "12",
            "-q",
        ],
    );
    for k in 1..=6 {
        let clock = (k - 1) as f64 / 5.0;
        let name = format!("s{k}.png");
        rts(
            &dir,
            &[
                "render",
                "orbit.rts",
                "-o",
                &name,
                "-W",
                "16",
                "-H",
                "12",
                "-q",
                "--clock",
                &clock.to_string(),
            ],
        );
        let frame = std::fs::read(dir.join(format!("f/o_{k:02}.png"))).unwrap();
        let still = std::fs::read(dir.join(&name)).unwrap();
        assert!(
            frame == still,
            "frame {k} differs from the still at clock {clock}"
        );
        // --frame K gives the same picture too.
        let by_frame = format!("k{k}.png");
        rts(
            &dir,
            &[
                "render",
                "orbit.rts",
                "-o",
                &by_frame,
                "-W",
                "16",
                "-H",
                "12",
                "-q",
                "--frame",
                &k.to_string(),
            ],
        );
        assert!(
            std::fs::read(dir.join(&by_frame)).unwrap() == frame,
            "--frame {k}"
        );
    }
}

#[test]
fn keys_are_hit_at_their_times_in_every_unit() {
    let dir = scratch("keys");
    std::fs::write(
        dir.join("keys.rts"),
        r#"
#version 3.7;
global_settings { assumed_gamma 1.0 }
animation { frames 0, 8  fps 4  clock_range 10, 12 }
#declare C = keyframes { catmull_rom key 10, 0.25  key 10.5, 0.75 ease_in  key 12, 2 };
#declare F = keyframes { frames natural_spline key 0, 1.5  key 4, -3  key 8, 7 };
#declare S = keyframes { seconds bezier_spline key 0, <1, 2, 3>  key 1, <4, 5, 6> tangent <1, 0, 0>  key 2, <0, 0, 0> };
#debug concat("F", str(frame_number, 0, 0), " C ", str(C, 0, 17), " F ", str(F, 0, 17), " S ", vstr(3, S, ",", 0, 17), "\n")
"#,
    )
    .unwrap();
    let debug = |frame: i64| -> String {
        let frame = frame.to_string();
        debug_line(
            &dir,
            &[
                "render", "keys.rts", "-o", "k.png", "-W", "4", "-H", "4", "-q", "--frame", &frame,
            ],
        )
    };
    // Frame 0: clock 10; frame 2: clock 10.5; frame 8: clock 12 (seconds 0, 0.5, 2).
    let f0 = debug(0);
    assert!(f0.contains(" C 0.25000000000000000 "), "{f0}");
    assert!(f0.contains(" F 1.50000000000000000 "), "{f0}");
    assert!(
        f0.contains(" S 1.00000000000000000,2.00000000000000000,3.00000000000000000"),
        "{f0}"
    );
    let f2 = debug(2);
    assert!(f2.contains(" C 0.75000000000000000 "), "{f2}");
    let f4 = debug(4);
    assert!(f4.contains(" F -3.00000000000000000 "), "{f4}");
    assert!(
        f4.contains(" S 4.00000000000000000,5.00000000000000000,6.00000000000000000"),
        "{f4}"
    );
    let f8 = debug(8);
    assert!(f8.contains(" C 2.00000000000000000 "), "{f8}");
    assert!(f8.contains(" F 7.00000000000000000 "), "{f8}");
    assert!(
        f8.contains(" S 0.00000000000000000,0.00000000000000000,0.00000000000000000"),
        "{f8}"
    );
}

/// Keys in seconds and frames on a clock that runs backwards (`clock_range 12,
/// 10`) give, frame by frame, what they give on the same clock forwards: keys
/// are placed in time, whichever way the clock goes (it once panicked).
#[test]
fn keys_in_time_units_follow_a_backwards_clock() {
    let dir = scratch("keys_back");
    let scene = |range: &str| {
        format!(
            r#"
#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
animation {{ frames 0, 8  fps 4  clock_range {range} }}
#declare S = keyframes {{ seconds catmull_rom key 0, 1  key 1, 3 ease_in  key 2, 7 }};
#declare F = keyframes {{ frames bezier_spline key 0, <1, 2, 3>  key 4, <4, 5, 6> tangent <1, 0, 0>  key 8, <0, 0, 0> }};
#declare N = keyframes {{ seconds natural_spline ping_pong key 0, 1.5  key 0.5, -3  key 1.5, 7 }};
#debug concat("V ", str(S, 0, 17), " ", vstr(3, F, " ", 0, 17), " ", str(N, 0, 17), "\n")
"#
        )
    };
    std::fs::write(dir.join("forward.rts"), scene("10, 12")).unwrap();
    std::fs::write(dir.join("backward.rts"), scene("12, 10")).unwrap();
    let values = |file: &str, frame: u32| -> Vec<f64> {
        let frame = frame.to_string();
        let line = debug_line(
            &dir,
            &[
                "render", file, "-o", "k.png", "-W", "4", "-H", "4", "-q", "--frame", &frame,
            ],
        );
        let v = line.split("V ").nth(1).expect("values");
        v.split_whitespace().map(|x| x.parse().unwrap()).collect()
    };
    for frame in 0..=8 {
        let (f, b) = (values("forward.rts", frame), values("backward.rts", frame));
        assert_eq!(f.len(), 5);
        for (x, y) in f.iter().zip(&b) {
            assert!((x - y).abs() < 1e-9, "frame {frame}: {f:?} vs {b:?}");
        }
        if frame == 4 {
            // Second 1 and frame 4 are keys: their values exactly.
            assert!(
                (f[0] - 3.0).abs() < 1e-12 && (f[1] - 4.0).abs() < 1e-12,
                "{f:?}"
            );
        }
    }
}

#[test]
fn povray_clock_variables() {
    let dir = scratch("clockvars");
    std::fs::write(
        dir.join("c.rts"),
        r#"
#version 3.7;
global_settings { assumed_gamma 1.0 }
#debug concat("V ", str(clock, 0, 4), " ", str(clock_delta, 0, 4), " ", str(clock_on, 0, 0), " ", str(frame_number, 0, 0), " ", str(initial_frame, 0, 0), " ", str(final_frame, 0, 0), " ", str(initial_clock, 0, 2), " ", str(final_clock, 0, 2), "\n")
"#,
    )
    .unwrap();
    let line = |args: &[&str]| -> String {
        let mut a = vec!["render", "c.rts", "-o", "c.png", "-W", "2", "-H", "2", "-q"];
        a.extend_from_slice(args);
        let debug = debug_line(&dir, &a);
        debug
            .split(": V ")
            .nth(1)
            .expect("the V values")
            .to_string()
    };
    // The values POV-Ray 3.7 prints for the same settings.
    assert_eq!(line(&[]), "0.0000 0.0000 0 0 0 0 0.00 0.00");
    assert_eq!(line(&["--clock", "0.3"]), "0.3000 0.0000 1 0 0 0 0.00 0.00");
    assert_eq!(
        line(&["--frames", "1..5", "--frame", "3"]),
        "0.5000 0.2500 1 3 1 5 0.00 1.00"
    );
    assert_eq!(
        line(&["--frames", "1..5", "--frame", "3", "--cyclic"]),
        "0.4000 0.2000 1 3 1 6 0.00 1.00"
    );
}

/// The first `#debug` line of `rts ARGS --message-format short` run in `dir`.
fn debug_line(dir: &Path, args: &[&str]) -> String {
    let mut a = args.to_vec();
    a.extend_from_slice(&["--message-format", "short"]);
    let o = rts(dir, &a);
    String::from_utf8_lossy(&o.stdout)
        .lines()
        .find(|l| l.contains("rts::scene::debug"))
        .expect("a #debug line")
        .to_string()
}

/// Renders ORBIT's frames into `sub` with `extra` options; returns stderr.
fn sequence(dir: &Path, sub: &str, extra: &[&str]) -> String {
    let pattern = format!("{sub}/o_####.png");
    let mut a = vec![
        "render",
        "orbit.rts",
        "-o",
        &pattern,
        "-W",
        "24",
        "-H",
        "18",
        "--samples",
        "4",
    ];
    a.extend_from_slice(extra);
    stderr(&rts(dir, &a))
}

#[test]
fn three_shards_equal_one_run_and_reruns_skip() {
    let dir = scratch("shards");
    std::fs::write(dir.join("orbit.rts"), ORBIT).unwrap();
    sequence(&dir, "one", &[]);
    for i in 1..=3 {
        let s = sequence(&dir, "sharded", &["--shard", &format!("{i}/3")]);
        assert!(s.contains("rendered 2,"), "{s}");
    }
    let one = frames_in(&dir.join("one"));
    assert_eq!(one.len(), 6);
    assert_eq!(one, frames_in(&dir.join("sharded")));
    // A second run finds every frame complete; --force renders them again.
    let again = sequence(&dir, "one", &[]);
    assert!(again.contains("rendered 0, skipped 6"), "{again}");
    let forced = sequence(&dir, "one", &["--force"]);
    assert!(forced.contains("rendered 6, skipped 0"), "{forced}");
    assert_eq!(one, frames_in(&dir.join("one")));
    // Thread count does not change a byte.
    sequence(&dir, "t1", &["--threads", "1"]);
    assert_eq!(one, frames_in(&dir.join("t1")));
}

#[test]
fn a_changed_scene_or_include_invalidates_old_frames() {
    let dir = scratch("stale");
    std::fs::write(dir.join("colour.inc"), "#declare Colour = rgb <1, 0, 0>;\n").unwrap();
    std::fs::write(
        dir.join("orbit.rts"),
        format!("#include \"colour.inc\"\n{}\nsphere {{ <0.6, -0.4, -1.5>, 0.4 pigment {{ Colour }} }}\n", ORBIT),
    )
    .unwrap();
    let first = sequence(&dir, "f", &[]);
    assert!(first.contains("rendered 6, skipped 0"), "{first}");
    let before = frames_in(&dir.join("f"));
    assert!(sequence(&dir, "f", &[]).contains("rendered 0, skipped 6"));
    std::fs::write(dir.join("colour.inc"), "#declare Colour = rgb <0, 0, 1>;\n").unwrap();
    let after_inc = sequence(&dir, "f", &[]);
    assert!(after_inc.contains("rendered 6, skipped 0"), "{after_inc}");
    assert_ne!(before, frames_in(&dir.join("f")));
    // So does a changed mesh file.
    std::fs::write(dir.join("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let text = std::fs::read_to_string(dir.join("orbit.rts")).unwrap();
    std::fs::write(
        dir.join("orbit.rts"),
        text + "mesh { obj_file \"tri.obj\" translate <-1.5, -0.5, -1> pigment { rgb <0, 1, 0> } }\n",
    )
    .unwrap();
    assert!(sequence(&dir, "f", &[]).contains("rendered 6, skipped 0"));
    assert!(sequence(&dir, "f", &[]).contains("rendered 0, skipped 6"));
    std::fs::write(
        dir.join("tri.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1.5 0\nf 1 2 3\n",
    )
    .unwrap();
    let after_obj = sequence(&dir, "f", &[]);
    assert!(after_obj.contains("rendered 6, skipped 0"), "{after_obj}");
    // Other options (here the size) make old frames stale too.
    let bigger = stderr(&rts(
        &dir,
        &[
            "render",
            "orbit.rts",
            "-o",
            "f/o_####.png",
            "-W",
            "20",
            "-H",
            "15",
            "--samples",
            "4",
        ],
    ));
    assert!(bigger.contains("rendered 6, skipped 0"), "{bigger}");
    // A frame file changed behind the manifest's back is rendered again.
    std::fs::write(dir.join("f/o_0003.png"), b"not a png").unwrap();
    let repaired = stderr(&rts(
        &dir,
        &[
            "render",
            "orbit.rts",
            "-o",
            "f/o_####.png",
            "-W",
            "20",
            "-H",
            "15",
            "--samples",
            "4",
        ],
    ));
    assert!(repaired.contains("rendered 1, skipped 5"), "{repaired}");
}

#[test]
fn a_killed_run_resumes_to_the_same_bytes() {
    let dir = scratch("kill");
    std::fs::write(dir.join("orbit.rts"), ORBIT).unwrap();
    let args = [
        "render",
        "orbit.rts",
        "-o",
        "k/o_####.png",
        "-W",
        "160",
        "-H",
        "120",
        "--samples",
        "16",
        "-q",
    ];
    let mut child = Command::new(env!("CARGO_BIN_EXE_rts"))
        .current_dir(&dir)
        .args(args)
        .spawn()
        .expect("spawn rts");
    let first = dir.join("k/o_0001.png");
    let start = std::time::Instant::now();
    while !first.exists() && start.elapsed().as_secs() < 60 {
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    let _ = child.kill();
    let _ = child.wait();
    // Whatever was written is whole; the re-run completes the sequence.
    rts(&dir, &args);
    let mut whole = args.to_vec();
    whole[3] = "w/o_####.png";
    rts(&dir, &whole);
    let resumed = frames_in(&dir.join("k"));
    assert_eq!(resumed.len(), 6);
    assert_eq!(resumed, frames_in(&dir.join("w")));
    // No temporary files are left behind.
    for e in std::fs::read_dir(dir.join("k")).unwrap().flatten() {
        let n = e.file_name().to_string_lossy().into_owned();
        assert!(
            n.ends_with(".png") || n.ends_with(".manifest.json"),
            "left over: {n}"
        );
    }
}

#[test]
fn sequences_assemble_into_gif_and_apng() {
    let dir = scratch("assemble");
    std::fs::write(dir.join("orbit.rts"), ORBIT).unwrap();
    let s = sequence(
        &dir,
        "a",
        &["--gif", "orbit.gif", "--apng", "orbit.apng.png"],
    );
    assert!(s.contains("GIF → orbit.gif"), "{s}");
    let gif = image::open(dir.join("orbit.gif")).expect("a GIF");
    assert_eq!((gif.width(), gif.height()), (24, 18));
    let file = std::fs::File::open(dir.join("orbit.apng.png")).unwrap();
    let reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .expect("an APNG");
    let actl = reader.info().animation_control.expect("animated");
    assert_eq!(actl.num_frames, 6);
    // With ffmpeg installed, an MP4; without it on PATH, a message naming the package.
    let has_ffmpeg = std::env::var_os("PATH")
        .is_some_and(|p| std::env::split_paths(&p).any(|d| d.join("ffmpeg").is_file()));
    if has_ffmpeg {
        let s = sequence(&dir, "a", &["--mp4", "orbit.mp4"]);
        assert!(s.contains("MP4 → orbit.mp4"), "{s}");
        assert!(std::fs::metadata(dir.join("orbit.mp4")).unwrap().len() > 0);
    }
    let empty = dir.join("empty-path");
    std::fs::create_dir_all(&empty).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rts"))
        .current_dir(&dir)
        .args([
            "render",
            "orbit.rts",
            "-o",
            "a/o_####.png",
            "-W",
            "24",
            "-H",
            "18",
            "--samples",
            "4",
            "--mp4",
            "o.mp4",
        ])
        .env("PATH", &empty)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("apt-get install ffmpeg"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn preview_and_motion_blur() {
    let dir = scratch("blur");
    std::fs::write(dir.join("orbit.rts"), ORBIT).unwrap();
    rts(
        &dir,
        &[
            "render",
            "orbit.rts",
            "-o",
            "p.png",
            "-W",
            "24",
            "-H",
            "18",
            "--preview",
            "-q",
        ],
    );
    let p = image::open(dir.join("p.png")).unwrap();
    assert_eq!((p.width(), p.height()), (12, 9));
    let base = [
        "render",
        "orbit.rts",
        "-W",
        "24",
        "-H",
        "18",
        "-q",
        "--frame",
        "3",
    ];
    let with = |out: &str, extra: &[&str]| -> Vec<u8> {
        let mut a = base.to_vec();
        a.extend_from_slice(&["-o", out]);
        a.extend_from_slice(extra);
        rts(&dir, &a);
        std::fs::read(dir.join(out)).unwrap()
    };
    let sharp = with("sharp.png", &[]);
    let blurred = with(
        "blur.png",
        &["--motion-blur", "0.8", "--motion-samples", "4"],
    );
    let blurred1 = with(
        "blur1.png",
        &[
            "--motion-blur",
            "0.8",
            "--motion-samples",
            "4",
            "--threads",
            "1",
        ],
    );
    assert_ne!(sharp, blurred, "motion blur changes a moving scene");
    assert_eq!(blurred, blurred1, "motion blur is deterministic");
    // A zero shutter is no blur.
    assert_eq!(sharp, with("zero.png", &["--motion-blur", "0"]));
}

/// Mean x (0 left … 1 right) of the clearly red pixels of a PNG.
fn red_x(path: &Path) -> f64 {
    let img = image::open(path).unwrap().to_rgb8();
    let (mut sum, mut n) = (0.0, 0.0);
    for (x, _, p) in img.enumerate_pixels() {
        if p.0[0] > 120 && p.0[1] < 60 && p.0[2] < 60 {
            sum += f64::from(x);
            n += 1.0;
        }
    }
    assert!(n > 0.0, "no red in {}", path.display());
    sum / n / f64::from(img.width())
}

#[test]
fn camera_path_does_not_flip_over_the_top() {
    let dir = scratch("pole");
    let scene = |camera: &str| {
        format!(
            r#"
#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
animation {{ frames 101 }}
{camera}
light_source {{ <0, 10, 0>, rgb 1 }}
plane {{ y, 0 pigment {{ rgb 0.5 }} }}
sphere {{ <1.2, 0, 0>, 0.5 pigment {{ rgb <1, 0, 0> }} finish {{ ambient 1 diffuse 0 }} }}
"#
        )
    };
    // Up from the front, over the top, down the back (an arc in the y-z plane).
    let arc =
        "keyframes { catmull_rom key 0, <0, 0.5, -6>  key 0.5, <0, 6, 0>  key 1, <0, 0.5, 6> }";
    std::fs::write(
        dir.join("path.rts"),
        scene(&format!(
            "camera_path {{ location {arc} look_at <0, 0, 0> angle 60 }}"
        )),
    )
    .unwrap();
    std::fs::write(
        dir.join("pov.rts"),
        scene(&format!(
            "camera {{ location {arc} look_at <0, 0, 0> angle 60 }}"
        )),
    )
    .unwrap();
    for (name, clock) in [("before", "0.49"), ("after", "0.51")] {
        for s in ["path", "pov"] {
            rts(
                &dir,
                &[
                    "render",
                    &format!("{s}.rts"),
                    "-o",
                    &format!("{s}_{name}.png"),
                    "-W",
                    "48",
                    "-H",
                    "36",
                    "-q",
                    "--clock",
                    clock,
                ],
            );
        }
    }
    // The camera_path keeps the red sphere on the right as it passes over the top …
    assert!(red_x(&dir.join("path_before.png")) > 0.6);
    assert!(red_x(&dir.join("path_after.png")) > 0.6);
    // … where a look_at camera turns the picture over between two close frames.
    assert!(red_x(&dir.join("pov_before.png")) > 0.6);
    assert!(red_x(&dir.join("pov_after.png")) < 0.4);
}

#[test]
fn keyframes_are_operands_in_expressions() {
    // `2 * keyframes { key 0, 1 key 1, 3 } + 1` is 3, 5 and 7 at clock 0, 0.5 and 1.
    let fixture =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/ok/anim_keyframes_expr.rts");
    let dir = scratch("kf_operand");
    for (clock, want) in [("0", "V=3.000"), ("0.5", "V=5.000"), ("1", "V=7.000")] {
        let out = rts(
            &dir,
            &[
                "check",
                fixture.to_str().unwrap(),
                "--clock",
                clock,
                "--message-format",
                "short",
            ],
        );
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "{text}");
        assert!(text.contains(want), "clock {clock}: {text}");
    }
}

#[test]
fn path_tracer_options_invalidate_old_frames() {
    let dir = scratch("path_options");
    std::fs::write(dir.join("orbit.rts"), ORBIT).unwrap();
    let path = |spp: &str| {
        stderr(&rts(
            &dir,
            &[
                "render",
                "orbit.rts",
                "-o",
                "p/o_####.png",
                "-W",
                "12",
                "-H",
                "9",
                "--integrator",
                "path",
                "--spp",
                spp,
            ],
        ))
    };
    assert!(path("1").contains("rendered 6, skipped 0"));
    assert!(path("1").contains("rendered 0, skipped 6"));
    // More samples per pixel are other pixels: every frame is rendered again.
    let more = path("2");
    assert!(more.contains("rendered 6, skipped 0"), "{more}");
}
