//! `function { EXPR }` and `function(a, b) { EXPR }`: compiling the body to a
//! [`Function`](crate::scene::Function) program once, when the function is declared.
//!
//! Parts of the body that do not depend on the parameters (declared floats,
//! `pi`, `V.x`, macro calls, calls of other functions with constant arguments)
//! are evaluated once by the ordinary evaluator and become constants, as POV-Ray
//! captures declared values when it parses a function. The rest compiles to
//! stack operations; a call of a macro whose body is one expression is inlined.

use super::value::Value;
use super::{Evaluator, Fail, R};
use crate::diag::{codes, Diagnostic};
use crate::scene::function::{max_depth, Body, Function, Op, MAX_CALL_DEPTH, MAX_STACK};
use crate::span::Span;
use crate::syntax::ast::{Arg, BinOp, Block, Expr, ExprKind, Item, Keyword, UnOp};
use crate::syntax::Sym;
use std::sync::Arc;

/// Most nested inlined macro calls in one function body.
const MAX_INLINE: usize = 32;

/// What a name means while a body compiles.
struct Env {
    /// The parameters, in order.
    params: Vec<Sym>,
    /// Arguments of the macros being inlined, innermost last: the name and the
    /// argument's code.
    inlined: Vec<(Sym, Vec<Op>)>,
    /// Deepest call chain met (1 + the deepest callee).
    depth: usize,
}

impl Env {
    fn param(&self, name: Sym) -> Option<u8> {
        self.params.iter().position(|p| *p == name).map(|i| i as u8)
    }

    fn inlined(&self, name: Sym) -> Option<&[Op]> {
        self.inlined
            .iter()
            .rev()
            .find(|(n, _)| *n == name)
            .map(|(_, c)| c.as_slice())
    }

    /// Whether `name` is a parameter or an inlined macro argument.
    fn bound(&self, name: Sym) -> bool {
        // `u` and `v` are POV-Ray's other names for x and y.
        self.param(name).is_some() || self.inlined(name).is_some() || self.alias(name).is_some()
    }

    /// `u` → x's index and `v` → y's, when the parameters are the default x, y, z.
    fn alias(&self, name: Sym) -> Option<u8> {
        let n = name.name();
        let target = match &*n {
            "u" => "x",
            "v" => "y",
            _ => return None,
        };
        if self
            .params
            .iter()
            .any(|p| &*p.name() == "u" || &*p.name() == "v")
        {
            return None;
        }
        self.params
            .iter()
            .position(|p| &*p.name() == target)
            .map(|i| i as u8)
    }
}

/// The float built-ins a function body may call, with their code.
fn builtin_op(name: &str, n: usize) -> Option<Op> {
    Some(match (name, n) {
        ("abs", 1) => Op::F1(f64::abs),
        ("acos", 1) => Op::F1(f64::acos),
        ("asin", 1) => Op::F1(f64::asin),
        ("atan", 1) => Op::F1(f64::atan),
        ("atan2", 2) => Op::F2(f64::atan2),
        ("ceil", 1) => Op::F1(f64::ceil),
        ("cos", 1) => Op::F1(f64::cos),
        ("cosh", 1) => Op::F1(f64::cosh),
        ("degrees", 1) => Op::F1(f64::to_degrees),
        ("radians", 1) => Op::F1(f64::to_radians),
        ("div", 2) => Op::F2(|a, b| (a / b).trunc()),
        ("exp", 1) => Op::F1(f64::exp),
        ("floor", 1) => Op::F1(f64::floor),
        ("int", 1) => Op::F1(f64::trunc),
        ("ln", 1) => Op::F1(f64::ln),
        ("log", 1) => Op::F1(f64::log10),
        ("mod", 2) => Op::F2(|a, b| a % b),
        ("pow", 2) => Op::F2(f64::powf),
        ("sin", 1) => Op::F1(f64::sin),
        ("sinh", 1) => Op::F1(f64::sinh),
        ("sqrt", 1) => Op::F1(f64::sqrt),
        ("tan", 1) => Op::F1(f64::tan),
        ("tanh", 1) => Op::F1(f64::tanh),
        ("acosh", 1) => Op::F1(f64::acosh),
        ("asinh", 1) => Op::F1(f64::asinh),
        ("atanh", 1) => Op::F1(f64::atanh),
        ("select", 3) => Op::Select3,
        ("select", 4) => Op::Select4,
        _ => return None,
    })
}

