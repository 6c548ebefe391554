//! Expression evaluation, operators and conversions between value kinds.

use super::builtins::{self, describe};
use super::value::{colour_from_array, colour_to_array, Array, Value, Vector};
use super::{Evaluator, Fail, R};
use crate::diag::{codes, did_you_mean, Diagnostic};
use crate::scene::Colour;
use crate::span::Span;
use crate::syntax::ast::{
    ArrayElem, ArrayInit, BinOp, ColourForm, ColourPart, Expr, ExprKind, UnOp,
};
use crate::syntax::Sym;
use glam::DVec3;
use std::rc::Rc;

impl Evaluator<'_> {
    /// Evaluates an expression.
    pub(crate) fn expr(&mut self, e: &Expr) -> R<Value> {
        match &e.kind {
            ExprKind::Number(n) => Ok(Value::Float(*n)),
            ExprKind::Str(s) => Ok(Value::Str(s.clone())),
            ExprKind::Ident(name) => self.ident(*name, e.span),
            ExprKind::Vector(parts) if parts.len() == 12 => {
                // `matrix <…12 numbers…>`.
                let mut m = [0.0; 12];
                for (i, p) in parts.iter().enumerate() {
                    let v = self.expr(p)?;
                    m[i] = self.to_float(&v, p.span)?;
                }
                match super::transforms::matrix_from_12(&m) {
                    Some(t) => Ok(Value::Transform(std::sync::Arc::new(t))),
                    None => Err(Diagnostic::error(
                        codes::DEGENERATE_TRANSFORM,
                        e.span,
                        "this matrix cannot be inverted",
                    )
                    .with_help(
                        "the first nine numbers must not flatten space (their determinant is 0)",
                    )
                    .into()),
                }
            }
            ExprKind::Vector(parts) if self.ctx.coefficient_lists && parts.len() > 5 => {
                // A `poly`/`cubic`/`quartic` coefficient list.
                let mut elems = Vec::with_capacity(parts.len());
                for p in parts {
                    let v = self.expr(p)?;
                    elems.push(Some(Value::Float(self.to_float(&v, p.span)?)));
                }
                Ok(Value::Array(Rc::new(Array {
                    dims: vec![elems.len()],
                    elems,
                })))
            }
            ExprKind::Vector(parts) => {
                if parts.len() < 2 || parts.len() > 5 {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        e.span,
                        format!(
                            "a vector has 2 to 5 components (12 after `matrix`, more in `poly`), this one has {}",
                            parts.len()
                        ),
                    )
                    .into());
                }
                let mut c = [0.0; 5];
                for (i, p) in parts.iter().enumerate() {
                    let v = self.expr(p)?;
                    c[i] = self.to_float(&v, p.span)?;
                }
                Ok(Value::Vector(Vector {
                    c,
                    len: parts.len() as u8,
                }))
            }
            ExprKind::Unary(op, a) => {
                let v = self.expr(a)?;
                match op {
                    UnOp::Plus => self.numeric(&v, a.span).map(|_| v),
                    UnOp::Neg => self.map_numeric(v, a.span, |x| -x),
                    UnOp::Not => {
                        let f = self.to_float(&v, a.span)?;
                        Ok(Value::Float(f64::from(u8::from(f == 0.0))))
                    }
                }
            }
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b, e.span),
            ExprKind::Cond(c, a, b) => {
                let cv = self.expr(c)?;
                if self.to_float(&cv, c.span)? != 0.0 {
                    self.expr(a)
                } else {
                    self.expr(b)
                }
            }
            ExprKind::Call {
                name,
                name_span,
                args,
            } => self.call_value(*name, *name_span, args, e.span),
            ExprKind::Dot(a, comp, comp_span) => {
                let v = self.expr(a)?;
                self.component(&v, *comp, *comp_span, a.span)
            }
            ExprKind::Index(a, i) => {
                let v = self.expr(a)?;
                let iv = self.expr(i)?;
                let idx = self.to_float(&iv, i.span)?;
                match &v {
                    Value::Array(arr) => {
                        let dim = arr.dims[0];
                        let k = self.check_index(idx, dim, i.span)?;
                        if arr.dims.len() == 1 {
                            return match &arr.elems[k] {
                                Some(x) => Ok(x.clone()),
                                None => Err(Diagnostic::error(
                                    codes::UNINITIALIZED,
                                    e.span,
                                    format!("array element [{k}] is read before it was given a value"),
                                )
                                .with_help("assign it first with `#declare A[I] = …;`, or initialise the array with `{ … }`")
                                .into()),
                            };
                        }
                        let stride: usize = arr.dims[1..].iter().product();
                        let sub = Array {
                            dims: arr.dims[1..].to_vec(),
                            elems: arr.elems[k * stride..(k + 1) * stride].to_vec(),
                        };
                        Ok(Value::Array(Rc::new(sub)))
                    }
                    Value::Poison => Err(Fail::silent()),
                    other => Err(self.mismatch("an array", other, a.span)),
                }
            }
            ExprKind::Colour { kw, value, parts } => {
                let mut c = match value {
                    None => [0.0; 5],
                    Some(v) => {
                        let val = self.expr(v)?;
                        self.colour_components(kw.form, &val, v.span)?
                    }
                };
                if kw.srgb {
                    for ch in c.iter_mut().take(3) {
                        *ch = srgb_to_linear(*ch);
                    }
                }
                for (part, pe) in parts {
                    let pv = self.expr(pe)?;
                    let f = self.to_float(&pv, pe.span)?;
                    match part {
                        ColourPart::Red => c[0] = f,
                        ColourPart::Green => c[1] = f,
                        ColourPart::Blue => c[2] = f,
                        ColourPart::Filter => c[3] = f,
                        ColourPart::Transmit => c[4] = f,
                        ColourPart::Gray => {
                            c[0] = f;
                            c[1] = f;
                            c[2] = f;
                        }
                    }
                }
                Ok(Value::Colour(colour_from_array(c)))
            }
            ExprKind::Array { dims, init } => self.array(dims, init.as_ref(), e.span),
            ExprKind::Block(b) => self.block_value(b),
            ExprKind::Directive(d) => self.directive_value(d),
        }
    }

    /// The components a colour keyword gives from its value.
    fn colour_components(&mut self, form: ColourForm, v: &Value, span: Span) -> R<[f64; 5]> {
        let want = match form {
            ColourForm::Plain => 0,
            ColourForm::Rgb => 3,
            ColourForm::Rgbf | ColourForm::Rgbt => 4,
            ColourForm::Rgbft => 5,
        };
        let mut c = [0.0; 5];
        match v {
            Value::Poison => return Err(Fail::silent()),
            Value::Colour(col) if form == ColourForm::Plain => return Ok(colour_to_array(col)),
            Value::Colour(col) => {
                // `rgb Red`: POV-Ray accepts a colour where a vector is expected.
                c = colour_to_array(col);
                if form == ColourForm::Rgb {
                    c[3] = 0.0;
                    c[4] = 0.0;
                }
                return Ok(c);
            }
            Value::Float(f) => {
                if form == ColourForm::Plain {
                    self.warn(
                        Diagnostic::warning(codes::IGNORED, span, format!("`color {f}` sets filter and transmit to {f} too"))
                            .with_help(format!("as in POV-Ray a float colour fills all five components; write `rgb {f}` for a grey")),
                    );
                    return Ok([*f; 5]);
                }
                c = [*f; 5];
                if want < 5 {
                    c[4] = 0.0;
                }
                if want < 4 {
                    c[3] = 0.0;
                }
                return Ok(c);
            }
            Value::Vector(vec) => {
                let n = vec.len as usize;
                if form == ColourForm::Plain {
                    if n < 3 {
                        return Err(self.mismatch("a colour", v, span));
                    }
                    c[..n].copy_from_slice(vec.as_slice());
                    return Ok(c);
                }
                if n != want && !(n == 3 && want > 3) {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        span,
                        format!("expected a vector of {want} components, found {n}"),
                    )
                    .with_help(match form {
                        ColourForm::Rgb => "write rgb <red, green, blue>",
                        ColourForm::Rgbf => "write rgbf <red, green, blue, filter>",
                        ColourForm::Rgbt => "write rgbt <red, green, blue, transmit>",
                        _ => "write rgbft <red, green, blue, filter, transmit>",
                    })
                    .into());
                }
                c[..3].copy_from_slice(&vec.c[..3]);
                match form {
                    ColourForm::Rgbf => c[3] = vec.c[3],
                    ColourForm::Rgbt => c[4] = vec.c[3],
                    ColourForm::Rgbft => {
                        c[3] = vec.c[3];
                        c[4] = vec.c[4];
                    }
                    _ => {}
                }
            }
            other => return Err(self.mismatch("a colour or vector", other, span)),
        }
        Ok(c)
    }

    fn ident(&mut self, name: Sym, span: Span) -> R<Value> {
        if !self.deprecated.is_empty() {
            if let Some((dep, warned)) = self.deprecated.get(&name) {
                if !(dep.once && warned.get()) {
                    warned.set(true);
                    let d = Diagnostic::warning(
                        codes::DEPRECATED,
                        span,
                        format!("`{name}` is deprecated: {}", dep.message),
                    )
                    .with_help("its declaration says what to use instead");
                    self.warn(d);
                }
            }
        }
        if name.is_builtin() {
            let i = name.0 as usize;
            if crate::syntax::builtins::is_function(i) {
                return Err(Diagnostic::error(
                    codes::TYPE_MISMATCH,
                    span,
                    format!("`{name}` is a function and needs arguments"),
                )
                .with_help(format!("call it as {}", builtins::signature(&name.name())))
                .into());
            }
            return Ok(self.builtin_constant(i));
        }
        self.force(name);
        match self.scope.get(name) {
            Some(b) => match &b.value {
                Value::Poison => Err(Fail::silent()),
                Value::Macro(m) => Err(Diagnostic::error(
                    codes::TYPE_MISMATCH,
                    span,
                    format!("`{name}` is a macro and needs `( )`"),
                )
                .with_help(format!(
                    "call it as {name}({})",
                    m.params
                        .iter()
                        .map(|p| p.name.to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                ))
                .into()),
                v => Ok(v.clone()),
            },
            None => Err(self.unknown_identifier(name, span).into()),
        }
    }

    /// "unknown identifier" with a suggestion among the names in scope and built-ins.
    pub(crate) fn unknown_identifier(&self, name: Sym, span: Span) -> Diagnostic {
        let text = name.name();
        if POV_KEYWORDS_NOT_YET.contains(&&*text) {
            return Diagnostic::error(
                codes::UNSUPPORTED,
                span,
                format!("`{text}` is a POV-Ray 3.7 keyword rts does not implement yet"),
            )
            .with_label("not implemented yet")
            .with_help("see docs/language.md for what this release supports");
        }
        let names: Vec<std::sync::Arc<str>> = self
            .scope
            .names()
            .into_iter()
            .chain(self.pending.names())
            .map(Sym::name)
            .collect();
        // Keywords are lowercase: suggest them only for lowercase words.
        let keywords: &[&str] = if text.chars().any(char::is_uppercase) {
            &[]
        } else {
            crate::syntax::keywords::KEYWORDS
        };
        let cands = names
            .iter()
            .map(|s| &**s)
            .chain(crate::syntax::builtins::BUILTIN_NAMES.iter().copied())
            .chain(keywords.iter().copied());
        // A functions.inc-like name is "not implemented" unless it looks like
        // a misspelt name the scene declared.
        if did_you_mean(&text, names.iter().map(|s| &**s)).is_none() {
            if let Some(d) = super::items::pov_function(&text, span) {
                return d;
            }
        }
        let suggestion = did_you_mean(&text, cands);
        let mut d = Diagnostic::error(
            codes::UNKNOWN_IDENTIFIER,
            span,
            format!("unknown identifier `{text}`"),
        )
        .with_label("not declared");
        if let Some(s) = suggestion {
            d = d.with_help(format!("did you mean `{s}`?"));
        } else if text.chars().next().is_some_and(char::is_uppercase) {
            d = d.with_help(format!(
                "declare it first with `#declare {text} = …;`, or #include the file that defines it (colour names need `#include \"colors.inc\"`)"
            ));
        } else {
            d = d.with_help(format!("declare it first with `#declare {text} = …;`"));
        }
        d
    }

    fn check_index(&self, idx: f64, dim: usize, span: Span) -> R<usize> {
        if idx < 0.0 || idx >= dim as f64 || !idx.is_finite() {
            return Err(Diagnostic::error(
                codes::INDEX_OUT_OF_RANGE,
                span,
                format!(
                    "index {idx} is outside the array (valid: 0 to {})",
                    dim as i64 - 1
                ),
            )
            .with_label(format!(
                "the dimension has {dim} element{}",
                if dim == 1 { "" } else { "s" }
            ))
            .with_help("array indices start at 0")
            .into());
        }
        Ok(idx as usize)
    }

    /// Evaluates `array[N]…{ … }`.
    fn array(&mut self, dims: &[Expr], init: Option<&ArrayInit>, span: Span) -> R<Value> {
        let mut sizes = Vec::new();
        let mut total: usize = 1;
        for d in dims {
            let v = self.expr(d)?;
            let n = self.to_float(&v, d.span)?;
            if n < 1.0 || n.fract() != 0.0 {
                return Err(Diagnostic::error(
                    codes::INVALID_SIZE,
                    d.span,
                    format!("array size must be a whole number of at least 1, found {n}"),
                )
                .into());
            }
            if n > self.options.max_array_size as f64 {
                return Err(self.array_too_big(d.span));
            }
            total = total.saturating_mul(n as usize);
            if total > self.options.max_array_size {
                return Err(self.array_too_big(span));
            }
            sizes.push(n as usize);
        }
        let bytes = total as u64 * std::mem::size_of::<Option<Value>>() as u64;
        self.reserve(bytes, span, &format!("this array of {total} elements"))?;
        let mut elems = vec![None; total];
        if let Some(init) = init {
            self.fill_array(init, &sizes, 0, &mut elems, 0)?;
        }
        Ok(Value::Array(Rc::new(Array { dims: sizes, elems })))
    }

    fn array_too_big(&self, span: Span) -> Fail {
        Diagnostic::error(
            codes::ARRAY_SIZE,
            span,
            format!("array larger than {} elements", self.options.max_array_size),
        )
        .with_help("use a smaller array, or raise the limit with --max-array-size")
        .into()
    }

    fn fill_array(
        &mut self,
        init: &ArrayInit,
        dims: &[usize],
        level: usize,
        out: &mut [Option<Value>],
        base: usize,
    ) -> R<()> {
        if init.elems.len() != dims[level] {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                init.span,
                format!(
                    "expected {} elements here, found {}",
                    dims[level],
                    init.elems.len()
                ),
            )
            .with_help("give exactly as many elements as the array's size in this dimension")
            .into());
        }
        let stride: usize = dims[level + 1..].iter().product();
        for (i, el) in init.elems.iter().enumerate() {
            let at = base + i * stride;
            let last = level + 1 == dims.len();
            match (el, last) {
                (ArrayElem::Nested(n), false) => self.fill_array(n, dims, level + 1, out, at)?,
                (ArrayElem::Nested(n), true) => {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        n.span,
                        "too many levels of `{ }` for this array",
                    )
                    .with_help("an array with one dimension takes `{ a, b, c }`")
                    .into())
                }
                (ArrayElem::Expr(e), true) => out[at] = Some(self.expr(e)?),
                (ArrayElem::Block(b), true) => out[at] = Some(self.block_value(b)?),
                (ArrayElem::Expr(e), false) => {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        e.span,
                        "expected `{` for the next dimension of the array",
                    )
                    .into())
                }
                (ArrayElem::Block(b), false) => {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        b.span,
                        "expected `{` for the next dimension of the array",
                    )
                    .into())
                }
            }
        }
        Ok(())
    }

    /// `.x`, `.red`, … of a value.
    fn component(&self, v: &Value, comp: Sym, comp_span: Span, vspan: Span) -> R<Value> {
        let name = comp.name();
        let idx = match &*name {
            "x" | "u" | "red" => 0,
            "y" | "v" | "green" => 1,
            "z" | "blue" => 2,
            "t" | "filter" => 3,
            "transmit" => 4,
            "gray" | "grey" => 5,
            _ => {
                let cands = [
                    "x", "y", "z", "t", "u", "v", "red", "green", "blue", "filter", "transmit",
                    "gray",
                ];
                return Err(Diagnostic::error(
                    codes::BAD_COMPONENT,
                    comp_span,
                    format!("unknown component `.{name}`"),
                )
                .with_help_opt(did_you_mean(&name, cands).map(|s| format!("did you mean `.{s}`?")))
                .into());
            }
        };
        match v {
            Value::Poison => Err(Fail::silent()),
            Value::Vector(vec) => {
                let colour_name = matches!(&*name, "red" | "green" | "blue" | "filter" | "transmit" | "gray" | "grey");
                if idx >= vec.len as usize || colour_name {
                    return Err(Diagnostic::error(
                        codes::BAD_COMPONENT,
                        comp_span,
                        format!("{} has no component `.{name}`", v.kind()),
                    )
                    .with_secondary(vspan, format!("this is {}", v.kind()))
                    .with_help(match vec.len {
                        2 => "a 2-vector has .x and .y (or .u and .v)",
                        3 => "a vector has .x, .y and .z",
                        _ => "vectors have .x, .y, .z and .t",
                    })
                    .into());
                }
                Ok(Value::Float(vec.c[idx]))
            }
            Value::Colour(c) => {
                if matches!(&*name, "u" | "v") {
                    return Err(Diagnostic::error(codes::BAD_COMPONENT, comp_span, format!("a colour has no component `.{name}`"))
                        .with_help("colours have .red, .green, .blue, .filter, .transmit and .gray")
                        .into());
                }
                let a = colour_to_array(c);
                Ok(Value::Float(if idx == 5 {
                    0.297 * a[0] + 0.589 * a[1] + 0.114 * a[2]
                } else {
                    a[idx]
                }))
            }
            other => Err(Diagnostic::error(
                codes::BAD_COMPONENT,
                comp_span,
                format!("`.{name}` needs a vector or colour, found {}", other.kind()),
            )
            .with_secondary(vspan, format!("this is {}", describe(other)))
            .with_help("components exist only on vectors (.x .y .z .t) and colours (.red .green .blue .filter .transmit)")
            .into()),
        }
    }

    fn binary(&mut self, op: BinOp, a: &Expr, b: &Expr, span: Span) -> R<Value> {
        // `&` and `|` short-circuit as in POV-Ray.
        if matches!(op, BinOp::And | BinOp::Or) {
            let av = self.expr(a)?;
            let x = self.to_float(&av, a.span)? != 0.0;
            if (op == BinOp::And && !x) || (op == BinOp::Or && x) {
                return Ok(Value::Float(f64::from(u8::from(x))));
            }
            let bv = self.expr(b)?;
            let y = self.to_float(&bv, b.span)? != 0.0;
            return Ok(Value::Float(f64::from(u8::from(y))));
        }
        let av = self.expr(a)?;
        let bv = self.expr(b)?;
        if let (Value::Float(x), Value::Float(y)) = (&av, &bv) {
            return self.float_op(op, *x, *y, b.span);
        }
        if let (Value::Str(x), Value::Str(y)) = (&av, &bv) {
            let r = match op {
                BinOp::Eq => x == y,
                BinOp::Ne => x != y,
                BinOp::Lt => x < y,
                BinOp::Le => x <= y,
                BinOp::Gt => x > y,
                BinOp::Ge => x >= y,
                _ => {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        span,
                        "strings cannot be combined with arithmetic",
                    )
                    .with_help("join strings with concat(A, B)")
                    .into())
                }
            };
            return Ok(Value::Float(f64::from(u8::from(r))));
        }
        // Component-wise on vectors and colours, promoting floats.
        let colour = matches!(av, Value::Colour(_)) || matches!(bv, Value::Colour(_));
        let (xa, na) = self.components(&av, a.span)?;
        let (xb, nb) = self.components(&bv, b.span)?;
        let n = if colour { 5 } else { na.max(nb) };
        if matches!(
            op,
            BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge | BinOp::Eq | BinOp::Ne
        ) {
            if !colour && na > 1 && nb > 1 && na != nb {
                return Err(self.mismatch(&format!("a vector of {na} components"), &bv, b.span));
            }
            // POV-Ray compares vectors by their first component.
            return self.float_op(op, xa[0], xb[0], b.span);
        }
        let mut out = [0.0; 5];
        for i in 0..n {
            let Value::Float(r) = self.float_op(op, xa[i], xb[i], b.span)? else {
                unreachable!()
            };
            out[i] = r;
        }
        Ok(if colour {
            Value::Colour(colour_from_array(out))
        } else {
            Value::Vector(Vector {
                c: out,
                len: n as u8,
            })
        })
    }

    /// Components of a numeric value: a float fills all five.
    fn components(&self, v: &Value, span: Span) -> R<([f64; 5], usize)> {
        match v {
            Value::Float(f) => Ok(([*f; 5], 1)),
            Value::Vector(x) => {
                let mut c = x.c;
                // A shorter vector promoted against a longer one gets zeros, as POV-Ray.
                for item in c.iter_mut().skip(x.len as usize) {
                    *item = 0.0;
                }
                Ok((c, x.len as usize))
            }
            Value::Colour(c) => Ok((colour_to_array(c), 5)),
            Value::Poison => Err(Fail::silent()),
            other => Err(self.mismatch("a number, vector or colour", other, span)),
        }
    }

    fn float_op(&self, op: BinOp, x: f64, y: f64, rhs: Span) -> R<Value> {
        let b = |c: bool| Value::Float(f64::from(u8::from(c)));
        Ok(match op {
            BinOp::Add => Value::Float(x + y),
            BinOp::Sub => Value::Float(x - y),
            BinOp::Mul => Value::Float(x * y),
            BinOp::Div => {
                if y == 0.0 {
                    return Err(Diagnostic::error(
                        codes::DIVISION_BY_ZERO,
                        rhs,
                        "division by zero",
                    )
                    .with_label("this is 0")
                    .into());
                }
                Value::Float(x / y)
            }
            BinOp::Lt => b(x < y),
            BinOp::Le => b(x <= y),
            BinOp::Gt => b(x > y),
            BinOp::Ge => b(x >= y),
            // POV-Ray compares floats with a small tolerance.
            BinOp::Eq => b((x - y).abs() < 1e-10),
            BinOp::Ne => b((x - y).abs() >= 1e-10),
            BinOp::And => b(x != 0.0 && y != 0.0),
            BinOp::Or => b(x != 0.0 || y != 0.0),
        })
    }

    fn numeric(&self, v: &Value, span: Span) -> R<()> {
        self.components(v, span).map(|_| ())
    }

    fn map_numeric(&self, v: Value, span: Span, f: impl Fn(f64) -> f64) -> R<Value> {
        Ok(match v {
            Value::Float(x) => Value::Float(f(x)),
            Value::Vector(mut vec) => {
                vec.c.iter_mut().for_each(|c| *c = f(*c));
                Value::Vector(vec)
            }
            Value::Colour(c) => {
                let mut a = colour_to_array(&c);
                a.iter_mut().for_each(|x| *x = f(*x));
                Value::Colour(colour_from_array(a))
            }
            Value::Poison => return Err(Fail::silent()),
            other => return Err(self.mismatch("a number, vector or colour", &other, span)),
        })
    }

    /// A type-mismatch failure: expected `want`, found `found`, at `span`.
    pub(crate) fn mismatch(&self, want: &str, found: &Value, span: Span) -> Fail {
        if let Value::Poison = found {
            return Fail::silent();
        }
        Diagnostic::error(
            codes::TYPE_MISMATCH,
            span,
            format!("expected {want}, found {}", found.kind()),
        )
        .with_label(format!("this is {}", describe(found)))
        .into()
    }

    /// The next value, which must be a finite number above 0: `expected` names it
    /// when it is missing, `what` in the message ("WHAT must be above 0, found X").
    pub(crate) fn take_above_zero(
        &mut self,
        c: &mut super::cursor::Cursor,
        expected: &str,
        what: &str,
        help: &str,
    ) -> R<f64> {
        let (v, s) = c.value(expected)?;
        let x = self.to_float(&v, s)?;
        if x.is_finite() && x > 0.0 {
            return Ok(x);
        }
        Err(Diagnostic::error(
            codes::OUT_OF_RANGE,
            s,
            format!("{what} must be above 0, found {x}"),
        )
        .with_help(help.to_string())
        .into())
    }

    /// A float.
    pub(crate) fn to_float(&self, v: &Value, span: Span) -> R<f64> {
        match v {
            Value::Float(f) => Ok(*f),
            other => Err(self.mismatch("a float", other, span)),
        }
    }

    /// A 3-vector, promoting floats (`2` is `<2,2,2>`) and 2-vectors.
    pub(crate) fn to_vec3(&self, v: &Value, span: Span) -> R<DVec3> {
        match v {
            Value::Float(f) => Ok(DVec3::splat(*f)),
            Value::Vector(x) if x.len <= 3 => Ok(x.xyz()),
            Value::Vector(x) => Err(Diagnostic::error(
                codes::TYPE_MISMATCH,
                span,
                format!("expected a vector of 3 components, found {}", x.len),
            )
            .into()),
            other => Err(self.mismatch("a vector", other, span)),
        }
    }

    /// A colour, promoting vectors (`<r,g,b>`) and floats (grey).
    pub(crate) fn to_colour(&self, v: &Value, span: Span) -> R<Colour> {
        match v {
            Value::Colour(c) => Ok(*c),
            Value::Vector(x) if x.len >= 3 => Ok(colour_from_array(x.c)),
            Value::Float(f) => Ok(Colour::rgb(*f, *f, *f)),
            other => Err(self.mismatch("a colour", other, span)),
        }
    }

    /// A string.
    pub(crate) fn to_str(&self, v: &Value, span: Span) -> R<Rc<str>> {
        match v {
            Value::Str(s) => Ok(s.clone()),
            other => Err(self.mismatch("a string", other, span)),
        }
    }
}

/// sRGB-encoded component to linear.
pub(crate) use crate::scene::srgb_to_linear;

/// POV-Ray 3.7 keywords (patterns, objects, camera types, modifiers) that rts does not
/// implement yet and does not reserve: met where a name is expected, they are
/// reported as unsupported rather than as unknown identifiers.
const POV_KEYWORDS_NOT_YET: &[&str] = &[
    "area_illumination",
    "facets",
    "omnimax",
    "pavement",
    "tiling",
];
