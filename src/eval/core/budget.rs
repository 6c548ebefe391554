//! What one evaluation may spend. A scene is a program: a loop that forgets its
//! step, a macro that calls itself twice, an array of arrays or a string that
//! doubles must end quickly in a diagnostic that names the limit, the place
//! responsible and the flag that raises it — never in gigabytes or minutes.
//!
//! - memory: the heap the evaluation has grown by ([`crate::memory`]),
//!   checked at every loop pass, macro call and placed item, and before a
//!   large allocation (`--max-memory`);
//! - macro calls in all (`--max-macro-calls`), as loop passes are
//!   (`--max-loop-iterations`);
//! - string length (`--max-string-length`);
//! - errors: the same diagnostic from the same place is reported once with a
//!   count, and evaluation stops after `--max-errors` errors;
//! - for editors: cancellation (a newer edit) and a deadline.

use super::{Evaluator, Fail, R};
use crate::diag::{codes, Diagnostic, Severity};
use crate::memory::show_size;
use crate::span::Span;
use std::hash::{Hash, Hasher};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Instant;

/// How an evaluation run by someone else (an editor) is stopped early: when
/// `cancel` is set (a newer edit arrived) or past `deadline`.
#[derive(Clone, Debug, Default)]
pub struct Interrupt {
    /// Set by the owner to stop the evaluation as soon as it checks.
    pub cancel: Option<Arc<AtomicBool>>,
    /// When the evaluation must stop on its own.
    pub deadline: Option<Instant>,
}

/// Checkpoints between two looks at the clock (reading it costs about as much
/// as a simple loop pass).
const CLOCK_EVERY: u32 = 64;

/// What the evaluation has spent so far.
#[derive(Debug, Default)]
pub(crate) struct Spent {
    /// The heap when the evaluation began.
    pub(crate) heap_start: usize,
    /// Macro calls so far.
    pub(crate) macro_calls: u64,
    /// Errors reported so far, repeats included.
    pub(crate) errors: usize,
    /// Checkpoints since the clock was last read.
    ticks: u32,
    /// Each reported diagnostic's key and its index in the list.
    seen: rustc_hash::FxHashMap<u64, usize>,
    /// How many more times a diagnostic was reported, by its index.
    pub(crate) repeats: rustc_hash::FxHashMap<usize, u64>,
}

impl Spent {
    /// A fresh account for an evaluation starting now.
    pub(crate) fn start() -> Spent {
        Spent {
            heap_start: crate::memory::heap_bytes(),
            ..Spent::default()
        }
    }
}

