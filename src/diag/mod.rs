//! Diagnostics as data: one [`Diagnostic`] type, rendered at the edge as a miette report
//! ([`render::human`]), one line per error ([`render::short`]) or JSON ([`render::json`]).

pub mod codes;
mod excerpt;
pub mod render;
mod suggest;

pub use suggest::did_you_mean;

use crate::span::Span;

/// How serious a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// The scene cannot be rendered.
    Error,
    /// The scene renders, but probably not as meant.
    Warning,
    /// Information (`#debug`).
    Note,
}

impl Severity {
    /// The lowercase name used in the short and JSON formats.
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Note => "note",
        }
    }
}

/// A secondary location with a message.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// Where.
    pub span: Span,
    /// What to say there.
    pub message: String,
}

/// A problem in a scene, with the span responsible, a stable code and words that name
/// the fix.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// Error, warning or note.
    pub severity: Severity,
    /// Stable code, e.g. `rts::eval::unknown_identifier` (see [`codes`]).
    pub code: &'static str,
    /// One-line description of the problem.
    pub message: String,
    /// The primary location.
    pub span: Span,
    /// Text shown under the primary location.
    pub label: Option<String>,
    /// Further locations (e.g. where a block was opened).
    pub labels: Vec<Label>,
    /// How to fix it.
    pub help: Option<String>,
    /// Extra remarks.
    pub notes: Vec<String>,
    /// How evaluation got here: each `#include` and macro call on the way, innermost
    /// first.
    pub trace: Vec<Label>,
}

impl Diagnostic {
    /// An error at `span`.
    pub fn error(code: &'static str, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Error,
            code,
            message: message.into(),
            span,
            label: None,
            labels: Vec::new(),
            help: None,
            notes: Vec::new(),
            trace: Vec::new(),
        }
    }

    /// A warning at `span`.
    pub fn warning(code: &'static str, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Warning,
            ..Diagnostic::error(code, span, message)
        }
    }

    /// A note at `span`.
    pub fn note(code: &'static str, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Note,
            ..Diagnostic::error(code, span, message)
        }
    }

    /// Moves every span of the diagnostic `by` bytes later in its file (for text
    /// parsed out of a larger file).
    pub fn shift(&mut self, by: usize) {
        let by = by as u32;
        let move_span = |s: &mut Span| {
            s.start += by;
            s.end += by;
        };
        move_span(&mut self.span);
        for l in self.labels.iter_mut().chain(self.trace.iter_mut()) {
            move_span(&mut l.span);
        }
    }

    /// Sets the text under the primary span.
    pub fn with_label(mut self, label: impl Into<String>) -> Diagnostic {
        self.label = Some(label.into());
        self
    }

    /// Adds a secondary label.
    pub fn with_secondary(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.labels.push(Label {
            span,
            message: message.into(),
        });
        self
    }

    /// Sets the help text.
    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }

    /// Adds the help only when there is one.
    pub fn with_help_opt(mut self, help: Option<String>) -> Diagnostic {
        if help.is_some() {
            self.help = help;
        }
        self
    }

    /// Adds a note.
    pub fn with_note(mut self, note: impl Into<String>) -> Diagnostic {
        self.notes.push(note.into());
        self
    }

    /// Whether this is an error.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// Whether any diagnostic in the list is an error.
pub fn has_errors(diags: &[Diagnostic]) -> bool {
    diags.iter().any(Diagnostic::is_error)
}
