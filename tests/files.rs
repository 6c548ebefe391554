//! Files a scene or a render writes and reads cannot hurt the user (the binary as
//! users run it): no writing through links, no waiting on FIFOs, no endless
//! reads of devices, budgets for what a scene writes and reads, streams for
//! `-o -` and `/dev/null`, no temporary file left by Ctrl-C or `kill`, output
//! folders checked before rendering. A command that should end but blocks fails
//! its test after a generous time instead of hanging it.
#![cfg(unix)]

use std::io::Read;
use std::os::unix::fs::FileTypeExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

/// Longest a command that must not block may take (it takes well under a second).
const HANG: Duration = Duration::from_secs(60);

fn rts() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rts"))
}

/// A fresh folder for one test.
fn folder(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("rts-files-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn mkfifo(p: &Path) {
    let ok = Command::new("mkfifo").arg(p).status().unwrap().success();
    assert!(ok, "mkfifo {}", p.display());
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Runs `cmd` to its end, failing the test (and killing it) if it has not ended
/// within [`HANG`]: it blocked.
fn run(mut cmd: Command) -> Output {
    let child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    finish(child, &format!("{cmd:?}"))
}

fn finish(mut child: Child, what: &str) -> Output {
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let t_out = std::thread::spawn(move || {
        let mut b = Vec::new();
        out.read_to_end(&mut b).unwrap();
        b
    });
    let t_err = std::thread::spawn(move || {
        let mut b = Vec::new();
        err.read_to_end(&mut b).unwrap();
        b
    });
    let start = Instant::now();
    let status = loop {
        if let Some(st) = child.try_wait().unwrap() {
            break st;
        }
        if start.elapsed() > HANG {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{what} did not end: it blocks");
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    Output {
        status,
        stdout: t_out.join().unwrap(),
        stderr: t_err.join().unwrap(),
    }
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// Error codes of a `--message-format short` run.
fn codes(out: &Output) -> Vec<String> {
    text(&out.stdout)
        .lines()
        .filter_map(|l| l.split("error[").nth(1))
        .filter_map(|l| l.split(']').next())
        .map(str::to_string)
        .collect()
}

const OBJECTS: &str = "sphere { 0, 1 pigment { rgb 1 } } light_source { <0, 5, -5> rgb 1 }\n";

fn render_small(scene: &Path, out: &Path) -> Command {
    let mut c = rts();
    c.args(["render", s(scene), "-o", s(out), "-W", "8", "-H", "8", "-q"])
        .args(["--message-format", "short"]);
    c
}

fn check(scene: &Path) -> Command {
    let mut c = rts();
    c.args(["check", s(scene), "--message-format", "short"]);
    c
}

/// PNG's signature, and its last chunk (IEND with its CRC).
const PNG_START: &[u8] = b"\x89PNG\r\n\x1a\n";
const PNG_END: &[u8] = b"IEND\xaeB`\x82";

#[test]
fn fopen_write_and_append_refuse_a_link_and_leave_its_target_alone() {
    let root = folder("link");
    std::fs::create_dir_all(root.join("scene")).unwrap();
    std::fs::create_dir_all(root.join("outside")).unwrap();
    let secret = root.join("outside/secret.txt");
    std::fs::write(&secret, "precious\n").unwrap();
    std::os::unix::fs::symlink(&secret, root.join("scene/link.txt")).unwrap();
    for mode in ["write", "append"] {
        let scene = root.join(format!("scene/{mode}.rts"));
        std::fs::write(
            &scene,
            format!("#fopen F \"link.txt\" {mode}\n#write (F, \"pwned\\n\")\n#fclose F\n{OBJECTS}"),
        )
        .unwrap();
        for cmd in [render_small(&scene, &root.join("out.png")), check(&scene)] {
            let out = run(cmd);
            assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
            // One error at the file name, none for the #write and #fclose after it.
            assert_eq!(
                codes(&out),
                ["rts::io::not_a_regular_file"],
                "{}",
                text(&out.stdout)
            );
            assert!(text(&out.stdout).contains(&format!("{mode}.rts:1:10:")));
        }
        assert_eq!(std::fs::read(&secret).unwrap(), b"precious\n");
    }
    // A link in the folder part leads out of the scene's folder: refused as before.
    std::os::unix::fs::symlink(root.join("outside"), root.join("scene/out")).unwrap();
    let scene = root.join("scene/folder.rts");
    std::fs::write(
        &scene,
        format!("#fopen F \"out/secret.txt\" write\n#write (F, \"x\")\n{OBJECTS}"),
    )
    .unwrap();
    let out = run(render_small(&scene, &root.join("out.png")));
    assert_eq!(codes(&out), ["rts::io::file_not_allowed"]);
    assert_eq!(std::fs::read(&secret).unwrap(), b"precious\n");
}

#[test]
fn fifos_and_devices_named_by_a_scene_are_refused_without_waiting() {
    let root = folder("fifo");
    mkfifo(&root.join("pipe.txt"));
    let cases = [
        (
            "write",
            "#fopen F \"pipe.txt\" write\n#write (F, \"x\")\n#fclose F\n",
        ),
        (
            "append",
            "#fopen F \"pipe.txt\" append\n#write (F, \"x\")\n#fclose F\n",
        ),
        ("read", "#fopen F \"pipe.txt\" read\n#read (F, X)\n"),
        ("include", "#include \"pipe.txt\"\n"),
        ("mesh", "mesh { obj_file \"pipe.txt\" }\n"),
    ];
    for (name, head) in cases {
        let scene = root.join(format!("{name}.rts"));
        std::fs::write(&scene, format!("{head}{OBJECTS}")).unwrap();
        for cmd in [render_small(&scene, &root.join("out.png")), check(&scene)] {
            let out = run(cmd);
            assert_eq!(out.status.code(), Some(1), "{name}: {}", text(&out.stderr));
            assert_eq!(
                codes(&out),
                ["rts::io::not_a_regular_file"],
                "{name}: {}",
                text(&out.stdout)
            );
        }
    }
    assert!(std::fs::metadata(root.join("pipe.txt"))
        .unwrap()
        .file_type()
        .is_fifo());
    // The scene itself: a FIFO, /dev/zero (which used to be read without end).
    for scene in [root.join("pipe.txt"), PathBuf::from("/dev/zero")] {
        let out = run(check(&scene));
        assert_eq!(out.status.code(), Some(1));
        let err = text(&out.stderr);
        assert!(err.contains("not a regular file"), "{err}");
    }
}

#[test]
fn what_a_scene_writes_has_one_budget_for_all_its_files() {
    let root = folder("budget");
    let scene = root.join("w.rts");
    std::fs::write(
        &scene,
        format!(
            "#fopen A \"a.txt\" write\n#fopen B \"b.txt\" write\n\
             #for (I, 1, 100)\n#write (A, \"0123456789\")\n#write (B, \"0123456789\")\n#end\n{OBJECTS}"
        ),
    )
    .unwrap();
    // 2000 bytes in two files of 1000: each fits under 1500, both do not.
    let mut c = check(&scene);
    c.args(["--max-write", "1500"]);
    let out = run(c);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(codes(&out), ["rts::limit::write_size"]);
    assert!(
        text(&out.stdout).contains("--max-write"),
        "{}",
        text(&out.stdout)
    );
    let mut c = render_small(&scene, &root.join("out.png"));
    c.args(["--max-write", "2K"]);
    let out = run(c);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    assert_eq!(std::fs::read(root.join("a.txt")).unwrap().len(), 1000);
    assert_eq!(std::fs::read(root.join("b.txt")).unwrap().len(), 1000);
    // Appending rewrites the file: what it held counts too.
    let scene = root.join("append.rts");
    std::fs::write(
        &scene,
        format!("#fopen A \"a.txt\" append\n#write (A, \"x\")\n#fclose A\n{OBJECTS}"),
    )
    .unwrap();
    let mut c = check(&scene);
    c.args(["--max-write", "999"]);
    assert_eq!(codes(&run(c)), ["rts::limit::write_size"]);
}

#[test]
fn source_files_over_the_size_limit_are_refused() {
    let root = folder("source");
    std::fs::write(root.join("big.inc"), format!("// {}\n", "x".repeat(4000))).unwrap();
    let scene = root.join("inc.rts");
    std::fs::write(&scene, format!("#include \"big.inc\"\n{OBJECTS}")).unwrap();
    let mut c = check(&scene);
    c.args(["--max-source-size", "2K"]);
    let out = run(c);
    assert_eq!(codes(&out), ["rts::limit::source_size"]);
    assert!(text(&out.stdout).contains("--max-source-size"));
    let mut c = check(&scene);
    c.args(["--max-source-size", "8K"]);
    assert_eq!(run(c).status.code(), Some(0));
    // #fopen … read takes the same limit.
    std::fs::write(&scene, format!("#fopen F \"big.inc\" read\n{OBJECTS}")).unwrap();
    let mut c = check(&scene);
    c.args(["--max-source-size", "2K"]);
    assert_eq!(codes(&run(c)), ["rts::limit::source_size"]);
    // The scene itself: an error line naming the flag.
    let mut c = check(&root.join("big.inc"));
    c.args(["--max-source-size", "2K"]);
    let out = run(c);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("--max-source-size"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn an_output_fifo_gets_one_png_and_stays_a_fifo() {
    let root = folder("out-fifo");
    let scene = root.join("s.rts");
    std::fs::write(&scene, OBJECTS).unwrap();
    let fifo = root.join("picture");
    mkfifo(&fifo);
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read(fifo).unwrap())
    };
    // No extension: PNG.
    let out = run(render_small(&scene, &fifo));
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let bytes = reader.join().unwrap();
    assert!(bytes.starts_with(PNG_START) && bytes.ends_with(PNG_END));
    let img = image::load_from_memory(&bytes).unwrap();
    assert_eq!((img.width(), img.height()), (8, 8));
    assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
    // A sequence needs files: refused before rendering, the FIFO untouched.
    let mut c = render_small(&scene, &fifo);
    c.args(["--frames", "1..3"]);
    let out = run(c);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("one per frame"),
        "{}",
        text(&out.stderr)
    );
    // So does a checkpoint; and OpenEXR (written out of order) into a stream.
    let mut c = render_small(&scene, &root.join("pt.png"));
    c.args([
        "--integrator",
        "path",
        "--spp",
        "1",
        "--checkpoint",
        s(&fifo),
    ]);
    let out = run(c);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("regular files only"),
        "{}",
        text(&out.stderr)
    );
    let mut c = render_small(&scene, &fifo);
    c.args(["--format", "exr"]);
    assert_eq!(run(c).status.code(), Some(2));
    assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
}

/// A FIFO at a frame's name is refused before any frame is rendered.
#[test]
fn a_fifo_among_the_frames_is_refused_before_rendering() {
    let root = folder("frames");
    let scene = root.join("s.rts");
    std::fs::write(&scene, OBJECTS).unwrap();
    mkfifo(&root.join("f_2.png"));
    let mut c = render_small(&scene, &root.join("f_#.png"));
    c.args(["--frames", "1..3"]);
    let out = run(c);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("f_2.png"),
        "{}",
        text(&out.stderr)
    );
    assert!(!root.join("f_1.png").exists(), "nothing rendered first");
}

#[test]
fn a_character_device_is_written_in_place() {
    let root = folder("device");
    let scene = root.join("s.rts");
    std::fs::write(&scene, OBJECTS).unwrap();
    // A private copy of /dev/null where the system lets us make one (as root), so
    // a regression cannot replace the machine's own; else /dev/null itself.
    let private = root.join("null");
    let made = Command::new("mknod")
        .args([s(&private), "c", "1", "3"])
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|st| st.success());
    let null = if made {
        private
    } else {
        PathBuf::from("/dev/null")
    };
    let mut c = render_small(&scene, &null);
    c.args(["--format", "png"]);
    let out = run(c);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(std::fs::metadata(&null)
        .unwrap()
        .file_type()
        .is_char_device());
    // Without --format, no extension: PNG, not "no extension is not a supported format".
    let out = run(render_small(&scene, &null));
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(std::fs::metadata(&null)
        .unwrap()
        .file_type()
        .is_char_device());
    assert!(std::fs::read_dir(&root).unwrap().all(|e| !e
        .unwrap()
        .file_name()
        .to_string_lossy()
        .ends_with(".tmp")));
}

#[test]
fn dash_writes_the_png_to_stdout_and_nothing_else() {
    let root = folder("stdout");
    let scene = root.join("s.rts");
    std::fs::write(&scene, OBJECTS).unwrap();
    // Not quiet: the statistics (and the scene's warnings) go to stderr.
    let out = run({
        let mut c = rts();
        c.current_dir(&root)
            .args(["render", "s.rts", "-o", "-", "-W", "8", "-H", "6"]);
        c
    });
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stdout.starts_with(PNG_START) && out.stdout.ends_with(PNG_END));
    let img = image::load_from_memory(&out.stdout).unwrap();
    assert_eq!((img.width(), img.height()), (8, 6));
    assert!(
        text(&out.stderr).contains("rendered 8x6"),
        "{}",
        text(&out.stderr)
    );
    assert!(!root.join("-").exists());
    // What else would print on stdout is refused with it.
    for extra in [["--stats-json", "-"], ["--message-format", "json"]] {
        let mut c = rts();
        c.args(["render", s(&scene), "-o", "-", "-q"]).args(extra);
        let out = run(c);
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
    }
}

