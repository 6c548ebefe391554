//! An index of names over the syntax tree of a document and the files it includes:
//! where each `#declare`, `#local`, `#macro`, macro parameter and `#for` variable is
//! defined, where each name is used, which files are included, and the document's
//! outline. It needs only the syntax tree, so it works when evaluation fails.

use crate::eval::OBJECT_BLOCKS;
use crate::eval::{find_include, load_file, EvalOptions, STDLIB};
use crate::source::SourceMap;
use crate::span::{FileId, Span};
use crate::syntax::ast::{
    Arg, ArrayElem, ArrayInit, Block, CaseTest, DirectiveKind, Expr, ExprKind, Item, Rhs,
};
use crate::syntax::Sym;
use rustc_hash::FxHashSet;
use std::path::{Path, PathBuf};

/// How deep includes are followed.
const MAX_INCLUDE_DEPTH: usize = 32;

/// What kind of name a [`Def`] defines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DefKind {
    /// `#declare`.
    Declare,
    /// `#local`.
    Local,
    /// `#macro`.
    Macro,
    /// A macro parameter.
    Param,
    /// The variable of a `#for` loop.
    LoopVar,
}

impl DefKind {
    /// How hover and completion name the kind.
    pub fn describe(self) -> &'static str {
        match self {
            DefKind::Declare => "#declare",
            DefKind::Local => "#local",
            DefKind::Macro => "#macro",
            DefKind::Param => "macro parameter",
            DefKind::LoopVar => "#for variable",
        }
    }
}

/// A definition of a name.
#[derive(Clone, Debug)]
pub struct Def {
    /// The name.
    pub name: Sym,
    /// What defines it.
    pub kind: DefKind,
    /// Where the name is written.
    pub span: Span,
    /// The whole definition (the directive).
    pub full: Span,
    /// For macros, the parameters as written (`optional B`).
    pub params: Vec<String>,
    /// For parameters and `#local`s inside a macro, the macro's span: the name is
    /// visible only there.
    pub scope: Option<Span>,
    /// For declarations whose value is a block, the block's keyword.
    pub block: Option<&'static str>,
}

/// A use of a name.
#[derive(Clone, Copy, Debug)]
pub struct Use {
    /// The name.
    pub name: Sym,
    /// Where it is written.
    pub span: Span,
}

/// An `#include` directive.
#[derive(Clone, Debug)]
pub struct Include {
    /// The file name's string literal.
    pub span: Span,
    /// The file it leads to, when found.
    pub target: Option<FileId>,
}

/// What an outline entry is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutlineKind {
    /// A `#declare`/`#local`.
    Variable,
    /// A `#macro`.
    Macro,
    /// An object (shape or CSG).
    Object,
    /// The camera.
    Camera,
    /// A light source.
    Light,
    /// Scene settings (`global_settings`, `background`, `fog`, `sky_sphere`).
    Settings,
}

/// An entry of the document outline.
#[derive(Clone, Debug)]
pub struct OutlineItem {
    /// The name shown.
    pub name: String,
    /// Extra words shown beside it.
    pub detail: String,
    /// What it is.
    pub kind: OutlineKind,
    /// The whole item.
    pub span: Span,
    /// The part to select (the name or keyword).
    pub name_span: Span,
    /// Nested entries (objects inside CSG).
    pub children: Vec<OutlineItem>,
}

/// The index of one document and its includes.
#[derive(Debug, Default)]
pub struct Index {
    /// Every definition, in the order met (includes where they are included).
    pub defs: Vec<Def>,
    /// Every use of a name.
    pub uses: Vec<Use>,
    /// Every `#include` met.
    pub includes: Vec<Include>,
    /// The outline of the main file.
    pub outline: Vec<OutlineItem>,
    /// The files indexed, the main file first.
    pub files: Vec<FileId>,
}

const CSG: &[&str] = &[
    "union",
    "merge",
    "intersection",
    "difference",
    "light_group",
];
const SETTINGS: &[&str] = &["global_settings", "background", "fog", "sky_sphere"];

struct Builder<'a> {
    sources: &'a mut SourceMap,
    options: &'a EvalOptions,
    scene_dir: Option<PathBuf>,
    index: Index,
    visited: FxHashSet<FileId>,
    depth: usize,
}

