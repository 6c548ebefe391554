//! The newcomer's documents cannot rot: every snippet of `docs/tutorial.md`, of the README
//! and the complete scenes of `docs/language.md` are run with the binary as a reader would
//! run them.
//!
//! Conventions (also written at the top of `docs/tutorial.md`):
//! - A ```` ```rts ```` block is a complete file whose first line is `// file: NAME`. The
//!   blocks of one page are written, in page order, to one temporary folder. A scene (`.rts`)
//!   must check with no diagnostic at all, or with exactly the codes of its
//!   `expect=CODE,CODE` attribute; a scene without errors is then rendered at 32×24 (a scene
//!   with an `animation { }` renders its frames and assembles them into a GIF). Include files
//!   (`.inc`) are only written: the scenes that include them check them.
//! - In a ```` ```sh ```` block every line that starts with `rts ` (or `cargo run --release --`,
//!   which stands for `rts`) runs through `sh` in that folder, with `-W`/`-H` made 32×24, and
//!   must succeed; `rts lsp` and `rts watch` (which do not end) and other programs (`cargo`,
//!   `npm`, `code`, `cd`) are not run. A relative path that names a file of the repository
//!   (`examples/showcase.rts`) is given to rts as that file.
//! - A ```` ```text output ```` block right after a ```` ```sh ```` block lists lines that
//!   the commands of that block print.

use std::path::{Path, PathBuf};
use std::process::Command;

