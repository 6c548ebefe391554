//! `rts`: a POV-Ray-compatible scene-description language and ray tracer.
//!
//! The modules follow the pipeline:
//! `source → syntax::parse → AST → eval::eval → scene → build::build → render::render → output::write`.

pub mod scene;
pub mod span;
pub mod build;
pub mod output;
pub mod render;
