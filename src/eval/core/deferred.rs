//! Branch bodies read when their branch is taken. A parse for rendering
//! leaves the long bodies of `#if`, `#ifdef`, `#ifndef` and `#switch` unread
//! ([`crate::syntax::parse_with`]), as POV-Ray skips the branches it
//! does not take without reading them: a scene that picks one of eighty
//! objects by `frame_number` reads one. A body is read the first time its
//! branch is taken and kept in the tree for the next time (a loop, a macro
//! called again, the next frame of an animation).

use super::Evaluator;
use crate::diag::Diagnostic;
use crate::syntax::ast::{Deferred, Item};
use std::rc::Rc;

impl Evaluator<'_> {
    /// The items of a deferred branch body, read now if not read before. A
    /// body that does not parse reports its errors (once) and counts as empty.
    pub(crate) fn deferred_items(&mut self, d: &Deferred) -> Rc<[Item]> {
        if let Some(items) = d.items.get() {
            return items.clone();
        }
        let (start, end) = (d.span.start as usize, d.span.end as usize);
        let text = self
            .sources
            .get(d.span.file)
            .text
            .get(start..end)
            .unwrap_or("");
        let (file, diags) = crate::syntax::parse_with(text, d.span.file, start, true);
        let failed = diags.iter().any(Diagnostic::is_error);
        for diag in diags {
            self.report(diag.into());
        }
        let items: Rc<[Item]> = if failed {
            Rc::from([])
        } else {
            file.items.into()
        };
        d.items.get_or_init(|| items).clone()
    }

    /// `items` with each deferred body in it replaced by its items (for the
    /// places that take a chosen branch's items whole).
    pub(crate) fn read_deferred(&mut self, items: Vec<Item>) -> Vec<Item> {
        if !items.iter().any(|i| matches!(i, Item::Deferred(_))) {
            return items;
        }
        let mut out = Vec::with_capacity(items.len());
        for item in items {
            match item {
                Item::Deferred(d) => out.extend(self.deferred_items(&d).iter().cloned()),
                other => out.push(other),
            }
        }
        out
    }
}
