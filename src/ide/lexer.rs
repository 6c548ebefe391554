//! A forgiving tokenizer for editor features that must work on text being typed (which
//! may not parse): semantic tokens, the word under the cursor, the block the cursor is
//! in. It never fails: unclosed strings end at the line end, unclosed comments at the
//! end of the text.

/// What a token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TokKind {
    /// `// …` or `/* … */`.
    Comment,
    /// `"…"`.
    Str,
    /// `1.5`, `.5`, `2e-3`.
    Number,
    /// An identifier or keyword.
    Word,
    /// `#` followed by a word: the token covers both.
    Directive,
    /// Any other character.
    Punct,
}

/// A token: its kind and byte range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tok {
    /// What it is.
    pub kind: TokKind,
    /// First byte.
    pub start: usize,
    /// One past the last byte.
    pub end: usize,
}

fn is_word(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// Splits `text` into tokens (whitespace is skipped).
pub fn tokenize(text: &str) -> Vec<Tok> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        let start = i;
        let kind = if c.is_ascii_whitespace() || c == 0x0B {
            i += 1;
            continue;
        } else if c == b'/' && b.get(i + 1) == Some(&b'/') {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
            TokKind::Comment
        } else if c == b'/' && b.get(i + 1) == Some(&b'*') {
            let mut depth = 0usize;
            while i < b.len() {
                if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
                    depth += 1;
                    i += 2;
                } else if b[i] == b'*' && b.get(i + 1) == Some(&b'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
            TokKind::Comment
        } else if c == b'"' {
            i += 1;
            while i < b.len() && b[i] != b'"' && b[i] != b'\n' {
                if b[i] == b'\\' && i + 1 < b.len() && b[i + 1] != b'\n' {
                    i += 1;
                }
                i += 1;
            }
            if i < b.len() && b[i] == b'"' {
                i += 1;
            }
            TokKind::Str
        } else if c.is_ascii_digit() || (c == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit))
        {
            i = crate::syntax::data::number_end(b, i);
            TokKind::Number
        } else if c.is_ascii_alphabetic() || c == b'_' {
            while i < b.len() && is_word(b[i]) {
                i += 1;
            }
            TokKind::Word
        } else if c == b'#' && b.get(i + 1).is_some_and(|n| n.is_ascii_alphabetic()) {
            i += 1;
            while i < b.len() && is_word(b[i]) {
                i += 1;
            }
            TokKind::Directive
        } else {
            i += 1;
            while i < b.len() && !text.is_char_boundary(i) {
                i += 1;
            }
            TokKind::Punct
        };
        out.push(Tok {
            kind,
            start,
            end: i,
        });
    }
    out
}

/// The token containing byte `offset`, or ending exactly at it (the cursor just after a
/// word still names that word).
pub fn token_at(toks: &[Tok], offset: usize) -> Option<Tok> {
    let i = toks.partition_point(|t| t.end < offset);
    let t = *toks.get(i)?;
    if t.start <= offset && offset <= t.end {
        // Prefer a word starting right at the offset over punctuation ending there.
        if t.end == offset {
            if let Some(n) = toks.get(i + 1) {
                if n.start == offset && n.kind != TokKind::Punct {
                    return Some(*n);
                }
            }
        }
        Some(t)
    } else {
        None
    }
}

/// Where the cursor at `offset` stands, for completion.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Context {
    /// Inside the string of `#include "…`: the text typed so far.
    IncludeName(String),
    /// After `#`: a directive name.
    Directive,
    /// Inside a comment or another string: nothing to complete.
    None,
    /// Among items: the keyword of the innermost block (`None` at top level).
    Items(Option<String>),
}

/// The completion context at byte `offset` of `text`.
pub fn context(text: &str, offset: usize) -> Context {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let toks = tokenize(&text[..offset]);
    // Blocks: `WORD {` pushes WORD, any other `{` pushes nothing useful.
    let mut stack: Vec<Option<String>> = Vec::new();
    for (i, t) in toks.iter().enumerate() {
        if t.kind != TokKind::Punct {
            continue;
        }
        match &text[t.start..t.end] {
            "{" => {
                let kw = i
                    .checked_sub(1)
                    .map(|p| toks[p])
                    .filter(|p| p.kind == TokKind::Word)
                    .map(|p| text[p.start..p.end].to_string());
                stack.push(kw);
            }
            "}" => {
                stack.pop();
            }
            _ => {}
        }
    }
    if let Some(last) = toks.last() {
        let s = &text[last.start..last.end];
        let touching = last.end == offset;
        match last.kind {
            TokKind::Comment
                if touching && (s.starts_with("//") || !s.ends_with("*/") || s.len() < 4) =>
            {
                return Context::None
            }
            TokKind::Str if touching && (s.len() == 1 || !s.ends_with('"')) => {
                let before = toks.len().checked_sub(2).map(|p| toks[p]);
                if before.is_some_and(|b| {
                    b.kind == TokKind::Directive && &text[b.start..b.end] == "#include"
                }) {
                    return Context::IncludeName(s[1..].to_string());
                }
                return Context::None;
            }
            TokKind::Directive if touching => return Context::Directive,
            TokKind::Punct if touching && s == "#" => return Context::Directive,
            _ => {}
        }
    }
    Context::Items(stack.into_iter().rev().find_map(|k| k))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contexts() {
        let t = "sphere { 0, 1 finish { ph";
        assert_eq!(context(t, t.len()), Context::Items(Some("finish".into())));
        let t = "sphere { 0, 1 finish { phong 1 } ";
        assert_eq!(context(t, t.len()), Context::Items(Some("sphere".into())));
        let t = "#include \"col";
        assert_eq!(context(t, t.len()), Context::IncludeName("col".into()));
        let t = "// sphere { ";
        assert_eq!(context(t, t.len()), Context::None);
        let t = "#dec";
        assert_eq!(context(t, t.len()), Context::Directive);
        let t = "/* a */ ";
        assert_eq!(context(t, t.len()), Context::Items(None));
    }

    #[test]
    fn tokens() {
        let t = "#declare A = 1.5e3; /* x /* y */ z */ \"s\\\"t\" // c\nb";
        let kinds: Vec<TokKind> = tokenize(t).iter().map(|t| t.kind).collect();
        use TokKind::*;
        assert_eq!(
            kinds,
            [Directive, Word, Punct, Number, Punct, Comment, Str, Comment, Word]
        );
    }
}
