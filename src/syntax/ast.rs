//! The syntax tree. Every node carries the [`Span`] it was parsed from.

use crate::span::Span;
use std::rc::Rc;

/// An interned identifier; see [`super::intern`].
pub type Sym = super::intern::Sym;

/// A parsed file: its top-level items.
#[derive(Clone, Debug, Default)]
pub struct File {
    /// The items in order.
    pub items: Vec<Item>,
    /// Text skipped after syntax errors (the items around it parsed).
    pub unparsed: Vec<Span>,
    /// Names `#declare`d, `#local`ed or `#macro`-defined in the skipped text:
    /// evaluation treats them as known but broken, so the items that parsed
    /// do not report them as unknown.
    pub unparsed_names: Vec<String>,
}

/// Anything that may stand at top level or inside a block.
#[derive(Clone, Debug)]
pub enum Item {
    /// `#declare …`, `#if …`, … .
    Directive(Box<Directive>),
    /// `keyword { items }`, e.g. `sphere { 0, 1 }`. Shared, so a block kept
    /// for later (a deferred pigment) costs no copy.
    Block(std::rc::Rc<Block>),
    /// A bare keyword, e.g. `phong` in `finish { phong 0.8 }`.
    Keyword(Keyword),
    /// `[ items ]`, e.g. `[0.5 color Red]` in a `color_map`.
    Bracket(Box<Bracket>),
    /// `,`.
    Comma(Span),
    /// `;`.
    Semicolon(Span),
    /// An expression, e.g. `<0, 1, 0>` or `Ball(1, 2)`.
    Expr(Box<Expr>),
    /// A run of plain numbers and vectors, packed: `3, <0, 0, 0>, <1, 0, 0>`
    /// (the items `3`, `,`, `<0, 0, 0>`, … read in one go).
    Data(std::rc::Rc<super::data::DataRun>),
    /// The body of a branch (`#if (C) BODY #else BODY #end`, `#case (V) BODY
    /// #break`) left unread by a parse for rendering, read when the branch is
    /// taken (see [`crate::syntax::parse_with`]).
    Deferred(std::rc::Rc<Deferred>),
}

/// A branch body left unread: `#if (Frame = 4) … #end` written as text.
#[derive(Debug)]
pub struct Deferred {
    /// The body's text (from after the branch's head to the `#` that ends it).
    pub span: Span,
    /// Its items, once read.
    pub items: std::cell::OnceCell<std::rc::Rc<[Item]>>,
}

impl Item {
    /// Where the item was written.
    pub fn span(&self) -> Span {
        match self {
            Item::Directive(d) => d.span,
            Item::Block(b) => b.span,
            Item::Keyword(k) => k.span,
            Item::Bracket(b) => b.span,
            Item::Comma(s) | Item::Semicolon(s) => *s,
            Item::Expr(e) => e.span,
            Item::Data(d) => d.span,
            Item::Deferred(d) => d.span,
        }
    }
}

/// A reserved keyword such as `sphere` or `phong`.
#[derive(Clone, Copy, Debug)]
pub struct Keyword {
    /// The keyword's text (always one of the grammar's reserved words).
    pub name: &'static str,
    /// Where it was written.
    pub span: Span,
}

/// `keyword { items }`.
#[derive(Clone, Debug)]
pub struct Block {
    /// The keyword before `{`.
    pub keyword: Keyword,
    /// The items between the braces.
    pub items: Vec<Item>,
    /// From the keyword to the closing brace.
    pub span: Span,
    /// The parameter names of `function(a, b) { … }` with where each was written;
    /// `None` for every other block (and for `function { … }`).
    pub params: Option<Vec<(Sym, Span)>>,
}

/// `[ items ]`.
#[derive(Clone, Debug)]
pub struct Bracket {
    /// The items between the brackets.
    pub items: Vec<Item>,
    /// From `[` to `]`.
    pub span: Span,
}

/// A directive with its span.
#[derive(Clone, Debug)]
pub struct Directive {
    /// What kind of directive.
    pub kind: DirectiveKind,
    /// From `#` to the end of the directive (its `#end` for block directives).
    pub span: Span,
}

