//! The directives: `#declare`, `#if`, loops, `#macro`, `#include`, messages, `#default`.

use super::context::Context;
use super::cursor::{Cursor, Sink, Tok};
use super::value::Value;
use super::{Evaluator, Fail, R};
use crate::diag::{codes, Diagnostic};
use crate::span::Span;
use crate::syntax::ast::{
    Case, CaseTest, Directive, DirectiveKind, Expr, Item, LValue, MessageKind, Rhs,
};
use std::rc::Rc;
use std::sync::Arc;

impl Evaluator<'_> {
    /// Runs one directive; block directives expand their chosen bodies into `out`.
    pub(crate) fn directive(&mut self, d: &Directive, out: &mut Sink) -> R<()> {
        match &d.kind {
            DirectiveKind::Declare {
                local,
                target,
                value,
                deprecated,
            } => {
                if let Some(dep) = deprecated {
                    if target.indices.is_empty() {
                        self.deprecated
                            .insert(target.name, (dep.clone(), std::cell::Cell::new(false)));
                    }
                } else if target.indices.is_empty() && !self.deprecated.is_empty() {
                    self.deprecated.remove(&target.name);
                }
                let v = match value {
                    Rhs::Block(b) if b.keyword.name == "function" && target.indices.is_empty() => {
                        if self.foreign_internal(b, target.name) {
                            return Ok(());
                        }
                        let ctx = Context {
                            declaring_function: Some(target.name),
                            ..self.ctx
                        };
                        self.within(ctx, |ev| ev.block_value(b))
                    }
                    Rhs::Block(b) => self.block_value(b),
                    Rhs::Expr(e) => self.expr(e),
                    Rhs::Directive(cond) => self.directive_value(cond),
                };
                let v = match v {
                    Ok(v) => v,
                    Err(f) => {
                        // Poison the name so its uses do not report again.
                        if target.indices.is_empty() && !target.name.is_builtin() {
                            self.bind(*local, target, Value::Poison, d.span)?;
                        }
                        return Err(f);
                    }
                };
                self.bind(*local, target, v, d.span)
            }
            DirectiveKind::Undef { name, span } => {
                let pending = self.pending.has(*name);
                self.before_bind(*name);
                if !self.scope.undef(*name) && !pending {
                    self.warn(
                        Diagnostic::warning(
                            codes::UNKNOWN_IDENTIFIER,
                            *span,
                            format!("`#undef {name}`: `{name}` is not defined"),
                        )
                        .with_help("remove the #undef, or check the name's spelling"),
                    );
                }
                Ok(())
            }
            DirectiveKind::If {
                branches,
                otherwise,
            } => {
                for (cond, body) in branches {
                    let v = self.expr(cond)?;
                    if self.to_float(&v, cond.span)? != 0.0 {
                        self.expand(body, out);
                        return Ok(());
                    }
                }
                if let Some(body) = otherwise {
                    self.expand(body, out);
                }
                Ok(())
            }
            DirectiveKind::IfDef {
                negate,
                target,
                then,
                otherwise,
            } => {
                let defined = self.is_defined(target)?;
                if defined != *negate {
                    self.expand(then, out);
                } else if let Some(body) = otherwise {
                    self.expand(body, out);
                }
                Ok(())
            }
            DirectiveKind::Switch {
                value,
                cases,
                otherwise,
            } => {
                let start = self.switch_start(value, cases)?;
                match start {
                    Some(i) => {
                        // Without #break a clause falls through into the next, as in POV-Ray.
                        for c in &cases[i..] {
                            self.expand(&c.body, out);
                            if c.breaks {
                                break;
                            }
                        }
                    }
                    None => {
                        if let Some(body) = otherwise {
                            self.expand(body, out);
                        }
                    }
                }
                Ok(())
            }
            DirectiveKind::While { cond, body } => loop {
                let v = self.expr(cond)?;
                if self.to_float(&v, cond.span)? == 0.0 {
                    return Ok(());
                }
                self.count_iteration(d.span)?;
                self.expand(body, out);
                if self.stopped {
                    return Ok(());
                }
            },
            DirectiveKind::For {
                var,
                var_span,
                start,
                end,
                step,
                body,
            } => {
                let sv = self.expr(start)?;
                let mut i = self.to_float(&sv, start.span)?;
                let ev = self.expr(end)?;
                let last = self.to_float(&ev, end.span)?;
                let step = match step {
                    Some(s) => {
                        let v = self.expr(s)?;
                        let st = self.to_float(&v, s.span)?;
                        if st == 0.0 {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                s.span,
                                "`#for` step of 0 would never end",
                            )
                            .with_help(
                                "use a positive step to count up or a negative one to count down",
                            )
                            .into());
                        }
                        st
                    }
                    None => 1.0,
                };
                if var.is_builtin() {
                    return Err(self.reserved(*var_span, &var.name()));
                }
                let eps = 1e-9 * step.abs();
                while (step > 0.0 && i <= last + eps) || (step < 0.0 && i >= last - eps) {
                    self.count_iteration(d.span)?;
                    self.scope.local(*var, Value::Float(i), *var_span);
                    self.expand(body, out);
                    if self.stopped {
                        return Ok(());
                    }
                    // The body may change the loop variable, as in POV-Ray.
                    i = match self.scope.get(*var).map(|b| &b.value) {
                        Some(Value::Float(f)) => *f,
                        _ => i,
                    } + step;
                }
                Ok(())
            }
            DirectiveKind::Macro(m) => {
                if m.name.is_builtin() {
                    // POV-Ray's own transforms.inc writes `vtransform` and
                    // `vinv_transform` as macros; rts has them built in, doing
                    // the same, so that file's definitions are left out.
                    let name = m.name.name();
                    let file = &self.sources.get(m.name_span.file).name;
                    let povray_include = std::path::Path::new(&**file)
                        .file_name()
                        .is_some_and(|f| f == "transforms.inc");
                    if povray_include && matches!(&*name, "vtransform" | "vinv_transform") {
                        return Ok(());
                    }
                    return Err(self.reserved(m.name_span, &name));
                }
                for (i, p) in m.params.iter().enumerate() {
                    if let Some(first) = m.params[..i].iter().find(|q| q.name == p.name) {
                        return Err(Diagnostic::error(
                            codes::DUPLICATE_MACRO_PARAMETER,
                            p.span,
                            format!("macro `{}` has two parameters named `{}`", m.name, p.name),
                        )
                        .with_label("second one")
                        .with_secondary(first.span, "first one here")
                        .with_help("rename one of them")
                        .into());
                    }
                    if p.name.is_builtin() {
                        return Err(self.reserved(p.span, &p.name.name()));
                    }
                }
                self.before_bind(m.name);
                self.scope
                    .declare(m.name, Value::Macro(m.clone()), m.name_span);
                Ok(())
            }
            DirectiveKind::Include(e) => {
                let v = self.expr(e)?;
                let name = self.to_str(&v, e.span)?;
                self.include(&name, e.span, d.span, out)
            }
            DirectiveKind::Message(kind, e) => {
                let v = self.expr(e)?;
                let text = self.to_str(&v, e.span)?;
                // `#debug` text is printed as it is, as POV-Ray prints it (a line
                // ends only where the text has "\n"); the others are one message.
                if *kind == MessageKind::Debug {
                    self.warn(Diagnostic::note(
                        codes::USER_DEBUG,
                        d.span,
                        text.to_string(),
                    ));
                    return Ok(());
                }
                let text = text.trim_end_matches('\n').to_string();
                match kind {
                    MessageKind::Debug => {}
                    MessageKind::Warning => {
                        self.warn(Diagnostic::warning(codes::USER_WARNING, d.span, text))
                    }
                    MessageKind::Error => {
                        self.stopped = true;
                        return Err(Diagnostic::error(codes::USER_ERROR, d.span, text)
                            .with_label("#error in the scene")
                            .into());
                    }
                }
                Ok(())
            }
            DirectiveKind::Default(items) => {
                let mut toks = Sink::new();
                self.expand(items, &mut toks);
                let mut c = Cursor::new(toks.toks, "#default", d.span);
                while let Some(t) = c.next() {
                    let mut tex = (*self.default_texture).clone();
                    match t {
                        Tok::Block(_, Value::Texture(t), span) if t.patterned.is_some() => {
                            let e = Diagnostic::error(
                                codes::UNEXPECTED_ITEM,
                                span,
                                "the default texture cannot be a patterned texture",
                            )
                            .with_label("chooses whole textures by a pattern")
                            .with_help("POV-Ray 3.7 refuses it too: give the objects the patterned texture instead")
                            .into();
                            self.report(e);
                            continue;
                        }
                        Tok::Block(_, Value::Texture(t), _) => tex = (*t).clone(),
                        Tok::Block(_, Value::Pigment(p), _) => tex.pigment = (*p).clone(),
                        Tok::Block(_, Value::Finish(f), _) => tex.finish = *f,
                        Tok::Block(_, Value::Normal(n), _) => tex.normal = Some((*n).clone()),
                        other => {
                            let e = self.unexpected(&c, &other, &["texture", "pigment", "finish"]);
                            self.report(e);
                            continue;
                        }
                    }
                    self.default_texture = Arc::new(tex);
                }
                Ok(())
            }
            DirectiveKind::FOpen {
                name,
                name_span,
                file,
                mode,
            } => self.fopen(*name, *name_span, file, *mode),
            DirectiveKind::FClose { name, span } => self.fclose(*name, *span),
            DirectiveKind::Read {
                name,
                name_span,
                targets,
            } => self.read_values(*name, *name_span, targets),
            DirectiveKind::Write {
                name,
                name_span,
                items,
            } => self.write_values(*name, *name_span, items),
            DirectiveKind::Version(e) => {
                let v = self.expr(e)?;
                let ver = self.to_float(&v, e.span)?;
                if ver > 3.8 {
                    self.warn(
                        Diagnostic::warning(
                            codes::IGNORED,
                            e.span,
                            format!("#version {ver}: rts follows POV-Ray 3.7"),
                        )
                        .with_help("write `#version 3.7;`"),
                    );
                }
                self.language_version = Some(ver);
                Ok(())
            }
        }
    }

    /// The first `#case`/`#range` clause of a `#switch` that matches its value.
    fn switch_start(&mut self, value: &Expr, cases: &[Case]) -> R<Option<usize>> {
        let v = self.expr(value)?;
        let x = self.to_float(&v, value.span)?;
        for (i, c) in cases.iter().enumerate() {
            let hit = match &c.test {
                CaseTest::Case(e) => {
                    let cv = self.expr(e)?;
                    (self.to_float(&cv, e.span)? - x).abs() < 1e-10
                }
                CaseTest::Range(a, b) => {
                    let av = self.expr(a)?;
                    let bv = self.expr(b)?;
                    let (lo, hi) = (self.to_float(&av, a.span)?, self.to_float(&bv, b.span)?);
                    lo <= x && x <= hi
                }
            };
            if hit {
                return Ok(Some(i));
            }
        }
        Ok(None)
    }

    /// The items of the branches a conditional directive (`#if`, `#ifdef`,
    /// `#switch`) chooses now, without running them: where the items are compiled
    /// rather than evaluated (a function's body), as POV-Ray chooses while parsing.
    /// `None` for other directives.
    pub(crate) fn chosen_items(&mut self, d: &Directive) -> R<Option<Vec<Item>>> {
        let mut out = Vec::new();
        match &d.kind {
            DirectiveKind::If {
                branches,
                otherwise,
            } => {
                let mut taken = false;
                for (cond, body) in branches {
                    let v = self.expr(cond)?;
                    if self.to_float(&v, cond.span)? != 0.0 {
                        out.extend(body.iter().cloned());
                        taken = true;
                        break;
                    }
                }
                if !taken {
                    out.extend(otherwise.iter().flatten().cloned());
                }
            }
            DirectiveKind::IfDef {
                negate,
                target,
                then,
                otherwise,
            } => {
                if self.is_defined(target)? != *negate {
                    out.extend(then.iter().cloned());
                } else {
                    out.extend(otherwise.iter().flatten().cloned());
                }
            }
            DirectiveKind::Switch {
                value,
                cases,
                otherwise,
            } => {
                let start = self.switch_start(value, cases)?;
                match start {
                    Some(i) => {
                        for c in &cases[i..] {
                            out.extend(c.body.iter().cloned());
                            if c.breaks {
                                break;
                            }
                        }
                    }
                    None => out.extend(otherwise.iter().flatten().cloned()),
                }
            }
            _ => return Ok(None),
        }
        Ok(Some(self.read_deferred(out)))
    }

    /// The value a conditional directive gives on the right of `#declare`: its
    /// chosen branch must hold exactly one value (a trailing `;` aside).
    pub(crate) fn directive_value(&mut self, d: &Directive) -> R<Value> {
        let mut out = Sink::new();
        self.directive(d, &mut out)?;
        let mut vals = out.toks.into_iter().filter(|t| !matches!(t, Tok::Semi(_)));
        match (vals.next(), vals.next()) {
            (Some(Tok::Val(v, _) | Tok::Block(_, v, _)), None) => match v {
                Value::Poison => Err(Fail::silent()),
                v => Ok(v),
            },
            (None, _) => Err(Diagnostic::error(
                codes::MISSING_VALUE,
                d.span,
                "the branch of this directive chosen gives no value to declare",
            )
            .with_help("give each branch the value: `#declare V = #if (C) 1; #else 2; #end`")
            .into()),
            (Some(t), _) => Err(Diagnostic::error(
                codes::TYPE_MISMATCH,
                d.span,
                "the branch of this directive chosen gives several items where one value is needed",
            )
            .with_label(format!("first item: {}", t.describe()))
            .into()),
        }
    }

    fn count_iteration(&mut self, span: Span) -> R<()> {
        self.loop_iterations += 1;
        if self.loop_iterations > self.options.max_loop_iterations {
            self.stopped = true;
            return Err(Diagnostic::error(
                codes::LOOP_LIMIT,
                span,
                format!("more than {} loop iterations", self.options.max_loop_iterations),
            )
            .with_label("this loop was running when the limit was reached")
            .with_help("check that the loop's condition becomes false (e.g. `#declare I = I + 1;` in the body), or raise the limit with --max-loop-iterations")
            .into());
        }
        self.checkpoint(span)
    }

    pub(crate) fn reserved(&self, span: Span, name: &str) -> Fail {
        Diagnostic::error(codes::RESERVED_NAME, span, format!("`{name}` is a built-in name and cannot be redefined"))
            .with_help("choose another name; a capital first letter never clashes with built-ins (e.g. `My_Value`)")
            .into()
    }

    pub(crate) fn bind(&mut self, local: bool, target: &LValue, v: Value, span: Span) -> R<()> {
        if target.name.is_builtin() {
            return Err(self.reserved(target.name_span, &target.name.name()));
        }
        if target.indices.is_empty() {
            self.before_bind(target.name);
            if local {
                self.scope.local(target.name, v, span);
            } else {
                self.scope.declare(target.name, v, span);
            }
            return Ok(());
        }
        self.force(target.name);
        let mut idx = Vec::new();
        for e in &target.indices {
            let iv = self.expr(e)?;
            idx.push((self.to_float(&iv, e.span)?, e.span));
        }
        if self.scope.get(target.name).is_none() {
            return Err(self
                .unknown_identifier(target.name, target.name_span)
                .into());
        }
        let Some(binding) = self.scope.get_mut(target.name) else {
            return Err(Fail::silent());
        };
        let Value::Array(arr) = &mut binding.value else {
            let kind = binding.value.kind();
            return Err(Diagnostic::error(
                codes::TYPE_MISMATCH,
                target.name_span,
                format!("`{}` is {kind}, not an array", target.name),
            )
            .into());
        };
        let arr = Rc::make_mut(arr);
        if idx.len() != arr.dims.len() {
            return Err(Diagnostic::error(
                codes::INDEX_OUT_OF_RANGE,
                target.name_span,
                format!(
                    "`{}` has {} dimension(s) but {} indices were given",
                    target.name,
                    arr.dims.len(),
                    idx.len()
                ),
            )
            .into());
        }
        let mut flat = 0;
        for ((i, s), dim) in idx.iter().zip(arr.dims.clone()) {
            if *i < 0.0 || *i >= dim as f64 {
                return Err(Diagnostic::error(
                    codes::INDEX_OUT_OF_RANGE,
                    *s,
                    format!(
                        "index {i} is outside the array (valid: 0 to {})",
                        dim as i64 - 1
                    ),
                )
                .with_help("array indices start at 0")
                .into());
            }
            flat = flat * dim + *i as usize;
        }
        arr.elems[flat] = Some(v);
        Ok(())
    }

    pub(crate) fn is_defined(&mut self, target: &LValue) -> R<bool> {
        if target.name.is_builtin() {
            return Ok(true);
        }
        if self.pending.has(target.name) {
            if target.indices.is_empty() {
                return Ok(true);
            }
            self.force(target.name);
        }
        let Some(b) = self.scope.get(target.name) else {
            return Ok(false);
        };
        if target.indices.is_empty() {
            return Ok(true);
        }
        let Value::Array(arr) = b.value.clone() else {
            return Ok(false);
        };
        let mut flat = 0;
        for (e, dim) in target.indices.iter().zip(arr.dims.iter()) {
            let v = self.expr(e)?;
            let i = self.to_float(&v, e.span)?;
            if i < 0.0 || i >= *dim as f64 {
                return Ok(false);
            }
            flat = flat * dim + i as usize;
        }
        Ok(arr.elems.get(flat).is_some_and(Option::is_some))
    }
}
