//! The editor's analysis functions never panic, whatever the document holds and
//! wherever the cursor is: random text and random soups of real tokens.

use proptest::prelude::*;
use rts::ide::{self, Position};
use std::collections::HashMap;
use std::path::Path;

fn check(text: String, positions: Vec<(u32, u32)>) {
    // The server analyses on a large stack, as the CLI does.
    std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(move || {
            let mut options = ide::editor_options(Vec::new());
            options.max_loop_iterations = 10_000;
            options.max_macro_depth = 50;
            let path = std::env::temp_dir().join("rts-ide-fuzz/none.rts");
            let a = ide::analyze(Path::new(&path), &text, &HashMap::new(), &options);
            let _ = ide::diagnostics(&a);
            let _ = ide::semantic_tokens(&a);
            let _ = ide::outline(&a);
            let formatted = ide::format(&text, "  ");
            assert_eq!(
                ide::format(&formatted, "  "),
                formatted,
                "formatting is idempotent"
            );
            for (line, character) in positions {
                let p = Position { line, character };
                let _ = ide::hover(&a, p);
                let _ = ide::completion(&a, p);
                let _ = ide::definition(&a, p);
                let _ = ide::references(&a, p, true);
            }
        })
        .expect("thread")
        .join()
        .expect("an ide function panicked");
}

const TOKENS: &[&str] = &[
    "sphere",
    "{",
    "}",
    "<",
    ">",
    ",",
    "(",
    ")",
    "[",
    "]",
    "#declare",
    "#local",
    "#macro",
    "#end",
    "#include",
    "#if",
    "#for",
    "\"colors.inc\"",
    "\"",
    "A",
    "B",
    "M",
    "=",
    ";",
    "1",
    "0.5",
    "finish",
    "phong",
    "pigment",
    "rgb",
    "/*",
    "*/",
    "//",
    "\n",
    " ",
    "é",
    "😀",
    "\t",
    "#",
    "optional",
    "array",
    "x",
    "sin",
    "union",
    "camera",
    "location",
];

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn random_text(text in "\\PC{0,200}", pos in proptest::collection::vec((0u32..6, 0u32..60), 0..6)) {
        check(text, pos);
    }

    #[test]
    fn token_soup(toks in proptest::collection::vec(proptest::sample::select(TOKENS), 0..80),
                  pos in proptest::collection::vec((0u32..8, 0u32..80), 0..8)) {
        check(toks.join(" "), pos);
    }
}