impl Evaluator<'_> {
    /// Bytes the evaluation has grown the heap by.
    fn memory_used(&self) -> u64 {
        crate::memory::heap_bytes().saturating_sub(self.spent.heap_start) as u64
    }

    /// The checks that must run often: cancellation, the deadline and the
    /// memory budget. Called at every loop pass, macro call and placed item.
    pub(crate) fn checkpoint(&mut self, span: Span) -> R<()> {
        let interrupt = &self.options.interrupt;
        if interrupt
            .cancel
            .as_ref()
            .is_some_and(|c| c.load(Ordering::Relaxed))
        {
            self.stopped = true;
            return Err(Fail::silent());
        }
        if let Some(deadline) = interrupt.deadline {
            self.spent.ticks += 1;
            if self.spent.ticks >= CLOCK_EVERY {
                self.spent.ticks = 0;
                if Instant::now() >= deadline {
                    self.stopped = true;
                    return Err(Diagnostic::error(
                        codes::TIME_LIMIT,
                        span,
                        "the editor stopped evaluating the scene here: it took too long",
                    )
                    .with_label("evaluating this when the time ran out")
                    .with_help("a loop that never ends? `rts check` evaluates the whole scene")
                    .into());
                }
            }
        }
        let used = self.memory_used();
        if used > self.options.max_memory {
            self.stopped = true;
            return Err(self.memory_exceeded(span, used, None));
        }
        Ok(())
    }

    /// Checks that `bytes` more (for `what`, about to be allocated) fit in the
    /// memory budget.
    pub(crate) fn reserve(&mut self, bytes: u64, span: Span, what: &str) -> R<()> {
        let used = self.memory_used();
        if used.saturating_add(bytes) > self.options.max_memory {
            return Err(self.memory_exceeded(span, used, Some((bytes, what))));
        }
        Ok(())
    }

    fn memory_exceeded(&self, span: Span, used: u64, asked: Option<(u64, &str)>) -> Fail {
        let max = self.options.max_memory;
        let d = match asked {
            Some((bytes, what)) => Diagnostic::error(
                codes::MEMORY_LIMIT,
                span,
                format!(
                    "{what} needs {}, more than the {} left of the evaluation's {} memory budget",
                    show_size(bytes),
                    show_size(max.saturating_sub(used)),
                    show_size(max)
                ),
            )
            .with_label("needs more memory than is left"),
            None => Diagnostic::error(
                codes::MEMORY_LIMIT,
                span,
                format!(
                    "the evaluation used more than its {} memory budget",
                    show_size(max)
                ),
            )
            .with_label("evaluating this when the budget ran out"),
        };
        d.with_help(format!(
            "a loop or macro that never stops making values or objects? Otherwise raise the budget with --max-memory (e.g. --max-memory {})",
            show_size(max.saturating_mul(2)).replace(' ', "").replace("iB", "")
        ))
        .into()
    }

    /// Counts a macro call against `--max-macro-calls`.
    pub(crate) fn count_macro_call(&mut self, span: Span) -> R<()> {
        self.spent.macro_calls += 1;
        if self.spent.macro_calls > self.options.max_macro_calls {
            self.stopped = true;
            return Err(Diagnostic::error(
                codes::MACRO_CALLS,
                span,
                format!("more than {} macro calls", self.options.max_macro_calls),
            )
            .with_label("this call was made when the limit was reached")
            .with_help("a macro that calls itself more than once per call grows exponentially; check its condition, or raise the limit with --max-macro-calls")
            .into());
        }
        self.checkpoint(span)
    }

    /// Refuses a string longer than `--max-string-length` bytes.
    pub(crate) fn check_string_length(&self, len: usize, span: Span) -> R<()> {
        let max = self.options.max_string_length;
        if len > max {
            return Err(Diagnostic::error(
                codes::STRING_LENGTH,
                span,
                format!(
                    "this string would be {}, longer than the {} a string may be",
                    show_size(len as u64),
                    show_size(max as u64)
                ),
            )
            .with_label("makes the string")
            .with_help("a string that doubles in a loop? Otherwise raise the limit with --max-string-length")
            .into());
        }
        Ok(())
    }

    /// Records a diagnostic unless the same one (code, place, message and
    /// include/macro chain) was recorded before, in which case it is counted.
    /// Evaluation stops after `--max-errors` errors, repeats included: a loop
    /// whose body fails on every pass ends there. Returns whether it was
    /// recorded.
    pub(crate) fn record(&mut self, d: Diagnostic) -> bool {
        if let Some(v) = &mut self.unit_diags {
            v.push(d.clone());
        }
        let mut h = rustc_hash::FxHasher::default();
        d.code.hash(&mut h);
        d.span.hash(&mut h);
        d.message.hash(&mut h);
        for t in &d.trace {
            t.span.hash(&mut h);
        }
        let key = h.finish();
        let error = d.severity == Severity::Error;
        let span = d.span;
        let new = match self.spent.seen.get(&key) {
            Some(&i) => {
                *self.spent.repeats.entry(i).or_insert(0) += 1;
                false
            }
            None => {
                self.spent.seen.insert(key, self.diags.len());
                self.diags.push(d);
                true
            }
        };
        if error {
            self.spent.errors += 1;
            let max = self.options.max_errors;
            if self.spent.errors == max && !self.stopped {
                self.stopped = true;
                let distinct = self
                    .diags
                    .iter()
                    .filter(|d| d.severity == Severity::Error)
                    .count();
                let message = if distinct == max {
                    format!("stopped after {max} errors")
                } else {
                    format!("stopped after {max} errors ({distinct} distinct, the rest repeats)")
                };
                self.diags.push(
                    Diagnostic::error(codes::ERROR_LIMIT, span, message)
                        .with_label("the last error reported")
                        .with_help("fix these first (later errors often follow from them), or raise the limit with --max-errors"),
                );
            }
        }
        new
    }

    /// Notes on each diagnostic reported more than once how many times.
    pub(crate) fn note_repeats(&mut self) {
        for (&i, &n) in &self.spent.repeats {
            if let Some(d) = self.diags.get_mut(i) {
                d.notes.push(format!(
                    "reported {} times in all (from the same place, shown once)",
                    n + 1
                ));
            }
        }
    }
}
