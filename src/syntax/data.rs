//! Literal data at memory speed: a run of plain numbers and vectors
//! (`3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>`, the grammar's `data_run`) is scanned
//! here into packed `f64`s, one pass over its text, instead of one expression
//! (and one syntax-tree node) per number. A block body of such elements is
//! read by the prepass as it checks it ([`plain_body`]); a short run keeps
//! where its elements are ([`DataRun::places`]), a long one does not (the
//! places are found again, without the numbers, when they are needed).

use crate::span::Span;

/// How many numbers each element of a run has (1: a number; 2 to 5: a vector).
#[derive(Clone, Debug, PartialEq)]
pub enum Dims {
    /// Every element has `n` numbers.
    Uniform(u8),
    /// Element `k` has `dims[k]` numbers.
    Mixed(Vec<u8>),
}

/// `0, <1, 2, 3>, <4, 5, 6>`: a run of plain numbers and vectors, packed.
#[derive(Clone, Debug, PartialEq)]
pub struct DataRun {
    /// Where the run was written.
    pub span: Span,
    /// Every element's numbers, in order.
    pub values: Vec<f64>,
    /// How the numbers divide into elements.
    pub dims: Dims,
    /// How many elements.
    pub len: usize,
    /// Where each element and comma was written, in order, as offsets into
    /// the run's text (a comma as `(at, COMMA)`): kept for short runs read by
    /// the prepass (a triangle's corners), whose elements become values with
    /// spans of their own; empty otherwise ([`scan_places`] finds them).
    pub places: Vec<(u32, u32)>,
}

/// The end [`DataRun::places`] gives a comma.
pub const COMMA: u32 = u32::MAX;

/// Runs longer than this keep no [`DataRun::places`].
const PLACES_MAX: usize = 32;

impl DataRun {
    /// The numbers of each element, in order.
    pub fn elements(&self) -> Elements<'_> {
        Elements {
            run: self,
            k: 0,
            at: 0,
        }
    }
}

/// The elements of a [`DataRun`]: each a slice of 1 (a number) to 5 numbers.
pub struct Elements<'a> {
    run: &'a DataRun,
    k: usize,
    at: usize,
}

impl<'a> Iterator for Elements<'a> {
    type Item = &'a [f64];

    fn next(&mut self) -> Option<&'a [f64]> {
        if self.k >= self.run.len {
            return None;
        }
        let n = match &self.run.dims {
            Dims::Uniform(n) => *n as usize,
            Dims::Mixed(d) => d[self.k] as usize,
        };
        let out = &self.run.values[self.at..self.at + n];
        self.k += 1;
        self.at += n;
        Some(out)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = self.run.len - self.k;
        (left, Some(left))
    }
}

impl ExactSizeIterator for Elements<'_> {}

/// What the scanner meets in a run's text, with byte offsets into that text.
#[derive(Debug, PartialEq)]
pub enum Piece<'a> {
    /// An element from `start` to `end`: its numbers.
    Element {
        /// Where it starts.
        start: usize,
        /// Where it ends.
        end: usize,
        /// Its numbers (1 for a number, 2 to 5 for a vector).
        values: &'a [f64],
    },
    /// A `,` between elements, at this offset.
    Comma(usize),
}

/// Why a run's text could not be read (a number too large for `f64`).
#[derive(Debug, PartialEq)]
pub struct BadNumber {
    /// Where the number starts in the run's text.
    pub start: usize,
    /// Where it ends.
    pub end: usize,
}

