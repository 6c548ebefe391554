//! Stage 2: syntax tree to scene description.
//!
//! [`eval`] runs the directives, expands macros and includes, evaluates expressions
//! and turns blocks into [`crate::scene`] data. Errors are collected, not thrown: a
//! failing statement is reported and evaluation goes on with the next one, and values
//! whose evaluation failed are [`Value::Poison`] so they do not cause further reports.

#[path = "settings/atmosphere.rs"]
mod atmosphere;
#[path = "objects/blob.rs"]
mod blob;
#[path = "core/blocks.rs"]
mod blocks;
#[path = "core/budget.rs"]
mod budget;
#[path = "core/builtins.rs"]
mod builtins;
#[path = "settings/camera.rs"]
mod camera;
#[path = "animation/camera_path.rs"]
mod camera_path;
#[path = "core/cursor.rs"]
mod cursor;
#[path = "core/directives.rs"]
mod directives;
#[path = "core/exprs.rs"]
mod exprs;
#[path = "core/file_data.rs"]
mod file_data;
#[path = "core/file_io.rs"]
pub mod file_io;
pub mod function;
#[path = "core/images.rs"]
mod images;
#[path = "objects/import.rs"]
mod import;
#[path = "core/include.rs"]
mod include;
#[path = "core/items.rs"]
mod items;
#[path = "animation/keyframe.rs"]
mod keyframe;
#[path = "settings/lights.rs"]
mod lights;
#[path = "core/list.rs"]
mod list;
#[path = "materials/material_block.rs"]
mod material_block;
#[path = "materials/texture.rs"]
mod materials;
#[path = "settings/media.rs"]
mod media;
#[path = "objects/mesh.rs"]
mod mesh;
#[path = "objects/mesh_cache.rs"]
mod mesh_cache;
#[path = "settings/mesh_camera.rs"]
mod mesh_camera;
#[path = "materials/modify.rs"]
mod modify;
#[path = "objects/object.rs"]
mod objects;
#[path = "settings/path_tracing.rs"]
mod path_tracing;
#[path = "materials/pattern_blocks.rs"]
mod pattern_blocks;
#[path = "materials/patterns.rs"]
mod patterns;
#[path = "settings/photons.rs"]
mod photons;
#[path = "settings/radiosity.rs"]
mod radiosity;
#[path = "objects/revolve.rs"]
mod revolve;
#[path = "core/scope.rs"]
mod scope;
#[path = "objects/shapes.rs"]
mod shapes;
#[path = "objects/shapes_more.rs"]
mod shapes_more;
#[path = "animation/spline.rs"]
mod spline;
#[path = "materials/subsurface.rs"]
mod subsurface;
#[path = "objects/text.rs"]
mod text;
#[path = "animation/timeline.rs"]
mod timeline;
#[path = "core/trace.rs"]
mod trace;
#[path = "core/value.rs"]
pub mod value;
#[path = "core/vocabulary.rs"]
mod vocabulary;
#[path = "materials/warps.rs"]
mod warps;

pub use budget::Interrupt;
pub use builtins::{is_function as is_builtin_function, BUILTIN_NAMES};
pub use include::{
    find_include, load_file, load_file_limited, search_dirs, LoadError, MAX_SOURCE_SIZE, STDLIB,
};
pub use keyframe::{ease, Easing};
pub use spline::{Spline, SplineKind};
pub use value::Value;
pub use vocabulary::{block_keywords, TOP_LEVEL_KEYWORDS};

