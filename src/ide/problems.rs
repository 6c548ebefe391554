//! Diagnostics of a document as an editor shows them: the same ones `rts check`
//! prints, placed in the document (a problem inside an included file or a macro body
//! is shown at the `#include` or call in this document that leads to it), with the
//! include chain, macro call sites and secondary labels as related information.

use super::{Analysis, Location, Range};
use crate::diag::{Diagnostic, Severity};
use crate::span::Span;

/// A related location with a message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Related {
    /// Where.
    pub location: Location,
    /// What is there.
    pub message: String,
}

/// A diagnostic placed in the document.
#[derive(Clone, Debug, PartialEq)]
pub struct IdeDiagnostic {
    /// Where in the document.
    pub range: Range,
    /// Error, warning or note.
    pub severity: Severity,
    /// The stable code.
    pub code: &'static str,
    /// The message, with the help and notes after it.
    pub message: String,
    /// Secondary labels, the original place of a problem shown elsewhere, and the
    /// include/macro chain.
    pub related: Vec<Related>,
}

/// The diagnostics of the analysed document.
pub fn diagnostics(a: &Analysis) -> Vec<IdeDiagnostic> {
    a.raw_diagnostics.iter().map(|d| place(a, d)).collect()
}

fn place(a: &Analysis, d: &Diagnostic) -> IdeDiagnostic {
    let mut related = Vec::new();
    let mut message = d.message.clone();
    let span = if d.span.file == a.main {
        d.span
    } else {
        // The outermost step of the chain that lies in this document.
        let site = d.trace.iter().rev().find(|l| l.span.file == a.main);
        let name = a.describe_span(d.span);
        message = format!("in {name}: {message}");
        if let Some(loc) = a.location(d.span) {
            related.push(Related {
                location: loc,
                message: d.label.clone().unwrap_or_else(|| d.message.clone()),
            });
        }
        site.map_or(Span::new(a.main, 0, 0), |l| l.span)
    };
    // Inside a macro body in this document, the call site is a related location.
    for l in d.labels.iter().chain(d.trace.iter()) {
        if let Some(location) = a.location(l.span) {
            related.push(Related {
                location,
                message: l.message.clone(),
            });
        }
    }
    if let Some(h) = &d.help {
        message.push_str(&format!("\nhelp: {h}"));
    }
    for n in &d.notes {
        message.push_str(&format!("\nnote: {n}"));
    }
    IdeDiagnostic {
        range: a.range(span),
        severity: d.severity,
        code: d.code,
        message,
        related,
    }
}
