//! Stage 2: syntax tree to scene description.
//!
//! [`eval`] runs the directives, expands macros and includes, evaluates expressions
//! and turns blocks into [`crate::scene`] data. Errors are collected, not thrown: a
//! failing statement is reported and evaluation goes on with the next one, and values
//! whose evaluation failed are [`Value::Poison`] so they do not cause further reports.
//!
//! The stage is laid out by what the code is:
//!
//! - `core/`: the language itself: the `Evaluator`
//!   and the context of the block being read, the cursor over a block's
//!   evaluated items, item expansion and macros, directives, expressions,
//!   values, scopes, `#include`, file I/O, built-ins and budgets, and the
//!   reuse of top-level items the clock does not touch from one frame to the
//!   next (`reuse.rs`);
//! - `objects/`: readers of shapes, CSG and object modifiers, meshes (mesh2,
//!   import), revolved shapes, blobs, text and isosurfaces;
//! - `materials/`: readers of textures, pigments, normals, finishes, interiors,
//!   maps, patterns and warps;
//! - `settings/`: readers of the camera, lights, atmosphere, media, photons,
//!   radiosity, path tracing and global settings;
//! - `animation/`: the timeline, keyframes, camera paths and splines.
//!
//! Only this file is public: the entry points [`eval`] and [`eval_cached`],
//! their options and results, and a few re-exported names editors and the
//! command line use.

mod animation;
mod core;
mod materials;
mod objects;
mod settings;

pub use self::core::budget::Interrupt;
pub use self::core::include::{
    find_include, load_file, load_file_limited, search_dirs, LoadError, MAX_SOURCE_SIZE, STDLIB,
};
pub use self::core::value::Value;
pub use self::core::vocabulary::{block_keywords, top_level_keywords};
pub use self::core::{file_io, value};
pub use self::objects::bicubic;
pub use self::objects::object::OBJECT_BLOCKS;
pub use crate::scene::{Spline, SplineKind};
pub use crate::syntax::builtins::{is_function as is_builtin_function, BUILTIN_NAMES};
pub use animation::keyframe::{ease, Easing};

use self::core::Evaluator;

use crate::diag::Diagnostic;
use crate::scene::Scene;
use crate::source::{FileAccess, SourceMap};
use crate::span::{FileId, Span};
use crate::syntax::ast;
use std::path::PathBuf;

/// The default of [`EvalOptions::max_image_pixels`]: 16384 × 16384, a 1 GiB
/// 8-bit RGBA picture.
pub const DEFAULT_MAX_IMAGE_PIXELS: u64 = 1 << 28;

