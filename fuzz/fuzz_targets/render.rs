//! Fuzz the whole pipeline: parse, evaluate with small budgets, and when the
//! scene has no errors, build it and render a tiny image with the classic
//! renderer (adaptive anti-aliasing, a pass chosen by the input's length) and
//! with the path tracer at one sample per pixel. Any input must end in
//! diagnostics or a picture, never a panic, a hang or an unbounded allocation.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "harness.rs"]
mod harness;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    harness::on_big_stack(|| {
        harness::pipeline(text, data.len());
    });
});
