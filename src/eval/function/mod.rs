//! User-defined functions (`#declare F = function { x*x + y*y - 1 }`): compiled
//! once to a small stack program ([`program`]) that isosurfaces, function
//! patterns and calls in expressions run; and the built-ins of our
//! `functions.inc` ([`internal`]).

#[path = "../core/function.rs"]
mod compile;
pub mod internal;
#[path = "../objects/isosurface.rs"]
pub(crate) mod isosurface;
pub mod program;

pub use program::{Body, Function, Op};
