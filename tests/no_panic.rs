//! Arbitrary input never panics the front end: random text and random soups of real
//! tokens go through parse and evaluate.

use proptest::prelude::*;
use rts::eval::{eval, EvalOptions};
use rts::source::SourceMap;

fn check(text: String) {
    // The CLI runs the front end on a large stack; do the same here.
    std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(move || {
            let mut sources = SourceMap::new();
            let id = sources.add("fuzz.rts", None, text.clone());
            let (file, diags) = rts::syntax::parse(&text, id);
            if !rts::diag::has_errors(&diags) {
                let options = EvalOptions {
                    max_loop_iterations: 10_000,
                    max_macro_depth: 50,
                    ..EvalOptions::default()
                };
                let out = eval(&file, id, &mut sources, &options);
                for d in &out.diagnostics {
                    let _ = rts::diag::render::short(d, &sources);
                    let _ = rts::diag::render::json(d, &sources);
                }
            } else {
                for d in &diags {
                    let _ = rts::diag::render::human(d, &sources, false);
                }
            }
        })
        .unwrap()
        .join()
        .expect("front end panicked");
}

const TOKENS: &[&str] = &[
    "sphere",
    "{",
    "}",
    "<",
    ">",
    ",",
    "0",
    "1",
    "-1",
    "2.5",
    "x",
    "y",
    "pigment",
    "finish",
    "phong",
    "rgb",
    "color",
    "#declare",
    "#local",
    "A",
    "=",
    ";",
    "#if",
    "(",
    ")",
    "#end",
    "#else",
    "#while",
    "#macro",
    "M",
    "M(",
    "#for",
    "I",
    "#switch",
    "#case",
    "#break",
    "array[2]",
    "[",
    "]",
    ".x",
    "+",
    "*",
    "/",
    "?",
    ":",
    "\"s\"",
    "camera",
    "light_source",
    "union",
    "object",
    "translate",
    "scale",
    "0",
    "checker",
    "reflection",
    "#include",
    "\"colors.inc\"",
    "#debug",
    "plane",
    "box",
    "triangle",
    "/*",
    "*/",
    "//",
    "\n",
    "!",
    "&",
    "|",
];

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, .. ProptestConfig::default() })]

    #[test]
    fn random_text_never_panics(s in "\\PC{0,200}") {
        check(s);
    }

    #[test]
    fn token_soup_never_panics(idx in proptest::collection::vec(0..TOKENS.len(), 0..60)) {
        let text = idx.iter().map(|i| TOKENS[*i]).collect::<Vec<_>>().join(" ");
        check(text);
    }
}