/// Settings that come from the command line rather than the scene.
#[derive(Clone, Debug)]
pub struct EvalOptions {
    /// Where includes may be found and which files may be read.
    pub access: FileAccess,
    /// `-D NAME=VALUE` definitions, evaluated as expressions before the scene.
    pub defines: Vec<(String, String)>,
    /// `clock`.
    pub clock: f64,
    /// `clock_delta`.
    pub clock_delta: f64,
    /// `clock_on`: whether an animation is being rendered.
    pub clock_on: bool,
    /// `frame_number`.
    pub frame_number: f64,
    /// `initial_frame`.
    pub initial_frame: f64,
    /// `final_frame`.
    pub final_frame: f64,
    /// `initial_clock`.
    pub initial_clock: f64,
    /// `final_clock`.
    pub final_clock: f64,
    /// The timeline being rendered (from the command line and the scene's
    /// `animation { }`), used to place keyframes given in seconds or frames.
    /// `None`: the scene's own `animation { }`, else a default timeline.
    pub timeline: Option<crate::scene::Timeline>,
    /// `image_width`.
    pub image_width: f64,
    /// `image_height`.
    pub image_height: f64,
    /// Most loop iterations (all loops together) before evaluation stops.
    pub max_loop_iterations: u64,
    /// Deepest macro recursion.
    pub max_macro_depth: usize,
    /// Deepest `#include` nesting.
    pub max_include_depth: usize,
    /// Most elements in one array.
    pub max_array_size: usize,
    /// Deepest nesting of CSG objects (`union`s of `union`s are flattened and
    /// do not count).
    pub max_object_depth: u32,
    /// Most pixels the images a scene reads may hold together (each file
    /// counted once): checked from each file's header before it is decoded.
    pub max_image_pixels: u64,
    /// Whether `#write` reaches the disk (rendering) or only later reads of the
    /// same evaluation (`rts check`, the editor).
    pub write_files: bool,
    /// Most bytes the evaluation may grow the heap by (values, arrays, strings,
    /// objects, meshes, decoded images).
    pub max_memory: u64,
    /// Most macro calls in all.
    pub max_macro_calls: u64,
    /// Most bytes in one string.
    pub max_string_length: usize,
    /// Errors after which evaluation stops.
    pub max_errors: usize,
    /// How an editor stops an evaluation early.
    pub interrupt: Interrupt,
    /// Whether the built-in library's declarations and macros are evaluated
    /// when first used instead of at the `#include` (same values; see
    /// `lazy.rs`).
    pub lazy_library: bool,
    /// Most bytes the files `#write` makes may hold, all together (`--max-write`).
    pub max_write: u64,
    /// Largest `#include`d file, and file `#fopen` reads, in bytes
    /// (`--max-source-size`).
    pub max_source_size: u64,
    /// In an animation (`clock_on`), whether [`eval_cached`] reuses what the
    /// top-level items the clock does not touch did in an earlier frame
    /// instead of evaluating them again (same scene; `--no-eval-cache` turns
    /// it off).
    pub reuse: bool,
    /// Whether an isosurface's function is sampled on a grid in its container
    /// when it is read, for the `max_gradient` warning (`rts check`, the
    /// editor: no render follows). A render leaves it off and warns from the
    /// slopes its rays met instead, as POV-Ray does ([`Evaluated::slope_checks`]).
    pub sample_gradients: bool,
    /// Whether included files are parsed for rendering: the long branch
    /// bodies of `#if`/`#switch` read only when taken
    /// ([`crate::syntax::parse_with`]). Off for `rts check` and the
    /// editor, which report errors in every branch.
    pub defer_branches: bool,
    /// Whether [`Evaluated::globals`] is filled (the editor's hover and
    /// completion show the values); a render leaves it empty.
    pub describe_globals: bool,
}

impl Default for EvalOptions {
    fn default() -> Self {
        EvalOptions {
            access: FileAccess::default(),
            defines: Vec::new(),
            clock: 0.0,
            clock_delta: 0.0,
            clock_on: false,
            frame_number: 0.0,
            initial_frame: 0.0,
            final_frame: 0.0,
            initial_clock: 0.0,
            final_clock: 0.0,
            timeline: None,
            image_width: 800.0,
            image_height: 600.0,
            max_loop_iterations: 20_000_000,
            max_macro_depth: 1_000,
            max_include_depth: 64,
            max_array_size: 1 << 22,
            max_object_depth: 10_000,
            max_image_pixels: DEFAULT_MAX_IMAGE_PIXELS,
            write_files: false,
            max_memory: crate::memory::default_eval_budget(),
            max_macro_calls: 10_000_000,
            max_string_length: 64 << 20,
            max_errors: 100,
            interrupt: Interrupt::default(),
            lazy_library: true,
            max_write: 256 << 20,
            max_source_size: MAX_SOURCE_SIZE,
            reuse: true,
            sample_gradients: true,
            defer_branches: false,
            describe_globals: true,
        }
    }
}

/// The outcome of evaluation: the scene (complete only when no error was reported)
/// and every diagnostic, in the order found.
#[derive(Debug)]
pub struct Evaluated {
    /// The scene description.
    pub scene: Scene,
    /// Errors, warnings and `#debug` notes.
    pub diagnostics: Vec<Diagnostic>,
    /// The global names defined at the end of evaluation, for editors (hover);
    /// empty unless [`EvalOptions::describe_globals`].
    pub globals: Vec<Declared>,
    /// The isosurfaces whose `max_gradient` the render is to check (without
    /// [`EvalOptions::sample_gradients`]).
    pub slope_checks: Vec<SlopeCheck>,
}

