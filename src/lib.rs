//! `rts`: a POV-Ray-compatible scene-description language and ray tracer.
//!
//! The modules follow the pipeline:
//! `source → syntax::parse → AST → eval::eval → scene → build::build → render::render → output::write`;
//! `scene` is plain data, `pattern` the runtime code (patterns, pigments, functions at a
//! point) that `eval`, `build` and `render` share, and no stage imports a later one
//! (`tests/layout.rs`); `files` (reading and writing files safely) serves them all and
//! imports none.

pub mod build;
pub mod diag;
pub mod eval;
pub mod files;
pub mod ide;
pub mod memory;
pub mod output;
pub mod pattern;
pub mod render;
pub mod scene;
pub mod source;
pub mod span;
pub mod syntax;
