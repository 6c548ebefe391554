//! Keeping going after a syntax error: what the skipped text says that is
//! worth reporting (a misspelled block keyword, `sphear {`) and what it would
//! have declared (so evaluating the rest does not report those names as
//! unknown).

use super::keywords::KEYWORDS;
use crate::diag::{codes, did_you_mean, Diagnostic};
use crate::span::{FileId, Span};

/// Words of `text[from..to]` outside strings and comments, with their offsets.
fn words(text: &str, from: usize, to: usize) -> Vec<(usize, &str)> {
    let b = text.as_bytes();
    let to = to.min(b.len());
    let mut out = Vec::new();
    let mut i = from;
    while i < to {
        match b[i] {
            b'"' => {
                i += 1;
                while i < to && b[i] != b'"' && b[i] != b'\n' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
                i += 1;
            }
            b'/' if b.get(i + 1) == Some(&b'/') => {
                while i < to && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                i += 2;
                while i < to && !(b[i] == b'*' && b.get(i + 1) == Some(&b'/')) {
                    i += 1;
                }
                i += 2;
            }
            c if c.is_ascii_alphabetic() || c == b'_' => {
                let start = i;
                while i < to && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                    i += 1;
                }
                // A word right after a digit is part of a number (`1e5`).
                if start == 0 || !b[start - 1].is_ascii_digit() {
                    out.push((start, &text[start..i]));
                }
            }
            _ => i += 1,
        }
    }
    out
}

/// The offset of the next character after `i` that is not a space.
fn next_solid(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && b[i].is_ascii_whitespace() {
        i += 1;
    }
    i
}

/// A word that is not a keyword, at `start`, standing before `{`: only a
/// keyword opens a block.
fn unknown_block(word: &str, start: usize, file: FileId) -> Diagnostic {
    let span = Span::new(file, start, start + word.len());
    let mut d = Diagnostic::error(
        codes::UNKNOWN_BLOCK,
        span,
        format!("`{word}` is not a keyword, so it cannot open a block"),
    )
    .with_label("not a keyword");
    d = match did_you_mean(word, KEYWORDS.iter().copied()) {
        Some(s) => d.with_help(format!("did you mean `{s}`?")),
        None => d.with_help(
            "a block starts with a keyword such as `sphere`, `pigment` or `texture`; a declared object is placed with `object { Name }`",
        ),
    };
    d
}

/// When the parse stopped at a `{` (offset `at`) right after a word that is
/// not a keyword: that word, reported as such.
pub(super) fn unknown_block_before(text: &str, at: usize, file: FileId) -> Option<Diagnostic> {
    let b = text.as_bytes();
    if !matches!(b.get(at), Some(b'{' | 0x01)) {
        return None;
    }
    let mut end = at;
    while end > 0 && b[end - 1].is_ascii_whitespace() {
        end -= 1;
    }
    let mut start = end;
    while start > 0 && (b[start - 1].is_ascii_alphanumeric() || b[start - 1] == b'_') {
        start -= 1;
    }
    let word = &text[start..end];
    let first = word.bytes().next()?;
    if !(first.is_ascii_alphabetic() || first == b'_') || KEYWORDS.binary_search(&word).is_ok() {
        return None;
    }
    Some(unknown_block(word, start, file))
}

/// Every word of `text[from..to]` that is not a keyword and stands before a
/// `{` (the parse would stop at each).
pub(super) fn unknown_blocks(text: &str, from: usize, to: usize, file: FileId) -> Vec<Diagnostic> {
    let b = text.as_bytes();
    words(text, from, to)
        .into_iter()
        .filter(|(start, w)| {
            b.get(next_solid(b, start + w.len())) == Some(&b'{')
                && KEYWORDS.binary_search(w).is_err()
                && !matches!(*w, "colour" | "color" | "array")
        })
        .map(|(start, w)| unknown_block(w, start, file))
        .collect()
}

/// The names that `#declare NAME`, `#local NAME` and `#macro NAME` in `text`
/// define.
pub(super) fn declared_names(text: &str) -> Vec<String> {
    let b = text.as_bytes();
    let all = words(text, 0, text.len());
    let mut out = Vec::new();
    for pair in all.windows(2) {
        let (at, kw) = pair[0];
        if !matches!(kw, "declare" | "local" | "macro") {
            continue;
        }
        // `#` (and spaces) right before the directive's word.
        let mut h = at;
        while h > 0 && matches!(b[h - 1], b' ' | b'\t') {
            h -= 1;
        }
        if h > 0 && b[h - 1] == b'#' {
            out.push(pair[1].1.to_string());
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn misspelled_block_keywords_are_found_outside_strings_and_comments() {
        let t = "sphear { 0, 1 pigmnet { rgb 1 } } // foo {\n#debug \"bar {\" box { 0, 1 }";
        let found: Vec<String> = unknown_blocks(t, 0, t.len(), FileId(0))
            .into_iter()
            .map(|d| d.message)
            .collect();
        assert_eq!(found.len(), 2, "{found:?}");
        assert!(found[0].contains("`sphear`") && found[1].contains("`pigmnet`"));
    }

    #[test]
    fn declared_names_in_skipped_text() {
        let t = "#declare A = 1 +;\n# local B = 2;\n#macro M(X) X #end\ndeclare C";
        assert_eq!(declared_names(t), ["A", "B", "M"]);
    }
}