impl Index {
    /// Indexes the parsed main file `items` (file `main` of `sources`), following its
    /// includes through the evaluator's file search. Include files are read into
    /// `sources` when they are not there yet.
    pub fn build(
        sources: &mut SourceMap,
        options: &EvalOptions,
        main: FileId,
        items: &[Item],
    ) -> Index {
        let scene_dir = sources.get(main).dir().map(Path::to_path_buf);
        let mut b = Builder {
            sources,
            options,
            scene_dir,
            index: Index::default(),
            visited: FxHashSet::default(),
            depth: 0,
        };
        b.visited.insert(main);
        b.index.files.push(main);
        b.items(items, None, main);
        let outline = items
            .iter()
            .filter_map(|i| outline_item(i, main))
            .flatten()
            .collect();
        let mut index = b.index;
        index.outline = outline;
        index
    }

    /// The definition a use of `name` at `at` refers to: a parameter or local of the
    /// macro it stands in, else the last definition before it in the same file, else
    /// the last one in an included file, else any.
    pub fn resolve(&self, name: Sym, at: Span) -> Option<&Def> {
        let candidates = self.defs.iter().filter(|d| d.name == name);
        let mut scoped: Option<&Def> = None;
        let mut before: Option<&Def> = None;
        let mut elsewhere: Option<&Def> = None;
        let mut any: Option<&Def> = None;
        for d in candidates {
            match d.scope {
                Some(s) => {
                    if s.file == at.file && s.start <= at.start && at.end <= s.end {
                        let better = scoped.is_none_or(|o| {
                            let os = o.scope.expect("scoped");
                            s.len() < os.len() || (s.len() == os.len() && d.span.start <= at.start)
                        });
                        if better {
                            scoped = Some(d);
                        }
                    }
                }
                None => {
                    if d.span.file == at.file {
                        if d.span.start <= at.start {
                            before = Some(d);
                        }
                        any = any.or(Some(d));
                    } else {
                        elsewhere = Some(d);
                    }
                }
            }
        }
        scoped.or(before).or(elsewhere).or(any)
    }

    /// The definition at `span` exactly (the cursor on a definition's name).
    pub fn def_at(&self, file: FileId, offset: usize) -> Option<&Def> {
        self.defs.iter().find(|d| {
            d.span.file == file && d.span.start as usize <= offset && offset <= d.span.end as usize
        })
    }

    /// The use at `offset` of `file`.
    pub fn use_at(&self, file: FileId, offset: usize) -> Option<&Use> {
        self.uses.iter().find(|u| {
            u.span.file == file && u.span.start as usize <= offset && offset <= u.span.end as usize
        })
    }

    /// The definition the cursor at `offset` of `file` names: the definition itself
    /// or the one a use there refers to.
    pub fn symbol_at(&self, file: FileId, offset: usize) -> Option<&Def> {
        if let Some(d) = self.def_at(file, offset) {
            return Some(d);
        }
        let u = self.use_at(file, offset)?;
        self.resolve(u.name, u.span)
    }

    /// Whether two definitions are the same symbol for references: the same
    /// definition, or both global definitions of one name (redeclarations).
    pub fn same_symbol(a: &Def, b: &Def) -> bool {
        a.name == b.name
            && (a.span == b.span
                || (a.scope.is_none()
                    && b.scope.is_none()
                    && a.kind != DefKind::LoopVar
                    && b.kind != DefKind::LoopVar))
    }

    /// The definitions and uses of the symbol `def`.
    pub fn references(&self, def: &Def) -> Vec<Span> {
        let mut out: Vec<Span> = self
            .defs
            .iter()
            .filter(|d| Index::same_symbol(d, def))
            .map(|d| d.span)
            .collect();
        for u in self.uses.iter().filter(|u| u.name == def.name) {
            if self
                .resolve(u.name, u.span)
                .is_some_and(|d| Index::same_symbol(d, def))
            {
                out.push(u.span);
            }
        }
        out.sort_by_key(|s| (s.file.0, s.start));
        out.dedup();
        out
    }
}

