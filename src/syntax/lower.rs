//! Lowering: pest's parse tree to the [`ast`](super::ast), one function per rule.

use super::ast::*;
use super::intern::intern;
use super::parser::Rule;
use crate::diag::{codes, Diagnostic};
use crate::span::{FileId, Span};
use pest::iterators::{Pair, Pairs};
use std::rc::Rc;

/// The longest chain of binary operators in one expression; longer chains are refused
/// so that evaluating the left-deep tree cannot exhaust the stack.
pub const MAX_CHAIN: usize = 10_000;

/// Lowers pest pairs of one file (byte offsets shifted by `offset`).
pub struct Lowerer {
    /// The file being lowered.
    pub file: FileId,
    /// Added to pest's byte offsets (non-zero when a tail of the file was parsed).
    pub offset: usize,
    /// Problems found while lowering (bad escapes, numbers, limits).
    pub diags: Vec<Diagnostic>,
    /// Macro bodies the grammar saw blank, by offsets in the file (see
    /// [`super::prepass::Marks::token_level`]).
    pub token_level: Vec<(usize, usize)>,
    /// Branch bodies left unread, by offsets in the file, in order (see
    /// [`super::prepass::Marks::deferred`]).
    pub deferred: Vec<(usize, usize)>,
    /// Data bodies the prepass has read, by the offset in the file of their
    /// `{`, in order (see [`super::prepass::Marks::data_runs`]); each taken
    /// when its body is lowered.
    pub runs: Vec<(usize, Option<super::data::DataRun>)>,
}

type P<'i> = Pair<'i, Rule>;

impl Lowerer {
    fn span(&self, p: &P) -> Span {
        let s = p.as_span();
        Span::new(self.file, s.start() + self.offset, s.end() + self.offset)
    }

    /// Lowers the children of `file`/`one_item`/`body`-like pairs into items.
    pub fn items(&mut self, pairs: Pairs<Rule>) -> Vec<Item> {
        let mut out = Vec::new();
        for p in pairs.filter(|p| p.as_rule() != Rule::EOI) {
            if p.as_rule() == Rule::sized_fn {
                self.sized_fn(p, &mut out);
            } else if p.as_rule() == Rule::data_run {
                out.extend(self.data(&p).map(Item::Data));
            } else if p.as_rule() == Rule::data_body {
                let at = self.span(&p).start as usize;
                let text = p.into_inner().next().expect("data_text");
                let read = self
                    .runs
                    .binary_search_by_key(&at, |r| r.0)
                    .ok()
                    .and_then(|k| self.runs[k].1.take());
                let run = match read {
                    Some(mut run) => {
                        run.span = self.span(&text);
                        Some(Rc::new(run))
                    }
                    None => self.data(&text),
                };
                out.extend(run.map(Item::Data));
            } else {
                out.push(self.item(p));
            }
        }
        out
    }

    /// A run of plain numbers and vectors (a `data_run`, or the text of a
    /// `data_body`), packed.
    fn data(&mut self, p: &P) -> Option<Rc<super::data::DataRun>> {
        let span = self.span(p);
        match super::data::read(p.as_str(), span) {
            Ok(run) => Some(Rc::new(run)),
            Err(bad) => {
                let at = span.start as usize;
                self.diags.push(
                    Diagnostic::error(
                        codes::BAD_NUMBER,
                        Span::new(self.file, at + bad.start, at + bad.end),
                        "number too large",
                    )
                    .with_label("this does not fit in a 64-bit float")
                    .with_help("use a number below 1.8e308"),
                );
                None
            }
        }
    }

    /// `function W, H { … }` as the items `W`, `,`, `H` and the block.
    fn sized_fn(&mut self, p: P, out: &mut Vec<Item>) {
        let span = self.span(&p);
        let mut inner = p.into_inner();
        let keyword = self.keyword(inner.next().expect("function keyword"));
        let w = inner.next().expect("width");
        out.push(Item::Expr(Box::new(self.expr(w))));
        let comma = inner.next().expect("comma");
        out.push(Item::Comma(self.span(&comma)));
        let h = inner.next().expect("height");
        out.push(Item::Expr(Box::new(self.expr(h))));
        let items = self.items(inner);
        out.push(Item::Block(std::rc::Rc::new(Block {
            span: Span {
                start: keyword.span.start,
                ..span
            },
            keyword,
            items,
            params: None,
        })));
    }