use crate::diag::{codes, Diagnostic, Label};
use crate::scene::{Scene, Texture};
use crate::source::{FileAccess, SourceMap};
use crate::span::{FileId, Span};
use crate::syntax::ast;
use std::path::PathBuf;
use std::sync::Arc;

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
    /// Most bytes the files `#write` makes may hold, all together (`--max-write`).
    pub max_write: u64,
    /// Largest `#include`d file, and file `#fopen` reads, in bytes
    /// (`--max-source-size`).
    pub max_source_size: u64,
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
            max_write: 256 << 20,
            max_source_size: MAX_SOURCE_SIZE,
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
    /// The global names defined at the end of evaluation, for editors (hover).
    pub globals: Vec<Declared>,
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
/// decoded images, read again only when their file changes.
#[derive(Default)]
pub struct EvalCache {
    parsed_includes: rustc_hash::FxHashMap<FileId, Option<std::rc::Rc<ast::File>>>,
    pub(crate) meshes: mesh_cache::MeshCache,
    images: images::ImageCache,
    data_files: std::collections::BTreeSet<PathBuf>,
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
    let scene_dir = sources.get(file_id).dir().map(PathBuf::from);
    cache.meshes.begin();
    cache.images.begin();
    let mut ev = Evaluator {
        sources,
        options,
        scope: scope::Scopes::new(),
        diags: Vec::new(),
        scene: Scene::default(),
        camera_seen: None,
        trace: Vec::new(),
        default_texture: Arc::new(Texture::default()),
        loop_iterations: 0,
        macro_depth: 0,
        include_stack: vec![file_id],
        scene_dir,
        rand_streams: Vec::new(),
        stopped: false,
        language_version: None,
        parsed_includes: std::mem::take(&mut cache.parsed_includes),
        mesh_cache: std::mem::take(&mut cache.meshes),
        images: std::mem::take(&mut cache.images),
        image_pixels: 0,
        data_files: Default::default(),
        fonts: Default::default(),
        coefficient_lists: false,
        defer_material_blocks: false,
        built_objects: Default::default(),
        blob_items: false,
        density_block: false,
        declaring_function: None,
        pending_function: None,
        written: Default::default(),
        written_bytes: 0,
        open_writes: Vec::new(),
        files_seen: Default::default(),
        files_failed: Default::default(),
        deprecated: Default::default(),
        pending_pattern: None,
        pattern_items: false,
        light_groups: 0,
        spent: budget::Spent::start(),
    };
    ev.define_command_line();
    ev.run_top(&file.items);
    ev.close_all_files(Span::new(file_id, 0, 0));
    cache.parsed_includes = std::mem::take(&mut ev.parsed_includes);
    cache.meshes = std::mem::take(&mut ev.mesh_cache);
    cache.meshes.end();
    cache.images = std::mem::take(&mut ev.images);
    cache.images.end();
    cache.data_files.extend(ev.data_files.take());
    ev.finish_scene()
}

/// A failure while evaluating: the diagnostic to report, or `None` when the cause was
/// already reported (a poisoned value).
#[derive(Debug)]
pub(crate) struct Fail(Option<Box<Diagnostic>>);

impl From<Diagnostic> for Fail {
    fn from(d: Diagnostic) -> Fail {
        Fail(Some(Box::new(d)))
    }
}

impl Fail {
    /// A failure that reports nothing (its cause was reported already).
    pub(crate) fn silent() -> Fail {
        Fail(None)
    }
}

/// Result of evaluation steps.
pub(crate) type R<T> = Result<T, Fail>;

