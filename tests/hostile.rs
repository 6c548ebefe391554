//! Hostile and careless scenes, run as users run the binary: each ends quickly in
//! the diagnostic that names its limit (budgets lowered by flags so the tests
//! stay fast), or renders where it is legal. A case that hangs fails the test
//! through its timeout instead of blocking the suite.

use std::io::Read;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The longest any case may take before it counts as a hang.
const HANG: Duration = Duration::from_secs(60);

struct Run {
    code: i32,
    stdout: String,
    stderr: String,
}

/// Runs `rts` with `args`, killing it (and failing) after [`HANG`].
fn rts(args: &[&str]) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_rts"))
        .args(args)
        .env("NO_COLOR", "1")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run rts");
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let reader = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = out.read_to_end(&mut s);
        s
    });
    let err_reader = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = err.read_to_end(&mut s);
        s
    });
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        if start.elapsed() > HANG {
            let _ = child.kill();
            panic!("rts {args:?} still running after {HANG:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    Run {
        code: status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&reader.join().unwrap()).into_owned(),
        stderr: String::from_utf8_lossy(&err_reader.join().unwrap()).into_owned(),
    }
}

fn scene(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("rts-hostile-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

fn out_png(name: &str) -> String {
    let dir: PathBuf = std::env::temp_dir().join(format!("rts-hostile-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name).display().to_string()
}

/// The error codes of a `--message-format short` run.
fn error_codes(r: &Run) -> Vec<String> {
    r.stdout
        .lines()
        .filter_map(|l| l.split(": error[").nth(1))
        .filter_map(|l| l.split(']').next())
        .map(str::to_string)
        .collect()
}

const LIT: &str = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n\
    camera { location <0, 2, -10> look_at <0, 0.5, 0> }\n\
    light_source { <10, 10, -10> color rgb 1 }\n";

#[test]
fn a_loop_that_forgets_its_step_ends_at_the_memory_budget() {
    let s = scene(
        "forgot_step.rts",
        "#declare I = 0;\n#while (I < 10)\n  sphere { <I, 0, 0>, 1 }\n#end\n",
    );
    let r = rts(&[
        "check",
        &s,
        "--max-memory",
        "64M",
        "--message-format",
        "short",
    ]);
    assert_eq!(r.code, 1, "{}{}", r.stdout, r.stderr);
    assert_eq!(error_codes(&r), ["rts::limit::memory"], "{}", r.stdout);
    assert!(r.stdout.contains("--max-memory"), "{}", r.stdout);
    assert!(
        r.stdout.contains("forgot_step.rts:2:1"),
        "the loop: {}",
        r.stdout
    );
}

#[test]
fn arrays_of_arrays_are_refused_before_they_are_made() {
    let s = scene(
        "arrays.rts",
        "#declare L = array[1000];\n#for (I, 0, 999)\n  #declare L[I] = array[4194304];\n#end\n",
    );
    let r = rts(&[
        "check",
        &s,
        "--max-memory",
        "256M",
        "--message-format",
        "short",
    ]);
    assert_eq!(r.code, 1);
    let codes = error_codes(&r);
    assert!(codes
        .iter()
        .all(|c| c == "rts::limit::memory" || c == "rts::limit::errors"));
    assert!(
        r.stdout.contains("this array of 4194304 elements needs"),
        "{}",
        r.stdout
    );
}

#[test]
fn a_macro_that_calls_itself_twice_ends_at_the_call_budget() {
    let s = scene(
        "twice.rts",
        "#macro M(D)\n  #if (D < 40)\n    M(D + 1)\n    M(D + 1)\n  #end\n#end\nM(0)\n",
    );
    let r = rts(&[
        "check",
        &s,
        "--max-macro-calls",
        "20000",
        "--message-format",
        "short",
    ]);
    assert_eq!(r.code, 1);
    assert_eq!(error_codes(&r), ["rts::limit::macro_calls"], "{}", r.stdout);
    assert!(
        r.stdout.contains("more than 20000 macro calls"),
        "{}",
        r.stdout
    );
}

#[test]
fn a_string_that_doubles_ends_at_the_length_limit() {
    let s = scene(
        "doubling.rts",
        "#declare S = \"ab\";\n#for (I, 1, 60)\n  #declare S = concat(S, S);\n#end\n",
    );
    let r = rts(&[
        "check",
        &s,
        "--max-string-length",
        "1M",
        "--message-format",
        "short",
    ]);
    assert_eq!(r.code, 1);
    assert_eq!(
        error_codes(&r),
        ["rts::limit::string_length"],
        "{}",
        r.stdout
    );
}

#[test]
fn one_error_in_a_huge_loop_is_shown_once_and_stops_the_loop() {
    let s = scene(
        "undefined.rts",
        "#for (I, 1, 1e9)\n  #declare X = Undefined_Name;\n#end\n",
    );
    let r = rts(&["check", &s, "--max-errors", "5"]);
    assert_eq!(r.code, 1);
    assert_eq!(
        r.stderr.matches("unknown identifier").count(),
        1,
        "{}",
        r.stderr
    );
    assert!(r.stderr.contains("reported 5 times in all"), "{}", r.stderr);
    assert!(r
        .stderr
        .contains("stopped after 5 errors (1 distinct, the rest repeats)"));
}

#[test]
fn a_union_grown_in_a_loop_renders() {
    // The POV-Ray idiom: each pass wraps the fence so far in a new union.
    let s = scene(
        "fence.rts",
        &format!(
            "{LIT}#declare Fence = box {{ <0, 0, 0>, <0.01, 1, 0.1> }}\n\
             #for (I, 1, 20000)\n\
               #declare Fence = union {{ object {{ Fence }} box {{ <I * 0.0004, 0, 0>, <I * 0.0004 + 0.0002, 1, 0.1> }} }}\n\
             #end\n\
             object {{ Fence translate -4 * x pigment {{ rgb 1 }} }}\n"
        ),
    );
    let r = rts(&[
        "render",
        &s,
        "-o",
        &out_png("fence.png"),
        "-W",
        "32",
        "-H",
        "24",
        "-q",
    ]);
    assert_eq!(r.code, 0, "{}", r.stderr);
}

#[test]
fn deeply_nested_csg_renders_on_every_thread() {
    // Each pass nests one level deeper (the inner object is moved, so nothing
    // can be flattened); the render threads walk the whole depth.
    let s = scene(
        "nested.rts",
        &format!(
            "{LIT}#declare D = box {{ <0, 0, 0>, <0.01, 1, 0.1> }}\n\
             #for (I, 1, 3000)\n\
               #declare D = union {{ object {{ D translate <-0.002, 0, 0> }} box {{ <0, 0, 0>, <0.001, 1, 0.1> }} pigment {{ rgb <1, I / 3000, 0> }} }}\n\
             #end\n\
             #declare C = sphere {{ 0, 1 }}\n\
             #for (I, 1, 2000)\n\
               #declare C = difference {{ sphere {{ 0, 1 + I * 0.001 }} object {{ C }} }}\n\
             #end\n\
             object {{ D }}\n\
             object {{ C translate 2 * x pigment {{ rgb 1 }} }}\n"
        ),
    );
    for threads in ["1", "2"] {
        let out = out_png(&format!("nested-{threads}.png"));
        let r = rts(&[
            "render",
            &s,
            "-o",
            &out,
            "-W",
            "32",
            "-H",
            "24",
            "--threads",
            threads,
            "-q",
        ]);
        assert_eq!(r.code, 0, "--threads {threads}: {}", r.stderr);
    }
}

#[test]
fn control_characters_in_the_source_are_shown_not_sent() {
    let s = scene(
        "escape.rts",
        "sphere { <0, 0, 0>, 1 pigment { rgb \u{1b}[31mRED\u{1b}[0m } }\n",
    );
    let r = rts(&["check", &s]);
    assert_eq!(r.code, 1);
    assert!(!r.stderr.contains('\u{1b}'), "{:?}", r.stderr);
    assert!(r.stderr.contains("\u{241b}[31mRED"), "{}", r.stderr);
    // The position in the header is the file's own column.
    assert!(r.stderr.contains("escape.rts:1:"), "{}", r.stderr);
}

/// A `#` that starts no directive is ignored, also inside a run of numbers and
/// vectors: evaluation finds the run's elements in the file's own text, where
/// the `#` still stands (the fuzzer found this looping forever, and in a
/// vector's last component, `<1, 0, #>`, taking all the memory it could).
#[test]
fn a_stray_hash_inside_a_run_of_numbers_is_skipped() {
    let s = scene(
        "hash_in_run.rts",
        "mesh { triangle { <0, 0, 0>, <1, 0, 0>, # <0, 1, 0> } }\n\
         #declare P = array[3] { 1, <1, 0, #>, 2 };\n\
         camera { location -3*z look_at 0 }\n",
    );
    let r = rts(&["check", &s, "--message-format", "short"]);
    assert_eq!(
        r.stdout
            .matches("warning[rts::syntax::unknown_directive]")
            .count(),
        2,
        "{}",
        r.stdout
    );
    assert!(error_codes(&r).is_empty(), "{}", r.stdout);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
}

/// Evaluates `text` with the library and returns the scene's objects.
fn objects(text: &str) -> Vec<rts::scene::Object> {
    let mut sources = rts::source::SourceMap::new();
    let id = sources.add("t.rts", None, text.to_string());
    let (file, diags) = rts::syntax::parse(text, id);
    assert!(!rts::diag::has_errors(&diags), "{diags:?}");
    let e = rts::eval::eval(&file, id, &mut sources, &rts::eval::EvalOptions::default());
    assert!(
        !rts::diag::has_errors(&e.diagnostics),
        "{:?}",
        e.diagnostics
    );
    e.scene.objects
}

#[test]
fn unions_of_plain_unions_are_flattened() {
    let o = objects(
        "#declare U = sphere { 0, 1 }\n\
         #for (I, 1, 500)\n  #declare U = union { object { U } sphere { I * x, 1 } }\n#end\n\
         object { U }\n\
         union { union { sphere { 0, 1 } sphere { x, 1 } translate y } sphere { 2 * x, 1 } }\n\
         difference { difference { sphere { 0, 2 } sphere { x, 1 } } sphere { -x, 1 } }\n\
         difference { sphere { 0, 2 } difference { sphere { x, 1 } sphere { -x, 1 } } }\n",
    );
    let members = |o: &rts::scene::Object| match &o.shape {
        rts::scene::Shape::Union { children } | rts::scene::Shape::Csg { children, .. } => {
            children.len()
        }
        _ => 0,
    };
    // The loop's union is one flat union of 501 spheres.
    assert_eq!((members(&o[0]), o[0].nesting), (501, 1));
    // A moved inner union keeps its own level.
    assert_eq!((members(&o[1]), o[1].nesting), (2, 2));
    // A difference as the first operand of a difference is taken apart...
    assert_eq!((members(&o[2]), o[2].nesting), (3, 1));
    // ...but not as a later operand (A - (B - C) is not A - B - C).
    assert_eq!((members(&o[3]), o[3].nesting), (2, 2));
}

/// Members keep the order written whichever side of the union grows: the
/// union so far first or last in each pass (the second order was quadratic
/// when the trees were joined: 100,000 passes took 30 s).
#[test]
fn flattened_unions_keep_their_members_in_order() {
    let o = objects(
        "#declare U = sphere { 0, 1 }\n\
         #for (I, 1, 300)\n  #declare U = union { sphere { I * x, 1 } object { U } }\n#end\n\
         object { U }\n\
         #declare V = sphere { 0, 1 }\n\
         #for (I, 1, 300)\n  #declare V = union { object { V } sphere { I * x, 1 } }\n#end\n\
         union { union { sphere { -2 * x, 1 } sphere { -x, 1 } } object { V } union { sphere { 1000 * x, 1 } } }\n",
    );
    let centres = |o: &rts::scene::Object| -> Vec<f64> {
        match &o.shape {
            rts::scene::Shape::Union { children } => children
                .iter()
                .map(|c| match c.shape {
                    rts::scene::Shape::Sphere { center, .. } => center.x,
                    _ => f64::NAN,
                })
                .collect(),
            _ => Vec::new(),
        }
    };
    let down: Vec<f64> = (0..=300).rev().map(f64::from).collect();
    assert_eq!(centres(&o[0]), down);
    let mut up: Vec<f64> = vec![-2.0, -1.0];
    up.extend((0..=300).map(f64::from));
    up.push(1000.0);
    assert_eq!(centres(&o[1]), up);
}
