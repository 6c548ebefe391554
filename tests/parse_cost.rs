//! The grammar's work grows in proportion to the input: every scene here is
//! parsed with pest's rule-call limit set to a fixed number of calls per byte
//! (the limit is process-wide, so this file holds one test). A rule that reads
//! ahead to the end of the input from each of many places (quadratic work, as
//! the comparison-or-vector lookahead once did on a run of unclosed `<`: 21 s
//! for 68 KB), or one that reads the same failing text again at each level of
//! nesting (exponential work: 6 s for 216 bytes of `s !e +<0.4, `), exceeds it
//! and the parse reports an error instead of a tree.

use std::num::NonZeroUsize;
use std::path::Path;

/// Rule calls allowed per byte of input (plus a constant for tiny inputs).
const CALLS_PER_BYTE: usize = 400;

fn parses_within_the_limit(name: &str, text: &str) -> Result<(), String> {
    let file = rts::span::FileId(0);
    let messages = |diags: Vec<rts::diag::Diagnostic>| -> Vec<String> {
        diags.into_iter().map(|d| d.message).collect()
    };
    let free = messages(rts::syntax::parse(text, file).1);
    pest::set_call_limit(NonZeroUsize::new(CALLS_PER_BYTE * text.len() + 100_000));
    let limited = messages(rts::syntax::parse(text, file).1);
    pest::set_call_limit(None);
    // A parse stopped by the limit ends in an error the free one does not have.
    if limited == free {
        Ok(())
    } else {
        Err(format!(
            "{name}: needs more than {CALLS_PER_BYTE} rule calls a byte"
        ))
    }
}

#[test]
fn parsing_takes_work_in_proportion_to_the_input() {
    // On a stack as big as the one `rts` parses on.
    std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(check_all)
        .unwrap()
        .join()
        .unwrap();
}

fn check_all() {
    let mut failed = Vec::new();
    // Runs of unclosed `<` after a value (found by the fuzzer), and other
    // shapes of unclosed or nested brackets.
    let hostile = [
        (
            "unclosed vectors after values",
            "#declare A = a".to_string() + &" < .4, 0.4, b 0.".repeat(1000),
        ),
        (
            "comparisons",
            "#declare A = a".to_string() + &" < b".repeat(1000),
        ),
        (
            "vectors in comparisons",
            "#declare A = 1".to_string() + &" < <1,".repeat(1000),
        ),
        (
            // Each `+<` once read the vector after it twice (as the operand of
            // `+`, then as a new component signed `+`): 2^18 times here.
            "signs before nested unclosed vectors",
            "#declare A = ".to_string() + &"s !e +<0.4, ".repeat(18) + "1;",
        ),
        (
            "unclosed parentheses",
            "#declare A = a".to_string() + &" < (b".repeat(1000),
        ),
    ];
    for (name, text) in &hostile {
        if let Err(e) = parses_within_the_limit(name, text) {
            failed.push(e);
        }
    }
    // Every example scene: the limit is not too tight for real input.
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    for entry in std::fs::read_dir(examples).unwrap() {
        let p = entry.unwrap().path();
        if p.extension().is_some_and(|e| e == "rts" || e == "inc") {
            let text = std::fs::read_to_string(&p).unwrap();
            if let Err(e) = parses_within_the_limit(&p.display().to_string(), &text) {
                failed.push(e);
            }
        }
    }
    assert!(failed.is_empty(), "{failed:#?}");
}