    fn item(&mut self, p: P) -> Item {
        let span = self.span(&p);
        match p.as_rule() {
            Rule::block => Item::Block(std::rc::Rc::new(self.block(p))),
            Rule::item_block => {
                // (Its span may take the spaces after a keyword alone.)
                let alone = p.clone().into_inner().next().is_some_and(|k| {
                    p.as_str()[k.as_span().end() - p.as_span().start()..]
                        .trim_ascii()
                        .is_empty()
                });
                if alone {
                    Item::Keyword(self.keyword(p.into_inner().next().expect("keyword")))
                } else {
                    Item::Block(std::rc::Rc::new(self.block(p)))
                }
            }
            Rule::keyword => Item::Keyword(self.keyword(p)),
            Rule::bracket => {
                let items = self.items(p.into_inner());
                Item::Bracket(Box::new(Bracket { items, span }))
            }
            Rule::comma => Item::Comma(span),
            Rule::semicolon => Item::Semicolon(span),
            Rule::expr => Item::Expr(Box::new(self.expr(p))),
            _ => Item::Directive(Box::new(self.directive(p))),
        }
    }

    fn keyword(&mut self, p: P) -> Keyword {
        Keyword {
            name: super::keywords::canonical(p.as_str()),
            span: self.span(&p),
        }
    }

    fn block(&mut self, p: P) -> Block {
        let span = self.span(&p);
        let mut inner = p.into_inner();
        let keyword = self.keyword(inner.next().expect("block keyword"));
        let mut params = None;
        if inner
            .peek()
            .is_some_and(|q| q.as_rule() == Rule::func_params)
        {
            let list = inner.next().expect("function parameters");
            params = Some(
                list.into_inner()
                    .map(|n| (intern(n.as_str()), self.span(&n)))
                    .collect(),
            );
        }
        let items = self.items(inner);
        Block {
            keyword,
            items,
            span,
            params,
        }
    }

    fn lvalue(&mut self, p: P) -> LValue {
        let mut inner = p.into_inner();
        let name = inner.next().expect("lvalue name");
        let name_span = self.span(&name);
        let indices = inner
            .map(|i| self.expr(i.into_inner().next().expect("index")))
            .collect();
        LValue {
            name: intern(name.as_str()),
            name_span,
            indices,
        }
    }

    fn body(&mut self, p: P) -> Vec<Item> {
        debug_assert_eq!(p.as_rule(), Rule::body);
        // A deferred body is blank: the grammar skipped it whole and the
        // (empty) body starts at the `#` that ends it.
        if !self.deferred.is_empty() && p.as_str().is_empty() {
            let at = p.as_span().start() + self.offset;
            if let Ok(k) = self.deferred.binary_search_by_key(&at, |&(_, end)| end) {
                let (start, end) = self.deferred[k];
                return vec![Item::Deferred(Rc::new(Deferred {
                    span: Span::new(self.file, start, end),
                    items: std::cell::OnceCell::new(),
                }))];
            }
        }
        self.items(p.into_inner())
    }