/// Scans the text of a `data_run` (the grammar guarantees its shape), calling
/// `f` for every element and comma in order.
pub fn scan(text: &str, f: impl FnMut(Piece<'_>)) -> Result<(), BadNumber> {
    scan_with(text, true, f)
}

/// [`scan`] for the places only: each element's `values` is empty (a run
/// already read has them; finding where elements start and end without
/// reading their numbers is several times cheaper).
pub fn scan_places(text: &str, f: impl FnMut(Piece<'_>)) {
    let _ = scan_with(text, false, f);
}

fn scan_with(text: &str, read: bool, mut f: impl FnMut(Piece<'_>)) -> Result<(), BadNumber> {
    let b = text.as_bytes();
    let number = |text: &str, i: usize| {
        if read {
            number(text, i)
        } else {
            match skip_number(text.as_bytes(), i) {
                // Not a number after all: stop rather than loop.
                end if end == i => Err(BadNumber { start: i, end }),
                end => Ok((0.0, end)),
            }
        }
    };
    let mut i = 0;
    let mut comps = [0.0f64; 5];
    loop {
        i = skip_gap(b, i);
        if i >= b.len() {
            return Ok(());
        }
        if b[i] == b',' {
            f(Piece::Comma(i));
            i += 1;
            continue;
        }
        let start = i;
        // `<`, or the marker the prepass puts in its place.
        if b[i] == b'<' || b[i] == super::prepass::PLAIN_VECTOR {
            i += 1;
            let mut n = 0;
            loop {
                i = skip_gap(b, i);
                match b.get(i) {
                    Some(b'>') => {
                        i += 1;
                        break;
                    }
                    Some(b',') => i += 1,
                    _ => {
                        let (v, next) = number(text, i)?;
                        if n < comps.len() {
                            comps[n] = v;
                        }
                        n += 1;
                        i = next;
                    }
                }
            }
            f(Piece::Element {
                start,
                end: i,
                values: &comps[..if read { n.min(comps.len()) } else { 0 }],
            });
        } else {
            let (v, next) = number(text, i)?;
            i = next;
            comps[0] = v;
            f(Piece::Element {
                start,
                end: i,
                values: &comps[..usize::from(read)],
            });
        }
    }
}

/// One component of a plain vector, with byte offsets into the vector's text.
#[derive(Debug, PartialEq)]
pub struct Component {
    /// The sign written before it and where: `Some((true, i))` for `-` at `i`.
    pub sign: Option<(bool, usize)>,
    /// Where its digits start.
    pub start: usize,
    /// Where they end.
    pub end: usize,
    /// The digits' value (the sign not applied), or `None` when it does not
    /// fit in an `f64`.
    pub value: Option<f64>,
}

/// The components of a plain vector's text (`<1, -2.5, 3e-2>`, as the
/// grammar's `plain_vector` took it), each with its sign and digits apart.
pub fn vector_components(text: &str) -> Vec<Component> {
    let b = text.as_bytes();
    let mut out = Vec::with_capacity(4);
    let mut i = skip_gap(b, 1);
    while i < b.len() && b[i] != b'>' {
        if b[i] == b',' {
            i = skip_gap(b, i + 1);
            continue;
        }
        let mut sign = None;
        if let Some(&s @ (b'-' | b'+')) = b.get(i) {
            sign = Some((s == b'-', i));
            i = skip_gap(b, i + 1);
        }
        let start = i;
        i = number_end(b, i);
        let value = super::decimal::parse(&text[start..i]);
        out.push(Component {
            sign,
            start,
            end: i,
            value,
        });
        if i == start {
            break; // not the grammar's shape: stop rather than loop
        }
        i = skip_gap(b, i);
    }
    out
}

/// How the numbers of a run divide into elements, noted element by element:
/// one count while every element has the same, one count each from the
/// first element of another size on.
#[derive(Default)]
struct DimsOf {
    uniform: Option<u8>,
    mixed: Vec<u8>,
    len: usize,
}

impl DimsOf {
    fn push(&mut self, n: u8) {
        match self.uniform {
            None if self.mixed.is_empty() => self.uniform = Some(n),
            Some(u) if u != n => {
                self.mixed = vec![u; self.len];
                self.mixed.push(n);
                self.uniform = None;
            }
            Some(_) => {}
            None => self.mixed.push(n),
        }
        self.len += 1;
    }

    /// The element sizes and how many elements.
    fn finish(self) -> (Dims, usize) {
        let dims = match self.uniform {
            Some(n) => Dims::Uniform(n),
            None => Dims::Mixed(self.mixed),
        };
        (dims, self.len)
    }
}

/// Reads `text` (the text of a `data_run` at `span`) into a packed run.
pub fn read(text: &str, span: Span) -> Result<DataRun, BadNumber> {
    let mut values = Vec::with_capacity(text.len() / 6);
    let mut dims = DimsOf::default();
    scan(text, |p| {
        if let Piece::Element { values: v, .. } = p {
            values.extend_from_slice(v);
            dims.push(v.len() as u8);
        }
    })?;
    values.shrink_to_fit();
    let (dims, len) = dims.finish();
    Ok(DataRun {
        span,
        values,
        dims,
        len,
        places: Vec::new(),
    })
}

/// The body that starts at `i` (after its `{`) when it is plain (two or more
/// plain numbers and vectors separated by commas, as the grammar's `data_run`
/// reads them), read in the same pass that checks it: where it stops
/// (its `}`, or the end of `b`) and its packed run, `None` when a number does
/// not fit in an `f64` (left to [`read`] to report). `None` when the body is
/// not plain; reading stops at the first byte that shows it.
pub fn plain_body(
    b: &[u8],
    mut i: usize,
    scratch: &mut Vec<f64>,
) -> Option<(usize, Option<DataRun>)> {
    let base = i;
    scratch.clear();
    let values = scratch;
    let mut places = Vec::with_capacity(16);
    let mut dims = DimsOf::default();
    let mut fits = true;
    i = skip_space(b, i);
    while i < b.len() && b[i] != b'}' {
        let before = values.len();
        let start = i;
        i = plain_element_into(b, i, values, &mut fits)?;
        if dims.len < PLACES_MAX {
            places.push(((start - base) as u32, (i - base) as u32));
        }
        dims.push((values.len() - before) as u8);
        let len = dims.len;
        i = skip_space(b, i);
        match b.get(i) {
            None | Some(b'}') => break,
            Some(b',') => {
                if len <= PLACES_MAX {
                    places.push(((i - base) as u32, COMMA));
                }
                i = skip_space(b, i + 1);
            }
            Some(_) => return None,
        }
    }
    let (dims, len) = dims.finish();
    if len < 2 {
        return None;
    }
    if !fits {
        return Some((i, None));
    }
    if len > PLACES_MAX {
        places = Vec::new();
    }
    let run = DataRun {
        span: Span::default(),
        values: values.as_slice().to_vec(),
        dims,
        len,
        places,
    };
    Some((i, Some(run)))
}

/// Spaces only (a body with comments is not marked).
fn skip_space(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && matches!(b[i], b' ' | b'\t' | b'\r' | b'\n' | 0x0B | 0x0C) {
        i += 1;
    }
    i
}

/// A plain number or vector at `i`: where it ends.
pub(crate) fn plain_element(b: &[u8], i: usize) -> Option<usize> {
    plain_element_with(b, i, |_| {})
}

/// [`plain_element`], its numbers pushed on `values` (`fits` cleared when
/// one does not fit in an `f64`).
fn plain_element_into(b: &[u8], i: usize, values: &mut Vec<f64>, fits: &mut bool) -> Option<usize> {
    plain_element_with(b, i, |v| match v {
        Some(v) => values.push(v),
        None => {
            *fits = false;
            values.push(0.0);
        }
    })
}

/// A plain number or vector at `i`, each of its numbers given to `number`
/// (`None` for one that does not fit in an `f64`): where it ends.
fn plain_element_with(b: &[u8], i: usize, mut number: impl FnMut(Option<f64>)) -> Option<usize> {
    if b[i] != b'<' {
        let (end, v) = plain_number(b, i)?;
        number(v);
        return Some(end);
    }
    let mut i = skip_space(b, i + 1);
    let mut n = 0;
    loop {
        let (end, v) = plain_number(b, i)?;
        number(v);
        i = skip_space(b, end);
        n += 1;
        match b.get(i)? {
            b',' => {
                i = skip_space(b, i + 1);
                if b.get(i) == Some(&b'>') {
                    return (2..=5).contains(&n).then_some(i + 1);
                }
            }
            b'>' => return (2..=5).contains(&n).then_some(i + 1),
            _ => return None,
        }
    }
}

/// A number as the grammar's `number` reads it, with an optional sign (and
/// spaces after the sign): where it ends, and its value.
fn plain_number(b: &[u8], mut i: usize) -> Option<(usize, Option<f64>)> {
    let mut negative = false;
    if let Some(&s @ (b'-' | b'+')) = b.get(i) {
        negative = s == b'-';
        i = skip_space(b, i + 1);
    }
    let (n, v) = super::decimal::prefix(b.get(i..)?)?;
    let end = i + n;
    if matches!(b.get(end), Some(b'e' | b'E')) {
        // `2e` is the number 2 and a name: not plain.
        return None;
    }
    Some((end, v.map(|v| if negative { -v } else { v })))
}

/// Where the digits of a number starting at `i` end: digits and points, then
/// an exponent (`e`, an optional sign, digits) when one follows.
pub fn number_end(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
        i += 1;
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        if j < b.len() && b[j].is_ascii_digit() {
            while j < b.len() && b[j].is_ascii_digit() {
                j += 1;
            }
            i = j;
        }
    }
    i
}

/// Skips spaces, comments (`// …` to the line's end, nested `/* … */`) and
/// `#`s: inside a run, a `#` can only be one that no directive name follows,
/// which the parser's copy of the text has as a space (see the prepass's
/// `Marks::blank`), so the file's own text reads as the parser read it.
fn skip_gap(b: &[u8], mut i: usize) -> usize {
    loop {
        match b.get(i) {
            Some(b' ' | b'\t' | b'\r' | b'\n' | 0x0B | 0x0C | b'#') => i += 1,
            Some(0xEF) if b.get(i + 1..i + 3) == Some(&[0xBB, 0xBF]) => i += 3,
            Some(b'/') if super::trivia::comment_end(b, i).is_some() => {
                i = super::trivia::comment_end(b, i).unwrap_or(b.len());
            }
            _ => return i,
        }
    }
}

/// Where the signed number at `i` ends (as [`number`] reads it).
fn skip_number(b: &[u8], mut i: usize) -> usize {
    if let Some(b'-' | b'+') = b.get(i) {
        i = skip_gap(b, i + 1);
    }
    number_end(b, i)
}

/// A signed number at `i` (a sign, spaces, then the digits the grammar's
/// `number` takes): its value and where it ends.
fn number(text: &str, mut i: usize) -> Result<(f64, usize), BadNumber> {
    let b = text.as_bytes();
    let start = i;
    let mut negative = false;
    if let Some(&s @ (b'-' | b'+')) = b.get(i) {
        negative = s == b'-';
        i = skip_gap(b, i + 1);
    }
    match super::decimal::prefix(&b[i..]) {
        Some((n, Some(v))) => Ok((if negative { -v } else { v }, i + n)),
        Some((n, None)) => Err(BadNumber { start, end: i + n }),
        None => Err(BadNumber {
            start,
            end: number_end(b, i),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether `text` (the inside of a `{ … }`) is nothing but two or more plain
    /// elements separated by commas, as the grammar's `data_run` reads them:
    /// numbers with an optional sign, and vectors of 2 to 5 such numbers with
    /// commas between (a trailing comma allowed, in a vector and after the last
    /// element; no comments). Such a body is read as one packed run.
    fn is_plain_body(text: &str) -> bool {
        matches!(plain_body(text.as_bytes(), 0, &mut Vec::new()), Some((end, _)) if end == text.len())
    }

    fn run(text: &str) -> DataRun {
        read(text, Span::default()).expect("readable")
    }

    #[test]
    fn numbers_and_vectors_are_packed() {
        let r = run("3, <0, 0, 0>, <1.5, -2, 3e-1>,\n  <+1,2,3,> // note\n");
        assert_eq!(r.len, 4);
        assert_eq!(
            r.dims,
            Dims::Mixed(vec![1, 3, 3, 3]),
            "a count, then vectors"
        );
        let e: Vec<&[f64]> = r.elements().collect();
        assert_eq!(e[0], &[3.0]);
        assert_eq!(e[2], &[1.5, -2.0, 0.3]);
        assert_eq!(e[3], &[1.0, 2.0, 3.0]);
        let u = run("<1, 2>, <3, 4> /* a /* nested */ comment */, <5, 6>");
        assert_eq!((u.len, u.dims), (3, Dims::Uniform(2)));
        assert_eq!(u.values, [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let n = run("- 1, .5, 2., 1E2");
        assert_eq!(n.values, [-1.0, 0.5, 2.0, 100.0]);
    }

    #[test]
    fn the_scanner_gives_element_and_comma_offsets() {
        let mut seen = Vec::new();
        scan("1, <2, 3>", |p| {
            seen.push(match p {
                Piece::Element { start, end, .. } => (start, end),
                Piece::Comma(at) => (at, at + 1),
            })
        })
        .unwrap();
        assert_eq!(seen, [(0, 1), (1, 2), (3, 9)]);
    }

    #[test]
    fn finding_places_skips_a_stray_hash_and_stops_at_what_is_not_a_number() {
        let mut seen = Vec::new();
        scan_places("1, # <2, 3,#>", |p| {
            seen.push(match p {
                Piece::Element { start, end, .. } => (start, end),
                Piece::Comma(at) => (at, at + 1),
            })
        });
        assert_eq!(seen, [(0, 1), (1, 2), (5, 13)]);
        // Text the grammar would not have taken as a run: no endless loop.
        let mut n = 0;
        scan_places("1, x, 2 <3, y>", |_| n += 1);
        assert_eq!(n, 2, "the element and comma before `x`");
    }

    #[test]
    fn a_plain_body_keeps_the_places_the_scanner_finds() {
        for text in [
            " <1, 2, 3>, - 4 ,<5,6>,",
            "1,2",
            &"7, ".repeat(32),
            &"7, ".repeat(33),
        ] {
            let (end, run) = plain_body(text.as_bytes(), 0, &mut Vec::new()).unwrap();
            assert_eq!(end, text.len());
            let run = run.unwrap();
            let mut want = Vec::new();
            let mut values = Vec::new();
            scan(text, |p| match p {
                Piece::Element {
                    start,
                    end,
                    values: v,
                } => {
                    want.push((start as u32, end as u32));
                    values.extend_from_slice(v);
                }
                Piece::Comma(at) => want.push((at as u32, COMMA)),
            })
            .unwrap();
            assert_eq!(run.values, values, "{text}");
            if run.len <= PLACES_MAX {
                assert_eq!(run.places, want, "{text}");
            } else {
                assert!(run.places.is_empty(), "a long run keeps no places");
            }
        }
    }

    #[test]
    fn plain_bodies_are_told_from_expressions() {
        assert!(is_plain_body(" 3, <0, 0, 0>, <1,-2.5,3e-2,>, <4, 5, 6>, "));
        assert!(is_plain_body("1,2"));
        assert!(is_plain_body("- 1, .5, 2., 1E+2"));
        assert!(!is_plain_body("1"), "one element");
        assert!(!is_plain_body("1 - 2, 3"), "a subtraction");
        assert!(!is_plain_body("1, 2 3"), "no comma");
        assert!(!is_plain_body("<1 2 3>, 4"), "a vector without commas");
        assert!(!is_plain_body("<1, 2> <3, 4>, 5"));
        assert!(!is_plain_body("<1>, 2"), "one component");
        assert!(!is_plain_body("<1,2,3,4,5,6>, 2"), "six components");
        assert!(!is_plain_body("1, 2e"));
        assert!(!is_plain_body("1, 2 < 3"));
        assert!(!is_plain_body("1, , 2"));
        assert!(!is_plain_body("."));
    }

    #[test]
    fn vector_components_keep_signs_and_places() {
        let c = vector_components("< -1.5,+2 , /* c */ 3e2,>");
        let got: Vec<_> = c
            .iter()
            .map(|c| (c.sign, c.start, c.end, c.value))
            .collect();
        assert_eq!(
            got,
            [
                (Some((true, 2)), 3, 6, Some(1.5)),
                (Some((false, 7)), 8, 9, Some(2.0)),
                (None, 20, 23, Some(300.0)),
            ]
        );
        assert_eq!(vector_components("<1e999, 0>")[0].value, None);
    }

    #[test]
    fn a_number_too_large_is_refused_with_its_place() {
        assert_eq!(
            read("1, 2e999", Span::default()),
            Err(BadNumber { start: 3, end: 8 })
        );
    }
}
