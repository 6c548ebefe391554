//! Expanding items into evaluated [`Tok`]s, placing them in the scene, and macros.

use super::cursor::{Sink, Tok};
use super::value::Value;
use super::{Evaluator, Fail, R};
use crate::diag::{codes, did_you_mean, Diagnostic, Label};
use crate::span::Span;
use crate::syntax::ast::{Arg, Block, DirectiveKind, ExprKind, Item, LValue, MacroDef, Rhs};
use crate::syntax::Sym;
use std::rc::Rc;
use std::sync::Arc;

impl Evaluator<'_> {
    /// Runs top-level items, placing what they produce in the scene.
    pub(crate) fn run_top(&mut self, items: &[Item]) {
        let mut sink = Sink::top();
        self.expand(items, &mut sink);
    }

    /// Expands items into `out`, running directives as they come.
    pub(crate) fn expand(&mut self, items: &[Item], out: &mut Sink) {
        let mut rest = items;
        while let Some(item) = rest.first() {
            if self.stopped {
                return;
            }
            // `#declare T = texture { A } texture { B } …`: one layered texture (B
            // over A), as POV-Ray reads the blocks that follow a declared texture.
            let mut n = 1;
            if declared_texture(item).is_some() {
                while let Some(Item::Block(next)) = rest.get(n) {
                    if next.keyword.name != "texture" {
                        break;
                    }
                    n += 1;
                }
            }
            let (unit, after) = rest.split_at(n);
            rest = after;
            // A top-level item is evaluated once for all frames when the clock
            // does not touch it (see `reuse.rs`).
            if out.top && self.is_unit(item) {
                self.unit(item.span(), |ev| ev.expand_unit(unit, out));
                continue;
            }
            // (The same as `expand_unit`, written here to keep deep macro
            // recursion from using more stack.)
            self.expand_item(item, out);
            if let Some((local, target)) = declared_texture(item) {
                for next in &unit[1..] {
                    if let Item::Block(next) = next {
                        if let Err(f) = self.layer_declared(local, target, next) {
                            self.report(f);
                        }
                    }
                }
            }
            if out.top {
                let toks = std::mem::take(&mut out.toks);
                for t in toks {
                    self.place(t);
                }
            }
        }
    }

    /// Expands an item and the texture blocks layered over it, and places
    /// what they produce when `out` is the top level.
    fn expand_unit(&mut self, unit: &[Item], out: &mut Sink) {
        let Some((item, layers)) = unit.split_first() else {
            return;
        };
        self.expand_item(item, out);
        if let Some((local, target)) = declared_texture(item) {
            for next in layers {
                if let Item::Block(next) = next {
                    if let Err(f) = self.layer_declared(local, target, next) {
                        self.report(f);
                    }
                }
            }
        }
        if out.top {
            let toks = std::mem::take(&mut out.toks);
            for t in toks {
                self.place(t);
            }
        }
    }

    fn expand_item(&mut self, item: &Item, out: &mut Sink) {
        match item {
            Item::Directive(d) => {
                if let Err(f) = self.directive(d, out) {
                    self.report(f);
                }
            }
            Item::Block(b)
                if self.ctx.defer_material_blocks
                    && matches!(b.keyword.name, "pigment" | "finish" | "normal") =>
            {
                out.push(Tok::Deferred(Rc::new(super::cursor::Deferred {
                    block: b.clone(),
                    locals: self.scope.locals(),
                    trace: self.trace.clone(),
                })));
            }
            Item::Block(b) => match self.block(b) {
                // `keyframes { }` stands for its value at the current time.
                Ok(Some(v)) if b.keyword.name == "keyframes" => out.push(Tok::Val(v, b.span)),
                Ok(Some(v)) => out.push(Tok::Block(b.keyword.name, v, b.span)),
                Ok(None) => {}
                Err(f) => {
                    self.report(f);
                    out.push(Tok::Block(b.keyword.name, Value::Poison, b.span));
                }
            },
            Item::Keyword(k) => out.push(Tok::Kw(k.name, k.span)),
            Item::Bracket(b) => {
                let mut inner = Sink::new();
                self.expand(&b.items, &mut inner);
                out.push(Tok::Bracket(inner.toks, b.span));
            }
            Item::Comma(s) => out.push(Tok::Comma(*s)),
            Item::Semicolon(s) => out.push(Tok::Semi(*s)),
            Item::Deferred(d) => {
                let items = self.deferred_items(d);
                self.expand(&items, out);
            }
            Item::Data(run) if out.packed => out.push(Tok::Data(run.clone())),
            Item::Data(run) => self.unpack(run, out),
            Item::Expr(e) => {
                if let ExprKind::Call { name, args, .. } = &e.kind {
                    if let Some(m) = self.lookup_macro(*name) {
                        if let Err(f) = self.call_macro(&m, args, e.span, out) {
                            self.report(f);
                            out.push(Tok::Val(Value::Poison, e.span));
                        }
                        return;
                    }
                }
                match self.expr(e) {
                    Ok(v) => out.push(Tok::Val(v, e.span)),
                    Err(f) => {
                        self.report(f);
                        out.push(Tok::Val(Value::Poison, e.span));
                    }
                }
            }
        }
    }

    /// A packed run of numbers and vectors as the items it was written as: each
    /// number and vector a value with its own span, and the commas between.
    fn unpack(&mut self, run: &crate::syntax::data::DataRun, out: &mut Sink) {
        use crate::syntax::data::{scan_places, Piece, COMMA};
        let base = run.span.start as usize;
        let file = run.span.file;
        let text = &self.sources.get(file).text;
        let Some(slice) = text.get(base..run.span.end as usize) else {
            return;
        };
        let at = |a: usize, b: usize| Span::new(file, base + a, base + b);
        // The numbers were read with the run: only their places are needed,
        // kept with a short run, found again in a long one.
        let mut elements = run.elements();
        let mut piece = |p: Piece| match p {
            Piece::Comma(i) => out.push(Tok::Comma(at(i, i + 1))),
            Piece::Element { start, end, .. } => {
                let v = match elements.next() {
                    Some([x]) => Value::Float(*x),
                    Some(v) => Value::Vector(super::value::Vector::from_slice(v)),
                    None => Value::Poison,
                };
                out.push(Tok::Val(v, at(start, end)));
            }
        };
        if run.places.is_empty() {
            scan_places(slice, piece);
        } else {
            for &(start, end) in &run.places {
                piece(match end {
                    COMMA => Piece::Comma(start as usize),
                    end => Piece::Element {
                        start: start as usize,
                        end: end as usize,
                        values: &[],
                    },
                });
            }
        }
    }

    /// Lays the texture block `top` over the texture just declared as `target`.
    fn layer_declared(&mut self, local: bool, target: &LValue, top: &Block) -> R<()> {
        let below = match self.scope.get(target.name).map(|b| &b.value) {
            Some(Value::Texture(t)) => Some(t.clone()),
            // The declaration failed and was reported; keep the name poisoned.
            _ => return Ok(()),
        };
        let Value::Texture(t) = self.block_value(top)? else {
            return Ok(());
        };
        let layered = crate::eval::materials::texture::layer_texture(below.as_ref(), t, top.span)?;
        self.bind(local, target, Value::Texture(layered), top.span)
    }

    fn lookup_macro(&mut self, name: Sym) -> Option<Rc<MacroDef>> {
        self.force(name);
        match self.scope.get(name).map(|b| &b.value) {
            Some(Value::Macro(m)) => Some(m.clone()),
            _ => None,
        }
    }

    /// Puts what a top-level item produced into the scene.
    fn place(&mut self, tok: Tok) {
        if let Err(f) = self.checkpoint(tok.span()) {
            self.report(f);
            return;
        }
        let fail: Fail = match tok {
            Tok::Deferred(b) => {
                let t = self.undefer(&b, None);
                return self.place(t);
            }
            Tok::Block(_, Value::Object(o), span) => {
                let mut o = Arc::try_unwrap(o).unwrap_or_else(|a| (*a).clone());
                if o.texture.is_none() {
                    o.texture = Some(self.default_texture.clone());
                }
                for l in crate::eval::settings::lights::take_lights(&mut o, None) {
                    self.place(Tok::Block("light_source", Value::Light(Arc::new(l)), span));
                }
                self.scene.objects.push(o);
                self.scene.placed.push(crate::scene::next_placement());
                return;
            }
            Tok::Block(_, Value::Light(l), span) => {
                if let Some(o) = &l.looks_like {
                    self.place(Tok::Block("object", Value::Object(o.clone()), span));
                }
                self.scene.lights.push((*l).clone());
                return;
            }
            Tok::Block(_, Value::SkySphere(s), _) => {
                // As in POV-Ray, a later sky_sphere replaces an earlier one.
                self.scene.atmosphere.sky_sphere = Some((*s).clone());
                return;
            }
            Tok::Block(_, Value::Fog(f), _) => {
                self.scene.atmosphere.fogs.push(*f);
                return;
            }
            Tok::Block(_, Value::Rainbow(r), _) => {
                self.scene.atmosphere.rainbows.push((*r).clone());
                return;
            }
            Tok::Block(_, Value::Media(m), _) => {
                // Atmospheric media: several add up, as in an interior.
                self.scene.atmosphere.media.push((*m).clone());
                return;
            }
            Tok::Block(_, Value::Camera(c), span) => {
                if let Some(prev) = self.camera_seen {
                    self.warn(
                        Diagnostic::warning(codes::DUPLICATE_PARAMETER, span, "a second camera replaces the first")
                            .with_secondary(prev, "first camera")
                            .with_help("keep one camera, or choose between them with #if"),
                    );
                }
                match self.resolve_camera(&c, span) {
                    Ok(cam) => self.scene.camera = cam,
                    Err(f) => self.report(f),
                }
                self.camera_seen = Some(span);
                return;
            }
            Tok::Block(_, Value::Poison, _) | Tok::Val(Value::Poison, _) | Tok::Semi(_) => return,
            // Top-level sinks are never packed.
            Tok::Data(d) => Diagnostic::error(
                codes::UNEXPECTED_ITEM,
                d.span,
                "numbers and vectors cannot stand alone at top level",
            )
            .into(),
            Tok::Block(k, v, span) => Diagnostic::error(
                codes::UNEXPECTED_ITEM,
                span,
                format!("a `{k}` block cannot stand alone at top level"),
            )
            .with_help(format!("use it inside an object, or give it a name: `#declare My_Thing = {k} {{ … }}` ({})", v.kind()))
            .into(),
            Tok::Val(v, span) => {
                let help = match &v {
                    Value::Object(_) => "to place a declared object write `object { Name }`".to_string(),
                    _ => "at top level only objects, lights, the camera and directives may stand".to_string(),
                };
                Diagnostic::error(codes::UNEXPECTED_ITEM, span, format!("{} cannot stand alone at top level", v.kind()))
                    .with_help(help)
                    .into()
            }
            Tok::Kw(k, span) => {
                let d = Diagnostic::error(codes::UNEXPECTED_ITEM, span, format!("`{k}` cannot stand at top level"))
                    .with_label("not inside a block");
                let d = if super::blocks::is_block_keyword(k) {
                    d.with_help(format!("`{k}` needs a block: `{k} {{ … }}`"))
                } else {
                    d.with_help(format!("`{k}` belongs inside a block such as an object, texture or finish"))
                };
                d.into()
            }
            Tok::Comma(span) => Diagnostic::error(codes::UNEXPECTED_ITEM, span, "unexpected `,` at top level").into(),
            Tok::Bracket(_, span) => Diagnostic::error(codes::UNEXPECTED_ITEM, span, "unexpected `[ … ]` at top level").into(),
        };
        self.report(fail);
    }

    /// Expands a macro call into `out`.
    pub(crate) fn call_macro(
        &mut self,
        m: &Rc<MacroDef>,
        args: &[Arg],
        call: Span,
        out: &mut Sink,
    ) -> R<()> {
        let required = m.params.iter().filter(|p| !p.optional).count();
        if args.len() < required || args.len() > m.params.len() {
            let want = if required == m.params.len() {
                format!("{required}")
            } else {
                format!("{required} to {}", m.params.len())
            };
            return Err(Diagnostic::error(
                codes::ARITY,
                call,
                format!(
                    "macro `{}` takes {want} argument{}, found {}",
                    m.name,
                    if want == "1" { "" } else { "s" },
                    args.len()
                ),
            )
            .with_secondary(m.name_span, "macro defined here")
            .with_help(format!(
                "call it as {}({})",
                m.name,
                m.params
                    .iter()
                    .map(|p| if p.optional {
                        format!("optional {}", p.name)
                    } else {
                        p.name.to_string()
                    })
                    .collect::<Vec<_>>()
                    .join(", ")
            ))
            .into());
        }
        self.count_macro_call(call)?;
        if self.macro_depth >= self.options.max_macro_depth {
            self.stopped = true;
            return Err(Diagnostic::error(
                codes::RECURSION_LIMIT,
                call,
                format!("macros nested more than {} deep", self.options.max_macro_depth),
            )
            .with_help("check that a recursive macro has a condition that ends it, or raise --max-macro-depth")
            .into());
        }
        let mut values = Vec::with_capacity(args.len());
        for (a, p) in args.iter().zip(&m.params) {
            values.push(match a {
                Arg::Expr(e) => Some(self.expr(e)?),
                Arg::Block(b) => Some(self.block_value(b)?),
                Arg::Empty(_) if p.optional => None,
                Arg::Empty(s) => {
                    return Err(Diagnostic::error(
                        codes::MISSING_VALUE,
                        *s,
                        format!("no value for parameter `{}` of macro `{}`", p.name, m.name),
                    )
                    .with_label("empty argument")
                    .with_secondary(m.name_span, "macro defined here")
                    .with_help(format!(
                        "give a value, or declare the parameter as `optional {}`",
                        p.name
                    ))
                    .into())
                }
            });
        }
        // As in POV-Ray, a parameter given a declared name stands for that
        // identifier: what the macro assigns to the parameter (`#local X = …` or
        // `#declare X = …`) is the identifier's value after the call. Here the
        // final value is copied back when the macro returns.
        let by_reference: Vec<(Sym, Sym, usize, Span)> = m
            .params
            .iter()
            .zip(args)
            .filter_map(|(p, a)| match a {
                Arg::Expr(e) => match &e.kind {
                    ExprKind::Ident(n) if !n.is_builtin() => {
                        self.scope.frame_of(*n).map(|f| (p.name, *n, f, e.span))
                    }
                    _ => None,
                },
                _ => None,
            })
            .collect();
        self.scope.push();
        for (p, (v, a)) in m.params.iter().zip(values.into_iter().zip(args)) {
            if let Some(v) = v {
                self.scope.local(p.name, v, a.span());
            }
        }
        self.macro_depth += 1;
        self.trace.push(Label {
            span: call,
            message: format!("in macro `{}` called here", m.name),
        });
        match m.raw {
            None => self.expand(&m.body, out),
            Some(raw) => match self.token_level_body(m, raw) {
                Ok(body) => self.expand(&body, out),
                Err(f) => self.report(f),
            },
        }
        self.trace.pop();
        self.macro_depth -= 1;
        let mut frame = self.scope.take_top();
        for (param, name, at, given) in by_reference {
            // Only a parameter the macro assigned to (its binding no longer
            // the argument's: the identifier may have been changed by name), or
            // an array, whose items the macro may have set.
            if let Some(b) = frame
                .remove(&param)
                .filter(|b| b.span != given || matches!(b.value, Value::Array(_)))
            {
                self.scope.set_in(at, name, b.value);
            }
        }
        Ok(())
    }

    /// A call in an expression: a built-in function or a macro that yields one value.
    pub(crate) fn call_value(
        &mut self,
        name: Sym,
        name_span: Span,
        args: &[Arg],
        span: Span,
    ) -> R<Value> {
        if name.is_builtin() && crate::syntax::builtins::is_function(name.0 as usize) {
            match crate::syntax::builtins::BUILTIN_NAMES[name.0 as usize] {
                "defined" => return self.defined(args, span),
                "trace" => return self.trace_call(args, span),
                _ => {}
            }
            let mut vals = Vec::with_capacity(args.len());
            for a in args {
                match a {
                    Arg::Expr(e) => vals.push((self.expr(e)?, e.span)),
                    Arg::Block(b) => vals.push((self.block_value(b)?, b.span)),
                    Arg::Empty(s) => {
                        return Err(Diagnostic::error(
                            codes::MISSING_VALUE,
                            *s,
                            "empty argument to a built-in function",
                        )
                        .with_label("a value is missing here")
                        .with_help("only optional macro parameters may be left empty")
                        .into())
                    }
                }
            }
            let v = self.call_builtin(name.0 as usize, span, &vals)?;
            if let Value::Str(s) = &v {
                self.check_string_length(s.len(), span)?;
            }
            return Ok(v);
        }
        if let Some(m) = self.lookup_macro(name) {
            let mut out = Sink::new();
            self.call_macro(&m, args, span, &mut out)?;
            let mut vals = out.toks.into_iter().filter(|t| !matches!(t, Tok::Semi(_)));
            return match (vals.next(), vals.next()) {
                (Some(Tok::Val(v, _) | Tok::Block(_, v, _)), None) => match v {
                    Value::Poison => Err(Fail::silent()),
                    v => Ok(v),
                },
                (None, _) => Err(Diagnostic::error(
                    codes::TYPE_MISMATCH,
                    span,
                    format!("macro `{name}` produced no value"),
                )
                .with_help("a macro used in an expression must end with the value it gives")
                .into()),
                (Some(t), _) => Err(Diagnostic::error(
                    codes::TYPE_MISMATCH,
                    span,
                    format!("macro `{name}` produced several items where one value is needed"),
                )
                .with_label(format!("first item: {}", t.describe()))
                .into()),
            };
        }
        if let Some(Value::Function(f)) = self.scope.get(name).map(|b| b.value.clone()) {
            return self.call_function(&f, name, args, span);
        }
        if let Some(Value::Spline(s)) = self.scope.get(name).map(|b| b.value.clone()) {
            let mut vals = Vec::with_capacity(args.len());
            for a in args {
                match a {
                    Arg::Expr(e) => vals.push((self.expr(e)?, e.span)),
                    Arg::Block(b) => vals.push((self.block_value(b)?, b.span)),
                    Arg::Empty(s) => vals.push((Value::Poison, *s)),
                }
            }
            return self.call_spline(&s, &vals, span);
        }
        match self.scope.get(name).map(|b| &b.value) {
            Some(Value::Poison) => Err(Fail::silent()),
            Some(v) => Err(Diagnostic::error(
                codes::TYPE_MISMATCH,
                name_span,
                format!("`{name}` is {}, not a macro or function", v.kind()),
            )
            .into()),
            None => {
                let names: Vec<Arc<str>> = self
                    .scope
                    .names()
                    .into_iter()
                    .filter(|s| {
                        matches!(self.scope.get(*s).map(|b| &b.value), Some(Value::Macro(_)))
                    })
                    .map(Sym::name)
                    .collect();
                let cands = names.iter().map(|s| &**s).chain(
                    crate::syntax::builtins::BUILTIN_NAMES
                        [crate::syntax::builtins::CONSTANT_COUNT..]
                        .iter()
                        .copied(),
                );
                let text = name.name();
                // A functions.inc-like name is "not implemented" unless it looks
                // like a misspelt macro the scene declared.
                if did_you_mean(&text, names.iter().map(|s| &**s)).is_none() {
                    if let Some(d) = pov_function(&text, name_span) {
                        return Err(d.into());
                    }
                }
                let suggestion = did_you_mean(&text, cands);
                Err(Diagnostic::error(
                    codes::UNKNOWN_IDENTIFIER,
                    name_span,
                    format!("unknown macro or function `{text}`"),
                )
                .with_label("not defined")
                .with_help(match suggestion {
                    Some(s) => format!("did you mean `{s}`?"),
                    None => format!("define it with `#macro {text}(…) … #end` before calling it"),
                })
                .into())
            }
        }
    }

    fn defined(&mut self, args: &[Arg], span: Span) -> R<Value> {
        match args {
            [Arg::Expr(e)] => match &e.kind {
                ExprKind::Ident(n) => Ok(Value::Float(f64::from(u8::from(
                    n.is_builtin() || self.scope.get(*n).is_some() || self.pending.has(*n),
                )))),
                _ => Err(
                    Diagnostic::error(codes::TYPE_MISMATCH, e.span, "`defined` needs a name")
                        .into(),
                ),
            },
            _ => Err(Diagnostic::error(codes::ARITY, span, "`defined` takes one name").into()),
        }
    }
}

