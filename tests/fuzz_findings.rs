//! Scenes the fuzzer found (see fuzz/README.md), each fixed in `src/`: every
//! `tests/fuzz/*.rts` is evaluated from the fuzz asset folder with the fuzz
//! target's budgets, then built and rendered at 8×6 by the classic renderer
//! (each debug pass and the shaded picture) and the path tracer, exactly as the
//! `render` fuzz target does. Each must get as far as rendering, without a panic.
//!
//! Some findings were integer overflows that only panic with overflow checks
//! on (`cargo test` without `--release`, and the fuzz build).

#[path = "../fuzz/fuzz_targets/harness.rs"]
mod harness;

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

#[test]
fn every_scene_the_fuzzer_found_renders_without_a_panic() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "rts"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no scenes in {}", dir.display());
    let mut failed = Vec::new();
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        // Depth, normal, albedo, then the shaded picture.
        for choice in 0..4 {
            let run = catch_unwind(AssertUnwindSafe(|| {
                harness::on_big_stack(|| harness::pipeline(&text, choice))
            }));
            match run {
                Ok(true) => {}
                Ok(false) => failed.push(format!("{name}: has errors, so it is not rendered")),
                Err(_) => failed.push(format!("{name}: panicked (pass {choice})")),
            }
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}
