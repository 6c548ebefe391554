//! Parsing as the user types: the document is cut into top-level chunks at lines that
//! can only start a new item, each chunk's syntax tree is cached by its text, and an
//! edit re-parses only the chunks it touched. The result is the tree the whole-file
//! parse gives: when any chunk fails to parse (or a boundary guess was wrong, which
//! shows as a failing chunk), the whole file is parsed as `rts check` does, so errors
//! are always the same.

use super::lexer::{tokenize, TokKind};
use crate::diag::Diagnostic;
use crate::span::{FileId, Span};
use crate::syntax::ast::{
    Arg, ArrayElem, ArrayInit, Block, Bracket, Case, CaseTest, Directive, DirectiveKind, Expr,
    ExprKind, File, Item, LValue, MacroDef, Param, Rhs,
};
use rustc_hash::FxHashMap;
use std::cell::RefCell;
use std::rc::Rc;

/// Chunks kept between parses (per thread: syntax trees are not `Send`).
const MAX_CACHED: usize = 20_000;

thread_local! {
    static CACHE: RefCell<FxHashMap<String, Rc<Vec<Item>>>> = RefCell::new(FxHashMap::default());
}

/// Directives that open a body closed by `#end`.
const OPENERS: &[&str] = &[
    "#if", "#ifdef", "#ifndef", "#while", "#for", "#macro", "#switch",
];
/// Directives that continue an open one.
const MIDDLE: &[&str] = &["#else", "#elseif", "#case", "#range", "#break", "#end"];

/// Byte offsets where a new top-level item surely starts: at column 0, outside any
/// bracket or directive body, a directive that is not a continuation, or a word
/// followed by `{` or `(` (a block or a macro call).
fn boundaries(text: &str) -> Vec<usize> {
    let toks = tokenize(text);
    let bytes = text.as_bytes();
    let mut out = vec![0];
    let mut depth = 0i64;
    let mut directives = 0i64;
    for (i, t) in toks.iter().enumerate() {
        let s = &text[t.start..t.end];
        let at_line_start = t.start == 0 || bytes[t.start - 1] == b'\n';
        if at_line_start && depth == 0 && directives == 0 && t.start > 0 {
            let starts_item = match t.kind {
                TokKind::Directive => !MIDDLE.contains(&s),
                TokKind::Word => toks.get(i + 1).is_some_and(|n| {
                    n.kind == TokKind::Punct && matches!(&text[n.start..n.end], "{" | "(")
                }),
                _ => false,
            };
            if starts_item {
                out.push(t.start);
            }
        }
        match t.kind {
            TokKind::Punct => match s {
                "{" | "(" | "[" => depth += 1,
                "}" | ")" | "]" => depth -= 1,
                _ => {}
            },
            TokKind::Directive => {
                if OPENERS.contains(&s) {
                    directives += 1;
                } else if s == "#end" {
                    directives -= 1;
                }
            }
            _ => {}
        }
    }
    out
}

/// Parses `text` (file `file`) into the same tree and diagnostics as
/// [`crate::syntax::parse`], re-using the trees of unchanged chunks.
pub fn parse(text: &str, file: FileId) -> (File, Vec<Diagnostic>) {
    let cuts = boundaries(text);
    let mut items = Vec::new();
    let ok = CACHE.with(|cache| {
        let mut cache = cache.borrow_mut();
        if cache.len() > MAX_CACHED {
            cache.clear();
        }
        for (k, &start) in cuts.iter().enumerate() {
            let end = cuts.get(k + 1).copied().unwrap_or(text.len());
            let chunk = &text[start..end];
            let parsed = match cache.get(chunk) {
                Some(p) => p.clone(),
                None => {
                    let (f, diags) = crate::syntax::parse(chunk, FileId(u32::MAX));
                    if !diags.is_empty() {
                        return false;
                    }
                    let p = Rc::new(f.items);
                    cache.insert(chunk.to_string(), p.clone());
                    p
                }
            };
            let shift = Shift {
                file,
                by: start as u32,
            };
            items.extend(parsed.iter().map(|i| shift.item(i)));
        }
        true
    });
    if ok {
        (
            File {
                items,
                ..File::default()
            },
            Vec::new(),
        )
    } else {
        crate::syntax::parse(text, file)
    }
}

