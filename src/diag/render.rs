//! The three renderings of a [`Diagnostic`]: a miette report for people, one line for
//! tools (`short`), and one JSON object per line (`json`).

use super::excerpt::{visible, Excerpt};
use super::{codes, Diagnostic, Label, Severity};
use crate::source::SourceMap;
use crate::span::Span;
use miette::{GraphicalReportHandler, GraphicalTheme, LabeledSpan};
use std::fmt;

/// `FILE:LINE:COL: error[CODE]: MESSAGE`, plus ` (help: …)` when there is help.
/// A `#debug` text's final line ends are left out and inner ones shown as `\n`,
/// so each diagnostic stays one line.
pub fn short(diag: &Diagnostic, sources: &SourceMap) -> String {
    let (file, line, col) = position(sources, diag.span.start as usize, diag.span);
    let message = message_line(diag);
    let mut out = format!(
        "{}:{line}:{col}: {}[{}]: {}",
        visible(&file),
        diag.severity.as_str(),
        diag.code,
        visible(&message)
    );
    if let Some(help) = &diag.help {
        out.push_str(&format!(" (help: {})", visible(help)));
    }
    out
}

/// The message on one line: a `#debug` text without its final line ends, inner
/// ones as `\n`.
fn message_line(diag: &Diagnostic) -> std::borrow::Cow<'_, str> {
    if diag.code == codes::USER_DEBUG {
        let text = diag.message.trim_end_matches('\n');
        if text.contains('\n') {
            return text.replace('\n', "\\n").into();
        }
        return text.into();
    }
    diag.message.as_str().into()
}

fn position(sources: &SourceMap, offset: usize, span: Span) -> (String, usize, usize) {
    let file = sources.get(span.file);
    let (line, col) = file.line_col(offset);
    (file.name.clone(), line, col)
}

/// The JSON object of `language.md`: severity, code, message, file, 1-based line and
/// column (in characters) of the start and end, help, labels and notes.
pub fn json(diag: &Diagnostic, sources: &SourceMap) -> serde_json::Value {
    let loc = |span: Span| {
        let file = sources.get(span.file);
        let (line, column) = file.line_col(span.start as usize);
        let (end_line, end_column) = file.line_col(span.end as usize);
        (file.name.clone(), line, column, end_line, end_column)
    };
    let label_json = |l: &Label| {
        let (file, line, column, end_line, end_column) = loc(l.span);
        serde_json::json!({
            "file": file, "line": line, "column": column,
            "end_line": end_line, "end_column": end_column, "message": l.message,
        })
    };
    let (file, line, column, end_line, end_column) = loc(diag.span);
    let mut labels: Vec<serde_json::Value> = diag.labels.iter().map(label_json).collect();
    labels.extend(diag.trace.iter().map(label_json));
    let mut notes = diag.notes.clone();
    for t in &diag.trace {
        let (file, line, column, ..) = loc(t.span);
        notes.push(format!("{} ({file}:{line}:{column})", t.message));
    }
    serde_json::json!({
        "severity": diag.severity.as_str(),
        "code": diag.code,
        "message": diag.message.trim_end_matches('\n'),
        "file": file,
        "line": line,
        "column": column,
        "end_line": end_line,
        "end_column": end_column,
        "help": diag.help,
        "labels": labels,
        "notes": notes,
    })
}

/// A graphical report (miette) with the source lines, labels, help and notes; the
/// include and macro chain appears as related reports pointing at each step.
/// What a scene says itself is printed as POV-Ray prints it: a `#debug` text
/// as it is (no line end added), a `#warning` as one line with its place.
pub fn human(diag: &Diagnostic, sources: &SourceMap, color: bool) -> String {
    if diag.code == codes::USER_DEBUG {
        return visible(&diag.message).into_owned();
    }
    if diag.code == codes::USER_WARNING {
        let (file, line, col) = position(sources, diag.span.start as usize, diag.span);
        return format!(
            "{}:{line}:{col}: warning: {}\n",
            visible(&file),
            visible(&diag.message)
        );
    }
    let theme = if color {
        GraphicalTheme::unicode()
    } else {
        GraphicalTheme::unicode_nocolor()
    };
    let handler = GraphicalReportHandler::new_themed(theme).with_width(100);
    let mut out = String::new();
    let mut report = Report::from_diag(diag, sources);
    // The chain is rendered as plain notes after the report (miette would head each
    // related report with "Advice:").
    let related = std::mem::take(&mut report.related);
    if handler.render_report(&mut out, &report).is_err() {
        return short(diag, sources);
    }
    for r in &related {
        let mut note = String::new();
        if handler.render_report(&mut note, r).is_ok() {
            out.push('\n');
            out.push_str(&note);
        }
    }
    out
}

