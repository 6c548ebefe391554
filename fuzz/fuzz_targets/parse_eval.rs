//! Fuzz parse + evaluate: any UTF-8 input must give diagnostics, never a panic or hang.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rts::eval::{eval, EvalOptions};
use rts::source::SourceMap;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let mut sources = SourceMap::new();
    let id = sources.add("fuzz.rts", None, text.to_string());
    let (file, diags) = rts::syntax::parse(text, id);
    if !rts::diag::has_errors(&diags) {
        let options = EvalOptions { max_loop_iterations: 100_000, max_macro_depth: 100, ..EvalOptions::default() };
        let _ = eval(&file, id, &mut sources, &options);
    }
});