/// `NAME` or `NAME[I][J]` on the left of `#declare`.
#[derive(Clone, Debug)]
pub struct LValue {
    /// The name.
    pub name: Sym,
    /// Where the name was written.
    pub name_span: Span,
    /// Indices, if an array element is assigned.
    pub indices: Vec<Expr>,
}

/// The value on the right of `#declare NAME =`.
#[derive(Clone, Debug)]
pub enum Rhs {
    /// `#declare T = texture { … }`.
    Block(Box<Block>),
    /// `#declare R = 1.5;`.
    Expr(Box<Expr>),
    /// `#declare R = #if (C) 1; #else 2; #end`: the chosen branch gives the value;
    /// also `#declare M = #include "mesh.inc"`.
    Directive(Box<Directive>),
}

/// One `#case (V)` or `#range (A, B)` clause of a `#switch`.
#[derive(Clone, Debug)]
pub struct Case {
    /// `#case (V)` or `#range (A, B)`.
    pub test: CaseTest,
    /// The items of the clause.
    pub body: Vec<Item>,
    /// Whether the clause ends with `#break`.
    pub breaks: bool,
    /// Where the clause's head was written.
    pub span: Span,
}

/// What a `#switch` clause tests.
#[derive(Clone, Debug)]
pub enum CaseTest {
    /// `#case (V)`: equal to V.
    Case(Expr),
    /// `#range (LOW, HIGH)`: LOW ≤ value ≤ HIGH.
    Range(Expr, Expr),
}

/// A macro parameter: `NAME` or `optional NAME`.
#[derive(Clone, Debug)]
pub struct Param {
    /// The name.
    pub name: Sym,
    /// Whether the caller may leave it out.
    pub optional: bool,
    /// Where it was written.
    pub span: Span,
}

/// `#macro NAME(PARAMS) BODY #end`.
#[derive(Debug)]
pub struct MacroDef {
    /// The macro's name.
    pub name: Sym,
    /// Where the name was written.
    pub name_span: Span,
    /// The parameters.
    pub params: Vec<Param>,
    /// The items the macro expands to.
    pub body: Vec<Item>,
    /// The body's text when its brackets balance only once its `#if`s are
    /// decided (`#if (F) #write (H, "{" #else mesh2 { #end`): POV-Ray reads a
    /// macro token by token as it runs. `body` is then empty and this text is
    /// parsed at each call, after the `#if`s the call decides.
    pub raw: Option<Span>,
}

/// `#debug`, `#warning` or `#error`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MessageKind {
    /// `#debug STRING`: printed as a note.
    Debug,
    /// `#warning STRING`.
    Warning,
    /// `#error STRING`: stops with an error.
    Error,
}

/// `deprecated [once] "MESSAGE"` in a declaration.
#[derive(Clone, Debug)]
pub struct Deprecation {
    /// `once`: warn at the first use only.
    pub once: bool,
    /// The message.
    pub message: Rc<str>,
}

/// How `#fopen` opens a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OpenMode {
    /// `read`: values are read with `#read`.
    Read,
    /// `write`: the file is created (or emptied) and written with `#write`.
    Write,
    /// `append`: `#write` adds to the end of the file.
    Append,
}

/// A binary integer type of `#write`: `uint8 V`, `sint16le V`, …
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryKind {
    /// `uint8`: one byte, 0 to 255.
    U8,
    /// `sint8`: one byte, -128 to 127.
    S8,
    /// `uint16be`: two bytes, big-endian.
    U16Be,
    /// `uint16le`: two bytes, little-endian.
    U16Le,
    /// `sint16be`: two bytes, big-endian, signed.
    S16Be,
    /// `sint16le`: two bytes, little-endian, signed.
    S16Le,
    /// `sint32be`: four bytes, big-endian, signed.
    S32Be,
    /// `sint32le`: four bytes, little-endian, signed.
    S32Le,
}