/// For an undeclared name like POV-Ray's functions.inc ones (`f_` and a lower-case
/// letter: `f_noise3d`, `f_rounded_box`): the diagnostic that says to include
/// functions.inc when ours declares it, else that rts does not provide it yet,
/// instead of "unknown identifier".
pub(crate) fn pov_function(name: &str, span: Span) -> Option<Diagnostic> {
    let rest = name.strip_prefix("f_")?;
    if !rest.starts_with(|c: char| c.is_ascii_lowercase()) {
        return None;
    }
    let ours = super::include::STDLIB
        .iter()
        .find(|(n, _)| *n == "functions.inc")
        .is_some_and(|(_, text)| text.contains(&format!("#declare {name} =")));
    Some(if ours {
        Diagnostic::error(
            codes::UNKNOWN_IDENTIFIER,
            span,
            format!("`{name}` is declared in functions.inc"),
        )
        .with_label("not declared")
        .with_help("add `#include \"functions.inc\"` before using it")
    } else {
        Diagnostic::error(
            codes::UNSUPPORTED,
            span,
            format!("`{name}` looks like one of POV-Ray's functions.inc functions, which rts does not provide yet"),
        )
        .with_label("not implemented yet")
        .with_help("see docs/language.md for the functions rts's functions.inc declares")
    })
}

/// For `#declare NAME = texture { … }` (or `#local`): whether it is local, and the name.
fn declared_texture(item: &Item) -> Option<(bool, &LValue)> {
    let Item::Directive(d) = item else {
        return None;
    };
    match &d.kind {
        DirectiveKind::Declare {
            local,
            target,
            value: Rhs::Block(b),
            ..
        } if b.keyword.name == "texture" && target.indices.is_empty() => Some((*local, target)),
        _ => None,
    }
}
