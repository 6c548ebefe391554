//! The language core: the evaluator and the context of the block it is in,
//! the cursor over a block's evaluated items, expanding items (and macros),
//! directives, expressions and values, scopes, `#include`, file input and
//! output, the built-in functions and constants, `function { }`, the
//! budgets one evaluation may spend, and reusing what top-level items the
//! clock does not touch did in an earlier frame. The readers in the sibling folders build
//! scene types on top of these.

pub(crate) mod blocks;
pub(crate) mod budget;
pub(crate) mod builtins;
pub(crate) mod context;
pub(crate) mod cursor;
pub(crate) mod deferred;
pub(crate) mod directives;
pub(crate) mod evaluator;
pub(crate) mod exprs;
pub(crate) mod file_data;
pub mod file_io;
pub(crate) mod function;
pub(crate) mod images;
pub(crate) mod include;
pub(crate) mod items;
pub(crate) mod lazy;
pub(crate) mod list;
pub(crate) mod reuse;
pub(crate) mod scope;
pub(crate) mod token_level;
pub(crate) mod trace;
pub(crate) mod transforms;
pub mod value;
pub(crate) mod vocabulary;

pub(crate) use evaluator::{Evaluator, Fail, R};
