//! Documentation stays in step with the code: every diagnostic code is listed in
//! `docs/diagnostics.md`, and every fixture named there exists.

use std::path::Path;

fn read(rel: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn every_diagnostic_code_is_documented() {
    let codes = read("src/diag/codes.rs");
    let docs = read("docs/diagnostics.md");
    let mut n = 0;
    for line in codes.lines().filter(|l| l.starts_with("pub const ")) {
        let code = line.split('"').nth(1).expect("a string constant");
        n += 1;
        assert!(
            docs.contains(&format!("`{code}`")),
            "{code} is not in docs/diagnostics.md"
        );
    }
    assert!(n > 30, "found only {n} codes");
}

#[test]
fn fixtures_named_in_the_docs_exist() {
    let docs = read("docs/diagnostics.md");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures");
    for word in docs.split('`').filter(|w| w.ends_with(".rts")) {
        assert!(
            root.join("err").join(word).exists() || root.join("ok").join(word).exists(),
            "docs name {word}, which does not exist"
        );
    }
}
