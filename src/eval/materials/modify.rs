//! POV-Ray's rule that a `pigment`, `finish` or `normal` written in a texture or an
//! object modifies the one in force there rather than starting afresh:
//! `texture { T finish { diffuse 0.5 } }` keeps T's ambient, `texture { T pigment {
//! octaves 3 rotate 90*z } }` keeps T's pattern and colours, and `object { O
//! pigment { scale 2 } }` scales O's pigment. Such blocks are read as
//! [`Tok::Deferred`] while their texture or object is expanded, and evaluated here
//! once the reader knows what they modify, so their items run exactly once.

use super::patterns::{MODIFIERS, PATTERNS};
use crate::eval::core::cursor::{Cursor, Deferred, Sink, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::Value;
use crate::eval::core::Evaluator;
use std::sync::Arc;

/// Whether a `kw` block whose first item is `first` modifies the one in force
/// (rather than replacing it): it starts with a modifier or a transform, or is
/// empty. A block that starts with a pattern, a colour or a declared name says
/// what it is by itself.
fn modifies(kw: &str, toks: &[Tok]) -> bool {
    let first = toks.first();
    if kw == "finish" {
        // Every finish item is a modifier: only a declared finish starts afresh.
        return !matches!(first, Some(Tok::Val(Value::Finish(_), _)));
    }
    match first {
        None => true,
        Some(Tok::Kw(k, _)) => {
            MODIFIERS.contains(k)
                || TRANSFORMS.contains(k)
                || (kw == "normal" && *k == "bump_size")
                // `texture { T_Gold_3C pigment { quick_color … } }` keeps the
                // gold: POV-Ray's quick colour only matters to its quick preview
                // (advanced/chess2.pov).
                || (kw == "pigment" && matches!(*k, "quick_color" | "quick_colour"))
        }
        Some(Tok::Block(k, _, _)) => {
            *k == "transform"
                // A leading warp warps the pattern in force, unless the block
                // goes on to name its own pattern (then it is a mistake that
                // the pigment reader reports).
                || (*k == "warp" && !toks.iter().any(|t| matches!(t, Tok::Kw(p, _) if PATTERNS.contains(p))))
                || (kw == "pigment" && matches!(*k, "color_map" | "colour_map" | "pigment_map"))
                || (kw == "normal" && matches!(*k, "slope_map" | "normal_map"))
        }
        Some(_) => false,
    }
}

impl Evaluator<'_> {
    /// Evaluates the deferred `pigment`, `finish` or `normal` block `d` as a
    /// modification of `base` (the one in force where it is written; `None` when
    /// there is nothing to modify), giving the token an eager read would have.
    /// It sees the local names it saw where it was written (a macro's
    /// parameters, though the macro has returned), and its errors show that
    /// place's macro calls.
    pub(crate) fn undefer(&mut self, d: &Deferred, base: Option<Value>) -> Tok {
        let b = &d.block;
        let kw = b.keyword.name;
        let mut sink = Sink::new();
        let trace = std::mem::replace(&mut self.trace, d.trace.clone());
        self.scope.reopen(&d.locals);
        self.within(self.ctx.deferred_items_of(kw), |ev| {
            ev.expand(&b.items, &mut sink);
        });
        for _ in &d.locals {
            self.scope.pop();
        }
        self.trace = trace;
        let mut toks = sink.toks;
        if let Some(base) = base {
            if modifies(kw, &toks) {
                toks.insert(0, Tok::Val(base, b.keyword.span));
            }
        }
        let mut c = Cursor::new(toks, kw, b.span);
        let value = match kw {
            "pigment" => self.pigment(&mut c).map(|p| Value::Pigment(Arc::new(p))),
            "finish" => self.finish(&mut c).map(|f| Value::Finish(Arc::new(f))),
            _ => self.normal(&mut c).map(|n| Value::Normal(Arc::new(n))),
        };
        match value {
            Ok(v) => Tok::Block(kw, v, b.span),
            Err(f) => {
                self.report(f);
                Tok::Block(kw, Value::Poison, b.span)
            }
        }
    }
}
