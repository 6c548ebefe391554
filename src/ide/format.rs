//! Formatting: re-indents lines by nesting (braces, brackets, parentheses and
//! directive bodies such as `#if … #end`) and removes trailing blanks. It changes
//! only whitespace at line starts and ends, never tokens, so a formatted scene means
//! exactly what it meant; lines inside block comments are left as they are.

use super::lexer::{tokenize, TokKind};

const OPENERS: &[&str] = &[
    "#if", "#ifdef", "#ifndef", "#while", "#for", "#macro", "#switch",
];
const MIDDLE: &[&str] = &["#else", "#elseif", "#case", "#range", "#break"];

/// `text` re-indented with `unit` per level (e.g. two spaces or a tab).
pub fn format(text: &str, unit: &str) -> String {
    let toks = tokenize(text);
    let mut out = String::with_capacity(text.len());
    let mut depth: i64 = 0;
    let mut t = 0; // next token
    let mut line_start = 0;
    while line_start <= text.len() {
        let line_end = text[line_start..]
            .find('\n')
            .map_or(text.len(), |i| line_start + i);
        let line = &text[line_start..line_end];
        let cr = line.ends_with('\r');
        let line = line.strip_suffix('\r').unwrap_or(line);
        // A token that began on an earlier line and reaches into this one (a block
        // comment): keep the line untouched.
        while t < toks.len() && toks[t].end <= line_start {
            t += 1;
        }
        let inside_comment = t < toks.len() && toks[t].start < line_start;
        let first = toks[t..]
            .iter()
            .find(|k| k.start >= line_start && k.start < line_end.max(line_start + 1));
        if inside_comment {
            out.push_str(line);
        } else if line.trim().is_empty() {
            // Blank lines stay blank.
        } else {
            let mut level = depth;
            if let Some(f) = first {
                let s = &text[f.start..f.end];
                let closes = (f.kind == TokKind::Punct && matches!(s, "}" | "]" | ")"))
                    || (f.kind == TokKind::Directive && (s == "#end" || MIDDLE.contains(&s)));
                if closes {
                    level -= 1;
                }
            }
            for _ in 0..level.max(0) {
                out.push_str(unit);
            }
            out.push_str(line.trim());
        }
        if cr {
            out.push('\r');
        }
        // Nesting after this line.
        for k in toks[t..].iter().take_while(|k| k.start < line_end) {
            if k.start < line_start {
                continue;
            }
            let s = &text[k.start..k.end];
            match k.kind {
                TokKind::Punct => match s {
                    "{" | "(" | "[" => depth += 1,
                    "}" | ")" | "]" => depth = (depth - 1).max(0),
                    _ => {}
                },
                TokKind::Directive if OPENERS.contains(&s) => depth += 1,
                TokKind::Directive if s == "#end" => depth = (depth - 1).max(0),
                _ => {}
            }
        }
        if line_end == text.len() {
            break;
        }
        out.push('\n');
        line_start = line_end + 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn indents_by_nesting() {
        let text = "#macro M(A)\nsphere { A, 1\npigment { rgb 1 }   \n}\n#end\n\n#if (1)\n  box { 0, 1 }\n#else\nplane { y, 0 }\n#end\n/* keep\n      this */\n";
        let want = "#macro M(A)\n  sphere { A, 1\n    pigment { rgb 1 }\n  }\n#end\n\n#if (1)\n  box { 0, 1 }\n#else\n  plane { y, 0 }\n#end\n/* keep\n      this */\n";
        assert_eq!(format(text, "  "), want);
        assert_eq!(format(want, "  "), want);
        let crlf = "a {\r\nb\r\n}\r\n";
        assert_eq!(format(crlf, "  "), "a {\r\n  b\r\n}\r\n");
    }

    #[test]
    fn only_whitespace_changes() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let files = ["examples", "tests/fixtures/ok", "src/stdlib"]
            .iter()
            .flat_map(|d| std::fs::read_dir(root.join(d)).expect("dir").flatten())
            .filter(|e| e.path().is_file());
        for e in files {
            let text = std::fs::read_to_string(e.path()).expect("read");
            let f = format(&text, "\t");
            let strip = |s: &str| s.split_whitespace().collect::<String>();
            assert_eq!(strip(&text), strip(&f), "{}", e.path().display());
            assert_eq!(
                format(&f, "\t"),
                f,
                "not idempotent: {}",
                e.path().display()
            );
        }
    }
}
