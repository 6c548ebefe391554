//! The command line as a newcomer meets it: what a scene prints itself
//! (`#debug`, `#warning`), options that do nothing in the chosen mode, values
//! in the wrong format, a timeline rendered to one file, include files checked
//! on their own. Each case asserts the exit status and the whole of stderr.

use std::path::{Path, PathBuf};
use std::process::Command;

struct Run {
    code: i32,
    stdout: String,
    stderr: String,
}

fn rts(dir: &Path, args: &[&str]) -> Run {
    let out = Command::new(env!("CARGO_BIN_EXE_rts"))
        .current_dir(dir)
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("run rts");
    Run {
        code: out.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rts-newcomer-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const HEAD: &str = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n\
    camera { location <0, 1, -4> look_at 0 }\nlight_source { <5, 5, -5> rgb 1 }\n\
    sphere { 0, 1 pigment { rgb 1 } }\n";

#[test]
fn debug_prints_its_text_as_povray_does() {
    let dir = folder("debug");
    std::fs::write(
        dir.join("s.rts"),
        format!(
            "{HEAD}#debug \"Loading\\n\"\n#debug \"no line end \"\n#debug concat(\"then one: \", str(2, 0, 1), \"\\n\")\n"
        ),
    )
    .unwrap();
    let r = rts(&dir, &["check", "s.rts"]);
    assert_eq!(r.code, 0);
    assert_eq!(r.stderr, "Loading\nno line end then one: 2.0\n");
    // -q silences it, and only it.
    let r = rts(
        &dir,
        &["render", "s.rts", "-o", "s.png", "-W", "8", "-H", "6", "-q"],
    );
    assert_eq!((r.code, r.stderr.as_str()), (0, ""));
    // Tools still get it as a note.
    let r = rts(&dir, &["check", "s.rts", "--message-format", "short"]);
    assert_eq!(
        r.stdout,
        "s.rts:6:1: note[rts::scene::debug]: Loading\n\
         s.rts:7:1: note[rts::scene::debug]: no line end \n\
         s.rts:8:1: note[rts::scene::debug]: then one: 2.0\n"
    );
}

#[test]
fn warning_is_one_line_with_its_place() {
    let dir = folder("warning");
    std::fs::write(
        dir.join("s.rts"),
        format!("{HEAD}#warning \"the floor is missing\"\n"),
    )
    .unwrap();
    let r = rts(&dir, &["check", "s.rts"]);
    assert_eq!(r.code, 0);
    assert_eq!(r.stderr, "s.rts:6:1: warning: the floor is missing\n");
}

#[test]
fn every_frame_of_a_sequence_speaks_once_with_its_number() {
    let dir = folder("frames");
    std::fs::write(
        dir.join("s.rts"),
        format!(
            "{HEAD}animation {{ frames 3 }}\n\
             #debug \"static\\n\"\n\
             #debug concat(\"clock \", str(clock, 0, 1), \"\\n\")\n\
             #if (frame_number = 2) #warning \"frame two\" #end\n"
        ),
    )
    .unwrap();
    let r = rts(
        &dir,
        &["render", "s.rts", "-o", "f_#.png", "-W", "8", "-H", "6"],
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    // The messages, then the sequence's summary.
    let (messages, summary) = r
        .stderr
        .split_at(r.stderr.find("sequence 3 frames").unwrap());
    assert!(
        summary.starts_with("sequence 3 frames 1..3: rendered 3"),
        "{summary}"
    );
    assert_eq!(
        messages,
        "frame 1: static\n\
         frame 1: clock 0.0\n\
         frame 2: clock 0.5\n\
         frame 2: s.rts:9:24: warning: frame two\n\
         frame 3: clock 1.0\n"
    );
}

#[test]
fn options_for_another_mode_are_named() {
    let dir = folder("modes");
    std::fs::write(dir.join("s.rts"), HEAD).unwrap();
    let r = rts(
        &dir,
        &[
            "render", "s.rts", "-o", "s.png", "-W", "8", "-H", "6", "-q", "--spp", "4", "--jitter",
            "0.5",
        ],
    );
    assert_eq!(r.code, 0);
    assert_eq!(
        r.stderr,
        "warning: --spp has no effect: it is a path tracer option, and the classic renderer renders this scene (add --integrator path to path trace it)\n\
         warning: --jitter has no effect: it tunes --antialias, which is not given\n"
    );
    let r = rts(
        &dir,
        &[
            "render",
            "s.rts",
            "-o",
            "s.png",
            "-W",
            "8",
            "-H",
            "6",
            "-q",
            "--integrator",
            "path",
            "--spp",
            "1",
            "--samples",
            "4",
        ],
    );
    assert_eq!(r.code, 0);
    assert_eq!(
        r.stderr,
        "warning: --samples has no effect: the path tracer renders this scene; it takes --spp (or --time-limit) instead\n"
    );
}

#[test]
fn values_in_the_wrong_format_are_usage_errors() {
    let dir = folder("values");
    std::fs::write(dir.join("s.rts"), HEAD).unwrap();
    let r = rts(&dir, &["render", "s.rts", "--time-limit", "5x"]);
    assert_eq!(r.code, 2);
    assert_eq!(
        r.stderr,
        "error: invalid value '5x' for '--time-limit <DURATION>': `x` is not a unit: use s, m or h (e.g. 60s, 2m, 1h)\n\nFor more information, try '--help'.\n"
    );
    let r = rts(&dir, &["render", "s.rts", "--frames", "5"]);
    assert_eq!(r.code, 2);
    assert_eq!(
        r.stderr,
        "error: invalid value '5' for '--frames <A..B>': expected FIRST..LAST: 1..5 for 5 frames, 5..5 for frame 5 alone (or --frame 5 for it as a still)\n\nFor more information, try '--help'.\n"
    );
    let r = rts(&dir, &["render", "s.rts", "-w", "100"]);
    assert_eq!(r.code, 2);
    assert_eq!(
        r.stderr,
        "error: unknown option '-w'\n\n  tip: options are case-sensitive: did you mean '-W' (--width)?\n\n\
         Usage: rts render [OPTIONS] <SCENE>\n\nFor more information, try 'rts render --help'.\n"
    );
}

#[test]
fn a_timeline_rendered_to_one_file_says_which_frame() {
    let dir = folder("timeline");
    std::fs::write(
        dir.join("s.rts"),
        format!("{HEAD}animation {{ frames 4 }}\n"),
    )
    .unwrap();
    let r = rts(
        &dir,
        &["render", "s.rts", "-o", "one.png", "-W", "8", "-H", "6"],
    );
    assert_eq!(r.code, 0);
    let first = r.stderr.lines().next().unwrap_or_default();
    assert_eq!(
        first,
        "note: the scene's timeline has frames 1..4; this renders frame 1 only (-o names one picture). For every frame use -o one_####.png (or --gif/--apng/--mp4), for another one --frame N"
    );
    assert!(dir.join("one.png").exists());
    // Asking for a GIF turns the one name into a pattern, and says so.
    let r = rts(
        &dir,
        &[
            "render", "s.rts", "-o", "one.png", "-W", "8", "-H", "6", "--gif", "one.gif", "-q",
        ],
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert_eq!(r.stderr, "");
    let r = rts(
        &dir,
        &[
            "render", "s.rts", "-o", "two.png", "-W", "8", "-H", "6", "--gif", "two.gif",
        ],
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stderr.starts_with(
            "note: rendering frames 1..4 of the scene's timeline to `two_####.png` (-o names one picture; a sequence writes one file per frame)\n"
        ),
        "{}",
        r.stderr
    );
    assert!(dir.join("two_0001.png").exists() && dir.join("two.gif").exists());
}

#[test]
fn an_include_file_is_checked_as_a_library() {
    let dir = folder("library");
    std::fs::write(
        dir.join("mylib.inc"),
        "#declare Lib_Size = 2;\n#macro Lib_Ball(P) sphere { P, Lib_Size } #end\n",
    )
    .unwrap();
    let r = rts(&dir, &["check", "mylib.inc"]);
    assert_eq!((r.code, r.stderr.as_str(), r.stdout.as_str()), (0, "", ""));
}

#[test]
fn the_path_tracer_counts_rays_through_glass_as_transmitted() {
    let dir = folder("glass");
    std::fs::write(
        dir.join("g.rts"),
        "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n\
         camera { location <0, 0, -3> look_at 0 }\nlight_source { <5, 5, -5> rgb 1 }\n\
         sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 } }\n",
    )
    .unwrap();
    let r = rts(
        &dir,
        &[
            "render",
            "g.rts",
            "-o",
            "g.png",
            "-W",
            "16",
            "-H",
            "12",
            "--integrator",
            "path",
            "--spp",
            "2",
            "-q",
            "--stats-json",
            "-",
        ],
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    let v: serde_json::Value = serde_json::from_str(&r.stdout).expect("stats JSON");
    let transmitted = v["rays"]["transmitted"].as_u64().expect("a count");
    assert!(transmitted > 0, "{}", r.stdout);
}
