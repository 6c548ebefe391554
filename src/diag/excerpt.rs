//! The part of a source file a report shows, safe to print: only the lines
//! around the labels (a report on a 36 MB mesh file copies a few lines, not the
//! file), with control characters shown as visible symbols so bytes from a
//! scene (an ESC sequence, a carriage return, a right-to-left override) can
//! never drive the terminal or hide text.

use crate::source::SourceFile;
use miette::{MietteError, MietteSpanContents, SourceCode, SourceSpan, SpanContents};
use std::borrow::Cow;

/// Lines kept before the first and after the last label (the report shows
/// fewer; these leave it room).
const CONTEXT_LINES: usize = 4;

/// A window of a source file, escaped, that reports its real line numbers.
#[derive(Debug)]
pub(crate) struct Excerpt {
    name: String,
    text: String,
    /// The 0-based line of the file the window starts at.
    first_line: usize,
    /// Byte offset in the file of the window's start.
    start: usize,
    /// Byte offset in the file of the window's end.
    end: usize,
    /// For each escaped character: its offset in the window (unescaped) and how
    /// many bytes longer the text is after it than before it, in order.
    growth: Vec<(usize, usize)>,
}

impl Excerpt {
    /// The window of `file` that holds every one of `spans` (byte ranges of
    /// the file) with a few lines around.
    pub(crate) fn new(file: &SourceFile, spans: &[(usize, usize)]) -> Excerpt {
        let text = file.text.as_str();
        let lo = spans.iter().map(|s| s.0).min().unwrap_or(0).min(text.len());
        let hi = spans
            .iter()
            .map(|s| s.1)
            .max()
            .unwrap_or(0)
            .clamp(lo, text.len());
        let first_line = (file.line_col(lo).0 - 1).saturating_sub(CONTEXT_LINES);
        let last_line = file.line_col(hi).0 - 1 + CONTEXT_LINES;
        let start = file.line_start(first_line);
        let end = file.line_start(last_line + 1).max(start);
        let (shown, growth) = escape_with_growth(&text[start..end]);
        Excerpt {
            name: file.name.clone(),
            text: shown,
            first_line,
            start,
            end,
            growth,
        }
    }

    /// The window's span for the file's byte range `start..end`.
    pub(crate) fn span(&self, start: usize, end: usize) -> SourceSpan {
        let a = self.offset(start);
        let b = self.offset(end.max(start));
        (a, b - a).into()
    }

    /// How many bytes escaping added before offset `at` of the window's text.
    fn growth_before(&self, at: usize) -> usize {
        match self.growth.partition_point(|&(p, extra)| p + extra <= at) {
            0 => 0,
            k => self.growth[k - 1].1,
        }
    }

    /// The window's offset for a byte offset of the file.
    fn offset(&self, at: usize) -> usize {
        let rel = at.clamp(self.start, self.end) - self.start;
        let extra = match self.growth.partition_point(|&(p, _)| p < rel) {
            0 => 0,
            k => self.growth[k - 1].1,
        };
        rel + extra
    }
}

impl SourceCode for Excerpt {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        context_lines_before: usize,
        context_lines_after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        let inner = self
            .text
            .read_span(span, context_lines_before, context_lines_after)?;
        // The column (a byte count from the line's start, for the report's
        // `file:line:column` header) is the file's, not the escaped text's.
        let column = match inner.column() {
            0 => 0,
            c => {
                let at = span.offset();
                c - (self.growth_before(at) - self.growth_before(at - c.min(at)))
            }
        };
        Ok(Box::new(MietteSpanContents::new_named(
            self.name.clone(),
            inner.data(),
            *inner.span(),
            inner.line() + self.first_line,
            column,
            inner.line_count(),
        )))
    }
}

