//! "Did you mean" suggestions by edit distance.

/// Edit distance between two short strings, case-insensitive: insertions,
/// deletions, substitutions and swaps of neighbours (`widht` is one edit from
/// `width`) each count one (strsim's optimal string alignment distance).
fn distance(a: &str, b: &str) -> usize {
    strsim::osa_distance(&a.to_lowercase(), &b.to_lowercase())
}

/// The candidate closest to `word`, if it is close enough to be a likely typo
/// (distance at most a third of the word's length, and at least 1 allowed).
pub fn did_you_mean<'a>(
    word: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<&'a str> {
    let limit = (word.chars().count() / 3).max(1);
    candidates
        .into_iter()
        .filter(|c| *c != word)
        .map(|c| (distance(word, c), c))
        .filter(|(d, _)| *d <= limit)
        .min_by(|a, b| a.0.cmp(&b.0).then(a.1.cmp(b.1)))
        .map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggests_close_words_only() {
        assert_eq!(
            did_you_mean("phongsize", ["phong_size", "phong"]),
            Some("phong_size")
        );
        assert_eq!(did_you_mean("spehre", ["sphere", "plane"]), Some("sphere"));
        assert_eq!(did_you_mean("xyzzy", ["sphere", "plane"]), None);
        assert_eq!(distance("abc", "abc"), 0);
        // A swap of neighbours is one typo.
        assert_eq!(did_you_mean("widht", ["width", "wood"]), Some("width"));
    }
}
