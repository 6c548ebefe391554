//! Snapshot tests over `tests/fixtures`: every `ok/*.rts` checks clean (its `#debug`
//! lines and warnings are the snapshot), every `err/*.rts` fails with the diagnostics
//! in the snapshot, in the short format and in the graphical (miette) report.
//!
//! Review changed snapshots with `cargo insta review` (or set `INSTA_UPDATE=always`).

use std::path::Path;
use std::process::Command;

/// Runs `rts check` on a fixture from inside its folder so paths in the output are
/// short and stable.
fn check(path: &Path, format: &str) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rts"))
        .current_dir(path.parent().expect("fixture folder"))
        .args(["check", "--message-format", format])
        .arg(path.file_name().expect("fixture name"))
        .env("NO_COLOR", "1")
        .output()
        .expect("run rts");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out.status.code().unwrap_or(-1), text)
}

#[test]
fn valid_scenes_check_clean() {
    insta::glob!("fixtures/ok/*.rts", |path| {
        let (code, short) = check(path, "short");
        assert_eq!(code, 0, "{}: {short}", path.display());
        assert!(!short.contains(": error["), "{short}");
        insta::assert_snapshot!(short);
    });
}

#[test]
fn invalid_scenes_report_diagnostics() {
    insta::glob!("fixtures/err/*.rts", |path| {
        let (code, short) = check(path, "short");
        assert_eq!(code, 1, "{}: {short}", path.display());
        assert!(short.contains(": error[rts::"), "{short}");
        let (_, human) = check(path, "human");
        // Every stable code in the short output also appears in the report.
        for line in short.lines().filter(|l| l.contains(": error[")) {
            let code = line.split('[').nth(1).and_then(|s| s.split(']').next());
            let code = code.expect("a code in every short line");
            assert!(human.contains(code), "{code} missing from:\n{human}");
        }
        insta::assert_snapshot!(format!("{short}\n{human}"));
    });
}