/// The evaluator's state for one run.
pub(crate) struct Evaluator<'a> {
    pub(crate) sources: &'a mut SourceMap,
    pub(crate) options: &'a EvalOptions,
    pub(crate) scope: scope::Scopes,
    pub(crate) diags: Vec<Diagnostic>,
    pub(crate) scene: Scene,
    pub(crate) camera_seen: Option<Span>,
    /// Include and macro-call sites on the way to the current item, outermost first.
    pub(crate) trace: Vec<Label>,
    pub(crate) default_texture: Arc<Texture>,
    pub(crate) loop_iterations: u64,
    pub(crate) macro_depth: usize,
    pub(crate) include_stack: Vec<FileId>,
    pub(crate) scene_dir: Option<PathBuf>,
    pub(crate) rand_streams: Vec<u64>,
    /// Set by `#error` and limits: evaluation stops.
    pub(crate) stopped: bool,
    /// The language version set by the last `#version` (a standard include file
    /// sets 3.7 when none was, as POV-Ray's own do); `None` when never set.
    pub(crate) language_version: Option<f64>,
    /// Include files parsed so far (`None`: it had syntax errors, already reported).
    pub(crate) parsed_includes: rustc_hash::FxHashMap<FileId, Option<std::rc::Rc<ast::File>>>,
    /// Meshes kept from earlier evaluations of the same scene.
    pub(crate) mesh_cache: mesh_cache::MeshCache,
    /// Decoded images, kept from earlier evaluations of the same scene.
    pub(crate) images: images::ImageCache,
    /// Pixels of the images this evaluation reads (each file counted once),
    /// against [`EvalOptions::max_image_pixels`].
    pub(crate) image_pixels: u64,
    /// Fonts read by `text` objects, by file.
    pub(crate) fonts: text::FontCache,
    /// Data files found (for the animation manifest's scene hash).
    pub(crate) data_files: std::cell::RefCell<Vec<PathBuf>>,
    /// Set while the items of a `poly`, `cubic` or `quartic` block are read:
    /// there, a vector of more than 5 numbers (other than a 12-number matrix) is
    /// a list of coefficients (a one-dimensional array).
    pub(crate) coefficient_lists: bool,
    /// Set while the items of a texture (or a texture_map's entries) or an object
    /// are read: there a
    /// `pigment`, `finish` or `normal` block modifies the one in force, as in
    /// POV-Ray, so it is kept unevaluated ([`cursor::Tok::Deferred`]) until the
    /// reader knows what it modifies (see `modify.rs`).
    pub(crate) defer_material_blocks: bool,
    /// Objects built for `trace`, `min_extent` and `max_extent`.
    pub(crate) built_objects: trace::BuiltObjects,
    /// Set while the items of a `blob` are read: there a `sphere` or `cylinder`
    /// block is a blob component (see `blob.rs`).
    pub(crate) blob_items: bool,
    /// Set while a media's `density { }` is read: it starts from density 1.
    pub(crate) density_block: bool,
    /// The name a `#declare NAME = function { … }` being evaluated binds: POV-Ray's
    /// functions.inc declares its built-ins as `function { internal(NUMBER) }`,
    /// and rts knows them by that name, not by POV-Ray's private numbers.
    pub(crate) declaring_function: Option<crate::syntax::Sym>,
    /// A `function { }` met as a pattern, until the pattern reader takes it.
    pub(crate) pending_function: Option<Arc<function::Function>>,
    /// Files written by `#write` in this evaluation (see `file_io.rs`).
    pub(crate) written: file_io::Overlay,
    /// Bytes the files being written hold so far, all together (see
    /// [`EvalOptions::max_write`]).
    pub(crate) written_bytes: u64,
    /// Files opened for writing, closed at the end if the scene does not.
    pub(crate) open_writes: Vec<std::rc::Rc<std::cell::RefCell<file_io::OpenFile>>>,
    /// Names declared `deprecated`, with whether a `once` warning was given.
    pub(crate) deprecated:
        rustc_hash::FxHashMap<crate::syntax::Sym, (ast::Deprecation, std::cell::Cell<bool>)>,
    /// Names ever opened by `#fopen` (closing one twice is allowed).
    pub(crate) files_seen: rustc_hash::FxHashSet<crate::syntax::Sym>,
    /// Names whose last `#fopen` failed (and was reported): their `#read` and
    /// `#write` report nothing more.
    pub(crate) files_failed: rustc_hash::FxHashSet<crate::syntax::Sym>,
    /// The pattern of a pattern block (`pigment_pattern { … }`) just met among a
    /// pigment's, normal's or texture's items (see `block_pattern_token`).
    pub(crate) pending_pattern: Option<crate::scene::PatternKind>,
    /// Set while the items of a `pigment`, `normal`, `texture` or `density`
    /// are read: there an `object { OBJECT A, B }` block is the object pattern.
    pub(crate) pattern_items: bool,
    /// `light_group`s made so far (each takes one bit of the objects' masks).
    pub(crate) light_groups: u32,
    /// What the evaluation has spent of its budgets (see `budget.rs`).
    pub(crate) spent: budget::Spent,
}

/// The longest include/macro chain shown in full: the innermost and outermost steps
/// are kept around a gap.
const MAX_TRACE: usize = 12;

/// The chain innermost first, with runs of the same step (recursion) merged into one
/// "(N times)" step and the middle of a very long chain left out. Returns the steps
/// and how many were left out.
fn compress_trace(trace: &[Label]) -> (Vec<Label>, usize) {
    let mut steps: Vec<(Label, usize)> = Vec::new();
    for l in trace.iter().rev() {
        match steps.last_mut() {
            Some((last, n)) if last.span == l.span && last.message == l.message => *n += 1,
            _ => steps.push((l.clone(), 1)),
        }
    }
    let mut out: Vec<Label> = steps
        .into_iter()
        .map(|(mut l, n)| {
            if n > 1 {
                l.message = format!("{} ({n} times)", l.message);
            }
            l
        })
        .collect();
    let mut omitted = 0;
    if out.len() > MAX_TRACE {
        let keep_tail = MAX_TRACE / 2;
        omitted = out.len() - MAX_TRACE;
        out.drain(MAX_TRACE - keep_tail..out.len() - keep_tail);
    }
    (out, omitted)
}

