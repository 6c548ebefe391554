//! Go to definition and find references for `#declare`/`#local`/`#macro` names,
//! parameters and loop variables, across `#include`s; on an `#include` file name, go
//! to definition opens the file.

use super::{Analysis, Location, Position, Range};
use crate::span::Span;

/// Where the name at `pos` is defined (or the file an `#include` at `pos` reads).
pub fn definition(a: &Analysis, pos: Position) -> Option<Location> {
    let offset = a.offset(pos);
    if let Some(inc) = a.index.includes.iter().find(|i| {
        i.span.file == a.main && i.span.start as usize <= offset && offset <= i.span.end as usize
    }) {
        let path = a.sources.get(inc.target?).path.clone()?;
        return Some(Location {
            path,
            range: Range::default(),
        });
    }
    let def = a.index.symbol_at(a.main, offset)?;
    a.location(def.span)
}

/// Every place the name at `pos` is defined or used, in the document and its
/// includes; `include_declaration` false leaves the definitions out.
pub fn references(a: &Analysis, pos: Position, include_declaration: bool) -> Vec<Location> {
    let offset = a.offset(pos);
    let Some(def) = a.index.symbol_at(a.main, offset) else {
        return Vec::new();
    };
    let defs: Vec<Span> = a
        .index
        .defs
        .iter()
        .filter(|d| super::index::Index::same_symbol(d, def))
        .map(|d| d.span)
        .collect();
    a.index
        .references(def)
        .into_iter()
        .filter(|s| include_declaration || !defs.contains(s))
        .filter_map(|s| a.location(s))
        .collect()
}
