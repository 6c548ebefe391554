//! Completion: the keywords valid in the block the cursor is in (inside `finish { }`
//! only finish keywords), the names and macros in scope (macros with their
//! parameters), built-ins, directives after `#`, and file names in `#include "…"`.

use super::index::{include_candidates, DefKind};
use super::lexer::{context, Context};
use super::{docs, Analysis, Position, Range};
use crate::eval::{block_keywords, top_level_keywords};
use crate::syntax::keywords::KEYWORDS;
use std::collections::HashSet;
use std::path::Path;

/// What a completion item is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompletionKind {
    /// A keyword.
    Keyword,
    /// A directive name.
    Directive,
    /// A user's name.
    Variable,
    /// A user's macro.
    Macro,
    /// A built-in function.
    Function,
    /// A built-in constant.
    Constant,
    /// A file name.
    File,
}

/// One completion proposal.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CompletionItem {
    /// The text shown and inserted.
    pub label: String,
    /// What it is.
    pub kind: CompletionKind,
    /// A short description shown beside it.
    pub detail: String,
    /// A snippet to insert instead of the label (`$1` placeholders), for macros.
    pub snippet: Option<String>,
    /// The text the item replaces, when it is not the word before the cursor (the
    /// typed part of an `#include` file name, which may hold `/` and `.`).
    pub replace: Option<Range>,
}

fn item(label: &str, kind: CompletionKind, detail: &str) -> CompletionItem {
    CompletionItem {
        label: label.to_string(),
        kind,
        detail: detail.to_string(),
        snippet: None,
        replace: None,
    }
}

/// The completions at `pos`.
pub fn completion(a: &Analysis, pos: Position) -> Vec<CompletionItem> {
    let offset = a.offset(pos);
    match context(a.text(), offset) {
        Context::None => Vec::new(),
        Context::Directive => docs::DOCS
            .iter()
            .filter(|d| d.kind == docs::DocKind::Directive)
            .map(|d| item(d.name, CompletionKind::Directive, d.syntax))
            .collect(),
        Context::IncludeName(prefix) => {
            let dir = a.sources.get(a.main).dir().map(Path::to_path_buf);
            let typed = a.lines.range(a.text(), offset - prefix.len(), offset);
            include_candidates(dir.as_deref(), &a.options, &prefix)
                .into_iter()
                .map(|n| CompletionItem {
                    replace: Some(typed),
                    ..item(&n, CompletionKind::File, "include file")
                })
                .collect()
        }
        Context::Items(block) => {
            let keywords: Vec<&'static str> = match block.as_deref() {
                None => top_level_keywords(),
                Some(b) => block_keywords(b).unwrap_or_else(|| KEYWORDS.to_vec()),
            };
            let mut out: Vec<CompletionItem> = keywords
                .iter()
                .map(|k| {
                    let detail = docs::lookup(k).map_or("", |d| d.syntax);
                    item(k, CompletionKind::Keyword, detail)
                })
                .collect();
            names(a, offset, &mut out);
            for d in docs::DOCS {
                let kind = match d.kind {
                    docs::DocKind::Function => CompletionKind::Function,
                    docs::DocKind::Constant => CompletionKind::Constant,
                    _ => continue,
                };
                out.push(item(d.name, kind, d.syntax));
            }
            out
        }
    }
}

/// The user's names visible at `offset`: globals of the document and its includes,
/// and the parameters, locals and loop variables of the macro or loop around it.
fn names(a: &Analysis, offset: usize, out: &mut Vec<CompletionItem>) {
    let mut seen = HashSet::new();
    // Later definitions first, so the detail shows the one in effect.
    for d in a.index.defs.iter().rev() {
        if let Some(s) = d.scope {
            let inside = s.file == a.main && s.start as usize <= offset && offset <= s.end as usize;
            if !inside {
                continue;
            }
        }
        let name = d.name.to_string();
        if !seen.insert(name.clone()) {
            continue;
        }
        let mut it = item(&name, CompletionKind::Variable, d.kind.describe());
        if d.kind == DefKind::Macro {
            it.kind = CompletionKind::Macro;
            it.detail = format!("#macro {name}({})", d.params.join(", "));
            let placeholders: Vec<String> = d
                .params
                .iter()
                .enumerate()
                .map(|(i, p)| format!("${{{}:{}}}", i + 1, p.trim_start_matches("optional ")))
                .collect();
            it.snippet = Some(format!("{name}({})", placeholders.join(", ")));
        } else if let Some(g) = a.globals.iter().find(|g| g.name == name) {
            it.detail = match &g.value {
                Some(v) => format!("{}: {v}", g.kind),
                None => g.kind.to_string(),
            };
        } else if let Some(b) = d.block {
            it.detail = format!("{b} {{ … }}");
        }
        out.push(it);
    }
}