impl Builder<'_> {
    fn items(&mut self, items: &[Item], scope: Option<Span>, file: FileId) {
        for item in items {
            self.item(item, scope, file);
        }
    }

    fn item(&mut self, item: &Item, scope: Option<Span>, file: FileId) {
        match item {
            Item::Directive(d) => self.directive(&d.kind, d.span, scope, file),
            Item::Block(b) => self.block(b, scope, file),
            Item::Bracket(b) => self.items(&b.items, scope, file),
            Item::Expr(e) => self.expr(e),
            // The editor parses every branch; a body read for a render is walked
            // once read.
            Item::Deferred(d) => {
                if let Some(read) = d.items.get() {
                    self.items(read, scope, file);
                }
            }
            Item::Keyword(_) | Item::Comma(_) | Item::Semicolon(_) | Item::Data(_) => {}
        }
    }

    fn block(&mut self, b: &Block, scope: Option<Span>, file: FileId) {
        self.items(&b.items, scope, file);
    }

    fn def(
        &mut self,
        name: Sym,
        kind: DefKind,
        span: Span,
        full: Span,
        scope: Option<Span>,
    ) -> &mut Def {
        self.index.defs.push(Def {
            name,
            kind,
            span,
            full,
            params: Vec::new(),
            scope,
            block: None,
        });
        self.index.defs.last_mut().expect("pushed")
    }

    fn directive(&mut self, d: &DirectiveKind, span: Span, scope: Option<Span>, file: FileId) {
        match d {
            DirectiveKind::Declare {
                local,
                target,
                value,
                ..
            } => {
                for i in &target.indices {
                    self.expr(i);
                }
                match value {
                    Rhs::Block(b) => self.block(b, scope, file),
                    Rhs::Expr(e) => self.expr(e),
                    Rhs::Directive(d) => self.directive(&d.kind, d.span, scope, file),
                }
                if target.indices.is_empty() {
                    let kind = if *local {
                        DefKind::Local
                    } else {
                        DefKind::Declare
                    };
                    // A #local inside a macro lives in the macro's call; a #declare
                    // is global (unless it updates a local, which we do not track).
                    let s = if *local { scope } else { None };
                    let def = self.def(target.name, kind, target.name_span, span, s);
                    if let Rhs::Block(b) = value {
                        def.block = Some(b.keyword.name);
                    }
                } else {
                    self.use_(target.name, target.name_span);
                }
            }
            DirectiveKind::Undef { name, span } => self.use_(*name, *span),
            DirectiveKind::If {
                branches,
                otherwise,
            } => {
                for (c, body) in branches {
                    self.expr(c);
                    self.items(body, scope, file);
                }
                if let Some(o) = otherwise {
                    self.items(o, scope, file);
                }
            }
            DirectiveKind::IfDef {
                target,
                then,
                otherwise,
                ..
            } => {
                self.use_(target.name, target.name_span);
                for i in &target.indices {
                    self.expr(i);
                }
                self.items(then, scope, file);
                if let Some(o) = otherwise {
                    self.items(o, scope, file);
                }
            }
            DirectiveKind::Switch {
                value,
                cases,
                otherwise,
            } => {
                self.expr(value);
                for c in cases {
                    match &c.test {
                        CaseTest::Case(e) => self.expr(e),
                        CaseTest::Range(a, b) => {
                            self.expr(a);
                            self.expr(b);
                        }
                    }
                    self.items(&c.body, scope, file);
                }
                if let Some(o) = otherwise {
                    self.items(o, scope, file);
                }
            }
            DirectiveKind::While { cond, body } => {
                self.expr(cond);
                self.items(body, scope, file);
            }
            DirectiveKind::For {
                var,
                var_span,
                start,
                end,
                step,
                body,
            } => {
                self.def(*var, DefKind::LoopVar, *var_span, span, Some(span));
                self.expr(start);
                self.expr(end);
                if let Some(s) = step {
                    self.expr(s);
                }
                self.items(body, scope, file);
            }
            DirectiveKind::Macro(m) => {
                let params: Vec<String> = m
                    .params
                    .iter()
                    .map(|p| {
                        if p.optional {
                            format!("optional {}", p.name)
                        } else {
                            p.name.to_string()
                        }
                    })
                    .collect();
                let def = self.def(m.name, DefKind::Macro, m.name_span, span, None);
                def.params = params;
                for p in &m.params {
                    self.def(p.name, DefKind::Param, p.span, p.span, Some(span));
                }
                self.items(&m.body, Some(span), file);
            }
            DirectiveKind::Include(e) => {
                self.expr(e);
                let target = match &e.kind {
                    ExprKind::Str(name) => self.include(name, file),
                    _ => None,
                };
                self.index.includes.push(Include {
                    span: e.span,
                    target,
                });
            }
            DirectiveKind::Message(_, e) | DirectiveKind::Version(e) => self.expr(e),
            DirectiveKind::Default(items) => self.items(items, scope, file),
            DirectiveKind::FOpen {
                name,
                name_span,
                file: f,
                ..
            } => {
                self.expr(f);
                self.def(*name, DefKind::Declare, *name_span, span, None);
            }
            DirectiveKind::FClose { name, span } => self.use_(*name, *span),
            DirectiveKind::Read {
                name,
                name_span,
                targets,
            } => {
                self.use_(*name, *name_span);
                for t in targets {
                    for i in &t.indices {
                        self.expr(i);
                    }
                    if t.indices.is_empty() {
                        self.def(t.name, DefKind::Declare, t.name_span, span, None);
                    } else {
                        self.use_(t.name, t.name_span);
                    }
                }
            }
            DirectiveKind::Write {
                name,
                name_span,
                items,
            } => {
                self.use_(*name, *name_span);
                for (_, e) in items {
                    self.expr(e);
                }
            }
        }
    }

    /// Finds, loads, parses and indexes an include file; returns its id.
    fn include(&mut self, name: &str, from: FileId) -> Option<FileId> {
        let here = self.sources.get(from).dir().map(Path::to_path_buf);
        let path = find_include(
            name,
            here.as_deref(),
            self.scene_dir.as_deref(),
            &self.options.access,
        )?;
        let id = match self.sources.find_path(&path) {
            Some(id) => id,
            None => match STDLIB
                .iter()
                .find(|(n, _)| path == Path::new(&format!("<stdlib>/{n}")))
            {
                Some((n, text)) => {
                    self.sources
                        .add(format!("<stdlib>/{n}"), Some(path), (*text).to_string())
                }
                None => {
                    let shown = path.display().to_string();
                    load_file(self.sources, &path, shown).ok()?
                }
            },
        };
        if self.depth >= MAX_INCLUDE_DEPTH || !self.visited.insert(id) {
            return Some(id);
        }
        let text = self.sources.get(id).text.clone();
        let (file, _) = super::incremental::parse(&text, id);
        self.index.files.push(id);
        self.depth += 1;
        self.items(&file.items, None, id);
        self.depth -= 1;
        Some(id)
    }

    fn use_(&mut self, name: Sym, span: Span) {
        if !name.is_builtin() {
            self.index.uses.push(Use { name, span });
        }
    }

    fn expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Number(_) | ExprKind::Str(_) => {}
            ExprKind::Ident(s) => self.use_(*s, e.span),
            ExprKind::Vector(v) => v.iter().for_each(|x| self.expr(x)),
            ExprKind::Unary(_, a) => self.expr(a),
            ExprKind::Binary(_, a, b) => {
                self.expr(a);
                self.expr(b);
            }
            ExprKind::Cond(a, b, c) => {
                self.expr(a);
                self.expr(b);
                self.expr(c);
            }
            ExprKind::Call {
                name,
                name_span,
                args,
            } => {
                self.use_(*name, *name_span);
                for a in args {
                    match a {
                        Arg::Expr(x) => self.expr(x),
                        Arg::Block(b) => self.block_in_expr(b),
                        Arg::Empty(_) => {}
                    }
                }
            }
            ExprKind::Dot(a, _, _) => self.expr(a),
            ExprKind::Index(a, i) => {
                self.expr(a);
                self.expr(i);
            }
            ExprKind::Colour { value, parts, .. } => {
                if let Some(v) = value {
                    self.expr(v);
                }
                parts.iter().for_each(|(_, x)| self.expr(x));
            }
            ExprKind::Array { dims, init } => {
                dims.iter().for_each(|x| self.expr(x));
                if let Some(i) = init {
                    self.array_init(i);
                }
            }
            ExprKind::Block(b) => self.block_in_expr(b),
            ExprKind::Directive(d) => self.directive(&d.kind, d.span, None, d.span.file),
        }
    }

    fn block_in_expr(&mut self, b: &Block) {
        let file = b.span.file;
        self.block(b, None, file);
    }

    fn array_init(&mut self, init: &ArrayInit) {
        for e in &init.elems {
            match e {
                ArrayElem::Nested(n) => self.array_init(n),
                ArrayElem::Expr(x) => self.expr(x),
                ArrayElem::Block(b) => self.block_in_expr(b),
            }
        }
    }
}

