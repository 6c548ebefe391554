//! Comments, the one piece of lexical knowledge every scanner of the
//! language's text needs (the prepass, the data scanner, the built-in
//! library's cut, macros read token by token).

/// The offset after the comment that starts at `i` (`// …` to the end of its
/// line, `/* … */` with nesting as in POV-Ray; an unclosed one runs to the
/// end), or `None` when no comment starts there.
pub fn comment_end(b: &[u8], i: usize) -> Option<usize> {
    match (b.get(i), b.get(i + 1)) {
        (Some(b'/'), Some(b'/')) => {
            let mut j = i;
            while j < b.len() && b[j] != b'\n' {
                j += 1;
            }
            Some(j)
        }
        (Some(b'/'), Some(b'*')) => {
            let mut depth = 0usize;
            let mut j = i;
            while j < b.len() {
                if b[j..].starts_with(b"/*") {
                    depth += 1;
                    j += 2;
                } else if b[j..].starts_with(b"*/") {
                    depth -= 1;
                    j += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    j += 1;
                }
            }
            Some(j)
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::comment_end;

    #[test]
    fn comments_end_where_pov_ray_ends_them() {
        let t = b"// a\nx /* b /* c */ d */ y /* open";
        assert_eq!(comment_end(t, 0), Some(4));
        assert_eq!(comment_end(t, 5), None);
        assert_eq!(comment_end(t, 7), Some(24));
        assert_eq!(comment_end(t, 27), Some(t.len()));
    }
}
