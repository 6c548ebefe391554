//! User-defined functions (`#declare F = function { x*x + y*y - 1 }`): compiled
//! once to a small stack program ([`program`]) that isosurfaces, function
//! patterns and calls in expressions run; and the built-ins of our
//! `functions.inc` ([`internal`]).

pub mod internal;
pub mod program;

pub use program::{Body, Function, Op};