/// One fenced block of a Markdown page.
struct Block {
    /// The first word of the info string (`rts`, `sh`, `text`).
    lang: String,
    /// The rest of the info string (`expect=…`, `output`).
    attrs: Vec<String>,
    text: String,
    /// 1-based line of the opening fence.
    line: usize,
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn read(rel: &str) -> String {
    let path = root().join(rel);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The fenced blocks of `md` (fences at the start of a line).
fn blocks(md: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut open: Option<Block> = None;
    for (i, line) in md.lines().enumerate() {
        match (&mut open, line.strip_prefix("```")) {
            (None, Some(info)) => {
                let mut words = info.split_whitespace().map(str::to_string);
                open = Some(Block {
                    lang: words.next().unwrap_or_default(),
                    attrs: words.collect(),
                    text: String::new(),
                    line: i + 1,
                });
            }
            (Some(_), Some(rest)) if rest.trim().is_empty() => out.push(open.take().unwrap()),
            (Some(b), _) => {
                b.text.push_str(line);
                b.text.push('\n');
            }
            (None, None) => {}
        }
    }
    assert!(open.is_none(), "a fence is not closed");
    out
}

/// A folder with `rts` in it, to put first on `PATH` for the shell lines.
fn bin_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rts-tutorial-bin-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let link = dir.join("rts");
    if !link.exists() {
        #[cfg(unix)]
        std::os::unix::fs::symlink(env!("CARGO_BIN_EXE_rts"), &link).unwrap();
        #[cfg(not(unix))]
        std::fs::copy(env!("CARGO_BIN_EXE_rts"), &link).unwrap();
    }
    dir
}

fn rts(dir: &Path, args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rts"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run rts");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The diagnostics `rts check` reports for `name`: (code, severity), sorted, no repeats.
fn check(dir: &Path, name: &str) -> Vec<(String, String)> {
    let (_, out, err) = rts(dir, &["check", name, "--message-format", "json"]);
    let mut diags: Vec<(String, String)> = out
        .lines()
        .map(|l| {
            serde_json::from_str::<serde_json::Value>(l)
                .unwrap_or_else(|e| panic!("{name}: not JSON ({e}): {l}\n{err}"))
        })
        .map(|v| {
            let field = |k: &str| v[k].as_str().expect("a string field").to_string();
            (field("code"), field("severity"))
        })
        .collect();
    diags.sort();
    diags.dedup();
    diags
}

/// Writes an ```rts block and checks (and renders) it when it is a scene.
fn run_file_block(page: &str, dir: &Path, b: &Block) {
    let first = b.text.lines().next().unwrap_or("");
    let name = first
        .strip_prefix("// file: ")
        .unwrap_or_else(|| {
            panic!(
                "{page}:{}: an rts block starts with `// file: NAME`",
                b.line
            )
        })
        .trim();
    std::fs::write(dir.join(name), &b.text).unwrap();
    if !name.ends_with(".rts") {
        return;
    }
    let mut expected: Vec<String> = b
        .attrs
        .iter()
        .filter_map(|a| a.strip_prefix("expect="))
        .flat_map(|list| list.split(',').map(str::to_string))
        .collect();
    expected.sort();
    let diags = check(dir, name);
    let codes: Vec<String> = diags.iter().map(|(c, _)| c.clone()).collect();
    assert_eq!(codes, expected, "{page}:{}: `rts check {name}`", b.line);
    if diags.iter().any(|(_, severity)| severity == "error") {
        return;
    }
    let stem = name.trim_end_matches(".rts");
    let small = ["-W", "32", "-H", "24", "-q"];
    if b.text.contains("animation {") {
        let frames = format!("{stem}_frames/f_##.png");
        let gif = format!("{stem}.gif");
        let mut args = vec!["render", name, "-o", &frames, "--gif", &gif];
        args.extend(small);
        let (ok, _, err) = rts(dir, &args);
        assert!(ok, "{page}:{}: rendering {name}: {err}", b.line);
        let bytes = std::fs::read(dir.join(&gif)).unwrap();
        assert!(
            bytes.starts_with(b"GIF89a"),
            "{page}:{}: {gif} is not a GIF",
            b.line
        );
    } else {
        let png = format!("{stem}.png");
        let mut args = vec!["render", name, "-o", &png];
        args.extend(small);
        let (ok, _, err) = rts(dir, &args);
        assert!(ok, "{page}:{}: rendering {name}: {err}", b.line);
        let bytes = std::fs::read(dir.join(&png)).unwrap();
        assert!(
            bytes.starts_with(b"\x89PNG"),
            "{page}:{}: {png} is not a PNG",
            b.line
        );
    }
}

/// The shell line as the test runs it: `rts` for `cargo run --release --`, a small picture,
/// repository files by their full path. `None` for lines not run.
fn shell_line(line: &str, dir: &Path) -> Option<String> {
    let line = line.trim();
    let line = match line.strip_prefix("cargo run --release -- ") {
        Some(rest) => format!("rts {rest}"),
        None => line.to_string(),
    };
    if !line.starts_with("rts ") || line.starts_with("rts lsp") || line.starts_with("rts watch") {
        return None;
    }
    // Drop a trailing `# comment` (a `#` after a blank; `f_##.png` keeps its `#`s).
    let code = match line.find(" #") {
        Some(i) => &line[..i],
        None => &line[..],
    };
    let mut words: Vec<String> = Vec::new();
    let mut sized = false;
    let mut it = code.split_whitespace().peekable();
    while let Some(w) = it.next() {
        match w {
            "-W" | "-H" => {
                it.next();
                words.push(w.to_string());
                words.push(if w == "-W" { "32" } else { "24" }.to_string());
                sized = true;
            }
            _ => {
                let repo_file = root().join(w);
                if !w.starts_with('-') && !dir.join(w).exists() && repo_file.is_file() {
                    words.push(repo_file.display().to_string());
                } else {
                    words.push(w.to_string());
                }
            }
        }
    }
    if words.get(1).map(String::as_str) == Some("render") && !sized {
        words.extend(["-W", "32", "-H", "24"].map(str::to_string));
    }
    Some(words.join(" "))
}

/// Runs the `rts` lines of an ```sh block; returns what they printed.
fn run_shell_block(page: &str, dir: &Path, b: &Block) -> (usize, String) {
    let path = format!(
        "{}:{}",
        bin_dir().display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let mut printed = String::new();
    let mut n = 0;
    for line in b.text.lines() {
        let Some(cmd) = shell_line(line, dir) else {
            continue;
        };
        let out = Command::new("sh")
            .arg("-c")
            .arg(&cmd)
            .current_dir(dir)
            .env("PATH", &path)
            .output()
            .expect("run sh");
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(
            out.status.success(),
            "{page}:{}: `{}` (run as `{cmd}`) failed:\n{text}",
            b.line,
            line.trim()
        );
        printed.push_str(&text);
        n += 1;
    }
    (n, printed)
}

/// Runs every snippet of `page`; returns the numbers of files and of commands checked.
fn run_page(page: &str) -> (usize, usize) {
    let md = read(page);
    let dir = tempfile::tempdir().unwrap();
    let (mut files, mut commands) = (0, 0);
    let mut last_output: Option<String> = None;
    for b in blocks(&md) {
        match (b.lang.as_str(), b.attrs.iter().any(|a| a == "output")) {
            ("rts", _) => {
                run_file_block(page, dir.path(), &b);
                files += 1;
                last_output = None;
            }
            ("sh", _) => {
                let (n, printed) = run_shell_block(page, dir.path(), &b);
                commands += n;
                last_output = Some(printed);
            }
            ("text", true) => {
                let printed = last_output
                    .as_deref()
                    .unwrap_or_else(|| panic!("{page}:{}: output block after no sh block", b.line));
                for want in b.text.lines().map(str::trim).filter(|l| !l.is_empty()) {
                    assert!(
                        printed.contains(want),
                        "{page}:{}: the commands did not print\n  {want}\nthey printed:\n{printed}",
                        b.line
                    );
                }
            }
            _ => last_output = None,
        }
    }
    (files, commands)
}

#[test]
fn tutorial_snippets_check_and_render() {
    let (files, commands) = run_page("docs/tutorial.md");
    // The tutorial's scenes and include file, and its rts commands: a page that lost its
    // blocks (a broken fence, a renamed tag) must fail here, not pass on nothing.
    assert!(files >= 8, "only {files} rts blocks in docs/tutorial.md");
    assert!(
        commands >= 8,
        "only {commands} rts commands in docs/tutorial.md"
    );
}

#[test]
fn readme_snippets_check_and_render() {
    let (files, commands) = run_page("README.md");
    assert!(files >= 1, "the README's first scene is not an rts block");
    assert!(commands >= 2, "only {commands} rts commands in README.md");
}

/// The reference's complete scenes (tagged `rts`; its fragments are untagged blocks).
#[test]
fn language_reference_scenes_check_and_render() {
    let (files, _) = run_page("docs/language.md");
    assert!(files >= 1, "docs/language.md has no complete rts scene");
}

/// The README's first block is the two commands a newcomer runs on a fresh clone: one
/// renders an example with anti-aliasing, the other is the test command CI runs.
#[test]
fn readme_starts_with_the_two_commands_ci_runs() {
    let readme = read("README.md");
    let first = blocks(&readme).into_iter().next().expect("a block");
    assert_eq!(first.lang, "sh", "README.md:{}", first.line);
    let commands: Vec<&str> = first
        .text
        .lines()
        .map(|l| l.split(" #").next().unwrap().trim())
        .filter(|l| !l.is_empty())
        .collect();
    assert_eq!(commands.len(), 2, "README's first block: {commands:?}");
    assert!(
        commands[0].starts_with("cargo run --release -- render examples/")
            && commands[0].contains("--antialias"),
        "the first command renders an example, anti-aliased: {}",
        commands[0]
    );
    let ci = read(".ci/run");
    assert!(
        ci.lines().any(|l| l.trim() == commands[1]),
        ".ci/run does not run the README's test command `{}`",
        commands[1]
    );
}

/// `docs/language.md` is the reference: syntax and meaning. How rts was measured against
/// POV-Ray belongs in `docs/compatibility.md`.
#[test]
fn language_reference_has_contents_and_no_measurement_notes() {
    let md = read("docs/language.md");
    assert!(
        md.contains("## Contents"),
        "docs/language.md has no table of contents"
    );
    for (i, line) in md.lines().enumerate() {
        assert!(
            !line.to_lowercase().contains("measured"),
            "docs/language.md:{}: a measurement note (move it to docs/compatibility.md): {line}",
            i + 1
        );
    }
    // Every link of the table of contents leads to a heading of the page.
    let anchors: Vec<String> = md
        .lines()
        .filter_map(|l| l.strip_prefix("## ").or_else(|| l.strip_prefix("### ")))
        .map(anchor)
        .collect();
    let contents = md.split("## Contents").nth(1).unwrap();
    let contents = &contents[..contents.find("\n## ").unwrap_or(contents.len())];
    let mut n = 0;
    for link in contents.split("](#").skip(1) {
        let target = &link[..link.find(')').unwrap()];
        assert!(
            anchors.iter().any(|a| a == target),
            "no heading for #{target}"
        );
        n += 1;
    }
    assert!(n >= 10, "the table of contents has only {n} links");
}

/// GitHub's anchor for a heading: lower case, spaces to `-`, punctuation dropped.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}