#[test]
fn output_folders_are_made_or_refused_before_rendering() {
    let root = folder("folders");
    let scene = root.join("s.rts");
    std::fs::write(&scene, OBJECTS).unwrap();
    let out = run(render_small(&scene, &root.join("new/deeper/x.png")));
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(root.join("new/deeper/x.png").is_file());
    // A path through a file cannot be made: the error comes before a render that
    // would take hours (4 million pixels, 4096 samples each).
    std::fs::write(root.join("plain"), "").unwrap();
    for (flag, name) in [
        ("-o", "x.png"),
        ("--stats-json", "x.json"),
        ("--gif", "x.gif"),
    ] {
        let mut c = rts();
        c.args([
            "render",
            s(&scene),
            "-W",
            "2000",
            "-H",
            "2000",
            "--samples",
            "4096",
            "-q",
        ]);
        if flag != "-o" {
            c.args(["-o", s(&root.join("out.png"))]);
        }
        let target = root.join("plain").join(name);
        c.args([flag, s(&target)]);
        let out = run(c);
        assert_eq!(out.status.code(), Some(1), "{flag}: {}", text(&out.stderr));
        assert!(
            text(&out.stderr).contains(s(&target)),
            "{}",
            text(&out.stderr)
        );
    }
    // A folder is not an image.
    let mut c = render_small(&scene, &root.join("new"));
    c.args(["--format", "png"]);
    let out = run(c);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("folder"),
        "{}",
        text(&out.stderr)
    );
    assert!(root.join("new").is_dir());
}