    fn directive(&mut self, p: P) -> Directive {
        let span = self.span(&p);
        let rule = p.as_rule();
        let mut inner = p.into_inner();
        let kind = match rule {
            Rule::declare_d => {
                let local = inner.next().expect("kind").as_str() == "local";
                let mut next = inner.next().expect("lvalue");
                let mut deprecated = None;
                if next.as_rule() == Rule::deprecated {
                    let mut parts = next.into_inner();
                    parts.next();
                    let mut p = parts.next().expect("message");
                    let once = p.as_rule() == Rule::once_kw;
                    if once {
                        p = parts.next().expect("message");
                    }
                    let text = self.unescape(&p.into_inner().next().expect("string inner"));
                    deprecated = Some(Deprecation {
                        once,
                        message: Rc::from(text),
                    });
                    next = inner.next().expect("lvalue");
                }
                let target = self.lvalue(next);
                let v = inner.next().expect("rhs");
                let value = match v.as_rule() {
                    Rule::block => Rhs::Block(Box::new(self.block(v))),
                    Rule::if_d | Rule::ifdef_d | Rule::switch_d | Rule::include_d => {
                        Rhs::Directive(Box::new(self.directive(v)))
                    }
                    _ => Rhs::Expr(Box::new(self.expr(v))),
                };
                DirectiveKind::Declare {
                    local,
                    target,
                    value,
                    deprecated,
                }
            }
            Rule::undef_d => {
                let n = inner.nth(1).expect("name");
                DirectiveKind::Undef {
                    name: intern(n.as_str()),
                    span: self.span(&n),
                }
            }
            Rule::if_d => {
                inner.next();
                let cond = self.expr(inner.next().expect("cond"));
                let body = self.body(inner.next().expect("body"));
                let mut branches = vec![(cond, body)];
                let mut otherwise = None;
                for part in inner {
                    match part.as_rule() {
                        Rule::elseif_d => {
                            let mut e = part.into_inner();
                            e.next();
                            let c = self.expr(e.next().expect("cond"));
                            let b = self.body(e.next().expect("body"));
                            branches.push((c, b));
                        }
                        Rule::else_d => otherwise = Some(self.else_body(part)),
                        _ => {}
                    }
                }
                DirectiveKind::If {
                    branches,
                    otherwise,
                }
            }
            Rule::ifdef_d => {
                let negate = inner.next().expect("kind").as_str() == "ifndef";
                let target = self.lvalue(inner.next().expect("lvalue"));
                let then = self.body(inner.next().expect("body"));
                let mut otherwise = None;
                for part in inner {
                    if part.as_rule() == Rule::else_d {
                        otherwise = Some(self.else_body(part));
                    }
                }
                DirectiveKind::IfDef {
                    negate,
                    target,
                    then,
                    otherwise,
                }
            }
            Rule::switch_d => {
                inner.next();
                let value = self.expr(inner.next().expect("value"));
                let mut cases = Vec::new();
                let mut otherwise = None;
                for part in inner {
                    match part.as_rule() {
                        Rule::case_d => cases.push(self.case(part)),
                        Rule::else_d => otherwise = Some(self.else_body(part)),
                        _ => {}
                    }
                }
                DirectiveKind::Switch {
                    value,
                    cases,
                    otherwise,
                }
            }
            Rule::while_d => {
                inner.next();
                let cond = self.expr(inner.next().expect("cond"));
                let body = self.body(inner.next().expect("body"));
                DirectiveKind::While { cond, body }
            }
            Rule::for_d => {
                inner.next();
                let v = inner.next().expect("var");
                let var_span = self.span(&v);
                let var = intern(v.as_str());
                let start = self.expr(inner.next().expect("start"));
                let end = self.expr(inner.next().expect("end"));
                let mut step = None;
                let mut body = Vec::new();
                for part in inner {
                    match part.as_rule() {
                        Rule::expr => step = Some(self.expr(part)),
                        Rule::body => body = self.body(part),
                        _ => {}
                    }
                }
                DirectiveKind::For {
                    var,
                    var_span,
                    start,
                    end,
                    step,
                    body,
                }
            }
            Rule::macro_d => {
                inner.next();
                let n = inner.next().expect("name");
                let name_span = self.span(&n);
                let mut params = Vec::new();
                let mut body = Vec::new();
                for part in inner {
                    match part.as_rule() {
                        Rule::param => {
                            let pspan = self.span(&part);
                            let mut optional = false;
                            let mut name = None;
                            for x in part.into_inner() {
                                match x.as_rule() {
                                    Rule::optional_kw => optional = true,
                                    _ => name = Some(intern(x.as_str())),
                                }
                            }
                            params.push(Param {
                                name: name.expect("param name"),
                                optional,
                                span: pspan,
                            });
                        }
                        Rule::body => body = self.body(part),
                        _ => {}
                    }
                }
                let raw = self
                    .token_level
                    .iter()
                    .copied()
                    .find(|&(s, e)| s >= span.start as usize && e <= span.end as usize)
                    .map(|(s, e)| Span::new(self.file, s, e));
                DirectiveKind::Macro(Rc::new(MacroDef {
                    name: intern(n.as_str()),
                    name_span,
                    params,
                    body,
                    raw,
                }))
            }
            Rule::include_d => {
                inner.next();
                DirectiveKind::Include(self.expr(inner.next().expect("file")))
            }
            Rule::message_d => {
                let kind = match inner.next().expect("kind").as_str() {
                    "debug" => MessageKind::Debug,
                    "warning" => MessageKind::Warning,
                    _ => MessageKind::Error,
                };
                DirectiveKind::Message(kind, self.expr(inner.next().expect("message")))
            }
            Rule::default_d => {
                inner.next();
                DirectiveKind::Default(self.items(inner))
            }
            Rule::version_d => {
                inner.next();
                DirectiveKind::Version(self.expr(inner.next().expect("version")))
            }
            Rule::fopen_d => {
                inner.next();
                let n = inner.next().expect("name");
                let file = self.expr(inner.next().expect("file"));
                let mode = match inner.next().expect("mode").as_str() {
                    "read" => OpenMode::Read,
                    "write" => OpenMode::Write,
                    _ => OpenMode::Append,
                };
                DirectiveKind::FOpen {
                    name: intern(n.as_str()),
                    name_span: self.span(&n),
                    file,
                    mode,
                }
            }
            Rule::fclose_d => {
                let n = inner.nth(1).expect("name");
                DirectiveKind::FClose {
                    name: intern(n.as_str()),
                    span: self.span(&n),
                }
            }
            Rule::read_d => {
                inner.next();
                let n = inner.next().expect("name");
                let targets = inner.map(|t| self.lvalue(t)).collect();
                DirectiveKind::Read {
                    name: intern(n.as_str()),
                    name_span: self.span(&n),
                    targets,
                }
            }
            Rule::write_d => {
                inner.next();
                let n = inner.next().expect("name");
                let items = inner
                    .map(|item| {
                        let mut parts = item.into_inner();
                        let first = parts.next().expect("write item");
                        if first.as_rule() == Rule::binary_kind {
                            let kind = match first.as_str() {
                                "uint8" => BinaryKind::U8,
                                "sint8" => BinaryKind::S8,
                                "uint16be" => BinaryKind::U16Be,
                                "uint16le" => BinaryKind::U16Le,
                                "sint16be" => BinaryKind::S16Be,
                                "sint16le" => BinaryKind::S16Le,
                                "sint32be" => BinaryKind::S32Be,
                                _ => BinaryKind::S32Le,
                            };
                            (Some(kind), self.expr(parts.next().expect("value")))
                        } else {
                            (None, self.expr(first))
                        }
                    })
                    .collect();
                DirectiveKind::Write {
                    name: intern(n.as_str()),
                    name_span: self.span(&n),
                    items,
                }
            }
            other => unreachable!("not a directive rule: {other:?}"),
        };
        Directive { kind, span }
    }

