//! Semantic tokens: keywords, directives, comments, strings, numbers, built-in
//! functions and constants, and the user's macros, parameters and variables, so
//! editors colour names by what they are rather than by how they look.

use super::index::DefKind;
use super::lexer::{tokenize, TokKind};
use super::{docs, Analysis};
use crate::syntax::keywords::KEYWORDS;
use rustc_hash::FxHashMap;

/// The token types, in the order of their numbers (the LSP legend).
pub const TOKEN_TYPES: &[&str] = &[
    "keyword",
    "comment",
    "string",
    "number",
    "function",
    "variable",
    "parameter",
    "macro",
];

/// The token modifiers, bit `i` for entry `i` (the LSP legend).
pub const TOKEN_MODIFIERS: &[&str] = &["declaration", "defaultLibrary", "readonly"];

const KEYWORD: u32 = 0;
const COMMENT: u32 = 1;
const STRING: u32 = 2;
const NUMBER: u32 = 3;
const FUNCTION: u32 = 4;
const VARIABLE: u32 = 5;
const PARAMETER: u32 = 6;
const DECLARATION: u32 = 1;
const DEFAULT_LIBRARY: u32 = 2;
const READONLY: u32 = 4;

/// Words of the grammar that are not in [`KEYWORDS`] (colour and array words).
const OTHER_WORDS: &[&str] = &[
    "color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft", "red",
    "green", "blue", "gray", "grey", "array", "optional",
];

/// One token: 0-based line, start column and length in UTF-16 units, type and
/// modifier bits (see [`TOKEN_TYPES`], [`TOKEN_MODIFIERS`]). Tokens never span lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SemanticToken {
    /// Line.
    pub line: u32,
    /// Start column (UTF-16).
    pub start: u32,
    /// Length (UTF-16).
    pub length: u32,
    /// Index into [`TOKEN_TYPES`].
    pub token_type: u32,
    /// Bits of [`TOKEN_MODIFIERS`].
    pub modifiers: u32,
}

/// The semantic tokens of the document, in order.
pub fn semantic_tokens(a: &Analysis) -> Vec<SemanticToken> {
    let text = a.text();
    let mut kinds: FxHashMap<String, u32> = FxHashMap::default();
    for d in &a.index.defs {
        let t = match d.kind {
            DefKind::Macro => FUNCTION,
            DefKind::Param => PARAMETER,
            _ => VARIABLE,
        };
        kinds.entry(d.name.to_string()).or_insert(t);
    }
    let decls: rustc_hash::FxHashSet<u32> = a
        .index
        .defs
        .iter()
        .filter(|d| d.span.file == a.main)
        .map(|d| d.span.start)
        .collect();
    let mut out = Vec::new();
    for tok in tokenize(text) {
        let word = &text[tok.start..tok.end];
        let (ty, mods) = match tok.kind {
            TokKind::Comment => (COMMENT, 0),
            TokKind::Str => (STRING, 0),
            TokKind::Number => (NUMBER, 0),
            TokKind::Directive => (KEYWORD, 0),
            TokKind::Punct => continue,
            TokKind::Word => {
                if KEYWORDS.binary_search(&word).is_ok() || OTHER_WORDS.contains(&word) {
                    (KEYWORD, 0)
                } else if let Some(d) =
                    docs::lookup(word).filter(|d| d.kind != docs::DocKind::Keyword)
                {
                    if d.kind == docs::DocKind::Function {
                        (FUNCTION, DEFAULT_LIBRARY)
                    } else {
                        (VARIABLE, DEFAULT_LIBRARY | READONLY)
                    }
                } else {
                    let ty = kinds.get(word).copied().unwrap_or(VARIABLE);
                    let m = if decls.contains(&(tok.start as u32)) {
                        DECLARATION
                    } else {
                        0
                    };
                    (ty, m)
                }
            }
        };
        // Split multi-line tokens (block comments) into one token per line.
        let mut start = tok.start;
        for piece in text[tok.start..tok.end].split_inclusive('\n') {
            let body = piece.trim_end_matches(['\n', '\r']);
            if !body.is_empty() {
                let p = a.lines.position(text, start);
                out.push(SemanticToken {
                    line: p.line,
                    start: p.character,
                    length: body.chars().map(char::len_utf16).sum::<usize>() as u32,
                    token_type: ty,
                    modifiers: mods,
                });
            }
            start += piece.len();
        }
    }
    out
}