/// How a character is shown when it must not reach the terminal as it is:
/// C0 controls (but tab and line ends) as their control pictures (`␛`), DEL as
/// `␡`, C1 controls and the bidirectional overrides and isolates as `\u{…}`.
fn shown_as(c: char, next: Option<char>) -> Option<Cow<'static, str>> {
    match c {
        '\t' | '\n' => None,
        '\r' if next == Some('\n') => None,
        '\u{0}'..='\u{1f}' => char::from_u32(0x2400 + c as u32).map(|p| p.to_string().into()),
        '\u{7f}' => Some("\u{2421}".into()),
        '\u{80}'..='\u{9f}'
        | '\u{200e}'
        | '\u{200f}'
        | '\u{202a}'..='\u{202e}'
        | '\u{2066}'..='\u{2069}' => Some(format!("\\u{{{:04x}}}", c as u32).into()),
        _ => None,
    }
}

/// `text` with control characters made visible (see [`shown_as`]); borrowed
/// when there is none.
pub fn visible(text: &str) -> Cow<'_, str> {
    let mut chars = text.chars().peekable();
    let mut out: Option<String> = None;
    let mut at = 0;
    while let Some(c) = chars.next() {
        match shown_as(c, chars.peek().copied()) {
            Some(s) => {
                let o = out.get_or_insert_with(|| text[..at].to_string());
                o.push_str(&s);
            }
            None => {
                if let Some(o) = &mut out {
                    o.push(c);
                }
            }
        }
        at += c.len_utf8();
    }
    match out {
        Some(o) => Cow::Owned(o),
        None => Cow::Borrowed(text),
    }
}

/// [`visible`], with where the text grew: (offset in `text`, total growth
/// after that character).
fn escape_with_growth(text: &str) -> (String, Vec<(usize, usize)>) {
    let mut out = String::with_capacity(text.len());
    let mut growth = Vec::new();
    let mut extra = 0;
    let mut chars = text.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        match shown_as(c, chars.peek().map(|&(_, n)| n)) {
            Some(s) => {
                out.push_str(&s);
                extra += s.len() - c.len_utf8();
                growth.push((i + c.len_utf8(), extra));
            }
            None => out.push(c),
        }
    }
    (out, growth)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(text: &str) -> crate::source::SourceMap {
        let mut m = crate::source::SourceMap::new();
        m.add("t.rts", None, text.to_string());
        m
    }

    #[test]
    fn control_characters_are_shown_not_sent() {
        assert_eq!(visible("a\u{1b}[31mb"), "a\u{241b}[31mb");
        assert_eq!(visible("x\ry\r\n\t"), "x\u{240d}y\r\n\t");
        assert_eq!(visible("\u{202e}abc"), "\\u{202e}abc");
        assert!(matches!(visible("plain é"), Cow::Borrowed(_)));
    }

    #[test]
    fn the_window_keeps_lines_around_the_span_and_maps_offsets() {
        let lines: Vec<String> = (1..=40).map(|i| format!("line {i}")).collect();
        let mut text = lines.join("\n");
        // An ESC on line 20, before the span.
        let at = text.find("line 20").unwrap();
        text.insert(at, '\u{1b}');
        let m = file(&text);
        let f = m.get(crate::span::FileId(0));
        let span_start = text.find("line 21").unwrap();
        let e = Excerpt::new(f, &[(span_start, span_start + 7)]);
        assert_eq!(e.first_line, 16, "four lines before line 21 (0-based 20)");
        assert!(e.text.starts_with("line 17\n"), "{}", e.text);
        assert!(e.text.ends_with("line 25\n"), "{}", e.text);
        let s = e.span(span_start, span_start + 7);
        assert_eq!(&e.text[s.offset()..s.offset() + s.len()], "line 21");
        let contents = e.read_span(&s, 0, 0).unwrap();
        assert_eq!(contents.line(), 20, "0-based line of the file");
        // On the line of the ESC, the column is the file's (in bytes).
        let x = text.find("line 20").unwrap() + 5;
        let contents = e.read_span(&e.span(x, x + 2), 0, 0).unwrap();
        assert_eq!((contents.line(), contents.column()), (19, 6));
    }
}