    fn else_body(&mut self, p: P) -> Vec<Item> {
        let body = p
            .into_inner()
            .find(|x| x.as_rule() == Rule::body)
            .expect("else body");
        self.body(body)
    }

    fn case(&mut self, p: P) -> Case {
        let mut inner = p.into_inner();
        let head = inner.next().expect("case head");
        let span = self.span(&head);
        let rule = head.as_rule();
        let mut exprs = head.into_inner().filter(|x| x.as_rule() == Rule::expr);
        let test = if rule == Rule::case_head {
            CaseTest::Case(self.expr(exprs.next().expect("case value")))
        } else {
            let a = self.expr(exprs.next().expect("low"));
            let b = self.expr(exprs.next().expect("high"));
            CaseTest::Range(a, b)
        };
        let body = self.body(inner.next().expect("case body"));
        let breaks = inner.next().is_some();
        Case {
            test,
            body,
            breaks,
            span,
        }
    }

    /// Lowers an expression-level pair of any precedence level.
    pub fn expr(&mut self, p: P) -> Expr {
        let span = self.span(&p);
        match p.as_rule() {
            Rule::expr => {
                let mut inner = p.into_inner();
                let first = self.expr(inner.next().expect("operand"));
                if inner.next().is_some() {
                    let a = self.expr(inner.next().expect("then"));
                    inner.next();
                    let b = self.expr(inner.next().expect("else"));
                    Expr {
                        kind: ExprKind::Cond(Box::new(first), Box::new(a), Box::new(b)),
                        span,
                    }
                } else {
                    first
                }
            }
            Rule::chain | Rule::sum => self.chain(p),
            Rule::number => {
                let v = super::decimal::parse(p.as_str());
                self.number(v, span)
            }
            Rule::plain_vector => self.plain_vector(&p, span),
            Rule::string => {
                let inner = p.into_inner().next().expect("string inner");
                let text = self.unescape(&inner);
                Expr {
                    kind: ExprKind::Str(Rc::from(text)),
                    span,
                }
            }
            Rule::vector => Expr {
                kind: ExprKind::Vector(p.into_inner().map(|x| self.expr(x)).collect()),
                span,
            },
            Rule::if_d | Rule::ifdef_d | Rule::switch_d => Expr {
                kind: ExprKind::Directive(Box::new(self.directive(p))),
                span,
            },
            Rule::paren => {
                let inner = self.expr(p.into_inner().next().expect("paren"));
                Expr { span, ..inner }
            }
            Rule::colour => self.colour(p),
            Rule::array => {
                let mut dims = Vec::new();
                let mut init = None;
                for x in p.into_inner() {
                    match x.as_rule() {
                        Rule::expr => dims.push(self.expr(x)),
                        Rule::array_init => init = Some(self.array_init(x)),
                        _ => {}
                    }
                }
                Expr {
                    kind: ExprKind::Array { dims, init },
                    span,
                }
            }
            Rule::call => {
                let mut inner = p.into_inner();
                let n = inner.next().expect("name");
                let name_span = self.span(&n);
                if inner.peek().is_none() {
                    return Expr {
                        kind: ExprKind::Ident(intern(n.as_str())),
                        span: name_span,
                    };
                }
                let mut args: Vec<Arg> = inner
                    .map(|a| match a.as_rule() {
                        Rule::block => Arg::Block(self.block(a)),
                        Rule::empty_arg => Arg::Empty(self.span(&a)),
                        _ => Arg::Expr(self.expr(a)),
                    })
                    .collect();
                // `f()` is no arguments, not one empty one.
                if let [Arg::Empty(_)] = args.as_slice() {
                    args.clear();
                }
                Expr {
                    kind: ExprKind::Call {
                        name: intern(n.as_str()),
                        name_span,
                        args,
                    },
                    span,
                }
            }
            Rule::value_block => {
                let b = self.block(p.into_inner().next().expect("value block"));
                Expr {
                    kind: ExprKind::Block(Box::new(b)),
                    span,
                }
            }
            other => unreachable!("not an expression rule: {other:?}"),
        }
    }