/// The outline entries of one item of the main file (directives may hold several).
fn outline_item(item: &Item, file: FileId) -> Option<Vec<OutlineItem>> {
    match item {
        Item::Directive(d) => match &d.kind {
            DirectiveKind::Declare {
                target,
                value,
                local,
                ..
            } if target.indices.is_empty() => {
                let detail = match value {
                    Rhs::Block(b) => format!("{} {{ … }}", b.keyword.name),
                    Rhs::Expr(_) | Rhs::Directive(_) => {
                        if *local { "#local" } else { "#declare" }.to_string()
                    }
                };
                Some(vec![OutlineItem {
                    name: target.name.to_string(),
                    detail,
                    kind: OutlineKind::Variable,
                    span: d.span,
                    name_span: target.name_span,
                    children: match value {
                        Rhs::Block(b) => block_children(b, file),
                        Rhs::Expr(_) | Rhs::Directive(_) => Vec::new(),
                    },
                }])
            }
            DirectiveKind::Macro(m) => Some(vec![OutlineItem {
                name: m.name.to_string(),
                detail: format!(
                    "({})",
                    m.params
                        .iter()
                        .map(|p| p.name.to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
                kind: OutlineKind::Macro,
                span: d.span,
                name_span: m.name_span,
                children: Vec::new(),
            }]),
            DirectiveKind::If {
                branches,
                otherwise,
            } => {
                let mut v: Vec<OutlineItem> = branches
                    .iter()
                    .flat_map(|(_, b)| b.iter())
                    .chain(otherwise.iter().flatten())
                    .filter_map(|i| outline_item(i, file))
                    .flatten()
                    .collect();
                v.retain(|o| o.span.file == file);
                Some(v)
            }
            DirectiveKind::IfDef {
                then, otherwise, ..
            } => Some(
                then.iter()
                    .chain(otherwise.iter().flatten())
                    .filter_map(|i| outline_item(i, file))
                    .flatten()
                    .collect(),
            ),
            DirectiveKind::For { body, .. } | DirectiveKind::While { body, .. } => Some(
                body.iter()
                    .filter_map(|i| outline_item(i, file))
                    .flatten()
                    .collect(),
            ),
            _ => None,
        },
        Item::Block(b) => block_outline(b, file).map(|o| vec![o]),
        _ => None,
    }
}

fn block_children(b: &Block, file: FileId) -> Vec<OutlineItem> {
    if !CSG.contains(&b.keyword.name) {
        return Vec::new();
    }
    b.items
        .iter()
        .filter_map(|i| match i {
            Item::Block(c) => block_outline(c, file),
            _ => None,
        })
        .collect()
}

fn block_outline(b: &Block, file: FileId) -> Option<OutlineItem> {
    let k = b.keyword.name;
    let kind = if OBJECT_BLOCKS.contains(&k) {
        OutlineKind::Object
    } else if k == "camera" {
        OutlineKind::Camera
    } else if k == "light_source" {
        OutlineKind::Light
    } else if SETTINGS.contains(&k) {
        OutlineKind::Settings
    } else {
        return None;
    };
    // `object { Name … }`: show the name.
    let detail = match b.items.first() {
        Some(Item::Expr(e)) if k == "object" => match &e.kind {
            ExprKind::Ident(s) => s.to_string(),
            _ => String::new(),
        },
        _ => String::new(),
    };
    Some(OutlineItem {
        name: k.to_string(),
        detail,
        kind,
        span: b.span,
        name_span: b.keyword.span,
        children: block_children(b, file),
    })
}

/// Names of files under the search folders of a document in `dir` whose names start
/// with `prefix`, for completing `#include "…"`: `.inc`, `.rts`, `.pov` and `.mcr`
/// files, and the built-in library.
pub fn include_candidates(dir: Option<&Path>, options: &EvalOptions, prefix: &str) -> Vec<String> {
    let mut out: Vec<String> = STDLIB.iter().map(|(n, _)| n.to_string()).collect();
    let mut dirs: Vec<PathBuf> = dir.map(Path::to_path_buf).into_iter().collect();
    dirs.extend(options.access.include_dirs.iter().cloned());
    // A prefix with a folder (`parts/ba`) lists that folder.
    let (sub, _) = prefix.rsplit_once('/').unwrap_or(("", prefix));
    for d in dirs {
        let folder = if sub.is_empty() {
            d.clone()
        } else {
            d.join(sub)
        };
        let Ok(rd) = std::fs::read_dir(&folder) else {
            continue;
        };
        for e in rd.flatten().take(2000) {
            let name = e.file_name().to_string_lossy().into_owned();
            let is_dir = e.file_type().is_ok_and(|t| t.is_dir());
            let ok = is_dir
                || [".inc", ".rts", ".pov", ".mcr"]
                    .iter()
                    .any(|ext| name.ends_with(ext));
            if ok && !name.starts_with('.') {
                let full = if sub.is_empty() {
                    name
                } else {
                    format!("{sub}/{name}")
                };
                out.push(if is_dir { format!("{full}/") } else { full });
            }
        }
    }
    out.retain(|n| n.starts_with(prefix));
    out.sort();
    out.dedup();
    out
}