/// Moves spans into a file at an offset.
struct Shift {
    file: FileId,
    by: u32,
}

impl Shift {
    fn span(&self, s: Span) -> Span {
        Span {
            file: self.file,
            start: s.start + self.by,
            end: s.end + self.by,
        }
    }

    fn items(&self, items: &[Item]) -> Vec<Item> {
        items.iter().map(|i| self.item(i)).collect()
    }

    fn item(&self, item: &Item) -> Item {
        match item {
            Item::Directive(d) => Item::Directive(Box::new(Directive {
                kind: self.directive(&d.kind),
                span: self.span(d.span),
            })),
            Item::Block(b) => Item::Block(Rc::new(self.block(b))),
            Item::Keyword(k) => Item::Keyword(crate::syntax::ast::Keyword {
                name: k.name,
                span: self.span(k.span),
            }),
            Item::Bracket(b) => Item::Bracket(Box::new(Bracket {
                items: self.items(&b.items),
                span: self.span(b.span),
            })),
            Item::Comma(s) => Item::Comma(self.span(*s)),
            Item::Semicolon(s) => Item::Semicolon(self.span(*s)),
            Item::Expr(e) => Item::Expr(Box::new(self.expr(e))),
            Item::Data(d) => Item::Data(std::rc::Rc::new(crate::syntax::data::DataRun {
                span: self.span(d.span),
                ..(**d).clone()
            })),
            Item::Deferred(d) => {
                let items = std::cell::OnceCell::new();
                if let Some(read) = d.items.get() {
                    let _ = items.set(self.items(read).into());
                }
                Item::Deferred(Rc::new(crate::syntax::ast::Deferred {
                    span: self.span(d.span),
                    items,
                }))
            }
        }
    }

    fn block(&self, b: &Block) -> Block {
        Block {
            keyword: crate::syntax::ast::Keyword {
                name: b.keyword.name,
                span: self.span(b.keyword.span),
            },
            items: self.items(&b.items),
            span: self.span(b.span),
            params: b
                .params
                .as_ref()
                .map(|ps| ps.iter().map(|(n, s)| (*n, self.span(*s))).collect()),
        }
    }

    fn lvalue(&self, l: &LValue) -> LValue {
        LValue {
            name: l.name,
            name_span: self.span(l.name_span),
            indices: l.indices.iter().map(|e| self.expr(e)).collect(),
        }
    }

    fn opt_items(&self, o: &Option<Vec<Item>>) -> Option<Vec<Item>> {
        o.as_ref().map(|v| self.items(v))
    }