    /// A number literal; one too large for an `f64` is reported and reads as 0.
    fn number(&mut self, v: Option<f64>, span: Span) -> Expr {
        let v = v.unwrap_or_else(|| {
            self.diags.push(
                Diagnostic::error(codes::BAD_NUMBER, span, "number too large")
                    .with_label("this does not fit in a 64-bit float")
                    .with_help("use a number below 1.8e308"),
            );
            0.0
        });
        Expr {
            kind: ExprKind::Number(v),
            span,
        }
    }

    /// `<1, -2, 3>` read by `plain_vector`: the same expressions `vector` gives
    /// (a signed component is the sign applied to the number).
    fn plain_vector(&mut self, p: &P, span: Span) -> Expr {
        let (file, base) = (self.file, span.start as usize);
        let at = |a: usize, b: usize| Span::new(file, base + a, base + b);
        let parts = super::data::vector_components(p.as_str())
            .into_iter()
            .map(|c| {
                let n = self.number(c.value, at(c.start, c.end));
                match c.sign {
                    None => n,
                    Some((negative, i)) => Expr {
                        kind: ExprKind::Unary(
                            if negative { UnOp::Neg } else { UnOp::Plus },
                            Box::new(n),
                        ),
                        span: at(i, c.end),
                    },
                }
            })
            .collect();
        Expr {
            kind: ExprKind::Vector(parts),
            span,
        }
    }

