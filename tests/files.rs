//! Files a scene writes and reads cannot hurt the user (the binary as users run
//! it): no writing through links, no waiting on FIFOs, no endless reads of
//! devices, budgets for what a scene writes and reads. A command that should end
//! but blocks fails its test after a generous time instead of hanging it.
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