/// The directives.
#[derive(Clone, Debug)]
pub enum DirectiveKind {
    /// `#declare NAME = VALUE;` (`local` false) or `#local NAME = VALUE;`.
    Declare {
        /// `#local` rather than `#declare`.
        local: bool,
        /// What is assigned.
        target: LValue,
        /// The value.
        value: Rhs,
        /// `#declare deprecated [once] "MESSAGE" NAME = …`: uses of the name warn
        /// with MESSAGE (only the first use with `once`).
        deprecated: Option<Deprecation>,
    },
    /// `#undef NAME`.
    Undef {
        /// The name.
        name: Sym,
        /// Where it was written.
        span: Span,
    },
    /// `#if (C) … #elseif (C) … #else … #end`: the branches in order, then the else.
    If {
        /// `(condition, body)` for the `#if` and each `#elseif`.
        branches: Vec<(Expr, Vec<Item>)>,
        /// The `#else` body.
        otherwise: Option<Vec<Item>>,
    },
    /// `#ifdef (NAME) … #else … #end` (`negate` for `#ifndef`).
    IfDef {
        /// `#ifndef` rather than `#ifdef`.
        negate: bool,
        /// The name (and indices) tested.
        target: LValue,
        /// Items when the test holds.
        then: Vec<Item>,
        /// Items otherwise.
        otherwise: Option<Vec<Item>>,
    },
    /// `#switch (V) #case … #range … #else … #end`.
    Switch {
        /// The value switched on.
        value: Expr,
        /// The clauses.
        cases: Vec<Case>,
        /// The `#else` items.
        otherwise: Option<Vec<Item>>,
    },
    /// `#while (C) … #end`.
    While {
        /// The condition.
        cond: Expr,
        /// The loop body.
        body: Vec<Item>,
    },
    /// `#for (I, START, END [, STEP]) … #end`.
    For {
        /// The loop variable.
        var: Sym,
        /// Where the loop variable was written.
        var_span: Span,
        /// First value.
        start: Expr,
        /// Last value (inclusive).
        end: Expr,
        /// Increment (default 1).
        step: Option<Expr>,
        /// The loop body.
        body: Vec<Item>,
    },
    /// `#macro NAME(PARAMS) … #end`.
    Macro(Rc<MacroDef>),
    /// `#include "FILE"`.
    Include(Expr),
    /// `#debug`, `#warning`, `#error` with the message expression.
    Message(MessageKind, Expr),
    /// `#default { texture { … } }`.
    Default(Vec<Item>),
    /// `#version V;`.
    Version(Expr),
    /// `#fopen NAME "FILE" read|write|append`.
    FOpen {
        /// The file identifier.
        name: Sym,
        /// Where the identifier was written.
        name_span: Span,
        /// The file name.
        file: Expr,
        /// How the file is opened.
        mode: OpenMode,
    },
    /// `#fclose NAME`.
    FClose {
        /// The file identifier.
        name: Sym,
        /// Where it was written.
        span: Span,
    },
    /// `#read (NAME, VAR, …)`.
    Read {
        /// The file identifier.
        name: Sym,
        /// Where it was written.
        name_span: Span,
        /// The variables read into, in order.
        targets: Vec<LValue>,
    },
    /// `#write (NAME, ITEM, …)`.
    Write {
        /// The file identifier.
        name: Sym,
        /// Where it was written.
        name_span: Span,
        /// The items, each optionally written as a binary integer.
        items: Vec<(Option<BinaryKind>, Expr)>,
    },
}

/// An expression with its span.
#[derive(Clone, Debug)]
pub struct Expr {
    /// What kind of expression.
    pub kind: ExprKind,
    /// Where it was written.
    pub span: Span,
}

/// Binary operators, in POV-Ray's precedence order from loosest to tightest:
/// `|`, `&`, comparisons, `+ -`, `* /`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    /// `|`.
    Or,
    /// `&`.
    And,
    /// `<`.
    Lt,
    /// `<=`.
    Le,
    /// `=`.
    Eq,
    /// `!=`.
    Ne,
    /// `>=`.
    Ge,
    /// `>`.
    Gt,
    /// `+`.
    Add,
    /// `-`.
    Sub,
    /// `*`.
    Mul,
    /// `/`.
    Div,
}