    fn directive(&self, d: &DirectiveKind) -> DirectiveKind {
        match d {
            DirectiveKind::Declare {
                local,
                target,
                value,
                deprecated,
            } => DirectiveKind::Declare {
                deprecated: deprecated.clone(),
                local: *local,
                target: self.lvalue(target),
                value: match value {
                    Rhs::Block(b) => Rhs::Block(Box::new(self.block(b))),
                    Rhs::Expr(e) => Rhs::Expr(Box::new(self.expr(e))),
                    Rhs::Directive(d) => Rhs::Directive(Box::new(Directive {
                        kind: self.directive(&d.kind),
                        span: self.span(d.span),
                    })),
                },
            },
            DirectiveKind::Undef { name, span } => DirectiveKind::Undef {
                name: *name,
                span: self.span(*span),
            },
            DirectiveKind::If {
                branches,
                otherwise,
            } => DirectiveKind::If {
                branches: branches
                    .iter()
                    .map(|(c, b)| (self.expr(c), self.items(b)))
                    .collect(),
                otherwise: self.opt_items(otherwise),
            },
            DirectiveKind::IfDef {
                negate,
                target,
                then,
                otherwise,
            } => DirectiveKind::IfDef {
                negate: *negate,
                target: self.lvalue(target),
                then: self.items(then),
                otherwise: self.opt_items(otherwise),
            },
            DirectiveKind::Switch {
                value,
                cases,
                otherwise,
            } => DirectiveKind::Switch {
                value: self.expr(value),
                cases: cases
                    .iter()
                    .map(|c| Case {
                        test: match &c.test {
                            CaseTest::Case(e) => CaseTest::Case(self.expr(e)),
                            CaseTest::Range(a, b) => CaseTest::Range(self.expr(a), self.expr(b)),
                        },
                        body: self.items(&c.body),
                        breaks: c.breaks,
                        span: self.span(c.span),
                    })
                    .collect(),
                otherwise: self.opt_items(otherwise),
            },
            DirectiveKind::While { cond, body } => DirectiveKind::While {
                cond: self.expr(cond),
                body: self.items(body),
            },
            DirectiveKind::For {
                var,
                var_span,
                start,
                end,
                step,
                body,
            } => DirectiveKind::For {
                var: *var,
                var_span: self.span(*var_span),
                start: self.expr(start),
                end: self.expr(end),
                step: step.as_ref().map(|s| self.expr(s)),
                body: self.items(body),
            },
            DirectiveKind::Macro(m) => DirectiveKind::Macro(Rc::new(MacroDef {
                name: m.name,
                name_span: self.span(m.name_span),
                params: m
                    .params
                    .iter()
                    .map(|p| Param {
                        name: p.name,
                        optional: p.optional,
                        span: self.span(p.span),
                    })
                    .collect(),
                body: self.items(&m.body),
                raw: m.raw.map(|s| self.span(s)),
            })),
            DirectiveKind::Include(e) => DirectiveKind::Include(self.expr(e)),
            DirectiveKind::Message(k, e) => DirectiveKind::Message(*k, self.expr(e)),
            DirectiveKind::Default(items) => DirectiveKind::Default(self.items(items)),
            DirectiveKind::Version(e) => DirectiveKind::Version(self.expr(e)),
            DirectiveKind::FOpen {
                name,
                name_span,
                file,
                mode,
            } => DirectiveKind::FOpen {
                name: *name,
                name_span: self.span(*name_span),
                file: self.expr(file),
                mode: *mode,
            },
            DirectiveKind::FClose { name, span } => DirectiveKind::FClose {
                name: *name,
                span: self.span(*span),
            },
            DirectiveKind::Read {
                name,
                name_span,
                targets,
            } => DirectiveKind::Read {
                name: *name,
                name_span: self.span(*name_span),
                targets: targets.iter().map(|t| self.lvalue(t)).collect(),
            },
            DirectiveKind::Write {
                name,
                name_span,
                items,
            } => DirectiveKind::Write {
                name: *name,
                name_span: self.span(*name_span),
                items: items.iter().map(|(k, e)| (*k, self.expr(e))).collect(),
            },
        }
    }

    fn boxed(&self, e: &Expr) -> Box<Expr> {
        Box::new(self.expr(e))
    }

    fn expr(&self, e: &Expr) -> Expr {
        let kind = match &e.kind {
            ExprKind::Number(n) => ExprKind::Number(*n),
            ExprKind::Str(s) => ExprKind::Str(s.clone()),
            ExprKind::Ident(s) => ExprKind::Ident(*s),
            ExprKind::Vector(v) => ExprKind::Vector(v.iter().map(|x| self.expr(x)).collect()),
            ExprKind::Unary(op, a) => ExprKind::Unary(*op, self.boxed(a)),
            ExprKind::Binary(op, a, b) => ExprKind::Binary(*op, self.boxed(a), self.boxed(b)),
            ExprKind::Cond(a, b, c) => ExprKind::Cond(self.boxed(a), self.boxed(b), self.boxed(c)),
            ExprKind::Call {
                name,
                name_span,
                args,
            } => ExprKind::Call {
                name: *name,
                name_span: self.span(*name_span),
                args: args
                    .iter()
                    .map(|a| match a {
                        Arg::Expr(x) => Arg::Expr(self.expr(x)),
                        Arg::Block(b) => Arg::Block(self.block(b)),
                        Arg::Empty(s) => Arg::Empty(self.span(*s)),
                    })
                    .collect(),
            },
            ExprKind::Dot(a, s, sp) => ExprKind::Dot(self.boxed(a), *s, self.span(*sp)),
            ExprKind::Index(a, i) => ExprKind::Index(self.boxed(a), self.boxed(i)),
            ExprKind::Colour { kw, value, parts } => ExprKind::Colour {
                kw: *kw,
                value: value.as_ref().map(|v| self.boxed(v)),
                parts: parts.iter().map(|(p, x)| (*p, self.expr(x))).collect(),
            },
            ExprKind::Array { dims, init } => ExprKind::Array {
                dims: dims.iter().map(|x| self.expr(x)).collect(),
                init: init.as_ref().map(|i| self.array_init(i)),
            },
            ExprKind::Block(b) => ExprKind::Block(Box::new(self.block(b))),
            ExprKind::Directive(d) => ExprKind::Directive(Box::new(Directive {
                kind: self.directive(&d.kind),
                span: self.span(d.span),
            })),
        };
        Expr {
            kind,
            span: self.span(e.span),
        }
    }