/// Names of the built-ins a function body may call (for messages).
const FUNCTION_BUILTINS: &str = "abs, acos, acosh, asin, asinh, atan, atan2, atanh, ceil, cos, cosh, degrees, div, exp, floor, int, ln, log, max, min, mod, pow, radians, select, sin, sinh, sqrt, tan, tanh";

impl Evaluator<'_> {
    /// Evaluates `function { … }` or `function(a, b) { … }` to a function value.
    pub(crate) fn function_block(&mut self, b: &Block) -> R<Value> {
        let params: Vec<(Sym, Span)> = match &b.params {
            Some(p) => p.clone(),
            None => ["x", "y", "z"]
                .iter()
                .map(|n| (crate::syntax::intern::intern(n), b.keyword.span))
                .collect(),
        };
        for (i, (n, s)) in params.iter().enumerate() {
            if params[..i].iter().any(|(m, _)| m == n) {
                return Err(Diagnostic::error(
                    codes::DUPLICATE_MACRO_PARAMETER,
                    *s,
                    format!("parameter `{n}` is named twice"),
                )
                .with_help("give each parameter of a function its own name")
                .into());
            }
        }
        if params.len() > 64 {
            return Err(Diagnostic::error(
                codes::FUNCTION_LIMIT,
                b.keyword.span,
                format!(
                    "a function takes at most 64 parameters, this one has {}",
                    params.len()
                ),
            )
            .into());
        }
        let expanded = self.expand_static(&b.items)?;
        let items: Vec<&Item> = expanded
            .iter()
            .filter(|i| !matches!(i, Item::Semicolon(_)))
            .collect();
        let arity = params.len();
        match items.as_slice() {
            [Item::Block(inner)] if matches!(inner.keyword.name, "pigment" | "pattern") => {
                let as_pigment = Block {
                    keyword: Keyword {
                        name: "pigment",
                        span: inner.keyword.span,
                    },
                    items: inner.items.clone(),
                    span: inner.span,
                    params: None,
                };
                let Value::Pigment(p) = self.block_value(&as_pigment)? else {
                    return Err(Fail::silent());
                };
                let body = if inner.keyword.name == "pigment" {
                    Body::Pigment(p)
                } else {
                    Body::Pattern(p)
                };
                Ok(Value::Function(Arc::new(Function {
                    arity,
                    body,
                    depth: 1,
                })))
            }
            [Item::Block(inner)] if inner.keyword.name == "spline" => {
                let Value::Spline(s) = self.block_value(inner)? else {
                    return Err(Fail::silent());
                };
                Ok(Value::Function(Arc::new(Function {
                    arity: b.params.as_ref().map_or(1, Vec::len),
                    body: Body::Spline(Arc::new((*s).clone())),
                    depth: 1,
                })))
            }
            [Item::Keyword(k), Item::Expr(e)] if k.name == "internal" => {
                self.internal_function(e, b.params.is_some().then_some(arity), b.span)
            }
            [Item::Expr(e)] => {
                let mut env = Env {
                    params: params.iter().map(|p| p.0).collect(),
                    inlined: Vec::new(),
                    depth: 1,
                };
                let mut ops = Vec::new();
                self.compile(e, &mut env, &mut ops)?;
                let too_big = || -> Fail {
                    Diagnostic::error(
                        codes::FUNCTION_LIMIT,
                        e.span,
                        format!(
                            "this function needs more than {MAX_STACK} intermediate values at once"
                        ),
                    )
                    .with_help("split it into smaller declared functions and call those")
                    .into()
                };
                match max_depth(&ops) {
                    Some(d) if d <= MAX_STACK => {}
                    _ => return Err(too_big()),
                }
                Ok(Value::Function(Arc::new(Function {
                    arity,
                    body: Body::Float(ops),
                    depth: env.depth,
                })))
            }
            [] => Err(
                Diagnostic::error(codes::MISSING_VALUE, b.span, "this function is empty")
                    .with_help(
                        "write the expression it computes: `function { x*x + y*y + z*z - 1 }`",
                    )
                    .into(),
            ),
            [first, ..] => Err(Diagnostic::error(
                codes::UNEXPECTED_ITEM,
                items.get(1).map_or(first.span(), |i| i.span()),
                "a function holds one expression, or one `pigment { }` or `pattern { }`",
            )
            .with_help("join the parts with operators: `function { x*x + y*y }`")
            .into()),
        }
    }

    /// Whether `#declare NAME = function { internal(NUMBER) }` is POV-Ray's own
    /// functions.inc declaring one of its built-ins that rts does not have (an
    /// `f_` name, as [`super::items::pov_function`] reads them): the
    /// declaration is then left out, so POV-Ray's include file can be read and a
    /// use of that name says rts lacks it.
    pub(crate) fn foreign_internal(&mut self, b: &Block, name: Sym) -> bool {
        let items: Vec<&Item> = b
            .items
            .iter()
            .filter(|i| !matches!(i, Item::Semicolon(_)))
            .collect();
        let [Item::Keyword(k), Item::Expr(e)] = items.as_slice() else {
            return false;
        };
        let n = name.name();
        let pov_name = n
            .strip_prefix("f_")
            .is_some_and(|r| r.starts_with(|c: char| c.is_ascii_lowercase()));
        k.name == "internal"
            && pov_name
            && !crate::pattern::internal::INTERNALS
                .iter()
                .any(|(m, _, _)| *m == &*n)
            && matches!(self.expr(e), Ok(Value::Float(_)))
    }

    /// `function(x, y, z, …) { internal("f_name") }`: a built-in of functions.inc
    /// (`arity`: the number of parameters declared, if any; without a list the
    /// built-in's own count). POV-Ray's own form, `#declare f_name = function {
    /// internal(NUMBER) }` (its functions.inc), is read by the declared name: its
    /// numbers are private to POV-Ray and change between versions.
    fn internal_function(&mut self, e: &Expr, arity: Option<usize>, span: Span) -> R<Value> {
        let v = self.expr(e)?;
        let name = match (&v, self.ctx.declaring_function) {
            (Value::Float(_), Some(declared))
                if crate::pattern::internal::INTERNALS
                    .iter()
                    .any(|(m, _, _)| *m == &*declared.name()) =>
            {
                std::rc::Rc::<str>::from(&*declared.name())
            }
            (Value::Float(n), declared) => {
                let help = match declared {
                    Some(d) => format!(
                        "rts knows functions.inc's built-ins by name, and `{d}` is not one of them: write `internal(\"f_name\")` with the built-in's name"
                    ),
                    None => "write `internal(\"f_name\")` with the built-in's name, or `#declare f_name = function { internal(…) }` under its functions.inc name".to_string(),
                };
                return Err(Diagnostic::error(
                    codes::UNSUPPORTED,
                    e.span,
                    format!("`internal({n})`: POV-Ray's numbers for its built-in functions are its own (they change between versions)"),
                )
                .with_help(help)
                .into());
            }
            _ => self.to_str(&v, e.span)?,
        };
        let Some(&(_, n, f)) = crate::pattern::internal::INTERNALS
            .iter()
            .find(|(m, _, _)| *m == &*name)
        else {
            return Err(Diagnostic::error(
                codes::UNKNOWN_IDENTIFIER,
                e.span,
                format!("`{name}` is not one of rts's internal functions"),
            )
            .with_help_opt(
                crate::diag::did_you_mean(
                    &name,
                    crate::pattern::internal::INTERNALS
                        .iter()
                        .map(|(m, _, _)| *m),
                )
                .map(|s| format!("did you mean `{s}`?")),
            )
            .into());
        };
        let arity = arity.unwrap_or(n);
        if n != arity {
            return Err(Diagnostic::error(
                codes::ARITY,
                span,
                format!("`{name}` takes {n} parameters, the function declares {arity}"),
            )
            .into());
        }
        let ops = (0..n as u8)
            .map(Op::Param)
            .chain([Op::Internal(f, n as u8)])
            .collect();
        Ok(Value::Function(Arc::new(Function {
            arity,
            body: Body::Float(ops),
            depth: 1,
        })))
    }

    /// Whether `e` reads a parameter (or an inlined argument).
    fn uses_params(&self, e: &Expr, env: &Env) -> bool {
        match &e.kind {
            ExprKind::Ident(n) => env.bound(*n),
            ExprKind::Number(_) | ExprKind::Str(_) | ExprKind::Block(_) => false,
            ExprKind::Vector(parts) => parts.iter().any(|p| self.uses_params(p, env)),
            ExprKind::Unary(_, a) | ExprKind::Dot(a, _, _) => self.uses_params(a, env),
            ExprKind::Binary(_, a, b) | ExprKind::Index(a, b) => {
                self.uses_params(a, env) || self.uses_params(b, env)
            }
            ExprKind::Cond(a, b, c) => {
                self.uses_params(a, env) || self.uses_params(b, env) || self.uses_params(c, env)
            }
            ExprKind::Call { args, .. } => args.iter().any(|a| match a {
                Arg::Expr(x) => self.uses_params(x, env),
                _ => false,
            }),
            ExprKind::Colour { value, parts, .. } => {
                value.as_ref().is_some_and(|v| self.uses_params(v, env))
                    || parts.iter().any(|(_, p)| self.uses_params(p, env))
            }
            ExprKind::Array { .. } => false,
            // Compiled only as a constant; a branch using parameters is refused below.
            ExprKind::Directive(_) => true,
        }
    }

    /// Compiles `e` (a float) onto `out`.
    /// A function body with its `#if`/`#ifdef`/`#switch` directives replaced by the
    /// branches they choose now (POV-Ray chooses while parsing the body).
    fn expand_static(&mut self, items: &[Item]) -> R<Vec<Item>> {
        let mut out = Vec::with_capacity(items.len());
        for item in items {
            if let Item::Directive(d) = item {
                if let Some(chosen) = self.chosen_items(d)? {
                    out.extend(self.expand_static(&chosen)?);
                    continue;
                }
            }
            out.push(item.clone());
        }
        Ok(out)
    }

    fn compile(&mut self, e: &Expr, env: &mut Env, out: &mut Vec<Op>) -> R<()> {
        if let ExprKind::Directive(d) = &e.kind {
            let chosen = self.chosen_items(d)?.unwrap_or_default();
            let chosen = self.expand_static(&chosen)?;
            let mut exprs = chosen.iter().filter(|i| !matches!(i, Item::Semicolon(_)));
            return match (exprs.next(), exprs.next()) {
                (Some(Item::Expr(inner)), None) => self.compile(inner, env, out),
                _ => Err(Diagnostic::error(
                    codes::TYPE_MISMATCH,
                    d.span,
                    "the branch chosen here must hold one expression",
                )
                .with_help("write one expression in each branch: `#if (C) x*2 #else x #end`")
                .into()),
            };
        }
        if !self.uses_params(e, env) {
            let v = self.expr(e)?;
            return match v {
                Value::Float(f) => {
                    out.push(Op::Const(f));
                    Ok(())
                }
                Value::Poison => Err(Fail::silent()),
                other => Err(Diagnostic::error(
                    codes::TYPE_MISMATCH,
                    e.span,
                    format!("a function computes with floats, this is {}", other.kind()),
                )
                .with_help("take a component (`V.x`) or use a float")
                .into()),
            };
        }
        match &e.kind {
            ExprKind::Ident(n) => {
                if let Some(code) = env.inlined(*n) {
                    out.extend(code.iter().cloned());
                } else if let Some(i) = env.param(*n).or_else(|| env.alias(*n)) {
                    out.push(Op::Param(i));
                }
                Ok(())
            }
            ExprKind::Unary(op, a) => {
                self.compile(a, env, out)?;
                match op {
                    UnOp::Neg => out.push(Op::Neg),
                    UnOp::Not => out.push(Op::Not),
                    UnOp::Plus => {}
                }
                Ok(())
            }
            ExprKind::Binary(op, a, b) => {
                self.compile(a, env, out)?;
                self.compile(b, env, out)?;
                out.push(match op {
                    BinOp::Or => Op::Or,
                    BinOp::And => Op::And,
                    BinOp::Lt => Op::Lt,
                    BinOp::Le => Op::Le,
                    BinOp::Eq => Op::Eq,
                    BinOp::Ne => Op::Ne,
                    BinOp::Ge => Op::Ge,
                    BinOp::Gt => Op::Gt,
                    BinOp::Add => Op::Add,
                    BinOp::Sub => Op::Sub,
                    BinOp::Mul => Op::Mul,
                    BinOp::Div => Op::Div,
                });
                Ok(())
            }
            ExprKind::Cond(c, a, b) => {
                self.compile(c, env, out)?;
                self.compile(a, env, out)?;
                self.compile(b, env, out)?;
                out.push(Op::Cond);
                Ok(())
            }
            ExprKind::Call {
                name,
                name_span,
                args,
            } => self.compile_call(*name, *name_span, args, e.span, None, env, out),
            ExprKind::Dot(a, comp, comp_span) => {
                let idx = match &*comp.name() {
                    "x" | "u" | "red" => 0,
                    "y" | "v" | "green" => 1,
                    "z" | "blue" => 2,
                    "t" | "filter" => 3,
                    "transmit" => 4,
                    "gray" | "grey" => 5,
                    other => {
                        return Err(Diagnostic::error(
                            codes::BAD_COMPONENT,
                            *comp_span,
                            format!("unknown component `.{other}`"),
                        )
                        .into())
                    }
                };
                if let ExprKind::Call {
                    name,
                    name_span,
                    args,
                } = &a.kind
                {
                    return self.compile_call(*name, *name_span, args, a.span, Some(idx), env, out);
                }
                Err(Diagnostic::error(
                    codes::TYPE_MISMATCH,
                    a.span,
                    "inside a function, components can only be taken of a pigment function's call or of declared values",
                )
                .with_help("write `P(x, y, z).red` for a pigment function P")
                .into())
            }
            _ => Err(Diagnostic::error(
                codes::TYPE_MISMATCH,
                e.span,
                "a function computes with floats only",
            )
            .with_help(
                "vectors, colours, strings and arrays cannot depend on a function's parameters",
            )
            .into()),
        }
    }

    /// Compiles a call `name(args)` (with `.component` when `comp` is given).
    #[allow(clippy::too_many_arguments)]
    fn compile_call(
        &mut self,
        name: Sym,
        name_span: Span,
        args: &[Arg],
        span: Span,
        comp: Option<u8>,
        env: &mut Env,
        out: &mut Vec<Op>,
    ) -> R<()> {
        let mut exprs = Vec::with_capacity(args.len());
        for a in args {
            match a {
                Arg::Expr(x) => exprs.push(x),
                other => {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        other.span(),
                        "inside a function, arguments are float expressions",
                    )
                    .into())
                }
            }
        }
        let text = name.name();
        let not_colour = |this: &Self| -> R<()> {
            let _ = this;
            match comp {
                Some(_) => Err(Diagnostic::error(
                    codes::BAD_COMPONENT,
                    span,
                    format!("`{text}` gives a float, which has no components"),
                )
                .into()),
                None => Ok(()),
            }
        };
        if name.is_builtin() && crate::eval::is_builtin_function(name.0 as usize) {
            not_colour(self)?;
            if matches!(&*text, "min" | "max") && !exprs.is_empty() {
                self.compile(exprs[0], env, out)?;
                for x in &exprs[1..] {
                    self.compile(x, env, out)?;
                    out.push(Op::F2(if &*text == "min" { f64::min } else { f64::max }));
                }
                return Ok(());
            }
            let Some(op) = builtin_op(&text, exprs.len()) else {
                let known = builtin_op(&text, 1)
                    .or_else(|| builtin_op(&text, 2))
                    .or_else(|| builtin_op(&text, 3))
                    .is_some();
                return Err(if known {
                    Diagnostic::error(
                        codes::ARITY,
                        span,
                        format!("`{text}` does not take {} arguments", exprs.len()),
                    )
                    .with_help(format!("call it as {}", super::builtins::signature(&text)))
                } else {
                    Diagnostic::error(
                        codes::UNSUPPORTED,
                        name_span,
                        format!("`{text}` cannot be used inside a function"),
                    )
                    .with_help(format!(
                        "functions may call {FUNCTION_BUILTINS} and declared functions"
                    ))
                }
                .into());
            };
            for x in &exprs {
                self.compile(x, env, out)?;
            }
            out.push(op);
            return Ok(());
        }
        self.force(name);
        let value = self.scope.get(name).map(|b| b.value.clone());
        match value {
            Some(Value::Function(f)) => {
                if exprs.len() != f.arity {
                    return Err(Diagnostic::error(
                        codes::ARITY,
                        span,
                        format!(
                            "`{text}` takes {} argument{}, found {}",
                            f.arity,
                            if f.arity == 1 { "" } else { "s" },
                            exprs.len()
                        ),
                    )
                    .into());
                }
                if f.depth + 1 > MAX_CALL_DEPTH {
                    return Err(Diagnostic::error(
                        codes::FUNCTION_LIMIT,
                        name_span,
                        format!("functions call each other more than {MAX_CALL_DEPTH} deep here"),
                    )
                    .into());
                }
                env.depth = env.depth.max(f.depth + 1);
                if comp.is_some() && !f.is_colour() {
                    not_colour(self)?;
                }
                for x in &exprs {
                    self.compile(x, env, out)?;
                }
                out.push(match comp {
                    Some(c) => Op::Component(f, c),
                    None => Op::Call(f.clone(), exprs.len() as u8),
                });
                Ok(())
            }
            Some(Value::Macro(m)) => {
                not_colour(self)?;
                let body: Vec<&Item> = m
                    .body
                    .iter()
                    .filter(|i| !matches!(i, Item::Semicolon(_)))
                    .collect();
                let [Item::Expr(body)] = body.as_slice() else {
                    return Err(Diagnostic::error(
                        codes::UNSUPPORTED,
                        name_span,
                        format!("macro `{text}` cannot be used inside a function with arguments that depend on its parameters"),
                    )
                    .with_help("only a macro whose body is a single expression can be; declare a function instead: `#declare F = function(a) { … }`")
                    .into());
                };
                if m.params.len() != exprs.len() {
                    return Err(Diagnostic::error(
                        codes::ARITY,
                        span,
                        format!(
                            "macro `{text}` takes {} arguments, found {}",
                            m.params.len(),
                            exprs.len()
                        ),
                    )
                    .into());
                }
                if env.inlined.len() >= MAX_INLINE * 8 {
                    return Err(Diagnostic::error(
                        codes::FUNCTION_LIMIT,
                        name_span,
                        "macros inlined in this function nest too deep",
                    )
                    .into());
                }
                let mut codes_ = Vec::with_capacity(exprs.len());
                for x in &exprs {
                    let mut c = Vec::new();
                    self.compile(x, env, &mut c)?;
                    codes_.push(c);
                }
                let mark = env.inlined.len();
                for (p, c) in m.params.iter().zip(codes_) {
                    env.inlined.push((p.name, c));
                }
                let r = if env.inlined.len() > MAX_INLINE * 8 || self.macro_depth > MAX_INLINE {
                    Err(Diagnostic::error(
                        codes::FUNCTION_LIMIT,
                        name_span,
                        "macros inlined in this function nest too deep",
                    )
                    .into())
                } else {
                    self.macro_depth += 1;
                    let r = self.compile(body, env, out);
                    self.macro_depth -= 1;
                    r
                };
                env.inlined.truncate(mark);
                r
            }
            Some(Value::Poison) => Err(Fail::silent()),
            Some(other) => Err(Diagnostic::error(
                codes::TYPE_MISMATCH,
                name_span,
                format!("`{text}` is {}, not a function", other.kind()),
            )
            .into()),
            None => {
                // Let the ordinary call report the unknown name.
                let e = Expr {
                    kind: ExprKind::Call {
                        name,
                        name_span,
                        args: Vec::new(),
                    },
                    span,
                };
                self.expr(&e).map(|_| ())
            }
        }
    }
}

impl Evaluator<'_> {
    /// `F(a, b, …)` in an ordinary expression: a float, or a colour for a
    /// pigment function.
    pub(crate) fn call_function(
        &mut self,
        f: &Function,
        name: Sym,
        args: &[Arg],
        span: Span,
    ) -> R<Value> {
        if args.len() != f.arity {
            return Err(Diagnostic::error(
                codes::ARITY,
                span,
                format!(
                    "`{name}` takes {} argument{}, found {}",
                    f.arity,
                    if f.arity == 1 { "" } else { "s" },
                    args.len()
                ),
            )
            .into());
        }
        let mut vals = Vec::with_capacity(args.len());
        for a in args {
            match a {
                Arg::Expr(e) => {
                    let v = self.expr(e)?;
                    vals.push(self.to_float(&v, e.span)?);
                }
                other => {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        other.span(),
                        "a function's arguments are floats",
                    )
                    .into())
                }
            }
        }
        Ok(if let Body::Spline(s) = &f.body {
            crate::eval::animation::spline::spline_value(s, vals[0])
        } else if f.is_colour() {
            Value::Colour(super::value::colour_from_array(f.colour(&vals)))
        } else {
            Value::Float(f.eval(&vals))
        })
    }
}