/// An isosurface's `max_gradient` and the meter of the slopes the render meets
/// in it: after rendering, [`SlopeCheck::warning`] says whether it was too low.
#[derive(Clone, Debug)]
pub struct SlopeCheck {
    /// The meter the renderer fills.
    pub meter: crate::scene::SlopeMeter,
    /// The `max_gradient` the isosurface was given.
    pub max_gradient: f64,
    /// Its `max_gradient` (or, when not written, its function).
    pub span: Span,
}

impl SlopeCheck {
    /// POV-Ray's warning after a render, when a ray met a slope above
    /// `max_gradient` (the surface may have holes there).
    pub fn warning(&self) -> Option<Diagnostic> {
        let found = self.meter.steepest();
        (found > self.max_gradient).then(|| {
            Diagnostic::warning(
                crate::diag::codes::MAX_GRADIENT,
                self.span,
                format!(
                    "max_gradient {} is below the function's slope the render met (up to {:.3}): the surface may show holes",
                    self.max_gradient, found
                ),
            )
            .with_help(format!(
                "write `max_gradient {:.3}` (a larger value is safe but slower)",
                found * 1.05
            ))
        })
    }
}

/// A global name as evaluation left it: where it was last declared and its value.
#[derive(Clone, Debug)]
pub struct Declared {
    /// The name.
    pub name: String,
    /// Where it was last declared.
    pub span: Span,
    /// The kind of value, as in messages ("a float", "a texture", …).
    pub kind: &'static str,
    /// The value, for floats, vectors, colours and strings.
    pub value: Option<String>,
}

/// What one evaluation leaves for the next evaluation of the same scene (the
/// frames of an animation): parsed include files, meshes read from files, and
/// meshes by content, so geometry that does not change keeps the same `Arc` (and
/// with it its BVH, see [`crate::build::BuildCache`]) from frame to frame; and
/// decoded images, read again only when their file changes; and, in an
/// animation ([`EvalOptions::reuse`]), what each top-level item the clock does
/// not touch did, replayed instead of evaluating the item again (the same
/// parsed file must be evaluated each time; other options than the clock's
/// make it forget).
#[derive(Default)]
pub struct EvalCache {
    parsed_includes: rustc_hash::FxHashMap<FileId, Option<std::rc::Rc<ast::File>>>,
    pub(crate) meshes: objects::mesh_cache::MeshCache,
    images: self::core::images::ImageCache,
    data_files: std::collections::BTreeSet<PathBuf>,
    records: self::core::reuse::Records,
}

impl EvalCache {
    /// Every data file (mesh, height field, image) the evaluations found, sorted.
    pub fn data_files(&self) -> impl Iterator<Item = &std::path::Path> {
        self.data_files.iter().map(PathBuf::as_path)
    }

    /// How many image files the evaluations decoded: each file once while its
    /// size and modification time stay the same, however often it is used.
    pub fn images_decoded(&self) -> u64 {
        self.images.decoded()
    }

    /// Top-level items (units) reused from an earlier evaluation instead of
    /// evaluated, and evaluated, over all evaluations so far.
    pub fn units(&self) -> (u64, u64) {
        (self.records.replayed, self.records.evaluated)
    }
}

/// Evaluates a parsed file (already added to `sources` as `file_id`).
pub fn eval(
    file: &ast::File,
    file_id: FileId,
    sources: &mut SourceMap,
    options: &EvalOptions,
) -> Evaluated {
    eval_cached(file, file_id, sources, options, &mut EvalCache::default())
}

/// Evaluates a parsed file like [`eval`], reusing and filling `cache` (keep the
/// same `sources` between calls).
pub fn eval_cached(
    file: &ast::File,
    file_id: FileId,
    sources: &mut SourceMap,
    options: &EvalOptions,
    cache: &mut EvalCache,
) -> Evaluated {
    let mut ev = Evaluator::start(file_id, sources, options, cache);
    ev.define_command_line();
    // Names the text skipped after syntax errors would have declared: known
    // but broken, so using them reports nothing more.
    for name in &file.unparsed_names {
        let sym = crate::syntax::intern(name);
        if !sym.is_builtin() {
            ev.scope
                .declare(sym, Value::Poison, Span::new(file_id, 0, 0));
        }
    }
    ev.partial = !file.unparsed.is_empty();
    ev.start_units();
    ev.run_top(&file.items);
    ev.finish_run(cache)
}