/// Prefix operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnOp {
    /// `-A`.
    Neg,
    /// `+A`.
    Plus,
    /// `!A`.
    Not,
}

/// The colour keywords: `rgb`, `rgbf`, `rgbt`, `rgbft`, their `srgb` forms, and a bare
/// `color`/`colour`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ColourKw {
    /// Which components the value gives.
    pub form: ColourForm,
    /// `srgb…`: the components are sRGB-encoded.
    pub srgb: bool,
}

/// Which components a colour keyword's vector gives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColourForm {
    /// `color EXPR`: the value is already a colour (or a vector of 3–5 components).
    Plain,
    /// `rgb <r, g, b>`.
    Rgb,
    /// `rgbf <r, g, b, f>`.
    Rgbf,
    /// `rgbt <r, g, b, t>`.
    Rgbt,
    /// `rgbft <r, g, b, f, t>`.
    Rgbft,
}

/// `red`, `green`, `blue`, `filter`, `transmit` or `gray` after a colour keyword.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColourPart {
    /// `red R`.
    Red,
    /// `green G`.
    Green,
    /// `blue B`.
    Blue,
    /// `filter F`.
    Filter,
    /// `transmit T`.
    Transmit,
    /// `gray G` (all three of red, green, blue).
    Gray,
}

/// The kinds of expression.
#[derive(Clone, Debug)]
pub enum ExprKind {
    /// `1.5`.
    Number(f64),
    /// `"text"` (escapes already resolved).
    Str(Rc<str>),
    /// `Name`, `x`, `pi`, `clock`, …
    Ident(Sym),
    /// `<a, b, c>`.
    Vector(Vec<Expr>),
    /// `-a`, `!a`.
    Unary(UnOp, Box<Expr>),
    /// `a + b`, …
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `c ? a : b`.
    Cond(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `name(args)`: a built-in function or a macro.
    Call {
        /// The name.
        name: Sym,
        /// Where the name was written.
        name_span: Span,
        /// The arguments (blocks are allowed as macro arguments).
        args: Vec<Arg>,
    },
    /// `a.x`, `c.red`, …
    Dot(Box<Expr>, Sym, Span),
    /// `a[i]`.
    Index(Box<Expr>, Box<Expr>),
    /// `rgb <…>`, `color red 1`, … .
    Colour {
        /// The keyword.
        kw: ColourKw,
        /// The main value, if any.
        value: Option<Box<Expr>>,
        /// `red R`-style parts after it.
        parts: Vec<(ColourPart, Expr)>,
    },
    /// `keyframes { … }` as an operand: `2 * keyframes { key 0, 1 key 1, 3 }`.
    Block(Box<Block>),
    /// `#if (C) A #else B #end` as an operand: the chosen branch gives the value.
    Directive(Box<Directive>),
    /// `array[N]…[M] { … }`.
    Array {
        /// The sizes.
        dims: Vec<Expr>,
        /// The initialiser.
        init: Option<ArrayInit>,
    },
}

/// A macro or function argument.
#[derive(Clone, Debug)]
pub enum Arg {
    /// An expression.
    Expr(Expr),
    /// A block, e.g. `texture { … }` passed to a macro.
    Block(Block),
    /// Nothing: `M(1, , 3)` leaves an optional macro parameter undefined.
    Empty(Span),
}

impl Arg {
    /// Where the argument was written.
    pub fn span(&self) -> Span {
        match self {
            Arg::Expr(e) => e.span,
            Arg::Block(b) => b.span,
            Arg::Empty(s) => *s,
        }
    }
}

/// `{ a, b, … }` in an array declaration: one element or a nested list each.
#[derive(Clone, Debug)]
pub struct ArrayInit {
    /// The elements.
    pub elems: Vec<ArrayElem>,
    /// From `{` to `}`.
    pub span: Span,
}

/// One element of an array initialiser.
#[derive(Clone, Debug)]
pub enum ArrayElem {
    /// A nested `{ … }` for the next dimension.
    Nested(ArrayInit),
    /// A value.
    Expr(Expr),
    /// An object, texture, … .
    Block(Block),
}
