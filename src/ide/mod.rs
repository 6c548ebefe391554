//! Editor analysis: pure functions over a document and the files it includes, used by
//! the language server (`rts lsp`) and called directly by tests.
//!
//! [`analyze`] parses and evaluates a document exactly as `rts check` does and indexes
//! its names ([`index::Index`]); the feature functions ([`diagnostics`], [`hover`],
//! [`completion`], [`definition`], [`references`], [`outline`], [`semantic_tokens`],
//! [`format`])
//! answer questions about the result, with positions in UTF-16 as editors count them.
//! The only I/O is reading included files through the evaluator's file search; texts of
//! documents open in the editor are given as overlays and win over the disk.

mod completion;
pub mod docs;
mod format;
mod hover;
mod incremental;
pub mod index;
pub mod lexer;
mod navigation;
mod problems;
mod text;
mod tokens;

#[cfg(test)]
mod tests;

pub use completion::{completion, CompletionItem, CompletionKind};
pub use format::format;
pub use hover::hover;
pub use navigation::{definition, references};
pub use problems::{diagnostics, IdeDiagnostic, Related};
pub use text::{LineIndex, Position, Range};
pub use tokens::{semantic_tokens, SemanticToken, TOKEN_MODIFIERS, TOKEN_TYPES};

use crate::diag::Diagnostic;
use crate::eval::{self, Declared, EvalOptions};
use crate::source::SourceMap;
use crate::span::{FileId, Span};
use index::{Index, OutlineItem};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// A location in some file: its path (for the built-in library, `<stdlib>/NAME`) and
/// range.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The file.
    pub path: PathBuf,
    /// The range in it.
    pub range: Range,
}

/// Everything known about one document after analysis.
#[derive(Debug)]
pub struct Analysis {
    /// The document and every file read for it.
    pub sources: SourceMap,
    /// The document's id in [`Self::sources`].
    pub main: FileId,
    /// Every diagnostic `rts check` reports for the document (any file).
    pub raw_diagnostics: Vec<Diagnostic>,
    /// The global names evaluation left, with their values (empty when it could not
    /// run).
    pub globals: Vec<Declared>,
    /// Definitions, uses, includes and outline.
    pub index: Index,
    /// The options the document was evaluated with.
    pub options: EvalOptions,
    lines: LineIndex,
}

/// The canonical form of a path when it exists, else the path as given.
pub fn canonical(path: &Path) -> PathBuf {
    path.canonicalize().unwrap_or_else(|_| path.to_path_buf())
}

/// Analyzes the document at `path` whose text is `text`. `overlays` holds the texts of
/// other open documents by canonical path; includes of those files read the overlay
/// instead of the disk.
pub fn analyze(
    path: &Path,
    text: &str,
    overlays: &HashMap<PathBuf, String>,
    options: &EvalOptions,
) -> Analysis {
    let mut sources = SourceMap::new();
    let main_path = canonical(path);
    for (p, t) in overlays {
        if *p != main_path {
            sources.add(p.display().to_string(), Some(p.clone()), t.clone());
        }
    }
    let main = sources.add(
        path.display().to_string(),
        Some(main_path),
        text.to_string(),
    );
    let (file, mut raw) = incremental::parse(text, main);
    let mut globals = Vec::new();
    // After syntax errors the items that parsed are evaluated too.
    if !crate::diag::has_errors(&raw) || !file.unparsed.is_empty() {
        let evaluated = eval::eval(&file, main, &mut sources, options);
        raw.extend(evaluated.diagnostics);
        globals = evaluated.globals;
    }
    let index = Index::build(&mut sources, options, main, &file.items);
    Analysis {
        sources,
        main,
        raw_diagnostics: raw,
        globals,
        index,
        options: options.clone(),
        lines: LineIndex::new(text),
    }
}

impl Analysis {
    /// The document's text.
    pub fn text(&self) -> &str {
        &self.sources.get(self.main).text
    }

    /// The byte offset of a position in the document.
    pub fn offset(&self, pos: Position) -> usize {
        self.lines.offset(self.text(), pos)
    }

    /// The range of a span of any file.
    pub fn range(&self, span: Span) -> Range {
        let text = &self.sources.get(span.file).text;
        if span.file == self.main {
            self.lines
                .range(text, span.start as usize, span.end as usize)
        } else {
            LineIndex::new(text).range(text, span.start as usize, span.end as usize)
        }
    }

    /// The location of a span, when its file has a path.
    pub fn location(&self, span: Span) -> Option<Location> {
        let path = self.sources.get(span.file).path.clone()?;
        Some(Location {
            path,
            range: self.range(span),
        })
    }

    /// `file:line` of a span, as shown in hovers.
    pub fn describe_span(&self, span: Span) -> String {
        let f = self.sources.get(span.file);
        let (line, _) = f.line_col(span.start as usize);
        let name = f
            .path
            .as_deref()
            .and_then(Path::file_name)
            .map_or_else(|| f.name.clone(), |n| n.to_string_lossy().into_owned());
        format!("{name}:{line}")
    }

    /// The files this document includes (directly or not), for re-checking it when
    /// one of them changes.
    pub fn included_paths(&self) -> Vec<PathBuf> {
        self.index
            .files
            .iter()
            .skip(1)
            .filter_map(|f| self.sources.get(*f).path.clone())
            .collect()
    }
}

/// The outline of the document: declarations, macros, objects, camera, lights,
/// settings.
pub fn outline(a: &Analysis) -> &[OutlineItem] {
    &a.index.outline
}

/// Default evaluation options for a document in an editor: the document's folder is
/// searched by the evaluator itself; `include_dirs` are added to the search.
pub fn editor_options(include_dirs: Vec<PathBuf>) -> EvalOptions {
    let mut o = EvalOptions::default();
    o.access.include_dirs = include_dirs;
    // An editor checks as the user types: keep runaway loops and macros short
    // and the memory small (the language server also cancels an analysis
    // when a newer edit arrives, and gives each a few seconds).
    o.max_loop_iterations = 2_000_000;
    o.max_macro_calls = 1_000_000;
    o.max_memory = o.max_memory.min(512 << 20);
    o
}