    fn array_init(&self, init: &ArrayInit) -> ArrayInit {
        ArrayInit {
            elems: init
                .elems
                .iter()
                .map(|e| match e {
                    ArrayElem::Nested(n) => ArrayElem::Nested(self.array_init(n)),
                    ArrayElem::Expr(x) => ArrayElem::Expr(self.expr(x)),
                    ArrayElem::Block(b) => ArrayElem::Block(self.block(b)),
                })
                .collect(),
            span: self.span(init.span),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The chunked parse gives the same tree as the whole-file parse (compared by
    /// their debug text), on the examples and on edits of them.
    #[test]
    fn same_tree_as_the_whole_file_parse() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut texts = Vec::new();
        for dir in ["examples", "tests/fixtures/ok"] {
            for e in std::fs::read_dir(root.join(dir)).expect("dir").flatten() {
                if e.path().extension().is_some_and(|x| x == "rts") {
                    texts.push(std::fs::read_to_string(e.path()).expect("read"));
                }
            }
        }
        texts.push("#declare C = color red 1\ngreen 0.5;\nsphere { 0, 1 }\n".into());
        texts.push("#declare S =\nsphere { 0, 1 }\n#macro M()\nbox { 0, 1 }\n#end\nM()\n".into());
        assert!(texts.len() > 5);
        for text in &texts {
            for variant in [
                text.clone(),
                format!("// edit\n{text}"),
                text.replacen('1', "2", 3),
            ] {
                let (a, da) = crate::syntax::parse(&variant, FileId(3));
                let (b, db) = parse(&variant, FileId(3));
                let key = |d: &[Diagnostic]| d.iter().map(|d| (d.code, d.span)).collect::<Vec<_>>();
                assert_eq!(key(&da), key(&db));
                assert_eq!(
                    format!("{:?}", a.items),
                    format!("{:?}", b.items),
                    "{variant}"
                );
            }
        }
    }

    const TOKENS: &[&str] = &[
        "\n", "\n", "\n", "sphere", "{", "}", "(", ")", "[", "]", "<", ">", ",", ";", "=",
        "#declare", "#macro", "#end", "#if", "#else", "#while", "#for", "A", "B", "M", "1",
        "color", "red", "green", "rgb", "texture", "pigment", "\"s\"", "/*", "*/", "//", "+",
    ];

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 400, ..Default::default() })]

        /// Random token soups with line breaks: the chunked parse equals the whole one.
        #[test]
        fn chunked_equals_whole(toks in proptest::collection::vec(proptest::sample::select(TOKENS), 0..60)) {
            let text = toks.iter().fold(String::new(), |mut s, t| {
                if !s.is_empty() && !s.ends_with('\n') && *t != "\n" {
                    s.push(' ');
                }
                s.push_str(t);
                s
            });
            let (a, da) = crate::syntax::parse(&text, FileId(1));
            let (b, db) = parse(&text, FileId(1));
            // Codes and places only: pest's error detail is a process-wide switch, so
            // the wording of "expected …" may vary while other threads parse.
            let key = |d: &[Diagnostic]| d.iter().map(|d| (d.code, d.span)).collect::<Vec<_>>();
            proptest::prop_assert_eq!(key(&da), key(&db));
            proptest::prop_assert_eq!(format!("{:?}", a.items), format!("{:?}", b.items), "{}", text);
        }
    }
}