impl Evaluator<'_> {
    /// Records a failure with the current include/macro chain.
    pub(crate) fn report(&mut self, fail: Fail) {
        if let Some(mut d) = fail.0 {
            let (trace, omitted) = compress_trace(&self.trace);
            d.trace.extend(trace);
            if omitted > 0 {
                d.notes.push(format!(
                    "{omitted} more steps of the include/macro chain are not shown"
                ));
            }
            self.record(*d);
        }
    }

    /// Records a warning or note.
    pub(crate) fn warn(&mut self, d: Diagnostic) {
        self.report(d.into());
    }

    fn define_command_line(&mut self) {
        let defines = self.options.defines.clone();
        for (name, value) in defines {
            let text = format!("#declare {name} = {value};\n");
            let id = self
                .sources
                .add(format!("<-D {name}={value}>"), None, text.clone());
            let (file, diags) = crate::syntax::parse(&text, id);
            if !diags.is_empty() {
                let span = Span::new(id, 0, text.len().saturating_sub(1));
                self.diags.push(
                    Diagnostic::error(codes::BAD_DEFINE, span, format!("cannot use `-D {name}={value}`"))
                        .with_help("write -D NAME=VALUE with a name and an expression, e.g. -D Radius=2 or -D Name=\\\"text\\\""),
                );
                continue;
            }
            self.run_top(&file.items);
        }
    }

    /// Every word written in the bodies of the global macros.
    fn names_in_macro_bodies(&self) -> rustc_hash::FxHashSet<String> {
        let mut words = rustc_hash::FxHashSet::default();
        for m in self.scope.global_macros() {
            let (Some(first), Some(last)) = (m.body.first(), m.body.last()) else {
                continue;
            };
            let (a, b) = (first.span(), last.span());
            if a.file != b.file || a.start > b.end {
                continue;
            }
            let text = &self.sources.get(a.file).text;
            let Some(body) = text.get(a.start as usize..b.end as usize) else {
                continue;
            };
            words.extend(
                body.split(|c: char| !(c.is_alphanumeric() || c == '_'))
                    .filter(|w| !w.is_empty())
                    .map(str::to_string),
            );
        }
        words
    }

    fn finish_scene(mut self) -> Evaluated {
        self.note_repeats();
        // An include file checked on its own (`rts check lib.inc`, the editor)
        // is a library, not a scene: no camera, light or gamma is expected of
        // it, and its declarations are for the scenes that include it.
        let library = self
            .sources
            .get(self.include_stack[0])
            .path
            .as_deref()
            .and_then(|p| p.extension())
            .is_some_and(|e| e.eq_ignore_ascii_case("inc"));
        let warn = !library;
        if !crate::diag::has_errors(&self.diags) {
            let main = self.include_stack[0];
            let in_macros = self.names_in_macro_bodies();
            for (name, span) in self.scope.unused_globals().into_iter().filter(|_| warn) {
                // A name a macro's text refers to is used whenever the macro
                // is called, even if this run never called it.
                if span.file != main
                    || name.name().starts_with('_')
                    || in_macros.contains(&*name.name())
                {
                    continue;
                }
                self.diags.push(
                    Diagnostic::warning(
                        codes::UNUSED_DECLARE,
                        span,
                        format!("`{name}` is declared but never used"),
                    )
                    .with_label("never used after this")
                    .with_help(format!(
                        "remove the declaration, or name it `_{name}` to keep it unused on purpose"
                    )),
                );
            }
            self.scene.global.pre_3_7 = self.language_version.is_none_or(|v| v < 3.7);
            if self.scene.global.assumed_gamma.is_none() {
                // POV-Ray 3.7 assumes 1.0 in a 3.7 scene; in a scene of an older
                // version, or of none, it turns gamma handling off (measured).
                let legacy = self.language_version.is_none_or(|v| v < 3.7);
                self.scene.global.gamma_off = legacy;
                let help = if legacy {
                    "add `#version 3.7;` and `global_settings { assumed_gamma 1.0 }`; without either, POV-Ray and rts turn gamma handling off (colours are written to the file as they are)"
                } else {
                    "add `global_settings { assumed_gamma 1.0 }` (POV-Ray 3.7 assumes 1.0 and warns too)"
                };
                if warn {
                    self.diags.push(
                        Diagnostic::warning(
                            codes::NO_GAMMA,
                            Span::new(self.include_stack[0], 0, 0),
                            "the scene does not set assumed_gamma",
                        )
                        .with_help(help),
                    );
                }
            }
            if warn
                && self.scene.lights.is_empty()
                && !self.scene.objects.is_empty()
                && self.scene.global.path_tracing.is_none()
            {
                let help = if self.scene.global.radiosity.is_some() {
                    "add `light_source { <10, 10, -10> color rgb 1 }`; radiosity will gather only the background, sky and `emission`"
                } else {
                    "add `light_source { <10, 10, -10> color rgb 1 }`; only ambient light will show"
                };
                self.diags.push(
                    Diagnostic::warning(
                        codes::NO_LIGHTS,
                        Span::new(self.include_stack[0], 0, 0),
                        "the scene has no light sources",
                    )
                    .with_help(help),
                );
            }
        }
        let globals = self.scope.globals();
        Evaluated {
            scene: self.scene,
            diagnostics: self.diags,
            globals,
        }
    }
}