    /// Operands joined by binary operators, read with their precedence (`|`
    /// loosest, then `&`, comparisons, `+ -`, `* /`; all left-associative), each
    /// operand with its prefix operators and its `.x` / `[I]` postfixes (which
    /// bind tighter: `-V.x` is `-(V.x)`). Iterative, so a long chain cannot
    /// exhaust the stack.
    fn chain(&mut self, p: P) -> Expr {
        // One operand alone (most values): itself, without the stacks.
        let mut inner = p.clone().into_inner();
        if let (Some(only), None) = (inner.next(), inner.next()) {
            if !matches!(
                only.as_rule(),
                Rule::prefix_op
                    | Rule::dot
                    | Rule::index
                    | Rule::or_op
                    | Rule::and_op
                    | Rule::cmp_op
                    | Rule::add_op
                    | Rule::mul_op
            ) {
                return self.expr(only);
            }
        }
        let span = self.span(&p);
        let mut operands: Vec<Expr> = Vec::new();
        let mut ops: Vec<BinOp> = Vec::new();
        let mut prefixes: Vec<(UnOp, Span)> = Vec::new();
        let mut current: Option<Expr> = None;
        for x in p.into_inner() {
            let xs = self.span(&x);
            match x.as_rule() {
                Rule::prefix_op => prefixes.push((
                    match x.as_str() {
                        "-" => UnOp::Neg,
                        "+" => UnOp::Plus,
                        _ => UnOp::Not,
                    },
                    xs,
                )),
                Rule::dot => {
                    let e = current.take().expect("an operand before `.`");
                    let name = x.into_inner().next().expect("component");
                    let span = e.span.join(xs);
                    current = Some(Expr {
                        kind: ExprKind::Dot(Box::new(e), intern(name.as_str()), xs),
                        span,
                    });
                }
                Rule::index => {
                    let e = current.take().expect("an operand before `[`");
                    let i = self.expr(x.into_inner().next().expect("index"));
                    let span = e.span.join(xs);
                    current = Some(Expr {
                        kind: ExprKind::Index(Box::new(e), Box::new(i)),
                        span,
                    });
                }
                Rule::or_op | Rule::and_op | Rule::cmp_op | Rule::add_op | Rule::mul_op => {
                    operands.push(apply_prefixes(
                        current.take().expect("an operand before an operator"),
                        &mut prefixes,
                    ));
                    ops.push(match x.as_str() {
                        "|" => BinOp::Or,
                        "&" => BinOp::And,
                        "<" => BinOp::Lt,
                        "<=" => BinOp::Le,
                        "=" => BinOp::Eq,
                        "!=" => BinOp::Ne,
                        ">=" => BinOp::Ge,
                        ">" => BinOp::Gt,
                        "+" => BinOp::Add,
                        "-" => BinOp::Sub,
                        "*" => BinOp::Mul,
                        _ => BinOp::Div,
                    });
                }
                _ => current = Some(self.expr(x)),
            }
        }
        operands.push(apply_prefixes(
            current.expect("a last operand"),
            &mut prefixes,
        ));
        if ops.len() >= MAX_CHAIN {
            self.diags.push(
                Diagnostic::error(
                    codes::NESTING_TOO_DEEP,
                    span,
                    format!("expression with more than {MAX_CHAIN} operators"),
                )
                .with_help("split it into several #declared parts"),
            );
            return operands.swap_remove(0);
        }
        // Shunting-yard: operands and operators of lower precedence wait on stacks.
        let mut values: Vec<Expr> = Vec::with_capacity(operands.len());
        let mut pending: Vec<BinOp> = Vec::new();
        let reduce = |values: &mut Vec<Expr>, op: BinOp| {
            let rhs = values.pop().expect("right operand");
            let lhs = values.pop().expect("left operand");
            let span = lhs.span.join(rhs.span);
            values.push(Expr {
                kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)),
                span,
            });
        };
        let mut operands = operands.into_iter();
        values.push(operands.next().expect("an operand"));
        for (op, rhs) in ops.into_iter().zip(operands) {
            while let Some(&top) = pending.last() {
                if precedence(top) >= precedence(op) {
                    pending.pop();
                    reduce(&mut values, top);
                } else {
                    break;
                }
            }
            pending.push(op);
            values.push(rhs);
        }
        while let Some(op) = pending.pop() {
            reduce(&mut values, op);
        }
        values.pop().expect("the whole expression")
    }

    fn colour(&mut self, p: P) -> Expr {
        let span = self.span(&p);
        let mut inner = p.into_inner().peekable();
        // Without a colour keyword (`red 1 green 0.5`) it is a plain `color`.
        let kw = match inner.peek() {
            Some(x) if x.as_rule() == Rule::colour_kw => inner.next().expect("peeked").as_str(),
            _ => "color",
        };
        let srgb = kw.starts_with('s');
        let form = match kw.trim_start_matches('s') {
            "rgb" => ColourForm::Rgb,
            "rgbf" => ColourForm::Rgbf,
            "rgbt" => ColourForm::Rgbt,
            "rgbft" => ColourForm::Rgbft,
            _ => ColourForm::Plain,
        };
        let mut value = None;
        let mut parts = Vec::new();
        for x in inner {
            match x.as_rule() {
                Rule::colour_part => {
                    let mut xi = x.into_inner();
                    let part = match xi.next().expect("part").as_str() {
                        "red" => ColourPart::Red,
                        "green" => ColourPart::Green,
                        "blue" => ColourPart::Blue,
                        "filter" => ColourPart::Filter,
                        "transmit" => ColourPart::Transmit,
                        _ => ColourPart::Gray,
                    };
                    parts.push((part, self.expr(xi.next().expect("part value"))));
                }
                _ => value = Some(Box::new(self.expr(x))),
            }
        }
        Expr {
            kind: ExprKind::Colour {
                kw: ColourKw { form, srgb },
                value,
                parts,
            },
            span,
        }
    }

    fn array_init(&mut self, p: P) -> ArrayInit {
        let span = self.span(&p);
        let mut elems = Vec::new();
        for x in p.into_inner() {
            match x.as_rule() {
                Rule::array_init => elems.push(ArrayElem::Nested(self.array_init(x))),
                Rule::block => elems.push(ArrayElem::Block(self.block(x))),
                Rule::data_body => {
                    let text = x.into_inner().next().expect("data_text");
                    let base = self.span(&text);
                    // Each number and vector an element, with its own span.
                    let _ = super::data::scan(text.as_str(), |piece| {
                        if let super::data::Piece::Element { start, end, values } = piece {
                            let at = Span::new(
                                self.file,
                                base.start as usize + start,
                                base.start as usize + end,
                            );
                            let number = |v: f64| Expr {
                                kind: ExprKind::Number(v),
                                span: at,
                            };
                            elems.push(ArrayElem::Expr(match values {
                                [v] => number(*v),
                                v => Expr {
                                    kind: ExprKind::Vector(v.iter().map(|&x| number(x)).collect()),
                                    span: at,
                                },
                            }));
                        }
                    });
                }
                _ => elems.push(ArrayElem::Expr(self.expr(x))),
            }
        }
        ArrayInit { elems, span }
    }

    fn unescape(&mut self, p: &P) -> String {
        let raw = p.as_str();
        let base = p.as_span().start() + self.offset;
        let mut out = String::with_capacity(raw.len());
        let mut chars = raw.char_indices();
        while let Some((i, c)) = chars.next() {
            if c != '\\' {
                out.push(c);
                continue;
            }
            let Some((_, e)) = chars.next() else { break };
            match e {
                'n' => out.push('\n'),
                't' => out.push('\t'),
                'r' => out.push('\r'),
                'b' => out.push('\u{8}'),
                'f' => out.push('\u{c}'),
                'a' => out.push('\u{7}'),
                'v' => out.push('\u{b}'),
                '\\' => out.push('\\'),
                '"' => out.push('"'),
                '\'' => out.push('\''),
                'u' => {
                    let hex: String = raw[i + 2..].chars().take(4).collect();
                    match u32::from_str_radix(&hex, 16).ok().and_then(char::from_u32) {
                        Some(ch) if hex.len() == 4 => {
                            out.push(ch);
                            for _ in 0..4 {
                                chars.next();
                            }
                        }
                        _ => self.bad_escape(
                            base + i,
                            base + i + 2 + hex.len(),
                            "`\\u` needs four hex digits",
                        ),
                    }
                }
                _ => self.bad_escape(base + i, base + i + 1 + e.len_utf8(), "unknown escape"),
            }
        }
        out
    }

    fn bad_escape(&mut self, start: usize, end: usize, what: &str) {
        self.diags.push(
            Diagnostic::error(
                codes::BAD_ESCAPE,
                Span::new(self.file, start, end),
                format!("{what} in string"),
            )
            .with_help(r#"valid escapes are \n \t \r \b \f \a \v \\ \" \' and \uXXXX"#),
        );
    }
}

/// How tightly a binary operator binds (higher: tighter).
fn precedence(op: BinOp) -> u8 {
    match op {
        BinOp::Or => 1,
        BinOp::And => 2,
        BinOp::Lt | BinOp::Le | BinOp::Eq | BinOp::Ne | BinOp::Ge | BinOp::Gt => 3,
        BinOp::Add | BinOp::Sub => 4,
        BinOp::Mul | BinOp::Div => 5,
    }
}

/// `e` under the prefix operators written before it, innermost last.
fn apply_prefixes(mut e: Expr, prefixes: &mut Vec<(UnOp, Span)>) -> Expr {
    while let Some((op, s)) = prefixes.pop() {
        let span = s.join(e.span);
        e = Expr {
            kind: ExprKind::Unary(op, Box::new(e)),
            span,
        };
    }
    e
}
