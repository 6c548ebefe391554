//! Fuzz parse + evaluate: any UTF-8 input must give diagnostics, never a panic,
//! a hang or an unbounded allocation.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "harness.rs"]
mod harness;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    harness::on_big_stack(|| {
        let _ = harness::parse_eval(text);
    });
});