/// Temporary files (`.NAME.XXXXXX.tmp`) in `dir`.
fn temporaries(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.') && n.ends_with(".tmp"))
        .collect()
}

/// A path traced render that writes its picture and checkpoint all the time,
/// stopped by `signal` as soon as a temporary file is seen: the exit status says
/// the signal, no temporary file is left, and the names seen are returned.
fn stop_while_writing(root: &Path, signal: &str, status: i32) -> Vec<String> {
    let scene = root.join("pt.rts");
    std::fs::write(
        &scene,
        format!(
            "#version 3.7; global_settings {{ assumed_gamma 1 path_tracing {{ }} }}\n\
                 camera {{ location <0, 1, -4> look_at 0 }}\n\
                 plane {{ y, -1 pigment {{ checker rgb 1 rgb 0.2 }} }}\n{OBJECTS}"
        ),
    )
    .unwrap();
    let out = root.join("out");
    let _ = std::fs::remove_dir_all(&out);
    std::fs::create_dir_all(&out).unwrap();
    let mut child = rts()
        .args(["render", s(&scene), "-o", s(&out.join("out.png")), "-q"])
        .args([
            "-W",
            "320",
            "-H",
            "240",
            "--time-limit",
            "50",
            "--save-every",
            "0.01",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let pid = child.id();
    let start = Instant::now();
    let mut seen = Vec::new();
    while seen.is_empty() && start.elapsed() < HANG && child.try_wait().unwrap().is_none() {
        seen = temporaries(&out);
    }
    assert!(!seen.is_empty(), "no temporary file seen");
    let sent = Command::new("kill")
        .args([&format!("-{signal}"), &pid.to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
    let result = finish(child, "the stopped render");
    assert_eq!(
        result.status.code(),
        Some(status),
        "{}",
        text(&result.stderr)
    );
    assert_eq!(temporaries(&out), Vec::<String>::new());
    for n in &seen {
        assert!(!n.contains(&pid.to_string()), "{n} is predictable");
    }
    seen
}

#[test]
fn ctrl_c_or_kill_leaves_no_temporary_file_and_names_are_unpredictable() {
    let root = folder("signals");
    let mut names = Vec::new();
    for (signal, status) in [("TERM", 143), ("INT", 130), ("TERM", 143)] {
        names.extend(stop_while_writing(&root, signal, status));
    }
    let mut unique = names.clone();
    unique.sort();
    unique.dedup();
    assert_eq!(unique.len(), names.len(), "a name came again: {names:?}");
}