/// A diagnostic in the shape miette wants.
#[derive(Debug)]
struct Report {
    message: String,
    code: Option<String>,
    severity: miette::Severity,
    help: Option<String>,
    source: Excerpt,
    labels: Vec<LabeledSpan>,
    related: Vec<Report>,
}

impl Report {
    fn from_diag(diag: &Diagnostic, sources: &SourceMap) -> Report {
        let file = sources.get(diag.span.file);
        let here: Vec<(usize, usize)> = std::iter::once(diag.span)
            .chain(
                diag.labels
                    .iter()
                    .map(|l| l.span)
                    .filter(|s| s.file == diag.span.file),
            )
            .map(|s| (s.start as usize, s.end as usize))
            .collect();
        let source = Excerpt::new(file, &here);
        let mut labels = vec![LabeledSpan::new_primary_with_span(
            diag.label.as_deref().map(|l| visible(l).into_owned()),
            miette_span(&source, diag.span),
        )];
        let mut related = Vec::new();
        for l in &diag.labels {
            if l.span.file == diag.span.file {
                labels.push(LabeledSpan::new_with_span(
                    Some(visible(&l.message).into_owned()),
                    miette_span(&source, l.span),
                ));
            } else {
                related.push(Report::note(l, sources));
            }
        }
        related.extend(diag.trace.iter().map(|t| Report::note(t, sources)));
        let mut help = diag.help.as_deref().map(|h| visible(h).into_owned());
        if !diag.notes.is_empty() {
            let notes = diag
                .notes
                .iter()
                .map(|n| format!("note: {}", visible(n)))
                .collect::<Vec<_>>()
                .join("\n");
            help = Some(match help {
                Some(h) => format!("{h}\n{notes}"),
                None => notes,
            });
        }
        Report {
            message: visible(&diag.message).into_owned(),
            code: Some(diag.code.to_string()),
            severity: match diag.severity {
                Severity::Error => miette::Severity::Error,
                Severity::Warning => miette::Severity::Warning,
                Severity::Note => miette::Severity::Advice,
            },
            help,
            source,
            labels,
            related,
        }
    }

    fn note(label: &Label, sources: &SourceMap) -> Report {
        let file = sources.get(label.span.file);
        let source = Excerpt::new(
            file,
            &[(label.span.start as usize, label.span.end as usize)],
        );
        Report {
            message: visible(&label.message).into_owned(),
            code: None,
            severity: miette::Severity::Advice,
            help: None,
            labels: vec![LabeledSpan::new_primary_with_span(
                None,
                miette_span(&source, label.span),
            )],
            source,
            related: Vec::new(),
        }
    }
}

fn miette_span(source: &Excerpt, span: Span) -> miette::SourceSpan {
    source.span(span.start as usize, span.end as usize)
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Report {}

impl miette::Diagnostic for Report {
    fn code<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.code
            .as_ref()
            .map(|c| Box::new(c) as Box<dyn fmt::Display>)
    }
    fn severity(&self) -> Option<miette::Severity> {
        Some(self.severity)
    }
    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.help
            .as_ref()
            .map(|h| Box::new(h) as Box<dyn fmt::Display>)
    }
    fn source_code(&self) -> Option<&dyn miette::SourceCode> {
        Some(&self.source)
    }
    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        Some(Box::new(self.labels.iter().cloned()))
    }
    fn related<'a>(&'a self) -> Option<Box<dyn Iterator<Item = &'a dyn miette::Diagnostic> + 'a>> {
        if self.related.is_empty() {
            None
        } else {
            Some(Box::new(
                self.related.iter().map(|r| r as &dyn miette::Diagnostic),
            ))
        }
    }
}
