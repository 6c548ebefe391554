//! The pest parser generated from `grammar/rts.pest`.

#![allow(missing_docs)]

/// The generated parser; [`Rule`] has one variant per grammar rule.
#[derive(pest_derive::Parser)]
#[grammar = "../grammar/rts.pest"]
#[grammar = "../grammar/keywords.pest"]
pub struct RtsParser;
